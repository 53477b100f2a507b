//! `FccSlotUsed`: which record slots of `FccSlotRecords` hold a record
//! written since the slot was last emptied (by a close, by a merge that
//! took its record, by a reset), one flip-flop a slot, so that the block
//! RAM needs no clearing: a slot not in use reads as the empty record.
//! A stage-1 read's flag shows in stage 2 (`used`); stage 3 sets or
//! clears its slot's flag. A slot is never in stages 1 and 3 at once.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;

/// Record slots.
pub const SLOTS: usize = 1 << SLOT_BITS;

#[derive(LogicBlock)]
pub struct FccSlotUsed {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rd_slot: Signal<In, Bits<SLOT_BITS>>,
    pub used: Signal<Out, Bit>,
    pub set: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub wr_slot: Signal<In, Bits<SLOT_BITS>>,
    mask: Signal<Local, Bits<SLOTS>>,
    flags: DFF<Bits<SLOTS>>,
    flag: DFF<Bit>,
    one: Constant<Bits<SLOTS>>,
    none: Constant<Bits<SLOTS>>,
}

impl Default for FccSlotUsed {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rd_slot: Default::default(),
            used: Default::default(),
            set: Default::default(),
            clear: Default::default(),
            wr_slot: Default::default(),
            mask: Default::default(),
            flags: Default::default(),
            flag: Default::default(),
            one: Constant::new(1_u64.to_bits()),
            none: Constant::new(0_u64.to_bits()),
        }
    }
}

impl Logic for FccSlotUsed {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, flags, flag);
        self.flag.d.next = self.flags.q.val().get_bit(self.rd_slot.val().index());
        self.mask.next = self.one.val() << self.wr_slot.val();
        if self.set.val() {
            self.flags.d.next = self.flags.q.val() | self.mask.val();
        }
        if self.clear.val() {
            self.flags.d.next = self.flags.q.val() & !self.mask.val();
        }
        if self.rst.val() {
            self.flags.d.next = self.none.val();
        }
        self.used.next = self.flag.q.val();
    }
}
