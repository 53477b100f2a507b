//! `FccSetAhead`: two ops of `FccSetQueue`'s FIFO held ahead in flip-flops,
//! so that `FccLabelSets` can take an op in the cycle after the one before
//! (two are in flight there) while the FIFO shows one every other cycle.
//! The FIFO's head is taken whenever fewer than two are held (`f_take`,
//! from flip-flops: not waiting on this cycle's `pop`), the older shows
//! (`h_valid`, `h_op`) and `pop` takes it.

use rust_hdl::prelude::*;

use super::fcc_set_queue::SetQOp;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccSetAhead {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub f_valid: Signal<In, Bit>,
    pub f_op: Signal<In, SetQOp>,
    pub f_take: Signal<Out, Bit>,
    pub h_valid: Signal<Out, Bit>,
    pub h_op: Signal<Out, SetQOp>,
    pub pop: Signal<In, Bit>,
    e0: DFF<SetQOp>,
    e1: DFF<SetQOp>,
    /// Ops held: 0, 1 or 2.
    held: DFF<Bits<2>>,
    zero: Constant<Bits<2>>,
    one: Constant<Bits<2>>,
    two: Constant<Bits<2>>,
}

impl Default for FccSetAhead {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            f_valid: Default::default(),
            f_op: Default::default(),
            f_take: Default::default(),
            h_valid: Default::default(),
            h_op: Default::default(),
            pop: Default::default(),
            e0: Default::default(),
            e1: Default::default(),
            held: Default::default(),
            zero: kb(0),
            one: kb(1),
            two: kb(2),
        }
    }
}

impl Logic for FccSetAhead {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, e0, e1, held);
        self.f_take.next = self.f_valid.val() & (self.held.q.val() != self.two.val());
        self.h_valid.next = self.held.q.val() != self.zero.val();
        self.h_op.next = self.e0.q.val();
        // A take goes behind what stays; a pop moves the second up.
        if self.pop.val() {
            self.e0.d.next = self.e1.q.val();
            self.held.d.next = self.held.q.val() - self.one.val();
        }
        if self.f_take.val() {
            self.held.d.next = self.held.q.val() + self.one.val();
            if self.pop.val() {
                self.held.d.next = self.held.q.val();
            }
            if (self.held.q.val() == self.zero.val()) | self.pop.val() {
                self.e0.d.next = self.f_op.val();
            } else {
                self.e1.d.next = self.f_op.val();
            }
        }
        if self.rst.val() {
            self.held.d.next = self.zero.val();
        }
    }
}
