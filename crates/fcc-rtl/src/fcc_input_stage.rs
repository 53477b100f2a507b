//! `FccInputStage`: the core's AXI4-Stream input, one pixel slot per
//! cycle. The row-major core takes its frame in raster order (`default`);
//! the column-streaming core in column order (`column_order`: rows
//! `0 .. R-1` of column 0, then of column 1, ...), where `col0` and `coln`
//! mark the slots of the first and the last column.
//!
//! In column order a column's first slot can be held (`col_hold`, the
//! column-start check's `hold`): while `col_first` (the next slot is its
//! column's first) and `col_hold` are high, neither a beat nor a padding
//! slot is taken and `s_axis_tready` is low. `col_first` comes from
//! registers; `col_hold` reaches the ready and the slot through a gate
//! each (an AND with `col_first`, then with the registered ready). The
//! row-major order ignores `col_hold`.
//!
//! Each accepted beat (64-bit `s_axis_tdata`: x, y, z Q7.8 in bits 47:0,
//! valid in bit 48) becomes a registered slot (`slot`, the coordinates
//! offset binary) with its row, column and frame flags; a frame that ends
//! early (`tlast` before its last pixel) is padded with empty slots, one
//! that ends late has its beats dropped up to and including the next
//! `tlast`; either sets `err` for the frame. `in_done` is set by the frame's
//! last slot and cleared when the next frame starts (`restart`).
//!
//! `s_axis_tready` comes from a register, high in the next cycle while the
//! frame runs (`run`), has slots left to take and the credits leave `room`
//! (or while a long frame's beats are dropped); in column order it is also
//! low while a column's first slot is held. The pipeline's reset `rst` is
//! one cycle behind `rst_next`: the ready goes low in the cycle before it,
//! so a beat offered right after a short reset waits instead of being lost.

use rust_hdl::prelude::*;

use crate::types::{kb, Pix};

#[derive(LogicBlock)]
pub struct FccInputStage {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `rst` one cycle ahead.
    pub rst_next: Signal<In, Bit>,
    pub s_axis_tdata: Signal<In, Bits<49>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    /// Rows and columns of the frame (the run registers; they may change up
    /// to the frame's first pixel).
    pub run_rows: Signal<In, Bits<8>>,
    pub run_cols: Signal<In, Bits<12>>,
    /// The frame phase is RUN; the next frame starts at the clock edge.
    pub run: Signal<In, Bit>,
    pub restart: Signal<In, Bit>,
    /// The phase after the clock edge is RUN.
    pub run_next: Signal<In, Bit>,
    /// The credit counter has room (registered).
    pub room: Signal<In, Bit>,
    /// Column order: the next slot, its column's first, waits.
    pub col_hold: Signal<In, Bit>,
    /// Column order: the next slot is its column's first (registered).
    pub col_first: Signal<Out, Bit>,
    /// A slot enters this cycle (a beat or a padding slot).
    pub slot_now: Signal<Out, Bit>,
    /// The registered slot.
    pub slot: Signal<Out, Pix>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    /// `run_cols - 1` (registered; modulo 4096).
    pub last_col: Signal<Out, Bits<12>>,
    /// Waiting for the first pixel of a frame; the same after the clock edge.
    pub idle: Signal<Out, Bit>,
    pub idle_next: Signal<Out, Bit>,
    tready_q: DFF<Bit>,
    pad_go: DFF<Bit>,
    slot_q: DFF<Pix>,
    row: DFF<Bits<8>>,
    col: DFF<Bits<12>>,
    col0: DFF<Bit>,
    col_last: DFF<Bit>,
    row_last: DFF<Bit>,
    first: DFF<Bit>,
    pad: DFF<Bit>,
    discard: DFF<Bit>,
    done: DFF<Bit>,
    err_q: DFF<Bit>,
    /// `run_cols - 1`, `run_cols - 2`, `run_rows - 2`, `run_rows == 1`.
    last_col_q: DFF<Bits<12>>,
    pen_col: DFF<Bits<12>>,
    pen_row: DFF<Bits<8>>,
    one_row: DFF<Bit>,
    /// Column order (build time).
    col_major: Constant<Bit>,
    accept: Signal<Local, Bit>,
    /// The next slot waits for `col_hold`.
    held: Signal<Local, Bit>,
    beat: Signal<Local, Bit>,
    is_last: Signal<Local, Bit>,
    nxt_pad: Signal<Local, Bit>,
    nxt_discard: Signal<Local, Bit>,
    nxt_done: Signal<Local, Bit>,
    nxt_run: Signal<Local, Bit>,
    sign16: Constant<Bits<16>>,
    zero8: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
    two8: Constant<Bits<8>>,
    zero12: Constant<Bits<12>>,
    one12: Constant<Bits<12>>,
    two12: Constant<Bits<12>>,
}

impl Default for FccInputStage {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_next: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tlast: Default::default(),
            s_axis_tready: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            run: Default::default(),
            restart: Default::default(),
            run_next: Default::default(),
            room: Default::default(),
            col_hold: Default::default(),
            col_first: Default::default(),
            slot_now: Default::default(),
            slot: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            last_col: Default::default(),
            idle: Default::default(),
            idle_next: Default::default(),
            tready_q: Default::default(),
            pad_go: Default::default(),
            slot_q: Default::default(),
            row: Default::default(),
            col: Default::default(),
            col0: Default::default(),
            col_last: Default::default(),
            row_last: Default::default(),
            first: Default::default(),
            pad: Default::default(),
            discard: Default::default(),
            done: Default::default(),
            err_q: Default::default(),
            last_col_q: Default::default(),
            pen_col: Default::default(),
            pen_row: Default::default(),
            one_row: Default::default(),
            col_major: Constant::new(false),
            accept: Default::default(),
            held: Default::default(),
            beat: Default::default(),
            is_last: Default::default(),
            nxt_pad: Default::default(),
            nxt_discard: Default::default(),
            nxt_done: Default::default(),
            nxt_run: Default::default(),
            sign16: kb(0x8000),
            zero8: kb(0),
            one8: kb(1),
            two8: kb(2),
            zero12: kb(0),
            one12: kb(1),
            two12: kb(2),
        }
    }
}

impl FccInputStage {
    /// The stage of the column-streaming core: the frame in column order.
    pub fn column_order() -> Self {
        Self {
            col_major: Constant::new(true),
            ..Self::default()
        }
    }
}

impl Logic for FccInputStage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, tready_q, pad_go, slot_q, row, col, col0, col_last, row_last, first, pad,
            discard, done, err_q, last_col_q, pen_col, pen_row, one_row
        );
        // Run size, registered so the counters compare with flip-flops.
        self.last_col_q.d.next = self.run_cols.val() - self.one12.val();
        self.pen_col.d.next = self.run_cols.val() - self.two12.val();
        self.pen_row.d.next = self.run_rows.val() - self.two8.val();
        self.one_row.d.next = self.run_rows.val() == self.one8.val();
        // Slots: a beat taken, or a padding slot of a short frame; in column
        // order not a column's first while it is held.
        self.col_first.next =
            self.col_major.val() & (self.row.q.val() == self.zero8.val()) & !self.discard.q.val();
        self.held.next = self.col_first.val() & self.col_hold.val();
        self.accept.next = self.s_axis_tvalid.val() & self.tready_q.q.val() & !self.held.val();
        self.beat.next = self.accept.val() & !self.discard.q.val();
        self.slot_now.next = self.beat.val() | (self.pad_go.q.val() & !self.held.val());
        self.is_last.next = self.col_last.q.val() & self.row_last.q.val();
        self.slot_q.d.next.valid = self.slot_now.val();
        self.slot_q.d.next.ok = self.beat.val() & self.s_axis_tdata.val().get_bit(48);
        self.slot_q.d.next.x = self.s_axis_tdata.val().get_bits::<16>(0) ^ self.sign16.val();
        self.slot_q.d.next.y = self.s_axis_tdata.val().get_bits::<16>(16) ^ self.sign16.val();
        self.slot_q.d.next.z = self.s_axis_tdata.val().get_bits::<16>(32) ^ self.sign16.val();
        self.slot_q.d.next.row = self.row.q.val();
        self.slot_q.d.next.col = self.col.q.val();
        self.slot_q.d.next.first = self.first.q.val();
        self.slot_q.d.next.last = self.is_last.val();
        self.slot_q.d.next.col0 = self.col0.q.val();
        self.slot_q.d.next.coln = self.col_last.q.val();
        self.nxt_pad.next = self.pad.q.val();
        self.nxt_discard.next = self.discard.q.val();
        self.nxt_done.next = self.done.q.val();
        // Row 0 is the last row of a one-row frame. `one_row` follows the
        // run registers two cycles later, long before row 0's last pixel (C >= 3).
        if self.row.q.val() == self.zero8.val() {
            self.row_last.d.next = self.one_row.q.val();
        }
        if self.slot_now.val() {
            self.first.d.next = false;
            if self.col_major.val() {
                // Column order: the row counts, then the column.
                self.row.d.next = self.row.q.val() + self.one8.val();
                self.row_last.d.next = self.row.q.val() == self.pen_row.q.val();
                if self.row_last.q.val() {
                    self.row.d.next = self.zero8.val();
                    self.row_last.d.next = self.one_row.q.val();
                    self.col0.d.next = false;
                    self.col.d.next = self.col.q.val() + self.one12.val();
                    self.col_last.d.next = self.col.q.val() == self.pen_col.q.val();
                }
            } else {
                self.col0.d.next = self.col_last.q.val();
                self.col.d.next = self.col.q.val() + self.one12.val();
                self.col_last.d.next = self.col.q.val() == self.pen_col.q.val();
                if self.col_last.q.val() {
                    self.col.d.next = self.zero12.val();
                    self.col_last.d.next = false;
                    self.row.d.next = self.row.q.val() + self.one8.val();
                    self.row_last.d.next = self.row.q.val() == self.pen_row.q.val();
                }
            }
            if self.is_last.val() {
                self.row.d.next = self.zero8.val();
                self.row_last.d.next = self.one_row.q.val();
                self.col.d.next = self.zero12.val();
                self.col_last.d.next = false;
                self.col0.d.next = true;
                self.first.d.next = true;
                self.nxt_done.next = true;
                self.nxt_pad.next = false;
            }
        }
        if self.beat.val() {
            if self.s_axis_tlast.val() & !self.is_last.val() {
                self.err_q.d.next = true;
                self.nxt_pad.next = true;
            }
            if self.is_last.val() & !self.s_axis_tlast.val() {
                self.err_q.d.next = true;
                self.nxt_discard.next = true;
            }
        }
        if self.discard.q.val() & self.accept.val() & self.s_axis_tlast.val() {
            self.nxt_discard.next = false;
        }
        self.nxt_run.next = self.run.val();
        if self.restart.val() {
            self.nxt_run.next = true;
            self.nxt_done.next = false;
            self.err_q.d.next = false;
        }
        self.pad.d.next = self.nxt_pad.val();
        self.discard.d.next = self.nxt_discard.val();
        self.done.d.next = self.nxt_done.val();
        // Next cycle's ready and padding slot, from registers and this cycle's events.
        self.tready_q.d.next = self.nxt_discard.val()
            | (self.nxt_run.val() & !self.nxt_done.val() & !self.nxt_pad.val() & self.room.val());
        self.pad_go.d.next =
            self.nxt_pad.val() & self.nxt_run.val() & !self.nxt_done.val() & self.room.val();
        if self.rst_next.val() {
            self.tready_q.d.next = false;
            self.pad_go.d.next = false;
        }
        if self.rst.val() {
            self.tready_q.d.next = false;
            self.pad_go.d.next = false;
            self.slot_q.d.next.valid = false;
            self.row.d.next = self.zero8.val();
            self.col.d.next = self.zero12.val();
            self.col0.d.next = true;
            self.col_last.d.next = false;
            self.row_last.d.next = false;
            self.first.d.next = true;
            self.pad.d.next = false;
            self.discard.d.next = false;
            self.done.d.next = false;
            self.err_q.d.next = false;
        }
        self.s_axis_tready.next = self.tready_q.q.val() & !self.held.val();
        self.slot.next = self.slot_q.q.val();
        self.in_done.next = self.done.q.val();
        self.err.next = self.err_q.q.val();
        self.last_col.next = self.last_col_q.q.val();
        self.idle.next = self.run.val() & !self.done.q.val() & self.first.q.val();
        self.idle_next.next = self.run_next.val() & !self.done.d.val() & self.first.d.val();
    }
}
