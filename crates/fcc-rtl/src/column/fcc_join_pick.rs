//! `FccJoinPick`: the merge a pixel asks for (combinational), from its
//! stage's join flags (`FccJoinFlags`, registered) and current slots: the
//! first flagged entry, in window order, merges its cluster into the
//! pixel's (`m_from` into `m_into`); with none, a flagged ring pair merges
//! the row's first run's cluster into its last's. Flags a cycle old may
//! name clusters merged since: the merge asked for is then of a slot into
//! itself, which changes nothing (`FccRowRoots` drops it from its output).

use rust_hdl::prelude::*;

use super::{slot_index, SLOT_BITS};
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccJoinPick {
    pub flag: Vec<Signal<In, Bit>>,
    pub ring_flag: Signal<In, Bit>,
    pub slot: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub m_valid: Signal<Out, Bit>,
    pub m_from: Signal<Out, Bits<SLOT_BITS>>,
    pub m_into: Signal<Out, Bits<SLOT_BITS>>,
    any: Signal<Local, Bit>,
    /// A flag before entry `e`; entry `e` is the first; its slot if so;
    /// the OR of those up to `e` (the first's slot at the end).
    before: Vec<Signal<Local, Bit>>,
    masked: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    acc: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    first: Signal<Local, Bits<SLOT_BITS>>,
    zero_slot: Constant<Bits<SLOT_BITS>>,
    _ne: usize,
    _own: usize,
    _ring_a: usize,
    _ring_b: usize,
}

impl FccJoinPick {
    /// `ne` window entries.
    pub fn new(ne: usize) -> Self {
        let ix = slot_index(ne);
        Self {
            flag: vec_of(ne),
            ring_flag: Default::default(),
            slot: vec_of(ix.joins),
            m_valid: Default::default(),
            m_from: Default::default(),
            m_into: Default::default(),
            any: Default::default(),
            before: vec_of(ne),
            masked: vec_of(ne),
            acc: vec_of(ne),
            first: Default::default(),
            zero_slot: kb(0),
            _ne: ne,
            _own: ix.own,
            _ring_a: ix.ring_a,
            _ring_b: ix.ring_b,
        }
    }
}

impl Logic for FccJoinPick {
    #[hdl_gen]
    fn update(&mut self) {
        // One-hot: the first flag, then an OR of the masked slots (a tree,
        // not a chain of multiplexers).
        self.before[0].next = false;
        for e in 1..self._ne {
            self.before[e].next = self.before[e - 1].val() | self.flag[e - 1].val();
        }
        for e in 0..self._ne {
            self.masked[e].next = self.zero_slot.val();
            if self.flag[e].val() & !self.before[e].val() {
                self.masked[e].next = self.slot[e].val();
            }
        }
        self.acc[0].next = self.masked[0].val();
        for e in 1..self._ne {
            self.acc[e].next = self.acc[e - 1].val() | self.masked[e].val();
        }
        for ne in self._ne..(self._ne + 1) {
            self.any.next = self.before[ne - 1].val() | self.flag[ne - 1].val();
            self.first.next = self.acc[ne - 1].val();
        }
        self.m_valid.next = self.any.val() | self.ring_flag.val();
        for ra in self._ring_a..(self._ring_a + 1) {
            for rb in self._ring_b..(self._ring_b + 1) {
                self.m_from.next = self.slot[ra].val();
                self.m_into.next = self.slot[rb].val();
            }
        }
        for own in self._own..(self._own + 1) {
            if self.any.val() {
                self.m_from.next = self.first.val();
                self.m_into.next = self.slot[own].val();
            }
        }
    }
}
