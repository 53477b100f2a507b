//! `FccJoinPick`: the merge a pixel at the slot table asks for this cycle
//! (combinational), from the clusters `FccRootMatch` found.
//!
//! The pixel's joins are its hits (`ent_ok`) into clusters other than its
//! own, and at the last column the ring check's pair (`ring`: the row's
//! first run's cluster and its last's). The first entry, in window order,
//! whose cluster is not the pixel's asks to merge that cluster into the
//! pixel's (`m_from` into `m_into`); with none, the ring pair asks
//! (`ring_a` into `ring_b`). `more` says the pixel joins yet another
//! cluster: an entry in a third cluster, or the ring pair as well as an
//! entry. The pixel then stays a cycle for each further merge, which finds
//! the clusters already merged rewritten.

use rust_hdl::prelude::*;

use super::SLOT_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccJoinPick {
    pub ent_ok: Vec<Signal<In, Bit>>,
    pub ent_slot: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub own_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ring: Signal<In, Bit>,
    pub ring_a_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ring_b_slot: Signal<In, Bits<SLOT_BITS>>,
    pub m_valid: Signal<Out, Bit>,
    pub m_from: Signal<Out, Bits<SLOT_BITS>>,
    pub m_into: Signal<Out, Bits<SLOT_BITS>>,
    pub more: Signal<Out, Bit>,
    /// The entry joins another cluster.
    other: Vec<Signal<Local, Bit>>,
    any: Signal<Local, Bit>,
    first: Signal<Local, Bits<SLOT_BITS>>,
    ring_other: Signal<Local, Bit>,
    zero_slot: Constant<Bits<SLOT_BITS>>,
    _ne: usize,
}

impl FccJoinPick {
    /// `ne` window entries.
    pub fn new(ne: usize) -> Self {
        Self {
            ent_ok: vec_of(ne),
            ent_slot: vec_of(ne),
            own_slot: Default::default(),
            ring: Default::default(),
            ring_a_slot: Default::default(),
            ring_b_slot: Default::default(),
            m_valid: Default::default(),
            m_from: Default::default(),
            m_into: Default::default(),
            more: Default::default(),
            other: vec_of(ne),
            any: Default::default(),
            first: Default::default(),
            ring_other: Default::default(),
            zero_slot: kb(0),
            _ne: ne,
        }
    }
}

impl Logic for FccJoinPick {
    #[hdl_gen]
    fn update(&mut self) {
        self.any.next = false;
        self.first.next = self.zero_slot.val();
        for e in 0..self._ne {
            self.other[e].next =
                self.ent_ok[e].val() & (self.ent_slot[e].val() != self.own_slot.val());
        }
        // The last entry first, so that the first in window order wins.
        for ne in self._ne..(self._ne + 1) {
            for e in 0..self._ne {
                if self.other[ne - 1 - e].val() {
                    self.any.next = true;
                    self.first.next = self.ent_slot[ne - 1 - e].val();
                }
            }
        }
        self.ring_other.next = self.ring.val() & (self.ring_a_slot.val() != self.ring_b_slot.val());
        self.more.next = self.any.val() & self.ring_other.val();
        for e in 0..self._ne {
            if self.other[e].val() & (self.ent_slot[e].val() != self.first.val()) {
                self.more.next = true;
            }
        }
        self.m_valid.next = self.any.val() | self.ring_other.val();
        self.m_from.next = self.ring_a_slot.val();
        self.m_into.next = self.ring_b_slot.val();
        if self.any.val() {
            self.m_from.next = self.first.val();
            self.m_into.next = self.own_slot.val();
        }
    }
}
