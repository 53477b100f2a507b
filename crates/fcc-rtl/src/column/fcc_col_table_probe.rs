//! `FccColTableProbe`: the column core's input half (`FccColIn`) and slot
//! table half (`FccColTable`) of the build, wired as the core wires them,
//! behind scalar ports, for their bench: the AXI4-Stream input, the frame
//! phase, the run parameters, the column-start check's counts, the label
//! and slot pools' heads in; the ready, the stage's state, the pools'
//! takes, the union-find queue's events and the oldest flush's accumulator
//! (`AccWord` field by field as `o_*`) out. An event is taken while
//! `ev_ready`, a find only with its accumulator, which goes with it (as
//! the record store's arbiter will take them).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_in::FccColIn;
use super::fcc_col_table::FccColTable;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_open_room::OPEN_ROOM_BITS;

#[derive(LogicBlock)]
pub struct FccColTableProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rst_next: Signal<In, Bit>,
    pub s_axis_tdata: Signal<In, Bits<49>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    pub run: Signal<In, Bit>,
    pub restart: Signal<In, Bit>,
    pub run_next: Signal<In, Bit>,
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
    pub n_o: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub slots_used: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub in_flight: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub labels_free: Signal<In, Bits<16>>,
    pub settled: Signal<In, Bit>,
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub last_col: Signal<In, Bits<12>>,
    pub half: Signal<In, Bits<12>>,
    pub slot_ok: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    pub ev_ready: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    pub label_take: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    pub idle_next: Signal<Out, Bit>,
    pub slot_take: Signal<Out, Bit>,
    pub ev_valid: Signal<Out, Bit>,
    pub ev_make: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_mark: Signal<Out, Bit>,
    pub ev_ring: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_label: Signal<Out, Bits<16>>,
    pub ev_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_other: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_col: Signal<Out, Bits<12>>,
    pub ev_row: Signal<Out, Bits<7>>,
    pub acc_valid: Signal<Out, Bit>,
    pub miss: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
    pub o_points: Signal<Out, Bits<20>>,
    pub o_min_col: Signal<Out, Bits<12>>,
    pub o_max_col: Signal<Out, Bits<12>>,
    pub o_lo_has: Signal<Out, Bit>,
    pub o_lo_max: Signal<Out, Bits<12>>,
    pub o_hi_has: Signal<Out, Bit>,
    pub o_hi_min: Signal<Out, Bits<12>>,
    pub o_first_row: Signal<Out, Bits<7>>,
    pub o_last_row: Signal<Out, Bits<7>>,
    pub o_min_x: Signal<Out, Bits<16>>,
    pub o_min_y: Signal<Out, Bits<16>>,
    pub o_min_z: Signal<Out, Bits<16>>,
    pub o_max_x: Signal<Out, Bits<16>>,
    pub o_max_y: Signal<Out, Bits<16>>,
    pub o_max_z: Signal<Out, Bits<16>>,
    pub o_r2_min: Signal<Out, Bits<32>>,
    pub o_r2_max: Signal<Out, Bits<32>>,
    pub o_sa: Signal<Out, Bits<35>>,
    pub o_sb: Signal<Out, Bits<35>>,
    pub o_sc: Signal<Out, Bits<35>>,
    pub o_sxx: Signal<Out, Bits<50>>,
    pub o_syy: Signal<Out, Bits<50>>,
    pub o_sab: Signal<Out, Bits<51>>,
    pub o_seam: Signal<Out, Bit>,
    find: Signal<Local, Bit>,
    took: Signal<Local, Bit>,
    inp: FccColIn,
    sets: FccColTable,
    _n: usize,
}

impl FccColTableProbe {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_next: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tlast: Default::default(),
            run: Default::default(),
            restart: Default::default(),
            run_next: Default::default(),
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
            last_col: Default::default(),
            half: Default::default(),
            slot_ok: Default::default(),
            slot: Default::default(),
            ev_ready: Default::default(),
            find: Default::default(),
            took: Default::default(),
            s_axis_tready: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            label_take: Default::default(),
            idle: Default::default(),
            idle_next: Default::default(),
            slot_take: Default::default(),
            ev_valid: Default::default(),
            ev_make: Default::default(),
            ev_join: Default::default(),
            ev_mark: Default::default(),
            ev_ring: Default::default(),
            ev_merged: Default::default(),
            ev_label: Default::default(),
            ev_slot: Default::default(),
            ev_other: Default::default(),
            ev_col: Default::default(),
            ev_row: Default::default(),
            acc_valid: Default::default(),
            miss: Default::default(),
            bad: Default::default(),
            o_points: Default::default(),
            o_min_col: Default::default(),
            o_max_col: Default::default(),
            o_lo_has: Default::default(),
            o_lo_max: Default::default(),
            o_hi_has: Default::default(),
            o_hi_min: Default::default(),
            o_first_row: Default::default(),
            o_last_row: Default::default(),
            o_min_x: Default::default(),
            o_min_y: Default::default(),
            o_min_z: Default::default(),
            o_max_x: Default::default(),
            o_max_y: Default::default(),
            o_max_z: Default::default(),
            o_r2_min: Default::default(),
            o_r2_max: Default::default(),
            o_sa: Default::default(),
            o_sb: Default::default(),
            o_sc: Default::default(),
            o_sxx: Default::default(),
            o_syy: Default::default(),
            o_sab: Default::default(),
            o_seam: Default::default(),
            inp: FccColIn::new(p),
            sets: FccColTable::new(p),
            _n: p.window_positions(),
        }
    }
}

impl Logic for FccColTableProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.inp.clk.next = self.clk.val();
        self.inp.rst.next = self.rst.val();
        self.inp.rst_next.next = self.rst_next.val();
        self.inp.s_axis_tdata.next = self.s_axis_tdata.val();
        self.inp.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.inp.s_axis_tlast.next = self.s_axis_tlast.val();
        self.inp.run.next = self.run.val();
        self.inp.restart.next = self.restart.val();
        self.inp.run_next.next = self.run_next.val();
        self.inp.start_hold.next = false;
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
        self.inp.slots_used.next = self.slots_used.val();
        self.inp.in_flight.next = self.in_flight.val();
        self.inp.labels_free.next = self.labels_free.val();
        self.inp.settled.next = self.settled.val();
        self.inp.free_ok.next = self.free_ok.val();
        self.inp.free_label.next = self.free_label.val();
        self.s_axis_tready.next = self.inp.s_axis_tready.val();
        self.in_done.next = self.inp.in_done.val();
        self.err.next = self.inp.err.val();
        self.label_take.next = self.inp.label_take.val();
        self.idle.next = self.inp.idle.val();
        self.idle_next.next = self.inp.idle_next.val();
        self.sets.clk.next = self.clk.val();
        self.sets.rst.next = self.rst.val();
        self.sets.last_row.next = self.last_row.val();
        self.sets.last_col.next = self.last_col.val();
        self.sets.half.next = self.half.val();
        // The end beat's flags are the record store's (its bench: `col_core`).
        self.sets.frame_err.next = self.inp.err.val();
        self.sets.slot_ok.next = self.slot_ok.val();
        self.sets.slot.next = self.slot.val();
        // A find waits for its accumulator.
        self.find.next = self.sets.ev_valid.val()
            & !(self.sets.ev_make.val() | self.sets.ev_join.val() | self.sets.ev_mark.val());
        self.took.next = self.ev_ready.val()
            & self.sets.ev_valid.val()
            & (!self.find.val() | self.sets.acc_valid.val());
        self.sets.ev_take.next = self.took.val();
        self.sets.acc_take.next = self.took.val() & self.find.val();
        // The buffer's head into the table.
        self.sets.valid.next = self.inp.valid.val();
        self.sets.centre.next = self.inp.centre.val();
        for e in 0..self._n {
            self.sets.hit[e].next = self.inp.hit[e].val();
            self.sets.hit_label[e].next = self.inp.hit_label[e].val();
        }
        self.inp.take.next = self.sets.take.val();
        self.slot_take.next = self.sets.slot_take.val();
        self.ev_valid.next = self.sets.ev_valid.val();
        self.ev_make.next = self.sets.ev_make.val();
        self.ev_join.next = self.sets.ev_join.val();
        self.ev_mark.next = self.sets.ev_mark.val();
        self.ev_ring.next = self.sets.ev_ring.val();
        self.ev_merged.next = self.sets.ev_merged.val();
        self.ev_label.next = self.sets.ev_label.val();
        self.ev_slot.next = self.sets.ev_slot.val();
        self.ev_other.next = self.sets.ev_other.val();
        self.ev_col.next = self.sets.ev_col.val();
        self.ev_row.next = self.sets.ev_row.val();
        self.acc_valid.next = self.sets.acc_valid.val();
        self.miss.next = self.sets.miss.val();
        self.bad.next = self.sets.bad.val();
        self.o_points.next = self.sets.acc.val().points;
        self.o_min_col.next = self.sets.acc.val().min_col;
        self.o_max_col.next = self.sets.acc.val().max_col;
        self.o_lo_has.next = self.sets.acc.val().lo_has;
        self.o_lo_max.next = self.sets.acc.val().lo_max;
        self.o_hi_has.next = self.sets.acc.val().hi_has;
        self.o_hi_min.next = self.sets.acc.val().hi_min;
        self.o_first_row.next = self.sets.acc.val().first_row;
        self.o_last_row.next = self.sets.acc.val().last_row;
        self.o_min_x.next = self.sets.acc.val().min_x;
        self.o_min_y.next = self.sets.acc.val().min_y;
        self.o_min_z.next = self.sets.acc.val().min_z;
        self.o_max_x.next = self.sets.acc.val().max_x;
        self.o_max_y.next = self.sets.acc.val().max_y;
        self.o_max_z.next = self.sets.acc.val().max_z;
        self.o_r2_min.next = self.sets.acc.val().r2_min;
        self.o_r2_max.next = self.sets.acc.val().r2_max;
        self.o_sa.next = self.sets.acc.val().sa;
        self.o_sb.next = self.sets.acc.val().sb;
        self.o_sc.next = self.sets.acc.val().sc;
        self.o_sxx.next = self.sets.acc.val().sxx;
        self.o_syy.next = self.sets.acc.val().syy;
        self.o_sab.next = self.sets.acc.val().sab;
        self.o_seam.next = self.sets.acc.val().seam;
    }
}
