//! `FccCloser`: which clusters close at each column, and in what order
//! (docs/column-core.md, item 4). The record store reports a cluster as
//! it goes quiet (`q_*`: slot, first pixel, last column, quiet column);
//! the closer keeps each report in a wait list (`FccFifo`, block RAM, in
//! arrival order) with its due column `max(last + h, quiet column)`,
//! `last + h` at most the frame's last column `last_col` (spec §9.2: hold
//! 1 ends with the frame's columns).
//! Once column `c` is done (`mark_*`: every op of column `c` has left the
//! store), and if an entry is due by `c`, it passes over the list once:
//! the entries due go into the sorted entries (`FccCloseOrder`, by first
//! pixel), the others back into the list; then it offers a close at `c`
//! for each sorted entry in order (`close_*`, taken with `close_take`),
//! naming the slot and the cluster's first pixel (the store's check finds
//! a stale report's cluster gone). More closes in a column than sorted
//! entries take more passes of that column, each sending the smallest
//! keys left.
//!
//! At the frame end (`ending`), reports are due at `end_col`: the top
//! reports every slot in use, marks `end_col`, and the closes come in the
//! golden order. `clear` (a frame start) empties the list. The record
//! store waits while `room` is low, so no report is ever lost. Blocks:
//! `FccCloserIn` (reports and markers in), `FccCloserPass` (the passes),
//! `FccCloserList` (the list's writes, count and smallest due column);
//! this block is wiring.

use rust_hdl::prelude::*;

use super::fcc_close_order::{FccCloseOrder, CLOSE_KEY_BITS};
use super::fcc_closer_in::FccCloserIn;
use super::fcc_closer_list::FccCloserList;
use super::fcc_closer_pass::FccCloserPass;
use super::fcc_label_sets::SLOT_BITS;
use super::FIRST_BITS;
use crate::fcc_fifo::FccFifo;

/// Address bits of the wait list. A column's ops leave at most `R`
/// clusters quiet (one flush a row; a start, or a join's merge, keeps its
/// cluster's run open), and a report is due at most `h` columns after its
/// own; so the entries not yet due, those of the last `h + 1` columns at
/// most, are at most `(h + 1) R <= 6 x 128 = 768`. The rest are due and
/// leave as the passes go: when the passes fall behind, `room` goes low
/// and the store waits while they catch up, but the list never fills with
/// entries that wait for a column not yet done. The frame end clears the
/// list first and reports at most the 512 slots.
pub const WAIT_ADDR_BITS: usize = SLOT_BITS + 1;
/// Bits of the wait list's count of entries.
pub const WAIT_BITS: usize = WAIT_ADDR_BITS + 1;
/// Entries kept free for the reports of ops already taken by the store,
/// and those on their way into the list: `room` goes low with fewer free.
pub const WAIT_ROOM: usize = 16;

/// A report waiting for its column: the slot, the cluster's first pixel
/// and the column it is due.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct WaitEntry {
    pub slot: Bits<SLOT_BITS>,
    pub key: Bits<CLOSE_KEY_BITS>,
    pub due: Bits<13>,
}

#[derive(LogicBlock, Default)]
pub struct FccCloser {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub half: Signal<In, Bits<3>>,
    /// The frame's last column, `C - 1` (run parameter): hold 1 ends there.
    pub last_col: Signal<In, Bits<12>>,
    pub ending: Signal<In, Bit>,
    pub end_col: Signal<In, Bits<12>>,
    pub q_valid: Signal<In, Bit>,
    pub q_slot: Signal<In, Bits<SLOT_BITS>>,
    pub q_first: Signal<In, Bits<FIRST_BITS>>,
    pub q_last: Signal<In, Bits<12>>,
    pub q_col: Signal<In, Bits<12>>,
    pub mark_valid: Signal<In, Bit>,
    pub mark_col: Signal<In, Bits<12>>,
    pub room: Signal<Out, Bit>,
    pub close_valid: Signal<Out, Bit>,
    pub close_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub close_key: Signal<Out, Bits<CLOSE_KEY_BITS>>,
    pub close_col: Signal<Out, Bits<13>>,
    pub close_take: Signal<In, Bit>,
    /// Every column marked is passed and its closes taken.
    pub caught_up: Signal<Out, Bit>,
    inp: FccCloserIn,
    pass: FccCloserPass,
    writes: FccCloserList,
    list: FccFifo<WaitEntry, WAIT_ADDR_BITS, WAIT_BITS>,
    order: FccCloseOrder,
}

impl Logic for FccCloser {
    #[hdl_gen]
    fn update(&mut self) {
        self.inp.clk.next = self.clk.val();
        self.pass.clk.next = self.clk.val();
        self.writes.clk.next = self.clk.val();
        self.list.clk.next = self.clk.val();
        self.order.clk.next = self.clk.val();
        self.inp.rst.next = self.rst.val();
        self.inp.clear.next = self.clear.val();
        self.pass.rst.next = self.rst.val() | self.clear.val();
        self.writes.rst.next = self.rst.val() | self.clear.val();
        self.list.rst.next = self.rst.val() | self.clear.val();
        self.order.rst.next = self.rst.val() | self.clear.val();
        self.inp.half.next = self.half.val();
        self.inp.last_col.next = self.last_col.val();
        self.inp.ending.next = self.ending.val();
        self.inp.end_col.next = self.end_col.val();
        self.inp.q_valid.next = self.q_valid.val();
        self.inp.q_slot.next = self.q_slot.val();
        self.inp.q_first.next = self.q_first.val();
        self.inp.q_last.next = self.q_last.val();
        self.inp.q_col.next = self.q_col.val();
        self.inp.mark_valid.next = self.mark_valid.val();
        self.inp.mark_col.next = self.mark_col.val();
        // The passes.
        self.pass.rd_valid.next = self.inp.rd_valid.val();
        self.pass.done_col.next = self.inp.done_col.val();
        self.pass.marked.next = self.inp.marked.val();
        self.pass.used.next = self.writes.used.val();
        self.pass.min_due.next = self.writes.min_due.val();
        self.pass.b_valid.next = self.writes.b_valid.val();
        self.pass.w_valid.next = self.list.valid.val();
        self.pass.w_out.next = self.list.dout.val();
        self.pass.o_head_valid.next = self.order.head_valid.val();
        self.pass.close_take.next = self.close_take.val();
        // The list's writes.
        self.writes.rd_valid.next = self.inp.rd_valid.val();
        self.writes.rd.next = self.inp.rd.val();
        self.writes.moves.next = self.pass.p_moves.val();
        self.writes.r1n.next = self.pass.p_r1n.val();
        self.writes.r1.next = self.pass.p_r1.val();
        self.writes.start.next = self.pass.p_start.val();
        self.writes.take.next = self.pass.w_take.val();
        self.writes.pass_col.next = self.pass.close_col.val();
        self.writes.drop_valid.next = self.order.drop_valid.val();
        self.writes.drop_key.next = self.order.drop_key.val();
        self.writes.drop_slot.next = self.order.drop_slot.val();
        self.list.push.next = self.writes.w_push.val();
        self.list.din.next = self.writes.w_in.val();
        self.list.take.next = self.pass.w_take.val();
        // The sorted entries.
        self.order.in_valid.next = self.pass.o_push.val();
        self.order.in_key.next = self.pass.o_key.val();
        self.order.in_slot.next = self.pass.o_slot.val();
        self.order.pop.next = self.pass.o_pop.val();
        self.room.next = self.writes.room.val();
        self.close_valid.next = self.pass.close_valid.val();
        self.close_slot.next = self.order.head_slot.val();
        self.close_key.next = self.order.head_key.val();
        self.close_col.next = self.pass.close_col.val();
        self.caught_up.next = self.pass.caught_up.val() & self.inp.empty.val();
    }
}
