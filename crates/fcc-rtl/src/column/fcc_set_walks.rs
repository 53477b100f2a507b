//! `FccSetWalks`: the walks and the order of `FccLabelSets`, the column
//! core's union-find over labels (docs/column-core.md, item 3). The table's
//! read port takes one read a cycle, answered two cycles later; a walk
//! (a *token*: which op, which side, the label read) whose word is not its
//! root reads the parent at once, in the cycle its word shows, so up to
//! two walks share the port, one a cycle each.
//!
//! Ops are taken in order, at most two at once: a find (`op_join` low:
//! the root of `op_a`) or a join (the roots of `op_a` and `op_b`, then the
//! larger root linked under the smaller), a join alone. They retire in
//! order, one a cycle, each with one event (`ev_*`, registered): a find's
//! root and its slot; a join's two roots and slots, `ev_merged` when they
//! differed and the link was written. A join's link is written on the
//! write port when no make is (makes come first), and no op starts in that
//! cycle, so every read after it sees it; finds write nothing, so two
//! overlap. A new op starts only with a free read port, by reading its
//! first word. The older op is A (a find or a join), the younger B (a
//! find, beside a find only), each known by a sequence bit its walks
//! carry; B becomes A when A retires.

use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct FccSetWalks {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_join: Signal<In, Bit>,
    pub op_a: Signal<In, Bits<16>>,
    pub op_b: Signal<In, Bits<16>>,
    pub op_take: Signal<Out, Bit>,
    /// A make is written this cycle (the write port is taken).
    pub mk_valid: Signal<In, Bit>,
    // The read port: the word read two cycles ago shows now.
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<16>>,
    pub word_parent: Signal<In, Bits<16>>,
    pub word_slot: Signal<In, Bits<9>>,
    // The link write: `parent[link_gone] = link_keep`.
    pub link_en: Signal<Out, Bit>,
    pub link_gone: Signal<Out, Bits<16>>,
    pub link_keep: Signal<Out, Bits<16>>,
    pub ev_valid: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_keep: Signal<Out, Bits<16>>,
    pub ev_keep_slot: Signal<Out, Bits<9>>,
    pub ev_gone: Signal<Out, Bits<16>>,
    pub ev_gone_slot: Signal<Out, Bits<9>>,
    /// No op in progress, no event to come.
    pub idle: Signal<Out, Bit>,
    // Tokens issued one (`p1`) and two (`p2`) cycles ago.
    p1_valid: DFF<Bit>,
    p1_seq: DFF<Bit>,
    p1_side: DFF<Bit>,
    p1_addr: DFF<Bits<16>>,
    p2_valid: DFF<Bit>,
    p2_seq: DFF<Bit>,
    p2_side: DFF<Bit>,
    p2_addr: DFF<Bits<16>>,
    a_valid: DFF<Bit>,
    a_seq: DFF<Bit>,
    a_join: DFF<Bit>,
    a_lb: DFF<Bits<16>>,
    /// A join's second read is still to issue.
    a_bpend: DFF<Bit>,
    a_done0: DFF<Bit>,
    a_root0: DFF<Bits<16>>,
    a_slot0: DFF<Bits<9>>,
    a_done1: DFF<Bit>,
    a_root1: DFF<Bits<16>>,
    a_slot1: DFF<Bits<9>>,
    b_valid: DFF<Bit>,
    b_seq: DFF<Bit>,
    b_done: DFF<Bit>,
    b_root: DFF<Bits<16>>,
    b_slot: DFF<Bits<9>>,
    /// The next op's sequence bit.
    seq: DFF<Bit>,
    evv: DFF<Bit>,
    evj: DFF<Bit>,
    evm: DFF<Bit>,
    evk: DFF<Bits<16>>,
    evks: DFF<Bits<9>>,
    evg: DFF<Bits<16>>,
    evgs: DFF<Bits<9>>,
    retire: Signal<Local, Bit>,
    linking: Signal<Local, Bit>,
    /// A join whose root 1 is the smaller; the roots kept and gone.
    swap: Signal<Local, Bit>,
    keep: Signal<Local, Bits<16>>,
    keep_slot: Signal<Local, Bits<9>>,
    gone: Signal<Local, Bits<16>>,
    gone_slot: Signal<Local, Bits<9>>,
    /// A and B after this cycle's retire.
    a_free: Signal<Local, Bit>,
    a_find: Signal<Local, Bit>,
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
    rd_valid: Signal<Local, Bit>,
    rd_addr: Signal<Local, Bits<16>>,
}

impl Logic for FccSetWalks {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, p1_valid, p1_seq, p1_side, p1_addr, p2_valid, p2_seq, p2_side, p2_addr,
            a_valid, a_seq, a_join, a_lb, a_bpend, a_done0, a_root0, a_slot0, a_done1, a_root1,
            a_slot1, b_valid, b_seq, b_done, b_root, b_slot, seq, evv, evj, evm, evk, evks, evg,
            evgs
        );
        // The word that shows: a root ends its walk.
        self.more.next = self.p2_valid.q.val() & (self.word_parent.val() != self.p2_addr.q.val());
        self.w_done.next = self.p2_valid.q.val() & !self.more.val();
        // Retire A once its walks are done (a join's link waits for the
        // write port).
        self.retire.next = self.a_valid.q.val()
            & self.a_done0.q.val()
            & (!self.a_join.q.val() | (self.a_done1.q.val() & !self.mk_valid.val()));
        self.linking.next = self.retire.val()
            & self.a_join.q.val()
            & (self.a_root0.q.val() != self.a_root1.q.val());
        self.swap.next = self.a_join.q.val() & (self.a_root1.q.val() < self.a_root0.q.val());
        self.keep.next = self.a_root0.q.val();
        self.keep_slot.next = self.a_slot0.q.val();
        self.gone.next = self.a_root1.q.val();
        self.gone_slot.next = self.a_slot1.q.val();
        if self.swap.val() {
            self.keep.next = self.a_root1.q.val();
            self.keep_slot.next = self.a_slot1.q.val();
            self.gone.next = self.a_root0.q.val();
            self.gone_slot.next = self.a_slot0.q.val();
        }
        self.a_free.next = !self.a_valid.q.val() | (self.retire.val() & !self.b_valid.q.val());
        self.a_find.next = (self.a_valid.q.val() & !self.retire.val() & !self.a_join.q.val())
            | (self.retire.val() & self.b_valid.q.val());
        self.b_free.next = !self.b_valid.q.val() | self.retire.val();
        // The read this cycle: a join's second, else a new op's first.
        self.issue.next = false;
        self.issue_seq.next = self.a_seq.q.val();
        self.issue_side.next = true;
        self.issue_addr.next = self.a_lb.q.val();
        self.take_a.next = false;
        self.take_b.next = false;
        if !self.more.val() {
            if self.a_valid.q.val() & self.a_bpend.q.val() {
                self.issue.next = true;
                self.a_bpend.d.next = false;
            } else if self.op_valid.val() & !self.linking.val() {
                self.take_a.next = self.a_free.val();
                self.take_b.next = !self.a_free.val()
                    & self.a_find.val()
                    & self.b_free.val()
                    & !self.op_join.val();
            }
        }
        self.op_take.next = self.take_a.val() | self.take_b.val();
        if self.op_take.val() {
            self.issue.next = true;
            self.issue_seq.next = self.seq.q.val();
            self.issue_side.next = false;
            self.issue_addr.next = self.op_a.val();
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
        self.read_en.next = self.rd_valid.val();
        self.read_addr.next = self.rd_addr.val();
        // The walks' roots.
        if self.w_done.val() {
            if self.a_valid.q.val() & (self.p2_seq.q.val() == self.a_seq.q.val()) {
                if self.p2_side.q.val() {
                    self.a_done1.d.next = true;
                    self.a_root1.d.next = self.p2_addr.q.val();
                    self.a_slot1.d.next = self.word_slot.val();
                } else {
                    self.a_done0.d.next = true;
                    self.a_root0.d.next = self.p2_addr.q.val();
                    self.a_slot0.d.next = self.word_slot.val();
                }
            } else {
                self.b_done.d.next = true;
                self.b_root.d.next = self.p2_addr.q.val();
                self.b_slot.d.next = self.word_slot.val();
            }
        }
        // Retire: the event; B (with a root it finds now) becomes A.
        self.evv.d.next = self.retire.val();
        self.evj.d.next = self.a_join.q.val();
        self.evm.d.next = self.linking.val();
        self.evk.d.next = self.keep.val();
        self.evks.d.next = self.keep_slot.val();
        self.evg.d.next = self.gone.val();
        self.evgs.d.next = self.gone_slot.val();
        self.link_en.next = self.linking.val();
        self.link_gone.next = self.gone.val();
        self.link_keep.next = self.keep.val();
        if self.retire.val() {
            self.a_valid.d.next = self.b_valid.q.val();
            self.a_seq.d.next = self.b_seq.q.val();
            self.a_join.d.next = false;
            self.a_bpend.d.next = false;
            self.a_done0.d.next = self.b_done.q.val();
            self.a_root0.d.next = self.b_root.q.val();
            self.a_slot0.d.next = self.b_slot.q.val();
            if self.w_done.val()
                & self.b_valid.q.val()
                & (self.p2_seq.q.val() == self.b_seq.q.val())
            {
                self.a_done0.d.next = true;
                self.a_root0.d.next = self.p2_addr.q.val();
                self.a_slot0.d.next = self.word_slot.val();
            }
            self.b_valid.d.next = false;
        }
        if self.take_a.val() {
            self.a_valid.d.next = true;
            self.a_seq.d.next = self.seq.q.val();
            self.a_join.d.next = self.op_join.val();
            self.a_lb.d.next = self.op_b.val();
            self.a_bpend.d.next = self.op_join.val();
            self.a_done0.d.next = false;
            self.a_done1.d.next = false;
        }
        if self.take_b.val() {
            self.b_valid.d.next = true;
            self.b_seq.d.next = self.seq.q.val();
            self.b_done.d.next = false;
        }
        self.ev_valid.next = self.evv.q.val();
        self.ev_join.next = self.evj.q.val();
        self.ev_merged.next = self.evm.q.val();
        self.ev_keep.next = self.evk.q.val();
        self.ev_keep_slot.next = self.evks.q.val();
        self.ev_gone.next = self.evg.q.val();
        self.ev_gone_slot.next = self.evgs.q.val();
        self.idle.next = !self.a_valid.q.val() & !self.b_valid.q.val() & !self.evv.q.val();
        if self.rst.val() {
            self.p1_valid.d.next = false;
            self.p2_valid.d.next = false;
            self.a_valid.d.next = false;
            self.b_valid.d.next = false;
            self.evv.d.next = false;
            self.seq.d.next = false;
        }
    }
}
