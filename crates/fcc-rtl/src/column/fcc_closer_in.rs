//! `FccCloserIn`: what reaches the closer (`FccCloser`,
//! docs/column-core.md, item 4). The record store's quiet reports are
//! registered twice on their way to the wait list: first with `last + h`
//! added (at most the frame's last column, `last_col`: hold 1 is gone
//! after it, spec §9.2), then with their due column, `max(last + h, quiet
//! column)` (at the frame end, `ending`: `end_col`, where every cluster
//! closes). A
//! column marker (`mark_*`: every op of that column has left the store, so
//! every report it causes has come) is delayed as long, so that the
//! column is `done` only once those reports are counted in the wait list.
//! `clear` (a frame start) drops what is in flight and the marks.

use rust_hdl::prelude::*;

use super::fcc_closer::WaitEntry;
use super::fcc_label_sets::SLOT_BITS;
use super::FIRST_BITS;

#[derive(LogicBlock, Default)]
pub struct FccCloserIn {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub half: Signal<In, Bits<3>>,
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
    /// The report to write into the wait list.
    pub rd_valid: Signal<Out, Bit>,
    pub rd: Signal<Out, WaitEntry>,
    /// The last column done, and whether one is since the last `clear`.
    pub done_col: Signal<Out, Bits<12>>,
    pub marked: Signal<Out, Bit>,
    /// No report or marker in flight.
    pub empty: Signal<Out, Bit>,
    e2: Signal<Local, WaitEntry>,
    reach: Signal<Local, Bits<13>>,
    // Stage 1: the report with `last + h`, and its quiet column (or
    // `end_col`).
    v1: DFF<Bit>,
    s1: DFF<Bits<SLOT_BITS>>,
    f1: DFF<Bits<FIRST_BITS>>,
    l1: DFF<Bits<13>>,
    q1: DFF<Bits<13>>,
    n1: DFF<Bit>,
    // Stage 2: the entry.
    v2: DFF<Bit>,
    d2: DFF<WaitEntry>,
    // The marker's delay, and the column done.
    mv1: DFF<Bit>,
    mc1: DFF<Bits<12>>,
    mv2: DFF<Bit>,
    mc2: DFF<Bits<12>>,
    done: DFF<Bits<12>>,
    any: DFF<Bit>,
}

impl Logic for FccCloserIn {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, v1, s1, f1, l1, q1, n1, v2, d2, mv1, mc1, mv2, mc2, done, any);
        self.v1.d.next = self.q_valid.val();
        self.s1.d.next = self.q_slot.val();
        self.f1.d.next = self.q_first.val();
        self.reach.next =
            bit_cast::<13, 12>(self.q_last.val()) + bit_cast::<13, 3>(self.half.val());
        self.l1.d.next = self.reach.val();
        if self.reach.val() > bit_cast::<13, 12>(self.last_col.val()) {
            self.l1.d.next = bit_cast::<13, 12>(self.last_col.val());
        }
        self.q1.d.next = bit_cast::<13, 12>(self.q_col.val());
        if self.ending.val() {
            self.q1.d.next = bit_cast::<13, 12>(self.end_col.val());
        }
        self.n1.d.next = self.ending.val();
        self.v2.d.next = self.v1.q.val();
        self.e2.next.slot = self.s1.q.val();
        self.e2.next.key = self.f1.q.val();
        self.e2.next.due = self.q1.q.val();
        if !self.n1.q.val() & (self.l1.q.val() > self.q1.q.val()) {
            self.e2.next.due = self.l1.q.val();
        }
        self.d2.d.next = self.e2.val();
        self.rd_valid.next = self.v2.q.val();
        self.rd.next = self.d2.q.val();
        self.mv1.d.next = self.mark_valid.val();
        self.mc1.d.next = self.mark_col.val();
        self.mv2.d.next = self.mv1.q.val();
        self.mc2.d.next = self.mc1.q.val();
        if self.mv2.q.val() {
            self.done.d.next = self.mc2.q.val();
            self.any.d.next = true;
        }
        self.done_col.next = self.done.q.val();
        self.marked.next = self.any.q.val();
        self.empty.next =
            !self.v1.q.val() & !self.v2.q.val() & !self.mv1.q.val() & !self.mv2.q.val();
        if self.rst.val() | self.clear.val() {
            self.v1.d.next = false;
            self.v2.d.next = false;
            self.mv1.d.next = false;
            self.mv2.d.next = false;
            self.any.d.next = false;
        }
    }
}
