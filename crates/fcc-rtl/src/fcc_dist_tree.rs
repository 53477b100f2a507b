//! `fcc_dist_tree`: the parameterised distance-processor tree, one
//! `FccDistUnit` per window position above the centre (K * (K-1)/2 of them,
//! a `Vec` sized at generation time), plus the centre's delay line so that
//! `centre` and `hit`/`label` leave together, four enabled cycles after entry.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_dist_unit::FccDistUnit;
use crate::types::{Centre, Ctr};

#[derive(LogicBlock)]
pub struct FccDistTree {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub en: Signal<In, Bit>,
    // From the window.
    pub centre_in: Signal<In, Centre>,
    pub ent_ok: Vec<Signal<In, Bit>>,
    pub ent_x: Vec<Signal<In, Bits<16>>>,
    pub ent_y: Vec<Signal<In, Bits<16>>>,
    pub ent_z: Vec<Signal<In, Bits<16>>>,
    pub ent_label: Vec<Signal<In, Bits<16>>>,
    // To the sort network.
    pub centre: Signal<Out, Ctr>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub label: Vec<Signal<Out, Bits<16>>>,
    units: Vec<FccDistUnit>,
    c1: DFF<Ctr>,
    c2: DFF<Ctr>,
    c3: DFF<Ctr>,
    c4: DFF<Ctr>,
    _n: usize,
}

fn v<T: Default>(n: usize) -> Vec<T> {
    (0..n).map(|_| T::default()).collect()
}

impl FccDistTree {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            en: Default::default(),
            centre_in: Default::default(),
            ent_ok: v(n),
            ent_x: v(n),
            ent_y: v(n),
            ent_z: v(n),
            ent_label: v(n),
            centre: Default::default(),
            hit: v(n),
            label: v(n),
            units: (0..n).map(|_| FccDistUnit::new(p)).collect(),
            c1: Default::default(),
            c2: Default::default(),
            c3: Default::default(),
            c4: Default::default(),
            _n: n,
        }
    }
}

impl Logic for FccDistTree {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, c1, c2, c3, c4);
        for e in 0..self._n {
            self.units[e].clk.next = self.clk.val();
            self.units[e].en.next = self.en.val();
            self.units[e].cx.next = self.centre_in.val().x;
            self.units[e].cy.next = self.centre_in.val().y;
            self.units[e].cz.next = self.centre_in.val().z;
            self.units[e].nok.next = self.ent_ok[e].val();
            self.units[e].nx.next = self.ent_x[e].val();
            self.units[e].ny.next = self.ent_y[e].val();
            self.units[e].nz.next = self.ent_z[e].val();
            self.units[e].nlabel.next = self.ent_label[e].val();
            self.hit[e].next = self.units[e].hit.val();
            self.label[e].next = self.units[e].label.val();
        }
        if self.en.val() {
            self.c1.d.next.valid = self.centre_in.val().valid;
            self.c1.d.next.ok = self.centre_in.val().ok;
            self.c1.d.next.label = self.centre_in.val().label;
            self.c1.d.next.last = self.centre_in.val().last;
            self.c1.d.next.ring = self.centre_in.val().ring;
            self.c1.d.next.ring_a = self.centre_in.val().ring_a;
            self.c1.d.next.ring_b = self.centre_in.val().ring_b;
            self.c2.d.next = self.c1.q.val();
            self.c3.d.next = self.c2.q.val();
            self.c4.d.next = self.c3.q.val();
        }
        if self.rst.val() {
            self.c1.d.next.valid = false;
            self.c2.d.next.valid = false;
            self.c3.d.next.valid = false;
            self.c4.d.next.valid = false;
        }
        self.centre.next = self.c4.q.val();
    }
}
