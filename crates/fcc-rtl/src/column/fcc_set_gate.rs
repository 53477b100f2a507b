//! `FccSetGate`: the issue of `FccSetQueue`'s head. With an entry free in
//! `FccSetOrder` (`space`), a make with a free slot or a column marker is
//! taken at once (`direct`), a find or a join is offered to
//! `FccLabelSets` (`op_valid`) and taken when it takes it (`op_take`).
//! What was taken is registered (`took`, `tag`, `made`) for the order,
//! which reserves its entry a cycle later, and a make goes to the union-
//! find's write port a cycle later too (the FIFO's next op shows two
//! cycles after a take). Kept apart from the order so that `op_valid`
//! does not wait on `op_take`.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_set_order::{SetQTag, SetRes};
use super::fcc_set_queue::SetQOp;

#[derive(LogicBlock, Default)]
pub struct FccSetGate {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub h_valid: Signal<In, Bit>,
    pub h_op: Signal<In, SetQOp>,
    pub h_take: Signal<Out, Bit>,
    pub space: Signal<In, Bit>,
    pub slot_ok: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    pub slot_take: Signal<Out, Bit>,
    pub op_valid: Signal<Out, Bit>,
    pub op_take: Signal<In, Bit>,
    // A cycle after the take: the make's write, and what the order keeps.
    pub mk_valid: Signal<Out, Bit>,
    pub mk_label: Signal<Out, Bits<16>>,
    pub mk_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub took: Signal<Out, Bit>,
    pub took_op: Signal<Out, Bit>,
    pub took_direct: Signal<Out, Bit>,
    pub took_tag: Signal<Out, SetQTag>,
    pub took_made: Signal<Out, SetRes>,
    direct: Signal<Local, Bit>,
    tag: Signal<Local, SetQTag>,
    made: Signal<Local, SetRes>,
    mk_q: DFF<Bit>,
    took_q: DFF<Bit>,
    op_q: DFF<Bit>,
    direct_q: DFF<Bit>,
    tag_q: DFF<SetQTag>,
    made_q: DFF<SetRes>,
}

impl Logic for FccSetGate {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, mk_q, took_q, op_q, direct_q, tag_q, made_q);
        self.slot_take.next =
            self.h_valid.val() & self.space.val() & self.h_op.val().make & self.slot_ok.val();
        self.direct.next =
            self.slot_take.val() | (self.h_valid.val() & self.space.val() & self.h_op.val().mark);
        self.op_valid.next =
            self.h_valid.val() & self.space.val() & !self.h_op.val().make & !self.h_op.val().mark;
        self.h_take.next = self.direct.val() | self.op_take.val();
        self.tag.next.make = self.h_op.val().make;
        self.tag.next.join = self.h_op.val().join;
        self.tag.next.mark = self.h_op.val().mark;
        self.tag.next.ring = self.h_op.val().ring;
        self.tag.next.col = self.h_op.val().col;
        self.tag.next.row = self.h_op.val().row;
        self.made.next.merged = false;
        self.made.next.label = self.h_op.val().a;
        self.made.next.slot = self.slot.val();
        self.made.next.other = self.slot.val();
        self.mk_q.d.next = self.slot_take.val();
        self.took_q.d.next = self.h_take.val();
        self.op_q.d.next = self.op_take.val();
        self.direct_q.d.next = self.direct.val();
        self.tag_q.d.next = self.tag.val();
        self.made_q.d.next = self.made.val();
        self.mk_valid.next = self.mk_q.q.val();
        self.mk_label.next = self.made_q.q.val().label;
        self.mk_slot.next = self.made_q.q.val().slot;
        self.took.next = self.took_q.q.val();
        self.took_op.next = self.op_q.q.val();
        self.took_direct.next = self.direct_q.q.val();
        self.took_tag.next = self.tag_q.q.val();
        self.took_made.next = self.made_q.q.val();
        if self.rst.val() {
            self.mk_q.d.next = false;
            self.took_q.d.next = false;
            self.op_q.d.next = false;
            self.direct_q.d.next = false;
        }
    }
}
