//! `FccLabelBank`: labels held in a pipeline stage of `FccRowRoots` (the
//! table row read for the window): they take `d` unless `hold`.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccLabelBank {
    pub clk: Signal<In, Clock>,
    pub hold: Signal<In, Bit>,
    pub d: Vec<Signal<In, Bits<16>>>,
    pub q: Vec<Signal<Out, Bits<16>>>,
    word: Vec<DFF<Bits<16>>>,
}

impl FccLabelBank {
    /// `n` labels.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            d: vec_of(n),
            q: vec_of(n),
            word: vec_of(n),
        }
    }
}

impl Logic for FccLabelBank {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self.word.len() {
            self.word[e].clock.next = self.clk.val();
            self.word[e].d.next = self.d[e].val();
            if self.hold.val() {
                self.word[e].d.next = self.word[e].q.val();
            }
        }
        for e in 0..self.word.len() {
            self.q[e].next = self.word[e].q.val();
        }
    }
}
