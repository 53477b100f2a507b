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
//! The centre itself (its run in S0, its fields and ring join from stage to
//! stage) travels in `FccFiltCentre`.
//!
//! Reset: `rst` is the reset one cycle ahead. Every group of reset loads
//! has its own registered copy (`FccKeepReg`), at most `MAX_FANOUT` loads
//! each: `valid_rst` for the record handshake and the write-back; the
//! centre pipeline's copies (`FccFiltCentre`); and the match delay lines'
//! own copies (`FccMatchDelay`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_any_or::FccAnyOr;
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_filt_centre::FccFiltCentre;
use crate::fcc_first_set::FccFirstSet;
use crate::fcc_group_or::{groups, FccGroupOr};
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_known_mask::FccKnownMask;
use crate::fcc_match_delay::FccMatchDelay;
use crate::fcc_min_tree::FccMinTree;
use crate::types::{clog2, kb, vec_of, Ctr, CtrRec};

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
    /// The centre from S0 to SM+2.
    centre_pipe: FccFiltCentre,
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
    // ---- Reset copy (see the module doc).
    valid_rst: FccKeepReg<Bit>,
    zero16: Constant<Bits<16>>,
    _n: usize,
    _groups: usize,
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
            centre_pipe: FccFiltCentre::new(l),
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
            zero16: kb(0),
            _n: n,
            _groups: groups(n),
        }
    }
}

impl Logic for FccSortFilter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
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
        self.valid_rst.clock.next = self.clk.val();
        self.valid_rst.d.next = self.rst.val();
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
        // ---- S0: the centre's run; the matches into the tree and the delay lines.
        self.centre_pipe.clk.next = self.clk.val();
        self.centre_pipe.rst.next = self.rst.val();
        self.centre_pipe.valid.next = self.centre.val().valid;
        self.centre_pipe.lok.next = self.centre.val().lok;
        self.centre_pipe.label.next = self.centre.val().label;
        self.centre_pipe.col.next = self.centre.val().col;
        self.centre_pipe.last.next = self.centre.val().last;
        self.centre_pipe.ring.next = self.centre.val().ring;
        self.centre_pipe.ring_a.next = self.centre.val().ring_a;
        self.centre_pipe.ring_b.next = self.centre.val().ring_b;
        for e in 0..self._n {
            self.min_tree.hit[e].next = self.hit[e].val();
            self.min_tree.value[e].next = self.rep[e].val();
            self.match_delay.hit[e].next = self.hit[e].val();
            self.match_delay.rep[e].next = self.rep[e].val();
        }
        // ---- S1: the sliding mask of positions already matched by this run.
        self.known_mask.valid.next = self.centre_pipe.s1_valid.val();
        self.known_mask.elig.next = self.centre_pipe.s1_elig.val();
        self.known_mask.same_run.next = self.centre_pipe.s1_same_run.val();
        for e in 0..self._n {
            self.known_mask.hit[e].next = self.match_delay.hit_s1[e].val();
        }
        // ---- SM: the run's representative; matches with the smallest one.
        self.run_rep_choice.next = self.centre_pipe.sm_c.val();
        if self.centre_pipe.sm_same_run.val() {
            self.run_rep_choice.next = self.run_rep.q.val();
        }
        self.run_rep_before_net.x.next = self.run_rep_choice.val();
        self.run_rep_before.next = self.run_rep_before_net.y.val();
        self.run_rep_after.next = self.run_rep_before.val();
        if self.min_tree.min.val() < self.run_rep_before.val() {
            self.run_rep_after.next = self.min_tree.min.val();
        }
        if self.centre_pipe.sm_elig.val() {
            self.run_rep.d.next = self.run_rep_after.val();
        }
        self.run_rep_sm1.d.next = self.run_rep_before.val();
        self.rep_write_en.d.next = self.centre_pipe.sm_valid.val();
        self.rep_write_col.d.next = self.centre_pipe.sm_col.val();
        self.rep_write_value.d.next = self.zero16.val();
        if self.centre_pipe.sm_elig.val() {
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
            self.keep_next[e].next = self.centre_pipe.sm1_elig.val()
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
        self.need_rec.next = self.keep_any.any.val()
            | self.centre_pipe.sm2_ring.val()
            | self.centre_pipe.sm2_last.val();
        self.rec_push_q.d.next = self.centre_pipe.sm2_valid.val() & self.need_rec.val();
        self.credit_drop_q.d.next = self.centre_pipe.sm2_valid.val() & !self.need_rec.val();
        self.rec_q.d.next.c = self.run_rep_sm2.q.val();
        self.rec_q.d.next.ring_a = self.centre_pipe.sm2_ring_a.val();
        self.rec_q.d.next.ring_b = self.centre_pipe.sm2_ring_b.val();
        self.rec_q.d.next.ring = self.centre_pipe.sm2_ring.val();
        self.rec_q.d.next.last = self.centre_pipe.sm2_last.val();
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
            self.rec_push_q.d.next = false;
            self.credit_drop_q.d.next = false;
            self.rep_write_en.d.next = false;
        }
    }
}
