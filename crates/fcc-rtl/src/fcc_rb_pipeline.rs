//! `fcc_rb_pipeline`: the read-back pipeline from the frame buffer to decoded
//! beats. Stage 0 issues the frame-buffer read of a beat (at most
//! `QUEUE_BEATS` beats between stage 0 and the output, counted by
//! `in_flight`, which sees a beat leave one cycle late, `beat_done_q`, so the
//! output handshake never reaches the issue decision), stage 2 has the
//! word, stage 3 has it decoded: per slot its source (zero, the run carried
//! from the previous beat (none into the frame's first beat), or the k-th new
//! label of this beat, as
//! `fcc_slot_mux` reads it) and how many new labels the beat needs. At
//! read-back the k-th code 2 (a labelled run starts) *is* the beat's k-th new
//! provisional label, so no label is looked up.

use rust_hdl::prelude::*;

use crate::fcc_beat_queue::{Beat, QUEUE_BEATS};
use crate::fcc_run_number::{FccRunNumber, CODE_EMPTY};
use crate::types::{kb, vec_of, FbWord};

#[derive(LogicBlock)]
pub struct FccRbPipeline {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Start the read-back of the frame just written.
    pub start: Signal<In, Bit>,
    pub beats_m1: Signal<In, Bits<20>>,
    pub last_beat_labels: Signal<In, Bits<3>>,
    /// A beat left the output side (frees a place).
    pub beat_done: Signal<In, Bit>,
    // Frame-buffer read port (one cycle latency).
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<17>>,
    pub read_data: Signal<In, FbWord>,
    // Decoded beats (no back-pressure: `in_flight` bounds them).
    pub beat_valid: Signal<Out, Bit>,
    pub beat: Signal<Out, Beat>,
    // Stage 0.
    active: DFF<Bit>,
    /// First pixel of the next beat.
    pixel: DFF<Bits<20>>,
    /// Beats still to issue after the next one; `last_next`: the next is the last.
    beats_left: DFF<Bits<20>>,
    last_next: DFF<Bit>,
    /// The next beat is the frame's first (no run is carried into it).
    first_next: DFF<Bit>,
    in_flight: DFF<Bits<3>>,
    /// `beat_done`, registered.
    beat_done_q: DFF<Bit>,
    // Stages 1 and 2: the beat's position in its word, its labels, last beat.
    valid_s1: DFF<Bit>,
    word_pos_s1: DFF<Bits<2>>,
    labels_s1: DFF<Bits<3>>,
    last_s1: DFF<Bit>,
    first_s1: DFF<Bit>,
    valid_s2: DFF<Bit>,
    word_pos_s2: DFF<Bits<2>>,
    /// The beat's `keep` mask, two bits per slot: slot i is used when bit
    /// 2i is set.
    keep_s2: DFF<Bits<8>>,
    last_s2: DFF<Bit>,
    first_s2: DFF<Bit>,
    // Stage 3.
    valid_s3: DFF<Bit>,
    beat_s3: DFF<Beat>,
    issue: Signal<Local, Bit>,
    /// Code of each slot, and the labelled runs it starts numbered.
    code: Vec<Signal<Local, Bits<2>>>,
    run_number: FccRunNumber,
    pos_in_word: Signal<Local, Bits<2>>,
    /// The bits of a beat's position in its word that can be set (the
    /// pixel counter steps by the labels per beat): none for 4 labels per
    /// beat, so synthesis drops the code multiplexers.
    word_pos_bits: Constant<Bits<2>>,
    pos: Vec<Constant<Bits<2>>>,
    slot_off: Vec<Constant<Bits<2>>>,
    /// Bit 2i: slot i's used flag in `keep_s2`.
    slot_used: Vec<Constant<Bits<8>>>,
    keep_n: Vec<Constant<Bits<8>>>,
    labels: Vec<Constant<Bits<3>>>,
    code_empty: Constant<Bits<2>>,
    max_in_flight: Constant<Bits<3>>,
    lpb3: Constant<Bits<3>>,
    lpb20: Constant<Bits<20>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    zero8: Constant<Bits<8>>,
    one20: Constant<Bits<20>>,
    zero20: Constant<Bits<20>>,
    _l: usize,
}

impl FccRbPipeline {
    /// `labels_per_beat`: 1, 2 or 4.
    pub fn new(labels_per_beat: usize) -> Self {
        assert!(matches!(labels_per_beat, 1 | 2 | 4));
        let l = labels_per_beat;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            start: Default::default(),
            beats_m1: Default::default(),
            last_beat_labels: Default::default(),
            beat_done: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            read_data: Default::default(),
            beat_valid: Default::default(),
            beat: Default::default(),
            active: Default::default(),
            pixel: Default::default(),
            beats_left: Default::default(),
            last_next: Default::default(),
            first_next: Default::default(),
            in_flight: Default::default(),
            beat_done_q: Default::default(),
            valid_s1: Default::default(),
            word_pos_s1: Default::default(),
            labels_s1: Default::default(),
            last_s1: Default::default(),
            first_s1: Default::default(),
            valid_s2: Default::default(),
            word_pos_s2: Default::default(),
            keep_s2: Default::default(),
            last_s2: Default::default(),
            first_s2: Default::default(),
            valid_s3: Default::default(),
            beat_s3: Default::default(),
            issue: Default::default(),
            code: vec_of(4),
            run_number: Default::default(),
            pos_in_word: Default::default(),
            word_pos_bits: kb((4 - l as u64) & 3),
            pos: (0..4).map(|i| kb(i as u64)).collect(),
            slot_off: (0..l).map(|i| kb(i as u64)).collect(),
            slot_used: (0..l).map(|i| kb(1u64 << (2 * i))).collect(),
            keep_n: (0..=4).map(|n| kb((1u64 << (2 * n)) - 1)).collect(),
            labels: (0..=4).map(|n| kb(n as u64)).collect(),
            code_empty: kb(CODE_EMPTY),
            max_in_flight: kb(QUEUE_BEATS as u64),
            lpb3: kb(l as u64),
            lpb20: kb(l as u64),
            one3: kb(1),
            zero3: kb(0),
            zero8: kb(0),
            one20: kb(1),
            zero20: kb(0),
            _l: l,
        }
    }
}

impl Logic for FccRbPipeline {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            active,
            pixel,
            beats_left,
            last_next,
            first_next,
            in_flight,
            beat_done_q,
            valid_s1,
            word_pos_s1,
            labels_s1,
            last_s1,
            first_s1,
            valid_s2,
            word_pos_s2,
            keep_s2,
            last_s2,
            first_s2,
            valid_s3,
            beat_s3
        );
        // ---- Stage 0: issue the frame-buffer read of the next beat. A beat
        // that has left frees its place a cycle late (`beat_done_q`), so the
        // output handshake does not reach this decision. Cycles are those of
        // four places freed at once: the n-th beat is issued at the latest
        // in the cycle after the (n-5)-th leaves, and reaches the queue's
        // head 4 cycles after its issue, which is no later than the cycle
        // after the (n-1)-th leaves (at least 4 cycles after the (n-5)-th),
        // the first cycle the n-th could leave anyway.
        self.beat_done_q.d.next = self.beat_done.val();
        self.issue.next = self.active.q.val()
            & ((self.in_flight.q.val() < self.max_in_flight.val()) | self.beat_done_q.q.val());
        self.read_en.next = self.issue.val();
        self.read_addr.next = self.pixel.q.val().get_bits::<17>(2);
        self.valid_s1.d.next = self.issue.val();
        if self.issue.val() {
            self.word_pos_s1.d.next =
                self.pixel.q.val().get_bits::<2>(0) & self.word_pos_bits.val();
            self.labels_s1.d.next = self.lpb3.val();
            self.last_s1.d.next = false;
            self.first_s1.d.next = self.first_next.q.val();
            self.first_next.d.next = false;
            if self.last_next.q.val() {
                self.labels_s1.d.next = self.last_beat_labels.val();
                self.last_s1.d.next = true;
                self.active.d.next = false;
            }
            self.pixel.d.next = self.pixel.q.val() + self.lpb20.val();
            self.beats_left.d.next = self.beats_left.q.val() - self.one20.val();
            self.last_next.d.next = self.beats_left.q.val() == self.one20.val();
        }
        if self.issue.val() & !self.beat_done_q.q.val() {
            self.in_flight.d.next = self.in_flight.q.val() + self.one3.val();
        }
        if !self.issue.val() & self.beat_done_q.q.val() {
            self.in_flight.d.next = self.in_flight.q.val() - self.one3.val();
        }
        // ---- Stage 1: the read is under way; the beat's `keep` mask (which
        // also flags the slots it uses) is decoded from its label count.
        self.valid_s2.d.next = self.valid_s1.q.val();
        self.word_pos_s2.d.next = self.word_pos_s1.q.val();
        self.keep_s2.d.next = self.keep_n[0].val();
        for n in 0..5 {
            if self.labels_s1.q.val() == self.labels[n].val() {
                self.keep_s2.d.next = self.keep_n[n].val();
            }
        }
        self.last_s2.d.next = self.last_s1.q.val();
        self.first_s2.d.next = self.first_s1.q.val();
        // ---- Stage 2: pick the beat's codes from the word, then number the
        // labelled runs that start in it (`FccRunNumber`).
        for i in 0..4 {
            self.code[i].next = self.code_empty.val();
        }
        for i in 0..self._l {
            self.pos_in_word.next = self.word_pos_s2.q.val() + self.slot_off[i].val();
            if self.pos_in_word.val() == self.pos[0].val() {
                self.code[i].next = self.read_data.val().s0;
            }
            if self.pos_in_word.val() == self.pos[1].val() {
                self.code[i].next = self.read_data.val().s1;
            }
            if self.pos_in_word.val() == self.pos[2].val() {
                self.code[i].next = self.read_data.val().s2;
            }
            if self.pos_in_word.val() == self.pos[3].val() {
                self.code[i].next = self.read_data.val().s3;
            }
            if (self.keep_s2.q.val() & self.slot_used[i].val()) == self.zero8.val() {
                self.code[i].next = self.code_empty.val();
            }
        }
        for i in 0..4 {
            self.run_number.code[i].next = self.code[i].val();
        }
        self.run_number.first.next = self.first_s2.q.val();
        self.valid_s3.d.next = self.valid_s2.q.val();
        self.beat_s3.d.next.s0 = self.run_number.src[0].val();
        self.beat_s3.d.next.s1 = self.run_number.src[1].val();
        self.beat_s3.d.next.s2 = self.run_number.src[2].val();
        self.beat_s3.d.next.s3 = self.run_number.src[3].val();
        self.beat_s3.d.next.run = self.run_number.run.val();
        self.beat_s3.d.next.need = self.run_number.need.val();
        self.beat_s3.d.next.keep = self.keep_s2.q.val();
        self.beat_s3.d.next.last = self.last_s2.q.val();
        self.beat_valid.next = self.valid_s3.q.val();
        self.beat.next = self.beat_s3.q.val();
        // ---- Start and reset.
        if self.start.val() {
            self.active.d.next = true;
            self.pixel.d.next = self.zero20.val();
            self.beats_left.d.next = self.beats_m1.val();
            self.last_next.d.next = self.beats_m1.val() == self.zero20.val();
            self.first_next.d.next = true;
            self.in_flight.d.next = self.zero3.val();
            self.beat_done_q.d.next = false;
            self.valid_s1.d.next = false;
            self.valid_s2.d.next = false;
            self.valid_s3.d.next = false;
        }
        if self.rst.val() {
            self.active.d.next = false;
            self.in_flight.d.next = self.zero3.val();
            self.beat_done_q.d.next = false;
            self.valid_s1.d.next = false;
            self.valid_s2.d.next = false;
            self.valid_s3.d.next = false;
        }
    }
}
