//! `fcc_sort_net`: reduces the window positions that matched a centre, and the
//! joins already made for the same centre run, to a few unique joins.
//!
//! Provisional labels are non-decreasing in raster order and a run never
//! leaves its row, so within one window row equal labels are contiguous among
//! the valid positions. Stage A keeps, per window row, a matched position only
//! when its label differs from the previous matched position's label, and
//! notes the two largest distinct matched labels of each row. Stage B drops
//! labels that a per-row memory says were already joined with the same centre
//! label (the last two per row, cleared when the centre label changes), then
//! compacts the survivors into FIFO entries of up to four joins (one entry per
//! cycle; a centre with more takes extra cycles and holds the front end). A
//! row's ring join is its own entry. Dropping only joins that were already
//! made never changes the connected components, so the filter is exact.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::types::{kb, Ctr, JoinEntry};

#[derive(LogicBlock)]
pub struct FccSortNet {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Clear the join counter (start of a frame).
    pub clear: Signal<In, Bit>,
    // From the distance tree.
    pub centre: Signal<In, Ctr>,
    pub hit: Vec<Signal<In, Bit>>,
    pub label: Vec<Signal<In, Bits<16>>>,
    // To the join FIFO.
    pub fifo_ok: Signal<In, Bit>,
    pub push: Signal<Out, Bit>,
    pub entry: Signal<Out, JoinEntry>,
    /// Stage B takes a new item at the next edge.
    pub ready: Signal<Out, Bit>,
    /// The frame's last pixel has left the sort network.
    pub last_done: Signal<Out, Bit>,
    /// Joins pushed in this frame.
    pub joins: Signal<Out, Bits<24>>,
    // Stage A (combinational).
    a_df: Vec<Signal<Local, Bit>>,
    a_a1: Vec<Signal<Local, Bits<16>>>,
    a_a2: Vec<Signal<Local, Bits<16>>>,
    a_h1: Vec<Signal<Local, Bit>>,
    a_h2: Vec<Signal<Local, Bit>>,
    hadm: Signal<Local, Bit>,
    lastm: Signal<Local, Bits<16>>,
    // Stage B registers.
    b_valid: DFF<Bit>,
    b_c: DFF<Bits<16>>,
    b_celig: DFF<Bit>,
    b_last: DFF<Bit>,
    b_ring: DFF<Bit>,
    b_ra: DFF<Bits<16>>,
    b_rb: DFF<Bits<16>>,
    b_ring_done: DFF<Bit>,
    b_df: Vec<DFF<Bit>>,
    b_lab: Vec<DFF<Bits<16>>>,
    b_emitted: Vec<DFF<Bit>>,
    b_a1: Vec<DFF<Bits<16>>>,
    b_a2: Vec<DFF<Bits<16>>>,
    b_h1: Vec<DFF<Bit>>,
    b_h2: Vec<DFF<Bit>>,
    // Per-row memory of joins made for centre label `mem_c`.
    mem_v: DFF<Bit>,
    mem_c: DFF<Bits<16>>,
    m1: Vec<DFF<Bits<16>>>,
    m2: Vec<DFF<Bits<16>>>,
    m1v: Vec<DFF<Bit>>,
    m2v: Vec<DFF<Bit>>,
    joins_q: DFF<Bits<24>>,
    // Stage B (combinational).
    same_c: Signal<Local, Bit>,
    keep: Vec<Signal<Local, Bit>>,
    cnt: Vec<Signal<Local, Bits<3>>>,
    n0: Signal<Local, Bits<16>>,
    n1: Signal<Local, Bits<16>>,
    n2: Signal<Local, Bits<16>>,
    n3: Signal<Local, Bits<16>>,
    v0: Signal<Local, Bit>,
    v1: Signal<Local, Bit>,
    v2: Signal<Local, Bit>,
    v3: Signal<Local, Bit>,
    has_centre: Signal<Local, Bit>,
    centre_fits: Signal<Local, Bit>,
    ring_pending: Signal<Local, Bit>,
    want: Signal<Local, Bit>,
    push_l: Signal<Local, Bit>,
    done: Signal<Local, Bit>,
    zero16: Constant<Bits<16>>,
    c0: Constant<Bits<3>>,
    c1: Constant<Bits<3>>,
    c2: Constant<Bits<3>>,
    c3: Constant<Bits<3>>,
    c4: Constant<Bits<3>>,
    c7: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    j0: Constant<Bits<24>>,
    j1: Constant<Bits<24>>,
    j2: Constant<Bits<24>>,
    j3: Constant<Bits<24>>,
    j4: Constant<Bits<24>>,
    _k: usize,
    _h: usize,
    _n: usize,
}

fn v<T: Default>(n: usize) -> Vec<T> {
    (0..n).map(|_| T::default()).collect()
}

impl FccSortNet {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            centre: Default::default(),
            hit: v(n),
            label: v(n),
            fifo_ok: Default::default(),
            push: Default::default(),
            entry: Default::default(),
            ready: Default::default(),
            last_done: Default::default(),
            joins: Default::default(),
            a_df: v(n),
            a_a1: v(h),
            a_a2: v(h),
            a_h1: v(h),
            a_h2: v(h),
            hadm: Default::default(),
            lastm: Default::default(),
            b_valid: Default::default(),
            b_c: Default::default(),
            b_celig: Default::default(),
            b_last: Default::default(),
            b_ring: Default::default(),
            b_ra: Default::default(),
            b_rb: Default::default(),
            b_ring_done: Default::default(),
            b_df: v(n),
            b_lab: v(n),
            b_emitted: v(n),
            b_a1: v(h),
            b_a2: v(h),
            b_h1: v(h),
            b_h2: v(h),
            mem_v: Default::default(),
            mem_c: Default::default(),
            m1: v(h),
            m2: v(h),
            m1v: v(h),
            m2v: v(h),
            joins_q: Default::default(),
            same_c: Default::default(),
            keep: v(n),
            cnt: v(n + 1),
            n0: Default::default(),
            n1: Default::default(),
            n2: Default::default(),
            n3: Default::default(),
            v0: Default::default(),
            v1: Default::default(),
            v2: Default::default(),
            v3: Default::default(),
            has_centre: Default::default(),
            centre_fits: Default::default(),
            ring_pending: Default::default(),
            want: Default::default(),
            push_l: Default::default(),
            done: Default::default(),
            zero16: kb(0),
            c0: kb(0),
            c1: kb(1),
            c2: kb(2),
            c3: kb(3),
            c4: kb(4),
            c7: kb(7),
            one3: kb(1),
            j0: kb(0),
            j1: kb(1),
            j2: kb(2),
            j3: kb(3),
            j4: kb(4),
            _k: k,
            _h: h,
            _n: n,
        }
    }
}

impl Logic for FccSortNet {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            b_valid,
            b_c,
            b_celig,
            b_last,
            b_ring,
            b_ra,
            b_rb,
            b_ring_done,
            mem_v,
            mem_c,
            joins_q
        );
        for e in 0..self._n {
            self.b_df[e].clock.next = self.clk.val();
            self.b_lab[e].clock.next = self.clk.val();
            self.b_emitted[e].clock.next = self.clk.val();
            self.b_df[e].d.next = self.b_df[e].q.val();
            self.b_lab[e].d.next = self.b_lab[e].q.val();
            self.b_emitted[e].d.next = self.b_emitted[e].q.val();
        }
        for r in 0..self._h {
            self.b_a1[r].clock.next = self.clk.val();
            self.b_a2[r].clock.next = self.clk.val();
            self.b_h1[r].clock.next = self.clk.val();
            self.b_h2[r].clock.next = self.clk.val();
            self.m1[r].clock.next = self.clk.val();
            self.m2[r].clock.next = self.clk.val();
            self.m1v[r].clock.next = self.clk.val();
            self.m2v[r].clock.next = self.clk.val();
            self.b_a1[r].d.next = self.b_a1[r].q.val();
            self.b_a2[r].d.next = self.b_a2[r].q.val();
            self.b_h1[r].d.next = self.b_h1[r].q.val();
            self.b_h2[r].d.next = self.b_h2[r].q.val();
            self.m1[r].d.next = self.m1[r].q.val();
            self.m2[r].d.next = self.m2[r].q.val();
            self.m1v[r].d.next = self.m1v[r].q.val();
            self.m2v[r].d.next = self.m2v[r].q.val();
        }
        // ---- Stage A: dedup within each window row; two largest distinct labels.
        for kk in self._k..(self._k + 1) {
            for r in 0..self._h {
                self.hadm.next = false;
                self.lastm.next = self.zero16.val();
                for n in 0..self._k {
                    self.a_df[r * kk + n].next = self.hit[r * kk + n].val()
                        & !(self.hadm.val() & (self.label[r * kk + n].val() == self.lastm.val()));
                    if self.hit[r * kk + n].val() {
                        self.hadm.next = true;
                        self.lastm.next = self.label[r * kk + n].val();
                    }
                }
                self.a_h1[r].next = false;
                self.a_h2[r].next = false;
                self.a_a1[r].next = self.zero16.val();
                self.a_a2[r].next = self.zero16.val();
                for t in 0..self._k {
                    if self.a_df[r * kk + kk - 1 - t].val() {
                        if !self.a_h1[r].val() {
                            self.a_a1[r].next = self.label[r * kk + kk - 1 - t].val();
                            self.a_h1[r].next = true;
                        } else if !self.a_h2[r].val() {
                            self.a_a2[r].next = self.label[r * kk + kk - 1 - t].val();
                            self.a_h2[r].next = true;
                        }
                    }
                }
            }
        }
        // ---- Stage B: memory filter and compaction.
        self.same_c.next = self.mem_v.q.val() & (self.mem_c.q.val() == self.b_c.q.val());
        self.cnt[0].next = self.c0.val();
        self.n0.next = self.zero16.val();
        self.n1.next = self.zero16.val();
        self.n2.next = self.zero16.val();
        self.n3.next = self.zero16.val();
        self.v0.next = false;
        self.v1.next = false;
        self.v2.next = false;
        self.v3.next = false;
        for kk in self._k..(self._k + 1) {
            for r in 0..self._h {
                for n in 0..self._k {
                    self.keep[r * kk + n].next = self.b_df[r * kk + n].q.val()
                        & self.b_celig.q.val()
                        & !self.b_emitted[r * kk + n].q.val()
                        & !(self.same_c.val()
                            & ((self.m1v[r].q.val()
                                & (self.b_lab[r * kk + n].q.val() == self.m1[r].q.val()))
                                | (self.m2v[r].q.val()
                                    & (self.b_lab[r * kk + n].q.val() == self.m2[r].q.val()))));
                }
            }
        }
        for e in 0..self._n {
            self.cnt[e + 1].next = self.cnt[e].val();
            if self.keep[e].val() & (self.cnt[e].val() != self.c7.val()) {
                self.cnt[e + 1].next = self.cnt[e].val() + self.one3.val();
            }
            if self.keep[e].val() {
                if self.cnt[e].val() == self.c0.val() {
                    self.n0.next = self.b_lab[e].q.val();
                    self.v0.next = true;
                }
                if self.cnt[e].val() == self.c1.val() {
                    self.n1.next = self.b_lab[e].q.val();
                    self.v1.next = true;
                }
                if self.cnt[e].val() == self.c2.val() {
                    self.n2.next = self.b_lab[e].q.val();
                    self.v2.next = true;
                }
                if self.cnt[e].val() == self.c3.val() {
                    self.n3.next = self.b_lab[e].q.val();
                    self.v3.next = true;
                }
            }
        }
        for nn in self._n..(self._n + 1) {
            self.has_centre.next = self.cnt[nn].val() != self.c0.val();
            self.centre_fits.next = self.cnt[nn].val() <= self.c4.val();
        }
        self.ring_pending.next = self.b_ring.q.val() & !self.b_ring_done.q.val();
        self.want.next = self.has_centre.val() | self.ring_pending.val();
        self.push_l.next = self.b_valid.q.val() & self.want.val() & self.fifo_ok.val();
        self.entry.next.c = self.b_c.q.val();
        self.entry.next.n0 = self.n0.val();
        self.entry.next.n1 = self.n1.val();
        self.entry.next.n2 = self.n2.val();
        self.entry.next.n3 = self.n3.val();
        self.entry.next.v0 = self.v0.val();
        self.entry.next.v1 = self.v1.val();
        self.entry.next.v2 = self.v2.val();
        self.entry.next.v3 = self.v3.val();
        if !self.has_centre.val() {
            self.entry.next.c = self.b_ra.q.val();
            self.entry.next.n0 = self.b_rb.q.val();
            self.entry.next.v0 = true;
        }
        self.push.next = self.push_l.val();
        self.done.next = self.b_valid.q.val()
            & (!self.want.val()
                | (self.push_l.val()
                    & ((self.has_centre.val()
                        & self.centre_fits.val()
                        & !self.ring_pending.val())
                        | (!self.has_centre.val() & self.ring_pending.val()))));
        self.ready.next = !self.b_valid.q.val() | self.done.val();
        self.last_done.next = self.done.val() & self.b_last.q.val();
        // Progress within a held item.
        if self.push_l.val() & self.has_centre.val() {
            for e in 0..self._n {
                if self.keep[e].val() & (self.cnt[e].val() < self.c4.val()) {
                    self.b_emitted[e].d.next = true;
                }
            }
        }
        if self.push_l.val() & !self.has_centre.val() {
            self.b_ring_done.d.next = true;
        }
        // Join counter.
        if self.push_l.val() {
            if self.v3.val() {
                self.joins_q.d.next = self.joins_q.q.val() + self.j4.val();
            } else if self.v2.val() {
                self.joins_q.d.next = self.joins_q.q.val() + self.j3.val();
            } else if self.v1.val() {
                self.joins_q.d.next = self.joins_q.q.val() + self.j2.val();
            } else {
                self.joins_q.d.next = self.joins_q.q.val() + self.j1.val();
            }
        }
        if self.clear.val() {
            self.joins_q.d.next = self.j0.val();
        }
        self.joins.next = self.joins_q.q.val();
        // Memory update when a centre with joins completes.
        if self.done.val() & self.b_celig.q.val() {
            self.mem_v.d.next = true;
            self.mem_c.d.next = self.b_c.q.val();
            for r in 0..self._h {
                if !self.same_c.val() {
                    self.m1[r].d.next = self.b_a1[r].q.val();
                    self.m2[r].d.next = self.b_a2[r].q.val();
                    self.m1v[r].d.next = self.b_h1[r].q.val();
                    self.m2v[r].d.next = self.b_h2[r].q.val();
                } else if self.b_h2[r].q.val() {
                    self.m1[r].d.next = self.b_a1[r].q.val();
                    self.m2[r].d.next = self.b_a2[r].q.val();
                    self.m1v[r].d.next = true;
                    self.m2v[r].d.next = true;
                } else if self.b_h1[r].q.val()
                    & !(self.m1v[r].q.val() & (self.b_a1[r].q.val() == self.m1[r].q.val()))
                {
                    self.m1[r].d.next = self.b_a1[r].q.val();
                    self.m2[r].d.next = self.m1[r].q.val();
                    self.m1v[r].d.next = true;
                    self.m2v[r].d.next = self.m1v[r].q.val();
                }
            }
        }
        if self.done.val() & self.b_last.q.val() {
            self.mem_v.d.next = false;
        }
        // Load the next item.
        if self.ready.val() {
            self.b_valid.d.next = self.centre.val().valid;
            self.b_c.d.next = self.centre.val().label;
            self.b_celig.d.next = self.centre.val().valid
                & self.centre.val().ok
                & (self.centre.val().label != self.zero16.val());
            self.b_last.d.next = self.centre.val().valid & self.centre.val().last;
            self.b_ring.d.next = self.centre.val().valid & self.centre.val().ring;
            self.b_ra.d.next = self.centre.val().ring_a;
            self.b_rb.d.next = self.centre.val().ring_b;
            self.b_ring_done.d.next = false;
            for e in 0..self._n {
                self.b_df[e].d.next = self.a_df[e].val();
                self.b_lab[e].d.next = self.label[e].val();
                self.b_emitted[e].d.next = false;
            }
            for r in 0..self._h {
                self.b_a1[r].d.next = self.a_a1[r].val();
                self.b_a2[r].d.next = self.a_a2[r].val();
                self.b_h1[r].d.next = self.a_h1[r].val();
                self.b_h2[r].d.next = self.a_h2[r].val();
            }
        }
        if self.rst.val() {
            self.b_valid.d.next = false;
            self.mem_v.d.next = false;
        }
    }
}
