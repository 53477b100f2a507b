//! `FccColDist`: pass 2's distance tests in the column core (spec §2 and
//! §4): one `FccDistUnit` per window entry, each telling whether the centre
//! and the entry join (`d2 < max(tV^2, min(T_V))`, the pair's addend that
//! of its point with the smaller key). The units take the keys and addends
//! `THR_WIN_LAG` cycles after the points, so here they wait that long; the
//! centre and the entries' labels wait alongside the units, and leave with
//! `hit` `SQ_LATENCY` cycles after entry, all from registers. A bubble
//! (centre not valid) tests nothing.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::RunPix;
use crate::fcc_dist_unit::FccDistUnit;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_sq_dist::SQ_LATENCY;
use crate::fcc_thr_window::THR_WIN_LAG;
use crate::types::{kb, vec_of};

/// Cycles from the window to `hit` and `centre`.
pub const COL_DIST_LATENCY: usize = SQ_LATENCY;

// The delay lines below are written out for these latencies.
const _: () = assert!(SQ_LATENCY == 7 && THR_WIN_LAG == 2);

#[derive(LogicBlock)]
pub struct FccColDist {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The window (`FccColWindow`'s T3).
    pub centre_in: Signal<In, RunPix>,
    pub ent_ok: Vec<Signal<In, Bit>>,
    pub ent_x: Vec<Signal<In, Bits<16>>>,
    pub ent_y: Vec<Signal<In, Bits<16>>>,
    pub ent_z: Vec<Signal<In, Bits<16>>>,
    pub ent_key: Vec<Signal<In, Bits<16>>>,
    pub ent_cv: Vec<Signal<In, Bits<36>>>,
    pub ent_label: Vec<Signal<In, Bits<16>>>,
    /// `SQ_LATENCY` cycles later: the centre, which entries it joins, and
    /// the entries' labels.
    pub centre: Signal<Out, RunPix>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub hit_label: Vec<Signal<Out, Bits<16>>>,
    units: Vec<FccDistUnit>,
    /// The keys and addends, `THR_WIN_LAG` stages (entry e's at `2e + s`).
    key_d: Vec<DFF<Bits<16>>>,
    cv_d: Vec<DFF<Bits<36>>>,
    ckey_d: Vec<DFF<Bits<16>>>,
    ccv_d: Vec<FccFanoutReg<Bits<36>>>,
    /// The centre and the labels, `SQ_LATENCY` stages (entry e's at `7e + s`).
    cd: Vec<DFF<RunPix>>,
    label_d: Vec<DFF<Bits<16>>>,
    zero16: Constant<Bits<16>>,
    zero36: Constant<Bits<36>>,
    _n: usize,
}

impl FccColDist {
    /// The tests of the build's window (`K x h` entries).
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            centre_in: Default::default(),
            ent_ok: vec_of(n),
            ent_x: vec_of(n),
            ent_y: vec_of(n),
            ent_z: vec_of(n),
            ent_key: vec_of(n),
            ent_cv: vec_of(n),
            ent_label: vec_of(n),
            centre: Default::default(),
            hit: vec_of(n),
            hit_label: vec_of(n),
            units: (0..n).map(|_| FccDistUnit::new()).collect(),
            key_d: vec_of(THR_WIN_LAG * n),
            cv_d: vec_of(THR_WIN_LAG * n),
            ckey_d: vec_of(THR_WIN_LAG),
            ccv_d: vec_of(THR_WIN_LAG),
            cd: vec_of(COL_DIST_LATENCY),
            label_d: vec_of(SQ_LATENCY * n),
            zero16: kb(0),
            zero36: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccColDist {
    #[hdl_gen]
    fn update(&mut self) {
        for s in 0..2 {
            self.ckey_d[s].clock.next = self.clk.val();
            self.ccv_d[s].clock.next = self.clk.val();
        }
        self.ckey_d[0].d.next = self.centre_in.val().key;
        self.ccv_d[0].d.next = self.centre_in.val().cv;
        self.ckey_d[1].d.next = self.ckey_d[0].q.val();
        self.ccv_d[1].d.next = self.ccv_d[0].q.val();
        for s in 0..7 {
            self.cd[s].clock.next = self.clk.val();
        }
        self.cd[0].d.next = self.centre_in.val();
        for s in 1..7 {
            self.cd[s].d.next = self.cd[s - 1].q.val();
        }
        for e in 0..self._n {
            self.units[e].clk.next = self.clk.val();
            self.units[e].cx.next = self.centre_in.val().x;
            self.units[e].cy.next = self.centre_in.val().y;
            self.units[e].cz.next = self.centre_in.val().z;
            self.units[e].nok.next = self.ent_ok[e].val() & self.centre_in.val().valid;
            self.units[e].nx.next = self.ent_x[e].val();
            self.units[e].ny.next = self.ent_y[e].val();
            self.units[e].nz.next = self.ent_z[e].val();
            self.key_d[2 * e].clock.next = self.clk.val();
            self.key_d[2 * e + 1].clock.next = self.clk.val();
            self.cv_d[2 * e].clock.next = self.clk.val();
            self.cv_d[2 * e + 1].clock.next = self.clk.val();
            self.key_d[2 * e].d.next = self.ent_key[e].val();
            self.key_d[2 * e + 1].d.next = self.key_d[2 * e].q.val();
            self.cv_d[2 * e].d.next = self.ent_cv[e].val();
            self.cv_d[2 * e + 1].d.next = self.cv_d[2 * e].q.val();
            self.units[e].ckey.next = self.ckey_d[1].q.val();
            self.units[e].ccv.next = self.ccv_d[1].q.val();
            self.units[e].nkey.next = self.key_d[2 * e + 1].q.val();
            self.units[e].ncv.next = self.cv_d[2 * e + 1].q.val();
            self.hit[e].next = self.units[e].hit.val();
            for s in 0..7 {
                self.label_d[7 * e + s].clock.next = self.clk.val();
            }
            self.label_d[7 * e].d.next = self.ent_label[e].val();
            for s in 1..7 {
                self.label_d[7 * e + s].d.next = self.label_d[7 * e + s - 1].q.val();
            }
            self.hit_label[e].next = self.label_d[7 * e + 6].q.val();
        }
        // The keys' and addends' last stages have a reset, so that they stay
        // flip-flops: chained with the window's registers, a delay line
        // without one becomes shift-register LUTs, whose output is slow.
        if self.rst.val() {
            self.ckey_d[1].d.next = self.zero16.val();
            self.ccv_d[1].d.next = self.zero36.val();
            for e in 0..self.units.len() {
                self.key_d[2 * e + 1].d.next = self.zero16.val();
                self.cv_d[2 * e + 1].d.next = self.zero36.val();
            }
            self.cd[0].d.next.valid = false;
            self.cd[1].d.next.valid = false;
            self.cd[2].d.next.valid = false;
            self.cd[3].d.next.valid = false;
            self.cd[4].d.next.valid = false;
            self.cd[5].d.next.valid = false;
            self.cd[6].d.next.valid = false;
        }
        self.centre.next = self.cd[6].q.val();
    }
}
