//! `FccRegRun`: a run-parameter register (RW, range-checked) whose active
//! copy is `N` bits wide: RUN_K, RUN_ROWS, RUN_COLS.
//!
//! A write is checked by an `FccRangeCheck`; an accepted value goes into
//! the register software reads back (the shadow, 16 bits), a value outside
//! the range is refused (the shadow keeps its value, `refused` sets the
//! register's ERROR bit). The core uses the *active* copy, loaded from the
//! shadow in every cycle `load` is high (the core waits for a frame's first
//! pixel), so a frame never sees a change. Both are reset by `run_rst`
//! (`rst` one cycle late) to the build's value.

use rust_hdl::prelude::*;

use crate::fcc_range_check::FccRangeCheck;
use crate::regmap::RunRange;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRegRun<const N: usize> {
    pub clk: Signal<In, Clock>,
    /// The shadow and the active copy take their reset value.
    pub run_rst: Signal<In, Bit>,
    // From the bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// A write to this register is performed.
    pub we: Signal<In, Bit>,
    /// Bits 15:0 of the held write data.
    pub wdata: Signal<In, Bits<16>>,
    /// The core is idle: the active copy loads the shadow.
    pub load: Signal<In, Bit>,
    /// The value software reads back.
    pub shadow: Signal<Out, Bits<16>>,
    /// The value the core uses.
    pub active: Signal<Out, Bits<N>>,
    /// The write in this cycle is refused.
    pub refused: Signal<Out, Bit>,
    check: FccRangeCheck,
    sh: DFF<Bits<16>>,
    act: DFF<Bits<N>>,
    reset16: Constant<Bits<16>>,
    reset: Constant<Bits<N>>,
}

impl<const N: usize> FccRegRun<N> {
    /// A register accepting `range` (`odd`: odd values only) with the
    /// reset value `reset`.
    pub fn new(range: RunRange, odd: bool, reset: u32) -> Self {
        assert!(N <= 16, "active copy of {N} bits");
        assert!(u64::from(reset) < 1 << N, "reset {reset} in {N} bits");
        Self {
            clk: Default::default(),
            run_rst: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            we: Default::default(),
            wdata: Default::default(),
            load: Default::default(),
            shadow: Default::default(),
            active: Default::default(),
            refused: Default::default(),
            check: FccRangeCheck::new(range, odd),
            sh: Default::default(),
            act: Default::default(),
            reset16: kb(u64::from(reset)),
            reset: kb(u64::from(reset)),
        }
    }
}

impl<const N: usize> Logic for FccRegRun<N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, sh, act);
        self.check.clk.next = self.clk.val();
        self.check.w_take.next = self.w_take.val();
        self.check.bus_wdata.next = self.bus_wdata.val();
        self.check.lsb.next = self.wdata.val().get_bit(0);
        self.refused.next = self.we.val() & !self.check.ok.val();
        if self.we.val() & self.check.ok.val() {
            self.sh.d.next = self.wdata.val();
        }
        if self.load.val() {
            self.act.d.next = self.sh.q.val().get_bits::<N>(0);
        }
        if self.run_rst.val() {
            self.sh.d.next = self.reset16.val();
            self.act.d.next = self.reset.val();
        }
        self.shadow.next = self.sh.q.val();
        self.active.next = self.act.q.val();
    }
}
