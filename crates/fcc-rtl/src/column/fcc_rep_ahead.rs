//! `FccRepAhead`: a stage's correction by the rewrite broadcast, worked out
//! a cycle ahead (docs/column-core.md, item 3). At each step of the
//! pipeline the pixel at B broadcasts and the pixel entering stage `l`
//! takes it; both stood one stage back a cycle before (M2, and the stage
//! before `l`'s), and the shifts between their A1s do not change. So from
//! those two, registered when the pipeline moves (`adv`), held otherwise:
//! `ov`, per group of `span` slots, whether the broadcaster (a labelled
//! pixel) names one the receiver names, in the receiver's rows
//! (`FccRepShift` by the shifts between their A1s, `FccRepGaps`;
//! `FccRepOverlap`).
//! `FccRepSeenAhead` is the same for a receiver whose mask is not known
//! a cycle ahead.

use rust_hdl::prelude::*;

use super::fcc_rep_overlap::FccRepOverlap;
use super::fcc_rep_shift::FccRepShift;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepAhead {
    pub clk: Signal<In, Clock>,
    pub adv: Signal<In, Bit>,
    /// The next broadcaster (now at M2): labelled, its mask.
    pub b_valid: Signal<In, Bit>,
    pub b_mask: Vec<Signal<In, Bit>>,
    /// The next receiver (now a stage before it): its mask, and the shifts
    /// between the two pixels' A1s (`FccRepGaps`).
    pub r_mask: Vec<Signal<In, Bit>>,
    pub d: Signal<In, Bits<3>>,
    pub ov: Vec<Signal<Out, Bit>>,
    shift: FccRepShift,
    overlap: FccRepOverlap,
    ov_q: Vec<DFF<Bit>>,
    zero3: Constant<Bits<3>>,
}

impl FccRepAhead {
    /// `k` rows of `n` run slots, shifts `0 ..= s`, groups of `span`.
    pub fn new(n: usize, k: usize, s: usize, span: usize) -> Self {
        let np = k * n;
        let overlap = FccRepOverlap::new(np, span);
        let g = overlap.ov.len();
        Self {
            clk: Default::default(),
            adv: Default::default(),
            b_valid: Default::default(),
            b_mask: vec_of(np),
            r_mask: vec_of(np),
            d: Default::default(),
            ov: vec_of(g),
            shift: FccRepShift::new(n, k, k, 0, s),
            overlap,
            ov_q: vec_of(g),
            zero3: kb(0),
        }
    }
}

impl Logic for FccRepAhead {
    #[hdl_gen]
    fn update(&mut self) {
        self.shift.a.next = self.d.val();
        self.shift.b.next = self.zero3.val();
        self.overlap.valid.next = self.b_valid.val();
        for j in 0..self.b_mask.len() {
            self.shift.inp[j].next = self.b_mask[j].val();
            self.overlap.mask[j].next = self.r_mask[j].val();
            self.overlap.seen[j].next = self.shift.out[j].val();
        }
        for g in 0..self.ov_q.len() {
            self.ov_q[g].clock.next = self.clk.val();
            self.ov_q[g].d.next = self.ov_q[g].q.val();
            if self.adv.val() {
                self.ov_q[g].d.next = self.overlap.ov[g].val();
            }
            self.ov[g].next = self.ov_q[g].q.val();
        }
    }
}
