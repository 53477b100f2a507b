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
}

/// A labelled pixel: the output of `fcc_intra`, the centre of `fcc_window`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Lab {
    pub valid: Bit,
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    /// Provisional label, 0 for an empty or unlabelled pixel.
    pub label: Bits<16>,
    /// Frame-buffer code: 0 empty, 1 continues a run, 2 starts a labelled run,
    /// 3 starts an unlabelled run (labels exhausted).
    pub state: Bits<2>,
    pub row: Bits<8>,
    pub col: Bits<12>,
    pub last: Bit,
    /// Ring join of this row (set on the row's last pixel only).
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// The labelled pixel as `fcc_window` takes it (no frame-buffer code).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct WinPix {
    pub valid: Bit,
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub label: Bits<16>,
    pub row: Bits<8>,
    pub col: Bits<12>,
    pub last: Bit,
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
    pub ok: Bit,
    pub label: Bits<16>,
    pub last: Bit,
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// What the sort network needs to know about a centre.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Ctr {
    pub valid: Bit,
    pub ok: Bit,
    pub label: Bits<16>,
    pub last: Bit,
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

/// One line-buffer word: a point of a row above and its provisional label.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct LbEntry {
    pub ok: Bit,
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub label: Bits<16>,
}

/// Four 2-bit frame-buffer codes (pixels 4a .. 4a+3).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct FbWord {
    pub s0: Bits<2>,
    pub s1: Bits<2>,
    pub s2: Bits<2>,
    pub s3: Bits<2>,
}

/// Joins of one centre label `c` with up to four labels `n0..n3` (valid
/// slots are contiguous from `n0`). A ring join is an entry with `c = first`
/// and `n0 = last`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct JoinEntry {
    pub c: Bits<16>,
    pub n0: Bits<16>,
    pub n1: Bits<16>,
    pub n2: Bits<16>,
    pub n3: Bits<16>,
    pub v0: Bit,
    pub v1: Bit,
    pub v2: Bit,
    pub v3: Bit,
}

/// Joins carried by one FIFO entry.
pub const JOIN_SLOTS: usize = 4;

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
