//! `FccPrefixOr`: for n flags, `pre[e]` = any of `x[0 .. e-1]`.
//!
//! Written by hand (`Verilog::Custom`) because a chain of ORs written in
//! rust-hdl stays a chain after synthesis, its depth growing with n. Here each
//! prefix is a reduction of its own, which synthesis shares and maps as a
//! tree (with one more input held at 0, the last output is "any of them").

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccPrefixOr {
    pub x: Vec<Signal<In, Bit>>,
    pub pre: Vec<Signal<Out, Bit>>,
}

impl FccPrefixOr {
    pub fn new(n: usize) -> Self {
        assert!(n >= 2);
        Self {
            x: (0..n).map(|_| Default::default()).collect(),
            pre: (0..n).map(|_| Default::default()).collect(),
        }
    }
}

impl Logic for FccPrefixOr {
    fn update(&mut self) {
        let mut acc = false;
        for (x, pre) in self.x.iter().zip(self.pre.iter_mut()) {
            pre.next = acc;
            acc |= x.val();
        }
    }

    fn connect(&mut self) {
        for p in self.pre.iter_mut() {
            p.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        // Each prefix is a reduction of its own; synthesis shares the common
        // parts and maps each to a tree of LUT6s (depth log6 of its width).
        let n = self.x.len();
        let m = n - 1;
        let mut s = format!(
            "// The last flag comes after every prefix, so nothing reads it.\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             wire unused_ok = x${m};\n\
             /* verilator lint_on UNUSEDSIGNAL */\n\
             always @(*) begin\n    pre$0 = 1'b0;\n"
        );
        for e in 1..n {
            let bits: Vec<String> = (0..e).rev().map(|i| format!("x${i}")).collect();
            s.push_str(&format!("    pre${e} = |{{{}}};\n", bits.join(", ")));
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}
