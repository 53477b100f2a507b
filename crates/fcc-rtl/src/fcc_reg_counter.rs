//! `FccRegCounter`: a read-only event counter (FRAME_COUNT, wraps): `inc`
//! is its addend (no enable on the counter), `clear` (CONTROL.CLEAR) and
//! `rst` zero it.

use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRegCounter {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub inc: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub q: Signal<Out, Bits<32>>,
    count: DFF<Bits<32>>,
    addend: Signal<Local, Bits<32>>,
    one32: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
}

impl FccRegCounter {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inc: Default::default(),
            clear: Default::default(),
            q: Default::default(),
            count: Default::default(),
            addend: Default::default(),
            one32: kb(1),
            zero32: kb(0),
        }
    }
}

impl Default for FccRegCounter {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccRegCounter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, count);
        self.addend.next = self.zero32.val();
        if self.inc.val() {
            self.addend.next = self.one32.val();
        }
        self.count.d.next = self.count.q.val() + self.addend.val();
        if self.clear.val() | self.rst.val() {
            self.count.d.next = self.zero32.val();
        }
        self.q.next = self.count.q.val();
    }
}
