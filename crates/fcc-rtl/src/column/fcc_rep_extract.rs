//! `FccRepExtract`: a pixel's joins, one a cycle, then the pixel
//! (docs/column-core.md, item 3). At B the pixel's smallest representative
//! `m` is known and the window still holds every earlier pixel's rewrite
//! but not its own: `b_mask` says which window positions it names with a
//! value other than `m`, `b_val` holds the values. Each distinct flagged
//! value `x` is one join, `(x, m)`; at the last column the ring check's
//! pair is one more.
//!
//! * C holds the values and flags those named other than `m`; D picks the first flagged value
//!   (`FccRepPick`) and clears its position; E clears the positions equal
//!   to it.
//! * R sends the join D picked with the pixel, and the pixel itself, in
//!   one cycle when no other join is left. Otherwise `busy` (a flip-flop)
//!   holds every stage while R picks the next value (`Pick`), sends it and
//!   clears its equals (`Check`), until `Pick` finds none left, then sends
//!   the ring pair (`Ring`): two cycles a further join, one to find none
//!   left, one for the ring pair, one to leave.
//!
//! In a cycle the join comes before the pixel, so a pixel leaves after
//! all its joins.

use rust_hdl::prelude::*;

use super::fcc_rep_pick::FccRepPick;
use super::RunPix;
use crate::types::vec_of;

/// What R does next while it holds a pixel.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum ReplayStep {
    Idle,
    Pick,
    Check,
    Ring,
}

#[derive(LogicBlock)]
pub struct FccRepExtract {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The pixel at B (captured when not `busy`).
    pub b_pix: Signal<In, RunPix>,
    pub b_mask: Vec<Signal<In, Bit>>,
    pub b_val: Vec<Signal<In, Bits<16>>>,
    pub b_m: Signal<In, Bits<16>>,
    pub busy: Signal<Out, Bit>,
    pub out: Signal<Out, RunPix>,
    pub j_valid: Signal<Out, Bit>,
    pub j_a: Signal<Out, Bits<16>>,
    pub j_b: Signal<Out, Bits<16>>,
    pick_d: FccRepPick,
    pick_r: FccRepPick,
    c_pix: DFF<RunPix>,
    c_f: Vec<DFF<Bit>>,
    c_val: Vec<DFF<Bits<16>>>,
    c_m: DFF<Bits<16>>,
    d_pix: DFF<RunPix>,
    d_f: Vec<DFF<Bit>>,
    d_val: Vec<DFF<Bits<16>>>,
    d_m: DFF<Bits<16>>,
    d_x: DFF<Bits<16>>,
    d_any: DFF<Bit>,
    e_pix: DFF<RunPix>,
    e_g: Vec<DFF<Bit>>,
    e_val: Vec<DFF<Bits<16>>>,
    e_m: DFF<Bits<16>>,
    e_x: DFF<Bits<16>>,
    e_any: DFF<Bit>,
    r_pix: DFF<RunPix>,
    r_rem: Vec<DFF<Bit>>,
    r_val: Vec<DFF<Bits<16>>>,
    r_m: DFF<Bits<16>>,
    r_x: DFF<Bits<16>>,
    r_emit: DFF<Bit>,
    r_step: DFF<ReplayStep>,
    rb: DFF<Bit>,
    e_more: Signal<Local, Bit>,
    /// R's flags with its value `r_x` cleared.
    rem2: Vec<Signal<Local, Bit>>,
    pix_zero: Constant<RunPix>,
}

impl FccRepExtract {
    /// `n` window positions.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            b_pix: Default::default(),
            b_mask: vec_of(n),
            b_val: vec_of(n),
            b_m: Default::default(),
            busy: Default::default(),
            out: Default::default(),
            j_valid: Default::default(),
            j_a: Default::default(),
            j_b: Default::default(),
            pick_d: FccRepPick::new(n),
            pick_r: FccRepPick::new(n),
            c_pix: Default::default(),
            c_f: vec_of(n),
            c_val: vec_of(n),
            c_m: Default::default(),
            d_pix: Default::default(),
            d_f: vec_of(n),
            d_val: vec_of(n),
            d_m: Default::default(),
            d_x: Default::default(),
            d_any: Default::default(),
            e_pix: Default::default(),
            e_g: vec_of(n),
            e_val: vec_of(n),
            e_m: Default::default(),
            e_x: Default::default(),
            e_any: Default::default(),
            r_pix: Default::default(),
            r_rem: vec_of(n),
            r_val: vec_of(n),
            r_m: Default::default(),
            r_x: Default::default(),
            r_emit: Default::default(),
            r_step: Default::default(),
            rb: Default::default(),
            e_more: Default::default(),
            rem2: vec_of(n),
            pix_zero: Constant::new(RunPix::default()),
        }
    }
}

impl Logic for FccRepExtract {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, c_pix, c_m, d_pix, d_m, d_x, d_any, e_pix, e_m, e_x, e_any, r_pix, r_m, r_x,
            r_emit, r_step, rb
        );
        for b in 0..self.b_mask.len() {
            self.c_f[b].clock.next = self.clk.val();
            self.c_val[b].clock.next = self.clk.val();
            self.d_f[b].clock.next = self.clk.val();
            self.d_val[b].clock.next = self.clk.val();
            self.e_g[b].clock.next = self.clk.val();
            self.e_val[b].clock.next = self.clk.val();
            self.r_rem[b].clock.next = self.clk.val();
            self.r_val[b].clock.next = self.clk.val();
            self.c_f[b].d.next = self.c_f[b].q.val();
            self.c_val[b].d.next = self.c_val[b].q.val();
            self.d_f[b].d.next = self.d_f[b].q.val();
            self.d_val[b].d.next = self.d_val[b].q.val();
            self.e_g[b].d.next = self.e_g[b].q.val();
            self.e_val[b].d.next = self.e_val[b].q.val();
            self.r_rem[b].d.next = self.r_rem[b].q.val();
            self.r_val[b].d.next = self.r_val[b].q.val();
            self.pick_d.flag[b].next = self.c_f[b].q.val();
            self.pick_d.val[b].next = self.c_val[b].q.val();
            self.pick_r.flag[b].next = self.r_rem[b].q.val();
            self.pick_r.val[b].next = self.r_val[b].q.val();
            self.rem2[b].next = self.r_rem[b].q.val() & (self.r_val[b].q.val() != self.r_x.q.val());
        }
        self.e_more.next = false;
        for b in 0..self.b_mask.len() {
            if self.e_g[b].q.val() {
                self.e_more.next = true;
            }
        }
        // C, D, E move on unless R holds a pixel.
        if !self.rb.q.val() {
            self.c_pix.d.next = self.b_pix.val();
            self.c_m.d.next = self.b_m.val();
            self.d_pix.d.next = self.c_pix.q.val();
            self.d_m.d.next = self.c_m.q.val();
            self.d_x.d.next = self.pick_d.x.val();
            self.d_any.d.next = self.pick_d.any.val();
            self.e_pix.d.next = self.d_pix.q.val();
            self.e_m.d.next = self.d_m.q.val();
            self.e_x.d.next = self.d_x.q.val();
            self.e_any.d.next = self.d_any.q.val();
            for b in 0..self.b_mask.len() {
                self.c_f[b].d.next = self.b_mask[b].val() & (self.b_val[b].val() != self.b_m.val());
                self.c_val[b].d.next = self.b_val[b].val();
                self.d_f[b].d.next = self.c_f[b].q.val() & !self.pick_d.first[b].val();
                self.d_val[b].d.next = self.c_val[b].q.val();
                self.e_g[b].d.next =
                    self.d_f[b].q.val() & (self.d_val[b].q.val() != self.d_x.q.val());
                self.e_val[b].d.next = self.d_val[b].q.val();
                self.r_rem[b].d.next = self.e_g[b].q.val();
                self.r_val[b].d.next = self.e_val[b].q.val();
            }
            // R takes E's pixel.
            self.r_pix.d.next = self.e_pix.q.val();
            self.r_m.d.next = self.e_m.q.val();
            self.r_x.d.next = self.e_x.q.val();
            self.r_emit.d.next = self.e_pix.q.val().valid & self.e_any.q.val();
            self.r_step.d.next = ReplayStep::Idle;
            if self.e_pix.q.val().valid & self.e_pix.q.val().ring {
                self.r_step.d.next = ReplayStep::Ring;
                self.rb.d.next = true;
            }
            if self.e_pix.q.val().valid & self.e_more.val() {
                self.r_step.d.next = ReplayStep::Pick;
                self.rb.d.next = true;
            }
        } else {
            match self.r_step.q.val() {
                ReplayStep::Idle => {}
                ReplayStep::Pick => {
                    self.r_emit.d.next = false;
                    if self.pick_r.any.val() {
                        self.r_x.d.next = self.pick_r.x.val();
                        self.r_emit.d.next = true;
                        self.r_step.d.next = ReplayStep::Check;
                        for b in 0..self.b_mask.len() {
                            self.r_rem[b].d.next =
                                self.r_rem[b].q.val() & !self.pick_r.first[b].val();
                        }
                    } else if self.r_pix.q.val().ring {
                        self.r_step.d.next = ReplayStep::Ring;
                    } else {
                        self.r_step.d.next = ReplayStep::Idle;
                        self.rb.d.next = false;
                    }
                }
                ReplayStep::Check => {
                    self.r_emit.d.next = false;
                    self.r_step.d.next = ReplayStep::Pick;
                    for b in 0..self.b_mask.len() {
                        self.r_rem[b].d.next = self.rem2[b].val();
                    }
                }
                ReplayStep::Ring => {
                    self.r_emit.d.next = false;
                    if !self.r_emit.q.val() {
                        self.r_step.d.next = ReplayStep::Idle;
                        self.rb.d.next = false;
                    }
                }
            }
        }
        // Out: R's join, then R's pixel once nothing holds it.
        self.busy.next = self.rb.q.val();
        self.j_valid.next = self.r_pix.q.val().valid
            & (self.r_emit.q.val() | ((self.r_step.q.val() == ReplayStep::Ring) & self.rb.q.val()));
        self.j_a.next = self.r_pix.q.val().ring_a;
        self.j_b.next = self.r_pix.q.val().ring_b;
        if self.r_emit.q.val() {
            self.j_a.next = self.r_x.q.val();
            self.j_b.next = self.r_m.q.val();
        }
        self.out.next = self.pix_zero.val();
        if !self.rb.q.val() {
            self.out.next = self.r_pix.q.val();
        }
        if self.rst.val() {
            self.c_pix.d.next = self.pix_zero.val();
            self.d_pix.d.next = self.pix_zero.val();
            self.e_pix.d.next = self.pix_zero.val();
            self.r_pix.d.next = self.pix_zero.val();
            self.r_emit.d.next = false;
            self.r_step.d.next = ReplayStep::Idle;
            self.rb.d.next = false;
        }
    }
}
