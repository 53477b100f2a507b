//! `FccSetGate`: the issue of `FccSetQueue`'s head op (the part of the
//! head's entry `FccSetPick` chose). With an entry free in
//! `FccSetOrder` (`space`), a make with a free slot (while `FccLabelSets`
//! takes makes, `mk_ready`) or a column marker is
//! taken at once (`direct`; a make, `slot_take`, goes to `FccLabelSets`'
//! write port in that cycle, so an op naming its label may be taken in the
//! next), a find or a join is offered to `FccLabelSets` (`op_valid`). What
//! the order keeps of the head (`tag`, `made`) is worked out here too.
//! Combinational,
//! and apart from `FccSetTook`, which reads `op_take`: `FccLabelSets` reads
//! `op_valid` and the make before it says `op_take`, and a block that reads
//! `op_take` and gives them would close a loop in the emitted Verilog's
//! ordering.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_set_order::{SetQTag, SetRes};
use super::fcc_set_queue::SetQOp;

#[derive(LogicBlock, Default)]
pub struct FccSetGate {
    pub h_valid: Signal<In, Bit>,
    pub h_op: Signal<In, SetQOp>,
    pub space: Signal<In, Bit>,
    pub slot_ok: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    /// `FccLabelSets` takes a make now.
    pub mk_ready: Signal<In, Bit>,
    pub slot_take: Signal<Out, Bit>,
    pub direct: Signal<Out, Bit>,
    pub op_valid: Signal<Out, Bit>,
    pub tag: Signal<Out, SetQTag>,
    pub made: Signal<Out, SetRes>,
}

impl Logic for FccSetGate {
    #[hdl_gen]
    fn update(&mut self) {
        self.slot_take.next = self.h_valid.val()
            & self.space.val()
            & self.h_op.val().make
            & self.slot_ok.val()
            & self.mk_ready.val();
        self.direct.next =
            self.slot_take.val() | (self.h_valid.val() & self.space.val() & self.h_op.val().mark);
        self.op_valid.next =
            self.h_valid.val() & self.space.val() & !self.h_op.val().make & !self.h_op.val().mark;
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
    }
}
