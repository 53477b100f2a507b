//! `FccSetTook`: what the op of `FccSetQueue`'s head became in the cycle
//! it was taken (at once, `direct`, or by `FccLabelSets`, `op_take`),
//! registered for `FccSetOrder`, which reserves its entry a cycle later
//! (`took*`); the head's entry leaves the FIFO with its last op
//! (`h_take`), and the part that goes next (`part_d`, which the queue
//! registers: `FccSetPick` must not read a block that reads `op_take`).

use rust_hdl::prelude::*;

use super::fcc_set_order::{SetQTag, SetRes};

#[derive(LogicBlock, Default)]
pub struct FccSetTook {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub direct: Signal<In, Bit>,
    pub op_take: Signal<In, Bit>,
    pub tag: Signal<In, SetQTag>,
    pub made: Signal<In, SetRes>,
    /// The op is its entry's last; the part after it (the first of the
    /// next entry after the last).
    pub last: Signal<In, Bit>,
    pub after: Signal<In, Bits<2>>,
    /// The part in the head's entry now.
    pub part: Signal<In, Bits<2>>,
    pub h_take: Signal<Out, Bit>,
    pub part_d: Signal<Out, Bits<2>>,
    pub took: Signal<Out, Bit>,
    pub took_op: Signal<Out, Bit>,
    pub took_direct: Signal<Out, Bit>,
    pub took_tag: Signal<Out, SetQTag>,
    pub took_made: Signal<Out, SetRes>,
    took_q: DFF<Bit>,
    op_q: DFF<Bit>,
    direct_q: DFF<Bit>,
    tag_q: DFF<SetQTag>,
    made_q: DFF<SetRes>,
    went: Signal<Local, Bit>,
}

impl Logic for FccSetTook {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, took_q, op_q, direct_q, tag_q, made_q);
        self.went.next = self.direct.val() | self.op_take.val();
        self.h_take.next = self.went.val() & self.last.val();
        self.part_d.next = self.part.val();
        if self.went.val() {
            self.part_d.next = self.after.val();
        }
        self.took_q.d.next = self.went.val();
        self.op_q.d.next = self.op_take.val();
        self.direct_q.d.next = self.direct.val();
        self.tag_q.d.next = self.tag.val();
        self.made_q.d.next = self.made.val();
        self.took.next = self.took_q.q.val();
        self.took_op.next = self.op_q.q.val();
        self.took_direct.next = self.direct_q.q.val();
        self.took_tag.next = self.tag_q.q.val();
        self.took_made.next = self.made_q.q.val();
        if self.rst.val() {
            self.took_q.d.next = false;
            self.op_q.d.next = false;
            self.direct_q.d.next = false;
        }
    }
}
