//! `FccRepMin`: one stage of the representative rows' minimum tree
//! (docs/column-core.md, item 3, "How the next pixel sees the rewrite").
//! Output `g` is the smallest of inputs `g * gs .. (g + 1) * gs` (a
//! group's partial minimum) and, when `ov[g]` (the rewrite broadcast this
//! cycle names a position the group covers), the rewrite's `m` too: `m`
//! is no larger than any value at the positions it rewrites, so that is
//! the group's minimum with the rewrite applied. Registered; held while
//! `hold`.
//!
//! Every candidate is compared with every other in parallel and the
//! winner chosen one-hot (the first of equals), so the stage is one
//! comparison deep. `v` has `gs` inputs a group: the parent gives a short
//! last group `0xFFFF` (larger than any label) where it has no value, as
//! `m` is without `ov`.

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepMin {
    pub clk: Signal<In, Clock>,
    pub hold: Signal<In, Bit>,
    pub v: Vec<Signal<In, Bits<16>>>,
    pub ov: Vec<Signal<In, Bit>>,
    pub m: Signal<In, Bits<16>>,
    pub out: Vec<Signal<Out, Bits<16>>>,
    out_q: Vec<DFF<Bits<16>>>,
    /// Group `g`'s candidate `c` at `g * (gs + 1) + c` (`m` last), and
    /// whether it wins.
    cand: Vec<Signal<Local, Bits<16>>>,
    win: Vec<Signal<Local, Bit>>,
    /// Candidate `c` is less than `c2`, at `(g * (gs + 1) + c) * (gs + 1) + c2`.
    lt: Vec<Signal<Local, Bit>>,
    /// `c2 < c`, at `c * (gs + 1) + c2` (constant).
    before: Vec<Constant<Bit>>,
    pick: Vec<Signal<Local, Bits<16>>>,
    none: Constant<Bits<16>>,
    zero: Constant<Bits<16>>,
    _gs: usize,
    /// Candidates a group, `gs + 1`.
    _nc: usize,
}

impl FccRepMin {
    /// `g` groups of `gs` inputs.
    pub fn new(g: usize, gs: usize) -> Self {
        Self {
            clk: Default::default(),
            hold: Default::default(),
            v: vec_of(g * gs),
            ov: vec_of(g),
            m: Default::default(),
            out: vec_of(g),
            out_q: vec_of(g),
            cand: vec_of(g * (gs + 1)),
            win: vec_of(g * (gs + 1)),
            lt: vec_of(g * (gs + 1) * (gs + 1)),
            before: (0..(gs + 1) * (gs + 1))
                .map(|i| Constant::new(i % (gs + 1) < i / (gs + 1)))
                .collect(),
            pick: vec_of(g),
            none: kb(0xFFFF),
            zero: kb(0),
            _gs: gs,
            _nc: gs + 1,
        }
    }
}

impl Logic for FccRepMin {
    #[hdl_gen]
    fn update(&mut self) {
        for nc in self._nc..(self._nc + 1) {
            for gs in self._gs..(self._gs + 1) {
                for g in 0..self.out.len() {
                    for c in 0..self._gs {
                        self.cand[g * nc + c].next = self.v[g * gs + c].val();
                    }
                    self.cand[g * nc + gs].next = self.none.val();
                    if self.ov[g].val() {
                        self.cand[g * nc + gs].next = self.m.val();
                    }
                    for c in 0..self._nc {
                        for c2 in 0..self._nc {
                            self.lt[(g * nc + c) * nc + c2].next =
                                self.cand[g * nc + c].val() < self.cand[g * nc + c2].val();
                        }
                    }
                    // Candidate c wins: smaller than every earlier one, no
                    // later one smaller than it.
                    for c in 0..self._nc {
                        self.win[g * nc + c].next = true;
                        for c2 in 0..self._nc {
                            if (self.before[c * nc + c2].val()
                                & !self.lt[(g * nc + c) * nc + c2].val())
                                | (self.before[c2 * nc + c].val()
                                    & self.lt[(g * nc + c2) * nc + c].val())
                            {
                                self.win[g * nc + c].next = false;
                            }
                        }
                    }
                    self.pick[g].next = self.zero.val();
                    for c in 0..self._nc {
                        if self.win[g * nc + c].val() {
                            self.pick[g].next = self.pick[g].val() | self.cand[g * nc + c].val();
                        }
                    }
                    self.out_q[g].clock.next = self.clk.val();
                    self.out_q[g].d.next = self.pick[g].val();
                    if self.hold.val() {
                        self.out_q[g].d.next = self.out_q[g].q.val();
                    }
                    self.out[g].next = self.out_q[g].q.val();
                }
            }
        }
    }
}
