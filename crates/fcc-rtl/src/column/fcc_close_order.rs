//! `FccCloseOrder`: the closer's sorted entries (docs/column-core.md,
//! item 4): a register array of `CLOSE_ENTRIES` entries (a key, a slot)
//! sorted by key, smallest first, that takes one entry (`in_*`) and gives
//! up its head (`pop`) in the same cycle if need be. The closer fills it
//! with the clusters that close at one column, keyed by their first pixel
//! (column in the high 12 bits, row in the low 7), so the head is the next
//! close to send, in the golden order; it is empty before the next
//! column's. Equal keys leave in the order they came.
//!
//! An entry taken while the array is `full` (and the head stays) drops the
//! largest of the entries and the new one (`drop_*`, in the same cycle; of
//! equal keys the one that came last): so a column with more closes than
//! entries is sent in passes, each the smallest ones left, and the closer
//! puts what is dropped back in its wait list.
//!
//! Each entry compares the new key with its own (`lt`: the new entry goes
//! before it, or it is empty; sorted, so `lt` is false then true along
//! the array), and from its neighbours' comparisons and `pop` decides
//! (`mv`) whether it keeps its value or takes the one before it, the one
//! after it or the new one: a four-way choice a bit.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::FIRST_BITS;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::vec_of;

/// Entries the closer holds.
pub const CLOSE_ENTRIES: usize = 32;
/// Bits of an entry's key: a first pixel in column order.
pub const CLOSE_KEY_BITS: usize = FIRST_BITS;

/// What an entry takes at the clock edge.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum CloseMove {
    Keep,
    /// The entry before it (an entry is taken in front).
    Prev,
    /// The entry after it (the head leaves).
    Next,
    /// The entry taken.
    New,
}

#[derive(LogicBlock)]
pub struct FccCloseOrder {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub in_valid: Signal<In, Bit>,
    pub in_key: Signal<In, Bits<CLOSE_KEY_BITS>>,
    pub in_slot: Signal<In, Bits<SLOT_BITS>>,
    /// The last entry is taken: an entry in without a pop drops one.
    pub full: Signal<Out, Bit>,
    pub pop: Signal<In, Bit>,
    /// The entry dropped this cycle (the old last one or the new one).
    pub drop_valid: Signal<Out, Bit>,
    pub drop_key: Signal<Out, Bits<CLOSE_KEY_BITS>>,
    pub drop_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub head_valid: Signal<Out, Bit>,
    pub head_key: Signal<Out, Bits<CLOSE_KEY_BITS>>,
    pub head_slot: Signal<Out, Bits<SLOT_BITS>>,
    /// The entry taken this cycle (`nv` low: none).
    nv: Signal<Local, Bit>,
    lt: Vec<Signal<Local, Bit>>,
    mv: Vec<Signal<Local, CloseMove>>,
    // The entries: valid, key, slot.
    ev: Vec<FccFanoutReg<Bit>>,
    ek: Vec<DFF<Bits<CLOSE_KEY_BITS>>>,
    es: Vec<DFF<Bits<SLOT_BITS>>>,
    _n: usize,
}

impl Default for FccCloseOrder {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            in_valid: Default::default(),
            in_key: Default::default(),
            in_slot: Default::default(),
            full: Default::default(),
            pop: Default::default(),
            drop_valid: Default::default(),
            drop_key: Default::default(),
            drop_slot: Default::default(),
            head_valid: Default::default(),
            head_key: Default::default(),
            head_slot: Default::default(),
            nv: Default::default(),
            lt: vec_of(CLOSE_ENTRIES),
            mv: vec_of(CLOSE_ENTRIES),
            ev: vec_of(CLOSE_ENTRIES),
            ek: vec_of(CLOSE_ENTRIES),
            es: vec_of(CLOSE_ENTRIES),
            _n: CLOSE_ENTRIES,
        }
    }
}

impl Logic for FccCloseOrder {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..self._n {
            self.ev[i].clock.next = self.clk.val();
            self.ek[i].clock.next = self.clk.val();
            self.es[i].clock.next = self.clk.val();
        }
        self.nv.next = self.in_valid.val();
        for i in 0..self._n {
            self.lt[i].next =
                !self.ev[i].q.val() | (self.nv.val() & (self.in_key.val() < self.ek[i].q.val()));
        }
        // The last entry (a loop of one): full, an entry in without a pop
        // drops the old last one if the new one goes before it, else the new
        // one.
        for i in (self._n - 1)..self._n {
            self.full.next = self.ev[i].q.val();
            self.drop_valid.next = self.nv.val() & self.ev[i].q.val() & !self.pop.val();
            self.drop_key.next = self.in_key.val();
            self.drop_slot.next = self.in_slot.val();
            if self.lt[i].val() {
                self.drop_key.next = self.ek[i].q.val();
                self.drop_slot.next = self.es[i].q.val();
            }
        }
        // The moves. Without a pop, each entry at or after the new one's
        // place moves up one; with a pop, each takes the one after it, or
        // the new one where it goes (the last entry has an empty one after
        // it).
        self.mv[0].next = CloseMove::Keep;
        if self.lt[0].val() {
            self.mv[0].next = CloseMove::New;
        }
        if self.pop.val() {
            self.mv[0].next = CloseMove::Next;
            if self.lt[1].val() {
                self.mv[0].next = CloseMove::New;
            }
        }
        for i in 1..(self._n - 1) {
            self.mv[i].next = CloseMove::Keep;
            if self.lt[i].val() {
                self.mv[i].next = CloseMove::New;
                if self.lt[i - 1].val() {
                    self.mv[i].next = CloseMove::Prev;
                }
            }
            if self.pop.val() {
                self.mv[i].next = CloseMove::Next;
                if self.lt[i + 1].val() {
                    self.mv[i].next = CloseMove::New;
                    if self.lt[i].val() {
                        self.mv[i].next = CloseMove::Keep;
                    }
                }
            }
        }
        for i in (self._n - 1)..self._n {
            self.mv[i].next = CloseMove::Keep;
            if self.lt[i].val() {
                self.mv[i].next = CloseMove::New;
                if self.lt[i - 1].val() {
                    self.mv[i].next = CloseMove::Prev;
                }
            }
            if self.pop.val() {
                self.mv[i].next = CloseMove::New;
                if self.lt[i].val() {
                    self.mv[i].next = CloseMove::Keep;
                }
            }
        }
        // Each entry's four-way choice.
        for i in 0..self._n {
            self.ev[i].d.next = self.ev[i].q.val();
            self.ek[i].d.next = self.ek[i].q.val();
            self.es[i].d.next = self.es[i].q.val();
            if self.mv[i].val() == CloseMove::New {
                self.ev[i].d.next = self.nv.val();
                self.ek[i].d.next = self.in_key.val();
                self.es[i].d.next = self.in_slot.val();
            }
        }
        for i in 1..self._n {
            if self.mv[i].val() == CloseMove::Prev {
                self.ev[i].d.next = self.ev[i - 1].q.val();
                self.ek[i].d.next = self.ek[i - 1].q.val();
                self.es[i].d.next = self.es[i - 1].q.val();
            }
        }
        for i in 0..(self._n - 1) {
            if self.mv[i].val() == CloseMove::Next {
                self.ev[i].d.next = self.ev[i + 1].q.val();
                self.ek[i].d.next = self.ek[i + 1].q.val();
                self.es[i].d.next = self.es[i + 1].q.val();
            }
        }
        if self.rst.val() {
            for i in 0..self._n {
                self.ev[i].d.next = false;
            }
        }
        self.head_valid.next = self.ev[0].q.val();
        self.head_key.next = self.ek[0].q.val();
        self.head_slot.next = self.es[0].q.val();
    }
}
