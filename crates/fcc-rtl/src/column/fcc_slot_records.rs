//! `FccSlotRecords`: the column core's record store (docs/column-core.md,
//! item 3): a cluster's record (its accumulator, `AccWord`) per slot, in
//! block RAM, and the ops the slot table sends it, one taken a cycle at
//! most (`op_take`):
//!
//! * `Add`: a run's accumulator (`op_acc`, a flush of `FccRunAcc`) added
//!   to the record of slot `op_slot`;
//! * `Merge`: the record of `op_other` merged into `op_slot`'s (a union's
//!   gone slot into the kept one; the two differ), `op_other` then empty;
//! * `Close`: the record of `op_slot` out (`out_valid` for a cycle, with
//!   `out_slot` and `out_acc`, three cycles after the op is taken: the
//!   taker has room for it), the slot then empty.
//!
//! Ops take effect in order. A slot that no add or merge wrote since it
//! was emptied holds the empty record: a merge's gone slot and a closed
//! one are written empty in the cycle a kept or added record would be,
//! and after a reset every slot is, one a cycle, before an op is taken
//! (`2^SLOT_BITS` cycles, `idle` low). An op waits while an op in flight
//! touches one of its slots (`FccSlotIssue`), so an op takes a cycle (a
//! merge two) but one on the slot of the op before it waits until that
//! one is written: four cycles apart. This block is wiring.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_slot_issue::{FccSlotIssue, SlotHalf, SlotOp};
use super::fcc_slot_pipe::FccSlotPipe;
use super::AccWord;
use crate::fcc_ram::FccRam;

/// Cycles from an op's taking to its write (or its record out).
pub const SLOT_RECORDS_LATENCY: usize = 3;

/// Record slots.
pub const SLOTS: usize = 1 << SLOT_BITS;

#[derive(LogicBlock)]
pub struct FccSlotRecords {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_kind: Signal<In, SlotOp>,
    pub op_slot: Signal<In, Bits<SLOT_BITS>>,
    pub op_other: Signal<In, Bits<SLOT_BITS>>,
    pub op_acc: Signal<In, AccWord>,
    pub op_take: Signal<Out, Bit>,
    pub out_valid: Signal<Out, Bit>,
    pub out_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub out_acc: Signal<Out, AccWord>,
    /// No op in flight.
    pub idle: Signal<Out, Bit>,
    records: FccRam<AccWord, SLOT_BITS>,
    issue: FccSlotIssue,
    pipe: FccSlotPipe,
    empty: Constant<AccWord>,
}

impl Default for FccSlotRecords {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            op_valid: Default::default(),
            op_kind: Default::default(),
            op_slot: Default::default(),
            op_other: Default::default(),
            op_acc: Default::default(),
            op_take: Default::default(),
            out_valid: Default::default(),
            out_slot: Default::default(),
            out_acc: Default::default(),
            idle: Default::default(),
            records: FccRam::new(SLOTS),
            issue: Default::default(),
            pipe: Default::default(),
            empty: Constant::new(AccWord::empty()),
        }
    }
}

impl Logic for FccSlotRecords {
    #[hdl_gen]
    fn update(&mut self) {
        self.records.clk.next = self.clk.val();
        self.issue.clk.next = self.clk.val();
        self.pipe.clk.next = self.clk.val();
        self.issue.rst.next = self.rst.val();
        self.issue.op_valid.next = self.op_valid.val();
        self.issue.op_kind.next = self.op_kind.val();
        self.issue.op_slot.next = self.op_slot.val();
        self.issue.op_other.next = self.op_other.val();
        self.op_take.next = self.issue.op_take.val();
        self.records.read_en.next = self.issue.read_en.val();
        self.records.read_addr.next = self.issue.read_addr.val();
        self.pipe.op_acc.next = self.op_acc.val();
        self.pipe.h1.next = self.issue.h1.val();
        self.pipe.word.next = self.records.read_data.val();
        // Stage 3: an add's or a kept record written, a gone or closed
        // slot emptied, a closed record out; after a reset, every slot
        // emptied.
        self.records.write_en.next = self.issue.v3.val() | self.issue.clearing.val();
        self.records.write_addr.next = self.issue.s3.val();
        self.records.write_data.next = self.empty.val();
        if (self.issue.h3.val() == SlotHalf::Add) | (self.issue.h3.val() == SlotHalf::Keep) {
            self.records.write_data.next = self.pipe.merged.val();
        }
        if self.issue.clearing.val() {
            self.records.write_addr.next = self.issue.sweep.val();
            self.records.write_data.next = self.empty.val();
        }
        self.out_valid.next = self.issue.v3.val() & (self.issue.h3.val() == SlotHalf::Close);
        self.out_slot.next = self.issue.s3.val();
        self.out_acc.next = self.pipe.merged.val();
        self.idle.next = self.issue.idle.val();
    }
}
