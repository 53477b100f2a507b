//! `FccSetWalks`: the walks and the order of `FccLabelSets`, the column
//! core's union-find over labels (docs/column-core.md, item 3). The table's
//! read port takes one read a cycle, answered two cycles later; a walk
//! (a *token*: which op, which side, the label read) whose word is not its
//! root reads the parent at once, in the cycle its word shows, so up to
//! two walks share the port, one a cycle each.
//!
//! Ops are taken in order, two in flight (`FccSetOp`: A the older, B the
//! younger, known by a sequence bit their walks carry): a find (`op_join`
//! low: the root of `op_a`) or a join (the roots of `op_a` and `op_b`,
//! then the larger root linked under the smaller). A new op is taken
//! while A or B is free, whatever the read port does, so that `op_take`
//! reads no word (it ends the queue's longest path); its reads go at the
//! free cycles of the port, older ops' first (its first read in the cycle
//! it is taken when the port is free). Ops retire in order, one a cycle, each with one
//! event (`ev_*`, registered): a find's root and its slot; a join's two
//! roots and slots, `ev_merged` when they differed and the link was
//! written (a make waits for the write port while a join may retire:
//! `mk_ready`). B becomes A when A retires.
//!
//! A walk that read the linked word before the link was written (B's, or
//! one started in the link's cycle) found a root that no longer is one: for
//! two cycles after a link its root, recorded or arriving, is chased to the
//! root kept (`FccSetOp`). No op retires in the first of them, when a root
//! recorded before the link may still be the linked one; by the second,
//! every recorded root is chased and every arriving one is chased as it
//! arrives, so an op may retire (and link again: two links are two cycles
//! apart at least, so a root misses one link at most). Reads issued after
//! the link's cycle see it.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_set_op::FccSetOp;

#[derive(LogicBlock, Default)]
pub struct FccSetWalks {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_join: Signal<In, Bit>,
    pub op_a: Signal<In, Bits<16>>,
    pub op_b: Signal<In, Bits<16>>,
    pub op_take: Signal<Out, Bit>,
    /// A make may take the write port this cycle: no join of A can retire
    /// (and link) in it. From flip-flops only.
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
    opa: FccSetOp,
    opb: FccSetOp,
    // Tokens issued one (`p1`) and two (`p2`) cycles ago.
    p1_valid: DFF<Bit>,
    p1_seq: DFF<Bit>,
    p1_side: DFF<Bit>,
    p1_addr: DFF<Bits<16>>,
    p2_valid: DFF<Bit>,
    p2_seq: DFF<Bit>,
    p2_side: DFF<Bit>,
    p2_addr: DFF<Bits<16>>,
    /// The next op's sequence bit.
    seq: DFF<Bit>,
    /// The last link, for the two cycles after it (`l1`, `l2`).
    l1: DFF<Bit>,
    l2: DFF<Bit>,
    l_gone: DFF<Bits<16>>,
    l_keep: DFF<Bits<16>>,
    l_keep_slot: DFF<Bits<SLOT_BITS>>,
    evv: DFF<Bit>,
    evj: DFF<Bit>,
    evm: DFF<Bit>,
    evk: DFF<Bits<16>>,
    evks: DFF<Bits<SLOT_BITS>>,
    evg: DFF<Bits<16>>,
    evgs: DFF<Bits<SLOT_BITS>>,
    l_valid: Signal<Local, Bit>,
    retire: Signal<Local, Bit>,
    linking: Signal<Local, Bit>,
    /// A join whose root 1 is the smaller; the roots kept and gone.
    swap: Signal<Local, Bit>,
    /// Root 1 is the smaller, and the roots a link writes (a join's
    /// only: without the find's case, the write's word is a level sooner).
    lt: Signal<Local, Bit>,
    w_keep: Signal<Local, Bits<16>>,
    w_gone: Signal<Local, Bits<16>>,
    keep: Signal<Local, Bits<16>>,
    keep_slot: Signal<Local, Bits<SLOT_BITS>>,
    gone: Signal<Local, Bits<16>>,
    gone_slot: Signal<Local, Bits<SLOT_BITS>>,
    /// A and B free after this cycle's retire.
    a_free: Signal<Local, Bit>,
    b_free: Signal<Local, Bit>,
    take_a: Signal<Local, Bit>,
    take_b: Signal<Local, Bit>,
    /// `p2`'s word is not its root: the walk reads on; else a walk is done
    /// (`w_done`) and the port is free for a new read (`issue`).
    more: Signal<Local, Bit>,
    w_done: Signal<Local, Bit>,
    issue: Signal<Local, Bit>,
    issue_seq: Signal<Local, Bit>,
    issue_side: Signal<Local, Bit>,
    issue_addr: Signal<Local, Bits<16>>,
    /// The op taken now has its first read issued now.
    new_sent: Signal<Local, Bit>,
    rd_valid: Signal<Local, Bit>,
    rd_addr: Signal<Local, Bits<16>>,
}

impl Logic for FccSetWalks {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            p1_valid,
            p1_seq,
            p1_side,
            p1_addr,
            p2_valid,
            p2_seq,
            p2_side,
            p2_addr,
            seq,
            l1,
            l2,
            l_gone,
            l_keep,
            l_keep_slot,
            evv,
            evj,
            evm,
            evk,
            evks,
            evg,
            evgs
        );
        self.opa.clk.next = self.clk.val();
        self.opb.clk.next = self.clk.val();
        self.opa.rst.next = self.rst.val();
        self.opb.rst.next = self.rst.val();
        // The word that shows: a root ends its walk.
        self.more.next = self.p2_valid.q.val() & (self.word_parent.val() != self.p2_addr.q.val());
        self.w_done.next = self.p2_valid.q.val() & !self.more.val();
        self.l_valid.next = self.l1.q.val() | self.l2.q.val();
        // Retire A once its walks are done and its roots chased: not in the
        // cycle after a link, when a root recorded before it may be the one
        // linked. A join that may retire keeps the write port from makes
        // (whether it links or not: `mk_ready` reads no root).
        self.retire.next = self.opa.valid.val()
            & self.opa.done0.val()
            & !self.l1.q.val()
            & (!self.opa.is_join.val() | self.opa.done1.val());
        self.mk_ready.next = !(self.opa.valid.val()
            & self.opa.done0.val()
            & !self.l1.q.val()
            & self.opa.is_join.val()
            & self.opa.done1.val());
        self.linking.next = self.retire.val()
            & self.opa.is_join.val()
            & (self.opa.root0.val() != self.opa.root1.val());
        self.lt.next = self.opa.root1.val() < self.opa.root0.val();
        self.swap.next = self.opa.is_join.val() & self.lt.val();
        self.w_keep.next = self.opa.root0.val();
        self.w_gone.next = self.opa.root1.val();
        if self.lt.val() {
            self.w_keep.next = self.opa.root1.val();
            self.w_gone.next = self.opa.root0.val();
        }
        self.keep.next = self.opa.root0.val();
        self.keep_slot.next = self.opa.slot0.val();
        self.gone.next = self.opa.root1.val();
        self.gone_slot.next = self.opa.slot1.val();
        if self.swap.val() {
            self.keep.next = self.opa.root1.val();
            self.keep_slot.next = self.opa.slot1.val();
            self.gone.next = self.opa.root0.val();
            self.gone_slot.next = self.opa.slot0.val();
        }
        self.a_free.next = !self.opa.valid.val() | (self.retire.val() & !self.opb.valid.val());
        self.b_free.next = !self.opb.valid.val() | self.retire.val();
        // An op is taken with A or B free, whatever the read port does
        // (`op_take` reads no word); its first read goes now if the port
        // is free and no read of the ops before it is still to issue.
        self.take_a.next = self.op_valid.val() & self.a_free.val();
        self.take_b.next = self.op_valid.val() & !self.a_free.val() & self.b_free.val();
        self.op_take.next = self.take_a.val() | self.take_b.val();
        // The read this cycle: A's reads still to issue, first side
        // first, then B's, then the new op's first.
        self.issue.next = false;
        self.issue_seq.next = self.opa.seq.val();
        self.issue_side.next = false;
        self.issue_addr.next = self.opa.la.val();
        self.new_sent.next = false;
        self.opa.a_sent.next = false;
        self.opb.a_sent.next = false;
        self.opa.b_sent.next = false;
        self.opb.b_sent.next = false;
        if !self.more.val() {
            if self.opa.valid.val() & self.opa.apend.val() {
                self.issue.next = true;
                self.opa.a_sent.next = true;
            } else if self.opa.valid.val() & self.opa.bpend.val() {
                self.issue.next = true;
                self.issue_side.next = true;
                self.issue_addr.next = self.opa.lb.val();
                self.opa.b_sent.next = true;
            } else if self.opb.valid.val() & self.opb.apend.val() {
                self.issue.next = true;
                self.issue_seq.next = self.opb.seq.val();
                self.issue_addr.next = self.opb.la.val();
                self.opb.a_sent.next = true;
            } else if self.opb.valid.val() & self.opb.bpend.val() {
                self.issue.next = true;
                self.issue_seq.next = self.opb.seq.val();
                self.issue_side.next = true;
                self.issue_addr.next = self.opb.lb.val();
                self.opb.b_sent.next = true;
            } else if self.op_valid.val() {
                // The address does not wait for `op_take`: an op not taken
                // reads a word no token follows.
                self.issue.next = self.op_take.val();
                self.issue_seq.next = self.seq.q.val();
                self.issue_addr.next = self.op_a.val();
                self.new_sent.next = self.op_take.val();
            }
        }
        if self.op_take.val() {
            self.seq.d.next = !self.seq.q.val();
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
        // The ops: a new one taken, roots found and chased, B becoming A.
        self.opa.take.next = self.take_a.val();
        self.opb.take.next = self.take_b.val();
        self.opa.take_seq.next = self.seq.q.val();
        self.opb.take_seq.next = self.seq.q.val();
        self.opa.take_join.next = self.op_join.val();
        self.opb.take_join.next = self.op_join.val();
        self.opa.take_la.next = self.op_a.val();
        self.opb.take_la.next = self.op_a.val();
        self.opa.take_apend.next = !self.new_sent.val();
        self.opb.take_apend.next = !self.new_sent.val();
        self.opa.take_lb.next = self.op_b.val();
        self.opb.take_lb.next = self.op_b.val();
        self.opa.shift.next = self.retire.val() & self.opb.valid.val();
        self.opa.clear.next = self.retire.val();
        self.opb.shift.next = false;
        self.opb.clear.next = self.retire.val();
        self.opa.sh_valid.next = self.opb.valid.val();
        self.opa.sh_seq.next = self.opb.seq.val();
        self.opa.sh_join.next = self.opb.is_join.val();
        self.opa.sh_la.next = self.opb.la.val();
        self.opa.sh_apend.next = self.opb.apend.val() & !self.opb.a_sent.val();
        self.opa.sh_lb.next = self.opb.lb.val();
        self.opa.sh_bpend.next = self.opb.bpend.val() & !self.opb.b_sent.val();
        self.opa.sh_done0.next = self.opb.done0.val();
        self.opa.sh_root0.next = self.opb.root0.val();
        self.opa.sh_slot0.next = self.opb.slot0.val();
        self.opa.sh_done1.next = self.opb.done1.val();
        self.opa.sh_root1.next = self.opb.root1.val();
        self.opa.sh_slot1.next = self.opb.slot1.val();
        self.opb.sh_valid.next = false;
        self.opb.sh_seq.next = false;
        self.opb.sh_join.next = false;
        self.opb.sh_la.next = self.opb.la.val();
        self.opb.sh_apend.next = false;
        self.opb.sh_lb.next = self.opb.lb.val();
        self.opb.sh_bpend.next = false;
        self.opb.sh_done0.next = false;
        self.opb.sh_root0.next = self.opb.root0.val();
        self.opb.sh_slot0.next = self.opb.slot0.val();
        self.opb.sh_done1.next = false;
        self.opb.sh_root1.next = self.opb.root1.val();
        self.opb.sh_slot1.next = self.opb.slot1.val();
        self.opa.w_done.next = self.w_done.val();
        self.opb.w_done.next = self.w_done.val();
        self.opa.w_seq.next = self.p2_seq.q.val();
        self.opb.w_seq.next = self.p2_seq.q.val();
        self.opa.w_side.next = self.p2_side.q.val();
        self.opb.w_side.next = self.p2_side.q.val();
        self.opa.w_root.next = self.p2_addr.q.val();
        self.opb.w_root.next = self.p2_addr.q.val();
        self.opa.w_slot.next = self.word_slot.val();
        self.opb.w_slot.next = self.word_slot.val();
        self.opa.l_valid.next = self.l_valid.val();
        self.opb.l_valid.next = self.l_valid.val();
        self.opa.l_gone.next = self.l_gone.q.val();
        self.opb.l_gone.next = self.l_gone.q.val();
        self.opa.l_keep.next = self.l_keep.q.val();
        self.opb.l_keep.next = self.l_keep.q.val();
        self.opa.l_keep_slot.next = self.l_keep_slot.q.val();
        self.opb.l_keep_slot.next = self.l_keep_slot.q.val();
        // Retire: the event, the link, kept for the chase.
        self.evv.d.next = self.retire.val();
        self.evj.d.next = self.opa.is_join.val();
        self.evm.d.next = self.linking.val();
        self.evk.d.next = self.keep.val();
        self.evks.d.next = self.keep_slot.val();
        self.evg.d.next = self.gone.val();
        self.evgs.d.next = self.gone_slot.val();
        self.link_en.next = self.linking.val();
        self.link_gone.next = self.w_gone.val();
        self.link_keep.next = self.w_keep.val();
        self.l1.d.next = self.linking.val();
        self.l2.d.next = self.l1.q.val();
        if self.linking.val() {
            self.l_gone.d.next = self.gone.val();
            self.l_keep.d.next = self.keep.val();
            self.l_keep_slot.d.next = self.keep_slot.val();
        }
        self.ev_valid.next = self.evv.q.val();
        self.ev_join.next = self.evj.q.val();
        self.ev_merged.next = self.evm.q.val();
        self.ev_keep.next = self.evk.q.val();
        self.ev_keep_slot.next = self.evks.q.val();
        self.ev_gone.next = self.evg.q.val();
        self.ev_gone_slot.next = self.evgs.q.val();
        self.idle.next = !self.opa.valid.val() & !self.opb.valid.val() & !self.evv.q.val();
        if self.rst.val() {
            self.p1_valid.d.next = false;
            self.p2_valid.d.next = false;
            self.l1.d.next = false;
            self.l2.d.next = false;
            self.evv.d.next = false;
            self.seq.d.next = false;
        }
    }
}
