//! `fcc_intra`: the intra-channel processor.
//!
//! Each pixel is compared with the previous *valid* pixel of its row (empty
//! pixels neither break nor start a run). A squared distance `<= tH^2`
//! continues the current run, otherwise the next provisional label is taken
//! (1, 2, ... in raster order over the frame; when `2^B - 1` are used, a new
//! run gets label 0 and the overflow flag is set). At the row's last pixel the
//! ring check joins the row's first and last runs when their end points are
//! within `tH`.
//!
//! Pipeline (no enable: bubbles travel as slots with `valid` low):
//! * N0: the pixel against the row's previous valid point (`near`) and the
//!   row's first valid point against its last (`ring`), both `FccSqDist`,
//!   each with its pair's threshold (spec §2: the pixel's own, `key` and
//!   `ch`, arrive in N2; `FccIntraThr` picks each pair's for N3, when the
//!   distance units add it).
//! * N7: the label decision. The next label is a 20-bit counter that keeps
//!   counting past the last provisional label, so the decision is one add and
//!   two multiplexers; whether a label fits is checked one stage later (labels
//!   are allocated in order, so "raw label > 2^B - 1" is exactly "labels ran out").
//! * N8: the range and ring comparisons; N9: the output codes (both in
//!   `FccIntraCodes`); `out` and its frame-buffer code `state` are
//!   registered, ten cycles after `pix`. The window's read column
//!   `(j + h) mod C` (`rdcol`) follows the frame's columns (`last_col`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_intra_codes::FccIntraCodes;
use crate::fcc_intra_thr::FccIntraThr;
use crate::fcc_sq_dist::{FccSqDist, SQ_LATENCY};
use crate::types::{kb, Pix, WinPix};

// The delay line below is written out for seven stages.
const _: () = assert!(SQ_LATENCY == 7);

#[derive(LogicBlock)]
pub struct FccIntra {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub pix: Signal<In, Pix>,
    /// The frame's last column, C - 1 (stable while a frame runs).
    pub last_col: Signal<In, Bits<12>>,
    /// Two cycles after `pix` (N2): its key and `-(T'_H + 1)` (36-bit two's
    /// complement, from `fcc_pix_thr`).
    pub key: Signal<In, Bits<16>>,
    pub ch: Signal<In, Bits<36>>,
    pub out: Signal<Out, WinPix>,
    /// The pixel's frame-buffer code (with `out`).
    pub state: Signal<Out, Bits<2>>,
    // Status of the frame in progress (stable after its last pixel).
    pub provisional: Signal<Out, Bits<17>>,
    pub overflow: Signal<Out, Bit>,
    pub unlabelled: Signal<Out, Bits<20>>,
    // N0: previous valid point of the row and the row's first valid point.
    prev_x: DFF<Bits<16>>,
    prev_y: DFF<Bits<16>>,
    prev_z: DFF<Bits<16>>,
    has_prev: DFF<Bit>,
    first_x: DFF<Bits<16>>,
    first_y: DFF<Bits<16>>,
    first_z: DFF<Bits<16>>,
    near: FccSqDist,
    ring: FccSqDist,
    thr: FccIntraThr,
    // Delay line N1 .. N7, aligned with the distance units.
    pd: Vec<DFF<Pix>>,
    fvd: Vec<DFF<Bit>>,
    // N7: labelling state.
    raw: DFF<Bits<20>>,
    cur: DFF<Bits<20>>,
    fl: DFF<Bits<20>>,
    any: DFF<Bit>,
    // N8, N9: the output codes.
    codes: FccIntraCodes,
    // Status.
    rm1: DFF<Bits<20>>,
    prov: DFF<Bits<17>>,
    ovf: DFF<Bit>,
    // Combinational helpers.
    hp_eff: Signal<Local, Bit>,
    /// The row's first valid point: loads `first_*` (and `fvd`).
    fv0: Signal<Local, Bit>,
    /// The ring's first operand is the incoming point: `fv0` without
    /// `valid` (the ring's result only counts for a valid point), so that
    /// the operand select and the `first_*` enables are two nets of 48
    /// loads, not one of 96.
    ring_first: Signal<Local, Bit>,
    /// A valid point with coordinates: loads `prev_*` (an enable of its own,
    /// so that the pixel's `valid` is not the enable of every point register).
    prev_load: Signal<Local, Bit>,
    p7: Signal<Local, Pix>,
    cont: Signal<Local, Bit>,
    nl: Signal<Local, Bits<20>>,
    newrun: Signal<Local, Bit>,
    lab: Signal<Local, Bits<20>>,
    fl_eff: Signal<Local, Bits<20>>,
    cur_next: Signal<Local, Bits<20>>,
    any_eff: Signal<Local, Bit>,
    // Constants.
    pix_zero: Constant<Pix>,
    one20: Constant<Bits<20>>,
    max20: Constant<Bits<20>>,
    max17: Constant<Bits<17>>,
}

impl FccIntra {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pix: Default::default(),
            last_col: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            out: Default::default(),
            state: Default::default(),
            provisional: Default::default(),
            overflow: Default::default(),
            unlabelled: Default::default(),
            prev_x: Default::default(),
            prev_y: Default::default(),
            prev_z: Default::default(),
            has_prev: Default::default(),
            first_x: Default::default(),
            first_y: Default::default(),
            first_z: Default::default(),
            near: FccSqDist::new(),
            ring: FccSqDist::new(),
            thr: FccIntraThr::new(),
            pd: (0..SQ_LATENCY).map(|_| Default::default()).collect(),
            fvd: (0..SQ_LATENCY).map(|_| Default::default()).collect(),
            raw: Default::default(),
            cur: Default::default(),
            fl: Default::default(),
            any: Default::default(),
            codes: FccIntraCodes::new(p),
            rm1: Default::default(),
            prov: Default::default(),
            ovf: Default::default(),
            hp_eff: Default::default(),
            fv0: Default::default(),
            ring_first: Default::default(),
            prev_load: Default::default(),
            p7: Default::default(),
            cont: Default::default(),
            nl: Default::default(),
            newrun: Default::default(),
            lab: Default::default(),
            fl_eff: Default::default(),
            cur_next: Default::default(),
            any_eff: Default::default(),
            pix_zero: Constant::new(Pix::default()),
            one20: kb(1),
            max20: kb(u64::from(p.max_label())),
            max17: kb(u64::from(p.max_label())),
        }
    }
}

impl Logic for FccIntra {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, prev_x, prev_y, prev_z, has_prev, first_x, first_y, first_z, raw, cur, fl,
            any, rm1, prov, ovf
        );
        for i in 0..7 {
            self.pd[i].clock.next = self.clk.val();
            self.fvd[i].clock.next = self.clk.val();
        }
        // ---- N0: the incoming pixel against the row's previous valid pixel.
        self.hp_eff.next = !self.pix.val().col0 & self.has_prev.q.val();
        self.fv0.next = self.pix.val().valid & self.pix.val().ok & !self.hp_eff.val();
        self.ring_first.next = self.pix.val().ok & !self.hp_eff.val();
        self.prev_load.next = self.pix.val().valid & self.pix.val().ok;
        self.near.clk.next = self.clk.val();
        self.near.ax.next = self.pix.val().x;
        self.near.ay.next = self.pix.val().y;
        self.near.az.next = self.pix.val().z;
        self.near.bx.next = self.prev_x.q.val();
        self.near.by.next = self.prev_y.q.val();
        self.near.bz.next = self.prev_z.q.val();
        self.near.en_in.next = self.pix.val().valid & self.pix.val().ok & self.hp_eff.val();
        self.thr.clk.next = self.clk.val();
        self.thr.prev_load.next = self.prev_load.val();
        self.thr.first_load.next = self.fv0.val();
        self.thr.ring_first.next = self.ring_first.val();
        self.thr.ok.next = self.pix.val().ok;
        self.thr.key.next = self.key.val();
        self.thr.ch.next = self.ch.val();
        self.near.c.next = self.thr.near_c.val();
        self.ring.c.next = self.thr.ring_c.val();
        // Ring: the row's first valid point against its last valid point.
        self.ring.clk.next = self.clk.val();
        self.ring.en_in.next = true;
        self.ring.ax.next = self.first_x.q.val();
        self.ring.ay.next = self.first_y.q.val();
        self.ring.az.next = self.first_z.q.val();
        if self.ring_first.val() {
            self.ring.ax.next = self.pix.val().x;
            self.ring.ay.next = self.pix.val().y;
            self.ring.az.next = self.pix.val().z;
        }
        self.ring.bx.next = self.prev_x.q.val();
        self.ring.by.next = self.prev_y.q.val();
        self.ring.bz.next = self.prev_z.q.val();
        if self.pix.val().ok {
            self.ring.bx.next = self.pix.val().x;
            self.ring.by.next = self.pix.val().y;
            self.ring.bz.next = self.pix.val().z;
        }
        if self.pix.val().valid {
            self.has_prev.d.next = self.pix.val().ok | self.hp_eff.val();
        }
        if self.prev_load.val() {
            self.prev_x.d.next = self.pix.val().x;
            self.prev_y.d.next = self.pix.val().y;
            self.prev_z.d.next = self.pix.val().z;
        }
        if self.fv0.val() {
            self.first_x.d.next = self.pix.val().x;
            self.first_y.d.next = self.pix.val().y;
            self.first_z.d.next = self.pix.val().z;
        }
        // ---- N1 .. N7: delay line.
        self.pd[0].d.next = self.pix.val();
        self.fvd[0].d.next = self.fv0.val();
        for i in 1..7 {
            self.pd[i].d.next = self.pd[i - 1].q.val();
            self.fvd[i].d.next = self.fvd[i - 1].q.val();
        }
        // ---- N7: decide the label (raw: may exceed the last provisional label).
        self.p7.next = self.pd[6].q.val();
        self.cont.next = self.near.hit.val();
        self.nl.next = self.raw.q.val();
        if self.p7.val().first {
            self.nl.next = self.one20.val();
        }
        self.newrun.next = self.p7.val().valid & self.p7.val().ok & !self.cont.val();
        self.lab.next = self.nl.val();
        if self.cont.val() {
            self.lab.next = self.cur.q.val();
        }
        self.cur_next.next = self.cur.q.val();
        if self.p7.val().valid & self.p7.val().ok {
            self.cur_next.next = self.lab.val();
        }
        self.fl_eff.next = self.fl.q.val();
        if self.fvd[6].q.val() {
            self.fl_eff.next = self.lab.val();
        }
        self.any_eff.next =
            (!self.p7.val().col0 & self.any.q.val()) | (self.p7.val().valid & self.p7.val().ok);
        if self.p7.val().valid {
            self.raw.d.next = self.nl.val();
            if self.newrun.val() {
                self.raw.d.next = self.nl.val() + self.one20.val();
            }
            self.cur.d.next = self.cur_next.val();
            self.fl.d.next = self.fl_eff.val();
            self.any.d.next = self.any_eff.val();
        }
        self.codes.clk.next = self.clk.val();
        self.codes.rst.next = self.rst.val();
        self.codes.last_col.next = self.last_col.val();
        self.codes.pix.next = self.p7.val();
        self.codes.cont.next = self.cont.val();
        self.codes.lab.next = self.lab.val();
        self.codes.fl.next = self.fl_eff.val();
        self.codes.cur.next = self.cur_next.val();
        self.codes.any.next = self.any_eff.val();
        self.codes.ring_hit.next = self.ring.hit.val();
        // ---- Status: labels used = min(raw - 1, 2^B - 1).
        self.rm1.d.next = self.raw.q.val() - self.one20.val();
        self.prov.d.next = self.rm1.q.val().get_bits::<17>(0);
        self.ovf.d.next = false;
        if self.rm1.q.val() > self.max20.val() {
            self.prov.d.next = self.max17.val();
            self.ovf.d.next = true;
        }
        if self.rst.val() {
            self.has_prev.d.next = false;
            self.pd[0].d.next.valid = false;
            self.pd[1].d.next.valid = false;
            self.pd[2].d.next.valid = false;
            self.pd[3].d.next.valid = false;
            self.pd[4].d.next.valid = false;
            self.pd[5].d.next.valid = false;
            // The whole last stage is reset, so that it stays a flip-flop
            // (a shift-register LUT's output is slow).
            self.pd[6].d.next = self.pix_zero.val();
        }
        self.out.next = self.codes.out.val();
        self.state.next = self.codes.state.val();
        self.provisional.next = self.prov.q.val();
        self.overflow.next = self.ovf.q.val();
        self.unlabelled.next = self.codes.unlabelled.val();
    }
}
