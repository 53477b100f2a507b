//! `FccRegRunParams`: the run-parameter registers of the register file and
//! their ERROR register, each a field block of its access type: RUN_K,
//! RUN_ROWS, RUN_COLS (`FccRegRun`), RUN_TH_H, RUN_TH_V, RUN_SLOPE_H and
//! RUN_SLOPE_V (`FccRegThresholds`), ERROR (`FccRegW1c`, set by a refused write). The
//! ranges, reset values and ERROR bits are those of the map.
//!
//! Each register has a shadow (written, read back) and an active copy (the
//! `run_*` outputs), loaded from the shadow in every cycle the core is idle
//! (waiting for a frame's first pixel), so a frame never sees a change. The
//! core's idle flag comes one cycle early (`idle_next`) and is registered
//! here in kept copies, one per group of at most 64 loads: `idle_dims` for
//! the active RUN_K, RUN_ROWS, RUN_COLS and -(tH^2 + 1), `idle_th_v` for the
//! active -tV^2 and STATUS.IDLE (`idle`), `idle_sl` for the active squared
//! slopes.
//!
//! The registers are reset by `rst` one cycle late, from kept copies of
//! `rst`, one per group of at most 64 flip-flops (`run_rst_dims`: RUN_K,
//! RUN_ROWS, RUN_COLS, shadow and active; `run_rst_th_h`, `run_rst_th_v`,
//! `run_rst_sl_h`, `run_rst_sl_v`: a shadow threshold or slope and its
//! square; `run_rst_act_h`, `run_rst_act_v`: the active addends;
//! `run_rst_act_sl`: the active squared slopes). Nothing can change them in that cycle (no write is held,
//! the squarer is in reset, the pipeline reads them only after its merge
//! table is initialised), and no read is taken in it (`read_block`).

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_reg_run::FccRegRun;
use crate::fcc_reg_thresholds::{FccRegThresholds, SquaredResets};
use crate::fcc_reg_w1c::FccRegW1c;
use crate::regmap::{self, bits, offset, Access, Register, RunRange};

#[derive(LogicBlock)]
pub struct FccRegRunParams {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// A write is performed (to any register).
    pub wr: Signal<In, Bit>,
    pub we_error: Signal<In, Bit>,
    pub we_k: Signal<In, Bit>,
    pub we_th_h: Signal<In, Bit>,
    pub we_th_v: Signal<In, Bit>,
    pub we_rows: Signal<In, Bit>,
    pub we_cols: Signal<In, Bit>,
    pub we_sl_h: Signal<In, Bit>,
    pub we_sl_v: Signal<In, Bit>,
    /// The held write data.
    pub wdata: Signal<In, Bits<32>>,
    /// No write is performed (the squarer runs).
    pub hold: Signal<Out, Bit>,
    /// The write performed now is a threshold's, answered on `done`.
    pub defer: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    /// No read is taken (the registers are in reset).
    pub read_block: Signal<Out, Bit>,
    // From the core.
    /// The core waits for a frame's first pixel in the next cycle.
    pub idle_next: Signal<In, Bit>,
    // Read back: STATUS.IDLE, the ERROR bits, the shadow values.
    pub idle: Signal<Out, Bit>,
    pub err_k: Signal<Out, Bit>,
    pub err_th_h: Signal<Out, Bit>,
    pub err_th_v: Signal<Out, Bit>,
    pub err_rows: Signal<Out, Bit>,
    pub err_cols: Signal<Out, Bit>,
    pub err_sl_h: Signal<Out, Bit>,
    pub err_sl_v: Signal<Out, Bit>,
    pub shadow_k: Signal<Out, Bits<16>>,
    pub shadow_th_h: Signal<Out, Bits<16>>,
    pub shadow_th_v: Signal<Out, Bits<16>>,
    pub shadow_rows: Signal<Out, Bits<16>>,
    pub shadow_cols: Signal<Out, Bits<16>>,
    pub shadow_sl_h: Signal<Out, Bits<16>>,
    pub shadow_sl_v: Signal<Out, Bits<16>>,
    // Active run parameters (constant during a frame).
    pub run_k: Signal<Out, Bits<4>>,
    /// -(tH^2 + 1), 36-bit two's complement.
    pub run_th_h_c: Signal<Out, Bits<36>>,
    /// -tV^2, 36-bit two's complement.
    pub run_th_v_c: Signal<Out, Bits<36>>,
    pub run_rows: Signal<Out, Bits<8>>,
    pub run_cols: Signal<Out, Bits<13>>,
    /// Squared slopes `A^2 >> 8` (UQ0.24).
    pub run_sl_h: Signal<Out, Bits<24>>,
    pub run_sl_v: Signal<Out, Bits<24>>,
    reg_k: FccRegRun<4>,
    reg_rows: FccRegRun<8>,
    reg_cols: FccRegRun<13>,
    thresholds: FccRegThresholds,
    error: FccRegW1c,
    run_rst_dims: FccKeepReg<Bit>,
    run_rst_th_h: FccKeepReg<Bit>,
    run_rst_th_v: FccKeepReg<Bit>,
    run_rst_act_h: FccKeepReg<Bit>,
    run_rst_act_v: FccKeepReg<Bit>,
    run_rst_sl_h: FccKeepReg<Bit>,
    run_rst_sl_v: FccKeepReg<Bit>,
    run_rst_act_sl: FccKeepReg<Bit>,
    idle_dims: FccKeepReg<Bit>,
    idle_th_v: FccKeepReg<Bit>,
    idle_sl: FccKeepReg<Bit>,
    // The position of each register's ERROR field among the ERROR block's
    // bits, in the map.
    _err_k: usize,
    _err_th_h: usize,
    _err_th_v: usize,
    _err_rows: usize,
    _err_cols: usize,
    _err_sl_h: usize,
    _err_sl_v: usize,
}

/// The register at `off` in `regs`, checked to have the access `access`.
pub(crate) fn find(regs: &[Register], off: u32, access: Access) -> &Register {
    let r = regs
        .iter()
        .find(|r| r.offset == off)
        .unwrap_or_else(|| panic!("no register at {off:#x} in the map"));
    assert_eq!(r.access, access, "{} is not {}", r.name, access.as_str());
    r
}

/// The range and reset value of the run register at `off`.
pub(crate) fn run(regs: &[Register], off: u32) -> (RunRange, u32) {
    let r = find(regs, off, Access::ReadWrite);
    let range = r.range.unwrap_or_else(|| panic!("{} has no range", r.name));
    (range, r.reset)
}

impl FccRegRunParams {
    /// The run registers and ERROR of the map `regs`.
    pub fn new(regs: &[Register]) -> Self {
        let error = find(regs, offset::ERROR, Access::WriteOneToClear);
        // Its own registers' bits (the stream limits' are
        // `FccRegStreamLimits`').
        let theirs = bits::ERROR_BRIDGE | bits::ERROR_RING_REACH | bits::ERROR_OPEN_LIMIT;
        let err_lsbs: Vec<u32> = error
            .fields
            .iter()
            .map(|f| f.lsb)
            .filter(|l| theirs & (1 << l) == 0)
            .collect();
        let err = |off: u32| {
            let b = regmap::run_error_bit(off).expect("a run register");
            err_lsbs
                .iter()
                .position(|l| 1 << l == b)
                .unwrap_or_else(|| panic!("no ERROR field for {off:#x}"))
        };
        let (k_range, k_reset) = run(regs, offset::RUN_K);
        let (th_range, th_h_reset) = run(regs, offset::RUN_TH_H);
        let (th_v_range, th_v_reset) = run(regs, offset::RUN_TH_V);
        assert_eq!(th_range, th_v_range, "the thresholds share one range check");
        let (sl_range, sl_h_reset) = run(regs, offset::RUN_SLOPE_H);
        let (sl_v_range, sl_v_reset) = run(regs, offset::RUN_SLOPE_V);
        assert_eq!(sl_range, sl_v_range, "the slopes share one range check");
        let (rows_range, rows_reset) = run(regs, offset::RUN_ROWS);
        let (cols_range, cols_reset) = run(regs, offset::RUN_COLS);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            wr: Default::default(),
            we_error: Default::default(),
            we_k: Default::default(),
            we_th_h: Default::default(),
            we_th_v: Default::default(),
            we_rows: Default::default(),
            we_cols: Default::default(),
            we_sl_h: Default::default(),
            we_sl_v: Default::default(),
            wdata: Default::default(),
            hold: Default::default(),
            defer: Default::default(),
            done: Default::default(),
            read_block: Default::default(),
            idle_next: Default::default(),
            idle: Default::default(),
            err_k: Default::default(),
            err_th_h: Default::default(),
            err_th_v: Default::default(),
            err_rows: Default::default(),
            err_cols: Default::default(),
            err_sl_h: Default::default(),
            err_sl_v: Default::default(),
            shadow_k: Default::default(),
            shadow_th_h: Default::default(),
            shadow_th_v: Default::default(),
            shadow_rows: Default::default(),
            shadow_cols: Default::default(),
            shadow_sl_h: Default::default(),
            shadow_sl_v: Default::default(),
            run_k: Default::default(),
            run_th_h_c: Default::default(),
            run_th_v_c: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            run_sl_h: Default::default(),
            run_sl_v: Default::default(),
            // RUN_K takes odd values only.
            reg_k: FccRegRun::new(k_range, true, k_reset),
            reg_rows: FccRegRun::new(rows_range, false, rows_reset),
            reg_cols: FccRegRun::new(cols_range, false, cols_reset),
            thresholds: FccRegThresholds::new(
                th_range,
                sl_range,
                SquaredResets {
                    th_h: th_h_reset,
                    th_v: th_v_reset,
                    slope_h: sl_h_reset,
                    slope_v: sl_v_reset,
                },
            ),
            error: FccRegW1c::new(&err_lsbs),
            run_rst_dims: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_th_h: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_th_v: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_act_h: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_act_v: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_sl_h: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_sl_v: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_act_sl: FccKeepReg::with_max_fanout(MAX_FANOUT),
            idle_dims: Default::default(),
            idle_th_v: Default::default(),
            idle_sl: Default::default(),
            _err_k: err(offset::RUN_K),
            _err_th_h: err(offset::RUN_TH_H),
            _err_th_v: err(offset::RUN_TH_V),
            _err_rows: err(offset::RUN_ROWS),
            _err_cols: err(offset::RUN_COLS),
            _err_sl_h: err(offset::RUN_SLOPE_H),
            _err_sl_v: err(offset::RUN_SLOPE_V),
        }
    }
}

impl Logic for FccRegRunParams {
    #[hdl_gen]
    fn update(&mut self) {
        self.run_rst_dims.clock.next = self.clk.val();
        self.run_rst_th_h.clock.next = self.clk.val();
        self.run_rst_th_v.clock.next = self.clk.val();
        self.run_rst_act_h.clock.next = self.clk.val();
        self.run_rst_act_v.clock.next = self.clk.val();
        self.idle_dims.clock.next = self.clk.val();
        self.idle_th_v.clock.next = self.clk.val();
        self.run_rst_sl_h.clock.next = self.clk.val();
        self.run_rst_sl_v.clock.next = self.clk.val();
        self.run_rst_act_sl.clock.next = self.clk.val();
        self.idle_sl.clock.next = self.clk.val();
        self.run_rst_sl_h.d.next = self.rst.val();
        self.run_rst_sl_v.d.next = self.rst.val();
        self.run_rst_act_sl.d.next = self.rst.val();
        self.idle_sl.d.next = self.idle_next.val();
        self.run_rst_dims.d.next = self.rst.val();
        self.run_rst_th_h.d.next = self.rst.val();
        self.run_rst_th_v.d.next = self.rst.val();
        self.run_rst_act_h.d.next = self.rst.val();
        self.run_rst_act_v.d.next = self.rst.val();
        self.idle_dims.d.next = self.idle_next.val();
        self.idle_th_v.d.next = self.idle_next.val();
        self.read_block.next = self.run_rst_dims.q.val();
        self.idle.next = self.idle_th_v.q.val();
        // RUN_K, RUN_ROWS, RUN_COLS.
        self.reg_k.clk.next = self.clk.val();
        self.reg_k.run_rst.next = self.run_rst_dims.q.val();
        self.reg_k.w_take.next = self.w_take.val();
        self.reg_k.bus_wdata.next = self.bus_wdata.val();
        self.reg_k.we.next = self.we_k.val();
        self.reg_k.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_k.load.next = self.idle_dims.q.val();
        self.reg_rows.clk.next = self.clk.val();
        self.reg_rows.run_rst.next = self.run_rst_dims.q.val();
        self.reg_rows.w_take.next = self.w_take.val();
        self.reg_rows.bus_wdata.next = self.bus_wdata.val();
        self.reg_rows.we.next = self.we_rows.val();
        self.reg_rows.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_rows.load.next = self.idle_dims.q.val();
        self.reg_cols.clk.next = self.clk.val();
        self.reg_cols.run_rst.next = self.run_rst_dims.q.val();
        self.reg_cols.w_take.next = self.w_take.val();
        self.reg_cols.bus_wdata.next = self.bus_wdata.val();
        self.reg_cols.we.next = self.we_cols.val();
        self.reg_cols.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_cols.load.next = self.idle_dims.q.val();
        // RUN_TH_H, RUN_TH_V and their squarer.
        self.thresholds.clk.next = self.clk.val();
        self.thresholds.rst.next = self.rst.val();
        self.thresholds.rst_h.next = self.run_rst_th_h.q.val();
        self.thresholds.rst_v.next = self.run_rst_th_v.q.val();
        self.thresholds.rst_act_h.next = self.run_rst_act_h.q.val();
        self.thresholds.rst_act_v.next = self.run_rst_act_v.q.val();
        self.thresholds.rst_sl_h.next = self.run_rst_sl_h.q.val();
        self.thresholds.rst_sl_v.next = self.run_rst_sl_v.q.val();
        self.thresholds.rst_act_sl.next = self.run_rst_act_sl.q.val();
        self.thresholds.w_take.next = self.w_take.val();
        self.thresholds.bus_wdata.next = self.bus_wdata.val();
        self.thresholds.wr.next = self.wr.val();
        self.thresholds.we_h.next = self.we_th_h.val();
        self.thresholds.we_v.next = self.we_th_v.val();
        self.thresholds.we_sl_h.next = self.we_sl_h.val();
        self.thresholds.we_sl_v.next = self.we_sl_v.val();
        self.thresholds.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.thresholds.load_h.next = self.idle_dims.q.val();
        self.thresholds.load_v.next = self.idle_th_v.q.val();
        self.thresholds.load_sl.next = self.idle_sl.q.val();
        self.hold.next = self.thresholds.hold.val();
        self.defer.next = self.thresholds.defer.val();
        self.done.next = self.thresholds.done.val();
        // ERROR: a refused write sets its bit.
        self.error.clk.next = self.clk.val();
        self.error.rst.next = self.rst.val();
        self.error.we.next = self.we_error.val();
        self.error.wdata.next = self.wdata.val();
        self.error.clear.next = false;
        for e in self._err_k..(self._err_k + 1) {
            self.error.set[e].next = self.reg_k.refused.val();
            self.err_k.next = self.error.q[e].val();
        }
        for e in self._err_th_h..(self._err_th_h + 1) {
            self.error.set[e].next = self.thresholds.refused_h.val();
            self.err_th_h.next = self.error.q[e].val();
        }
        for e in self._err_th_v..(self._err_th_v + 1) {
            self.error.set[e].next = self.thresholds.refused_v.val();
            self.err_th_v.next = self.error.q[e].val();
        }
        for e in self._err_rows..(self._err_rows + 1) {
            self.error.set[e].next = self.reg_rows.refused.val();
            self.err_rows.next = self.error.q[e].val();
        }
        for e in self._err_cols..(self._err_cols + 1) {
            self.error.set[e].next = self.reg_cols.refused.val();
            self.err_cols.next = self.error.q[e].val();
        }
        for e in self._err_sl_h..(self._err_sl_h + 1) {
            self.error.set[e].next = self.thresholds.refused_sl_h.val();
            self.err_sl_h.next = self.error.q[e].val();
        }
        for e in self._err_sl_v..(self._err_sl_v + 1) {
            self.error.set[e].next = self.thresholds.refused_sl_v.val();
            self.err_sl_v.next = self.error.q[e].val();
        }
        // ---- Outputs.
        self.shadow_k.next = self.reg_k.shadow.val();
        self.shadow_th_h.next = self.thresholds.shadow_h.val();
        self.shadow_th_v.next = self.thresholds.shadow_v.val();
        self.shadow_rows.next = self.reg_rows.shadow.val();
        self.shadow_cols.next = self.reg_cols.shadow.val();
        self.shadow_sl_h.next = self.thresholds.shadow_sl_h.val();
        self.shadow_sl_v.next = self.thresholds.shadow_sl_v.val();
        self.run_k.next = self.reg_k.active.val();
        self.run_th_h_c.next = self.thresholds.run_th_h_c.val();
        self.run_th_v_c.next = self.thresholds.run_th_v_c.val();
        self.run_rows.next = self.reg_rows.active.val();
        self.run_cols.next = self.reg_cols.active.val();
        self.run_sl_h.next = self.thresholds.run_sl_h.val();
        self.run_sl_v.next = self.thresholds.run_sl_v.val();
    }
}
