//! Bundles that travel between the blocks, and small helpers shared by them.
//!
//! Coordinates inside the core are kept in *offset binary*: the Q7.8 two's
//! complement value with its sign bit flipped, so that unsigned comparison and
//! subtraction order them exactly like the signed values. Every width here is a
//! fixed maximum (labels 16 bits, columns 12 bits, rows 8 bits); the run-time
//! parameters (rows, columns, K, label bits, thresholds) become constants.

use rust_hdl::prelude::*;

/// One pixel slot of the input raster, as produced by the input stage of `fcc_top`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Pix {
    /// A pixel position is present in this pipeline slot (not a bubble).
    pub valid: Bit,
    /// The pixel holds a point.
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub row: Bits<8>,
    pub col: Bits<12>,
    /// First pixel of the frame.
    pub first: Bit,
    /// Last pixel of the frame.
    pub last: Bit,
    /// First column of a row.
    pub col0: Bit,
    /// Last column of a row.
    pub coln: Bit,
}

/// A labelled pixel: the output of `fcc_intra` (its frame-buffer code
/// travels beside it, to the label updater) and the input of `fcc_window`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct WinPix {
    pub valid: Bit,
    /// The pixel holds a point with a provisional label (it can join).
    pub lok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    /// Provisional label, 0 for an empty or unlabelled pixel.
    pub label: Bits<16>,
    pub row: Bits<8>,
    pub col: Bits<12>,
    /// Column `(col + h) mod C` that the window reads for this pixel.
    pub rdcol: Bits<12>,
    pub last: Bit,
    /// Ring join of this row (set on the row's last pixel only).
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// The window's centre as the distance tree takes it.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Centre {
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub valid: Bit,
    pub lok: Bit,
    pub label: Bits<16>,
    pub col: Bits<12>,
    pub last: Bit,
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// What the sort network needs to know about a centre.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Ctr {
    pub valid: Bit,
    /// The centre is a point with a provisional label (it can join).
    pub lok: Bit,
    pub label: Bits<16>,
    pub col: Bits<12>,
    pub last: Bit,
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// One line-buffer word: a point of a row above, and whether it has a
/// provisional label (only such points can join).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct LbEntry {
    pub lok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
}

/// Four 2-bit frame-buffer codes (pixels 4a .. 4a+3).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct FbWord {
    pub s0: Bits<2>,
    pub s1: Bits<2>,
    pub s2: Bits<2>,
    pub s3: Bits<2>,
}

/// The largest K the generator supports, and so the most positions of a window row.
pub const MAX_K: usize = *fcc_params::limits::HW_FSIZE.end();

/// The centre part of a centre-buffer record: the centre's join side, its
/// ring join and the frame's end (the window rows travel in `FccRowPack` words).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct CtrRec {
    pub c: Bits<16>,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
    pub ring: Bit,
    pub last: Bit,
}

/// A join for the union engine: connect `a` and `b`; `same`: `a` is the
/// previous join's `a`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct JoinRec {
    pub a: Bits<16>,
    pub b: Bits<16>,
    pub same: Bit,
}

/// A typed constant of `N` bits.
pub fn kb<const N: usize>(v: u64) -> Constant<Bits<N>> {
    Constant::new(v.to_bits::<N>())
}

/// Ceiling of log2, at least 1 (width of an index into `n` entries).
pub fn clog2(n: usize) -> usize {
    let mut w = 1;
    while (1usize << w) < n {
        w += 1;
    }
    w
}

/// A `Vec` of `n` default values (ports, registers and signals of a block
/// whose count is a run-time parameter).
pub fn vec_of<T: Default>(n: usize) -> Vec<T> {
    (0..n).map(|_| T::default()).collect()
}
