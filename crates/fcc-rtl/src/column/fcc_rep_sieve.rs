//! `FccRepSieve`: a pixel's first join and the rest flagged, in four
//! stages after B (docs/column-core.md, item 3), each moving while `go`
//! and holding while R replays a pixel:
//!
//! * C: the window's values as they were at B, flagged where the pixel
//!   names them with a value other than its `m`;
//! * D: the first flag (`FccRepFirst`), cleared;
//! * E: its value `x` (`FccRepTake`), the pixel's first join `(x, m)`;
//! * F: the flags left, those equal to `x` cleared: `more` says the pixel
//!   has a further join.

use rust_hdl::prelude::*;

use super::fcc_rep_first::FccRepFirst;
use super::fcc_rep_take::FccRepTake;
use super::RunPix;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepSieve {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub go: Signal<In, Bit>,
    pub b_pix: Signal<In, RunPix>,
    pub b_mask: Vec<Signal<In, Bit>>,
    pub b_val: Vec<Signal<In, Bits<16>>>,
    pub b_m: Signal<In, Bits<16>>,
    /// F: the pixel, its `m`, its first join `x` (`any`: it has one), the
    /// flags left and the values.
    pub pix: Signal<Out, RunPix>,
    pub m: Signal<Out, Bits<16>>,
    pub x: Signal<Out, Bits<16>>,
    pub any: Signal<Out, Bit>,
    pub more: Signal<Out, Bit>,
    pub left: Vec<Signal<Out, Bit>>,
    pub val: Vec<Signal<Out, Bits<16>>>,
    first: FccRepFirst,
    take: FccRepTake,
    c_pix: DFF<RunPix>,
    c_f: Vec<DFF<Bit>>,
    c_val: Vec<DFF<Bits<16>>>,
    c_m: DFF<Bits<16>>,
    d_pix: DFF<RunPix>,
    d_first: Vec<DFF<Bit>>,
    d_f: Vec<DFF<Bit>>,
    d_val: Vec<DFF<Bits<16>>>,
    d_m: DFF<Bits<16>>,
    d_any: DFF<Bit>,
    e_pix: DFF<RunPix>,
    e_f: Vec<DFF<Bit>>,
    e_val: Vec<DFF<Bits<16>>>,
    e_m: DFF<Bits<16>>,
    e_x: FccFanoutReg<Bits<16>>,
    e_any: DFF<Bit>,
    f_pix: DFF<RunPix>,
    f_g: Vec<DFF<Bit>>,
    f_val: Vec<DFF<Bits<16>>>,
    f_m: DFF<Bits<16>>,
    f_x: DFF<Bits<16>>,
    f_any: DFF<Bit>,
    pix_zero: Constant<RunPix>,
}

impl FccRepSieve {
    /// `n` window positions.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            go: Default::default(),
            b_pix: Default::default(),
            b_mask: vec_of(n),
            b_val: vec_of(n),
            b_m: Default::default(),
            pix: Default::default(),
            m: Default::default(),
            x: Default::default(),
            any: Default::default(),
            more: Default::default(),
            left: vec_of(n),
            val: vec_of(n),
            first: FccRepFirst::new(n),
            take: FccRepTake::new(n),
            c_pix: Default::default(),
            c_f: vec_of(n),
            c_val: vec_of(n),
            c_m: Default::default(),
            d_pix: Default::default(),
            d_first: vec_of(n),
            d_f: vec_of(n),
            d_val: vec_of(n),
            d_m: Default::default(),
            d_any: Default::default(),
            e_pix: Default::default(),
            e_f: vec_of(n),
            e_val: vec_of(n),
            e_m: Default::default(),
            e_x: Default::default(),
            e_any: Default::default(),
            f_pix: Default::default(),
            f_g: vec_of(n),
            f_val: vec_of(n),
            f_m: Default::default(),
            f_x: Default::default(),
            f_any: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
        }
    }
}

impl Logic for FccRepSieve {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, c_pix, c_m, d_pix, d_m, d_any, e_pix, e_m, e_x, e_any, f_pix, f_m, f_x,
            f_any
        );
        self.more.next = false;
        for b in 0..self.b_mask.len() {
            self.c_f[b].clock.next = self.clk.val();
            self.c_val[b].clock.next = self.clk.val();
            self.d_first[b].clock.next = self.clk.val();
            self.d_f[b].clock.next = self.clk.val();
            self.d_val[b].clock.next = self.clk.val();
            self.e_f[b].clock.next = self.clk.val();
            self.e_val[b].clock.next = self.clk.val();
            self.f_g[b].clock.next = self.clk.val();
            self.f_val[b].clock.next = self.clk.val();
            self.c_f[b].d.next = self.c_f[b].q.val();
            self.c_val[b].d.next = self.c_val[b].q.val();
            self.d_first[b].d.next = self.d_first[b].q.val();
            self.d_f[b].d.next = self.d_f[b].q.val();
            self.d_val[b].d.next = self.d_val[b].q.val();
            self.e_f[b].d.next = self.e_f[b].q.val();
            self.e_val[b].d.next = self.e_val[b].q.val();
            self.f_g[b].d.next = self.f_g[b].q.val();
            self.f_val[b].d.next = self.f_val[b].q.val();
            self.first.flag[b].next = self.c_f[b].q.val();
            self.take.first[b].next = self.d_first[b].q.val();
            self.take.val[b].next = self.d_val[b].q.val();
            self.left[b].next = self.f_g[b].q.val();
            self.val[b].next = self.f_val[b].q.val();
            if self.f_g[b].q.val() {
                self.more.next = true;
            }
        }
        if self.go.val() {
            self.c_pix.d.next = self.b_pix.val();
            self.c_m.d.next = self.b_m.val();
            self.d_pix.d.next = self.c_pix.q.val();
            self.d_m.d.next = self.c_m.q.val();
            self.d_any.d.next = self.first.any.val();
            self.e_pix.d.next = self.d_pix.q.val();
            self.e_m.d.next = self.d_m.q.val();
            self.e_x.d.next = self.take.x.val();
            self.e_any.d.next = self.d_any.q.val();
            self.f_pix.d.next = self.e_pix.q.val();
            self.f_m.d.next = self.e_m.q.val();
            self.f_x.d.next = self.e_x.q.val();
            self.f_any.d.next = self.e_any.q.val();
            for b in 0..self.b_mask.len() {
                self.c_f[b].d.next = self.b_mask[b].val() & (self.b_val[b].val() != self.b_m.val());
                self.c_val[b].d.next = self.b_val[b].val();
                self.d_first[b].d.next = self.first.first[b].val();
                self.d_f[b].d.next = self.c_f[b].q.val() & !self.first.first[b].val();
                self.d_val[b].d.next = self.c_val[b].q.val();
                self.e_f[b].d.next = self.d_f[b].q.val();
                self.e_val[b].d.next = self.d_val[b].q.val();
                self.f_g[b].d.next =
                    self.e_f[b].q.val() & (self.e_val[b].q.val() != self.e_x.q.val());
                self.f_val[b].d.next = self.e_val[b].q.val();
            }
        }
        self.pix.next = self.f_pix.q.val();
        self.m.next = self.f_m.q.val();
        self.x.next = self.f_x.q.val();
        self.any.next = self.f_any.q.val();
        if self.rst.val() {
            self.c_pix.d.next = self.pix_zero.val();
            self.d_pix.d.next = self.pix_zero.val();
            self.e_pix.d.next = self.pix_zero.val();
            self.f_pix.d.next = self.pix_zero.val();
        }
    }
}
