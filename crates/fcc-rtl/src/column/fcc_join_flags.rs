//! `FccJoinFlags`: which of a pixel's joins still cross clusters
//! (combinational), from its stage's slots and the merge being broadcast
//! (`rw_*`): a hit entry whose slot is not the pixel's own, and the ring
//! check's pair in two slots, after the merge. Two slots `s`, `t` are one
//! after a merge of `a` into `b` when `s == t`, or `s == a` and `t == b`, or
//! `s == b` and `t == a`: compared side by side rather than after
//! rewriting, which saves the rewrite's levels of logic.

use rust_hdl::prelude::*;

use super::{slot_index, SLOT_BITS};
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccJoinFlags {
    /// The stage's slots (`slot_index`'s first `joins`), and its hits.
    pub slot: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub hit: Vec<Signal<In, Bit>>,
    pub ring: Signal<In, Bit>,
    pub rw_valid: Signal<In, Bit>,
    pub rw_from: Signal<In, Bits<SLOT_BITS>>,
    pub rw_into: Signal<In, Bits<SLOT_BITS>>,
    pub flag: Vec<Signal<Out, Bit>>,
    pub ring_flag: Signal<Out, Bit>,
    /// The pixel's own slot is the merge's `a`, its `b`.
    own_a: Signal<Local, Bit>,
    own_b: Signal<Local, Bit>,
    _ne: usize,
    _own: usize,
    _ring_a: usize,
    _ring_b: usize,
}

impl FccJoinFlags {
    /// `ne` window entries.
    pub fn new(ne: usize) -> Self {
        let ix = slot_index(ne);
        Self {
            slot: vec_of(ix.joins),
            hit: vec_of(ne),
            ring: Default::default(),
            rw_valid: Default::default(),
            rw_from: Default::default(),
            rw_into: Default::default(),
            flag: vec_of(ne),
            ring_flag: Default::default(),
            own_a: Default::default(),
            own_b: Default::default(),
            _ne: ne,
            _own: ix.own,
            _ring_a: ix.ring_a,
            _ring_b: ix.ring_b,
        }
    }
}

impl Logic for FccJoinFlags {
    #[hdl_gen]
    fn update(&mut self) {
        for ra in self._ring_a..(self._ring_a + 1) {
            for rb in self._ring_b..(self._ring_b + 1) {
                self.ring_flag.next = self.ring.val()
                    & !((self.slot[ra].val() == self.slot[rb].val())
                        | (self.rw_valid.val()
                            & (self.slot[ra].val() == self.rw_from.val())
                            & (self.slot[rb].val() == self.rw_into.val()))
                        | (self.rw_valid.val()
                            & (self.slot[ra].val() == self.rw_into.val())
                            & (self.slot[rb].val() == self.rw_from.val())));
            }
        }
        for own in self._own..(self._own + 1) {
            self.own_a.next = self.rw_valid.val() & (self.slot[own].val() == self.rw_from.val());
            self.own_b.next = self.rw_valid.val() & (self.slot[own].val() == self.rw_into.val());
            for e in 0..self._ne {
                self.flag[e].next = self.hit[e].val()
                    & !((self.slot[e].val() == self.slot[own].val())
                        | (self.own_b.val() & (self.slot[e].val() == self.rw_from.val()))
                        | (self.own_a.val() & (self.slot[e].val() == self.rw_into.val())));
            }
        }
    }
}
