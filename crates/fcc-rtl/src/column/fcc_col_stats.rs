//! `FccColStats`: the column core's frame status, for the register file's
//! snapshot (taken as a frame's end beat leaves, `end_sent`):
//! - `records`, `overflow`, `frame_error`: the end beat's fields (spec §9.4;
//!   `clusters` is `records`, 0xFFFF for that many or more);
//! - `provisional`: the most provisional labels in use at once since the
//!   frame before ended (the label pool's labels less its free ones);
//! - `held`: the cycles a column's first pixel waited for the column-start
//!   check since the frame before ended (saturating).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::types::kb;

// The end beat's fields as `update` reads them (spec §9.4).
const _: () = {
    use fcc_pixel::record::END_LAYOUT;
    assert!(END_LAYOUT[1].lsb == 20 && END_LAYOUT[1].bits == 20);
    assert!(END_LAYOUT[2].lsb == 40 && END_LAYOUT[2].bits == 1);
    assert!(END_LAYOUT[3].lsb == 41 && END_LAYOUT[3].bits == 1);
};

#[derive(LogicBlock)]
pub struct FccColStats {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub end_sent: Signal<In, Bit>,
    /// Bits 41:20 of the end beat (valid with `end_sent`): `records`,
    /// `overflow`, `frame_error`.
    pub end_word: Signal<In, Bits<22>>,
    pub labels_free: Signal<In, Bits<16>>,
    pub col_held: Signal<In, Bit>,
    pub clusters: Signal<Out, Bits<16>>,
    pub overflow: Signal<Out, Bit>,
    pub frame_error: Signal<Out, Bit>,
    pub provisional: Signal<Out, Bits<16>>,
    pub held: Signal<Out, Bits<24>>,
    peak: DFF<Bits<16>>,
    stalls: DFF<Bits<24>>,
    in_use: Signal<Local, Bits<16>>,
    records: Signal<Local, Bits<20>>,
    labels: Constant<Bits<16>>,
    max16: Constant<Bits<20>>,
    max24: Constant<Bits<24>>,
    all16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    zero24: Constant<Bits<24>>,
    one24: Constant<Bits<24>>,
}

impl FccColStats {
    /// The build's label pool: labels `1 ..= 2^B - 1`.
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            end_sent: Default::default(),
            end_word: Default::default(),
            labels_free: Default::default(),
            col_held: Default::default(),
            clusters: Default::default(),
            overflow: Default::default(),
            frame_error: Default::default(),
            provisional: Default::default(),
            held: Default::default(),
            peak: Default::default(),
            stalls: Default::default(),
            in_use: Default::default(),
            records: Default::default(),
            labels: kb((1 << super::label_bits(p)) - 1),
            max16: kb(0xFFFF),
            max24: kb(0xFF_FFFF),
            all16: kb(0xFFFF),
            zero16: kb(0),
            zero24: kb(0),
            one24: kb(1),
        }
    }
}

impl Logic for FccColStats {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, peak, stalls);
        self.records.next = self.end_word.val().get_bits::<20>(0);
        self.clusters.next = self.records.val().get_bits::<16>(0);
        if self.records.val() > self.max16.val() {
            self.clusters.next = self.all16.val();
        }
        self.overflow.next = self.end_word.val().get_bit(20);
        self.frame_error.next = self.end_word.val().get_bit(21);
        self.in_use.next = self.labels.val() - self.labels_free.val();
        if self.in_use.val() > self.peak.q.val() {
            self.peak.d.next = self.in_use.val();
        }
        if self.col_held.val() & (self.stalls.q.val() != self.max24.val()) {
            self.stalls.d.next = self.stalls.q.val() + self.one24.val();
        }
        if self.end_sent.val() {
            self.peak.d.next = self.in_use.val();
            self.stalls.d.next = self.zero24.val();
            if self.col_held.val() {
                self.stalls.d.next = self.one24.val();
            }
        }
        if self.rst.val() {
            self.peak.d.next = self.zero16.val();
            self.stalls.d.next = self.zero24.val();
        }
        self.provisional.next = self.peak.q.val();
        self.held.next = self.stalls.q.val();
    }
}
