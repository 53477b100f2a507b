//! `FccBitBank`: one pipeline stage's flags in `FccRowRoots` (its hits, and
//! which joins still cross clusters): they take `d` unless `hold`.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccBitBank {
    pub clk: Signal<In, Clock>,
    pub hold: Signal<In, Bit>,
    pub d: Vec<Signal<In, Bit>>,
    pub q: Vec<Signal<Out, Bit>>,
    bit: Vec<DFF<Bit>>,
}

impl FccBitBank {
    /// `n` flags.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            d: vec_of(n),
            q: vec_of(n),
            bit: vec_of(n),
        }
    }
}

impl Logic for FccBitBank {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self.bit.len() {
            self.bit[e].clock.next = self.clk.val();
            self.bit[e].d.next = self.d[e].val();
            if self.hold.val() {
                self.bit[e].d.next = self.bit[e].q.val();
            }
        }
        for e in 0..self.bit.len() {
            self.q[e].next = self.bit[e].q.val();
        }
    }
}
