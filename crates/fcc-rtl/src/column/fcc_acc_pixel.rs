//! `FccAccPixel`: the accumulator of one pixel, [`ACC_PIXEL_LATENCY`]
//! cycles after it (no enable; every stage registered): its column (below
//! `C/2` or not: the seam span), row, point as box and sums, `|x|^2`,
//! `|y|^2`, `|z|^2` (the squared range) and `a * b`. Offset binary in:
//! `|x|` is `a - 2^15` or `2^15 - a`, at most `2^15`.
//!
//! * P1: `|x|`, `|y|`, `|z|`, which half the column is in.
//! * P2: the four 16 x 16 products (DSP multipliers with their output
//!   register).
//! * P3: `|x|^2 + |y|^2`.
//! * P4: the squared range (`+ |z|^2`) and the accumulator word.

use rust_hdl::prelude::*;

use super::AccWord;
use crate::types::kb;

/// Cycles from a pixel to its accumulator.
pub const ACC_PIXEL_LATENCY: usize = 4;

#[derive(LogicBlock)]
pub struct FccAccPixel {
    pub clk: Signal<In, Clock>,
    /// Clears the output stage (which so stays a flip-flop: a shift-register
    /// LUT's output is slow).
    pub rst: Signal<In, Bit>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    /// `C / 2` (rounded down), constant while a frame runs.
    pub half: Signal<In, Bits<12>>,
    pub acc: Signal<Out, AccWord>,
    // P1.
    ax: DFF<Bits<16>>,
    ay: DFF<Bits<16>>,
    az: DFF<Bits<16>>,
    x1: DFF<Bits<16>>,
    y1: DFF<Bits<16>>,
    z1: DFF<Bits<16>>,
    row1: DFF<Bits<7>>,
    col1: DFF<Bits<12>>,
    lo1: DFF<Bit>,
    // P2.
    xx: DFF<Bits<32>>,
    yy: DFF<Bits<32>>,
    zz: DFF<Bits<32>>,
    ab: DFF<Bits<32>>,
    x2: DFF<Bits<16>>,
    y2: DFF<Bits<16>>,
    z2: DFF<Bits<16>>,
    row2: DFF<Bits<7>>,
    col2: DFF<Bits<12>>,
    lo2: DFF<Bit>,
    // P3.
    xy3: DFF<Bits<32>>,
    zz3: DFF<Bits<32>>,
    xx3: DFF<Bits<32>>,
    yy3: DFF<Bits<32>>,
    ab3: DFF<Bits<32>>,
    x3: DFF<Bits<16>>,
    y3: DFF<Bits<16>>,
    z3: DFF<Bits<16>>,
    row3: DFF<Bits<7>>,
    col3: DFF<Bits<12>>,
    lo3: DFF<Bit>,
    // P4.
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
            x1: Default::default(),
            y1: Default::default(),
            z1: Default::default(),
            row1: Default::default(),
            col1: Default::default(),
            lo1: Default::default(),
            xx: Default::default(),
            yy: Default::default(),
            zz: Default::default(),
            ab: Default::default(),
            x2: Default::default(),
            y2: Default::default(),
            z2: Default::default(),
            row2: Default::default(),
            col2: Default::default(),
            lo2: Default::default(),
            xy3: Default::default(),
            zz3: Default::default(),
            xx3: Default::default(),
            yy3: Default::default(),
            ab3: Default::default(),
            x3: Default::default(),
            y3: Default::default(),
            z3: Default::default(),
            row3: Default::default(),
            col3: Default::default(),
            lo3: Default::default(),
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
            self, clk, ax, ay, az, x1, y1, z1, row1, col1, lo1, xx, yy, zz, ab, x2, y2, z2, row2,
            col2, lo2, xy3, zz3, xx3, yy3, ab3, x3, y3, z3, row3, col3, lo3, out
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
        self.x1.d.next = self.x.val();
        self.y1.d.next = self.y.val();
        self.z1.d.next = self.z.val();
        self.row1.d.next = self.row.val();
        self.col1.d.next = self.col.val();
        self.lo1.d.next = self.col.val() < self.half.val();
        // ---- P2: the products.
        self.xx.d.next = self.ax.q.val() * self.ax.q.val();
        self.yy.d.next = self.ay.q.val() * self.ay.q.val();
        self.zz.d.next = self.az.q.val() * self.az.q.val();
        self.ab.d.next = self.x1.q.val() * self.y1.q.val();
        self.x2.d.next = self.x1.q.val();
        self.y2.d.next = self.y1.q.val();
        self.z2.d.next = self.z1.q.val();
        self.row2.d.next = self.row1.q.val();
        self.col2.d.next = self.col1.q.val();
        self.lo2.d.next = self.lo1.q.val();
        // ---- P3: the first sum of the squared range.
        self.xy3.d.next = self.xx.q.val() + self.yy.q.val();
        self.zz3.d.next = self.zz.q.val();
        self.xx3.d.next = self.xx.q.val();
        self.yy3.d.next = self.yy.q.val();
        self.ab3.d.next = self.ab.q.val();
        self.x3.d.next = self.x2.q.val();
        self.y3.d.next = self.y2.q.val();
        self.z3.d.next = self.z2.q.val();
        self.row3.d.next = self.row2.q.val();
        self.col3.d.next = self.col2.q.val();
        self.lo3.d.next = self.lo2.q.val();
        // ---- P4: the accumulator word.
        self.word.next = self.zero.val();
        self.word.next.points = self.one20.val();
        self.word.next.min_col = self.col3.q.val();
        self.word.next.max_col = self.col3.q.val();
        if self.lo3.q.val() {
            self.word.next.lo_has = true;
            self.word.next.lo_max = self.col3.q.val();
        } else {
            self.word.next.hi_has = true;
            self.word.next.hi_min = self.col3.q.val();
        }
        self.word.next.first_row = self.row3.q.val();
        self.word.next.last_row = self.row3.q.val();
        self.word.next.min_x = self.x3.q.val();
        self.word.next.min_y = self.y3.q.val();
        self.word.next.min_z = self.z3.q.val();
        self.word.next.max_x = self.x3.q.val();
        self.word.next.max_y = self.y3.q.val();
        self.word.next.max_z = self.z3.q.val();
        self.word.next.r2_min = self.xy3.q.val() + self.zz3.q.val();
        self.word.next.r2_max = self.xy3.q.val() + self.zz3.q.val();
        self.word.next.sa = bit_cast::<35, 16>(self.x3.q.val());
        self.word.next.sb = bit_cast::<35, 16>(self.y3.q.val());
        self.word.next.sc = bit_cast::<35, 16>(self.z3.q.val());
        self.word.next.sxx = bit_cast::<50, 32>(self.xx3.q.val());
        self.word.next.syy = bit_cast::<50, 32>(self.yy3.q.val());
        self.word.next.sab = bit_cast::<51, 32>(self.ab3.q.val());
        self.out.d.next = self.word.val();
        if self.rst.val() {
            self.out.d.next = self.zero.val();
        }
        self.acc.next = self.out.q.val();
    }
}
