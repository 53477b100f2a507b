//! `FccKeepReg`: a flip-flop that synthesis must keep apart from its
//! equivalents.
//!
//! A net with many loads is split by giving each small group of loads its own
//! copy of the register that drives it (same input, same reset, same
//! cycle). Synthesis tools merge such equivalent registers back into one
//! (Yosys `opt_merge`, Vivado's equivalent-register removal), so this block is
//! written as `Verilog::Custom` with `keep` on the register (Vivado) and on its
//! process (Yosys takes the attribute onto the flip-flop cell). In every other
//! respect it is rust-hdl's `DFF`: `q` follows `d` on the rising clock edge,
//! and powers up at `T::default()`.
//!
//! A copy whose loads may still exceed the fanout target (a reset copy that
//! serves a whole block) is built with [`FccKeepReg::with_max_fanout`]: the
//! register carries Vivado's `max_fanout` instead of `keep` (Vivado's
//! `keep` would forbid the replication): Vivado may merge such copies, then
//! replicates the register until no copy drives more than that many loads.
//! Yosys ignores `max_fanout` and keeps the copies apart.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccKeepReg<T: Synth> {
    pub clock: Signal<In, Clock>,
    pub d: Signal<In, T>,
    pub q: Signal<Out, T>,
    _max_fanout: Option<usize>,
}

impl<T: Synth> Default for FccKeepReg<T> {
    fn default() -> Self {
        Self {
            clock: Default::default(),
            d: Default::default(),
            q: Default::default(),
            _max_fanout: None,
        }
    }
}

impl<T: Synth> FccKeepReg<T> {
    /// A copy that Vivado may replicate until no copy drives more than
    /// `loads` loads.
    pub fn with_max_fanout(loads: usize) -> Self {
        assert!(loads >= 2, "max_fanout {loads} is below 2");
        Self {
            _max_fanout: Some(loads),
            ..Default::default()
        }
    }
}

impl<T: Synth> Logic for FccKeepReg<T> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.q.next = self.d.val();
        }
    }

    fn connect(&mut self) {
        self.q.connect();
    }

    fn hdl(&self) -> Verilog {
        match self._max_fanout {
            Some(n) => {
                register_verilog::<T>(&format!("max_fanout = {n}"), "(* keep = \"true\" *) ")
            }
            None => register_verilog::<T>("keep = \"true\"", "(* keep = \"true\" *) "),
        }
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "keep_reg".into(),
            clock: "clock".into(),
            inputs: vec!["d".into()],
            outputs: vec!["q".into()],
        }]
    }
}

/// The Verilog of a rust-hdl `DFF` of `T` written by hand: the register
/// `held` carries `reg_attrs`, its clocked process starts with
/// `process_prefix` (an attribute or nothing), `q` follows `held`.
pub(crate) fn register_verilog<T: Synth>(reg_attrs: &str, process_prefix: &str) -> Verilog {
    Verilog::Custom(format!(
        "(* {reg_attrs} *) reg {range}held;\n\
         initial begin\n\
         \x20   held = {init:x};\n\
         end\n\
         {process_prefix}always @(posedge clock) begin\n\
         \x20   held <= d;\n\
         end\n\
         always @(*) begin\n\
         \x20   q = held;\n\
         end\n",
        range = verilog_range(T::BITS),
        init = T::default().verilog()
    ))
}

/// A declaration's range for `bits` bits (`[bits-1:0] `, nothing for one).
pub(crate) fn verilog_range(bits: usize) -> String {
    if bits == 1 {
        String::new()
    } else {
        format!("[{}:0] ", bits - 1)
    }
}
