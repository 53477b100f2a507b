//! `FccMinTree`: the smallest of n 16-bit values among those whose flag is
//! set (all ones when none is), and which position holds it first, as a
//! registered tree: the leaves are registered with the inputs, then one level
//! per stage, so the minimum of the inputs of cycle t shows in cycle t + L + 1
//! (L = ceil(log2 n) levels).
//!
//! The tree is heap-ordered: node i (1 = root) is held in `node[i - 1]`, its
//! children are nodes 2i and 2i + 1, and the leaves are nodes 2^L .. 2^(L+1)-1
//! (leaves past n are never flagged). Each node holds a value and whether any
//! leaf under it is flagged (unflagged leaves hold all ones). The left child
//! wins unless the right one is smaller, or equal and flagged while the left
//! one is not (`left_wins`), so the winner is the first (lowest) flagged
//! position with the minimum, even when that minimum is all ones. Each
//! internal node also holds its winner's position (`winner[i - 1]`): the
//! bottom level picks one of two constants, the levels above one of their
//! children's.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::{clog2, kb, vec_of};

/// Width of a position: the tree takes at most 64 values.
const POS_BITS: usize = 6;

#[derive(LogicBlock)]
pub struct FccMinTree {
    pub clk: Signal<In, Clock>,
    pub hit: Vec<Signal<In, Bit>>,
    pub value: Vec<Signal<In, Bits<16>>>,
    /// The minimum, L + 1 cycles after its inputs.
    pub min: Signal<Out, Bits<16>>,
    /// Position e is the first flagged one whose value is `min` (beside
    /// `min`; none is when no flag was set).
    pub first: Vec<Signal<Out, Bit>>,
    node: Vec<FccFanoutReg<Bits<16>>>,
    flagged: Vec<DFF<Bit>>,
    /// Internal node i takes its left child's value (`left_wins[i - 1]`).
    left_wins: Vec<Signal<Local, Bit>>,
    winner: Vec<DFF<Bits<POS_BITS>>>,
    /// Position numbers, one per leaf.
    position: Vec<Constant<Bits<POS_BITS>>>,
    all_ones: Constant<Bits<16>>,
    _n: usize,
    _leaves: usize,
}

impl FccMinTree {
    pub fn new(n: usize) -> Self {
        assert!(n >= 2);
        let leaves = 1 << clog2(n);
        assert!(
            leaves <= 1 << POS_BITS,
            "{n} values do not fit {POS_BITS}-bit positions"
        );
        Self {
            clk: Default::default(),
            hit: vec_of(n),
            value: vec_of(n),
            min: Default::default(),
            first: vec_of(n),
            node: vec_of(2 * leaves - 1),
            flagged: vec_of(2 * leaves - 1),
            left_wins: vec_of(leaves - 1),
            winner: vec_of(leaves - 1),
            position: (0..leaves).map(|e| kb(e as u64)).collect(),
            all_ones: kb(0xffff),
            _n: n,
            _leaves: leaves,
        }
    }
}

impl Logic for FccMinTree {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..(2 * self._leaves - 1) {
            self.node[i].clock.next = self.clk.val();
            self.flagged[i].clock.next = self.clk.val();
        }
        for i in 0..(self._leaves - 1) {
            self.winner[i].clock.next = self.clk.val();
        }
        // The leaves.
        for lv in self._leaves..(self._leaves + 1) {
            for e in 0..self._n {
                self.node[lv + e - 1].d.next = self.all_ones.val();
                if self.hit[e].val() {
                    self.node[lv + e - 1].d.next = self.value[e].val();
                }
                self.flagged[lv + e - 1].d.next = self.hit[e].val();
            }
            for e in self._n..self._leaves {
                self.node[lv + e - 1].d.next = self.all_ones.val();
                self.flagged[lv + e - 1].d.next = false;
            }
        }
        // Internal node i: children 2i, 2i + 1 at `node[2i - 1]`, `node[2i]`.
        for i in 1..self._leaves {
            self.left_wins[i - 1].next = (self.flagged[2 * i - 1].q.val()
                & !self.flagged[2 * i].q.val())
                | ((self.flagged[2 * i - 1].q.val() == self.flagged[2 * i].q.val())
                    & (self.node[2 * i - 1].q.val() <= self.node[2 * i].q.val()));
            self.node[i - 1].d.next = self.node[2 * i].q.val();
            if self.left_wins[i - 1].val() {
                self.node[i - 1].d.next = self.node[2 * i - 1].q.val();
            }
            self.flagged[i - 1].d.next =
                self.flagged[2 * i - 1].q.val() | self.flagged[2 * i].q.val();
        }
        // The winner's position: the bottom level picks a leaf, the levels
        // above a child's winner.
        for lv in self._leaves..(self._leaves + 1) {
            for i in (self._leaves / 2)..self._leaves {
                self.winner[i - 1].d.next = self.position[2 * i + 1 - lv].val();
                if self.left_wins[i - 1].val() {
                    self.winner[i - 1].d.next = self.position[2 * i - lv].val();
                }
            }
        }
        for i in 1..(self._leaves / 2) {
            self.winner[i - 1].d.next = self.winner[2 * i].q.val();
            if self.left_wins[i - 1].val() {
                self.winner[i - 1].d.next = self.winner[2 * i - 1].q.val();
            }
        }
        self.min.next = self.node[0].q.val();
        for e in 0..self._n {
            self.first[e].next =
                self.flagged[0].q.val() & (self.winner[0].q.val() == self.position[e].val());
        }
    }
}
