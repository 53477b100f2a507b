//! `FccRowEntry`: a pixel against its row's entry in the per-row table
//! (combinational; `FccRowRuns` stage N2, when the entry has been read).
//!
//! * The new entry (`wr`): the pixel becomes the row's latest valid pixel
//!   when it holds a point, and its first when the row had none. At the
//!   frame's column 0 the entry read is ignored (every row is visited
//!   there, so every entry is written before it is read again).
//! * Pass 1 (spec §3): the pixel is tested against the row's latest valid
//!   pixel (`near_en`) when the bridge reaches it (the bridge limit: the
//!   entry keeps the last column the latest pixel reaches, `l_col + reach`,
//!   `reach` as `RunLimits` gives it, so the test is one comparison).
//! * The ring check (at the last column) tests the row's first valid pixel
//!   against its last: the new entry's two points.
//! * What the label decision needs (`ctl`): the row's labels (0 where it
//!   has none), hold 2 (the bridge reaches the next column), the ring reach
//!   of the first and latest pixels after this one (`ring_on`: `N_r >= 1`;
//!   a first pixel in columns `0 ..= ring_f_max`, a latest in `ring_l_min
//!   ..= C - 1`; unlimited: `C - 1` and 0).

use rust_hdl::prelude::*;

use super::{ColPix, RowLabs, RowPts, RunCtl};
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRowEntry {
    /// The pixel and its point's key and addend.
    pub pix: Signal<In, ColPix>,
    pub key: Signal<In, Bits<16>>,
    pub ch: Signal<In, Bits<36>>,
    /// Its pass-2 addend, carried on.
    pub cv: Signal<In, Bits<36>>,
    /// Its row's entry as read.
    pub pts: Signal<In, RowPts>,
    pub labs: Signal<In, RowLabs>,
    // Run parameters.
    pub last_col: Signal<In, Bits<12>>,
    /// The last column the bridge reaches from this pixel, `col + reach`
    /// saturated at 4095 (worked out a stage earlier).
    pub dead: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    /// The row's new entry.
    pub wr: Signal<Out, RowPts>,
    pub ctl: Signal<Out, RunCtl>,
    /// The pass-1 test applies.
    pub near_en: Signal<Out, Bit>,
    fresh: Signal<Local, Bit>,
    l_has: Signal<Local, Bit>,
    f_has: Signal<Local, Bit>,
    point: Signal<Local, Bit>,
    nw: Signal<Local, RowPts>,
    is_last: Signal<Local, Bit>,
    f_in: Signal<Local, Bit>,
    l_in: Signal<Local, Bit>,
    /// The row's labels, 0 where it has none.
    lm: Signal<Local, Bits<16>>,
    fm: Signal<Local, Bits<16>>,
    hm: Signal<Local, Bits<16>>,
    zero7: Constant<Bits<7>>,
    zero12: Constant<Bits<12>>,
    zero16: Constant<Bits<16>>,
}

impl Default for FccRowEntry {
    fn default() -> Self {
        Self {
            pix: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            cv: Default::default(),
            pts: Default::default(),
            labs: Default::default(),
            last_col: Default::default(),
            dead: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            wr: Default::default(),
            ctl: Default::default(),
            near_en: Default::default(),
            fresh: Default::default(),
            l_has: Default::default(),
            f_has: Default::default(),
            point: Default::default(),
            nw: Default::default(),
            is_last: Default::default(),
            f_in: Default::default(),
            l_in: Default::default(),
            lm: Default::default(),
            fm: Default::default(),
            hm: Default::default(),
            zero7: kb(0),
            zero12: kb(0),
            zero16: kb(0),
        }
    }
}

impl Logic for FccRowEntry {
    #[hdl_gen]
    fn update(&mut self) {
        self.fresh.next = self.pix.val().col == self.zero12.val();
        self.l_has.next = !self.fresh.val() & self.pts.val().l_has;
        self.f_has.next = !self.fresh.val() & self.pts.val().f_has;
        self.point.next = self.pix.val().valid & self.pix.val().ok;
        self.is_last.next = self.pix.val().col == self.last_col.val();
        // ---- Pass 1 against the row's latest valid pixel.
        self.near_en.next =
            self.point.val() & self.l_has.val() & (self.pix.val().col <= self.pts.val().l_dead);
        // ---- The new entry.
        self.nw.next = self.pts.val();
        self.nw.next.l_has = self.l_has.val();
        self.nw.next.f_has = self.f_has.val();
        if self.point.val() {
            self.nw.next.l_has = true;
            self.nw.next.l_col = self.pix.val().col;
            self.nw.next.l_dead = self.dead.val();
            self.nw.next.l_x = self.pix.val().x;
            self.nw.next.l_y = self.pix.val().y;
            self.nw.next.l_z = self.pix.val().z;
            self.nw.next.l_key = self.key.val();
            self.nw.next.l_ch = self.ch.val();
            if !self.f_has.val() {
                self.nw.next.f_has = true;
                self.nw.next.f_col = self.pix.val().col;
                self.nw.next.f_x = self.pix.val().x;
                self.nw.next.f_y = self.pix.val().y;
                self.nw.next.f_z = self.pix.val().z;
                self.nw.next.f_key = self.key.val();
                self.nw.next.f_ch = self.ch.val();
            }
        }
        self.wr.next = self.nw.val();
        // ---- What the label decision needs.
        self.ctl.next.valid = self.pix.val().valid;
        self.ctl.next.ok = self.pix.val().ok;
        self.ctl.next.x = self.pix.val().x;
        self.ctl.next.y = self.pix.val().y;
        self.ctl.next.z = self.pix.val().z;
        self.ctl.next.row = self.pix.val().row;
        self.ctl.next.col = self.pix.val().col;
        self.ctl.next.col_first = self.pix.val().row == self.zero7.val();
        self.ctl.next.first = self.pix.val().first;
        self.ctl.next.last = self.pix.val().last;
        self.ctl.next.key = self.key.val();
        self.ctl.next.cv = self.cv.val();
        self.ctl.next.first_here = self.point.val() & !self.f_has.val();
        self.lm.next = self.zero16.val();
        if self.l_has.val() {
            self.lm.next = self.labs.val().l_lab;
        }
        self.fm.next = self.zero16.val();
        if self.f_has.val() {
            self.fm.next = self.labs.val().f_lab;
        }
        self.hm.next = self.zero16.val();
        if !self.fresh.val() {
            self.hm.next = self.labs.val().h_lab;
        }
        self.ctl.next.l_lab = self.lm.val();
        self.ctl.next.f_lab = self.fm.val();
        self.ctl.next.h_lab = self.hm.val();
        // The comparisons on the labels as read, masked after (in parallel
        // with the masks): a row has a first valid pixel exactly when it has
        // a latest one.
        self.ctl.next.l_nz = self.l_has.val() & (self.labs.val().l_lab != self.zero16.val());
        self.ctl.next.f_nz = self.f_has.val() & (self.labs.val().f_lab != self.zero16.val());
        self.ctl.next.h_nz = !self.fresh.val() & (self.labs.val().h_lab != self.zero16.val());
        self.ctl.next.l_ne_h = !self.fresh.val() & (self.labs.val().h_lab != self.zero16.val());
        if self.l_has.val() {
            self.ctl.next.l_ne_h = self.labs.val().l_lab != self.labs.val().h_lab;
        }
        self.ctl.next.f_ne_l = self.f_has.val() & (self.labs.val().f_lab != self.labs.val().l_lab);
        self.ctl.next.bridge_h = !self.is_last.val()
            & (self.point.val()
                | (self.l_has.val() & (self.pix.val().col < self.pts.val().l_dead)));
        // The reach of the first and latest pixels after this one, compared
        // on both candidates (the entry's, the pixel's) and then chosen.
        self.f_in.next = self.pix.val().col <= self.ring_f_max.val();
        if self.f_has.val() {
            self.f_in.next = self.pts.val().f_col <= self.ring_f_max.val();
        }
        self.l_in.next = self.pts.val().l_col >= self.ring_l_min.val();
        if self.point.val() {
            self.l_in.next = self.pix.val().col >= self.ring_l_min.val();
        }
        self.ctl.next.ring_geom = self.ring_on.val()
            & (self.f_has.val() | self.point.val())
            & self.f_in.val()
            & self.l_in.val();
        self.ctl.next.first_reach =
            self.ring_on.val() & (self.pix.val().col <= self.ring_f_max.val());
        self.ctl.next.last_col = self.is_last.val();
    }
}
