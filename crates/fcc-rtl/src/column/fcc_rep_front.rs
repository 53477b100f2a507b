//! `FccRepFront`: the representative rows' input and A1 (docs/column-core.md,
//! item 3). A pixel is taken while nothing holds the pipeline and the
//! table has the row that enters the window with it (`ready`); taking it
//! shifts the window (`shift`) and pushes the run it starts (`push`). A1
//! holds the pixel, its hits and their labels' matches (`FccRepEq`) for
//! `FccRepMatch`; A2 the representatives of A1's rows as the window has
//! them after this cycle's rewrite (`rep_next`), for the minimum tree
//! (`v`, padded with `0xFFFF`; A2's mask says which are present). `miss`
//! is sticky until reset (a cycle after the match).

use rust_hdl::prelude::*;

use super::RunPix;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepFront {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub inp: Signal<In, RunPix>,
    pub inp_hit: Vec<Signal<In, Bit>>,
    /// The entries' and the pixel's own label matches (`FccRepEq`).
    pub inp_eq: Vec<Signal<In, Bit>>,
    pub inp_own_eq: Vec<Signal<In, Bit>>,
    pub busy: Signal<In, Bit>,
    pub head_ok: Signal<In, Bit>,
    /// The window's representatives at A1's rows with this cycle's
    /// rewrite, and A1's match's `miss`.
    pub rep_next: Vec<Signal<In, Bits<16>>>,
    pub match_miss: Signal<In, Bit>,
    pub ready: Signal<Out, Bit>,
    pub adv: Signal<Out, Bit>,
    pub shift: Signal<Out, Bit>,
    pub push: Signal<Out, Bit>,
    pub a1_pix: Signal<Out, RunPix>,
    pub a1_hit: Vec<Signal<Out, Bit>>,
    pub a1_eq: Vec<Signal<Out, Bit>>,
    pub a1_own_eq: Vec<Signal<Out, Bit>>,
    pub v: Vec<Signal<Out, Bits<16>>>,
    pub miss: Signal<Out, Bit>,
    pix_q: DFF<RunPix>,
    hit_q: Vec<DFF<Bit>>,
    eq_q: Vec<DFF<Bit>>,
    own_eq_q: Vec<DFF<Bit>>,
    rep_q: Vec<DFF<Bits<16>>>,
    /// A1's match missed last cycle (registered before `miss_q` takes it:
    /// the match is a long path).
    miss_p: DFF<Bit>,
    miss_q: DFF<Bit>,
    take: Signal<Local, Bit>,
    pix_zero: Constant<RunPix>,
    none: Constant<Bits<16>>,
}

impl FccRepFront {
    /// `ne` window entries, `n` run slots a row, `np` run slots, `nv`
    /// values for the tree.
    pub fn new(ne: usize, n: usize, np: usize, nv: usize) -> Self {
        assert!(nv >= np);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            inp_hit: vec_of(ne),
            inp_eq: vec_of(ne * n),
            inp_own_eq: vec_of(n),
            busy: Default::default(),
            head_ok: Default::default(),
            rep_next: vec_of(np),
            match_miss: Default::default(),
            ready: Default::default(),
            adv: Default::default(),
            shift: Default::default(),
            push: Default::default(),
            a1_pix: Default::default(),
            a1_hit: vec_of(ne),
            a1_eq: vec_of(ne * n),
            a1_own_eq: vec_of(n),
            v: vec_of(nv),
            miss: Default::default(),
            pix_q: Default::default(),
            hit_q: vec_of(ne),
            eq_q: vec_of(ne * n),
            own_eq_q: vec_of(n),
            rep_q: vec_of(np),
            miss_p: Default::default(),
            miss_q: Default::default(),
            take: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
            none: kb(0xFFFF),
        }
    }
}

impl Logic for FccRepFront {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, pix_q, miss_p, miss_q);
        self.adv.next = !self.busy.val();
        self.ready.next = !self.busy.val() & self.head_ok.val();
        self.take.next = self.inp.val().valid & !self.busy.val() & self.head_ok.val();
        self.shift.next = self.take.val();
        self.push.next = self.take.val() & self.inp.val().start;
        if !self.busy.val() {
            self.pix_q.d.next = self.pix_zero.val();
            if self.take.val() {
                self.pix_q.d.next = self.inp.val();
            }
        }
        for e in 0..self.hit_q.len() {
            self.hit_q[e].clock.next = self.clk.val();
            self.hit_q[e].d.next = self.hit_q[e].q.val();
            if !self.busy.val() {
                self.hit_q[e].d.next = self.inp_hit[e].val();
            }
            self.a1_hit[e].next = self.hit_q[e].q.val();
        }
        for q in 0..self.eq_q.len() {
            self.eq_q[q].clock.next = self.clk.val();
            self.eq_q[q].d.next = self.eq_q[q].q.val();
            if !self.busy.val() {
                self.eq_q[q].d.next = self.inp_eq[q].val();
            }
            self.a1_eq[q].next = self.eq_q[q].q.val();
        }
        for k in 0..self.own_eq_q.len() {
            self.own_eq_q[k].clock.next = self.clk.val();
            self.own_eq_q[k].d.next = self.own_eq_q[k].q.val();
            if !self.busy.val() {
                self.own_eq_q[k].d.next = self.inp_own_eq[k].val();
            }
            self.a1_own_eq[k].next = self.own_eq_q[k].q.val();
        }
        self.a1_pix.next = self.pix_q.q.val();
        for j in 0..self.v.len() {
            self.v[j].next = self.none.val();
        }
        for j in 0..self.rep_q.len() {
            self.rep_q[j].clock.next = self.clk.val();
            self.rep_q[j].d.next = self.rep_q[j].q.val();
            if !self.busy.val() {
                self.rep_q[j].d.next = self.rep_next[j].val();
            }
            self.v[j].next = self.rep_q[j].q.val();
        }
        self.miss_p.d.next = self.pix_q.q.val().valid & self.match_miss.val();
        if self.miss_p.q.val() {
            self.miss_q.d.next = true;
        }
        if self.rst.val() {
            self.pix_q.d.next = self.pix_zero.val();
            self.miss_p.d.next = false;
            self.miss_q.d.next = false;
        }
        self.miss.next = self.miss_q.q.val();
    }
}
