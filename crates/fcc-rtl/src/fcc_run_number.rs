//! `FccRunNumber`: numbers the labelled runs that start in a read-back beat
//! (combinational, `fcc_rb_pipeline`'s stage 2). From the beat's four
//! frame-buffer codes (`code`, an unused slot's code is empty) and whether
//! the beat is the frame's first: each slot's source `src` (`fcc_slot_mux`'s
//! encoding), the source of the run carried into the next beat (`run`) and
//! how many new labels the beat needs (`need`).
//!
//! A used slot's source is `SRC_ZERO` when it is empty or its run is
//! unlabelled (`zero_run`: an unlabelled run started last, or none started
//! and the beat is the frame's first), else 1 + the labelled runs started up
//! to it (with none started, `SRC_CARRIED`: the carried run; with the k-th
//! started last, `SRC_NEW + k`). The counts are looked up from the set of
//! labelled slots, not added, so the decode is no carry chain.

use rust_hdl::prelude::*;

use crate::fcc_slot_mux::{SRC_CARRIED, SRC_NEW, SRC_ZERO};
use crate::types::{kb, vec_of};

// A slot's source is 1 + the labelled runs started up to it: the carried
// run with none, `SRC_NEW + k` for the k-th.
const _: () = assert!(SRC_NEW == SRC_CARRIED + 1);

/// Frame-buffer codes (`FccIntra::state`).
pub const CODE_EMPTY: u64 = 0;
pub const CODE_LABELLED: u64 = 2;
pub const CODE_UNLABELLED: u64 = 3;

#[derive(LogicBlock)]
pub struct FccRunNumber {
    /// The beat's slot codes and whether it is the frame's first beat.
    pub code: Vec<Signal<In, Bits<2>>>,
    pub first: Signal<In, Bit>,
    /// Each slot's source, the carried run's source, the new labels needed.
    pub src: Vec<Signal<Out, Bits<3>>>,
    pub run: Signal<Out, Bits<3>>,
    pub need: Signal<Out, Bits<3>>,
    /// The slots that start a labelled run (bit i: slot i); those up to slot i.
    labelled: Signal<Local, Bits<4>>,
    labelled_upto: Vec<Signal<Local, Bits<4>>>,
    /// The run before slot i (after the beat, at 4) has label 0.
    zero_run: Vec<Signal<Local, Bit>>,
    /// Bit i; bits 0 to i; the 16 sets of labelled slots, the labelled
    /// runs in each (`count_of`) and 1 + that (`src_of`).
    slot_bit: Vec<Constant<Bits<4>>>,
    upto_mask: Vec<Constant<Bits<4>>>,
    set: Vec<Constant<Bits<4>>>,
    count_of: Vec<Constant<Bits<3>>>,
    src_of: Vec<Constant<Bits<3>>>,
    zero4: Constant<Bits<4>>,
    code_empty: Constant<Bits<2>>,
    code_labelled: Constant<Bits<2>>,
    code_unlabelled: Constant<Bits<2>>,
    src_zero: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
}

impl Default for FccRunNumber {
    fn default() -> Self {
        Self {
            code: vec_of(4),
            first: Default::default(),
            src: vec_of(4),
            run: Default::default(),
            need: Default::default(),
            labelled: Default::default(),
            labelled_upto: vec_of(4),
            zero_run: vec_of(5),
            slot_bit: (0..4).map(|i| kb(1u64 << i)).collect(),
            upto_mask: (0..4).map(|i| kb((2u64 << i) - 1)).collect(),
            set: (0..16).map(|m| kb(m as u64)).collect(),
            count_of: (0..16u64).map(|m| kb(m.count_ones() as u64)).collect(),
            src_of: (0..16u64)
                .map(|m| kb(SRC_CARRIED + m.count_ones() as u64))
                .collect(),
            zero4: kb(0),
            code_empty: kb(CODE_EMPTY),
            code_labelled: kb(CODE_LABELLED),
            code_unlabelled: kb(CODE_UNLABELLED),
            src_zero: kb(SRC_ZERO),
            zero3: kb(0),
        }
    }
}

impl Logic for FccRunNumber {
    #[hdl_gen]
    fn update(&mut self) {
        self.zero_run[0].next = self.first.val();
        self.labelled.next = self.zero4.val();
        for i in 0..4 {
            self.zero_run[i + 1].next = self.zero_run[i].val();
            if self.code[i].val() == self.code_labelled.val() {
                self.labelled.next = self.labelled.val() | self.slot_bit[i].val();
                self.zero_run[i + 1].next = false;
            }
            if self.code[i].val() == self.code_unlabelled.val() {
                self.zero_run[i + 1].next = true;
            }
        }
        // Labelled runs started up to each slot, looked up from the set of
        // labelled slots up to it.
        for i in 0..4 {
            self.labelled_upto[i].next = self.labelled.val() & self.upto_mask[i].val();
            self.src[i].next = self.src_zero.val();
            for m in 0..16 {
                if self.labelled_upto[i].val() == self.set[m].val() {
                    self.src[i].next = self.src_of[m].val();
                }
            }
            if self.zero_run[i + 1].val() | (self.code[i].val() == self.code_empty.val()) {
                self.src[i].next = self.src_zero.val();
            }
        }
        self.need.next = self.zero3.val();
        self.run.next = self.src_zero.val();
        for m in 0..16 {
            if self.labelled.val() == self.set[m].val() {
                self.need.next = self.count_of[m].val();
                self.run.next = self.src_of[m].val();
            }
        }
        if self.zero_run[4].val() {
            self.run.next = self.src_zero.val();
        }
    }
}
