//! `FccSetWalks`: the walks and the order of `FccLabelSets`, the column
//! core's union-find over labels (docs/column-core.md, item 3). The table's
//! read port takes one read a cycle, answered two cycles later; a walk
//! (a *token*: which op, which side, the label read) whose word is not its
//! root reads the parent at once, in the cycle its word shows, so up to
//! two walks share the port, one a cycle each.
//!
//! Ops are taken in order, up to [`SET_OPS`] in flight (`FccSetOp`s, the
//! oldest first, each known by a sequence number its walks carry): a find
//! (`op_join` low: the root of `op_a`) or a join (the roots of `op_a` and
//! `op_b`, then one linked under the other: `op_b`'s kept when `op_under`
//! says `op_a` is a run just started, filed under `op_b`'s cluster, else
//! the smaller root). A new op is
//! taken while a place is free, whatever the read port does, so that
//! `op_take` reads no word (it ends the queue's longest path); the reads
//! go at the free cycles of the port, the oldest op's first (a new op's
//! first read in the cycle it is taken when none waits and the port is
//! free). Ops retire in order, the oldest, one a cycle, each with one event
//! (`ev_*`, registered): a find's root and its slot; a join's two roots
//! and slots, `ev_merged` when they differed and the link was written (a
//! make waits for the write port while a join may retire: `mk_ready`;
//! the retire, the link and the event are `FccSetRetire`'s). The others
//! move up when the oldest retires.
//!
//! A walk that read the linked word before the link was written (another
//! op's, or one started in the link's cycle) found a root that no longer
//! is one: for two cycles after a link its root, recorded or arriving, is
//! chased to the root kept (`FccSetOp`). No op retires in the first of
//! them, when a root recorded before the link may still be the linked one;
//! by the second, every recorded root is chased and every arriving one is
//! chased as it arrives, so an op may retire (and link again: two links
//! are two cycles apart at least, so a root misses one link at most).
//! Reads issued after the link's cycle see it.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_set_op::{FccSetOp, SEQ_BITS};
use super::fcc_set_reads::FccSetReads;
use super::fcc_set_retire::FccSetRetire;
use crate::types::{kb, vec_of};

/// Ops in flight at most (their sequence numbers must stay distinct).
pub const SET_OPS: usize = 3;
const _: () = assert!(SET_OPS >= 2 && SET_OPS <= 1 << SEQ_BITS);

#[derive(LogicBlock)]
pub struct FccSetWalks {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_join: Signal<In, Bit>,
    pub op_under: Signal<In, Bit>,
    pub op_a: Signal<In, Bits<16>>,
    pub op_b: Signal<In, Bits<16>>,
    pub op_take: Signal<Out, Bit>,
    /// A make may take the write port this cycle: the oldest op is not a
    /// join that can retire (and link) in it. From flip-flops only.
    pub mk_ready: Signal<Out, Bit>,
    // The read port: the word read two cycles ago shows now.
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<16>>,
    pub word_parent: Signal<In, Bits<16>>,
    pub word_slot: Signal<In, Bits<SLOT_BITS>>,
    // The link write: `parent[link_gone] = link_keep`.
    pub link_en: Signal<Out, Bit>,
    pub link_gone: Signal<Out, Bits<16>>,
    pub link_keep: Signal<Out, Bits<16>>,
    pub ev_valid: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_keep: Signal<Out, Bits<16>>,
    pub ev_keep_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_gone: Signal<Out, Bits<16>>,
    pub ev_gone_slot: Signal<Out, Bits<SLOT_BITS>>,
    /// No op in progress, no event to come.
    pub idle: Signal<Out, Bit>,
    /// The ops in flight, the oldest in place 0; the places in use come
    /// first.
    ops: Vec<FccSetOp>,
    /// The reads still to issue, oldest first.
    reads: FccSetReads,
    // Tokens issued one (`p1`) and two (`p2`) cycles ago.
    p1_valid: DFF<Bit>,
    p1_seq: DFF<Bits<SEQ_BITS>>,
    p1_side: DFF<Bit>,
    p1_addr: DFF<Bits<16>>,
    p2_valid: DFF<Bit>,
    p2_seq: DFF<Bits<SEQ_BITS>>,
    p2_side: DFF<Bit>,
    p2_addr: DFF<Bits<16>>,
    /// The oldest op's retire, its link and its event.
    oldest: FccSetRetire,
    /// The next op's sequence number, and each place's op's (they move
    /// with the ops).
    seq: DFF<Bits<SEQ_BITS>>,
    seqs: Vec<DFF<Bits<SEQ_BITS>>>,
    retire: Signal<Local, Bit>,
    /// Per place: free after this cycle's retire; the new op goes there.
    free: Vec<Signal<Local, Bit>>,
    take: Vec<Signal<Local, Bit>>,
    /// `p2`'s word is not its root: the walk reads on; else a walk is done
    /// (`w_done`) and the port is free for a new read (`issue`).
    more: Signal<Local, Bit>,
    w_done: Signal<Local, Bit>,
    issue: Signal<Local, Bit>,
    issue_seq: Signal<Local, Bits<SEQ_BITS>>,
    issue_side: Signal<Local, Bit>,
    issue_addr: Signal<Local, Bits<16>>,
    rd_valid: Signal<Local, Bit>,
    rd_addr: Signal<Local, Bits<16>>,
    busy: Signal<Local, Bit>,
    _n: usize,
    one_seq: Constant<Bits<SEQ_BITS>>,
    zero_seq: Constant<Bits<SEQ_BITS>>,
}

impl Default for FccSetWalks {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            op_valid: Default::default(),
            op_join: Default::default(),
            op_under: Default::default(),
            op_a: Default::default(),
            op_b: Default::default(),
            op_take: Default::default(),
            mk_ready: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            word_parent: Default::default(),
            word_slot: Default::default(),
            link_en: Default::default(),
            link_gone: Default::default(),
            link_keep: Default::default(),
            ev_valid: Default::default(),
            ev_join: Default::default(),
            ev_merged: Default::default(),
            ev_keep: Default::default(),
            ev_keep_slot: Default::default(),
            ev_gone: Default::default(),
            ev_gone_slot: Default::default(),
            idle: Default::default(),
            ops: vec_of(SET_OPS),
            reads: Default::default(),
            p1_valid: Default::default(),
            p1_seq: Default::default(),
            p1_side: Default::default(),
            p1_addr: Default::default(),
            p2_valid: Default::default(),
            p2_seq: Default::default(),
            p2_side: Default::default(),
            p2_addr: Default::default(),
            oldest: Default::default(),
            seq: Default::default(),
            seqs: vec_of(SET_OPS),
            retire: Default::default(),
            free: vec_of(SET_OPS),
            take: vec_of(SET_OPS),
            more: Default::default(),
            w_done: Default::default(),
            issue: Default::default(),
            issue_seq: Default::default(),
            issue_side: Default::default(),
            issue_addr: Default::default(),
            rd_valid: Default::default(),
            rd_addr: Default::default(),
            busy: Default::default(),
            _n: SET_OPS,
            one_seq: kb(1),
            zero_seq: kb(0),
        }
    }
}

impl Logic for FccSetWalks {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, p1_valid, p1_seq, p1_side, p1_addr, p2_valid, p2_seq, p2_side, p2_addr, seq
        );
        for i in 0..(self._n) {
            self.ops[i].clk.next = self.clk.val();
            self.ops[i].rst.next = self.rst.val();
            self.seqs[i].clock.next = self.clk.val();
            self.seqs[i].d.next = self.seqs[i].q.val();
        }
        // The word that shows: a root ends its walk.
        self.more.next = self.p2_valid.q.val() & (self.word_parent.val() != self.p2_addr.q.val());
        self.w_done.next = self.p2_valid.q.val() & !self.more.val();
        // The oldest op's retire (`FccSetRetire`).
        self.oldest.clk.next = self.clk.val();
        self.oldest.rst.next = self.rst.val();
        self.oldest.o_valid.next = self.ops[0].valid.val();
        self.oldest.o_join.next = self.ops[0].is_join.val();
        self.oldest.o_under.next = self.ops[0].under.val();
        self.oldest.o_lt.next = self.ops[0].lt.val();
        self.oldest.o_lt_ok.next = self.ops[0].lt_ok.val();
        self.oldest.o_done0.next = self.ops[0].done0.val();
        self.oldest.o_done1.next = self.ops[0].done1.val();
        self.oldest.o_root0.next = self.ops[0].root0.val();
        self.oldest.o_root1.next = self.ops[0].root1.val();
        self.oldest.o_slot0.next = self.ops[0].slot0.val();
        self.oldest.o_slot1.next = self.ops[0].slot1.val();
        self.retire.next = self.oldest.retire.val();
        self.mk_ready.next = self.oldest.mk_ready.val();
        // Places free after this cycle's retire (the ones in use come
        // first); a new op goes to the first, with one free, whatever the
        // read port does (`op_take` reads no word).
        for i in 0..(self._n - 1) {
            self.free[i].next =
                !self.ops[i].valid.val() | (self.retire.val() & !self.ops[i + 1].valid.val());
        }
        for i in (self._n - 1)..(self._n) {
            self.free[i].next = !self.ops[i].valid.val() | self.retire.val();
        }
        self.take[0].next = self.op_valid.val() & self.free[0].val();
        for i in 1..(self._n) {
            self.take[i].next = self.op_valid.val() & self.free[i].val() & !self.free[i - 1].val();
        }
        for i in (self._n - 1)..(self._n) {
            self.op_take.next = self.op_valid.val() & self.free[i].val();
        }
        // The read this cycle: the oldest still to issue (`FccSetReads`'
        // head, from flip-flops), else the new op's first. The address
        // does not wait for `op_take`: an op not taken reads a word no
        // token follows.
        self.reads.clk.next = self.clk.val();
        self.reads.rst.next = self.rst.val();
        self.reads.busy.next = self.more.val();
        self.reads.take.next = self.op_take.val();
        self.reads.is_join.next = self.op_join.val();
        self.reads.seq.next = self.seq.q.val();
        self.reads.a.next = self.op_a.val();
        self.reads.b.next = self.op_b.val();
        self.issue.next = !self.more.val() & (self.reads.valid.val() | self.op_take.val());
        self.issue_seq.next = self.reads.head.val().seq;
        self.issue_side.next = self.reads.head.val().side;
        self.issue_addr.next = self.reads.head.val().addr;
        if !self.reads.valid.val() {
            self.issue_seq.next = self.seq.q.val();
            self.issue_side.next = false;
            self.issue_addr.next = self.op_a.val();
        }
        if self.op_take.val() {
            self.seq.d.next = self.seq.q.val() + self.one_seq.val();
        }
        // This cycle's read: the walk going on, else what was issued.
        self.p2_valid.d.next = self.p1_valid.q.val();
        self.p2_seq.d.next = self.p1_seq.q.val();
        self.p2_side.d.next = self.p1_side.q.val();
        self.p2_addr.d.next = self.p1_addr.q.val();
        self.rd_valid.next = self.issue.val();
        self.rd_addr.next = self.issue_addr.val();
        self.p1_seq.d.next = self.issue_seq.val();
        self.p1_side.d.next = self.issue_side.val();
        if self.more.val() {
            self.rd_valid.next = true;
            self.rd_addr.next = self.word_parent.val();
            self.p1_seq.d.next = self.p2_seq.q.val();
            self.p1_side.d.next = self.p2_side.q.val();
        }
        self.p1_valid.d.next = self.rd_valid.val();
        self.p1_addr.d.next = self.rd_addr.val();
        // The port reads every cycle (the enable would wait for
        // `op_take`); a word shows with a token only when `p2_valid`.
        self.read_en.next = true;
        self.read_addr.next = self.rd_addr.val();
        // The ops: a new one taken, roots found and chased, the others
        // moving up as the oldest retires.
        for i in 0..(self._n) {
            self.ops[i].take.next = self.take[i].val();
            self.ops[i].seq.next = self.seqs[i].q.val();
            self.ops[i].take_join.next = self.op_join.val();
            self.ops[i].take_under.next = self.op_under.val();
            self.ops[i].shift.next = self.retire.val();
            self.ops[i].w_done.next = self.w_done.val();
            self.ops[i].w_seq.next = self.p2_seq.q.val();
            self.ops[i].w_side.next = self.p2_side.q.val();
            self.ops[i].w_root.next = self.p2_addr.q.val();
            self.ops[i].w_slot.next = self.word_slot.val();
            self.ops[i].l_valid.next = self.oldest.l_valid.val();
            self.ops[i].l_gone.next = self.oldest.l_gone.val();
            self.ops[i].l_keep.next = self.oldest.l_keep.val();
            self.ops[i].l_keep_slot.next = self.oldest.l_keep_slot.val();
        }
        for i in 0..(self._n - 1) {
            self.ops[i].sh_valid.next = self.ops[i + 1].valid.val();
            self.ops[i].sh_seq.next = self.seqs[i + 1].q.val();
            if self.retire.val() {
                self.seqs[i].d.next = self.seqs[i + 1].q.val();
            }
            self.ops[i].sh_join.next = self.ops[i + 1].is_join.val();
            self.ops[i].sh_under.next = self.ops[i + 1].under.val();
            self.ops[i].sh_lt.next = self.ops[i + 1].lt.val();
            self.ops[i].sh_lt_ok.next = self.ops[i + 1].lt_ok.val();
            self.ops[i].sh_done0.next = self.ops[i + 1].done0.val();
            self.ops[i].sh_root0.next = self.ops[i + 1].root0.val();
            self.ops[i].sh_slot0.next = self.ops[i + 1].slot0.val();
            self.ops[i].sh_done1.next = self.ops[i + 1].done1.val();
            self.ops[i].sh_root1.next = self.ops[i + 1].root1.val();
            self.ops[i].sh_slot1.next = self.ops[i + 1].slot1.val();
        }
        for i in (self._n - 1)..(self._n) {
            self.ops[i].sh_valid.next = false;
            self.ops[i].sh_seq.next = self.zero_seq.val();
            self.ops[i].sh_join.next = false;
            self.ops[i].sh_under.next = false;
            self.ops[i].sh_lt.next = false;
            self.ops[i].sh_lt_ok.next = false;
            self.ops[i].sh_done0.next = false;
            self.ops[i].sh_root0.next = self.ops[i].root0.val();
            self.ops[i].sh_slot0.next = self.ops[i].slot0.val();
            self.ops[i].sh_done1.next = false;
            self.ops[i].sh_root1.next = self.ops[i].root1.val();
            self.ops[i].sh_slot1.next = self.ops[i].slot1.val();
        }
        // A new op's sequence number goes with it (after the move up).
        for i in 0..(self._n) {
            if self.take[i].val() {
                self.seqs[i].d.next = self.seq.q.val();
            }
        }
        // Retire: the event, the link.
        self.link_en.next = self.oldest.link_en.val();
        self.link_gone.next = self.oldest.link_gone.val();
        self.link_keep.next = self.oldest.link_keep.val();
        self.ev_valid.next = self.oldest.ev_valid.val();
        self.ev_join.next = self.oldest.ev_join.val();
        self.ev_merged.next = self.oldest.ev_merged.val();
        self.ev_keep.next = self.oldest.ev_keep.val();
        self.ev_keep_slot.next = self.oldest.ev_keep_slot.val();
        self.ev_gone.next = self.oldest.ev_gone.val();
        self.ev_gone_slot.next = self.oldest.ev_gone_slot.val();
        self.busy.next = self.oldest.ev_valid.val();
        for i in 0..(self._n) {
            if self.ops[i].valid.val() {
                self.busy.next = true;
            }
        }
        self.idle.next = !self.busy.val();
        if self.rst.val() {
            self.p1_valid.d.next = false;
            self.p2_valid.d.next = false;
            self.seq.d.next = self.zero_seq.val();
        }
    }
}
