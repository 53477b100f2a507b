//! `fcc_slot_mux`: the label of one slot of the head beat (or of the run the
//! head beat carries into the next one), chosen by its source.
//!
//! A source is 0 (label 0), 1 (the run carried in from the previous beat) or
//! 2 + k (the beat's k-th new label). The head beat has already collected
//! `taken` of its new labels (in `collected`, slots `0 .. taken`); new labels `taken`
//! and `taken + 1` may arrive from the gearbox in this very cycle, as
//! `gear_head` and `gear_next`, and are forwarded.
//!
//! Slot j of a beat can only hold one of the beat's first j + 1 new labels
//! (the slots before it hold at least as many labels as there are new ones
//! before it), so slot j's multiplexer is built with j + 1 new-label arms;
//! the run carried into the next beat may be any of the beat's new labels
//! (all [`NEW_LABELS`] arms).

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

/// Four 16-bit label slots (an output beat, or the new labels a head beat
/// has collected).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct OutWord {
    pub l0: Bits<16>,
    pub l1: Bits<16>,
    pub l2: Bits<16>,
    pub l3: Bits<16>,
}

/// New labels a beat can hold (four slots).
pub const NEW_LABELS: usize = 4;

/// Slot source: label 0.
pub const SRC_ZERO: u64 = 0;
/// Slot source: the run carried in from the previous beat.
pub const SRC_CARRIED: u64 = 1;
/// Slot source of the beat's first new label (the k-th is `SRC_NEW + k`).
pub const SRC_NEW: u64 = 2;

#[derive(LogicBlock)]
pub struct FccSlotMux {
    pub source: Signal<In, Bits<3>>,
    /// New labels the head beat has collected so far.
    pub taken: Signal<In, Bits<3>>,
    pub carried: Signal<In, Bits<16>>,
    pub collected: Signal<In, OutWord>,
    /// The gearbox's first and second label (popped in this cycle when needed).
    pub gear_head: Signal<In, Bits<16>>,
    pub gear_next: Signal<In, Bits<16>>,
    pub label: Signal<Out, Bits<16>>,
    collected_k: Vec<Signal<Local, Bits<16>>>,
    src_carried: Constant<Bits<3>>,
    src_new: Vec<Constant<Bits<3>>>,
    count: Vec<Constant<Bits<3>>>,
    zero16: Constant<Bits<16>>,
    /// New labels this slot can hold (its arms `SRC_NEW + k`, `k < _arms`).
    _arms: usize,
}

impl FccSlotMux {
    /// The multiplexer of a slot that can hold one of the beat's first
    /// `arms` new labels (1 ..= [`NEW_LABELS`]).
    pub fn new(arms: usize) -> Self {
        assert!((1..=NEW_LABELS).contains(&arms), "{arms} new-label arms");
        Self {
            source: Default::default(),
            taken: Default::default(),
            carried: Default::default(),
            collected: Default::default(),
            gear_head: Default::default(),
            gear_next: Default::default(),
            label: Default::default(),
            collected_k: vec_of(NEW_LABELS),
            src_carried: kb(SRC_CARRIED),
            src_new: (0..arms).map(|k| kb(SRC_NEW + k as u64)).collect(),
            count: (0..arms).map(|k| kb(k as u64)).collect(),
            zero16: kb(0),
            _arms: arms,
        }
    }
}

impl Logic for FccSlotMux {
    #[hdl_gen]
    fn update(&mut self) {
        self.collected_k[0].next = self.collected.val().l0;
        self.collected_k[1].next = self.collected.val().l1;
        self.collected_k[2].next = self.collected.val().l2;
        self.collected_k[3].next = self.collected.val().l3;
        self.label.next = self.zero16.val();
        if self.source.val() == self.src_carried.val() {
            self.label.next = self.carried.val();
        }
        for k in 0..self._arms {
            if self.source.val() == self.src_new[k].val() {
                self.label.next = self.collected_k[k].val();
                if self.taken.val() == self.count[k].val() {
                    self.label.next = self.gear_head.val();
                }
            }
        }
        for k in 1..self._arms {
            if (self.source.val() == self.src_new[k].val())
                & (self.taken.val() == self.count[k - 1].val())
            {
                self.label.next = self.gear_next.val();
            }
        }
    }
}
