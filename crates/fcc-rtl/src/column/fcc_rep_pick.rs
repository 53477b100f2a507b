//! `FccRepPick`: the first flagged value of a pixel's run slots
//! (combinational; docs/column-core.md, item 3): `first`, one-hot, from
//! `FccGroupOr` and `FccFirstSet` (two short reductions), then `x`, an OR
//! of the values masked by it; `any` says some flag is set (`x` is 0
//! otherwise).

use rust_hdl::prelude::*;

use crate::fcc_first_set::FccFirstSet;
use crate::fcc_group_or::FccGroupOr;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepPick {
    pub flag: Vec<Signal<In, Bit>>,
    pub val: Vec<Signal<In, Bits<16>>>,
    pub any: Signal<Out, Bit>,
    pub first: Vec<Signal<Out, Bit>>,
    pub x: Signal<Out, Bits<16>>,
    groups: FccGroupOr,
    firsts: FccFirstSet,
    zero16: Constant<Bits<16>>,
}

impl FccRepPick {
    /// `n` run slots.
    pub fn new(n: usize) -> Self {
        Self {
            flag: vec_of(n),
            val: vec_of(n),
            any: Default::default(),
            first: vec_of(n),
            x: Default::default(),
            groups: FccGroupOr::new(n),
            firsts: FccFirstSet::new(n),
            zero16: kb(0),
        }
    }
}

impl Logic for FccRepPick {
    #[hdl_gen]
    fn update(&mut self) {
        for b in 0..self.flag.len() {
            self.groups.x[b].next = self.flag[b].val();
            self.firsts.x[b].next = self.flag[b].val();
        }
        self.any.next = false;
        for g in 0..self.groups.any.len() {
            self.firsts.gany[g].next = self.groups.any[g].val();
            if self.groups.any[g].val() {
                self.any.next = true;
            }
        }
        self.x.next = self.zero16.val();
        for b in 0..self.flag.len() {
            self.first[b].next = self.firsts.first[b].val();
            if self.firsts.first[b].val() {
                self.x.next = self.x.val() | self.val[b].val();
            }
        }
    }
}
