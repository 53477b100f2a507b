//! `FccGroupOr`: for n flags taken in groups of `GROUP` (the last one may be
//! shorter), `any[g]` = any flag of group g is set. Written by hand
//! (`Verilog::Custom`) like `FccAnyOr`, each group a reduction of its own.
//!
//! Registered, the group flags let `FccFirstSet` find the first set flag of
//! many in a few LUT levels: synthesis maps a prefix OR over all the flags
//! as a chain (the smallest circuit), whatever the source says.

use rust_hdl::prelude::*;

/// Flags per group.
pub const GROUP: usize = 8;

/// Groups of `GROUP` flags that hold n flags.
pub fn groups(n: usize) -> usize {
    n.div_ceil(GROUP)
}

#[derive(LogicBlock)]
pub struct FccGroupOr {
    pub x: Vec<Signal<In, Bit>>,
    pub any: Vec<Signal<Out, Bit>>,
}

impl FccGroupOr {
    pub fn new(n: usize) -> Self {
        assert!(n >= 1);
        Self {
            x: (0..n).map(|_| Default::default()).collect(),
            any: (0..groups(n)).map(|_| Default::default()).collect(),
        }
    }
}

impl Logic for FccGroupOr {
    fn update(&mut self) {
        for (g, any) in self.any.iter_mut().enumerate() {
            any.next = self.x.iter().skip(g * GROUP).take(GROUP).any(|x| x.val());
        }
    }

    fn connect(&mut self) {
        for a in self.any.iter_mut() {
            a.connect();
        }
    }

    fn hdl(&self) -> Verilog {
        let n = self.x.len();
        let mut s = String::from("always @(*) begin\n");
        for g in 0..self.any.len() {
            let bits: Vec<String> = (g * GROUP..n.min((g + 1) * GROUP))
                .rev()
                .map(|e| format!("x${e}"))
                .collect();
            s.push_str(&format!("    any${g} = |{{{}}};\n", bits.join(", ")));
        }
        s.push_str("end\n");
        Verilog::Custom(s)
    }
}
