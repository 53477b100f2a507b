//! `FccRegW1c`: the sticky single-bit fields of one W1C register (STATUS
//! FRAME_DONE, the ERROR bits): hardware sets bit i (`set[i]`), a write of 1
//! to its field clears it; a set in the cycle of that write wins, `clear`
//! (CONTROL.CLEAR) wins over a set, `rst` over everything.

use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRegW1c {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A write to this register is performed.
    pub we: Signal<In, Bit>,
    /// The held write data.
    pub wdata: Signal<In, Bits<32>>,
    pub set: Vec<Signal<In, Bit>>,
    pub clear: Signal<In, Bit>,
    pub q: Vec<Signal<Out, Bit>>,
    sticky: Vec<DFF<Bit>>,
    mask: Vec<Constant<Bits<32>>>,
    zero32: Constant<Bits<32>>,
    _n: usize,
}

impl FccRegW1c {
    /// One sticky bit per entry of `lsbs`: the bit position of its field.
    pub fn new(lsbs: &[u32]) -> Self {
        assert!(!lsbs.is_empty(), "a W1C register without fields");
        assert!(lsbs.iter().all(|b| *b < 32), "field bits {lsbs:?}");
        let n = lsbs.len();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            we: Default::default(),
            wdata: Default::default(),
            set: (0..n).map(|_| Default::default()).collect(),
            clear: Default::default(),
            q: (0..n).map(|_| Default::default()).collect(),
            sticky: (0..n).map(|_| Default::default()).collect(),
            mask: lsbs.iter().map(|b| kb(1u64 << b)).collect(),
            zero32: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccRegW1c {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..self._n {
            self.sticky[i].clock.next = self.clk.val();
            self.sticky[i].d.next = self.sticky[i].q.val();
            if self.we.val() & ((self.wdata.val() & self.mask[i].val()) != self.zero32.val()) {
                self.sticky[i].d.next = false;
            }
            if self.set[i].val() {
                self.sticky[i].d.next = true;
            }
            if self.clear.val() | self.rst.val() {
                self.sticky[i].d.next = false;
            }
            self.q[i].next = self.sticky[i].q.val();
        }
    }
}
