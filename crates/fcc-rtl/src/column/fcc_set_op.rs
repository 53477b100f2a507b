//! `FccSetOp`: one op in flight in `FccSetWalks` (docs/column-core.md,
//! item 3): a find or a join, its sequence bit (its walks carry it), its
//! labels and whether their first reads are still to issue (a join's
//! second always; the first when the read port was busy), and per
//! side whether its root is found, the root and its slot. Every output is
//! a flip-flop.
//!
//! * `take` loads a new op; `shift` the other op's state (with a root it
//!   finds in this cycle); `clear` empties it (`take` wins).
//! * A root arriving for it (`w_*`, by sequence bit and side) is recorded;
//!   while a link made in the last two cycles is given (`l_*`), a root
//!   equal to the linked one, arriving or recorded, becomes the root kept:
//!   a walk that read the linked word before the link was written found a
//!   root that is no longer one.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;

#[derive(LogicBlock, Default)]
pub struct FccSetOp {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    pub take_seq: Signal<In, Bit>,
    pub take_join: Signal<In, Bit>,
    pub take_la: Signal<In, Bits<16>>,
    pub take_lb: Signal<In, Bits<16>>,
    /// Its first read is not issued in the cycle it is taken.
    pub take_apend: Signal<In, Bit>,
    pub shift: Signal<In, Bit>,
    pub sh_valid: Signal<In, Bit>,
    pub sh_seq: Signal<In, Bit>,
    pub sh_join: Signal<In, Bit>,
    pub sh_la: Signal<In, Bits<16>>,
    pub sh_apend: Signal<In, Bit>,
    pub sh_lb: Signal<In, Bits<16>>,
    pub sh_bpend: Signal<In, Bit>,
    pub sh_done0: Signal<In, Bit>,
    pub sh_root0: Signal<In, Bits<16>>,
    pub sh_slot0: Signal<In, Bits<SLOT_BITS>>,
    pub sh_done1: Signal<In, Bit>,
    pub sh_root1: Signal<In, Bits<16>>,
    pub sh_slot1: Signal<In, Bits<SLOT_BITS>>,
    pub clear: Signal<In, Bit>,
    /// Its first (second) read issued this cycle.
    pub a_sent: Signal<In, Bit>,
    pub b_sent: Signal<In, Bit>,
    pub w_done: Signal<In, Bit>,
    pub w_seq: Signal<In, Bit>,
    pub w_side: Signal<In, Bit>,
    pub w_root: Signal<In, Bits<16>>,
    pub w_slot: Signal<In, Bits<SLOT_BITS>>,
    pub l_valid: Signal<In, Bit>,
    pub l_gone: Signal<In, Bits<16>>,
    pub l_keep: Signal<In, Bits<16>>,
    pub l_keep_slot: Signal<In, Bits<SLOT_BITS>>,
    pub valid: Signal<Out, Bit>,
    pub seq: Signal<Out, Bit>,
    pub is_join: Signal<Out, Bit>,
    pub la: Signal<Out, Bits<16>>,
    pub apend: Signal<Out, Bit>,
    pub lb: Signal<Out, Bits<16>>,
    pub bpend: Signal<Out, Bit>,
    pub done0: Signal<Out, Bit>,
    pub root0: Signal<Out, Bits<16>>,
    pub slot0: Signal<Out, Bits<SLOT_BITS>>,
    pub done1: Signal<Out, Bit>,
    pub root1: Signal<Out, Bits<16>>,
    pub slot1: Signal<Out, Bits<SLOT_BITS>>,
    v: DFF<Bit>,
    sq: DFF<Bit>,
    jn: DFF<Bit>,
    a: DFF<Bits<16>>,
    ap: DFF<Bit>,
    b: DFF<Bits<16>>,
    bp: DFF<Bit>,
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
        dff_setup!(self, clk, v, sq, jn, a, ap, b, bp, d0, r0, s0, d1, r1, s1);
        self.rt.next = self.w_root.val();
        self.sl.next = self.w_slot.val();
        if self.l_valid.val() {
            if self.w_root.val() == self.l_gone.val() {
                self.rt.next = self.l_keep.val();
                self.sl.next = self.l_keep_slot.val();
            }
            if self.r0.q.val() == self.l_gone.val() {
                self.r0.d.next = self.l_keep.val();
                self.s0.d.next = self.l_keep_slot.val();
            }
            if self.r1.q.val() == self.l_gone.val() {
                self.r1.d.next = self.l_keep.val();
                self.s1.d.next = self.l_keep_slot.val();
            }
        }
        if self.a_sent.val() {
            self.ap.d.next = false;
        }
        if self.b_sent.val() {
            self.bp.d.next = false;
        }
        self.mine.next = self.w_done.val() & self.v.q.val() & (self.w_seq.val() == self.sq.q.val());
        if self.clear.val() {
            self.v.d.next = false;
        }
        if self.shift.val() {
            self.v.d.next = self.sh_valid.val();
            self.sq.d.next = self.sh_seq.val();
            self.jn.d.next = self.sh_join.val();
            self.a.d.next = self.sh_la.val();
            self.ap.d.next = self.sh_apend.val();
            self.b.d.next = self.sh_lb.val();
            self.bp.d.next = self.sh_bpend.val();
            self.d0.d.next = self.sh_done0.val();
            self.r0.d.next = self.sh_root0.val();
            self.s0.d.next = self.sh_slot0.val();
            self.d1.d.next = self.sh_done1.val();
            self.r1.d.next = self.sh_root1.val();
            self.s1.d.next = self.sh_slot1.val();
            self.mine.next =
                self.w_done.val() & self.sh_valid.val() & (self.w_seq.val() == self.sh_seq.val());
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
        }
        if self.take.val() {
            self.v.d.next = true;
            self.sq.d.next = self.take_seq.val();
            self.jn.d.next = self.take_join.val();
            self.a.d.next = self.take_la.val();
            self.ap.d.next = self.take_apend.val();
            self.b.d.next = self.take_lb.val();
            self.bp.d.next = self.take_join.val();
            self.d0.d.next = false;
            self.d1.d.next = false;
        }
        if self.rst.val() {
            self.v.d.next = false;
        }
        self.valid.next = self.v.q.val();
        self.seq.next = self.sq.q.val();
        self.is_join.next = self.jn.q.val();
        self.la.next = self.a.q.val();
        self.apend.next = self.ap.q.val();
        self.lb.next = self.b.q.val();
        self.bpend.next = self.bp.q.val();
        self.done0.next = self.d0.q.val();
        self.root0.next = self.r0.q.val();
        self.slot0.next = self.s0.q.val();
        self.done1.next = self.d1.q.val();
        self.root1.next = self.r1.q.val();
        self.slot1.next = self.s1.q.val();
    }
}
