//! `FccOpenRoom`: spec §9.1's open limit at `FccRowRuns`'s label decision.
//! A run starting at column `c` is labelled only while fewer than `N_o`
//! clusters count as open: those open after column `c - 1` closed, plus the
//! runs labelled so far in column `c`.
//!
//! `open_room` is `N_o` less the clusters open after the previous column
//! closed: the runs the limit still allows in this column (with no limit,
//! any value of at least `R`: a column starts at most `R` runs). The core
//! holds it steady from before the column's first slot reaches the
//! decision until after. It is registered, with whether it is 0, a cycle
//! before use. At the column's first slot
//! (`col_start`) the room is `open_room`; after that it is what is left,
//! one less per label taken (`taken`), kept as a counter and a flag, so
//! that `room_ok` comes from flip-flops (or the registered input) through
//! one multiplexer.

use rust_hdl::prelude::*;

use crate::types::kb;

/// Width of `open_room`: the column core's record slots (at most 512) and
/// more.
pub const OPEN_ROOM_BITS: usize = 10;

#[derive(LogicBlock)]
pub struct FccOpenRoom {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub open_room: Signal<In, Bits<OPEN_ROOM_BITS>>,
    /// The decision's slot is its column's first.
    pub col_start: Signal<In, Bit>,
    /// A run of the decision's slot took a label.
    pub taken: Signal<In, Bit>,
    /// The open limit allows a run to start at the column's first slot
    /// (`start_ok`), at a later slot (`left_ok`).
    pub start_ok: Signal<Out, Bit>,
    pub left_ok: Signal<Out, Bit>,
    open_q: DFF<Bits<OPEN_ROOM_BITS>>,
    open_nz: DFF<Bit>,
    room: DFF<Bits<OPEN_ROOM_BITS>>,
    room_nz: DFF<Bit>,
    zero: Constant<Bits<OPEN_ROOM_BITS>>,
    one: Constant<Bits<OPEN_ROOM_BITS>>,
}

impl Default for FccOpenRoom {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            open_room: Default::default(),
            col_start: Default::default(),
            taken: Default::default(),
            start_ok: Default::default(),
            left_ok: Default::default(),
            open_q: Default::default(),
            open_nz: Default::default(),
            room: Default::default(),
            room_nz: Default::default(),
            zero: kb(0),
            one: kb(1),
        }
    }
}

impl Logic for FccOpenRoom {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, open_q, open_nz, room, room_nz);
        self.open_q.d.next = self.open_room.val();
        self.open_nz.d.next = self.open_room.val() != self.zero.val();
        self.start_ok.next = self.open_nz.q.val();
        self.left_ok.next = self.room_nz.q.val();
        if self.col_start.val() {
            self.room.d.next = self.open_q.q.val();
            self.room_nz.d.next = self.open_nz.q.val();
            if self.taken.val() {
                self.room.d.next = self.open_q.q.val() - self.one.val();
                self.room_nz.d.next = self.open_q.q.val() != self.one.val();
            }
        } else if self.taken.val() {
            self.room.d.next = self.room.q.val() - self.one.val();
            self.room_nz.d.next = self.room.q.val() != self.one.val();
        }
        if self.rst.val() {
            self.room.d.next = self.zero.val();
            self.room_nz.d.next = false;
        }
    }
}
