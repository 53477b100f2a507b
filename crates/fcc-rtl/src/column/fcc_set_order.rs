//! `FccSetOrder`: the order of `FccSetQueue`. Each op taken at its head
//! reserves one of [`ORDER_ENTRIES`] entries a cycle later (`space` says
//! one is free, counting a reservation on its way): a make (its label and
//! slot) or a column marker complete at once; a find or a join complete when its
//! event comes from `FccLabelSets` (events come in the order of their ops,
//! so the entries waiting for one are kept in a list, `pend`). The entries
//! leave in the order they were taken, each once complete (`ev_valid`,
//! taken by `ev_take`).

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_set_queue::SetQEv;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::{kb, vec_of};

/// Ops issued and not yet out (its pointers are 3 bits).
pub const ORDER_ENTRIES: usize = 8;

/// What an issued op keeps of itself while it waits: its kind, ring
/// flag, column and row.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetQTag {
    pub make: Bit,
    pub join: Bit,
    pub mark: Bit,
    pub ring: Bit,
    pub col: Bits<12>,
    pub row: Bits<7>,
}

/// What an issued op became: a make's label and slot; a find's root and
/// slot; a join's root and slot kept, the slot gone, whether it merged.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetRes {
    pub merged: Bit,
    pub label: Bits<16>,
    pub slot: Bits<SLOT_BITS>,
    pub other: Bits<SLOT_BITS>,
}

#[derive(LogicBlock)]
pub struct FccSetOrder {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// An entry is free for an op taken now.
    pub space: Signal<Out, Bit>,
    // What the head became a cycle ago (`FccSetTook`).
    pub took: Signal<In, Bit>,
    pub took_op: Signal<In, Bit>,
    pub took_direct: Signal<In, Bit>,
    pub took_tag: Signal<In, SetQTag>,
    pub took_made: Signal<In, SetRes>,
    // `FccLabelSets`' events.
    pub s_valid: Signal<In, Bit>,
    pub s_merged: Signal<In, Bit>,
    pub s_keep: Signal<In, Bits<16>>,
    pub s_keep_slot: Signal<In, Bits<SLOT_BITS>>,
    pub s_gone_slot: Signal<In, Bits<SLOT_BITS>>,
    // The ops out, in order.
    pub ev_valid: Signal<Out, Bit>,
    pub ev: Signal<Out, SetQEv>,
    pub ev_take: Signal<In, Bit>,
    /// An op is issued and not yet out.
    pub busy: Signal<Out, Bit>,
    ops: Vec<DFF<SetQTag>>,
    res: Vec<DFF<SetRes>>,
    done: Vec<DFF<Bit>>,
    /// The entries waiting for an event, oldest at `pr`.
    pend: Vec<DFF<Bits<3>>>,
    wr: DFF<Bits<3>>,
    rd: FccFanoutReg<Bits<3>>,
    pw: DFF<Bits<3>>,
    pr: DFF<Bits<3>>,
    count: DFF<Bits<4>>,
    /// `pend[pr]`, kept in a flip-flop (an event's write names its entry
    /// without a lookup).
    fill_at: DFF<Bits<3>>,
    pr_next: Signal<Local, Bits<3>>,
    pop: Signal<Local, Bit>,
    /// The oldest entry's op and result.
    out_op: Signal<Local, SetQTag>,
    out_res: Signal<Local, SetRes>,
    got: Signal<Local, SetRes>,
    _n: usize,
    idx: Vec<Constant<Bits<3>>>,
    zero3: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    one4: Constant<Bits<4>>,
    full: Constant<Bits<4>>,
    full_less1: Constant<Bits<4>>,
    zero4: Constant<Bits<4>>,
}

impl Default for FccSetOrder {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            space: Default::default(),
            took: Default::default(),
            took_op: Default::default(),
            took_direct: Default::default(),
            took_tag: Default::default(),
            took_made: Default::default(),
            s_valid: Default::default(),
            s_merged: Default::default(),
            s_keep: Default::default(),
            s_keep_slot: Default::default(),
            s_gone_slot: Default::default(),
            ev_valid: Default::default(),
            ev: Default::default(),
            ev_take: Default::default(),
            busy: Default::default(),
            ops: vec_of(ORDER_ENTRIES),
            res: vec_of(ORDER_ENTRIES),
            done: vec_of(ORDER_ENTRIES),
            pend: vec_of(ORDER_ENTRIES),
            wr: Default::default(),
            rd: Default::default(),
            pw: Default::default(),
            pr: Default::default(),
            count: Default::default(),
            fill_at: Default::default(),
            pr_next: Default::default(),
            pop: Default::default(),
            out_op: Default::default(),
            out_res: Default::default(),
            got: Default::default(),
            _n: ORDER_ENTRIES,
            idx: (0..ORDER_ENTRIES).map(|i| kb(i as u64)).collect(),
            zero3: kb(0),
            one3: kb(1),
            one4: kb(1),
            full: kb(ORDER_ENTRIES as u64),
            full_less1: kb(ORDER_ENTRIES as u64 - 1),
            zero4: kb(0),
        }
    }
}

impl Logic for FccSetOrder {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, wr, rd, pw, pr, count, fill_at);
        for i in 0..(self._n) {
            self.ops[i].clock.next = self.clk.val();
            self.ops[i].d.next = self.ops[i].q.val();
            self.res[i].clock.next = self.clk.val();
            self.res[i].d.next = self.res[i].q.val();
            self.done[i].clock.next = self.clk.val();
            self.done[i].d.next = self.done[i].q.val();
            self.pend[i].clock.next = self.clk.val();
            self.pend[i].d.next = self.pend[i].q.val();
        }
        // Free: fewer than all entries in use, one fewer while a take's
        // reservation is on its way (takes can come a cycle apart).
        self.space.next = self.count.q.val() != self.full.val();
        if self.took.val() {
            self.space.next = self.count.q.val() != self.full_less1.val();
        }
        self.got.next.merged = self.s_merged.val();
        self.got.next.label = self.s_keep.val();
        self.got.next.slot = self.s_keep_slot.val();
        self.got.next.other = self.s_gone_slot.val();
        // The oldest entry waiting for an event after this cycle, read at
        // `pr` as it will be. An op's event comes two cycles after its
        // `took_op` at the soonest (the union-find's read takes two), so the
        // list's word written with `took_op` is read here before its event.
        self.pr_next.next = self.pr.q.val();
        if self.s_valid.val() {
            self.pr_next.next = self.pr.q.val() + self.one3.val();
        }
        for i in 0..(self._n) {
            if self.pr_next.val() == self.idx[i].val() {
                self.fill_at.d.next = self.pend[i].q.val();
            }
        }
        // The oldest out.
        self.ev_valid.next = false;
        self.out_op.next = self.ops[0].q.val();
        self.out_res.next = self.res[0].q.val();
        for i in 0..(self._n) {
            if self.rd.q.val() == self.idx[i].val() {
                self.ev_valid.next = self.done[i].q.val();
                self.out_op.next = self.ops[i].q.val();
                self.out_res.next = self.res[i].q.val();
            }
        }
        self.ev.next.make = self.out_op.val().make;
        self.ev.next.join = self.out_op.val().join;
        self.ev.next.mark = self.out_op.val().mark;
        self.ev.next.ring = self.out_op.val().ring;
        self.ev.next.col = self.out_op.val().col;
        self.ev.next.row = self.out_op.val().row;
        self.ev.next.merged = self.out_res.val().merged;
        self.ev.next.label = self.out_res.val().label;
        self.ev.next.slot = self.out_res.val().slot;
        self.ev.next.other = self.out_res.val().other;
        self.pop.next = self.ev_valid.val() & self.ev_take.val();
        // The three writes name three different entries: a free one, the
        // oldest waiting, the oldest out (complete).
        for i in 0..(self._n) {
            if self.took.val() & (self.wr.q.val() == self.idx[i].val()) {
                self.ops[i].d.next = self.took_tag.val();
                self.res[i].d.next = self.took_made.val();
                self.done[i].d.next = self.took_direct.val();
            }
            if self.took_op.val() & (self.pw.q.val() == self.idx[i].val()) {
                self.pend[i].d.next = self.wr.q.val();
            }
            if self.s_valid.val() & (self.fill_at.q.val() == self.idx[i].val()) {
                self.res[i].d.next = self.got.val();
                self.done[i].d.next = true;
            }
            if self.pop.val() & (self.rd.q.val() == self.idx[i].val()) {
                self.done[i].d.next = false;
            }
        }
        if self.took.val() {
            self.wr.d.next = self.wr.q.val() + self.one3.val();
        }
        if self.took_op.val() {
            self.pw.d.next = self.pw.q.val() + self.one3.val();
        }
        if self.s_valid.val() {
            self.pr.d.next = self.pr.q.val() + self.one3.val();
        }
        if self.pop.val() {
            self.rd.d.next = self.rd.q.val() + self.one3.val();
        }
        if self.took.val() & !self.pop.val() {
            self.count.d.next = self.count.q.val() + self.one4.val();
        }
        if !self.took.val() & self.pop.val() {
            self.count.d.next = self.count.q.val() - self.one4.val();
        }
        self.busy.next = self.count.q.val() != self.zero4.val();
        if self.rst.val() {
            self.wr.d.next = self.zero3.val();
            self.rd.d.next = self.zero3.val();
            self.pw.d.next = self.zero3.val();
            self.pr.d.next = self.zero3.val();
            self.count.d.next = self.zero4.val();
            for i in 0..(self._n) {
                self.done[i].d.next = false;
            }
        }
    }
}
