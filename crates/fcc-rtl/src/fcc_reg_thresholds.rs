//! `FccRegThresholds`: the run registers whose core value the shared squarer
//! derives (RW, range-checked run parameters, as `FccRegRun`; the slopes'
//! range is every 16-bit value, so `FccHiZeroCheck` checks it): the
//! thresholds RUN_TH_H and RUN_TH_V and the threshold slopes RUN_SLOPE_H and
//! RUN_SLOPE_V (spec §2), each stored in an `FccRegSquared`.
//!
//! An accepted write starts the squarer (serially, shift and add, at most
//! 19 cycles, no DSP) and is answered when the square is ready (`defer` in
//! the write's cycle, `done` at the end; `hold` keeps the bus adapter from
//! performing another write meanwhile), so the shadow value (read back) and
//! its derived value change together. A refused write sets the register's
//! ERROR bit (`refused_*`). The derived values: the addends `run_th_h_c` =
//! -(tH^2 + 1) and `run_th_v_c` = -tV^2 (36-bit two's complement) of the
//! distance units' first DSP, so that a hit is the sign of the sum
//! (`d2 <= tH^2` and `d2 < tV^2`), and the squared slopes `run_sl_h`,
//! `run_sl_v` = `A^2 >> 8` (UQ0.24) of `FccPointThr`. The active copies are
//! loaded while the core is idle (`load_h`, `load_v`, `load_sl`).
//!
//! `sq_v`: the squarer works for a V register (else H); `sq_sl`: for a
//! slope (else a threshold); `sq_a`: the value, taken at every write;
//! `sq_start`: the write, one cycle late, starts the squarer on `sq_a` (so
//! the write data's range check does not reach the squarer's registers);
//! `sq_busy_q`: `sq.busy` one cycle late (its fall is the end).
//! Reset: the squarer by `rst`; the shadow pairs (`rst_h`, `rst_v`,
//! `rst_sl_h`, `rst_sl_v`) and the active copies (`rst_act_h`, `rst_act_v`,
//! `rst_act_sl`) by kept copies of `rst` one cycle late, one per group of at
//! most 64 flip-flops.

use rust_hdl::prelude::*;

use crate::fcc_hi_zero_check::FccHiZeroCheck;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_range_check::FccRangeCheck;
use crate::fcc_reg_squared::FccRegSquared;
use crate::fcc_th_square::FccThSquare;
use crate::regmap::RunRange;

/// `-(v)` in 36-bit two's complement.
fn neg36(v: u64) -> u64 {
    (1u64 << 36).wrapping_sub(v) & ((1u64 << 36) - 1)
}

#[derive(LogicBlock)]
pub struct FccRegThresholds {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rst_h: Signal<In, Bit>,
    pub rst_v: Signal<In, Bit>,
    pub rst_sl_h: Signal<In, Bit>,
    pub rst_sl_v: Signal<In, Bit>,
    pub rst_act_h: Signal<In, Bit>,
    pub rst_act_v: Signal<In, Bit>,
    pub rst_act_sl: Signal<In, Bit>,
    // The bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// A write is performed (to any register).
    pub wr: Signal<In, Bit>,
    pub we_h: Signal<In, Bit>,
    pub we_v: Signal<In, Bit>,
    pub we_sl_h: Signal<In, Bit>,
    pub we_sl_v: Signal<In, Bit>,
    /// Bits 15:0 of the held write data.
    pub wdata: Signal<In, Bits<16>>,
    pub hold: Signal<Out, Bit>,
    pub defer: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    // Registers.
    pub load_h: Signal<In, Bit>,
    pub load_v: Signal<In, Bit>,
    pub load_sl: Signal<In, Bit>,
    pub refused_h: Signal<Out, Bit>,
    pub refused_v: Signal<Out, Bit>,
    pub refused_sl_h: Signal<Out, Bit>,
    pub refused_sl_v: Signal<Out, Bit>,
    pub shadow_h: Signal<Out, Bits<16>>,
    pub shadow_v: Signal<Out, Bits<16>>,
    pub shadow_sl_h: Signal<Out, Bits<16>>,
    pub shadow_sl_v: Signal<Out, Bits<16>>,
    /// -(tH^2 + 1), 36-bit two's complement.
    pub run_th_h_c: Signal<Out, Bits<36>>,
    /// -tV^2, 36-bit two's complement.
    pub run_th_v_c: Signal<Out, Bits<36>>,
    /// Squared slopes `A^2 >> 8` (UQ0.24).
    pub run_sl_h: Signal<Out, Bits<24>>,
    pub run_sl_v: Signal<Out, Bits<24>>,
    check: FccRangeCheck,
    check_sl: FccHiZeroCheck,
    sq: FccThSquare,
    sq_v: DFF<Bit>,
    sq_sl: DFF<Bit>,
    sq_a: DFF<Bits<16>>,
    sq_start: FccKeepReg<Bit>,
    /// `sq_start` again (kept apart): clears the squarer's sum, so that no
    /// start net drives all of its registers.
    sq_start_acc: FccKeepReg<Bit>,
    sq_start_next: Signal<Local, Bit>,
    sq_busy_q: DFF<Bit>,
    /// The squarer finished (in this cycle).
    fin: Signal<Local, Bit>,
    th_h: FccRegSquared<36>,
    th_v: FccRegSquared<36>,
    sl_h: FccRegSquared<24>,
    sl_v: FccRegSquared<24>,
}

/// The build's values of the four registers.
#[derive(Debug, Clone, Copy)]
pub struct SquaredResets {
    pub th_h: u32,
    pub th_v: u32,
    pub slope_h: u32,
    pub slope_v: u32,
}

impl FccRegThresholds {
    /// The thresholds accept `th_range`, the slopes `slope_range`; `r`:
    /// the reset values.
    pub fn new(th_range: RunRange, slope_range: RunRange, r: SquaredResets) -> Self {
        assert!(
            th_range.max <= 0x8000,
            "the squarer takes thresholds up to 0x8000"
        );
        let th = |t: u32| u64::from(t) * u64::from(t);
        let slope = |a: u32| (u64::from(a) * u64::from(a)) >> 8;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_h: Default::default(),
            rst_v: Default::default(),
            rst_sl_h: Default::default(),
            rst_sl_v: Default::default(),
            rst_act_h: Default::default(),
            rst_act_v: Default::default(),
            rst_act_sl: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            wr: Default::default(),
            we_h: Default::default(),
            we_v: Default::default(),
            we_sl_h: Default::default(),
            we_sl_v: Default::default(),
            wdata: Default::default(),
            hold: Default::default(),
            defer: Default::default(),
            done: Default::default(),
            load_h: Default::default(),
            load_v: Default::default(),
            load_sl: Default::default(),
            refused_h: Default::default(),
            refused_v: Default::default(),
            refused_sl_h: Default::default(),
            refused_sl_v: Default::default(),
            shadow_h: Default::default(),
            shadow_v: Default::default(),
            shadow_sl_h: Default::default(),
            shadow_sl_v: Default::default(),
            run_th_h_c: Default::default(),
            run_th_v_c: Default::default(),
            run_sl_h: Default::default(),
            run_sl_v: Default::default(),
            check: FccRangeCheck::new(th_range, false),
            check_sl: FccHiZeroCheck::new(slope_range),
            sq: FccThSquare::new(),
            sq_v: Default::default(),
            sq_sl: Default::default(),
            sq_a: Default::default(),
            sq_start: Default::default(),
            sq_start_acc: Default::default(),
            sq_start_next: Default::default(),
            sq_busy_q: Default::default(),
            fin: Default::default(),
            th_h: FccRegSquared::new(r.th_h, neg36(th(r.th_h) + 1)),
            th_v: FccRegSquared::new(r.th_v, neg36(th(r.th_v))),
            sl_h: FccRegSquared::new(r.slope_h, slope(r.slope_h)),
            sl_v: FccRegSquared::new(r.slope_v, slope(r.slope_v)),
        }
    }
}

impl Logic for FccRegThresholds {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, sq_v, sq_sl, sq_a, sq_busy_q);
        self.check.clk.next = self.clk.val();
        self.check.w_take.next = self.w_take.val();
        self.check.bus_wdata.next = self.bus_wdata.val();
        self.check.lsb.next = self.wdata.val().get_bit(0);
        self.check_sl.clk.next = self.clk.val();
        self.check_sl.w_take.next = self.w_take.val();
        self.check_sl.bus_hi.next = self.bus_wdata.val().get_bits::<16>(16);
        self.sq.clk.next = self.clk.val();
        self.sq.rst.next = self.rst.val();
        self.sq.a.next = self.sq_a.q.val();
        self.sq.start.next = self.sq_start.q.val();
        self.sq.start_acc.next = self.sq_start_acc.q.val();
        self.sq_start.clock.next = self.clk.val();
        self.sq_start_acc.clock.next = self.clk.val();
        // No write is performed while the squarer starts or runs.
        self.hold.next = self.sq_start.q.val() | self.sq.busy.val() | self.sq_busy_q.q.val();
        // A value in range starts the squarer; the response waits for it.
        self.sq_start_next.next = false;
        self.defer.next = ((self.we_h.val() | self.we_v.val()) & self.check.ok.val())
            | ((self.we_sl_h.val() | self.we_sl_v.val()) & self.check_sl.ok.val());
        self.refused_h.next = self.we_h.val() & !self.check.ok.val();
        self.refused_v.next = self.we_v.val() & !self.check.ok.val();
        self.refused_sl_h.next = self.we_sl_h.val() & !self.check_sl.ok.val();
        self.refused_sl_v.next = self.we_sl_v.val() & !self.check_sl.ok.val();
        if self.we_h.val() & self.check.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = false;
            self.sq_sl.d.next = false;
        }
        if self.we_v.val() & self.check.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = true;
            self.sq_sl.d.next = false;
        }
        if self.we_sl_h.val() & self.check_sl.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = false;
            self.sq_sl.d.next = true;
        }
        if self.we_sl_v.val() & self.check_sl.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = true;
            self.sq_sl.d.next = true;
        }
        if self.wr.val() {
            self.sq_a.d.next = self.wdata.val();
        }
        // Squarer done: the shadow value and its derived value together.
        self.sq_busy_q.d.next = self.sq.busy.val();
        self.fin.next = self.sq_busy_q.q.val() & !self.sq.busy.val();
        self.done.next = self.fin.val();
        self.th_h.take.next = self.fin.val() & !self.sq_sl.q.val() & !self.sq_v.q.val();
        self.th_v.take.next = self.fin.val() & !self.sq_sl.q.val() & self.sq_v.q.val();
        self.sl_h.take.next = self.fin.val() & self.sq_sl.q.val() & !self.sq_v.q.val();
        self.sl_v.take.next = self.fin.val() & self.sq_sl.q.val() & self.sq_v.q.val();
        self.th_h.val.next = self.sq.c_le.val();
        self.th_v.val.next = self.sq.c_lt.val();
        self.sl_h.val.next = self.sq.s.val();
        self.sl_v.val.next = self.sq.s.val();
        self.th_h.a.next = self.sq_a.q.val();
        self.th_v.a.next = self.sq_a.q.val();
        self.sl_h.a.next = self.sq_a.q.val();
        self.sl_v.a.next = self.sq_a.q.val();
        // Storage, its resets and its loads (the active copies: while the
        // core waits for a frame).
        self.th_h.clk.next = self.clk.val();
        self.th_v.clk.next = self.clk.val();
        self.sl_h.clk.next = self.clk.val();
        self.sl_v.clk.next = self.clk.val();
        self.th_h.rst.next = self.rst_h.val();
        self.th_v.rst.next = self.rst_v.val();
        self.sl_h.rst.next = self.rst_sl_h.val();
        self.sl_v.rst.next = self.rst_sl_v.val();
        self.th_h.rst_act.next = self.rst_act_h.val();
        self.th_v.rst_act.next = self.rst_act_v.val();
        self.sl_h.rst_act.next = self.rst_act_sl.val();
        self.sl_v.rst_act.next = self.rst_act_sl.val();
        self.th_h.load.next = self.load_h.val();
        self.th_v.load.next = self.load_v.val();
        self.sl_h.load.next = self.load_sl.val();
        self.sl_v.load.next = self.load_sl.val();
        if self.rst.val() {
            self.sq_start_next.next = false;
            self.sq_busy_q.d.next = false;
        }
        self.sq_start.d.next = self.sq_start_next.val();
        self.sq_start_acc.d.next = self.sq_start_next.val();
        self.shadow_h.next = self.th_h.shadow.val();
        self.shadow_v.next = self.th_v.shadow.val();
        self.shadow_sl_h.next = self.sl_h.shadow.val();
        self.shadow_sl_v.next = self.sl_v.shadow.val();
        self.run_th_h_c.next = self.th_h.active.val();
        self.run_th_v_c.next = self.th_v.active.val();
        self.run_sl_h.next = self.sl_h.active.val();
        self.run_sl_v.next = self.sl_v.active.val();
    }
}
