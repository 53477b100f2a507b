//! `FccColSlotBuf`: the buffer between the column core's front and the
//! blocks that can hold it (docs/column-core.md, item 8, "Where
//! back-pressure goes"). `FccColFront` cannot be held, so every slot it
//! sends (the centre with its hits and their labels) is pushed here, and
//! the input takes a slot only while a credit is left: a credit is taken
//! by each slot the input stage takes (`slot`) and returned when the slot
//! leaves the buffer (`take` while `valid`). [`SLOT_CREDITS`] is the
//! buffer's size less the slots that can still enter after `room` falls
//! (it is registered, and so is the ready it gates), so the buffer never
//! overflows.
//!
//! A stream FIFO (`FccStreamFifo`'s blocks) of several lanes
//! (`FccStreamLane`) under one control (`FccStreamCtl`), so they stay in
//! step: the centre (`RunPix`), the hits as a mask, the labels four to a
//! word (`FccQuadLane`). A slot pushed at `t` is at the head at `t + 4` at
//! the soonest, and one leaves every cycle while `take` is high.
//!
//! The size: a slot taken at the input is at the buffer's head
//! `FRONT_LATENCY + 5` cycles later at the soonest (the stage's register,
//! the front, the buffer's four), and the input starts
//! again two cycles after a credit comes back, so with more credits than
//! that round trip slots flow one a cycle while the consumer takes them,
//! and after a hold the slots buffered cover the input's restart.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_front::FRONT_LATENCY;
use super::fcc_quad_lane::FccQuadLane;
use super::RunPix;
use crate::fcc_credits::FccCredits;
use crate::fcc_stream_ctl::FccStreamCtl;
use crate::fcc_stream_lane::FccStreamLane;
use crate::types::{kb, vec_of};

/// Address bits of the buffer.
pub const SLOT_BUF_BITS: usize = 6;
/// Slots the buffer holds.
pub const SLOT_BUF: usize = 1 << SLOT_BUF_BITS;
/// Credits: the buffer less the slots that enter after `room` falls.
pub const SLOT_CREDITS: usize = SLOT_BUF - 4;

// A credit's round trip fits: the input stage's two registers, the
// front, the buffer's four cycles to its head, `room` and the ready.
const _: () = assert!(SLOT_CREDITS >= FRONT_LATENCY + 8);
// Two slots can enter after the credits run out (`room` and the ready it
// gates are registered): the buffer holds them.
const _: () = assert!(SLOT_CREDITS + 2 <= SLOT_BUF);

type Lane<T> = FccStreamLane<T, SLOT_BUF_BITS>;

#[derive(LogicBlock)]
pub struct FccColSlotBuf {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The input stage takes a slot (a credit).
    pub slot: Signal<In, Bit>,
    /// A credit is left (registered): the input stage's `room`.
    pub room: Signal<Out, Bit>,
    /// The front's output: pushed while `in_centre.valid`.
    pub in_centre: Signal<In, RunPix>,
    pub in_hit: Vec<Signal<In, Bit>>,
    pub in_label: Vec<Signal<In, Bits<16>>>,
    /// The head, and `take` (while `valid`) lets it go.
    pub valid: Signal<Out, Bit>,
    pub centre: Signal<Out, RunPix>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub hit_label: Vec<Signal<Out, Bits<16>>>,
    pub take: Signal<In, Bit>,
    credits: FccCredits,
    ctl: FccStreamCtl<SLOT_BUF_BITS, { SLOT_BUF_BITS + 1 }>,
    pix: Lane<RunPix>,
    hits: Lane<Bits<64>>,
    labels: Vec<FccQuadLane>,
    /// The mask so far: entries below `e` at `acc[e]`.
    acc: Vec<Signal<Local, Bits<64>>>,
    onehot: Vec<Constant<Bits<64>>>,
    /// The entries' labels, zeros past the last.
    lab: Vec<Signal<Local, Bits<16>>>,
    /// Zero for the last word's unused labels (none when the entries fill
    /// whole words, as at K = 9).
    zero16: Vec<Constant<Bits<16>>>,
    zero64: Constant<Bits<64>>,
    _n: usize,
}

impl FccColSlotBuf {
    /// The buffer of the build's window (`K x h` entries).
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(n <= 64, "{n} window entries do not fit the hits' lane");
        let w = n.div_ceil(4);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            slot: Default::default(),
            room: Default::default(),
            in_centre: Default::default(),
            in_hit: vec_of(n),
            in_label: vec_of(n),
            valid: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            hit_label: vec_of(n),
            take: Default::default(),
            credits: FccCredits::with_limit(SLOT_CREDITS),
            ctl: Default::default(),
            pix: Default::default(),
            hits: Default::default(),
            labels: (0..w).map(|_| Default::default()).collect(),
            acc: vec_of(n + 1),
            onehot: (0..n).map(|e| kb(1u64 << e)).collect(),
            lab: vec_of(4 * w),
            zero16: (n < 4 * w).then(|| kb(0)).into_iter().collect(),
            zero64: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccColSlotBuf {
    #[hdl_gen]
    fn update(&mut self) {
        self.credits.clk.next = self.clk.val();
        self.credits.rst.next = self.rst.val();
        self.credits.slot.next = self.slot.val();
        // A slot comes back as its entry leaves (the control's pop).
        self.credits.take.next = self.ctl.shift.val();
        self.credits.drop.next = false;
        self.room.next = self.credits.room.val();
        // The one control.
        self.ctl.clk.next = self.clk.val();
        self.ctl.rst.next = self.rst.val();
        self.ctl.push.next = self.in_centre.val().valid;
        self.ctl.take.next = self.take.val();
        self.valid.next = self.ctl.valid.val();
        // The centre's lane.
        self.pix.clk.next = self.clk.val();
        self.pix.we.next = self.in_centre.val().valid;
        self.pix.waddr.next = self.ctl.ram_waddr.val();
        self.pix.din.next = self.in_centre.val();
        self.pix.re.next = self.ctl.ram_re.val();
        self.pix.raddr.next = self.ctl.ram_raddr.val();
        self.pix.shift.next = self.ctl.shift.val();
        self.pix.load.next = self.ctl.load.val();
        self.centre.next = self.pix.dout.val();
        // The hits as a mask.
        self.acc[0].next = self.zero64.val();
        for e in 0..self._n {
            self.acc[e + 1].next = self.acc[e].val();
            if self.in_hit[e].val() {
                self.acc[e + 1].next = self.acc[e].val() | self.onehot[e].val();
            }
        }
        self.hits.clk.next = self.clk.val();
        self.hits.we.next = self.in_centre.val().valid;
        self.hits.waddr.next = self.ctl.ram_waddr.val();
        for e in (self._n)..(self._n + 1) {
            self.hits.din.next = self.acc[e].val();
        }
        self.hits.re.next = self.ctl.ram_re.val();
        self.hits.raddr.next = self.ctl.ram_raddr.val();
        self.hits.shift.next = self.ctl.shift.val();
        self.hits.load.next = self.ctl.load.val();
        for e in 0..self._n {
            self.hit[e].next = self.hits.dout.val().get_bit(e);
        }
        // The labels, four to a word.
        for e in 0..self._n {
            self.lab[e].next = self.in_label[e].val();
        }
        for e in (self._n)..(self.lab.len()) {
            self.lab[e].next = self.zero16[0].val();
        }
        for w in 0..self.labels.len() {
            self.labels[w].clk.next = self.clk.val();
            self.labels[w].we.next = self.in_centre.val().valid;
            self.labels[w].waddr.next = self.ctl.ram_waddr.val();
            self.labels[w].re.next = self.ctl.ram_re.val();
            self.labels[w].raddr.next = self.ctl.ram_raddr.val();
            self.labels[w].shift.next = self.ctl.shift.val();
            self.labels[w].load.next = self.ctl.load.val();
            self.labels[w].l0.next = self.lab[w * 4].val();
            self.labels[w].l1.next = self.lab[w * 4 + 1].val();
            self.labels[w].l2.next = self.lab[w * 4 + 2].val();
            self.labels[w].l3.next = self.lab[w * 4 + 3].val();
        }
        for w in 0..(self._n / 4) {
            self.hit_label[w * 4].next = self.labels[w].o0.val();
            self.hit_label[w * 4 + 1].next = self.labels[w].o1.val();
            self.hit_label[w * 4 + 2].next = self.labels[w].o2.val();
            self.hit_label[w * 4 + 3].next = self.labels[w].o3.val();
        }
        // The last word's entries, `K x h mod 4` of them.
        for w in (self._n / 4)..(self.labels.len()) {
            self.hit_label[w * 4].next = self.labels[w].o0.val();
        }
        for w in (self._n / 4)..((self._n + 2) / 4) {
            self.hit_label[w * 4 + 1].next = self.labels[w].o1.val();
        }
        for w in (self._n / 4)..((self._n + 1) / 4) {
            self.hit_label[w * 4 + 2].next = self.labels[w].o2.val();
        }
    }
}
