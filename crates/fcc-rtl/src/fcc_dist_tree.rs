//! `fcc_dist_tree`: the parameterised distance-processor tree, one
//! `FccDistUnit` per window position above the centre (K * (K-1)/2 of them,
//! a `Vec` sized at generation time), plus the centre's delay line so that
//! `centre` and `hit` leave together, `SQ_LATENCY` cycles after entry,
//! all from registers.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_dist_unit::FccDistUnit;
use crate::fcc_sq_dist::SQ_LATENCY;
use crate::types::{vec_of, Centre, Ctr};

// The centre's delay line below is written out for seven stages.
const _: () = assert!(SQ_LATENCY == 7);

#[derive(LogicBlock)]
pub struct FccDistTree {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // From the window.
    pub centre_in: Signal<In, Centre>,
    pub ent_ok: Vec<Signal<In, Bit>>,
    pub ent_x: Vec<Signal<In, Bits<16>>>,
    pub ent_y: Vec<Signal<In, Bits<16>>>,
    pub ent_z: Vec<Signal<In, Bits<16>>>,
    /// From the threshold window, `THR_WIN_LAG` cycles after the points:
    /// the keys and addends `-T'_V` of the centre and the positions.
    pub centre_key: Signal<In, Bits<16>>,
    pub centre_cv: Signal<In, Bits<36>>,
    pub ent_key: Vec<Signal<In, Bits<16>>>,
    pub ent_cv: Vec<Signal<In, Bits<36>>>,
    // To the sort network.
    pub centre: Signal<Out, Ctr>,
    pub hit: Vec<Signal<Out, Bit>>,
    units: Vec<FccDistUnit>,
    cd: Vec<DFF<Ctr>>,
    c0: Signal<Local, Ctr>,
    ctr_zero: Constant<Ctr>,
    _n: usize,
}

impl FccDistTree {
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
            centre_key: Default::default(),
            centre_cv: Default::default(),
            ent_key: vec_of(n),
            ent_cv: vec_of(n),
            centre: Default::default(),
            hit: vec_of(n),
            units: (0..n).map(|_| FccDistUnit::new()).collect(),
            cd: (0..SQ_LATENCY).map(|_| Default::default()).collect(),
            c0: Default::default(),
            ctr_zero: Constant::new(Ctr::default()),
            _n: n,
        }
    }
}

impl Logic for FccDistTree {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self._n {
            self.units[e].clk.next = self.clk.val();
            self.units[e].cx.next = self.centre_in.val().x;
            self.units[e].cy.next = self.centre_in.val().y;
            self.units[e].cz.next = self.centre_in.val().z;
            self.units[e].nok.next = self.ent_ok[e].val();
            self.units[e].nx.next = self.ent_x[e].val();
            self.units[e].ny.next = self.ent_y[e].val();
            self.units[e].nz.next = self.ent_z[e].val();
            self.units[e].ckey.next = self.centre_key.val();
            self.units[e].ccv.next = self.centre_cv.val();
            self.units[e].nkey.next = self.ent_key[e].val();
            self.units[e].ncv.next = self.ent_cv[e].val();
            self.hit[e].next = self.units[e].hit.val();
        }
        self.c0.next.valid = self.centre_in.val().valid;
        self.c0.next.lok = self.centre_in.val().lok;
        self.c0.next.label = self.centre_in.val().label;
        self.c0.next.col = self.centre_in.val().col;
        self.c0.next.last = self.centre_in.val().last;
        self.c0.next.ring = self.centre_in.val().ring;
        self.c0.next.ring_a = self.centre_in.val().ring_a;
        self.c0.next.ring_b = self.centre_in.val().ring_b;
        for i in 0..7 {
            self.cd[i].clock.next = self.clk.val();
        }
        self.cd[0].d.next = self.c0.val();
        for i in 1..7 {
            self.cd[i].d.next = self.cd[i - 1].q.val();
        }
        if self.rst.val() {
            self.cd[0].d.next.valid = false;
            self.cd[1].d.next.valid = false;
            self.cd[2].d.next.valid = false;
            self.cd[3].d.next.valid = false;
            self.cd[4].d.next.valid = false;
            self.cd[5].d.next.valid = false;
            // The whole last stage is reset, so that it stays a flip-flop
            // (a shift-register LUT's output is slow).
            self.cd[6].d.next = self.ctr_zero.val();
        }
        self.centre.next = self.cd[6].q.val();
    }
}
