//! `FccAccPixel`: the accumulator of one pixel, [`ACC_PIXEL_LATENCY`]
//! cycles after it (no enable; every stage registered): its column (below
//! `C/2` or not: the seam span), row, point as box and sums, `|x|^2`,
//! `|y|^2`, `|z|^2` (the squared range) and `a * b`. Offset binary in:
//! `|x|` is `a - 2^15` or `2^15 - a`, at most `2^15`.
//!
//! * P1: `|x|`, `|y|`, `|z|`, which half the column is in.
//! * P2: the four 16 x 16 products (DSP multipliers with their output
//!   register).
//! * PF: the products copied into fabric flip-flops (a DSP's output is too
//!   slow to feed a carry chain in the same cycle).
//! * P3: `|x|^2 + |y|^2`.
//! * P4: the squared range (`+ |z|^2`) and the accumulator word, in a
//!   register that `rst` clears (so it stays a flip-flop: a shift-register
//!   LUT's output is slow).

use rust_hdl::prelude::*;

use super::AccWord;
use crate::types::kb;

/// Cycles from a pixel to its accumulator.
pub const ACC_PIXEL_LATENCY: usize = 5;

/// What waits beside the products: the point (offset binary), its row and
/// column, and whether the column is below `C/2`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct AccSide {
    pub x: Bits<16>,
    pub y: Bits<16>,
    pub z: Bits<16>,
    pub row: Bits<7>,
    pub col: Bits<12>,
    pub lo: Bit,
}

/// The products: `|x|^2`, `|y|^2`, `|z|^2`, `a * b`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct AccProducts {
    pub xx: Bits<32>,
    pub yy: Bits<32>,
    pub zz: Bits<32>,
    pub ab: Bits<32>,
}

#[derive(LogicBlock)]
pub struct FccAccPixel {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    /// `C / 2` (rounded down), constant while a frame runs.
    pub half: Signal<In, Bits<12>>,
    pub acc: Signal<Out, AccWord>,
    /// P1: `|x|`, `|y|`, `|z|`.
    ax: DFF<Bits<16>>,
    ay: DFF<Bits<16>>,
    az: DFF<Bits<16>>,
    /// P1 .. P3: the point and its place.
    side1: DFF<AccSide>,
    side2: DFF<AccSide>,
    sidef: DFF<AccSide>,
    side3: DFF<AccSide>,
    /// P2, PF, P3: the products; P3: `|x|^2 + |y|^2`.
    prod2: DFF<AccProducts>,
    prodf: DFF<AccProducts>,
    prod3: DFF<AccProducts>,
    xy3: DFF<Bits<32>>,
    /// P4.
    out: DFF<AccWord>,
    word: Signal<Local, AccWord>,
    zero: Constant<AccWord>,
    one20: Constant<Bits<20>>,
    mid: Constant<Bits<16>>,
}

impl Default for FccAccPixel {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            row: Default::default(),
            col: Default::default(),
            half: Default::default(),
            acc: Default::default(),
            ax: Default::default(),
            ay: Default::default(),
            az: Default::default(),
            side1: Default::default(),
            side2: Default::default(),
            sidef: Default::default(),
            side3: Default::default(),
            prod2: Default::default(),
            prodf: Default::default(),
            prod3: Default::default(),
            xy3: Default::default(),
            out: Default::default(),
            word: Default::default(),
            zero: Constant::new(AccWord::default()),
            one20: kb(1),
            mid: kb(0x8000),
        }
    }
}

impl Logic for FccAccPixel {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, ax, ay, az, side1, side2, sidef, side3, prod2, prodf, prod3, xy3, out
        );
        // ---- P1: |x|, |y|, |z| from offset binary; the column's half.
        self.ax.d.next = self.mid.val() - self.x.val();
        if self.x.val() >= self.mid.val() {
            self.ax.d.next = self.x.val() - self.mid.val();
        }
        self.ay.d.next = self.mid.val() - self.y.val();
        if self.y.val() >= self.mid.val() {
            self.ay.d.next = self.y.val() - self.mid.val();
        }
        self.az.d.next = self.mid.val() - self.z.val();
        if self.z.val() >= self.mid.val() {
            self.az.d.next = self.z.val() - self.mid.val();
        }
        self.side1.d.next.x = self.x.val();
        self.side1.d.next.y = self.y.val();
        self.side1.d.next.z = self.z.val();
        self.side1.d.next.row = self.row.val();
        self.side1.d.next.col = self.col.val();
        self.side1.d.next.lo = self.col.val() < self.half.val();
        // ---- P2: the products.
        self.prod2.d.next.xx = self.ax.q.val() * self.ax.q.val();
        self.prod2.d.next.yy = self.ay.q.val() * self.ay.q.val();
        self.prod2.d.next.zz = self.az.q.val() * self.az.q.val();
        self.prod2.d.next.ab = self.side1.q.val().x * self.side1.q.val().y;
        self.side2.d.next = self.side1.q.val();
        // ---- PF: the products in fabric flip-flops.
        self.prodf.d.next = self.prod2.q.val();
        self.sidef.d.next = self.side2.q.val();
        // ---- P3: the first sum of the squared range.
        self.xy3.d.next = self.prodf.q.val().xx + self.prodf.q.val().yy;
        self.prod3.d.next = self.prodf.q.val();
        self.side3.d.next = self.sidef.q.val();
        // ---- P4: the accumulator word.
        self.word.next = self.zero.val();
        self.word.next.points = self.one20.val();
        self.word.next.min_col = self.side3.q.val().col;
        self.word.next.max_col = self.side3.q.val().col;
        if self.side3.q.val().lo {
            self.word.next.lo_has = true;
            self.word.next.lo_max = self.side3.q.val().col;
        } else {
            self.word.next.hi_has = true;
            self.word.next.hi_min = self.side3.q.val().col;
        }
        self.word.next.first_row = self.side3.q.val().row;
        self.word.next.last_row = self.side3.q.val().row;
        self.word.next.min_x = self.side3.q.val().x;
        self.word.next.min_y = self.side3.q.val().y;
        self.word.next.min_z = self.side3.q.val().z;
        self.word.next.max_x = self.side3.q.val().x;
        self.word.next.max_y = self.side3.q.val().y;
        self.word.next.max_z = self.side3.q.val().z;
        self.word.next.r2_min = self.xy3.q.val() + self.prod3.q.val().zz;
        self.word.next.r2_max = self.xy3.q.val() + self.prod3.q.val().zz;
        self.word.next.sa = bit_cast::<35, 16>(self.side3.q.val().x);
        self.word.next.sb = bit_cast::<35, 16>(self.side3.q.val().y);
        self.word.next.sc = bit_cast::<35, 16>(self.side3.q.val().z);
        self.word.next.sxx = bit_cast::<50, 32>(self.prod3.q.val().xx);
        self.word.next.syy = bit_cast::<50, 32>(self.prod3.q.val().yy);
        self.word.next.sab = bit_cast::<51, 32>(self.prod3.q.val().ab);
        self.out.d.next = self.word.val();
        if self.rst.val() {
            self.out.d.next = self.zero.val();
        }
        self.acc.next = self.out.q.val();
    }
}
