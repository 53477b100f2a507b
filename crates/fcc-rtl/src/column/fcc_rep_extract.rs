//! `FccRepExtract`: a pixel's joins, one a cycle, then the pixel
//! (docs/column-core.md, item 3). At B the pixel's smallest representative
//! `m` is known and the window still holds every earlier pixel's rewrite
//! but not its own: `b_mask` says which window positions it names, `b_val`
//! holds the values. Each distinct named value `x` other than `m` is one
//! join, `(x, m)`; at the last column the ring check's pair is one more.
//!
//! `FccRepSieve` finds the first join and flags the rest in four stages
//! (C to F: flags, the first flag, its value, its equals cleared), so that
//! a first flag and its value never share a cycle; `FccRepReplay` (R)
//! sends it with the pixel and holds the stages (`go` low) while it sends
//! the rest. This block is wiring.

use rust_hdl::prelude::*;

use super::fcc_rep_replay::FccRepReplay;
use super::fcc_rep_sieve::FccRepSieve;
use super::RunPix;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepExtract {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The pixel at B (captured on `go`).
    pub b_pix: Signal<In, RunPix>,
    pub b_mask: Vec<Signal<In, Bit>>,
    pub b_val: Vec<Signal<In, Bits<16>>>,
    pub b_m: Signal<In, Bits<16>>,
    /// The stages before R, and every one before B, move this cycle.
    pub go: Signal<Out, Bit>,
    pub out: Signal<Out, RunPix>,
    /// The pixel out last has joins still to come after this cycle's.
    pub more: Signal<Out, Bit>,
    pub j_valid: Signal<Out, Bit>,
    pub j_a: Signal<Out, Bits<16>>,
    pub j_b: Signal<Out, Bits<16>>,
    pub j_under: Signal<Out, Bit>,
    /// The join is the ring check's.
    pub j_seam: Signal<Out, Bit>,
    sieve: FccRepSieve,
    replay: FccRepReplay,
}

impl FccRepExtract {
    /// `n` window positions.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            b_pix: Default::default(),
            b_mask: vec_of(n),
            b_val: vec_of(n),
            b_m: Default::default(),
            go: Default::default(),
            out: Default::default(),
            more: Default::default(),
            j_valid: Default::default(),
            j_a: Default::default(),
            j_b: Default::default(),
            j_under: Default::default(),
            j_seam: Default::default(),
            sieve: FccRepSieve::new(n),
            replay: FccRepReplay::new(n),
        }
    }
}

impl Logic for FccRepExtract {
    #[hdl_gen]
    fn update(&mut self) {
        self.sieve.clk.next = self.clk.val();
        self.sieve.rst.next = self.rst.val();
        self.sieve.go.next = self.replay.go.val();
        self.sieve.b_pix.next = self.b_pix.val();
        self.sieve.b_m.next = self.b_m.val();
        self.replay.clk.next = self.clk.val();
        self.replay.rst.next = self.rst.val();
        self.replay.f_pix.next = self.sieve.pix.val();
        self.replay.f_m.next = self.sieve.m.val();
        self.replay.f_x.next = self.sieve.x.val();
        self.replay.f_any.next = self.sieve.any.val();
        self.replay.f_more.next = self.sieve.more.val();
        for b in 0..self.b_mask.len() {
            self.sieve.b_mask[b].next = self.b_mask[b].val();
            self.sieve.b_val[b].next = self.b_val[b].val();
            self.replay.f_left[b].next = self.sieve.left[b].val();
            self.replay.f_val[b].next = self.sieve.val[b].val();
        }
        self.go.next = self.replay.go.val();
        self.more.next = self.replay.more.val();
        self.out.next = self.replay.out.val();
        self.j_valid.next = self.replay.j_valid.val();
        self.j_a.next = self.replay.j_a.val();
        self.j_under.next = self.replay.under.val();
        self.j_seam.next = self.replay.seam.val();
        self.j_b.next = self.replay.j_b.val();
    }
}
