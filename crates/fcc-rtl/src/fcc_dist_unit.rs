//! `FccDistUnit`: one distance processor of `fcc_dist_tree`: the squared
//! distance between the centre and one window position, compared strictly
//! with `tV^2`, four registered stages. The neighbour's label rides along.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_sq_dist::FccSqDist;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccDistUnit {
    pub clk: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    // Centre point.
    pub cx: Signal<In, Bits<16>>,
    pub cy: Signal<In, Bits<16>>,
    pub cz: Signal<In, Bits<16>>,
    // Window position (ok already masked).
    pub nok: Signal<In, Bit>,
    pub nx: Signal<In, Bits<16>>,
    pub ny: Signal<In, Bits<16>>,
    pub nz: Signal<In, Bits<16>>,
    pub nlabel: Signal<In, Bits<16>>,
    // Four enabled cycles later.
    pub hit: Signal<Out, Bit>,
    pub label: Signal<Out, Bits<16>>,
    sq: FccSqDist,
    ok1: DFF<Bit>,
    ok2: DFF<Bit>,
    ok3: DFF<Bit>,
    lab1: DFF<Bits<16>>,
    lab2: DFF<Bits<16>>,
    lab3: DFF<Bits<16>>,
    hit_q: DFF<Bit>,
    lab_q: DFF<Bits<16>>,
    th_v_sq: Constant<Bits<32>>,
}

impl FccDistUnit {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            en: Default::default(),
            cx: Default::default(),
            cy: Default::default(),
            cz: Default::default(),
            nok: Default::default(),
            nx: Default::default(),
            ny: Default::default(),
            nz: Default::default(),
            nlabel: Default::default(),
            hit: Default::default(),
            label: Default::default(),
            sq: Default::default(),
            ok1: Default::default(),
            ok2: Default::default(),
            ok3: Default::default(),
            lab1: Default::default(),
            lab2: Default::default(),
            lab3: Default::default(),
            hit_q: Default::default(),
            lab_q: Default::default(),
            th_v_sq: kb(p.th_v_sq() as u64),
        }
    }
}

impl Logic for FccDistUnit {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, ok1, ok2, ok3, lab1, lab2, lab3, hit_q, lab_q);
        self.sq.clk.next = self.clk.val();
        self.sq.en.next = self.en.val();
        self.sq.ax.next = self.cx.val();
        self.sq.ay.next = self.cy.val();
        self.sq.az.next = self.cz.val();
        self.sq.bx.next = self.nx.val();
        self.sq.by.next = self.ny.val();
        self.sq.bz.next = self.nz.val();
        if self.en.val() {
            self.ok1.d.next = self.nok.val();
            self.ok2.d.next = self.ok1.q.val();
            self.ok3.d.next = self.ok2.q.val();
            self.lab1.d.next = self.nlabel.val();
            self.lab2.d.next = self.lab1.q.val();
            self.lab3.d.next = self.lab2.q.val();
            self.hit_q.d.next = self.ok3.q.val() & (self.sq.d2.val() < self.th_v_sq.val());
            self.lab_q.d.next = self.lab3.q.val();
        }
        self.hit.next = self.hit_q.q.val();
        self.label.next = self.lab_q.q.val();
    }
}
