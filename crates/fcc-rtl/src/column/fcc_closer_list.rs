//! `FccCloserList`: the write side of the closer's wait list (`FccCloser`,
//! docs/column-core.md, item 4). One entry is written a cycle: a report
//! (`rd`) first, else the entry going back (`b`: the pass's entry not due
//! yet, or the one the sorted entries dropped, due at `pass_col`), which
//! waits in its register while a report is written. `used` counts the
//! entries in the list (written, less those the pass takes); `room` is
//! low with fewer than `WAIT_ROOM` free; `min_due` is the smallest due
//! column in the list, exactly: a pass's `start` begins it afresh (every
//! entry then in the list is read by that pass, and goes back through
//! here or leaves) and every entry written is counted.
//!
//! Apart from the pass (`FccCloserPass`) so that the sorted entries'
//! drop, which depends on the pass's entry in, feeds registers only.

use rust_hdl::prelude::*;

use super::fcc_close_order::CLOSE_KEY_BITS;
use super::fcc_closer::{WaitEntry, WAIT_BITS, WAIT_ROOM};
use super::fcc_label_sets::SLOT_BITS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccCloserList {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rd_valid: Signal<In, Bit>,
    pub rd: Signal<In, WaitEntry>,
    /// The pass's entry moves on (`r1`, due by `pass_col` if `r1n`); a
    /// pass starts; the pass takes the list's head.
    pub moves: Signal<In, Bit>,
    pub r1n: Signal<In, Bit>,
    pub r1: Signal<In, WaitEntry>,
    pub start: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    pub pass_col: Signal<In, Bits<13>>,
    pub drop_valid: Signal<In, Bit>,
    pub drop_key: Signal<In, Bits<CLOSE_KEY_BITS>>,
    pub drop_slot: Signal<In, Bits<SLOT_BITS>>,
    /// The entry written.
    pub w_push: Signal<Out, Bit>,
    pub w_in: Signal<Out, WaitEntry>,
    pub b_valid: Signal<Out, Bit>,
    pub used: Signal<Out, Bits<WAIT_BITS>>,
    pub min_due: Signal<Out, Bits<13>>,
    pub room: Signal<Out, Bit>,
    push: Signal<Local, Bit>,
    keep: Signal<Local, Bits<13>>,
    fresh: Signal<Local, Bits<13>>,
    ew: Signal<Local, WaitEntry>,
    bv: DFF<Bit>,
    b: DFF<WaitEntry>,
    n: DFF<Bits<WAIT_BITS>>,
    low: DFF<Bits<13>>,
    none_due: Constant<Bits<13>>,
    room_max: Constant<Bits<WAIT_BITS>>,
    one: Constant<Bits<WAIT_BITS>>,
    zero: Constant<Bits<WAIT_BITS>>,
}

impl Default for FccCloserList {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rd_valid: Default::default(),
            rd: Default::default(),
            moves: Default::default(),
            r1n: Default::default(),
            r1: Default::default(),
            start: Default::default(),
            take: Default::default(),
            pass_col: Default::default(),
            drop_valid: Default::default(),
            drop_key: Default::default(),
            drop_slot: Default::default(),
            w_push: Default::default(),
            w_in: Default::default(),
            b_valid: Default::default(),
            used: Default::default(),
            min_due: Default::default(),
            room: Default::default(),
            push: Default::default(),
            keep: Default::default(),
            fresh: Default::default(),
            ew: Default::default(),
            bv: Default::default(),
            b: Default::default(),
            n: Default::default(),
            low: Default::default(),
            none_due: kb((1 << 13) - 1),
            room_max: kb((1 << (WAIT_BITS - 1)) - WAIT_ROOM as u64),
            one: kb(1),
            zero: kb(0),
        }
    }
}

impl Logic for FccCloserList {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, bv, b, n, low);
        // `b`: kept while a report is written; then the pass's entry if it
        // goes back, or the entry the sorted entries drop.
        if !(self.bv.q.val() & self.rd_valid.val()) {
            self.bv.d.next = false;
        }
        if self.moves.val() & !self.r1n.val() {
            self.bv.d.next = true;
            self.b.d.next = self.r1.val();
        }
        if self.moves.val() & self.r1n.val() & self.drop_valid.val() {
            self.bv.d.next = true;
            self.b.d.next.slot = self.drop_slot.val();
            self.b.d.next.key = self.drop_key.val();
            self.b.d.next.due = self.pass_col.val();
        }
        // The write, the count and the smallest due column.
        self.push.next = self.rd_valid.val() | self.bv.q.val();
        self.ew.next = self.b.q.val();
        if self.rd_valid.val() {
            self.ew.next = self.rd.val();
        }
        self.w_push.next = self.push.val();
        self.w_in.next = self.ew.val();
        if self.push.val() & !self.take.val() {
            self.n.d.next = self.n.q.val() + self.one.val();
        }
        if !self.push.val() & self.take.val() {
            self.n.d.next = self.n.q.val() - self.one.val();
        }
        // Both the smallest kept and the one a pass starts afresh with are
        // worked out before `start` (two comparisons late) chooses.
        self.keep.next = self.low.q.val();
        if self.push.val() & (self.ew.val().due < self.low.q.val()) {
            self.keep.next = self.ew.val().due;
        }
        self.fresh.next = self.none_due.val();
        if self.push.val() {
            self.fresh.next = self.ew.val().due;
        }
        self.low.d.next = self.keep.val();
        if self.start.val() {
            self.low.d.next = self.fresh.val();
        }
        self.b_valid.next = self.bv.q.val();
        self.used.next = self.n.q.val();
        self.min_due.next = self.low.q.val();
        self.room.next = self.n.q.val() < self.room_max.val();
        if self.rst.val() {
            self.bv.d.next = false;
            self.n.d.next = self.zero.val();
            self.low.d.next = self.none_due.val();
        }
    }
}
