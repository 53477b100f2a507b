//! `FccSerializer`: takes the centre buffer's head record and sends its
//! joins to the join queue, one every other cycle, then the ring join, and
//! takes the record with its last join.
//!
//! A kept position e of a record is the join (c, rep[e]): `c` is the run's
//! representative the filter stored in the record. The record's kept flags,
//! but its first, are loaded into `pending`; each Select moves the first
//! pending flag out. The `b` of the join the next Emit sends is picked
//! (`FccPick`) when its position is chosen, at Load (the record's first-kept
//! flags, found by the filter) or at Select, and held in `pick_q`: the join
//! queue's RAM write data come from flip-flops through one multiplexer
//! level (Emit or Ring, chosen by `phase` alone, whether or not the queue
//! has room).
//!
//! * Load (`loaded` low, a head record): pick the first kept position;
//!   phase Emit, or Ring (no kept position, a ring join), or Select (neither:
//!   the record is taken at once).
//! * Emit (when the queue has room): send the picked join; then Select,
//!   or Ring or done when nothing is pending.
//! * Select: pick the next pending position; then Emit, or Ring or done.
//! * Ring (when the queue has room): send the ring join; done.
//!
//! Done takes the record and returns its input credit (`take`).
//!
//! Timing: no decision waits on a reduction of `pending` in the cycle that
//! uses it. `more_pending` says whether any position is left after the
//! picked one: at Load, any kept position but the first; at Select, "at
//! least two" of the pending flags (removing the first set flag leaves some
//! iff at least two were set), registered from `pending` in the cycle
//! before. Select reads that register and `sel_flip`, both loaded in the
//! cycle before it: Select always follows Emit (which leaves `pending` as it
//! is) or a Load that found no kept position (`pending` empty, `sel_flip`
//! and `head_first` clear, so nothing is picked), so they are up to date.
//!
//! `same` of each join (its `a` is the previous join's `a` in this frame) is
//! decided once per record, at Load.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_any_or::FccAnyOr;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_pick::FccPick;
use crate::fcc_prefix_or::FccPrefixOr;
use crate::fcc_two_or::FccTwoOr;
use crate::types::{vec_of, CtrRec, JoinRec};

/// What the serializer does with a loaded record.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum SerPhase {
    Select,
    Emit,
    Ring,
}

#[derive(LogicBlock)]
pub struct FccSerializer {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The centre buffer's head record.
    pub head_valid: Signal<In, Bit>,
    pub head: Signal<In, CtrRec>,
    pub head_rep: Vec<Signal<In, Bits<16>>>,
    pub head_keep: Vec<Signal<In, Bit>>,
    pub head_first: Vec<Signal<In, Bit>>,
    /// Take the head record (its joins are out); its input credit returns.
    pub take: Signal<Out, Bit>,
    // To the join queue.
    pub join_room: Signal<In, Bit>,
    pub join_push: Signal<Out, Bit>,
    pub join_rec: Signal<Out, JoinRec>,
    /// The frame's last record has been taken (registered).
    pub last_done: Signal<Out, Bit>,
    loaded: FccFanoutReg<Bit>,
    phase: DFF<SerPhase>,
    /// Kept positions not picked yet; the `b` of the join to emit next.
    pending: Vec<DFF<Bit>>,
    pick_q: DFF<Bits<16>>,
    /// `head_first` XOR the position the next Select picks (all clear
    /// while no record is loaded): the pick's flags are `head_first` XOR
    /// `sel_flip`, two flip-flops, at Load and at Select alike.
    sel_flip: Vec<DFF<Bit>>,
    /// Any position pending after the picked one.
    more_pending: DFF<Bit>,
    /// Registered from `pending`: at least two flags are pending.
    pending_two: DFF<Bit>,
    /// The record has a ring join not sent yet.
    ring_pending: DFF<Bit>,
    /// A join of this record has been sent.
    emitted: DFF<Bit>,
    /// The previous join's `a` in this frame, if any.
    prev_a: DFF<Bits<16>>,
    prev_a_valid: DFF<Bit>,
    /// Decided at Load: the record's joins' `a` equals `prev_a`; the ring
    /// join's `a` equals `c`; the ring join's `a` equals `prev_a`.
    centre_same: DFF<Bit>,
    ring_same_centre: DFF<Bit>,
    ring_same_prev: DFF<Bit>,
    last_done_q: DFF<Bit>,
    done: Signal<Local, Bit>,
    head_any: FccAnyOr,
    /// Any kept position after the first (the record has two or more).
    head_rest: FccAnyOr,
    pending_prefix: FccPrefixOr,
    pending_two_or: FccTwoOr,
    pick: FccPick,
    _n: usize,
}

impl FccSerializer {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            head_valid: Default::default(),
            head: Default::default(),
            head_rep: vec_of(n),
            head_keep: vec_of(n),
            head_first: vec_of(n),
            take: Default::default(),
            join_room: Default::default(),
            join_push: Default::default(),
            join_rec: Default::default(),
            last_done: Default::default(),
            loaded: Default::default(),
            phase: Default::default(),
            pending: vec_of(n),
            pick_q: Default::default(),
            sel_flip: vec_of(n),
            more_pending: Default::default(),
            pending_two: Default::default(),
            ring_pending: Default::default(),
            emitted: Default::default(),
            prev_a: Default::default(),
            prev_a_valid: Default::default(),
            centre_same: Default::default(),
            ring_same_centre: Default::default(),
            ring_same_prev: Default::default(),
            last_done_q: Default::default(),
            done: Default::default(),
            head_any: FccAnyOr::new(n),
            head_rest: FccAnyOr::new(n),
            pending_prefix: FccPrefixOr::new(n),
            pending_two_or: FccTwoOr::new(n),
            pick: FccPick::new(n),
            _n: n,
        }
    }
}

impl Logic for FccSerializer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            loaded,
            phase,
            pick_q,
            more_pending,
            pending_two,
            ring_pending,
            emitted,
            prev_a,
            prev_a_valid,
            centre_same,
            ring_same_centre,
            ring_same_prev,
            last_done_q
        );
        for e in 0..self._n {
            self.pending[e].clock.next = self.clk.val();
            self.pending[e].d.next = self.pending[e].q.val();
            self.head_any.x[e].next = self.head_keep[e].val();
            self.head_rest.x[e].next = self.head_keep[e].val() & !self.head_first[e].val();
            self.pending_prefix.x[e].next = self.pending[e].q.val();
            self.pending_two_or.x[e].next = self.pending[e].q.val();
            // The position the next Emit sends: the record's first kept
            // one at Load (`sel_flip` clear), the first pending one at
            // Select (`sel_flip` loaded in the Emit before, when `pending`
            // is what Select sees).
            self.sel_flip[e].clock.next = self.clk.val();
            self.sel_flip[e].d.next = self.loaded.q.val()
                & (self.head_first[e].val()
                    ^ (self.pending[e].q.val() & !self.pending_prefix.pre[e].val()));
            self.pick.sel[e].next = self.head_first[e].val() ^ self.sel_flip[e].q.val();
            self.pick.v[e].next = self.head_rep[e].val();
        }
        self.pending_two.d.next = self.pending_two_or.two.val();
        self.join_push.next = false;
        // The join's fields depend on `phase` alone (not on the queue's room).
        self.join_rec.next.a = self.head.val().c;
        self.join_rec.next.b = self.pick_q.q.val();
        self.join_rec.next.same = self.centre_same.q.val() | self.emitted.q.val();
        if self.phase.q.val() == SerPhase::Ring {
            self.join_rec.next.a = self.head.val().ring_a;
            self.join_rec.next.b = self.head.val().ring_b;
            self.join_rec.next.same = self.ring_same_prev.q.val();
            if self.emitted.q.val() {
                self.join_rec.next.same = self.ring_same_centre.q.val();
            }
        }
        self.done.next = false;
        if !self.loaded.q.val() & self.head_valid.val() {
            self.loaded.d.next = true;
            self.more_pending.d.next = self.head_rest.any.val();
            self.ring_pending.d.next = self.head.val().ring;
            self.centre_same.d.next =
                self.prev_a_valid.q.val() & (self.head.val().c == self.prev_a.q.val());
            self.ring_same_centre.d.next = self.head.val().ring_a == self.head.val().c;
            self.ring_same_prev.d.next =
                self.prev_a_valid.q.val() & (self.head.val().ring_a == self.prev_a.q.val());
            self.emitted.d.next = false;
            self.pick_q.d.next = self.pick.o.val();
            for e in 0..self._n {
                self.pending[e].d.next = self.head_keep[e].val() & !self.head_first[e].val();
            }
            self.phase.d.next = SerPhase::Select;
            if self.head_any.any.val() {
                self.phase.d.next = SerPhase::Emit;
            } else if self.head.val().ring {
                self.phase.d.next = SerPhase::Ring;
            }
        }
        if self.loaded.q.val() {
            match self.phase.q.val() {
                SerPhase::Select => {
                    self.more_pending.d.next = self.pending_two.q.val();
                    self.pick_q.d.next = self.pick.o.val();
                    for e in 0..self._n {
                        self.pending[e].d.next = self.pending[e].q.val()
                            & !(self.head_first[e].val() ^ self.sel_flip[e].q.val());
                    }
                    if self.more_pending.q.val() {
                        self.phase.d.next = SerPhase::Emit;
                    } else if self.ring_pending.q.val() {
                        self.phase.d.next = SerPhase::Ring;
                    } else {
                        self.done.next = true;
                    }
                }
                SerPhase::Emit => {
                    if self.join_room.val() {
                        self.join_push.next = true;
                        self.emitted.d.next = true;
                        self.prev_a.d.next = self.head.val().c;
                        self.prev_a_valid.d.next = true;
                        self.phase.d.next = SerPhase::Select;
                        if !self.more_pending.q.val() {
                            if self.ring_pending.q.val() {
                                self.phase.d.next = SerPhase::Ring;
                            } else {
                                self.done.next = true;
                            }
                        }
                    }
                }
                SerPhase::Ring => {
                    if self.join_room.val() {
                        self.join_push.next = true;
                        self.prev_a.d.next = self.head.val().ring_a;
                        self.prev_a_valid.d.next = true;
                        self.ring_pending.d.next = false;
                        self.done.next = true;
                    }
                }
            }
        }
        // The record is done: take it, return its credit.
        self.take.next = self.done.val();
        self.last_done_q.d.next = false;
        if self.done.val() {
            self.loaded.d.next = false;
            self.last_done_q.d.next = self.head.val().last;
            if self.head.val().last {
                self.prev_a_valid.d.next = false;
            }
        }
        self.last_done.next = self.last_done_q.q.val();
        if self.rst.val() {
            self.loaded.d.next = false;
            self.prev_a_valid.d.next = false;
            self.last_done_q.d.next = false;
        }
    }
}
