//! `fcc_slot_mux`: the label of one slot of the head beat (or of the run the
//! head beat carries into the next one), chosen by its source.
//!
//! A source is 0 (label 0), 1 (the run carried in from the previous beat) or
//! 2 + k (the beat's k-th new label). The head beat has already collected
//! `taken` of its new labels (in `collected`, slots `0 .. taken`); new labels `taken`
//! and `taken + 1` may arrive from the gearbox in this very cycle, as
//! `gear_head` and `gear_next`, and are forwarded.

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
}

impl FccSlotMux {
    pub fn new() -> Self {
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
            src_new: (0..NEW_LABELS).map(|k| kb(SRC_NEW + k as u64)).collect(),
            count: (0..NEW_LABELS).map(|k| kb(k as u64)).collect(),
            zero16: kb(0),
        }
    }
}

impl Default for FccSlotMux {
    fn default() -> Self {
        Self::new()
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
        for k in 0..4 {
            if self.source.val() == self.src_new[k].val() {
                self.label.next = self.collected_k[k].val();
                if self.taken.val() == self.count[k].val() {
                    self.label.next = self.gear_head.val();
                }
            }
        }
        for k in 1..4 {
            if (self.source.val() == self.src_new[k].val())
                & (self.taken.val() == self.count[k - 1].val())
            {
                self.label.next = self.gear_next.val();
            }
        }
    }
}
