//! `FccPick`: the value whose flag is set, of n 16-bit values with at most one
//! flag set (0 when none is), through a balanced tree of ORs.
//!
//! Written by hand (`Verilog::Custom`) for the same reason as `FccPrefixOr`:
//! an OR chain written in rust-hdl keeps its depth through synthesis. The
//! flags are named `keep` nets: synthesis still maps the leaves as it likes
//! (a flag that is logic of several flip-flops is folded into them), but the
//! Yosys mapping of the serializer's pick came out about 30 LUTs smaller at
//! K = 9 with them.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccPick {
    pub sel: Vec<Signal<In, Bit>>,
    pub v: Vec<Signal<In, Bits<16>>>,
    pub o: Signal<Out, Bits<16>>,
}

impl FccPick {
    pub fn new(n: usize) -> Self {
        assert!(n >= 1);
        Self {
            sel: (0..n).map(|_| Default::default()).collect(),
            v: (0..n).map(|_| Default::default()).collect(),
            o: Default::default(),
        }
    }
}

impl Logic for FccPick {
    fn update(&mut self) {
        let mut acc = Bits::<16>::default();
        for (s, v) in self.sel.iter().zip(self.v.iter()) {
            if s.val() {
                acc = acc | v.val();
            }
        }
        self.o.next = acc;
    }

    fn connect(&mut self) {
        self.o.connect();
    }

    fn hdl(&self) -> Verilog {
        let n = self.sel.len();
        let mut s = String::new();
        let mut terms: Vec<String> = (0..n)
            .map(|e| {
                let w = format!("t0_{e}");
                s.push_str(&format!("(* keep *) wire s_{e} = sel${e};\n"));
                s.push_str(&format!("wire [15:0] {w} = {{16{{s_{e}}}}} & v${e};\n"));
                w
            })
            .collect();
        let mut level = 0;
        while terms.len() > 1 {
            level += 1;
            let mut next = vec![];
            for (i, pair) in terms.chunks(2).enumerate() {
                let w = format!("t{level}_{i}");
                if pair.len() == 2 {
                    s.push_str(&format!("wire [15:0] {w} = {} | {};\n", pair[0], pair[1]));
                } else {
                    s.push_str(&format!("wire [15:0] {w} = {};\n", pair[0]));
                }
                next.push(w);
            }
            terms = next;
        }
        s.push_str(&format!("always @(*) begin\n    o = {};\nend\n", terms[0]));
        Verilog::Custom(s)
    }
}
