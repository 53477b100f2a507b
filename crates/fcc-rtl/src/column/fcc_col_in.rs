//! `FccColIn`: the column core's input half (docs/column-core.md, item 8):
//! the AXI4-Stream input in column order (`FccInputStage::column_order`),
//! the column-start check (`FccColStart`, whose `hold` keeps a column's
//! first pixel at the input and whose `open_room` goes to the row runs),
//! the front (`FccColFront`) and the slot buffer with its credits
//! (`FccColSlotBuf`, whose `room` gates the input). Out of it: the buffer's
//! head, a pixel with its run and joins, taken by `take`.
//!
//! Wiring only. The counts the column-start check compares (the slots in
//! use and on their way, the free labels, the previous column settled) and
//! the label pool's head are the slot table's, at the top.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_front::FccColFront;
use super::fcc_col_slot_buf::FccColSlotBuf;
use super::fcc_col_start::FccColStart;
use super::fcc_open_room::OPEN_ROOM_BITS;
use super::RunPix;
use crate::fcc_input_stage::FccInputStage;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccColIn {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `rst` one cycle ahead.
    pub rst_next: Signal<In, Bit>,
    pub s_axis_tdata: Signal<In, Bits<49>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    /// The frame phase (as `FccInputStage` takes it) and the stage's state.
    pub run: Signal<In, Bit>,
    pub restart: Signal<In, Bit>,
    pub run_next: Signal<In, Bit>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    /// The frame's first pixel waits (the top's run registers are loading).
    pub start_hold: Signal<In, Bit>,
    pub idle_next: Signal<Out, Bit>,
    /// A column's first slot enters the front.
    pub col_begin: Signal<Out, Bit>,
    /// The column-start check holds a column's first pixel this cycle.
    pub col_held: Signal<Out, Bit>,
    /// Run parameters: the frame's size (`last_row` is `R - 1`), K, the
    /// thresholds, the bridge and ring limits.
    pub run_rows: Signal<In, Bits<8>>,
    pub run_cols: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub run_k: Signal<In, Bits<4>>,
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    /// The column-start check's counts (`FccColStart`).
    pub n_o: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub slots_used: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub in_flight: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub labels_free: Signal<In, Bits<16>>,
    pub settled: Signal<In, Bit>,
    /// The label pool's head, and `label_take` pops it.
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub label_take: Signal<Out, Bit>,
    /// The buffer's head, and `take` (while `valid`) lets it go.
    pub valid: Signal<Out, Bit>,
    pub centre: Signal<Out, RunPix>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub hit_label: Vec<Signal<Out, Bits<16>>>,
    pub take: Signal<In, Bit>,
    stage: FccInputStage,
    start: FccColStart,
    front: FccColFront,
    slots: FccColSlotBuf,
}

impl FccColIn {
    /// The input half of the build's rows and K.
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_next: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tlast: Default::default(),
            s_axis_tready: Default::default(),
            run: Default::default(),
            restart: Default::default(),
            run_next: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            idle: Default::default(),
            start_hold: Default::default(),
            idle_next: Default::default(),
            col_begin: Default::default(),
            col_held: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            n_o: Default::default(),
            slots_used: Default::default(),
            in_flight: Default::default(),
            labels_free: Default::default(),
            settled: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            label_take: Default::default(),
            valid: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            hit_label: vec_of(n),
            take: Default::default(),
            stage: FccInputStage::column_order(),
            start: Default::default(),
            front: FccColFront::new(p),
            slots: FccColSlotBuf::new(p),
        }
    }
}

impl Logic for FccColIn {
    #[hdl_gen]
    fn update(&mut self) {
        // The input stage: its room from the buffer's credits, a column's
        // first pixel held by the column-start check.
        self.stage.clk.next = self.clk.val();
        self.stage.rst.next = self.rst.val();
        self.stage.rst_next.next = self.rst_next.val();
        self.stage.s_axis_tdata.next = self.s_axis_tdata.val();
        self.stage.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.stage.s_axis_tlast.next = self.s_axis_tlast.val();
        self.s_axis_tready.next = self.stage.s_axis_tready.val();
        self.stage.run_rows.next = self.run_rows.val();
        self.stage.run_cols.next = self.run_cols.val();
        self.stage.run.next = self.run.val();
        self.stage.restart.next = self.restart.val();
        self.stage.run_next.next = self.run_next.val();
        self.stage.room.next = self.slots.room.val();
        // A frame's first pixel is its first column's first.
        self.stage.col_hold.next = self.start.hold.val() | self.start_hold.val();
        self.in_done.next = self.stage.in_done.val();
        self.err.next = self.stage.err.val();
        self.idle.next = self.stage.idle.val();
        self.idle_next.next = self.stage.idle_next.val();
        // The column-start check.
        self.start.clk.next = self.clk.val();
        self.start.rst.next = self.rst.val();
        self.start.rows.next = self.run_rows.val();
        self.start.n_o.next = self.n_o.val();
        self.start.slots_used.next = self.slots_used.val();
        self.start.in_flight.next = self.in_flight.val();
        self.start.labels_free.next = self.labels_free.val();
        self.start.settled.next = self.settled.val();
        self.start.first.next = self.stage.col_first.val();
        self.start.accept.next = self.stage.slot_now.val();
        self.col_begin.next = self.stage.col_first.val() & self.stage.slot_now.val();
        self.col_held.next = self.start.hold.val();
        // The front.
        self.front.clk.next = self.clk.val();
        self.front.rst.next = self.rst.val();
        self.front.pix.next = self.stage.slot.val();
        self.front.sh.next = self.sh.val();
        self.front.sv.next = self.sv.val();
        self.front.ch_t.next = self.ch_t.val();
        self.front.cv_t.next = self.cv_t.val();
        self.front.last_col.next = self.stage.last_col.val();
        self.front.reach.next = self.reach.val();
        self.front.ring_on.next = self.ring_on.val();
        self.front.ring_f_max.next = self.ring_f_max.val();
        self.front.ring_l_min.next = self.ring_l_min.val();
        self.front.last_row.next = self.last_row.val();
        self.front.run_k.next = self.run_k.val();
        self.front.free_ok.next = self.free_ok.val();
        self.front.free_label.next = self.free_label.val();
        self.label_take.next = self.front.take.val();
        self.front.open_room.next = self.start.open_room.val();
        // The slot buffer.
        self.slots.clk.next = self.clk.val();
        self.slots.rst.next = self.rst.val();
        self.slots.slot.next = self.stage.slot_now.val();
        self.slots.in_centre.next = self.front.centre.val();
        for e in 0..self.hit.len() {
            self.slots.in_hit[e].next = self.front.hit[e].val();
            self.slots.in_label[e].next = self.front.hit_label[e].val();
            self.hit[e].next = self.slots.hit[e].val();
            self.hit_label[e].next = self.slots.hit_label[e].val();
        }
        self.slots.take.next = self.take.val();
        self.valid.next = self.slots.valid.val();
        self.centre.next = self.slots.centre.val();
    }
}
