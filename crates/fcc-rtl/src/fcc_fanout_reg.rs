//! `FccFanoutReg`: a flip-flop that Vivado replicates until no copy drives
//! more than [`MAX_FANOUT`] loads.
//!
//! Where a register fans out to more loads than the routing target allows
//! and copying it by hand ([`crate::fcc_keep_reg::FccKeepReg`], one copy per
//! group of loads) would cost more flip-flops and LUTs than the block's
//! resource budget leaves, the register is built as this block instead: it
//! is rust-hdl's `DFF` (`q` follows `d` on the rising clock edge and powers
//! up at `T::default()`), written as `Verilog::Custom` so that the register
//! carries Vivado's `max_fanout` attribute. Vivado synthesis then replicates
//! it (UG901, `MAX_FANOUT`: registers and combinational signals; the placer
//! honours it too). Unlike `FccKeepReg` it carries no `keep`: Yosys may
//! still remove unused bits or merge it with an equal register, and keeps
//! the attribute on the net, which is how `fcc synth` tells these nets from
//! the ones nothing replicates.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::register_verilog;

/// The fanout target: loads per copy that Vivado replicates a marked driver
/// down to, and above which `fcc synth` reports a net.
pub const MAX_FANOUT: usize = 64;

#[derive(LogicBlock, Default)]
pub struct FccFanoutReg<T: Synth> {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, T>,
    pub q: Signal<Out, T>,
}

impl<T: Synth> Logic for FccFanoutReg<T> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.q.next = self.d.val();
        }
    }

    fn connect(&mut self) {
        self.q.connect();
    }

    fn hdl(&self) -> Verilog {
        register_verilog::<T>(&format!("max_fanout = {MAX_FANOUT}"), "")
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "fanout_reg".into(),
            clock: "clock".into(),
            inputs: vec!["d".into()],
            outputs: vec!["q".into()],
        }]
    }
}
