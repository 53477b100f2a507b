//! `FccSlotReturns`: the record slots' two ways back to the slot pool
//! (docs/column-core.md, item 8, "The record store half"), one return a
//! cycle out (`ret_*`, into `FccLabelPool`'s). A merge's gone slot (`a_*`)
//! and a closed record's slot (`b_*`) may come in the same cycle; the one
//! not returned then waits in a register (`held`) and goes first in the
//! next cycle. Closes come at least `CLOSE_GAP` cycles apart and merges
//! two cycles apart, so at most one waits; a slot that would be lost
//! instead sets `bad` (sticky until a reset).

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;

#[derive(LogicBlock, Default)]
pub struct FccSlotReturns {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub a_valid: Signal<In, Bit>,
    pub a_slot: Signal<In, Bits<SLOT_BITS>>,
    pub b_valid: Signal<In, Bit>,
    pub b_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ret_valid: Signal<Out, Bit>,
    pub ret_slot: Signal<Out, Bits<SLOT_BITS>>,
    /// Nothing waits.
    pub empty: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
    held_v: DFF<Bit>,
    held: DFF<Bits<SLOT_BITS>>,
    lost: DFF<Bit>,
}

impl Logic for FccSlotReturns {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, held_v, held, lost);
        self.held_v.d.next = false;
        self.lost.d.next = self.lost.q.val();
        self.ret_valid.next = self.held_v.q.val() | self.a_valid.val() | self.b_valid.val();
        self.ret_slot.next = self.b_slot.val();
        if self.a_valid.val() {
            self.ret_slot.next = self.a_slot.val();
        }
        if self.held_v.q.val() {
            self.ret_slot.next = self.held.q.val();
            // The held one goes; a new one waits.
            self.held_v.d.next = self.a_valid.val() | self.b_valid.val();
            self.held.d.next = self.b_slot.val();
            if self.a_valid.val() {
                self.held.d.next = self.a_slot.val();
            }
            if self.a_valid.val() & self.b_valid.val() {
                self.lost.d.next = true;
            }
        } else if self.a_valid.val() & self.b_valid.val() {
            self.held_v.d.next = true;
            self.held.d.next = self.b_slot.val();
        }
        self.empty.next = !self.held_v.q.val();
        self.bad.next = self.lost.q.val();
        if self.rst.val() {
            self.held_v.d.next = false;
            self.lost.d.next = false;
        }
    }
}
