//! `FccRepTake`: the value of the run slot `first` names, one-hot
//! (combinational; docs/column-core.md, item 3): an OR of the values
//! masked by it, 0 when it names none.

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepTake {
    pub first: Vec<Signal<In, Bit>>,
    pub val: Vec<Signal<In, Bits<16>>>,
    pub x: Signal<Out, Bits<16>>,
    zero16: Constant<Bits<16>>,
}

impl FccRepTake {
    /// `n` run slots.
    pub fn new(n: usize) -> Self {
        Self {
            first: vec_of(n),
            val: vec_of(n),
            x: Default::default(),
            zero16: kb(0),
        }
    }
}

impl Logic for FccRepTake {
    #[hdl_gen]
    fn update(&mut self) {
        self.x.next = self.zero16.val();
        for b in 0..self.first.len() {
            if self.first[b].val() {
                self.x.next = self.x.val() | self.val[b].val();
            }
        }
    }
}
