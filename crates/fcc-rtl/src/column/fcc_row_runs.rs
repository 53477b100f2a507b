//! `FccRowRuns`: pass 1 of the column core (spec §3 in column order), with
//! the per-row state the closing rule needs (spec §9.2).
//!
//! In column order the consecutive valid pixels of a row arrive `R` pixel
//! slots apart, so each row keeps its latest and first valid pixel in a
//! table of `R` entries: points and thresholds in one RAM, written as soon
//! as the entry is read; labels in another, written when the label is
//! decided. Every slot of the frame visits its row (empty pixels too), so
//! a row's next read comes `R` slots (at least `HW_ROWS` minimum) after its
//! last write: no forwarding.
//!
//! Pipeline (no enable: bubbles travel as slots with `valid` low):
//! * N0: the pixel reads its row's entry (`FccRam`, two cycles).
//! * N1: the last column the bridge would reach from the pixel.
//! * N2: its key and addend arrive (`FccPixThr`, `THR_LAG` behind the
//!   slot); `FccRowEntry` writes the new points back and starts the pass-1
//!   test (`FccSqDist`, seven cycles; its hit waits one more).
//! * N3: the ring check starts on the new entry's first and last points,
//!   registered; each test's addend is the one of its point with the
//!   smaller key, as `FccIntraThr` picks it (spec §2), added in N5 (pass 1)
//!   and N6 (ring).
//! * N10: `FccRunDecide` decides the label, pops the free list (`take`,
//!   combinational from `free_ok` and `free_label`, and from `FccOpenRoom`'s
//!   open limit) and writes the labels back; `out` is registered, eleven
//!   cycles after `pix`.

use fcc_params::limits;
use rust_hdl::prelude::*;

use super::fcc_open_room::{FccOpenRoom, OPEN_ROOM_BITS};
use super::fcc_row_entry::FccRowEntry;
use super::fcc_run_decide::FccRunDecide;
use super::{ColPix, RowLabs, RowPts, RunCtl, RunPix};
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_pix_thr::THR_LAG;
use crate::fcc_ram::FccRam;
use crate::fcc_sq_dist::{FccSqDist, SQ_LATENCY};
use crate::types::{kb, vec_of};

/// Cycles from `pix` to `out`.
pub const RUNS_LATENCY: usize = 4 + SQ_LATENCY;

// The stages below are written out for these latencies (the table's read,
// the thresholds' lag, the distance units'), and a row's next read must
// come after its labels are written (N10).
const _: () = assert!(THR_LAG == 2 && SQ_LATENCY == 7);
const _: () = assert!(*limits::HW_ROWS.start() > RUNS_LATENCY);

/// Address bits of the per-row table (`HW_ROWS` at most 128): the width of
/// a slot's row.
const ROW_BITS: usize = 7;
const _: () = assert!(*limits::HW_ROWS.end() <= 1 << ROW_BITS);

#[derive(LogicBlock)]
pub struct FccRowRuns {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Pixel slots in column order.
    pub pix: Signal<In, ColPix>,
    /// `THR_LAG` cycles after `pix`: its key, `-(T'_H + 1)` and `-T'_V`
    /// (carried on to `out` for pass 2).
    pub key: Signal<In, Bits<16>>,
    pub ch: Signal<In, Bits<36>>,
    pub cv: Signal<In, Bits<36>>,
    /// Run parameters (see `FccRowEntry`): the last column `C - 1`, the
    /// bridge limit, the ring reach.
    pub last_col: Signal<In, Bits<12>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    /// The free list of labels: its head (never 0), and `take` pops it.
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub take: Signal<Out, Bit>,
    /// The runs spec §9.1's open limit allows in the column whose first
    /// slot is at the decision (see `FccOpenRoom`).
    pub open_room: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub out: Signal<Out, RunPix>,
    pts: FccRam<RowPts, ROW_BITS>,
    labs: FccRam<RowLabs, ROW_BITS>,
    /// The tables' read row and enable, replicated by Vivado: in LUT RAM
    /// they reach every word's bits.
    rd_row: FccFanoutNet<Bits<ROW_BITS>>,
    rd_en: FccFanoutNet<Bit>,
    pd: Vec<FccFanoutReg<ColPix>>,
    entry: FccRowEntry,
    cd: Vec<FccFanoutReg<RunCtl>>,
    near: FccSqDist,
    ring: FccSqDist,
    /// N3: the two tests' points' keys and addends (pixel and latest;
    /// first and last), then the picked addends (N4, N5).
    near_key: Vec<DFF<Bits<16>>>,
    near_ch: Vec<DFF<Bits<36>>>,
    /// N3: the new entry (the ring check's points and thresholds) and
    /// whether the check applies.
    wr_q: DFF<RowPts>,
    ring_en: DFF<Bit>,
    /// Pass 1's hit, waiting for the ring check's.
    near_hit: DFF<Bit>,
    near_cd: Vec<DFF<Bits<36>>>,
    ring_cd: Vec<DFF<Bits<36>>>,
    decide: FccRunDecide,
    room: FccOpenRoom,
    out_q: DFF<RunPix>,
    ctl_zero: Constant<RunCtl>,
    dead_sum: Signal<Local, Bits<12>>,
    dead: DFF<Bits<12>>,
    max12: Constant<Bits<12>>,
}

impl FccRowRuns {
    /// The block for frames of at most `rows` rows.
    pub fn new(rows: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pix: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            cv: Default::default(),
            last_col: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            take: Default::default(),
            open_room: Default::default(),
            out: Default::default(),
            pts: FccRam::new(rows),
            labs: FccRam::new(rows),
            rd_row: Default::default(),
            rd_en: Default::default(),
            pd: vec_of(2),
            entry: Default::default(),
            cd: vec_of(SQ_LATENCY + 1),
            near: FccSqDist::new(),
            ring: FccSqDist::new(),
            near_key: vec_of(2),
            near_ch: vec_of(2),
            wr_q: Default::default(),
            ring_en: Default::default(),
            near_hit: Default::default(),
            near_cd: vec_of(2),
            ring_cd: vec_of(3),
            decide: Default::default(),
            room: Default::default(),
            out_q: Default::default(),
            ctl_zero: Constant::new(RunCtl::default()),
            dead_sum: Default::default(),
            dead: Default::default(),
            max12: kb(0xfff),
        }
    }
}

impl Logic for FccRowRuns {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, out_q, dead, wr_q, ring_en, near_hit);
        for i in 0..2 {
            self.pd[i].clock.next = self.clk.val();
        }
        for i in 0..8 {
            self.cd[i].clock.next = self.clk.val();
        }
        for i in 0..2 {
            self.near_key[i].clock.next = self.clk.val();
            self.near_ch[i].clock.next = self.clk.val();
            self.near_cd[i].clock.next = self.clk.val();
        }
        for i in 0..3 {
            self.ring_cd[i].clock.next = self.clk.val();
        }
        // ---- N0: read the row's entry.
        self.pts.clk.next = self.clk.val();
        self.labs.clk.next = self.clk.val();
        self.rd_row.x.next = self.pix.val().row;
        self.rd_en.x.next = self.pix.val().valid;
        self.pts.read_en.next = self.rd_en.y.val();
        self.pts.read_addr.next = self.rd_row.y.val();
        self.labs.read_en.next = self.rd_en.y.val();
        self.labs.read_addr.next = self.rd_row.y.val();
        self.pd[0].d.next = self.pix.val();
        self.pd[1].d.next = self.pd[0].q.val();
        // N1: the last column the bridge reaches from this pixel, saturated.
        self.dead_sum.next = self.pd[0].q.val().col + self.reach.val();
        self.dead.d.next = self.dead_sum.val();
        if self.dead_sum.val() < self.pd[0].q.val().col {
            self.dead.d.next = self.max12.val();
        }
        // ---- N2: the entry against the pixel; its points written back.
        self.entry.pix.next = self.pd[1].q.val();
        self.entry.key.next = self.key.val();
        self.entry.ch.next = self.ch.val();
        self.entry.cv.next = self.cv.val();
        self.entry.pts.next = self.pts.read_data.val();
        self.entry.labs.next = self.labs.read_data.val();
        self.entry.last_col.next = self.last_col.val();
        self.entry.dead.next = self.dead.q.val();
        self.entry.ring_on.next = self.ring_on.val();
        self.entry.ring_f_max.next = self.ring_f_max.val();
        self.entry.ring_l_min.next = self.ring_l_min.val();
        self.pts.write_en.next = self.pd[1].q.val().valid;
        self.pts.write_addr.next = self.pd[1].q.val().row;
        self.pts.write_data.next = self.entry.wr.val();
        self.near.clk.next = self.clk.val();
        self.near.ax.next = self.pd[1].q.val().x;
        self.near.ay.next = self.pd[1].q.val().y;
        self.near.az.next = self.pd[1].q.val().z;
        self.near.bx.next = self.pts.read_data.val().l_x;
        self.near.by.next = self.pts.read_data.val().l_y;
        self.near.bz.next = self.pts.read_data.val().l_z;
        self.near.en_in.next = self.entry.near_en.val();
        self.wr_q.d.next = self.entry.wr.val();
        self.ring_en.d.next = self.entry.ctl.val().ring_geom & self.entry.ctl.val().last_col;
        self.ring.clk.next = self.clk.val();
        self.ring.ax.next = self.wr_q.q.val().f_x;
        self.ring.ay.next = self.wr_q.q.val().f_y;
        self.ring.az.next = self.wr_q.q.val().f_z;
        self.ring.bx.next = self.wr_q.q.val().l_x;
        self.ring.by.next = self.wr_q.q.val().l_y;
        self.ring.bz.next = self.wr_q.q.val().l_z;
        self.ring.en_in.next = self.ring_en.q.val();
        self.near_key[0].d.next = self.key.val();
        self.near_ch[0].d.next = self.ch.val();
        self.near_key[1].d.next = self.pts.read_data.val().l_key;
        self.near_ch[1].d.next = self.pts.read_data.val().l_ch;
        // ---- N3 .. N10: the pixel waits for the distance units. N3: each
        // pair's addend (added in N5).
        self.cd[0].d.next = self.entry.ctl.val();
        for i in 1..8 {
            self.cd[i].d.next = self.cd[i - 1].q.val();
        }
        self.near_cd[0].d.next = self.near_ch[1].q.val();
        if self.near_key[0].q.val() <= self.near_key[1].q.val() {
            self.near_cd[0].d.next = self.near_ch[0].q.val();
        }
        self.ring_cd[0].d.next = self.wr_q.q.val().l_ch;
        if self.wr_q.q.val().f_key <= self.wr_q.q.val().l_key {
            self.ring_cd[0].d.next = self.wr_q.q.val().f_ch;
        }
        self.near_cd[1].d.next = self.near_cd[0].q.val();
        self.ring_cd[1].d.next = self.ring_cd[0].q.val();
        self.ring_cd[2].d.next = self.ring_cd[1].q.val();
        self.near.c.next = self.near_cd[1].q.val();
        self.ring.c.next = self.ring_cd[2].q.val();
        self.near_hit.d.next = self.near.hit.val();
        // ---- N10: the label; the row's labels written back.
        self.decide.ctl.next = self.cd[7].q.val();
        self.decide.near_hit.next = self.near_hit.q.val();
        self.decide.ring_hit.next = self.ring.hit.val();
        self.decide.free_ok.next = self.free_ok.val();
        self.decide.free_label.next = self.free_label.val();
        self.take.next = self.decide.take.val();
        self.room.clk.next = self.clk.val();
        self.room.rst.next = self.rst.val();
        self.room.open_room.next = self.open_room.val();
        self.room.col_start.next = self.cd[7].q.val().valid & self.cd[7].q.val().col_first;
        self.room.taken.next = self.decide.take.val();
        self.decide.start_ok.next = self.room.start_ok.val();
        self.decide.left_ok.next = self.room.left_ok.val();
        self.labs.write_en.next = self.cd[7].q.val().valid;
        self.labs.write_addr.next = self.cd[7].q.val().row;
        self.labs.write_data.next = self.decide.labs.val();
        self.out_q.d.next = self.decide.out.val();
        if self.rst.val() {
            self.pd[0].d.next.valid = false;
            self.pd[1].d.next.valid = false;
            self.cd[0].d.next.valid = false;
            self.cd[1].d.next.valid = false;
            self.cd[2].d.next.valid = false;
            self.cd[3].d.next.valid = false;
            self.cd[4].d.next.valid = false;
            self.cd[5].d.next.valid = false;
            self.cd[6].d.next.valid = false;
            // The whole last stage is reset, so that it stays a flip-flop
            // (a shift-register LUT's output is slow).
            self.cd[7].d.next = self.ctl_zero.val();
            self.out_q.d.next.valid = false;
        }
        self.out.next = self.out_q.q.val();
    }
}
