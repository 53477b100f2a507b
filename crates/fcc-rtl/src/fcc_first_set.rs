//! `FccFirstSet`: `first[e]` = `x[e]` is the first set flag of n, given
//! `gany[g]` = any flag of group g is set (groups of `GROUP`, as
//! `FccGroupOr` makes them). A flag is first when no earlier flag of its
//! group and no earlier group is set: two short reductions, whatever n.
//!
//! Written by hand (`Verilog::Custom`) for the same reason as `FccPrefixOr`.

use rust_hdl::prelude::*;

use crate::fcc_group_or::{groups, GROUP};

#[derive(LogicBlock)]
pub struct FccFirstSet {
    pub x: Vec<Signal<In, Bit>>,
    pub gany: Vec<Signal<In, Bit>>,
    pub first: Vec<Signal<Out, Bit>>,
}

impl FccFirstSet {
    pub fn new(n: usize) -> Self {
        assert!(n >= 1);
        Self {
            x: (0..n).map(|_| Default::default()).collect(),
            gany: (0..groups(n)).map(|_| Default::default()).collect(),
            first: (0..n).map(|_| Default::default()).collect(),
        }
    }
}

impl Logic for FccFirstSet {
    fn update(&mut self) {
        for e in 0..self.x.len() {
            let g = e / GROUP;
            let earlier_group = self.gany.iter().take(g).any(|a| a.val());
            let earlier_here = self.x[g * GROUP..e].iter().any(|x| x.val());
            self.first[e].next = self.x[e].val() & !earlier_group & !earlier_here;
        }
    }

    fn connect(&mut self) {
        for f in self.first.iter_mut() {
            f.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        let n = self.x.len();
        let gs = self.gany.len();
        let mut s = String::new();
        if gs > 0 {
            s.push_str(&format!(
                "// The last group comes after every other, so nothing reads its flag.\n\
                 /* verilator lint_off UNUSEDSIGNAL */\n\
                 wire unused_ok = gany${};\n\
                 /* verilator lint_on UNUSEDSIGNAL */\n",
                gs - 1
            ));
        }
        s.push_str("always @(*) begin\n");
        for e in 0..n {
            let g = e / GROUP;
            let mut earlier: Vec<String> = (0..g).rev().map(|i| format!("gany${i}")).collect();
            earlier.extend((g * GROUP..e).rev().map(|i| format!("x${i}")));
            if earlier.is_empty() {
                s.push_str(&format!("    first${e} = x${e};\n"));
            } else {
                s.push_str(&format!(
                    "    first${e} = x${e} & ~(|{{{}}});\n",
                    earlier.join(", ")
                ));
            }
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}
