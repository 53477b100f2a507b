//! `FccColSettle`: the column core's counts for the column-start check
//! (`FccColStart`; docs/column-core.md, "Slot overflow") and the input's
//! frame flag for the frame end.
//!
//! * `settled`: the column whose first slot waits at the input may start
//!   exactly: every column begun before it has had its marker taken by the
//!   record store (`marked`; the last column of a frame counts the frame
//!   end's marker too), the store is `calm` (so those columns' closes are
//!   out, their labels and slots back) and has been for [`CALM_CYCLES`]
//!   cycles (a label returned is handed out four cycles later), and no
//!   run's start is on its way to a slot (`in_flight` 0). Columns are
//!   counted as they begin (`col_begin`), frame by frame (`last_col`, the
//!   frame's `C - 1`).
//! * `in_flight`: labels taken by runs' starts (`label_take`) whose makes
//!   have not taken a slot (`make_taken`, the union-find's take from the
//!   slot pool, after which the pool counts it in use); a make still on
//!   its way to the store comes before the next marker, so `settled`
//!   waits for it anyway.
//! * `frame_err`: the input's error flag of its last frame (`err` while
//!   `in_done`: both hold until the next frame starts), kept until the
//!   next frame is in.

use rust_hdl::prelude::*;

use super::fcc_open_room::OPEN_ROOM_BITS;
use crate::types::kb;

/// Cycles the store must have been calm before a column starts on it.
pub const CALM_CYCLES: usize = 6;

#[derive(LogicBlock)]
pub struct FccColSettle {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub last_col: Signal<In, Bits<12>>,
    pub col_begin: Signal<In, Bit>,
    pub marked: Signal<In, Bit>,
    pub calm: Signal<In, Bit>,
    pub label_take: Signal<In, Bit>,
    pub make_taken: Signal<In, Bit>,
    pub in_done: Signal<In, Bit>,
    pub err: Signal<In, Bit>,
    pub settled: Signal<Out, Bit>,
    pub in_flight: Signal<Out, Bits<OPEN_ROOM_BITS>>,
    pub frame_err: Signal<Out, Bit>,
    col: DFF<Bits<12>>,
    need: DFF<Bits<16>>,
    marks: DFF<Bits<16>>,
    flight: DFF<Bits<OPEN_ROOM_BITS>>,
    calm_n: DFF<Bits<3>>,
    ok: DFF<Bit>,
    ferr: DFF<Bit>,
    one12: Constant<Bits<12>>,
    zero12: Constant<Bits<12>>,
    one16: Constant<Bits<16>>,
    two16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    one_f: Constant<Bits<OPEN_ROOM_BITS>>,
    zero_f: Constant<Bits<OPEN_ROOM_BITS>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    calm_full: Constant<Bits<3>>,
}

impl Default for FccColSettle {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_col: Default::default(),
            col_begin: Default::default(),
            marked: Default::default(),
            calm: Default::default(),
            label_take: Default::default(),
            make_taken: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            settled: Default::default(),
            in_flight: Default::default(),
            frame_err: Default::default(),
            col: Default::default(),
            need: Default::default(),
            marks: Default::default(),
            flight: Default::default(),
            calm_n: Default::default(),
            ok: Default::default(),
            ferr: Default::default(),
            one12: kb(1),
            zero12: kb(0),
            one16: kb(1),
            two16: kb(2),
            zero16: kb(0),
            one_f: kb(1),
            zero_f: kb(0),
            one3: kb(1),
            zero3: kb(0),
            calm_full: kb(CALM_CYCLES as u64),
        }
    }
}

impl Logic for FccColSettle {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, col, need, marks, flight, calm_n, ok, ferr);
        if self.col_begin.val() {
            self.col.d.next = self.col.q.val() + self.one12.val();
            self.need.d.next = self.need.q.val() + self.one16.val();
            if self.col.q.val() == self.last_col.val() {
                self.col.d.next = self.zero12.val();
                self.need.d.next = self.need.q.val() + self.two16.val();
            }
        }
        if self.marked.val() {
            self.marks.d.next = self.marks.q.val() + self.one16.val();
        }
        if self.label_take.val() & !self.make_taken.val() {
            self.flight.d.next = self.flight.q.val() + self.one_f.val();
        }
        if !self.label_take.val() & self.make_taken.val() {
            self.flight.d.next = self.flight.q.val() - self.one_f.val();
        }
        self.calm_n.d.next = self.zero3.val();
        if self.calm.val() {
            self.calm_n.d.next = self.calm_n.q.val();
            if self.calm_n.q.val() != self.calm_full.val() {
                self.calm_n.d.next = self.calm_n.q.val() + self.one3.val();
            }
        }
        self.ok.d.next = (self.marks.q.val() == self.need.q.val())
            & (self.calm_n.q.val() == self.calm_full.val())
            & !self.flight.q.val().any();
        self.settled.next = self.ok.q.val() & self.calm.val();
        self.in_flight.next = self.flight.q.val();
        if self.in_done.val() {
            self.ferr.d.next = self.err.val();
        }
        self.frame_err.next = self.ferr.q.val();
        if self.rst.val() {
            self.col.d.next = self.zero12.val();
            self.need.d.next = self.zero16.val();
            self.marks.d.next = self.zero16.val();
            self.flight.d.next = self.zero_f.val();
            self.calm_n.d.next = self.zero3.val();
            self.ok.d.next = false;
            self.ferr.d.next = false;
        }
    }
}
