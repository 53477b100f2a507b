//! `FccDistUnit`: one distance processor of `fcc_dist_tree`: is the centre
//! closer than `tV` (strictly) to one window position? An `FccSqDist` (seven
//! registered stages) with the position's `ok` as its enable and `-tV^2` as
//! its addend.

use rust_hdl::prelude::*;

use crate::fcc_sq_dist::FccSqDist;

#[derive(LogicBlock)]
pub struct FccDistUnit {
    pub clk: Signal<In, Clock>,
    // Centre point.
    pub cx: Signal<In, Bits<16>>,
    pub cy: Signal<In, Bits<16>>,
    pub cz: Signal<In, Bits<16>>,
    // Window position (ok already masked).
    pub nok: Signal<In, Bit>,
    pub nx: Signal<In, Bits<16>>,
    pub ny: Signal<In, Bits<16>>,
    pub nz: Signal<In, Bits<16>>,
    /// -tV^2 (36-bit two's complement), from the run parameters.
    pub th_c: Signal<In, Bits<36>>,
    /// `SQ_LATENCY` cycles later (registered).
    pub hit: Signal<Out, Bit>,
    sq: FccSqDist,
}

impl FccDistUnit {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            cx: Default::default(),
            cy: Default::default(),
            cz: Default::default(),
            nok: Default::default(),
            nx: Default::default(),
            ny: Default::default(),
            nz: Default::default(),
            th_c: Default::default(),
            hit: Default::default(),
            sq: FccSqDist::new(),
        }
    }
}

impl Default for FccDistUnit {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccDistUnit {
    #[hdl_gen]
    fn update(&mut self) {
        self.sq.clk.next = self.clk.val();
        self.sq.ax.next = self.cx.val();
        self.sq.ay.next = self.cy.val();
        self.sq.az.next = self.cz.val();
        self.sq.bx.next = self.nx.val();
        self.sq.by.next = self.ny.val();
        self.sq.bz.next = self.nz.val();
        self.sq.en_in.next = self.nok.val();
        self.sq.c.next = self.th_c.val();
        self.hit.next = self.sq.hit.val();
    }
}
