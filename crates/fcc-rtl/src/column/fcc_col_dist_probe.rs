//! `FccColDistProbe`: `FccColDist` of the build's K behind scalar ports,
//! for its own bench. The bench loads a bank of entries one per cycle
//! (`wr`, `widx` and the fields), then `go` presents the bank with a centre
//! for one cycle (zeros at every other cycle, so a test that sampled a
//! key or point a cycle early or late would see them). When the centre
//! comes out (`o_valid`) its label and every entry's hit and label are
//! kept; `hsel` picks one of them combinationally (zero past the last).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_dist::FccColDist;
use super::RunPix;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccColDistProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The centre, presented with `go`.
    pub go: Signal<In, Bit>,
    pub cx: Signal<In, Bits<16>>,
    pub cy: Signal<In, Bits<16>>,
    pub cz: Signal<In, Bits<16>>,
    pub ckey: Signal<In, Bits<16>>,
    pub ccv: Signal<In, Bits<36>>,
    pub clabel: Signal<In, Bits<16>>,
    // One entry of the bank, written with `wr`.
    pub wr: Signal<In, Bit>,
    pub widx: Signal<In, Bits<8>>,
    pub wok: Signal<In, Bit>,
    pub wx: Signal<In, Bits<16>>,
    pub wy: Signal<In, Bits<16>>,
    pub wz: Signal<In, Bits<16>>,
    pub wkey: Signal<In, Bits<16>>,
    pub wcv: Signal<In, Bits<36>>,
    pub wlabel: Signal<In, Bits<16>>,
    pub hsel: Signal<In, Bits<8>>,
    pub o_valid: Signal<Out, Bit>,
    pub o_label: Signal<Out, Bits<16>>,
    pub h_hit: Signal<Out, Bit>,
    pub h_label: Signal<Out, Bits<16>>,
    col_dist: FccColDist,
    slot: Signal<Local, RunPix>,
    slot_zero: Constant<RunPix>,
    b_ok: Vec<DFF<Bit>>,
    b_x: Vec<DFF<Bits<16>>>,
    b_y: Vec<DFF<Bits<16>>>,
    b_z: Vec<DFF<Bits<16>>>,
    b_key: Vec<DFF<Bits<16>>>,
    b_cv: Vec<DFF<Bits<36>>>,
    b_label: Vec<DFF<Bits<16>>>,
    k_hit: Vec<DFF<Bit>>,
    k_label: Vec<DFF<Bits<16>>>,
    k_centre: DFF<Bits<16>>,
    index: Vec<Constant<Bits<8>>>,
    zero16: Constant<Bits<16>>,
    zero36: Constant<Bits<36>>,
}

impl FccColDistProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(n <= 256, "{n} window entries do not fit widx");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            go: Default::default(),
            cx: Default::default(),
            cy: Default::default(),
            cz: Default::default(),
            ckey: Default::default(),
            ccv: Default::default(),
            clabel: Default::default(),
            wr: Default::default(),
            widx: Default::default(),
            wok: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            wz: Default::default(),
            wkey: Default::default(),
            wcv: Default::default(),
            wlabel: Default::default(),
            hsel: Default::default(),
            o_valid: Default::default(),
            o_label: Default::default(),
            h_hit: Default::default(),
            h_label: Default::default(),
            col_dist: FccColDist::new(p),
            slot: Default::default(),
            slot_zero: Constant::new(RunPix::default()),
            b_ok: vec_of(n),
            b_x: vec_of(n),
            b_y: vec_of(n),
            b_z: vec_of(n),
            b_key: vec_of(n),
            b_cv: vec_of(n),
            b_label: vec_of(n),
            k_hit: vec_of(n),
            k_label: vec_of(n),
            k_centre: Default::default(),
            index: (0..n).map(|e| kb(e as u64)).collect(),
            zero16: kb(0),
            zero36: kb(0),
        }
    }
}

impl Logic for FccColDistProbe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, k_centre);
        self.slot.next = self.slot_zero.val();
        if self.go.val() {
            self.slot.next.valid = true;
            self.slot.next.ok = true;
            self.slot.next.lok = true;
            self.slot.next.x = self.cx.val();
            self.slot.next.y = self.cy.val();
            self.slot.next.z = self.cz.val();
            self.slot.next.key = self.ckey.val();
            self.slot.next.cv = self.ccv.val();
            self.slot.next.label = self.clabel.val();
        }
        self.col_dist.clk.next = self.clk.val();
        self.col_dist.rst.next = self.rst.val();
        self.col_dist.centre_in.next = self.slot.val();
        self.o_valid.next = self.col_dist.centre.val().valid;
        self.k_centre.d.next = self.k_centre.q.val();
        if self.col_dist.centre.val().valid {
            self.k_centre.d.next = self.col_dist.centre.val().label;
        }
        self.o_label.next = self.k_centre.q.val();
        self.h_hit.next = false;
        self.h_label.next = self.zero16.val();
        for e in 0..self.index.len() {
            self.b_ok[e].clock.next = self.clk.val();
            self.b_x[e].clock.next = self.clk.val();
            self.b_y[e].clock.next = self.clk.val();
            self.b_z[e].clock.next = self.clk.val();
            self.b_key[e].clock.next = self.clk.val();
            self.b_cv[e].clock.next = self.clk.val();
            self.b_label[e].clock.next = self.clk.val();
            self.k_hit[e].clock.next = self.clk.val();
            self.k_label[e].clock.next = self.clk.val();
            self.b_ok[e].d.next = self.b_ok[e].q.val();
            self.b_x[e].d.next = self.b_x[e].q.val();
            self.b_y[e].d.next = self.b_y[e].q.val();
            self.b_z[e].d.next = self.b_z[e].q.val();
            self.b_key[e].d.next = self.b_key[e].q.val();
            self.b_cv[e].d.next = self.b_cv[e].q.val();
            self.b_label[e].d.next = self.b_label[e].q.val();
            if self.wr.val() & (self.widx.val() == self.index[e].val()) {
                self.b_ok[e].d.next = self.wok.val();
                self.b_x[e].d.next = self.wx.val();
                self.b_y[e].d.next = self.wy.val();
                self.b_z[e].d.next = self.wz.val();
                self.b_key[e].d.next = self.wkey.val();
                self.b_cv[e].d.next = self.wcv.val();
                self.b_label[e].d.next = self.wlabel.val();
            }
            self.col_dist.ent_ok[e].next = false;
            self.col_dist.ent_x[e].next = self.zero16.val();
            self.col_dist.ent_y[e].next = self.zero16.val();
            self.col_dist.ent_z[e].next = self.zero16.val();
            self.col_dist.ent_key[e].next = self.zero16.val();
            self.col_dist.ent_cv[e].next = self.zero36.val();
            self.col_dist.ent_label[e].next = self.zero16.val();
            if self.go.val() {
                self.col_dist.ent_ok[e].next = self.b_ok[e].q.val();
                self.col_dist.ent_x[e].next = self.b_x[e].q.val();
                self.col_dist.ent_y[e].next = self.b_y[e].q.val();
                self.col_dist.ent_z[e].next = self.b_z[e].q.val();
                self.col_dist.ent_key[e].next = self.b_key[e].q.val();
                self.col_dist.ent_cv[e].next = self.b_cv[e].q.val();
                self.col_dist.ent_label[e].next = self.b_label[e].q.val();
            }
            self.k_hit[e].d.next = self.k_hit[e].q.val();
            self.k_label[e].d.next = self.k_label[e].q.val();
            if self.col_dist.centre.val().valid {
                self.k_hit[e].d.next = self.col_dist.hit[e].val();
                self.k_label[e].d.next = self.col_dist.hit_label[e].val();
            }
            if self.hsel.val() == self.index[e].val() {
                self.h_hit.next = self.k_hit[e].q.val();
                self.h_label.next = self.k_label[e].q.val();
            }
        }
    }
}
