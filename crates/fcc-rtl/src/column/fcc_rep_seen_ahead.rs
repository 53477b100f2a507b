//! `FccRepSeenAhead`: the rewrite broadcast seen from a receiver's rows,
//! worked out a cycle ahead (docs/column-core.md, item 3), for the tree's
//! first stage, whose receiver's mask (A1's) is known only late in the
//! cycle before: `seen`, the next broadcaster's mask (a labelled pixel's,
//! now at M2) shifted by its `sh` (the receiver's, at A1, is 0, and both
//! gain the same shift as they move), registered when the pipeline moves
//! (`adv`). `FccRepAhead` does the whole overlap where it can.

use rust_hdl::prelude::*;

use super::fcc_rep_shift::FccRepShift;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepSeenAhead {
    pub clk: Signal<In, Clock>,
    pub adv: Signal<In, Bit>,
    pub b_valid: Signal<In, Bit>,
    pub b_mask: Vec<Signal<In, Bit>>,
    pub b_sh: Signal<In, Bits<3>>,
    pub seen: Vec<Signal<Out, Bit>>,
    shift: FccRepShift,
    seen_q: Vec<DFF<Bit>>,
    zero3: Constant<Bits<3>>,
}

impl FccRepSeenAhead {
    /// `k` rows of `n` run slots, shifts `0 ..= s`.
    pub fn new(n: usize, k: usize, s: usize) -> Self {
        let np = k * n;
        Self {
            clk: Default::default(),
            adv: Default::default(),
            b_valid: Default::default(),
            b_mask: vec_of(np),
            b_sh: Default::default(),
            seen: vec_of(np),
            shift: FccRepShift::new(n, k, k, 0, s),
            seen_q: vec_of(np),
            zero3: kb(0),
        }
    }
}

impl Logic for FccRepSeenAhead {
    #[hdl_gen]
    fn update(&mut self) {
        self.shift.a.next = self.b_sh.val();
        self.shift.b.next = self.zero3.val();
        for j in 0..self.seen_q.len() {
            self.shift.inp[j].next = self.b_mask[j].val();
            self.seen_q[j].clock.next = self.clk.val();
            self.seen_q[j].d.next = self.seen_q[j].q.val();
            if self.adv.val() {
                self.seen_q[j].d.next = self.b_valid.val() & self.shift.out[j].val();
            }
            self.seen[j].next = self.seen_q[j].q.val();
        }
    }
}
