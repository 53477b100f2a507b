//! `FccFanoutNet`: a combinational signal whose driver Vivado replicates
//! until no copy drives more than [`MAX_FANOUT`] loads.
//!
//! `y` is `x`. The Verilog declares `y` with Vivado's `max_fanout` attribute
//! (UG901: on a combinational signal, synthesis replicates the logic that
//! drives it). Used for enables computed in one cycle that reach many
//! registers and block RAMs, where registering them would cost a cycle.
//! See [`crate::fcc_fanout_reg`] for registers.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_keep_reg::verilog_range;

#[derive(LogicBlock, Default)]
pub struct FccFanoutNet<T: Synth> {
    pub x: Signal<In, T>,
    pub y: Signal<Out, T>,
}

impl<T: Synth> Logic for FccFanoutNet<T> {
    fn update(&mut self) {
        self.y.next = self.x.val();
    }

    fn connect(&mut self) {
        self.y.connect();
    }

    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "(* max_fanout = {MAX_FANOUT} *) wire {range}net;\n\
             assign net = x;\n\
             always @(*) begin\n\
             \x20   y = net;\n\
             end\n",
            range = verilog_range(T::BITS)
        ))
    }
}
