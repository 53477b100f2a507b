//! `FccRepFirst`: the first flagged run slot of a pixel's (combinational;
//! docs/column-core.md, item 3): `first`, one-hot, from `FccGroupOr` and
//! `FccFirstSet` (two short reductions); `any` says some flag is set. Its
//! value is taken a cycle later (`FccRepTake`), so that the two never
//! share a cycle.

use rust_hdl::prelude::*;

use crate::fcc_first_set::FccFirstSet;
use crate::fcc_group_or::FccGroupOr;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepFirst {
    pub flag: Vec<Signal<In, Bit>>,
    pub any: Signal<Out, Bit>,
    pub first: Vec<Signal<Out, Bit>>,
    groups: FccGroupOr,
    firsts: FccFirstSet,
}

impl FccRepFirst {
    /// `n` run slots.
    pub fn new(n: usize) -> Self {
        Self {
            flag: vec_of(n),
            any: Default::default(),
            first: vec_of(n),
            groups: FccGroupOr::new(n),
            firsts: FccFirstSet::new(n),
        }
    }
}

impl Logic for FccRepFirst {
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
        for b in 0..self.flag.len() {
            self.first[b].next = self.firsts.first[b].val();
        }
    }
}
