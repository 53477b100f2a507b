//! `FccHoldBank`: values held in a pipeline stage of `FccRowRoots` (a
//! stage's hits and the joins it flags; the table row read for the
//! window's labels): they take `d` unless `hold`.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccHoldBank<T: Synth> {
    pub clk: Signal<In, Clock>,
    pub hold: Signal<In, Bit>,
    pub d: Vec<Signal<In, T>>,
    pub q: Vec<Signal<Out, T>>,
    value: Vec<DFF<T>>,
}

impl<T: Synth> FccHoldBank<T> {
    /// `n` values.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            d: vec_of(n),
            q: vec_of(n),
            value: vec_of(n),
        }
    }
}

impl<T: Synth> Logic for FccHoldBank<T> {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self.value.len() {
            self.value[e].clock.next = self.clk.val();
            self.value[e].d.next = self.d[e].val();
            if self.hold.val() {
                self.value[e].d.next = self.value[e].q.val();
            }
        }
        for e in 0..self.value.len() {
            self.q[e].next = self.value[e].q.val();
        }
    }
}
