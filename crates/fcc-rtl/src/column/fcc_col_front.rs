//! `FccColFront`: the column core's front, the blocks a pixel slot passes
//! through one a cycle without a hold (docs/column-core.md, item 8, "Where
//! back-pressure goes"): its own thresholds (`FccPixThr`), pass 1 and the
//! row's run state (`FccRowRuns`, labels from the pool's head), the pass-2
//! window in column order (`FccColWindow`) and its distance tests
//! (`FccColDist`). Out of it, `FRONT_LATENCY` cycles after the slot came
//! in: the pixel with its run (`centre`, a `RunPix`), which window entries
//! it joins (`hit`) and their labels (`hit_label`), which are the
//! representative rows' input (`FccRepJoins`).
//!
//! Wiring only: the input stage's slot (rows below 128) narrowed to a
//! `ColPix` for the row runs, which take its key and addends `THR_LAG`
//! cycles after it as `FccPixThr` gives them; the run parameters pass
//! through. `open_room` is the column-start check's (`FccColStart`), whose
//! timing counts `FccPixThr`'s delay in front of the row runs.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_dist::{FccColDist, COL_DIST_LATENCY};
use super::fcc_col_window::{FccColWindow, COL_WINDOW_LATENCY};
use super::fcc_open_room::OPEN_ROOM_BITS;
use super::fcc_row_runs::{FccRowRuns, RUNS_LATENCY};
use super::{ColPix, RunPix};
use crate::fcc_pix_thr::{FccPixThr, PIX_DELAY};
use crate::types::{vec_of, Pix};

/// Cycles from a slot at `pix` to it at `centre` with its hits.
pub const FRONT_LATENCY: usize = PIX_DELAY + RUNS_LATENCY + COL_WINDOW_LATENCY + COL_DIST_LATENCY;

#[derive(LogicBlock)]
pub struct FccColFront {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Pixel slots in column order (the input stage's).
    pub pix: Signal<In, Pix>,
    /// Thresholds (`FccPixThr`): squared slopes, fixed addends.
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    /// Run parameters (`FccRowRuns`, `FccColWindow`).
    pub last_col: Signal<In, Bits<12>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub run_k: Signal<In, Bits<4>>,
    /// The label pool's head, and `take` pops it.
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub take: Signal<Out, Bit>,
    /// The runs the open limit allows in the column (`FccColStart`).
    pub open_room: Signal<In, Bits<OPEN_ROOM_BITS>>,
    /// The pixel with its run, the entries it joins and their labels.
    pub centre: Signal<Out, RunPix>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub hit_label: Vec<Signal<Out, Bits<16>>>,
    thr: FccPixThr,
    runs: FccRowRuns,
    window: FccColWindow,
    pass2: FccColDist,
    slot: Signal<Local, ColPix>,
    row8: Signal<Local, Bits<8>>,
}

impl FccColFront {
    /// The front of the build's rows and K.
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pix: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            last_col: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            take: Default::default(),
            open_room: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            hit_label: vec_of(n),
            thr: FccPixThr::new(),
            runs: FccRowRuns::new(p.rows),
            window: FccColWindow::new(p),
            pass2: FccColDist::new(p),
            slot: Default::default(),
            row8: Default::default(),
        }
    }
}

impl Logic for FccColFront {
    #[hdl_gen]
    fn update(&mut self) {
        self.thr.clk.next = self.clk.val();
        self.thr.rst.next = self.rst.val();
        self.thr.pix.next = self.pix.val();
        self.thr.sh.next = self.sh.val();
        self.thr.sv.next = self.sv.val();
        self.thr.ch_t.next = self.ch_t.val();
        self.thr.cv_t.next = self.cv_t.val();
        // The slot as the row runs take it (at most 128 rows).
        self.slot.next.valid = self.thr.out.val().valid;
        self.slot.next.ok = self.thr.out.val().ok;
        self.slot.next.x = self.thr.out.val().x;
        self.slot.next.y = self.thr.out.val().y;
        self.slot.next.z = self.thr.out.val().z;
        self.row8.next = self.thr.out.val().row;
        self.slot.next.row = self.row8.val().get_bits::<7>(0);
        self.slot.next.col = self.thr.out.val().col;
        self.slot.next.first = self.thr.out.val().first;
        self.slot.next.last = self.thr.out.val().last;
        self.runs.clk.next = self.clk.val();
        self.runs.rst.next = self.rst.val();
        self.runs.pix.next = self.slot.val();
        self.runs.key.next = self.thr.key.val();
        self.runs.ch.next = self.thr.ch.val();
        self.runs.cv.next = self.thr.cv.val();
        self.runs.last_col.next = self.last_col.val();
        self.runs.reach.next = self.reach.val();
        self.runs.ring_on.next = self.ring_on.val();
        self.runs.ring_f_max.next = self.ring_f_max.val();
        self.runs.ring_l_min.next = self.ring_l_min.val();
        self.runs.free_ok.next = self.free_ok.val();
        self.runs.free_label.next = self.free_label.val();
        self.runs.open_room.next = self.open_room.val();
        self.take.next = self.runs.take.val();
        self.window.clk.next = self.clk.val();
        self.window.rst.next = self.rst.val();
        self.window.inp.next = self.runs.out.val();
        self.window.last_row.next = self.last_row.val();
        self.window.run_k.next = self.run_k.val();
        self.pass2.clk.next = self.clk.val();
        self.pass2.rst.next = self.rst.val();
        self.pass2.centre_in.next = self.window.centre.val();
        for e in 0..self.hit.len() {
            self.pass2.ent_ok[e].next = self.window.ent_ok[e].val();
            self.pass2.ent_x[e].next = self.window.ent_x[e].val();
            self.pass2.ent_y[e].next = self.window.ent_y[e].val();
            self.pass2.ent_z[e].next = self.window.ent_z[e].val();
            self.pass2.ent_key[e].next = self.window.ent_key[e].val();
            self.pass2.ent_cv[e].next = self.window.ent_cv[e].val();
            self.pass2.ent_label[e].next = self.window.ent_label[e].val();
            self.hit[e].next = self.pass2.hit[e].val();
            self.hit_label[e].next = self.pass2.hit_label[e].val();
        }
        self.centre.next = self.pass2.centre.val();
    }
}
