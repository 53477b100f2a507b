//! `FccSortFilter`: reduces the window positions that matched a centre to
//! the few joins the centre needs, one centre per cycle without stalls, and
//! writes the centre's representative back to the window.
//!
//! Stages (L = ceil(log2 positions) levels of the minimum tree):
//!
//! * S0: the centre's run (`same_run`: same label as the last labelled
//!   centre). The representatives of the matched positions enter the
//!   registered minimum tree (`FccMinTree`); the matches, their adjacency
//!   (`adj`) and representatives enter the delay lines (`FccMatchDelay`).
//! * S1: the sliding mask of positions already matched by this run
//!   (`FccKnownMask`).
//! * SM = S(L+1): the smallest representative among the matches, `min`, and
//!   the first position that has it (the tree's winner: ties go to the lower
//!   position). The run's representative becomes min(run_rep, min) (min(c,
//!   min) for a new run) and is written back to the window as the centre's
//!   representative. A later match with representative `min` is marked
//!   (`later_min`).
//! * SM+1: a match is kept unless it is known, `adj`, has the run's
//!   representative (before this centre), or is a later match with `min`;
//!   whether each group of `GROUP` positions has a kept one (`keep_group`).
//! * SM+2: a centre with kept matches, a ring join or the frame's end asks
//!   for a centre-buffer record (`rec_push` in SM+3); any other valid centre
//!   returns its input credit (`credit_drop`). The first kept position
//!   (`FccFirstSet`, from `keep` and `keep_group`).
//!
//! The record's row values (`rec_rep`), kept flags (`rec_keep`) and
//! first-kept flags (`rec_first`: the first kept position, found in SM+2 so
//! that the serializer picks its first join from flip-flops) show beside
//! `rec` in SM+3.
//!
//! Reset: `rst` is the reset one cycle ahead. Every group of reset loads
//! has its own registered copy (`FccKeepReg`), at most `MAX_FANOUT` loads
//! each: `valid_rst` for the centre's valid flags and the record handshake;
//! for minimum-tree stage i, `tree_rst[2i]` for the centre (33 flip-flops,
//! reset whole so that the stage stays a flip-flop rather than a shift
//! register) and `tree_rst[2i + 1]` for its ring join (32); and the match
//! delay lines' own copies (`FccMatchDelay`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_any_or::FccAnyOr;
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_first_set::FccFirstSet;
use crate::fcc_group_or::{groups, FccGroupOr};
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_known_mask::FccKnownMask;
use crate::fcc_match_delay::FccMatchDelay;
use crate::fcc_min_tree::FccMinTree;
use crate::types::{clog2, kb, vec_of, Ctr, CtrRec};

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
pub struct FccSortFilter {
    pub clk: Signal<In, Clock>,
    /// Reset, one cycle ahead (see the module doc).
    pub rst: Signal<In, Bit>,
    // From the distance tree and the window (S0).
    pub centre: Signal<In, Ctr>,
    pub hit: Vec<Signal<In, Bit>>,
    pub rep: Vec<Signal<In, Bits<16>>>,
    // The centre pixel's representative, back to the window.
    pub rep_we: Signal<Out, Bit>,
    pub rep_waddr: Signal<Out, Bits<12>>,
    pub rep_wdata: Signal<Out, Bits<16>>,
    // To the centre buffer (SM+3).
    pub rec_push: Signal<Out, Bit>,
    pub rec: Signal<Out, CtrRec>,
    pub rec_rep: Vec<Signal<Out, Bits<16>>>,
    pub rec_keep: Vec<Signal<Out, Bit>>,
    pub rec_first: Vec<Signal<Out, Bit>>,
    /// A valid centre that needs no record (its input credit returns).
    pub credit_drop: Signal<Out, Bit>,
    // ---- S0.
    last_label: DFF<Bits<16>>,
    last_label_valid: DFF<Bit>,
    ctr_s0: Signal<Local, FiltCtr>,
    ring_s0: Signal<Local, RingJoin>,
    // ---- The centre from stage to stage: S1, S2 .. SL, SM, SM+1, SM+2.
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
    match_delay: FccMatchDelay,
    min_tree: FccMinTree,
    known_mask: FccKnownMask,
    // ---- SM.
    run_rep: DFF<Bits<16>>,
    /// The run's representative before this centre, and after it.
    run_rep_before: Signal<Local, Bits<16>>,
    /// `run_rep_before` reaches every position's compare: Vivado replicates
    /// the multiplexer that chooses it.
    run_rep_choice: Signal<Local, Bits<16>>,
    run_rep_before_net: FccFanoutNet<Bits<16>>,
    run_rep_after: Signal<Local, Bits<16>>,
    run_rep_sm1: DFF<Bits<16>>,
    run_rep_sm2: DFF<Bits<16>>,
    rep_write_en: DFF<Bit>,
    rep_write_col: DFF<Bits<12>>,
    rep_write_value: DFF<Bits<16>>,
    /// A match with the smallest representative that is not the first
    /// position with it; a position whose representative is the run's.
    later_min: Vec<DFF<Bit>>,
    is_run_rep: Vec<DFF<Bit>>,
    // ---- SM+1.
    keep_next: Vec<Signal<Local, Bit>>,
    keep: Vec<DFF<Bit>>,
    /// Any kept position in each group of `GROUP` (for `keep_any` and the
    /// first-kept search).
    keep_group_or: FccGroupOr,
    keep_group: Vec<DFF<Bit>>,
    // ---- SM+2.
    keep_any: FccAnyOr,
    keep_first: FccFirstSet,
    need_rec: Signal<Local, Bit>,
    keep_sm3: Vec<DFF<Bit>>,
    first_sm3: Vec<DFF<Bit>>,
    rec_push_q: FccFanoutReg<Bit>,
    credit_drop_q: DFF<Bit>,
    rec_q: DFF<CtrRec>,
    // ---- Reset copies (see the module doc).
    valid_rst: FccKeepReg<Bit>,
    tree_rst: Vec<FccKeepReg<Bit>>,
    ctr_zero: Constant<FiltCtr>,
    ring_zero: Constant<RingJoin>,
    zero16: Constant<Bits<16>>,
    _n: usize,
    _groups: usize,
    /// Levels of the minimum tree.
    _l: usize,
}

impl FccSortFilter {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        assert!(n <= 64);
        let l = clog2(n);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            rep: vec_of(n),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            rec_push: Default::default(),
            rec: Default::default(),
            rec_rep: vec_of(n),
            rec_keep: vec_of(n),
            rec_first: vec_of(n),
            credit_drop: Default::default(),
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
            match_delay: FccMatchDelay::new(k, h, l),
            min_tree: FccMinTree::new(n),
            // S1 .. SM+1.
            known_mask: FccKnownMask::new(k, h, l + 1),
            run_rep: Default::default(),
            run_rep_before: Default::default(),
            run_rep_choice: Default::default(),
            run_rep_before_net: Default::default(),
            run_rep_after: Default::default(),
            run_rep_sm1: Default::default(),
            run_rep_sm2: Default::default(),
            rep_write_en: Default::default(),
            rep_write_col: Default::default(),
            rep_write_value: Default::default(),
            later_min: vec_of(n),
            is_run_rep: vec_of(n),
            keep_next: vec_of(n),
            keep: vec_of(n),
            keep_group_or: FccGroupOr::new(n),
            keep_group: vec_of(groups(n)),
            keep_any: FccAnyOr::new(groups(n)),
            keep_first: FccFirstSet::new(n),
            need_rec: Default::default(),
            keep_sm3: vec_of(n),
            first_sm3: vec_of(n),
            rec_push_q: Default::default(),
            credit_drop_q: Default::default(),
            rec_q: Default::default(),
            valid_rst: Default::default(),
            tree_rst: vec_of(2 * (l - 1)),
            ctr_zero: Constant::new(FiltCtr::default()),
            ring_zero: Constant::new(RingJoin::default()),
            zero16: kb(0),
            _n: n,
            _groups: groups(n),
            _l: l,
        }
    }
}

impl Logic for FccSortFilter {
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
            ring_sm2,
            run_rep,
            run_rep_sm1,
            run_rep_sm2,
            rep_write_en,
            rep_write_col,
            rep_write_value,
            rec_push_q,
            credit_drop_q,
            rec_q
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
        for e in 0..self._n {
            self.later_min[e].clock.next = self.clk.val();
            self.is_run_rep[e].clock.next = self.clk.val();
            self.keep[e].clock.next = self.clk.val();
            self.keep_sm3[e].clock.next = self.clk.val();
            self.first_sm3[e].clock.next = self.clk.val();
        }
        self.min_tree.clk.next = self.clk.val();
        self.known_mask.clk.next = self.clk.val();
        self.match_delay.clk.next = self.clk.val();
        self.match_delay.rst.next = self.rst.val();
        // ---- S0: the centre's run and the adjacent duplicates.
        self.ctr_s0.next.valid = self.centre.val().valid;
        self.ctr_s0.next.elig = self.centre.val().valid & self.centre.val().lok;
        self.ctr_s0.next.same_run =
            self.last_label_valid.q.val() & (self.centre.val().label == self.last_label.q.val());
        self.ctr_s0.next.c = self.centre.val().label;
        self.ctr_s0.next.col = self.centre.val().col;
        self.ctr_s0.next.last = self.centre.val().last;
        self.ctr_s0.next.ring = self.centre.val().ring;
        self.ring_s0.next.a = self.centre.val().ring_a;
        self.ring_s0.next.b = self.centre.val().ring_b;
        if self.centre.val().valid & self.centre.val().lok {
            self.last_label.d.next = self.centre.val().label;
            self.last_label_valid.d.next = true;
        }
        if self.centre.val().valid & self.centre.val().last {
            self.last_label_valid.d.next = false;
        }
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
        for e in 0..self._n {
            self.min_tree.hit[e].next = self.hit[e].val();
            self.min_tree.value[e].next = self.rep[e].val();
            self.match_delay.hit[e].next = self.hit[e].val();
            self.match_delay.rep[e].next = self.rep[e].val();
        }
        // ---- S1: the sliding mask of positions already matched by this run.
        self.known_mask.valid.next = self.ctr_s1.q.val().valid;
        self.known_mask.elig.next = self.ctr_s1.q.val().elig;
        self.known_mask.same_run.next = self.ctr_s1.q.val().same_run;
        for e in 0..self._n {
            self.known_mask.hit[e].next = self.match_delay.hit_s1[e].val();
        }
        // ---- SM: the run's representative; matches with the smallest one.
        self.run_rep_choice.next = self.ctr_sm.q.val().c;
        if self.ctr_sm.q.val().same_run {
            self.run_rep_choice.next = self.run_rep.q.val();
        }
        self.run_rep_before_net.x.next = self.run_rep_choice.val();
        self.run_rep_before.next = self.run_rep_before_net.y.val();
        self.run_rep_after.next = self.run_rep_before.val();
        if self.min_tree.min.val() < self.run_rep_before.val() {
            self.run_rep_after.next = self.min_tree.min.val();
        }
        if self.ctr_sm.q.val().elig {
            self.run_rep.d.next = self.run_rep_after.val();
        }
        self.run_rep_sm1.d.next = self.run_rep_before.val();
        self.rep_write_en.d.next = self.ctr_sm.q.val().valid;
        self.rep_write_col.d.next = self.ctr_sm.q.val().col;
        self.rep_write_value.d.next = self.zero16.val();
        if self.ctr_sm.q.val().elig {
            self.rep_write_value.d.next = self.run_rep_after.val();
        }
        for e in 0..self._n {
            self.later_min[e].d.next = self.match_delay.hit_sm[e].val()
                & (self.match_delay.rep_sm[e].val() == self.min_tree.min.val())
                & !self.min_tree.first[e].val();
            self.is_run_rep[e].d.next =
                self.match_delay.rep_sm[e].val() == self.run_rep_before.val();
        }
        self.rep_we.next = self.rep_write_en.q.val();
        self.rep_waddr.next = self.rep_write_col.q.val();
        self.rep_wdata.next = self.rep_write_value.q.val();
        // ---- SM+1: keep a match unless known, adjacent or a later minimum.
        for e in 0..self._n {
            self.keep_next[e].next = self.ctr_sm1.q.val().elig
                & self.match_delay.hit_sm1[e].val()
                & !self.match_delay.adj_sm1[e].val()
                & !self.known_mask.known_late[e].val()
                & !self.is_run_rep[e].q.val()
                & !self.later_min[e].q.val();
            self.keep[e].d.next = self.keep_next[e].val();
            self.keep_group_or.x[e].next = self.keep_next[e].val();
        }
        for g in 0..self._groups {
            self.keep_group[g].clock.next = self.clk.val();
            self.keep_group[g].d.next = self.keep_group_or.any[g].val();
            self.keep_any.x[g].next = self.keep_group[g].q.val();
            self.keep_first.gany[g].next = self.keep_group[g].q.val();
        }
        self.run_rep_sm2.d.next = self.run_rep_sm1.q.val();
        // ---- SM+2: does the centre need a record? Its first kept position.
        for e in 0..self._n {
            self.keep_first.x[e].next = self.keep[e].q.val();
            self.keep_sm3[e].d.next = self.keep[e].q.val();
            self.first_sm3[e].d.next = self.keep_first.first[e].val();
        }
        self.need_rec.next =
            self.keep_any.any.val() | self.ctr_sm2.q.val().ring | self.ctr_sm2.q.val().last;
        self.rec_push_q.d.next = self.ctr_sm2.q.val().valid & self.need_rec.val();
        self.credit_drop_q.d.next = self.ctr_sm2.q.val().valid & !self.need_rec.val();
        self.rec_q.d.next.c = self.run_rep_sm2.q.val();
        self.rec_q.d.next.ring_a = self.ring_sm2.q.val().a;
        self.rec_q.d.next.ring_b = self.ring_sm2.q.val().b;
        self.rec_q.d.next.ring = self.ctr_sm2.q.val().ring;
        self.rec_q.d.next.last = self.ctr_sm2.q.val().last;
        // ---- SM+3: the record.
        self.rec_push.next = self.rec_push_q.q.val();
        self.credit_drop.next = self.credit_drop_q.q.val();
        self.rec.next = self.rec_q.q.val();
        for e in 0..self._n {
            self.rec_rep[e].next = self.match_delay.rep_sm3[e].val();
            self.rec_keep[e].next = self.keep_sm3[e].q.val();
            self.rec_first[e].next = self.first_sm3[e].q.val();
        }
        if self.valid_rst.q.val() {
            self.last_label_valid.d.next = false;
            self.ctr_s1.d.next.valid = false;
            self.ctr_sm.d.next.valid = false;
            self.ctr_sm1.d.next.valid = false;
            self.ctr_sm2.d.next.valid = false;
            self.rec_push_q.d.next = false;
            self.credit_drop_q.d.next = false;
            self.rep_write_en.d.next = false;
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
