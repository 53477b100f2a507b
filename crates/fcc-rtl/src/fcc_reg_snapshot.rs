//! `FccRegSnapshot`: a read-only status field that holds a value of the
//! core latched at the frame's end (CLUSTERS, PROVISIONAL, UNLABELLED, the
//! FRAME_FLAGS bits, JOINS, GEAR_STALLS): `latch` takes `value`, `clear`
//! (CONTROL.CLEAR, wins over `latch`) and `rst` zero it.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct FccRegSnapshot<T: Synth> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub latch: Signal<In, Bit>,
    pub value: Signal<In, T>,
    pub clear: Signal<In, Bit>,
    pub q: Signal<Out, T>,
    held: DFF<T>,
    zero: Constant<T>,
}

impl<T: Synth> Default for FccRegSnapshot<T> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            latch: Default::default(),
            value: Default::default(),
            clear: Default::default(),
            q: Default::default(),
            held: Default::default(),
            zero: Constant::new(T::default()),
        }
    }
}

impl<T: Synth> Logic for FccRegSnapshot<T> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, held);
        if self.latch.val() {
            self.held.d.next = self.value.val();
        }
        if self.clear.val() | self.rst.val() {
            self.held.d.next = self.zero.val();
        }
        self.q.next = self.held.q.val();
    }
}
