//! `fcc_fb_writer`: packs the labelled pixel stream's 2-bit frame-buffer codes
//! four to a word and writes the word when it is full or the frame ends; at
//! the frame's last pixel it records the frame's geometry for the read-back.

use rust_hdl::prelude::*;

use crate::types::{kb, FbWord};

#[derive(LogicBlock)]
pub struct FccFbWriter {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The labelled pixel stream (no back-pressure).
    pub pixel_valid: Signal<In, Bit>,
    pub pixel_code: Signal<In, Bits<2>>,
    pub pixel_last: Signal<In, Bit>,
    // Frame-buffer write port.
    pub write_en: Signal<Out, Bit>,
    pub write_addr: Signal<Out, Bits<17>>,
    pub write_data: Signal<Out, FbWord>,
    /// The last frame's beats less one, and labels in its last beat (1 .. L).
    pub beats_m1: Signal<Out, Bits<20>>,
    pub last_beat_labels: Signal<Out, Bits<3>>,
    /// Codes of the word's first three pixels, as they arrive.
    code0: DFF<Bits<2>>,
    code1: DFF<Bits<2>>,
    code2: DFF<Bits<2>>,
    /// Position of the next pixel in its word.
    word_pos: DFF<Bits<2>>,
    word_addr: DFF<Bits<17>>,
    /// Pixels of this frame so far (at its last pixel, the pixels less one).
    pixel_count: DFF<Bits<20>>,
    frame_beats_m1: DFF<Bits<20>>,
    frame_last_labels: DFF<Bits<3>>,
    /// Pixels of the last beat less one.
    last_beat_pos: Signal<Local, Bits<2>>,
    pos: Vec<Constant<Bits<2>>>,
    /// `last_labels[i]`: i + 1 labels.
    last_labels: Vec<Constant<Bits<3>>>,
    /// log2 of the labels per beat; labels per beat less one.
    lpb_log: Constant<Bits<2>>,
    lpb_m1: Constant<Bits<2>>,
    one17: Constant<Bits<17>>,
    zero17: Constant<Bits<17>>,
    one20: Constant<Bits<20>>,
    zero20: Constant<Bits<20>>,
}

impl FccFbWriter {
    /// `labels_per_beat`: 1, 2 or 4.
    pub fn new(labels_per_beat: usize) -> Self {
        assert!(matches!(labels_per_beat, 1 | 2 | 4));
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pixel_valid: Default::default(),
            pixel_code: Default::default(),
            pixel_last: Default::default(),
            write_en: Default::default(),
            write_addr: Default::default(),
            write_data: Default::default(),
            beats_m1: Default::default(),
            last_beat_labels: Default::default(),
            code0: Default::default(),
            code1: Default::default(),
            code2: Default::default(),
            word_pos: Default::default(),
            word_addr: Default::default(),
            pixel_count: Default::default(),
            frame_beats_m1: Default::default(),
            frame_last_labels: Default::default(),
            last_beat_pos: Default::default(),
            pos: (0..4).map(|i| kb(i as u64)).collect(),
            last_labels: (1..=4).map(|n| kb(n as u64)).collect(),
            lpb_log: kb(u64::from(labels_per_beat.trailing_zeros())),
            lpb_m1: kb(labels_per_beat as u64 - 1),
            one17: kb(1),
            zero17: kb(0),
            one20: kb(1),
            zero20: kb(0),
        }
    }
}

impl Logic for FccFbWriter {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            code0,
            code1,
            code2,
            word_pos,
            word_addr,
            pixel_count,
            frame_beats_m1,
            frame_last_labels
        );
        self.last_beat_pos.next = self.pixel_count.q.val().get_bits::<2>(0) & self.lpb_m1.val();
        self.write_en.next = false;
        self.write_addr.next = self.word_addr.q.val();
        self.write_data.next.s0 = self.code0.q.val();
        self.write_data.next.s1 = self.code1.q.val();
        self.write_data.next.s2 = self.code2.q.val();
        self.write_data.next.s3 = self.pixel_code.val();
        if self.word_pos.q.val() == self.pos[0].val() {
            self.write_data.next.s0 = self.pixel_code.val();
        }
        if self.word_pos.q.val() == self.pos[1].val() {
            self.write_data.next.s1 = self.pixel_code.val();
        }
        if self.word_pos.q.val() == self.pos[2].val() {
            self.write_data.next.s2 = self.pixel_code.val();
        }
        if self.pixel_valid.val() {
            if self.word_pos.q.val() == self.pos[0].val() {
                self.code0.d.next = self.pixel_code.val();
            }
            if self.word_pos.q.val() == self.pos[1].val() {
                self.code1.d.next = self.pixel_code.val();
            }
            if self.word_pos.q.val() == self.pos[2].val() {
                self.code2.d.next = self.pixel_code.val();
            }
            self.word_pos.d.next = self.word_pos.q.val() + self.pos[1].val();
            if (self.word_pos.q.val() == self.pos[3].val()) | self.pixel_last.val() {
                self.write_en.next = true;
                self.word_addr.d.next = self.word_addr.q.val() + self.one17.val();
            }
            self.pixel_count.d.next = self.pixel_count.q.val() + self.one20.val();
            if self.pixel_last.val() {
                self.word_pos.d.next = self.pos[0].val();
                self.word_addr.d.next = self.zero17.val();
                // `pixel_count` is the frame's pixels less one (L is a power of two).
                self.pixel_count.d.next = self.zero20.val();
                self.frame_beats_m1.d.next = self.pixel_count.q.val() >> self.lpb_log.val();
                self.frame_last_labels.d.next = self.last_labels[0].val();
                if self.last_beat_pos.val() == self.pos[1].val() {
                    self.frame_last_labels.d.next = self.last_labels[1].val();
                }
                if self.last_beat_pos.val() == self.pos[2].val() {
                    self.frame_last_labels.d.next = self.last_labels[2].val();
                }
                if self.last_beat_pos.val() == self.pos[3].val() {
                    self.frame_last_labels.d.next = self.last_labels[3].val();
                }
            }
        }
        if self.rst.val() {
            self.word_pos.d.next = self.pos[0].val();
            self.word_addr.d.next = self.zero17.val();
            self.pixel_count.d.next = self.zero20.val();
        }
        self.beats_m1.next = self.frame_beats_m1.q.val();
        self.last_beat_labels.next = self.frame_last_labels.q.val();
    }
}
