//! `FccColLimitsProbe`: `FccColLimits` behind registered inputs (the inputs
//! given in one cycle are its inputs in the next), for its bench; the
//! outputs are the block's (the ring check's a cycle later).

use rust_hdl::prelude::*;

use super::fcc_col_limits::FccColLimits;
use super::fcc_open_room::OPEN_ROOM_BITS;

#[derive(LogicBlock, Default)]
pub struct FccColLimitsProbe {
    pub clk: Signal<In, Clock>,
    pub run_rows: Signal<In, Bits<7>>,
    pub run_cols: Signal<In, Bits<13>>,
    pub half_k: Signal<In, Bits<3>>,
    pub bridge: Signal<In, Bits<12>>,
    pub ring_reach: Signal<In, Bits<12>>,
    pub open_limit: Signal<In, Bits<12>>,
    pub cols: Signal<Out, Bits<12>>,
    pub last_row: Signal<Out, Bits<7>>,
    pub last_col: Signal<Out, Bits<12>>,
    pub col_half: Signal<Out, Bits<12>>,
    pub h: Signal<Out, Bits<3>>,
    pub reach: Signal<Out, Bits<12>>,
    pub ring_on: Signal<Out, Bit>,
    pub ring_f_max: Signal<Out, Bits<12>>,
    pub ring_l_min: Signal<Out, Bits<12>>,
    pub n_o: Signal<Out, Bits<OPEN_ROOM_BITS>>,
    limits: FccColLimits,
    rows_q: DFF<Bits<7>>,
    cols_q: DFF<Bits<13>>,
    k_q: DFF<Bits<3>>,
    bridge_q: DFF<Bits<12>>,
    reach_q: DFF<Bits<12>>,
    open_q: DFF<Bits<12>>,
}

impl Logic for FccColLimitsProbe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, rows_q, cols_q, k_q, bridge_q, reach_q, open_q);
        self.rows_q.d.next = self.run_rows.val();
        self.cols_q.d.next = self.run_cols.val();
        self.k_q.d.next = self.half_k.val();
        self.bridge_q.d.next = self.bridge.val();
        self.reach_q.d.next = self.ring_reach.val();
        self.open_q.d.next = self.open_limit.val();
        self.limits.clk.next = self.clk.val();
        self.limits.run_rows.next = self.rows_q.q.val();
        self.limits.run_cols.next = self.cols_q.q.val();
        self.limits.half_k.next = self.k_q.q.val();
        self.limits.bridge.next = self.bridge_q.q.val();
        self.limits.ring_reach.next = self.reach_q.q.val();
        self.limits.open_limit.next = self.open_q.q.val();
        self.cols.next = self.limits.cols.val();
        self.last_row.next = self.limits.last_row.val();
        self.last_col.next = self.limits.last_col.val();
        self.col_half.next = self.limits.col_half.val();
        self.h.next = self.limits.h.val();
        self.reach.next = self.limits.reach.val();
        self.ring_on.next = self.limits.ring_on.val();
        self.ring_f_max.next = self.limits.ring_f_max.val();
        self.ring_l_min.next = self.limits.ring_l_min.val();
        self.n_o.next = self.limits.n_o.val();
    }
}
