//! `FccColInProbe`: `FccColIn` of the build behind scalar ports, for its
//! own bench: the AXI4-Stream input, the frame phase, the run parameters,
//! the column-start check's counts, the label pool's head and `take` in;
//! the ready, the stage's state, `label_take` and the buffer's head
//! (`valid`, the centre field by field as `o_*`, its hits and labels
//! packed by `FccHitsPack`) out.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_in::FccColIn;
use super::fcc_hits_pack::FccHitsPack;
use super::fcc_open_room::OPEN_ROOM_BITS;
use super::fcc_quad_lane::LabelQuad;

#[derive(LogicBlock)]
pub struct FccColInProbe {
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
    pub take: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    pub label_take: Signal<Out, Bit>,
    pub valid: Signal<Out, Bit>,
    pub idle: Signal<Out, Bit>,
    pub idle_next: Signal<Out, Bit>,
    pub o_valid: Signal<Out, Bit>,
    pub o_ok: Signal<Out, Bit>,
    pub o_lok: Signal<Out, Bit>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_first: Signal<Out, Bit>,
    pub o_last: Signal<Out, Bit>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_refused: Signal<Out, Bit>,
    pub o_ring_first: Signal<Out, Bit>,
    pub o_ring: Signal<Out, Bit>,
    pub o_ring_a: Signal<Out, Bits<16>>,
    pub o_ring_b: Signal<Out, Bits<16>>,
    pub o_hold_drop: Signal<Out, Bits<16>>,
    pub o_hold_add: Signal<Out, Bits<16>>,
    pub hits: Signal<Out, Bits<64>>,
    pub lw0: Signal<Out, LabelQuad>,
    pub lw1: Signal<Out, LabelQuad>,
    pub lw2: Signal<Out, LabelQuad>,
    pub lw3: Signal<Out, LabelQuad>,
    pub lw4: Signal<Out, LabelQuad>,
    pub lw5: Signal<Out, LabelQuad>,
    pub lw6: Signal<Out, LabelQuad>,
    pub lw7: Signal<Out, LabelQuad>,
    pub lw8: Signal<Out, LabelQuad>,
    pub lw9: Signal<Out, LabelQuad>,
    pub lw10: Signal<Out, LabelQuad>,
    pub lw11: Signal<Out, LabelQuad>,
    pub lw12: Signal<Out, LabelQuad>,
    pub lw13: Signal<Out, LabelQuad>,
    half: FccColIn,
    pack: FccHitsPack,
    _n: usize,
}

impl FccColInProbe {
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
            take: Default::default(),
            s_axis_tready: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            label_take: Default::default(),
            valid: Default::default(),
            idle: Default::default(),
            idle_next: Default::default(),
            o_valid: Default::default(),
            o_ok: Default::default(),
            o_lok: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_first: Default::default(),
            o_last: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_refused: Default::default(),
            o_ring_first: Default::default(),
            o_ring: Default::default(),
            o_ring_a: Default::default(),
            o_ring_b: Default::default(),
            o_hold_drop: Default::default(),
            o_hold_add: Default::default(),
            hits: Default::default(),
            lw0: Default::default(),
            lw1: Default::default(),
            lw2: Default::default(),
            lw3: Default::default(),
            lw4: Default::default(),
            lw5: Default::default(),
            lw6: Default::default(),
            lw7: Default::default(),
            lw8: Default::default(),
            lw9: Default::default(),
            lw10: Default::default(),
            lw11: Default::default(),
            lw12: Default::default(),
            lw13: Default::default(),
            half: FccColIn::new(p),
            pack: FccHitsPack::new(p),
            _n: p.window_positions(),
        }
    }
}

impl Logic for FccColInProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.half.clk.next = self.clk.val();
        self.half.rst.next = self.rst.val();
        self.half.rst_next.next = self.rst_next.val();
        self.half.s_axis_tdata.next = self.s_axis_tdata.val();
        self.half.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.half.s_axis_tlast.next = self.s_axis_tlast.val();
        self.half.run.next = self.run.val();
        self.half.restart.next = self.restart.val();
        self.half.run_next.next = self.run_next.val();
        self.half.start_hold.next = false;
        self.half.run_rows.next = self.run_rows.val();
        self.half.run_cols.next = self.run_cols.val();
        self.half.last_row.next = self.last_row.val();
        self.half.run_k.next = self.run_k.val();
        self.half.sh.next = self.sh.val();
        self.half.sv.next = self.sv.val();
        self.half.ch_t.next = self.ch_t.val();
        self.half.cv_t.next = self.cv_t.val();
        self.half.reach.next = self.reach.val();
        self.half.ring_on.next = self.ring_on.val();
        self.half.ring_f_max.next = self.ring_f_max.val();
        self.half.ring_l_min.next = self.ring_l_min.val();
        self.half.n_o.next = self.n_o.val();
        self.half.slots_used.next = self.slots_used.val();
        self.half.in_flight.next = self.in_flight.val();
        self.half.labels_free.next = self.labels_free.val();
        self.half.settled.next = self.settled.val();
        self.half.free_ok.next = self.free_ok.val();
        self.half.free_label.next = self.free_label.val();
        self.half.take.next = self.take.val();
        self.s_axis_tready.next = self.half.s_axis_tready.val();
        self.in_done.next = self.half.in_done.val();
        self.err.next = self.half.err.val();
        self.label_take.next = self.half.label_take.val();
        self.valid.next = self.half.valid.val();
        self.idle.next = self.half.idle.val();
        self.idle_next.next = self.half.idle_next.val();
        self.o_valid.next = self.half.centre.val().valid;
        self.o_ok.next = self.half.centre.val().ok;
        self.o_lok.next = self.half.centre.val().lok;
        self.o_row.next = self.half.centre.val().row;
        self.o_col.next = self.half.centre.val().col;
        self.o_first.next = self.half.centre.val().first;
        self.o_last.next = self.half.centre.val().last;
        self.o_label.next = self.half.centre.val().label;
        self.o_start.next = self.half.centre.val().start;
        self.o_refused.next = self.half.centre.val().refused;
        self.o_ring_first.next = self.half.centre.val().ring_first;
        self.o_ring.next = self.half.centre.val().ring;
        self.o_ring_a.next = self.half.centre.val().ring_a;
        self.o_ring_b.next = self.half.centre.val().ring_b;
        self.o_hold_drop.next = self.half.centre.val().hold_drop;
        self.o_hold_add.next = self.half.centre.val().hold_add;
        for e in 0..self._n {
            self.pack.hit[e].next = self.half.hit[e].val();
            self.pack.hit_label[e].next = self.half.hit_label[e].val();
        }
        self.hits.next = self.pack.hits.val();
        self.lw0.next = self.pack.lw0.val();
        self.lw1.next = self.pack.lw1.val();
        self.lw2.next = self.pack.lw2.val();
        self.lw3.next = self.pack.lw3.val();
        self.lw4.next = self.pack.lw4.val();
        self.lw5.next = self.pack.lw5.val();
        self.lw6.next = self.pack.lw6.val();
        self.lw7.next = self.pack.lw7.val();
        self.lw8.next = self.pack.lw8.val();
        self.lw9.next = self.pack.lw9.val();
        self.lw10.next = self.pack.lw10.val();
        self.lw11.next = self.pack.lw11.val();
        self.lw12.next = self.pack.lw12.val();
        self.lw13.next = self.pack.lw13.val();
    }
}
