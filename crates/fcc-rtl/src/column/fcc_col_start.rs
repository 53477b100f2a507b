//! `FccColStart`: the column-start check (docs/column-core.md, "Slot
//! overflow"). Spec §9.1 refuses a run a label when none is free and
//! refuses it by the open limit `N_o` when the clusters counted open
//! (those open after the previous column closed, plus the runs already
//! labelled in the column) reach it. The core's counts of both lag the
//! golden stream's while the previous column's ops, closes and label
//! returns are on their way, so a column may start only when either
//!
//! * no run of it can be refused, by the core or the golden stream: the
//!   slots in use, the starts on their way to a slot (`in_flight`) and
//!   two columns of starts (`2 R`: the previous column's pixels not yet
//!   decided, and this column's), and [`COUNT_MARGIN`] more for the
//!   counts' lateness, are at most `N_o` (`n_o`), and at least `2 R` and
//!   the margin labels are free (`fast`, from the counts of two cycles
//!   before); the
//!   column's `open_room` is then `R`, which it cannot use up; or
//! * the previous column is settled (`settled`: its ops through the
//!   record store, its closes sent and their records and labels back, no
//!   start on its way), when the slots in use are the clusters open, so
//!   `open_room` is `N_o` less them, and the label pool
//!   refuses a label exactly when the golden stream does.
//!
//! Otherwise the column's first pixel waits at the input (`hold`). The
//! room is latched as the first pixel is accepted (`first` and `accept`)
//! and held until the next column's.

use rust_hdl::prelude::*;

use super::fcc_open_room::OPEN_ROOM_BITS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColStart {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `R`, the rows (run parameter, at most 128).
    pub rows: Signal<In, Bits<8>>,
    /// `N_o`, the open limit (at most the 511 slots).
    pub n_o: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub slots_used: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub in_flight: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub labels_free: Signal<In, Bits<16>>,
    pub settled: Signal<In, Bit>,
    /// The pixel offered at the input is its column's first; it is taken.
    pub first: Signal<In, Bit>,
    pub accept: Signal<In, Bit>,
    pub hold: Signal<Out, Bit>,
    pub open_room: Signal<Out, Bits<OPEN_ROOM_BITS>>,
    /// Slots in use and on their way, two columns of starts and the
    /// margin more (registered); `2 R` and the margin.
    need: DFF<Bits<12>>,
    rows2: DFF<Bits<12>>,
    exact: Signal<Local, Bits<OPEN_ROOM_BITS>>,
    go: Signal<Local, Bit>,
    fast: DFF<Bit>,
    room: DFF<Bits<OPEN_ROOM_BITS>>,
    margin: Constant<Bits<12>>,
    need_max: Constant<Bits<12>>,
    zero: Constant<Bits<OPEN_ROOM_BITS>>,
}

impl Default for FccColStart {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rows: Default::default(),
            n_o: Default::default(),
            slots_used: Default::default(),
            in_flight: Default::default(),
            labels_free: Default::default(),
            settled: Default::default(),
            first: Default::default(),
            accept: Default::default(),
            hold: Default::default(),
            open_room: Default::default(),
            need: Default::default(),
            rows2: Default::default(),
            exact: Default::default(),
            go: Default::default(),
            fast: Default::default(),
            room: Default::default(),
            margin: kb(COUNT_MARGIN as u64),
            need_max: kb(0xfff),
            zero: kb(0),
        }
    }
}

/// Starts the counts may be late by: the check reads them two cycles late
/// (registered twice), a start may take a slot or a label in each of
/// those cycles, and the slot pool's count is registered once more.
pub const COUNT_MARGIN: usize = 4;

impl Logic for FccColStart {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, need, rows2, fast, room);
        self.rows2.d.next = bit_cast::<12, 8>(self.rows.val())
            + bit_cast::<12, 8>(self.rows.val())
            + self.margin.val();
        self.need.d.next = bit_cast::<12, OPEN_ROOM_BITS>(self.slots_used.val())
            + bit_cast::<12, OPEN_ROOM_BITS>(self.in_flight.val())
            + self.rows2.q.val();
        self.fast.d.next = (self.need.q.val() <= bit_cast::<12, OPEN_ROOM_BITS>(self.n_o.val()))
            & (self.labels_free.val() >= bit_cast::<16, 12>(self.rows2.q.val()));
        // Settled, the slots in use are the clusters open, which the open
        // limit keeps at most `N_o`.
        self.exact.next = self.n_o.val() - self.slots_used.val();
        self.go.next = self.fast.q.val() | self.settled.val();
        self.hold.next = self.first.val() & !self.go.val();
        if self.first.val() & self.accept.val() & self.go.val() {
            self.room.d.next = self.exact.val();
            if self.fast.q.val() {
                self.room.d.next = bit_cast::<OPEN_ROOM_BITS, 8>(self.rows.val());
            }
        }
        self.open_room.next = self.room.q.val();
        // After a reset the counts are fresh only a cycle later: `need` at
        // its largest keeps `fast` low until they are.
        if self.rst.val() {
            self.need.d.next = self.need_max.val();
            self.fast.d.next = false;
            self.room.d.next = self.zero.val();
        }
    }
}
