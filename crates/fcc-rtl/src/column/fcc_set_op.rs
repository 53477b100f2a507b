//! `FccSetOp`: one op in flight in `FccSetWalks` (docs/column-core.md,
//! item 3): a find or a join (`under`: `a` is a run just started, filed
//! under `b`'s cluster), and per side whether its root is found, the
//! root and its slot. Every output is a flip-flop. Its sequence number
//! (its walks carry it) is its place's, kept by `FccSetWalks`.
//!
//! * `take` loads a new op; `shift` the next place's op (with a root it
//!   finds in this cycle; an empty one at the last place), `take`
//!   winning.
//! * A root arriving for it (`w_*`, by sequence number and side) is recorded;
//!   while a link made in the last two cycles is given (`l_*`), a root
//!   equal to the linked one, arriving or recorded, becomes the root kept:
//!   a walk that read the linked word before the link was written found a
//!   root that is no longer one.
//! * `lt` says root 1 is below root 0, registered (off the link's path):
//!   as a root arrives, against the other side's recorded one; else from
//!   the recorded roots, a cycle after them; moving up, the next place's.
//!   `lt_ok` says it is the roots' order: not when a chase changed a root
//!   in the cycle before (a cycle later it is).

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;

/// Bits of an op's sequence number, which its walks carry: unique among
/// the ops in flight (`SET_OPS` at most `2^SEQ_BITS`).
pub const SEQ_BITS: usize = 2;

#[derive(LogicBlock, Default)]
pub struct FccSetOp {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    /// Its place's sequence number, and the next place's (`FccSetWalks`
    /// keeps them).
    pub seq: Signal<In, Bits<SEQ_BITS>>,
    pub take_join: Signal<In, Bit>,
    pub take_under: Signal<In, Bit>,
    pub shift: Signal<In, Bit>,
    pub sh_valid: Signal<In, Bit>,
    pub sh_seq: Signal<In, Bits<SEQ_BITS>>,
    pub sh_join: Signal<In, Bit>,
    pub sh_under: Signal<In, Bit>,
    /// The next place's `lt` and `lt_ok`.
    pub sh_lt: Signal<In, Bit>,
    pub sh_lt_ok: Signal<In, Bit>,
    pub sh_done0: Signal<In, Bit>,
    pub sh_root0: Signal<In, Bits<16>>,
    pub sh_slot0: Signal<In, Bits<SLOT_BITS>>,
    pub sh_done1: Signal<In, Bit>,
    pub sh_root1: Signal<In, Bits<16>>,
    pub sh_slot1: Signal<In, Bits<SLOT_BITS>>,
    pub w_done: Signal<In, Bit>,
    pub w_seq: Signal<In, Bits<SEQ_BITS>>,
    pub w_side: Signal<In, Bit>,
    pub w_root: Signal<In, Bits<16>>,
    pub w_slot: Signal<In, Bits<SLOT_BITS>>,
    pub l_valid: Signal<In, Bit>,
    pub l_gone: Signal<In, Bits<16>>,
    pub l_keep: Signal<In, Bits<16>>,
    pub l_keep_slot: Signal<In, Bits<SLOT_BITS>>,
    pub valid: Signal<Out, Bit>,
    pub is_join: Signal<Out, Bit>,
    pub under: Signal<Out, Bit>,
    pub lt: Signal<Out, Bit>,
    pub lt_ok: Signal<Out, Bit>,
    pub done0: Signal<Out, Bit>,
    pub root0: Signal<Out, Bits<16>>,
    pub slot0: Signal<Out, Bits<SLOT_BITS>>,
    pub done1: Signal<Out, Bit>,
    pub root1: Signal<Out, Bits<16>>,
    pub slot1: Signal<Out, Bits<SLOT_BITS>>,
    v: DFF<Bit>,
    jn: DFF<Bit>,
    un: DFF<Bit>,
    lt_q: DFF<Bit>,
    lt_okq: DFF<Bit>,
    /// A recorded root is chased this cycle; the arriving one is.
    chased: Signal<Local, Bit>,
    w_chased: Signal<Local, Bit>,
    /// An arriving root against the other side's recorded one (the op's
    /// own, or the next place's as it moves up): root 1 below root 0.
    c_own0: Signal<Local, Bit>,
    c_own1: Signal<Local, Bit>,
    c_sh0: Signal<Local, Bit>,
    c_sh1: Signal<Local, Bit>,
    arr_lt: Signal<Local, Bit>,
    /// The recorded roots' order.
    lt_now: Signal<Local, Bit>,
    d0: DFF<Bit>,
    r0: DFF<Bits<16>>,
    s0: DFF<Bits<SLOT_BITS>>,
    d1: DFF<Bit>,
    r1: DFF<Bits<16>>,
    s1: DFF<Bits<SLOT_BITS>>,
    /// A root arrives for this op (or the one shifted in); the root,
    /// chased.
    mine: Signal<Local, Bit>,
    rt: Signal<Local, Bits<16>>,
    sl: Signal<Local, Bits<SLOT_BITS>>,
}

impl Logic for FccSetOp {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, v, jn, un, lt_q, lt_okq, d0, r0, s0, d1, r1, s1);
        self.rt.next = self.w_root.val();
        self.sl.next = self.w_slot.val();
        // Only a recorded root is chased (an unrecorded one is no word
        // the op has read: after reset it is not even defined).
        self.chased.next = self.l_valid.val()
            & ((self.d0.q.val() & (self.r0.q.val() == self.l_gone.val()))
                | (self.d1.q.val() & (self.r1.q.val() == self.l_gone.val())));
        // The recorded roots' order is the next one's unless a chase
        // changes one.
        self.lt_okq.d.next = !self.chased.val();
        self.w_chased.next = self.l_valid.val() & (self.w_root.val() == self.l_gone.val());
        self.lt_now.next = self.r1.q.val() < self.r0.q.val();
        self.lt_q.d.next = self.lt_now.val();
        self.c_own0.next = self.w_root.val() < self.r0.q.val();
        self.c_own1.next = self.r1.q.val() < self.w_root.val();
        self.c_sh0.next = self.w_root.val() < self.sh_root0.val();
        self.c_sh1.next = self.sh_root1.val() < self.w_root.val();
        self.arr_lt.next = self.c_own1.val();
        if self.w_side.val() {
            self.arr_lt.next = self.c_own0.val();
        }
        if self.shift.val() {
            self.arr_lt.next = self.c_sh1.val();
            if self.w_side.val() {
                self.arr_lt.next = self.c_sh0.val();
            }
        }
        if self.l_valid.val() {
            if self.w_root.val() == self.l_gone.val() {
                self.rt.next = self.l_keep.val();
                self.sl.next = self.l_keep_slot.val();
            }
            if self.d0.q.val() & (self.r0.q.val() == self.l_gone.val()) {
                self.r0.d.next = self.l_keep.val();
                self.s0.d.next = self.l_keep_slot.val();
            }
            if self.d1.q.val() & (self.r1.q.val() == self.l_gone.val()) {
                self.r1.d.next = self.l_keep.val();
                self.s1.d.next = self.l_keep_slot.val();
            }
        }
        self.mine.next = self.w_done.val() & self.v.q.val() & (self.w_seq.val() == self.seq.val());
        if self.shift.val() {
            self.v.d.next = self.sh_valid.val();
            self.jn.d.next = self.sh_join.val();
            self.un.d.next = self.sh_under.val();
            self.d0.d.next = self.sh_done0.val();
            self.r0.d.next = self.sh_root0.val();
            self.s0.d.next = self.sh_slot0.val();
            self.d1.d.next = self.sh_done1.val();
            self.r1.d.next = self.sh_root1.val();
            self.s1.d.next = self.sh_slot1.val();
            self.mine.next =
                self.w_done.val() & self.sh_valid.val() & (self.w_seq.val() == self.sh_seq.val());
            self.lt_q.d.next = self.sh_lt.val();
            self.lt_okq.d.next = self.sh_lt_ok.val();
        }
        if self.mine.val() {
            if self.w_side.val() {
                self.d1.d.next = true;
                self.r1.d.next = self.rt.val();
                self.s1.d.next = self.sl.val();
            } else {
                self.d0.d.next = true;
                self.r0.d.next = self.rt.val();
                self.s0.d.next = self.sl.val();
            }
            // An arriving root gives the order (a chase does not reach an
            // op moving up: it is chased a cycle later).
            self.lt_q.d.next = self.arr_lt.val();
            self.lt_okq.d.next = !self.w_chased.val() & (self.shift.val() | !self.chased.val());
        }
        if self.take.val() {
            self.v.d.next = true;
            self.jn.d.next = self.take_join.val();
            self.un.d.next = self.take_under.val();
            self.d0.d.next = false;
            self.d1.d.next = false;
            self.lt_okq.d.next = false;
        }
        if self.rst.val() {
            self.v.d.next = false;
            self.d0.d.next = false;
            self.d1.d.next = false;
        }
        self.valid.next = self.v.q.val();
        self.is_join.next = self.jn.q.val();
        self.under.next = self.un.q.val();
        self.lt.next = self.lt_q.q.val();
        self.lt_ok.next = self.lt_okq.q.val();
        self.done0.next = self.d0.q.val();
        self.root0.next = self.r0.q.val();
        self.slot0.next = self.s0.q.val();
        self.done1.next = self.d1.q.val();
        self.root1.next = self.r1.q.val();
        self.slot1.next = self.s1.q.val();
    }
}
