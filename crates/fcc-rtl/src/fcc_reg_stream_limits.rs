//! `FccRegStreamLimits`: the column core's run registers for the stream's
//! limits (spec §3, §9.1), RUN_BRIDGE, RUN_RING_REACH and RUN_OPEN_LIMIT,
//! each an `FccRegRun`, and their three ERROR bits (`FccRegW1c`; the
//! other ERROR bits are `FccRegRunParams`'). Ranges, reset values and bits
//! are the map's. As the other run registers: the active copies load from
//! the shadows while the core is idle (`idle_next`, registered here), and
//! are reset one cycle after `rst` (`run_rst`, a kept copy).

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_reg_run::FccRegRun;
use crate::fcc_reg_run_params::{find, run};
use crate::fcc_reg_w1c::FccRegW1c;
use crate::regmap::{self, offset, Access, Register};

#[derive(LogicBlock)]
pub struct FccRegStreamLimits {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    pub we_error: Signal<In, Bit>,
    pub we_bridge: Signal<In, Bit>,
    pub we_reach: Signal<In, Bit>,
    pub we_open: Signal<In, Bit>,
    /// The held write data.
    pub wdata: Signal<In, Bits<32>>,
    /// The core waits for a frame's first pixel in the next cycle.
    pub idle_next: Signal<In, Bit>,
    // Read back.
    pub err_bridge: Signal<Out, Bit>,
    pub err_reach: Signal<Out, Bit>,
    pub err_open: Signal<Out, Bit>,
    pub shadow_bridge: Signal<Out, Bits<16>>,
    pub shadow_reach: Signal<Out, Bits<16>>,
    pub shadow_open: Signal<Out, Bits<16>>,
    // Active values (constant during a frame).
    pub run_bridge: Signal<Out, Bits<12>>,
    pub run_reach: Signal<Out, Bits<12>>,
    pub run_open: Signal<Out, Bits<12>>,
    reg_bridge: FccRegRun<12>,
    reg_reach: FccRegRun<12>,
    /// 12 bits wide to match the others (its values are below 512).
    reg_open: FccRegRun<12>,
    error: FccRegW1c,
    run_rst: FccKeepReg<Bit>,
    idle: FccKeepReg<Bit>,
}

impl FccRegStreamLimits {
    /// The three registers of the map `regs` (a column core's).
    pub fn new(regs: &[Register]) -> Self {
        let error = find(regs, offset::ERROR, Access::WriteOneToClear);
        // The ERROR W1C's bits in the order bridge, reach, open.
        let lsbs: Vec<u32> = [
            offset::RUN_BRIDGE,
            offset::RUN_RING_REACH,
            offset::RUN_OPEN_LIMIT,
        ]
        .iter()
        .map(|off| {
            let b = regmap::run_error_bit(*off).expect("a run register");
            let f = error
                .fields
                .iter()
                .find(|f| 1 << f.lsb == b)
                .unwrap_or_else(|| panic!("no ERROR field for {off:#x}"));
            f.lsb
        })
        .collect();
        let (bridge_range, bridge_reset) = run(regs, offset::RUN_BRIDGE);
        let (reach_range, reach_reset) = run(regs, offset::RUN_RING_REACH);
        let (open_range, open_reset) = run(regs, offset::RUN_OPEN_LIMIT);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            we_error: Default::default(),
            we_bridge: Default::default(),
            we_reach: Default::default(),
            we_open: Default::default(),
            wdata: Default::default(),
            idle_next: Default::default(),
            err_bridge: Default::default(),
            err_reach: Default::default(),
            err_open: Default::default(),
            shadow_bridge: Default::default(),
            shadow_reach: Default::default(),
            shadow_open: Default::default(),
            run_bridge: Default::default(),
            run_reach: Default::default(),
            run_open: Default::default(),
            reg_bridge: FccRegRun::new(bridge_range, false, bridge_reset),
            reg_reach: FccRegRun::new(reach_range, false, reach_reset),
            reg_open: FccRegRun::new(open_range, false, open_reset),
            error: FccRegW1c::new(&lsbs),
            run_rst: Default::default(),
            idle: Default::default(),
        }
    }
}

impl Logic for FccRegStreamLimits {
    #[hdl_gen]
    fn update(&mut self) {
        self.run_rst.clock.next = self.clk.val();
        self.run_rst.d.next = self.rst.val();
        self.idle.clock.next = self.clk.val();
        self.idle.d.next = self.idle_next.val();
        self.reg_bridge.clk.next = self.clk.val();
        self.reg_bridge.run_rst.next = self.run_rst.q.val();
        self.reg_bridge.w_take.next = self.w_take.val();
        self.reg_bridge.bus_wdata.next = self.bus_wdata.val();
        self.reg_bridge.we.next = self.we_bridge.val();
        self.reg_bridge.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_bridge.load.next = self.idle.q.val();
        self.reg_reach.clk.next = self.clk.val();
        self.reg_reach.run_rst.next = self.run_rst.q.val();
        self.reg_reach.w_take.next = self.w_take.val();
        self.reg_reach.bus_wdata.next = self.bus_wdata.val();
        self.reg_reach.we.next = self.we_reach.val();
        self.reg_reach.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_reach.load.next = self.idle.q.val();
        self.reg_open.clk.next = self.clk.val();
        self.reg_open.run_rst.next = self.run_rst.q.val();
        self.reg_open.w_take.next = self.w_take.val();
        self.reg_open.bus_wdata.next = self.bus_wdata.val();
        self.reg_open.we.next = self.we_open.val();
        self.reg_open.wdata.next = self.wdata.val().get_bits::<16>(0);
        self.reg_open.load.next = self.idle.q.val();
        self.error.clk.next = self.clk.val();
        self.error.rst.next = self.rst.val();
        self.error.we.next = self.we_error.val();
        self.error.wdata.next = self.wdata.val();
        self.error.clear.next = false;
        self.error.set[0].next = self.reg_bridge.refused.val();
        self.error.set[1].next = self.reg_reach.refused.val();
        self.error.set[2].next = self.reg_open.refused.val();
        self.err_bridge.next = self.error.q[0].val();
        self.err_reach.next = self.error.q[1].val();
        self.err_open.next = self.error.q[2].val();
        self.shadow_bridge.next = self.reg_bridge.shadow.val();
        self.shadow_reach.next = self.reg_reach.shadow.val();
        self.shadow_open.next = self.reg_open.shadow.val();
        self.run_bridge.next = self.reg_bridge.active.val();
        self.run_reach.next = self.reg_reach.active.val();
        self.run_open.next = self.reg_open.active.val();
    }
}
