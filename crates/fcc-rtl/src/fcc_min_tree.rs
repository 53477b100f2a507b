//! `FccMinTree`: the smallest of n 16-bit values among those whose flag is
//! set (all ones when none is), as a registered tree: the leaves are
//! registered with the inputs, then one level per stage, so the minimum of
//! the inputs of cycle t shows in cycle t + L + 1 (L = ceil(log2 n) levels).
//!
//! The tree is heap-ordered: node i (1 = root) is held in `node[i - 1]`, its
//! children are nodes 2i and 2i + 1, and the leaves are nodes 2^L .. 2^(L+1)-1
//! (leaves past n hold all ones).

use rust_hdl::prelude::*;

use crate::types::{clog2, kb, vec_of};

#[derive(LogicBlock)]
pub struct FccMinTree {
    pub clk: Signal<In, Clock>,
    pub hit: Vec<Signal<In, Bit>>,
    pub value: Vec<Signal<In, Bits<16>>>,
    /// The minimum, L + 1 cycles after its inputs.
    pub min: Signal<Out, Bits<16>>,
    node: Vec<DFF<Bits<16>>>,
    all_ones: Constant<Bits<16>>,
    _n: usize,
    _leaves: usize,
}

impl FccMinTree {
    pub fn new(n: usize) -> Self {
        assert!(n >= 2);
        let leaves = 1 << clog2(n);
        Self {
            clk: Default::default(),
            hit: vec_of(n),
            value: vec_of(n),
            min: Default::default(),
            node: vec_of(2 * leaves - 1),
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
        }
        for lv in self._leaves..(self._leaves + 1) {
            for e in 0..self._n {
                self.node[lv + e - 1].d.next = self.all_ones.val();
                if self.hit[e].val() {
                    self.node[lv + e - 1].d.next = self.value[e].val();
                }
            }
            for e in self._n..self._leaves {
                self.node[lv + e - 1].d.next = self.all_ones.val();
            }
        }
        for i in 1..self._leaves {
            self.node[i - 1].d.next = self.node[2 * i].q.val();
            if self.node[2 * i - 1].q.val() <= self.node[2 * i].q.val() {
                self.node[i - 1].d.next = self.node[2 * i - 1].q.val();
            }
        }
        self.min.next = self.node[0].q.val();
    }
}
