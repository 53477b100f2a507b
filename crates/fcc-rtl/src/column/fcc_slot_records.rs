//! `FccSlotRecords`: the column core's record store (docs/column-core.md,
//! items 3 and 4): per slot, in block RAM, a cluster's record (its
//! accumulator, `AccWord`) and its holds (`SlotHolds`), together a
//! `SlotWord`; the ops the slot table sends it, one taken a cycle at most
//! (`op_take`), each at a column (`op_col`, the column of the pixel slot
//! that caused it):
//!
//! * `Add`: a word (`op_word`) merged into slot `op_slot`'s: a run's
//!   start (no pixel, one run open, its ring flag and first pixel) or its
//!   flush (its accumulator, one run open less);
//! * `Merge`: the word of `op_other` merged into `op_slot`'s (a union's
//!   gone slot into the kept one; the two differ), `op_other` then empty;
//! * `Close`: the record of `op_slot` out if nothing holds the cluster
//!   after `op_col` (`FccSlotCheck`, with `half` = `h`; at the last
//!   column, `last_col`, hold 1 no longer counts), the slot then empty;
//!   otherwise nothing;
//! * `End`: at the frame end, the record out if the slot has one;
//! * `Peek`: at the frame end, the slot reported (`q_*`, as a quiet
//!   cluster is) if it has a record, whatever holds it, and left as it
//!   is: so the closer learns every slot in use, ring-held ones included,
//!   and closes them in the golden order.
//!
//! A close or end names its cluster by its first pixel too (`op_word`'s
//! `holds.first`, the closer's key): the record leaves only if the slot's
//! first pixel is that one, so a stale report of the closer's finds the
//! slot's record, if any, not its own and does nothing.
//!
//! A record out shows for a cycle (`out_valid`, with `out_slot`, `out_acc`
//! and its labels' list, `out_head` to `out_tail`) three cycles after its
//! op is taken; the taker has room for it. A word written that joins two
//! labels' lists says so in its cycle (`link_*`: the kept list's tail
//! points to the other's head, for `FccLabelLists`). An add
//! or merge that leaves its cluster quiet (no run open, no ring flag)
//! reports it in the cycle of its write (`q_valid`: the slot, its first
//! pixel, its last column and the quiet column), so that a closer can
//! send its close when it is due.
//!
//! Ops take effect in order. A slot that no add or merge wrote since it
//! was emptied holds the empty word: a merge's gone slot and a closed one
//! are written empty in the cycle a kept or added word would be, and
//! after a reset every slot is, one a cycle, before an op is taken
//! (`2^SLOT_BITS` cycles, `idle` low). An op takes a cycle (a merge two),
//! on any slot: the writes its read misses are forwarded into stage 2
//! (`FccSlotPipe`). This block is wiring.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_slot_issue::{FccSlotIssue, SlotHalf, SlotOp};
use super::fcc_slot_pipe::FccSlotPipe;
use super::{AccWord, SlotHolds, SlotWord, FIRST_BITS};
use crate::fcc_ram::FccRam;

/// Cycles from an op's taking to its write (or its record out).
pub const SLOT_RECORDS_LATENCY: usize = 3;

/// Record slots.
pub const SLOTS: usize = 1 << SLOT_BITS;

#[derive(LogicBlock)]
pub struct FccSlotRecords {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `h`, the window's half-size (run parameter).
    pub half: Signal<In, Bits<3>>,
    /// The frame's last column, `C - 1` (run parameter): a close there
    /// drops hold 1, as nothing follows it (spec §9.2).
    pub last_col: Signal<In, Bits<12>>,
    pub op_valid: Signal<In, Bit>,
    pub op_kind: Signal<In, SlotOp>,
    pub op_slot: Signal<In, Bits<SLOT_BITS>>,
    pub op_other: Signal<In, Bits<SLOT_BITS>>,
    pub op_word: Signal<In, SlotWord>,
    pub op_col: Signal<In, Bits<12>>,
    pub op_take: Signal<Out, Bit>,
    pub out_valid: Signal<Out, Bit>,
    pub out_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub out_acc: Signal<Out, AccWord>,
    pub out_head: Signal<Out, Bits<16>>,
    pub out_tail: Signal<Out, Bits<16>>,
    pub link_valid: Signal<Out, Bit>,
    pub link_from: Signal<Out, Bits<16>>,
    pub link_to: Signal<Out, Bits<16>>,
    pub q_valid: Signal<Out, Bit>,
    pub q_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub q_first: Signal<Out, Bits<FIRST_BITS>>,
    pub q_last: Signal<Out, Bits<12>>,
    pub q_col: Signal<Out, Bits<12>>,
    /// No op in flight.
    pub idle: Signal<Out, Bit>,
    mw: Signal<Local, SlotWord>,
    ma: Signal<Local, AccWord>,
    mh: Signal<Local, SlotHolds>,
    kept: Signal<Local, Bit>,
    /// Stage 3's word has points (a peek reports it).
    has: Signal<Local, Bit>,
    records: FccRam<SlotWord, SLOT_BITS>,
    issue: FccSlotIssue,
    pipe: FccSlotPipe,
    empty: Constant<SlotWord>,
}

impl Default for FccSlotRecords {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            half: Default::default(),
            last_col: Default::default(),
            op_valid: Default::default(),
            op_kind: Default::default(),
            op_slot: Default::default(),
            op_other: Default::default(),
            op_word: Default::default(),
            op_col: Default::default(),
            op_take: Default::default(),
            out_valid: Default::default(),
            out_slot: Default::default(),
            out_acc: Default::default(),
            out_head: Default::default(),
            out_tail: Default::default(),
            link_valid: Default::default(),
            link_from: Default::default(),
            link_to: Default::default(),
            q_valid: Default::default(),
            q_slot: Default::default(),
            q_first: Default::default(),
            q_last: Default::default(),
            q_col: Default::default(),
            idle: Default::default(),
            mw: Default::default(),
            ma: Default::default(),
            mh: Default::default(),
            kept: Default::default(),
            has: Default::default(),
            records: FccRam::new(SLOTS),
            issue: Default::default(),
            pipe: Default::default(),
            empty: Constant::new(SlotWord::empty()),
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
        self.pipe.take.next = self.issue.op_take.val();
        self.pipe.op_word.next = self.op_word.val();
        self.pipe.op_col.next = self.op_col.val();
        self.pipe.half.next = self.half.val();
        self.pipe.last_col.next = self.last_col.val();
        self.pipe.h1.next = self.issue.h1.val();
        self.pipe.word.next = self.records.read_data.val();
        // Stage 3: an add's or a kept word written, a gone slot or a
        // leaving record's emptied, a record out; after a reset, every
        // slot emptied.
        self.mw.next = self.pipe.merged.val();
        self.ma.next = self.mw.val().acc;
        self.mh.next = self.mw.val().holds;
        self.kept.next =
            (self.issue.h3.val() == SlotHalf::Add) | (self.issue.h3.val() == SlotHalf::Keep);
        self.pipe.s2.next = self.issue.s2.val();
        self.pipe.v3.next = self.issue.v3.val();
        self.pipe.h3.next = self.issue.h3.val();
        self.pipe.s3.next = self.issue.s3.val();
        self.records.write_en.next = self.pipe.wen.val() | self.issue.clearing.val();
        self.records.write_addr.next = self.issue.s3.val();
        self.records.write_data.next = self.pipe.wdata.val();
        if self.issue.clearing.val() {
            self.records.write_addr.next = self.issue.sweep.val();
            self.records.write_data.next = self.empty.val();
        }
        self.out_valid.next = self.issue.v3.val() & self.pipe.leaves.val();
        self.out_slot.next = self.issue.s3.val();
        self.out_acc.next = self.ma.val();
        self.out_head.next = self.mh.val().head;
        self.out_tail.next = self.mh.val().tail;
        self.link_valid.next = self.issue.v3.val() & self.kept.val() & self.pipe.link.val();
        self.link_from.next = self.pipe.link_from.val();
        self.link_to.next = self.pipe.link_to.val();
        self.has.next = self.ma.val().points.any();
        self.q_valid.next = self.issue.v3.val()
            & ((self.kept.val() & self.pipe.quiet.val())
                | ((self.issue.h3.val() == SlotHalf::Peek) & self.has.val()));
        self.q_slot.next = self.issue.s3.val();
        self.q_first.next = self.mh.val().first;
        self.q_last.next = self.ma.val().max_col;
        self.q_col.next = self.mh.val().quiet;
        self.idle.next = self.issue.idle.val();
    }
}
