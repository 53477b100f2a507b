//! `FccTwoOr`: are at least two of n flags set? A balanced tree in which each
//! node knows "any" and "at least two" of its leaves, written by hand
//! (`Verilog::Custom`) so that its depth grows with log2(n), as
//! `FccPrefixOr` does.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccTwoOr {
    pub x: Vec<Signal<In, Bit>>,
    pub two: Signal<Out, Bit>,
}

impl FccTwoOr {
    pub fn new(n: usize) -> Self {
        assert!(n >= 2);
        Self {
            x: (0..n).map(|_| Default::default()).collect(),
            two: Default::default(),
        }
    }
}

/// Emits the wires of the subtree over leaves `lo..hi`; returns the names
/// of its "any" and "at least two" wires (`None`: a single leaf has no two).
/// The root's "any" is a by-product that nothing reads.
fn subtree(lo: usize, hi: usize, root: bool, s: &mut String) -> (String, Option<String>) {
    if hi - lo == 1 {
        return (format!("x${lo}"), None);
    }
    let mid = lo + (hi - lo) / 2;
    let (al, tl) = subtree(lo, mid, false, s);
    let (ar, tr) = subtree(mid, hi, false, s);
    let any = format!("a_{lo}_{hi}");
    let two = format!("t_{lo}_{hi}");
    let wire = format!("wire {any} = {al} | {ar};\n");
    if root {
        s.push_str("/* verilator lint_off UNUSEDSIGNAL */\n");
        s.push_str(&wire);
        s.push_str("/* verilator lint_on UNUSEDSIGNAL */\n");
    } else {
        s.push_str(&wire);
    }
    let mut terms = vec![format!("({al} & {ar})")];
    terms.extend(tl);
    terms.extend(tr);
    s.push_str(&format!("wire {two} = {};\n", terms.join(" | ")));
    (any, Some(two))
}

impl Logic for FccTwoOr {
    fn update(&mut self) {
        self.two.next = self.x.iter().filter(|x| x.val()).count() >= 2;
    }

    fn connect(&mut self) {
        self.two.connect();
    }

    fn hdl(&self) -> Verilog {
        let mut s = String::new();
        let (_, two) = subtree(0, self.x.len(), true, &mut s);
        let two = two.expect("two or more leaves have a \"two\"");
        s.push_str(&format!("always @(*) begin\n    two = {two};\nend\n"));
        Verilog::Custom(s)
    }
}
