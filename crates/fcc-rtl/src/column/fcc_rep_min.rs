//! `FccRepMin`: one stage of the representative rows' minimum tree
//! (docs/column-core.md, item 3, "How the next pixel sees the rewrite").
//! Output `g` is the smallest of the present inputs `g * gs .. (g + 1) *
//! gs` (a group's partial minimum) and, when `ov[g]` (the rewrite
//! broadcast this cycle names a position the group covers), the rewrite's
//! `m` too: `m` is no larger than any value at the positions it rewrites,
//! so that is the group's minimum with the rewrite applied. `0xFFFF`
//! (above any label) when neither. Registered; taken while `go` (the
//! pipeline moves), held otherwise.
//!
//! Every value is compared with every other and with `m`, straight from
//! the registers before (presence and overlap only enter the choice, not
//! the comparisons), and the winner chosen one-hot (the first of equals,
//! a value before `m`), so the stage is one comparison and a choice deep.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepMin {
    pub clk: Signal<In, Clock>,
    pub go: Signal<In, Bit>,
    pub v: Vec<Signal<In, Bits<16>>>,
    pub pres: Vec<Signal<In, Bit>>,
    pub ov: Vec<Signal<In, Bit>>,
    pub m: Signal<In, Bits<16>>,
    pub out: Vec<Signal<Out, Bits<16>>>,
    out_q: Vec<FccFanoutReg<Bits<16>>>,
    /// Group `g`'s value `c` wins, at `g * gs + c`; `m` wins.
    win: Vec<Signal<Local, Bit>>,
    win_m: Vec<Signal<Local, Bit>>,
    /// Value `c` is less than value `c2` of its group, at
    /// `(g * gs + c) * gs + c2`; `m` is less than value `c`.
    lt: Vec<Signal<Local, Bit>>,
    m_lt: Vec<Signal<Local, Bit>>,
    /// `c2 < c`, at `c * gs + c2` (constant).
    before: Vec<Constant<Bit>>,
    any: Vec<Signal<Local, Bit>>,
    pick: Vec<Signal<Local, Bits<16>>>,
    none: Constant<Bits<16>>,
    zero: Constant<Bits<16>>,
    _gs: usize,
}

impl FccRepMin {
    /// `g` groups of `gs` inputs.
    pub fn new(g: usize, gs: usize) -> Self {
        Self {
            clk: Default::default(),
            go: Default::default(),
            v: vec_of(g * gs),
            pres: vec_of(g * gs),
            ov: vec_of(g),
            m: Default::default(),
            out: vec_of(g),
            out_q: vec_of(g),
            win: vec_of(g * gs),
            win_m: vec_of(g),
            lt: vec_of(g * gs * gs),
            m_lt: vec_of(g * gs),
            before: (0..gs * gs)
                .map(|i| Constant::new(i % gs < i / gs))
                .collect(),
            any: vec_of(g),
            pick: vec_of(g),
            none: kb(0xFFFF),
            zero: kb(0),
            _gs: gs,
        }
    }
}

impl Logic for FccRepMin {
    #[hdl_gen]
    fn update(&mut self) {
        for gs in self._gs..(self._gs + 1) {
            for g in 0..self.out.len() {
                for c in 0..self._gs {
                    self.m_lt[g * gs + c].next = self.m.val() < self.v[g * gs + c].val();
                    for c2 in 0..self._gs {
                        self.lt[(g * gs + c) * gs + c2].next =
                            self.v[g * gs + c].val() < self.v[g * gs + c2].val();
                    }
                }
                // Value c wins: present, smaller than every earlier present
                // value, no later present value or `m` (with `ov`) smaller.
                self.win_m[g].next = self.ov[g].val();
                self.any[g].next = self.ov[g].val();
                for c in 0..self._gs {
                    self.win[g * gs + c].next = self.pres[g * gs + c].val();
                    if self.pres[g * gs + c].val() {
                        self.any[g].next = true;
                        if self.m_lt[g * gs + c].val() {
                            self.win[g * gs + c].next = !self.ov[g].val();
                        } else {
                            self.win_m[g].next = false;
                        }
                    }
                    for c2 in 0..self._gs {
                        if self.pres[g * gs + c2].val()
                            & ((self.before[c * gs + c2].val()
                                & !self.lt[(g * gs + c) * gs + c2].val())
                                | (self.before[c2 * gs + c].val()
                                    & self.lt[(g * gs + c2) * gs + c].val()))
                        {
                            self.win[g * gs + c].next = false;
                        }
                    }
                }
                self.pick[g].next = self.zero.val();
                if self.win_m[g].val() {
                    self.pick[g].next = self.m.val();
                }
                for c in 0..self._gs {
                    if self.win[g * gs + c].val() {
                        self.pick[g].next = self.pick[g].val() | self.v[g * gs + c].val();
                    }
                }
                if !self.any[g].val() {
                    self.pick[g].next = self.none.val();
                }
                self.out_q[g].clock.next = self.clk.val();
                self.out_q[g].d.next = self.out_q[g].q.val();
                if self.go.val() {
                    self.out_q[g].d.next = self.pick[g].val();
                }
                self.out[g].next = self.out_q[g].q.val();
            }
        }
    }
}
