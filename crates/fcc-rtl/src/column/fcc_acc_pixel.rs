//! `FccAccPixel`: the accumulator of one pixel (combinational): its
//! column (below `C/2` or not: the seam span), row, point as box and sums,
//! `|x|^2`, `|y|^2`, `|z|^2` (the squared range) and `a * b` from three
//! 16 x 16 products and one more. Offset binary in: `|x|` is `a - 2^15` or
//! `2^15 - a`, at most `2^15`.

use rust_hdl::prelude::*;

use super::AccWord;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccAccPixel {
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    /// `C / 2` (rounded down), constant while a frame runs.
    pub half: Signal<In, Bits<12>>,
    pub acc: Signal<Out, AccWord>,
    ax: Signal<Local, Bits<16>>,
    ay: Signal<Local, Bits<16>>,
    az: Signal<Local, Bits<16>>,
    xx: Signal<Local, Bits<32>>,
    yy: Signal<Local, Bits<32>>,
    zz: Signal<Local, Bits<32>>,
    ab: Signal<Local, Bits<32>>,
    r2: Signal<Local, Bits<32>>,
    zero: Constant<AccWord>,
    one20: Constant<Bits<20>>,
    mid: Constant<Bits<16>>,
}

impl Default for FccAccPixel {
    fn default() -> Self {
        Self {
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
            xx: Default::default(),
            yy: Default::default(),
            zz: Default::default(),
            ab: Default::default(),
            r2: Default::default(),
            zero: Constant::new(AccWord::default()),
            one20: kb(1),
            mid: kb(0x8000),
        }
    }
}

impl Logic for FccAccPixel {
    #[hdl_gen]
    fn update(&mut self) {
        // |x|, |y|, |z| from offset binary.
        self.ax.next = self.mid.val() - self.x.val();
        if self.x.val() >= self.mid.val() {
            self.ax.next = self.x.val() - self.mid.val();
        }
        self.ay.next = self.mid.val() - self.y.val();
        if self.y.val() >= self.mid.val() {
            self.ay.next = self.y.val() - self.mid.val();
        }
        self.az.next = self.mid.val() - self.z.val();
        if self.z.val() >= self.mid.val() {
            self.az.next = self.z.val() - self.mid.val();
        }
        self.xx.next = self.ax.val() * self.ax.val();
        self.yy.next = self.ay.val() * self.ay.val();
        self.zz.next = self.az.val() * self.az.val();
        self.ab.next = self.x.val() * self.y.val();
        self.r2.next = (self.xx.val() + self.yy.val()) + self.zz.val();
        self.acc.next = self.zero.val();
        self.acc.next.points = self.one20.val();
        self.acc.next.min_col = self.col.val();
        self.acc.next.max_col = self.col.val();
        if self.col.val() < self.half.val() {
            self.acc.next.lo_has = true;
            self.acc.next.lo_max = self.col.val();
        } else {
            self.acc.next.hi_has = true;
            self.acc.next.hi_min = self.col.val();
        }
        self.acc.next.first_row = self.row.val();
        self.acc.next.last_row = self.row.val();
        self.acc.next.min_x = self.x.val();
        self.acc.next.min_y = self.y.val();
        self.acc.next.min_z = self.z.val();
        self.acc.next.max_x = self.x.val();
        self.acc.next.max_y = self.y.val();
        self.acc.next.max_z = self.z.val();
        self.acc.next.r2_min = self.r2.val();
        self.acc.next.r2_max = self.r2.val();
        self.acc.next.sa = bit_cast::<35, 16>(self.x.val());
        self.acc.next.sb = bit_cast::<35, 16>(self.y.val());
        self.acc.next.sc = bit_cast::<35, 16>(self.z.val());
        self.acc.next.sxx = bit_cast::<50, 32>(self.xx.val());
        self.acc.next.syy = bit_cast::<50, 32>(self.yy.val());
        self.acc.next.sab = bit_cast::<51, 32>(self.ab.val());
    }
}
