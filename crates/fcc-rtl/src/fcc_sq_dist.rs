//! `FccSqDist`: exact squared Euclidean distance of two Q7.8 points, three
//! registered stages (|difference|, squares, sum), advancing when `en` is high.
//!
//! Exactness: each |difference| fits 16 bits unsigned (offset-binary inputs).
//! A difference above 32768 (128 m) is clamped to 32769: any threshold is below
//! 128 m, so such a pair is never connected and stays unconnected after the
//! clamp (32769^2 > 2^30 >= t^2), while every difference that could pass is
//! kept exact. The clamp bounds the sum by 3 * 32769^2 < 2^32.

use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccSqDist {
    pub clk: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    // Operands (offset binary).
    pub ax: Signal<In, Bits<16>>,
    pub ay: Signal<In, Bits<16>>,
    pub az: Signal<In, Bits<16>>,
    pub bx: Signal<In, Bits<16>>,
    pub by: Signal<In, Bits<16>>,
    pub bz: Signal<In, Bits<16>>,
    /// Squared distance, three enabled cycles after the operands.
    pub d2: Signal<Out, Bits<32>>,
    mx: DFF<Bits<16>>,
    my: DFF<Bits<16>>,
    mz: DFF<Bits<16>>,
    sx: DFF<Bits<32>>,
    sy: DFF<Bits<32>>,
    sz: DFF<Bits<32>>,
    sum: DFF<Bits<32>>,
    dx: Signal<Local, Bits<16>>,
    dy: Signal<Local, Bits<16>>,
    dz: Signal<Local, Bits<16>>,
    limit: Constant<Bits<16>>,
    clamp: Constant<Bits<16>>,
}

impl Default for FccSqDist {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            en: Default::default(),
            ax: Default::default(),
            ay: Default::default(),
            az: Default::default(),
            bx: Default::default(),
            by: Default::default(),
            bz: Default::default(),
            d2: Default::default(),
            mx: Default::default(),
            my: Default::default(),
            mz: Default::default(),
            sx: Default::default(),
            sy: Default::default(),
            sz: Default::default(),
            sum: Default::default(),
            dx: Default::default(),
            dy: Default::default(),
            dz: Default::default(),
            limit: kb(32768),
            clamp: kb(32769),
        }
    }
}

impl Logic for FccSqDist {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, mx, my, mz, sx, sy, sz, sum);
        self.dx.next = self.bx.val() - self.ax.val();
        if self.ax.val() > self.bx.val() {
            self.dx.next = self.ax.val() - self.bx.val();
        }
        if self.dx.val() > self.limit.val() {
            self.dx.next = self.clamp.val();
        }
        self.dy.next = self.by.val() - self.ay.val();
        if self.ay.val() > self.by.val() {
            self.dy.next = self.ay.val() - self.by.val();
        }
        if self.dy.val() > self.limit.val() {
            self.dy.next = self.clamp.val();
        }
        self.dz.next = self.bz.val() - self.az.val();
        if self.az.val() > self.bz.val() {
            self.dz.next = self.az.val() - self.bz.val();
        }
        if self.dz.val() > self.limit.val() {
            self.dz.next = self.clamp.val();
        }
        if self.en.val() {
            self.mx.d.next = self.dx.val();
            self.my.d.next = self.dy.val();
            self.mz.d.next = self.dz.val();
            self.sx.d.next = self.mx.q.val() * self.mx.q.val();
            self.sy.d.next = self.my.q.val() * self.my.q.val();
            self.sz.d.next = self.mz.q.val() * self.mz.q.val();
            self.sum.d.next = (self.sx.q.val() + self.sy.q.val()) + self.sz.q.val();
        }
        self.d2.next = self.sum.q.val();
    }
}
