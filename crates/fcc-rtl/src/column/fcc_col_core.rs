//! `FccColCore`: the column-streaming core's datapath (docs/column-core.md,
//! item 8): the input half (`FccColIn`: pixels in column order, the
//! column-start check, the front, the slot buffer), the slot table half
//! (`FccColTable`: the representative rows, the run accumulators, the
//! union-find's queue, the frame end's ops) and the record store half
//! (`FccColStore`: the records, the closer, the labels' lists, the record
//! stream and both pools), with `FccColSettle`'s counts for the
//! column-start check. Pixels in (`s_axis_*`, spec §9's beats in column
//! order), one record per cluster out as it closes and an end beat per
//! frame (`m_axis_*`, spec §9.4). The run parameters come from the
//! registers at the top. This block is wiring, and the reset tree: each
//! half has its own copy of `rst` (a register of `rst_next`, as `rst` is),
//! which Vivado replicates further (`FccKeepReg::with_max_fanout`); the
//! settle counts, a few registers, take `rst` itself.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_in::FccColIn;
use super::fcc_col_settle::FccColSettle;
use super::fcc_col_store::FccColStore;
use super::fcc_col_table::FccColTable;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_open_room::OPEN_ROOM_BITS;
use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_keep_reg::FccKeepReg;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColCore {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `rst` one cycle ahead.
    pub rst_next: Signal<In, Bit>,
    pub s_axis_tdata: Signal<In, Bits<49>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    /// The frame phase (as `FccInputStage` takes it) and the input's state.
    pub run: Signal<In, Bit>,
    pub restart: Signal<In, Bit>,
    pub run_next: Signal<In, Bit>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    pub idle_next: Signal<Out, Bit>,
    /// Hold the frame's first pixel (while `idle`).
    pub start_hold: Signal<In, Bit>,
    /// A column's first pixel waits for the column-start check (the
    /// previous column to settle).
    pub col_held: Signal<Out, Bit>,
    /// Provisional labels free in the label pool.
    pub labels_free: Signal<Out, Bits<16>>,
    /// Run parameters: the frame's size (`last_row`, `last_col`: `R - 1`,
    /// `C - 1`; `col_half`: `C / 2`), K and `h`, the thresholds, the
    /// bridge and ring limits, the open limit `N_o`.
    pub run_rows: Signal<In, Bits<8>>,
    pub run_cols: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub last_col: Signal<In, Bits<12>>,
    pub col_half: Signal<In, Bits<12>>,
    pub run_k: Signal<In, Bits<4>>,
    pub h: Signal<In, Bits<3>>,
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    pub n_o: Signal<In, Bits<OPEN_ROOM_BITS>>,
    /// The record stream.
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    /// Sticky faults (never, by design): a label named that its row does
    /// not hold; a run, flush, accumulator or slot return gone wrong.
    pub miss: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
    inp: FccColIn,
    /// The slot table half (`table` is a Verilog keyword).
    sets: FccColTable,
    store: FccColStore,
    settle: FccColSettle,
    /// The reset tree: `rst` again, one copy per half.
    inp_rst: FccKeepReg<Bit>,
    sets_rst: FccKeepReg<Bit>,
    store_rst: FccKeepReg<Bit>,
    /// Slots in use.
    used: Signal<Local, Bits<16>>,
    max_slot: Constant<Bits<16>>,
}

impl FccColCore {
    /// The core of the build's rows, K and labels.
    pub fn new(p: &FccParams) -> Self {
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
            idle_next: Default::default(),
            start_hold: Default::default(),
            col_held: Default::default(),
            labels_free: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            last_row: Default::default(),
            last_col: Default::default(),
            col_half: Default::default(),
            run_k: Default::default(),
            h: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            n_o: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tlast: Default::default(),
            m_axis_tready: Default::default(),
            miss: Default::default(),
            bad: Default::default(),
            inp: FccColIn::new(p),
            sets: FccColTable::new(p),
            store: FccColStore::new(p),
            settle: Default::default(),
            inp_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            sets_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            store_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            used: Default::default(),
            max_slot: kb((1 << SLOT_BITS) - 1),
        }
    }
}

impl Logic for FccColCore {
    #[hdl_gen]
    fn update(&mut self) {
        // The reset tree: each copy is `rst`'s flip-flop again.
        self.inp_rst.clock.next = self.clk.val();
        self.sets_rst.clock.next = self.clk.val();
        self.store_rst.clock.next = self.clk.val();
        self.inp_rst.d.next = self.rst_next.val();
        self.sets_rst.d.next = self.rst_next.val();
        self.store_rst.d.next = self.rst_next.val();
        // The input half.
        self.inp.clk.next = self.clk.val();
        self.inp.rst.next = self.inp_rst.q.val();
        self.inp.rst_next.next = self.rst_next.val();
        self.inp.s_axis_tdata.next = self.s_axis_tdata.val();
        self.inp.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.inp.s_axis_tlast.next = self.s_axis_tlast.val();
        self.s_axis_tready.next = self.inp.s_axis_tready.val();
        self.inp.run.next = self.run.val();
        self.inp.restart.next = self.restart.val();
        self.inp.run_next.next = self.run_next.val();
        self.in_done.next = self.inp.in_done.val();
        self.err.next = self.inp.err.val();
        self.idle.next = self.inp.idle.val();
        self.idle_next.next = self.inp.idle_next.val();
        self.inp.start_hold.next = self.start_hold.val();
        self.col_held.next = self.inp.col_held.val();
        self.inp.run_rows.next = self.run_rows.val();
        self.inp.run_cols.next = self.run_cols.val();
        self.inp.last_row.next = self.last_row.val();
        self.inp.run_k.next = self.run_k.val();
        self.inp.sh.next = self.sh.val();
        self.inp.sv.next = self.sv.val();
        self.inp.ch_t.next = self.ch_t.val();
        self.inp.cv_t.next = self.cv_t.val();
        self.inp.reach.next = self.reach.val();
        self.inp.ring_on.next = self.ring_on.val();
        self.inp.ring_f_max.next = self.ring_f_max.val();
        self.inp.ring_l_min.next = self.ring_l_min.val();
        self.inp.n_o.next = self.n_o.val();
        self.used.next = self.max_slot.val() - self.store.slots_free.val();
        self.inp.slots_used.next = self.used.val().get_bits::<OPEN_ROOM_BITS>(0);
        self.inp.in_flight.next = self.settle.in_flight.val();
        self.inp.labels_free.next = self.store.labels_free.val();
        self.labels_free.next = self.store.labels_free.val();
        self.inp.settled.next = self.settle.settled.val();
        self.inp.free_ok.next = self.store.free_ok.val();
        self.inp.free_label.next = self.store.free_label.val();
        self.inp.take.next = self.sets.take.val();
        // The slot table half.
        self.sets.clk.next = self.clk.val();
        self.sets.rst.next = self.sets_rst.q.val();
        self.sets.last_row.next = self.last_row.val();
        self.sets.last_col.next = self.last_col.val();
        self.sets.half.next = self.col_half.val();
        self.sets.valid.next = self.inp.valid.val();
        self.sets.centre.next = self.inp.centre.val();
        for e in 0..self.sets.hit.len() {
            self.sets.hit[e].next = self.inp.hit[e].val();
            self.sets.hit_label[e].next = self.inp.hit_label[e].val();
        }
        self.sets.frame_err.next = self.settle.frame_err.val();
        self.sets.slot_ok.next = self.store.slot_ok.val();
        self.sets.slot.next = self.store.slot.val();
        self.sets.ev_take.next = self.store.ev_take.val();
        self.sets.acc_take.next = self.store.acc_take.val();
        self.miss.next = self.sets.miss.val();
        self.bad.next = self.sets.bad.val() | self.store.bad.val();
        // The record store half.
        self.store.clk.next = self.clk.val();
        self.store.rst.next = self.store_rst.q.val();
        self.store.half.next = self.h.val();
        self.store.last_col.next = self.last_col.val();
        self.store.ev_valid.next = self.sets.ev_valid.val();
        self.store.ev_make.next = self.sets.ev_make.val();
        self.store.ev_join.next = self.sets.ev_join.val();
        self.store.ev_mark.next = self.sets.ev_mark.val();
        self.store.ev_ring.next = self.sets.ev_ring.val();
        self.store.ev_merged.next = self.sets.ev_merged.val();
        self.store.ev_label.next = self.sets.ev_label.val();
        self.store.ev_slot.next = self.sets.ev_slot.val();
        self.store.ev_other.next = self.sets.ev_other.val();
        self.store.ev_col.next = self.sets.ev_col.val();
        self.store.ev_row.next = self.sets.ev_row.val();
        self.store.acc_valid.next = self.sets.acc_valid.val();
        self.store.acc.next = self.sets.acc.val();
        self.store.label_take.next = self.inp.label_take.val();
        self.store.slot_take.next = self.sets.slot_take.val();
        self.m_axis_tdata.next = self.store.m_axis_tdata.val();
        self.m_axis_tvalid.next = self.store.m_axis_tvalid.val();
        self.m_axis_tlast.next = self.store.m_axis_tlast.val();
        self.store.m_axis_tready.next = self.m_axis_tready.val();
        // The column-start check's counts.
        self.settle.clk.next = self.clk.val();
        self.settle.rst.next = self.rst.val();
        self.settle.last_col.next = self.last_col.val();
        self.settle.col_begin.next = self.inp.col_begin.val();
        self.settle.marked.next = self.store.marked.val();
        self.settle.calm.next = self.store.calm.val();
        self.settle.label_take.next = self.inp.label_take.val();
        // A make takes its slot in the union-find: from then on the slot
        // pool counts it.
        self.settle.make_taken.next = self.sets.slot_take.val();
        self.settle.in_done.next = self.inp.in_done.val();
        self.settle.err.next = self.inp.err.val();
    }
}
