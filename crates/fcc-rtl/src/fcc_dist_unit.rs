//! `FccDistUnit`: one distance processor of `fcc_dist_tree`: is the centre
//! closer than the pair's threshold (strictly) to one window position? An
//! `FccSqDist` (seven registered stages) with the position's `ok` as its
//! enable and the pair's addend `-T'_V` (spec §2): the addend of the point
//! with the smaller key, picked in the cycle before the `FccSqDist` adds it
//! (the keys and addends arrive `THR_WIN_LAG` = 2 cycles after the points).

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
    /// Two cycles after the points: their keys and addends `-T'_V`.
    pub ckey: Signal<In, Bits<16>>,
    pub ccv: Signal<In, Bits<36>>,
    pub nkey: Signal<In, Bits<16>>,
    pub ncv: Signal<In, Bits<36>>,
    /// `SQ_LATENCY` cycles later (registered).
    pub hit: Signal<Out, Bit>,
    sq: FccSqDist,
    /// The pair's addend (in the cycle `FccSqDist` adds it).
    pair_c: DFF<Bits<36>>,
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
            ckey: Default::default(),
            ccv: Default::default(),
            nkey: Default::default(),
            ncv: Default::default(),
            hit: Default::default(),
            sq: FccSqDist::new(),
            pair_c: Default::default(),
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
        dff_setup!(self, clk, pair_c);
        self.pair_c.d.next = self.ccv.val();
        if self.nkey.val() < self.ckey.val() {
            self.pair_c.d.next = self.ncv.val();
        }
        self.sq.c.next = self.pair_c.q.val();
        self.hit.next = self.sq.hit.val();
    }
}
