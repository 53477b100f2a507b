//! `FccRegThresholds`: the two threshold registers RUN_TH_H and RUN_TH_V (RW,
//! range-checked run parameters, as `FccRegRun`) and the squarer they share.
//!
//! An accepted threshold write starts the squarer (serially, shift and add,
//! at most 19 cycles, no DSP) and is answered when the square is ready
//! (`defer` in the write's cycle, `done` at the end; `hold` keeps the bus
//! adapter from performing another write meanwhile), so the shadow threshold
//! (read back) and its square change together. A refused write sets the
//! register's ERROR bit (`refused_h`, `refused_v`). The active addends
//! `run_th_h_c` = -(tH^2 + 1) and `run_th_v_c` = -tV^2 (36-bit two's
//! complement) of the distance units' first DSP, so that a hit is the sign of
//! the sum (`d2 <= tH^2` and `d2 < tV^2`), are loaded from the shadow squares
//! while the core is idle (`load_h`, `load_v`).
//!
//! `sq_v`: the squarer works for TH_V (else TH_H); `sq_a`: the value, taken
//! at every write; `sq_start`: the write, one cycle late, starts the squarer
//! on `sq_a` (so the write data's range check does not reach the squarer's
//! registers); `sq_busy_q`: `sq.busy` one cycle late (its fall is the end).
//! Reset: the squarer by `rst`; the shadow values (`rst_h`, `rst_v`) and the
//! active addends (`rst_act_h`, `rst_act_v`) by kept copies of `rst` one
//! cycle late, one per group of at most 64 flip-flops.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_range_check::FccRangeCheck;
use crate::fcc_th_square::FccThSquare;
use crate::regmap::RunRange;
use crate::types::kb;

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
    pub rst_act_h: Signal<In, Bit>,
    pub rst_act_v: Signal<In, Bit>,
    // The bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// A write is performed (to any register).
    pub wr: Signal<In, Bit>,
    pub we_h: Signal<In, Bit>,
    pub we_v: Signal<In, Bit>,
    /// Bits 15:0 of the held write data.
    pub wdata: Signal<In, Bits<16>>,
    pub hold: Signal<Out, Bit>,
    pub defer: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    // Registers.
    pub load_h: Signal<In, Bit>,
    pub load_v: Signal<In, Bit>,
    pub refused_h: Signal<Out, Bit>,
    pub refused_v: Signal<Out, Bit>,
    pub shadow_h: Signal<Out, Bits<16>>,
    pub shadow_v: Signal<Out, Bits<16>>,
    /// -(tH^2 + 1), 36-bit two's complement.
    pub run_th_h_c: Signal<Out, Bits<36>>,
    /// -tV^2, 36-bit two's complement.
    pub run_th_v_c: Signal<Out, Bits<36>>,
    check: FccRangeCheck,
    sq: FccThSquare,
    sq_v: DFF<Bit>,
    sq_a: DFF<Bits<16>>,
    sq_start: FccKeepReg<Bit>,
    /// `sq_start` again (kept apart): clears the squarer's sum, so that no
    /// start net drives all of its registers.
    sq_start_acc: FccKeepReg<Bit>,
    sq_start_next: Signal<Local, Bit>,
    sq_busy_q: DFF<Bit>,
    sh_thh: DFF<Bits<16>>,
    sh_thv: DFF<Bits<16>>,
    sh_thh_c: DFF<Bits<36>>,
    sh_thv_c: DFF<Bits<36>>,
    act_thh_c: DFF<Bits<36>>,
    act_thv_c: DFF<Bits<36>>,
    def_thh: Constant<Bits<16>>,
    def_thv: Constant<Bits<16>>,
    def_thh_c: Constant<Bits<36>>,
    def_thv_c: Constant<Bits<36>>,
}

impl FccRegThresholds {
    /// Both registers accept `range`; `th_h`, `th_v`: their reset values.
    pub fn new(range: RunRange, th_h: u32, th_v: u32) -> Self {
        assert!(
            range.max <= 0x8000,
            "the squarer takes thresholds up to 0x8000"
        );
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_h: Default::default(),
            rst_v: Default::default(),
            rst_act_h: Default::default(),
            rst_act_v: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            wr: Default::default(),
            we_h: Default::default(),
            we_v: Default::default(),
            wdata: Default::default(),
            hold: Default::default(),
            defer: Default::default(),
            done: Default::default(),
            load_h: Default::default(),
            load_v: Default::default(),
            refused_h: Default::default(),
            refused_v: Default::default(),
            shadow_h: Default::default(),
            shadow_v: Default::default(),
            run_th_h_c: Default::default(),
            run_th_v_c: Default::default(),
            check: FccRangeCheck::new(range, false),
            sq: FccThSquare::new(),
            sq_v: Default::default(),
            sq_a: Default::default(),
            sq_start: Default::default(),
            sq_start_acc: Default::default(),
            sq_start_next: Default::default(),
            sq_busy_q: Default::default(),
            sh_thh: Default::default(),
            sh_thv: Default::default(),
            sh_thh_c: Default::default(),
            sh_thv_c: Default::default(),
            act_thh_c: Default::default(),
            act_thv_c: Default::default(),
            def_thh: kb(u64::from(th_h)),
            def_thv: kb(u64::from(th_v)),
            def_thh_c: kb(neg36(u64::from(th_h) * u64::from(th_h) + 1)),
            def_thv_c: kb(neg36(u64::from(th_v) * u64::from(th_v))),
        }
    }
}

impl Logic for FccRegThresholds {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, sq_v, sq_a, sq_busy_q, sh_thh, sh_thv, sh_thh_c, sh_thv_c, act_thh_c,
            act_thv_c
        );
        self.check.clk.next = self.clk.val();
        self.check.w_take.next = self.w_take.val();
        self.check.bus_wdata.next = self.bus_wdata.val();
        self.check.lsb.next = self.wdata.val().get_bit(0);
        self.sq.clk.next = self.clk.val();
        self.sq.rst.next = self.rst.val();
        self.sq.a.next = self.sq_a.q.val();
        self.sq.start.next = self.sq_start.q.val();
        self.sq.start_acc.next = self.sq_start_acc.q.val();
        self.sq_start.clock.next = self.clk.val();
        self.sq_start_acc.clock.next = self.clk.val();
        // No write is performed while the squarer starts or runs.
        self.hold.next = self.sq_start.q.val() | self.sq.busy.val() | self.sq_busy_q.q.val();
        // A threshold in range starts the squarer; the response waits for it.
        self.sq_start_next.next = false;
        self.defer.next = (self.we_h.val() | self.we_v.val()) & self.check.ok.val();
        self.refused_h.next = self.we_h.val() & !self.check.ok.val();
        self.refused_v.next = self.we_v.val() & !self.check.ok.val();
        if self.we_h.val() & self.check.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = false;
        }
        if self.we_v.val() & self.check.ok.val() {
            self.sq_start_next.next = true;
            self.sq_v.d.next = true;
        }
        if self.wr.val() {
            self.sq_a.d.next = self.wdata.val();
        }
        // Squarer done: the shadow threshold and its square together.
        self.sq_busy_q.d.next = self.sq.busy.val();
        self.done.next = self.sq_busy_q.q.val() & !self.sq.busy.val();
        if self.sq_busy_q.q.val() & !self.sq.busy.val() {
            if self.sq_v.q.val() {
                self.sh_thv.d.next = self.sq_a.q.val();
                self.sh_thv_c.d.next = self.sq.c_lt.val();
            } else {
                self.sh_thh.d.next = self.sq_a.q.val();
                self.sh_thh_c.d.next = self.sq.c_le.val();
            }
        }
        // Active addends: loaded while the core waits for a frame.
        if self.load_h.val() {
            self.act_thh_c.d.next = self.sh_thh_c.q.val();
        }
        if self.load_v.val() {
            self.act_thv_c.d.next = self.sh_thv_c.q.val();
        }
        if self.rst.val() {
            self.sq_start_next.next = false;
            self.sq_busy_q.d.next = false;
        }
        self.sq_start.d.next = self.sq_start_next.val();
        self.sq_start_acc.d.next = self.sq_start_next.val();
        if self.rst_h.val() {
            self.sh_thh.d.next = self.def_thh.val();
            self.sh_thh_c.d.next = self.def_thh_c.val();
        }
        if self.rst_v.val() {
            self.sh_thv.d.next = self.def_thv.val();
            self.sh_thv_c.d.next = self.def_thv_c.val();
        }
        if self.rst_act_h.val() {
            self.act_thh_c.d.next = self.def_thh_c.val();
        }
        if self.rst_act_v.val() {
            self.act_thv_c.d.next = self.def_thv_c.val();
        }
        self.shadow_h.next = self.sh_thh.q.val();
        self.shadow_v.next = self.sh_thv.q.val();
        self.run_th_h_c.next = self.act_thh_c.q.val();
        self.run_th_v_c.next = self.act_thv_c.q.val();
    }
}
