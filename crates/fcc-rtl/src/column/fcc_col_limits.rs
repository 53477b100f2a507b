//! `FccColLimits`: the column core's run parameters in the form its
//! datapath takes them, worked out from the active run registers (the
//! registers change only while the core is idle and quiet): the frame's
//! last row and column and half its columns, the window's half-size `h`,
//! the bridge limit as a reach, the ring check's column bounds, the open
//! limit. All are combinational but the ring check's (`ring_on`,
//! `ring_f_max`, `ring_l_min`), which are registered: they follow the run
//! registers a cycle later. Only pixels read them, in the front's row
//! entry, which no pixel reaches within cycles of a load (the load's
//! reset of the datapath comes first); registered, the column count's
//! compare and subtraction end at a flip-flop instead of running on into
//! the row entry's compares. The rules are `RunLimits`' (spec §3):
//! - reach `min(RUN_BRIDGE + 1, 0xFFF)` (a gap of `g` empty pixels is
//!   bridged while `g < reach`);
//! - with `m = min(RUN_RING_REACH, C)`: the ring check is on while
//!   `m > 0`, for a row whose first valid pixel is in columns `0 ..= m - 1`
//!   and its last in `C - m ..= C - 1`.

use rust_hdl::prelude::*;

use super::fcc_open_room::OPEN_ROOM_BITS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColLimits {
    pub clk: Signal<In, Clock>,
    /// Active RUN_ROWS, RUN_COLS, RUN_K, RUN_BRIDGE, RUN_RING_REACH and
    /// RUN_OPEN_LIMIT (9 bits, zero-extended).
    /// RUN_ROWS' low 7 bits (128 rows: 0, and `R - 1` is 127 all the same).
    pub run_rows: Signal<In, Bits<7>>,
    pub run_cols: Signal<In, Bits<13>>,
    /// RUN_K's bits 3:1 (K is odd): `h`.
    pub half_k: Signal<In, Bits<3>>,
    pub bridge: Signal<In, Bits<12>>,
    pub ring_reach: Signal<In, Bits<12>>,
    pub open_limit: Signal<In, Bits<12>>,
    /// `C` in 12 bits (the column core has at most 4095 columns).
    pub cols: Signal<Out, Bits<12>>,
    pub last_row: Signal<Out, Bits<7>>,
    pub last_col: Signal<Out, Bits<12>>,
    pub col_half: Signal<Out, Bits<12>>,
    pub h: Signal<Out, Bits<3>>,
    pub reach: Signal<Out, Bits<12>>,
    /// A cycle after the run registers.
    pub ring_on: Signal<Out, Bit>,
    pub ring_f_max: Signal<Out, Bits<12>>,
    pub ring_l_min: Signal<Out, Bits<12>>,
    pub n_o: Signal<Out, Bits<OPEN_ROOM_BITS>>,
    c: Signal<Local, Bits<12>>,
    m: Signal<Local, Bits<12>>,
    ring_on_q: DFF<Bit>,
    f_max_q: DFF<Bits<12>>,
    l_min_q: DFF<Bits<12>>,
    one7: Constant<Bits<7>>,
    one12: Constant<Bits<12>>,
    /// The largest bridge value below "none".
    bridge_top: Constant<Bits<12>>,
    max12: Constant<Bits<12>>,
    zero12: Constant<Bits<12>>,
}

impl Default for FccColLimits {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            half_k: Default::default(),
            bridge: Default::default(),
            ring_reach: Default::default(),
            open_limit: Default::default(),
            cols: Default::default(),
            last_row: Default::default(),
            last_col: Default::default(),
            col_half: Default::default(),
            h: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            n_o: Default::default(),
            c: Default::default(),
            m: Default::default(),
            ring_on_q: Default::default(),
            f_max_q: Default::default(),
            l_min_q: Default::default(),
            one7: kb(1),
            one12: kb(1),
            bridge_top: kb(0xFFE),
            max12: kb(0xFFF),
            zero12: kb(0),
        }
    }
}

impl Logic for FccColLimits {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ring_on_q, f_max_q, l_min_q);
        self.c.next = self.run_cols.val().get_bits::<12>(0);
        self.cols.next = self.c.val();
        self.last_row.next = self.run_rows.val() - self.one7.val();
        self.last_col.next = self.c.val() - self.one12.val();
        self.col_half.next = self.c.val() >> 1;
        self.h.next = self.half_k.val();
        self.reach.next = self.max12.val();
        if self.bridge.val() < self.bridge_top.val() {
            self.reach.next = self.bridge.val() + self.one12.val();
        }
        self.m.next = self.ring_reach.val();
        if self.c.val() < self.ring_reach.val() {
            self.m.next = self.c.val();
        }
        self.ring_on_q.d.next = self.m.val() != self.zero12.val();
        self.f_max_q.d.next = self.m.val() - self.one12.val();
        self.l_min_q.d.next = self.c.val() - self.m.val();
        if self.m.val() == self.zero12.val() {
            // As `RunLimits`: both 0 while the check is off.
            self.f_max_q.d.next = self.zero12.val();
            self.l_min_q.d.next = self.zero12.val();
        }
        self.ring_on.next = self.ring_on_q.q.val();
        self.ring_f_max.next = self.f_max_q.q.val();
        self.ring_l_min.next = self.l_min_q.q.val();
        self.n_o.next = self.open_limit.val().get_bits::<OPEN_ROOM_BITS>(0);
    }
}
