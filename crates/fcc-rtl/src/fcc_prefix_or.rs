//! `FccPrefixOr`: for n flags, `pre[e]` = any of `x[0 .. e-1]`, through a
//! log-depth (Kogge-Stone) network. (With one more input held at 0, the last
//! output is "any of them".)
//!
//! Written by hand (`Verilog::Custom`) because a chain of ORs written in
//! rust-hdl stays a chain after synthesis: its depth grows with n, this one
//! with log2(n).

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
        let n = self.x.len();
        let m = n - 1;
        let bits: Vec<String> = (0..m).rev().map(|e| format!("x${e}")).collect();
        let mut s = format!(
            "// The last flag comes after every prefix, so nothing reads it.\n\
             /* verilator lint_off UNUSEDSIGNAL */\n\
             wire unused_ok = x${m};\n\
             /* verilator lint_on UNUSEDSIGNAL */\n"
        );
        if m == 1 {
            s.push_str("wire p0 = x$0;\n");
        } else {
            s.push_str(&format!(
                "wire [{}:0] p0 = {{{}}};\n",
                m - 1,
                bits.join(", ")
            ));
        }
        let mut level = 0;
        while (1usize << level) < m {
            s.push_str(&format!(
                "wire [{top}:0] p{next} = p{level} | {{p{level}[{low}:0], {w}'d0}};\n",
                top = m - 1,
                next = level + 1,
                low = m - 1 - (1 << level),
                w = 1 << level,
            ));
            level += 1;
        }
        s.push_str("always @(*) begin\n    pre$0 = 1'b0;\n");
        for e in 1..n {
            if m == 1 {
                s.push_str(&format!("    pre${e} = p{level};\n"));
            } else {
                s.push_str(&format!("    pre${e} = p{level}[{}];\n", e - 1));
            }
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}
