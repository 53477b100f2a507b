//! `FccAnyOr`: is any of n flags set? A plain reduction, written by hand
//! (`Verilog::Custom`) so that it is a reduction rather than a chain of ORs.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccAnyOr {
    pub x: Vec<Signal<In, Bit>>,
    pub any: Signal<Out, Bit>,
}

impl FccAnyOr {
    pub fn new(n: usize) -> Self {
        assert!(n >= 1);
        Self {
            x: (0..n).map(|_| Default::default()).collect(),
            any: Default::default(),
        }
    }
}

impl Logic for FccAnyOr {
    fn update(&mut self) {
        self.any.next = self.x.iter().any(|x| x.val());
    }

    fn connect(&mut self) {
        self.any.connect();
    }

    fn hdl(&self) -> Verilog {
        let bits: Vec<String> = (0..self.x.len()).rev().map(|e| format!("x${e}")).collect();
        Verilog::Custom(format!(
            "always @(*) begin\n    any = |{{{}}};\nend\n",
            bits.join(", ")
        ))
    }
}
