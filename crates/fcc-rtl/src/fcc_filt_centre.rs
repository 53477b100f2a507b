//! `FccFiltCentre`: the sort filter's centre from stage to stage. In S0 it
//! finds the centre's run (`same_run`: same label as the last labelled
//! centre of the frame, forgotten after the frame's last centre) and it
//! carries the centre and its ring join through S1, the minimum tree's
//! stages S2 .. SL, SM = S(L+1), SM+1 and SM+2 (`FccSortFilter`'s module
//! documentation), L being the tree's levels. Each stage shows the fields
//! the filter reads there, one port per field.
//!
//! Reset: `rst` is the reset one cycle ahead. `valid_rst`, its registered
//! copy, clears the run memory and the valid flags; for tree stage i,
//! `tree_rst[2i]` clears the centre (33 flip-flops, reset whole so that the
//! stage stays a flip-flop rather than a shift register) and
//! `tree_rst[2i + 1]` its ring join (32).

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_keep_reg::FccKeepReg;
use crate::types::vec_of;

/// What the filter carries about a centre from stage to stage.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct FiltCtr {
    pub valid: Bit,
    /// A labelled point: it can join.
    pub elig: Bit,
    /// Same label as the last labelled centre of the frame.
    pub same_run: Bit,
    pub c: Bits<16>,
    pub col: Bits<12>,
    pub last: Bit,
    pub ring: Bit,
}

/// The centre's ring join (valid with `FiltCtr::ring`), carried beside it.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RingJoin {
    pub a: Bits<16>,
    pub b: Bits<16>,
}

#[derive(LogicBlock)]
pub struct FccFiltCentre {
    pub clk: Signal<In, Clock>,
    /// Reset, one cycle ahead.
    pub rst: Signal<In, Bit>,
    // The centre (S0): `Ctr`'s fields.
    pub valid: Signal<In, Bit>,
    pub lok: Signal<In, Bit>,
    pub label: Signal<In, Bits<16>>,
    pub col: Signal<In, Bits<12>>,
    pub last: Signal<In, Bit>,
    pub ring: Signal<In, Bit>,
    pub ring_a: Signal<In, Bits<16>>,
    pub ring_b: Signal<In, Bits<16>>,
    // S1 (the known mask).
    pub s1_valid: Signal<Out, Bit>,
    pub s1_elig: Signal<Out, Bit>,
    pub s1_same_run: Signal<Out, Bit>,
    // SM (the run's representative and the write-back).
    pub sm_valid: Signal<Out, Bit>,
    pub sm_elig: Signal<Out, Bit>,
    pub sm_same_run: Signal<Out, Bit>,
    pub sm_c: Signal<Out, Bits<16>>,
    pub sm_col: Signal<Out, Bits<12>>,
    // SM+1 (the kept matches).
    pub sm1_elig: Signal<Out, Bit>,
    // SM+2 (the record request).
    pub sm2_valid: Signal<Out, Bit>,
    pub sm2_ring: Signal<Out, Bit>,
    pub sm2_last: Signal<Out, Bit>,
    pub sm2_ring_a: Signal<Out, Bits<16>>,
    pub sm2_ring_b: Signal<Out, Bits<16>>,
    last_label: DFF<Bits<16>>,
    last_label_valid: DFF<Bit>,
    ctr_s0: Signal<Local, FiltCtr>,
    ring_s0: Signal<Local, RingJoin>,
    ctr_s1: FccFanoutReg<FiltCtr>,
    ctr_tree: Vec<DFF<FiltCtr>>,
    ctr_sm: FccFanoutReg<FiltCtr>,
    ctr_sm1: DFF<FiltCtr>,
    ctr_sm2: DFF<FiltCtr>,
    ring_s1: DFF<RingJoin>,
    ring_tree: Vec<DFF<RingJoin>>,
    ring_sm: DFF<RingJoin>,
    ring_sm1: DFF<RingJoin>,
    ring_sm2: DFF<RingJoin>,
    valid_rst: FccKeepReg<Bit>,
    tree_rst: Vec<FccKeepReg<Bit>>,
    ctr_zero: Constant<FiltCtr>,
    ring_zero: Constant<RingJoin>,
    /// Levels of the minimum tree.
    _l: usize,
}

impl FccFiltCentre {
    /// The pipeline around a minimum tree of `l` levels (at least 2).
    pub fn new(l: usize) -> Self {
        assert!(l >= 2, "a minimum tree of at least two levels");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            lok: Default::default(),
            label: Default::default(),
            col: Default::default(),
            last: Default::default(),
            ring: Default::default(),
            ring_a: Default::default(),
            ring_b: Default::default(),
            s1_valid: Default::default(),
            s1_elig: Default::default(),
            s1_same_run: Default::default(),
            sm_valid: Default::default(),
            sm_elig: Default::default(),
            sm_same_run: Default::default(),
            sm_c: Default::default(),
            sm_col: Default::default(),
            sm1_elig: Default::default(),
            sm2_valid: Default::default(),
            sm2_ring: Default::default(),
            sm2_last: Default::default(),
            sm2_ring_a: Default::default(),
            sm2_ring_b: Default::default(),
            last_label: Default::default(),
            last_label_valid: Default::default(),
            ctr_s0: Default::default(),
            ring_s0: Default::default(),
            ctr_s1: Default::default(),
            ctr_tree: vec_of(l - 1),
            ctr_sm: Default::default(),
            ctr_sm1: Default::default(),
            ctr_sm2: Default::default(),
            ring_s1: Default::default(),
            ring_tree: vec_of(l - 1),
            ring_sm: Default::default(),
            ring_sm1: Default::default(),
            ring_sm2: Default::default(),
            valid_rst: Default::default(),
            tree_rst: vec_of(2 * (l - 1)),
            ctr_zero: Constant::new(FiltCtr::default()),
            ring_zero: Constant::new(RingJoin::default()),
            _l: l,
        }
    }
}

impl Logic for FccFiltCentre {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            last_label,
            last_label_valid,
            ctr_s1,
            ctr_sm,
            ctr_sm1,
            ctr_sm2,
            ring_s1,
            ring_sm,
            ring_sm1,
            ring_sm2
        );
        for i in 0..(self._l - 1) {
            self.ctr_tree[i].clock.next = self.clk.val();
            self.ring_tree[i].clock.next = self.clk.val();
        }
        self.valid_rst.clock.next = self.clk.val();
        self.valid_rst.d.next = self.rst.val();
        for i in 0..(2 * (self._l - 1)) {
            self.tree_rst[i].clock.next = self.clk.val();
            self.tree_rst[i].d.next = self.rst.val();
        }
        // ---- S0: the centre's run.
        self.ctr_s0.next.valid = self.valid.val();
        self.ctr_s0.next.elig = self.valid.val() & self.lok.val();
        self.ctr_s0.next.same_run =
            self.last_label_valid.q.val() & (self.label.val() == self.last_label.q.val());
        self.ctr_s0.next.c = self.label.val();
        self.ctr_s0.next.col = self.col.val();
        self.ctr_s0.next.last = self.last.val();
        self.ctr_s0.next.ring = self.ring.val();
        self.ring_s0.next.a = self.ring_a.val();
        self.ring_s0.next.b = self.ring_b.val();
        if self.valid.val() & self.lok.val() {
            self.last_label.d.next = self.label.val();
            self.last_label_valid.d.next = true;
        }
        if self.valid.val() & self.last.val() {
            self.last_label_valid.d.next = false;
        }
        // ---- S1 .. SM+2.
        self.ctr_s1.d.next = self.ctr_s0.val();
        self.ctr_tree[0].d.next = self.ctr_s1.q.val();
        for i in 1..(self._l - 1) {
            self.ctr_tree[i].d.next = self.ctr_tree[i - 1].q.val();
        }
        for l in self._l..(self._l + 1) {
            self.ctr_sm.d.next = self.ctr_tree[l - 2].q.val();
        }
        self.ctr_sm1.d.next = self.ctr_sm.q.val();
        self.ctr_sm2.d.next = self.ctr_sm1.q.val();
        self.ring_s1.d.next = self.ring_s0.val();
        self.ring_tree[0].d.next = self.ring_s1.q.val();
        for i in 1..(self._l - 1) {
            self.ring_tree[i].d.next = self.ring_tree[i - 1].q.val();
        }
        for l in self._l..(self._l + 1) {
            self.ring_sm.d.next = self.ring_tree[l - 2].q.val();
        }
        self.ring_sm1.d.next = self.ring_sm.q.val();
        self.ring_sm2.d.next = self.ring_sm1.q.val();
        // ---- The fields each stage shows.
        self.s1_valid.next = self.ctr_s1.q.val().valid;
        self.s1_elig.next = self.ctr_s1.q.val().elig;
        self.s1_same_run.next = self.ctr_s1.q.val().same_run;
        self.sm_valid.next = self.ctr_sm.q.val().valid;
        self.sm_elig.next = self.ctr_sm.q.val().elig;
        self.sm_same_run.next = self.ctr_sm.q.val().same_run;
        self.sm_c.next = self.ctr_sm.q.val().c;
        self.sm_col.next = self.ctr_sm.q.val().col;
        self.sm1_elig.next = self.ctr_sm1.q.val().elig;
        self.sm2_valid.next = self.ctr_sm2.q.val().valid;
        self.sm2_ring.next = self.ctr_sm2.q.val().ring;
        self.sm2_last.next = self.ctr_sm2.q.val().last;
        self.sm2_ring_a.next = self.ring_sm2.q.val().a;
        self.sm2_ring_b.next = self.ring_sm2.q.val().b;
        // ---- Reset.
        if self.valid_rst.q.val() {
            self.last_label_valid.d.next = false;
            self.ctr_s1.d.next.valid = false;
            self.ctr_sm.d.next.valid = false;
            self.ctr_sm1.d.next.valid = false;
            self.ctr_sm2.d.next.valid = false;
        }
        for i in 0..(self._l - 1) {
            if self.tree_rst[2 * i].q.val() {
                self.ctr_tree[i].d.next = self.ctr_zero.val();
            }
            if self.tree_rst[2 * i + 1].q.val() {
                self.ring_tree[i].d.next = self.ring_zero.val();
            }
        }
    }
}
