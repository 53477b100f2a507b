//! `FccSlotPipe`: the records' data path in `FccSlotRecords`: in stage 2
//! the word read is merged with the stage's other record, registered for
//! stage 3's write (or, for a close, as the record out). The other record
//! is known a cycle ahead: an add's accumulator, taken with the op; a
//! merge's gone record, in stage 2 while its kept half is in stage 1; the
//! empty record (the merge's identity) for a close. So the merge starts
//! from registers.

use rust_hdl::prelude::*;

use super::fcc_acc_merge::FccAccMerge;
use super::fcc_slot_issue::SlotHalf;
use super::AccWord;

#[derive(LogicBlock)]
pub struct FccSlotPipe {
    pub clk: Signal<In, Clock>,
    pub op_acc: Signal<In, AccWord>,
    pub h1: Signal<In, SlotHalf>,
    /// Stage 2: the word read.
    pub word: Signal<In, AccWord>,
    /// Stage 3: the merged record.
    pub merged: Signal<Out, AccWord>,
    a1: DFF<AccWord>,
    b2: DFF<AccWord>,
    m3: DFF<AccWord>,
    merge: FccAccMerge,
    empty: Constant<AccWord>,
}

impl Default for FccSlotPipe {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            op_acc: Default::default(),
            h1: Default::default(),
            word: Default::default(),
            merged: Default::default(),
            a1: Default::default(),
            b2: Default::default(),
            m3: Default::default(),
            merge: Default::default(),
            empty: Constant::new(AccWord::empty()),
        }
    }
}

impl Logic for FccSlotPipe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, a1, b2, m3);
        self.a1.d.next = self.op_acc.val();
        self.b2.d.next = self.empty.val();
        if self.h1.val() == SlotHalf::Add {
            self.b2.d.next = self.a1.q.val();
        }
        if self.h1.val() == SlotHalf::Keep {
            self.b2.d.next = self.word.val();
        }
        self.merge.a.next = self.word.val();
        self.merge.b.next = self.b2.q.val();
        self.m3.d.next = self.merge.out.val();
        self.merged.next = self.m3.q.val();
    }
}
