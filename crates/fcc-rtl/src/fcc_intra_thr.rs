//! `fcc_intra_thr`: the pair thresholds of `fcc_intra`'s two distance units
//! (spec §2): a pair's addend is the one of its point with the smaller key
//! (`rc2`; equal keys have equal thresholds).
//!
//! Timing: the controls arrive with the pixel at N0 and wait two cycles for
//! the pixel's thresholds (`key`, `ch`, from `fcc_pix_thr`, `THR_LAG` = 2
//! cycles behind it); `near_c` and `ring_c` are registered, valid in N3,
//! when `FccSqDist` adds them. The previous valid point's and the row's
//! first valid point's thresholds are kept here, loaded two cycles after
//! `fcc_intra` loads their coordinates.
//! * near: the pixel against the previous valid point;
//! * ring: the row's first valid point (the pixel itself when it is the
//!   first) against its last (the pixel itself when it holds a point).

use rust_hdl::prelude::*;

use crate::fcc_pix_thr::THR_LAG;

// The controls' delay below is written out for two cycles.
const _: () = assert!(THR_LAG == 2);

#[derive(LogicBlock)]
pub struct FccIntraThr {
    pub clk: Signal<In, Clock>,
    // N0 controls (as `fcc_intra` computes them).
    /// A valid point: it becomes the previous point.
    pub prev_load: Signal<In, Bit>,
    /// The row's first valid point: it becomes the first point.
    pub first_load: Signal<In, Bit>,
    /// The ring's first operand is the pixel itself.
    pub ring_first: Signal<In, Bit>,
    /// The pixel holds a point: the ring's second operand is the pixel.
    pub ok: Signal<In, Bit>,
    // N2: the pixel's key and `-(T'_H + 1)`.
    pub key: Signal<In, Bits<16>>,
    pub ch: Signal<In, Bits<36>>,
    // N3: the addends of the two distance units.
    pub near_c: Signal<Out, Bits<36>>,
    pub ring_c: Signal<Out, Bits<36>>,
    prev_load_d: Vec<DFF<Bit>>,
    first_load_d: Vec<DFF<Bit>>,
    ring_first_d: Vec<DFF<Bit>>,
    ok_d: Vec<DFF<Bit>>,
    prev_key: DFF<Bits<16>>,
    prev_ch: DFF<Bits<36>>,
    first_key: DFF<Bits<16>>,
    first_ch: DFF<Bits<36>>,
    near_q: DFF<Bits<36>>,
    ring_q: DFF<Bits<36>>,
    a_key: Signal<Local, Bits<16>>,
    a_ch: Signal<Local, Bits<36>>,
    b_key: Signal<Local, Bits<16>>,
    b_ch: Signal<Local, Bits<36>>,
}

impl FccIntraThr {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            prev_load: Default::default(),
            first_load: Default::default(),
            ring_first: Default::default(),
            ok: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            near_c: Default::default(),
            ring_c: Default::default(),
            prev_load_d: (0..2).map(|_| Default::default()).collect(),
            first_load_d: (0..2).map(|_| Default::default()).collect(),
            ring_first_d: (0..2).map(|_| Default::default()).collect(),
            ok_d: (0..2).map(|_| Default::default()).collect(),
            prev_key: Default::default(),
            prev_ch: Default::default(),
            first_key: Default::default(),
            first_ch: Default::default(),
            near_q: Default::default(),
            ring_q: Default::default(),
            a_key: Default::default(),
            a_ch: Default::default(),
            b_key: Default::default(),
            b_ch: Default::default(),
        }
    }
}

impl Default for FccIntraThr {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccIntraThr {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, prev_key, prev_ch, first_key, first_ch, near_q, ring_q);
        for i in 0..2 {
            self.prev_load_d[i].clock.next = self.clk.val();
            self.first_load_d[i].clock.next = self.clk.val();
            self.ring_first_d[i].clock.next = self.clk.val();
            self.ok_d[i].clock.next = self.clk.val();
        }
        self.prev_load_d[0].d.next = self.prev_load.val();
        self.first_load_d[0].d.next = self.first_load.val();
        self.ring_first_d[0].d.next = self.ring_first.val();
        self.ok_d[0].d.next = self.ok.val();
        self.prev_load_d[1].d.next = self.prev_load_d[0].q.val();
        self.first_load_d[1].d.next = self.first_load_d[0].q.val();
        self.ring_first_d[1].d.next = self.ring_first_d[0].q.val();
        self.ok_d[1].d.next = self.ok_d[0].q.val();
        // ---- N2: keep the points' thresholds; pick each pair's.
        if self.prev_load_d[1].q.val() {
            self.prev_key.d.next = self.key.val();
            self.prev_ch.d.next = self.ch.val();
        }
        if self.first_load_d[1].q.val() {
            self.first_key.d.next = self.key.val();
            self.first_ch.d.next = self.ch.val();
        }
        self.near_q.d.next = self.prev_ch.q.val();
        if self.key.val() <= self.prev_key.q.val() {
            self.near_q.d.next = self.ch.val();
        }
        self.a_key.next = self.first_key.q.val();
        self.a_ch.next = self.first_ch.q.val();
        if self.ring_first_d[1].q.val() {
            self.a_key.next = self.key.val();
            self.a_ch.next = self.ch.val();
        }
        self.b_key.next = self.prev_key.q.val();
        self.b_ch.next = self.prev_ch.q.val();
        if self.ok_d[1].q.val() {
            self.b_key.next = self.key.val();
            self.b_ch.next = self.ch.val();
        }
        self.ring_q.d.next = self.b_ch.val();
        if self.a_key.val() <= self.b_key.val() {
            self.ring_q.d.next = self.a_ch.val();
        }
        // ---- N3.
        self.near_c.next = self.near_q.q.val();
        self.ring_c.next = self.ring_q.q.val();
    }
}
