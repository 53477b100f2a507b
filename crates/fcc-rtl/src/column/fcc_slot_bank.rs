//! `FccSlotBank`: one pipeline stage's record slots in `FccRowRoots`, kept
//! current under the merges (its flags are in an `FccHoldBank`).
//!
//! A merge of slot `a` into `b` is broadcast for one cycle (`rw_*`); every
//! register holding a slot rewrites `a` to `b` at the edge that ends it.
//! `eff` is the bank's slots with the merge being broadcast applied (what
//! they are after the edge), combinational. The bank takes `d` (which must
//! be current, an `eff` of the stage before) unless `hold`, when it keeps
//! its slots, rewritten. (`hold` rather than a load: a flip-flop's output
//! as it is, so that Verilator sees no loop through the stages.)
//!
//! A `late` bank takes slots looked up combinationally in the stage before
//! (`FccRootMatch`), which miss the merge broadcast in that cycle: it keeps
//! that merge (`late_*`) and applies it before the current one, in `eff`
//! and when it holds.

use rust_hdl::prelude::*;

use super::SLOT_BITS;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccSlotBank {
    pub clk: Signal<In, Clock>,
    pub hold: Signal<In, Bit>,
    pub d: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub rw_valid: Signal<In, Bit>,
    pub rw_from: Signal<In, Bits<SLOT_BITS>>,
    pub rw_into: Signal<In, Bits<SLOT_BITS>>,
    pub eff: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    /// The slots before the merge being broadcast (after the late one).
    pub held: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    slot: Vec<DFF<Bits<SLOT_BITS>>>,
    /// After the late merge, and after both.
    mid: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    cur: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    late_valid: DFF<Bit>,
    late_from: DFF<Bits<SLOT_BITS>>,
    late_into: DFF<Bits<SLOT_BITS>>,
    /// The late merge's target is the current merge's source.
    chain: Signal<Local, Bit>,
    is_late: Constant<Bit>,
    _n: usize,
}

impl FccSlotBank {
    /// `n` slots; `late` as above.
    pub fn new(n: usize, late: bool) -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            d: vec_of(n),
            rw_valid: Default::default(),
            rw_from: Default::default(),
            rw_into: Default::default(),
            eff: vec_of(n),
            held: vec_of(n),
            slot: vec_of(n),
            mid: vec_of(n),
            cur: vec_of(n),
            late_valid: Default::default(),
            late_from: Default::default(),
            late_into: Default::default(),
            chain: Default::default(),
            is_late: Constant::new(late),
            _n: n,
        }
    }
}

impl Logic for FccSlotBank {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, late_from, late_into);
        self.late_valid.clock.next = self.clk.val();
        self.late_valid.d.next = false;
        if !self.hold.val() & self.is_late.val() {
            self.late_valid.d.next = self.rw_valid.val();
            self.late_from.d.next = self.rw_from.val();
            self.late_into.d.next = self.rw_into.val();
        }
        // The slots after the merges: both comparisons side by side, and
        // whether the late merge's target is the current one's source.
        self.chain.next = self.rw_valid.val() & (self.late_into.q.val() == self.rw_from.val());
        for j in 0..self._n {
            self.mid[j].next = self.slot[j].q.val();
            self.cur[j].next = self.slot[j].q.val();
            if self.rw_valid.val() & (self.slot[j].q.val() == self.rw_from.val()) {
                self.cur[j].next = self.rw_into.val();
            }
            if self.late_valid.q.val() & (self.slot[j].q.val() == self.late_from.q.val()) {
                self.mid[j].next = self.late_into.q.val();
                self.cur[j].next = self.late_into.q.val();
                if self.chain.val() {
                    self.cur[j].next = self.rw_into.val();
                }
            }
            self.eff[j].next = self.cur[j].val();
            self.held[j].next = self.mid[j].val();
        }
        for j in 0..self._n {
            self.slot[j].clock.next = self.clk.val();
            self.slot[j].d.next = self.d[j].val();
            if self.hold.val() {
                self.slot[j].d.next = self.cur[j].val();
            }
        }
    }
}
