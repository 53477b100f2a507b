//! `FccTwoOr`: are at least two of n flags set? Written by hand
//! (`Verilog::Custom`) as three tiers whose every wire is a function of at
//! most six inputs, one LUT6 each, so that synthesis maps it three LUTs deep
//! for up to 60 flags (a balanced tree of two-input nodes maps deeper, through
//! MUXF7 wide-function muxes):
//!
//! * tier 1, per group of six flags: any of them (`a1_g`), at least two of
//!   them (`t1_g`);
//! * tier 2, per group of five tier-1 groups: any of them (`a2_h`), at least
//!   two of the groups have a flag (`u2_h`), some group has two (`o2_h`);
//! * the root: any `u2` or `o2`, or at least two tier-2 groups have a flag.

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

/// Flags per tier-1 group, and tier-1 groups per tier-2 group.
const TIER1_GROUP: usize = 6;
const TIER2_GROUP: usize = 5;

/// "Any of" the terms, as a Verilog expression.
fn any_of(terms: &[String]) -> String {
    match terms {
        [one] => one.clone(),
        _ => format!("|{{{}}}", terms.join(", ")),
    }
}

/// "At least two of" the terms (two or more), as a Verilog expression.
fn two_of(terms: &[String]) -> String {
    let mut pairs = vec![];
    for (i, a) in terms.iter().enumerate() {
        for b in &terms[i + 1..] {
            pairs.push(format!("({a} & {b})"));
        }
    }
    pairs.join(" | ")
}

/// The identifiers an expression reads.
fn names(expr: &str) -> impl Iterator<Item = &str> {
    expr.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '$'))
        .filter(|t| !t.is_empty())
}

impl Logic for FccTwoOr {
    fn update(&mut self) {
        self.two.next = self.x.iter().filter(|x| x.val()).count() >= 2;
    }

    fn connect(&mut self) {
        self.two.connect();
    }

    fn hdl(&self) -> Verilog {
        let leaves: Vec<String> = (0..self.x.len()).map(|e| format!("x${e}")).collect();
        // (name, expression), each reading only the flags and earlier wires.
        let mut wires: Vec<(String, String)> = vec![];
        let mut tier1 = vec![];
        for (g, group) in leaves.chunks(TIER1_GROUP).enumerate() {
            let any = format!("a1_{g}");
            wires.push((any.clone(), any_of(group)));
            let two = (group.len() >= 2).then(|| {
                let two = format!("t1_{g}");
                wires.push((two.clone(), two_of(group)));
                two
            });
            tier1.push((any, two));
        }
        let mut root_terms = vec![];
        let mut tier2_any = vec![];
        for (h, group) in tier1.chunks(TIER2_GROUP).enumerate() {
            let anys: Vec<String> = group.iter().map(|(any, _)| any.clone()).collect();
            let any = format!("a2_{h}");
            wires.push((any.clone(), any_of(&anys)));
            tier2_any.push(any);
            if anys.len() >= 2 {
                let two = format!("u2_{h}");
                wires.push((two.clone(), two_of(&anys)));
                root_terms.push(two);
            }
            let twos: Vec<String> = group.iter().filter_map(|(_, two)| two.clone()).collect();
            if !twos.is_empty() {
                let some = format!("o2_{h}");
                wires.push((some.clone(), any_of(&twos)));
                root_terms.push(some);
            }
        }
        if tier2_any.len() >= 2 {
            root_terms.push(format!("({})", two_of(&tier2_any)));
        }
        let root = any_of(&root_terms);
        // Only the wires the root reads, directly or through other wires (a
        // single group's "any" is read by nobody).
        let mut used: std::collections::HashSet<&str> = names(&root).collect();
        for (name, expr) in wires.iter().rev() {
            if used.contains(name.as_str()) {
                used.extend(names(expr));
            }
        }
        let mut s = String::new();
        for (name, expr) in &wires {
            if used.contains(name.as_str()) {
                s.push_str(&format!("wire {name} = {expr};\n"));
            }
        }
        s.push_str(&format!("always @(*) begin\n    two = {root};\nend\n"));
        Verilog::Custom(s)
    }
}
