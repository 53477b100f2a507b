//! `FccRunDecide`: a pixel's label and its row's new labels
//! (combinational; `FccRowRuns` stage N10, when the distance units answer).
//!
//! * A point within `tH` of its row's latest valid pixel (`near_hit`)
//!   continues that pixel's run and takes its label (0 when that run is
//!   unlabelled: it stays so, spec §7). Any other point starts a run: it
//!   takes the free list's head (`take`) when `free_ok` and the open limit
//!   allows it (spec §9.1: `start_ok` at the column's first slot, `left_ok`
//!   after), else it is left unlabelled (`refused`).
//! * The row holds its latest valid pixel's label open (spec §9.2) while
//!   the bridge reaches the next column (hold 2) or, its first pixel
//!   labelled, both lie within the ring reach (hold 4). A change of the
//!   held label comes out as the label dropped and the label added.
//! * Hold 3: the row's first valid pixel, labelled, within the ring reach.
//! * At the last column the ring check joins the row's first run and its
//!   last when both are labelled, differ, lie within the reach and their
//!   pixels within `tH` (`ring_hit`).

use rust_hdl::prelude::*;

use super::{RowLabs, RunCtl, RunPix};
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRunDecide {
    pub ctl: Signal<In, RunCtl>,
    pub near_hit: Signal<In, Bit>,
    pub ring_hit: Signal<In, Bit>,
    /// The free list's head, when `free_ok`.
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    /// The open limit allows a run to start at the column's first slot,
    /// at a later slot (`FccOpenRoom`).
    pub start_ok: Signal<In, Bit>,
    pub left_ok: Signal<In, Bit>,
    /// Pop the free list's head.
    pub take: Signal<Out, Bit>,
    /// The row's new labels.
    pub labs: Signal<Out, RowLabs>,
    pub out: Signal<Out, RunPix>,
    point: Signal<Local, Bit>,
    newrun: Signal<Local, Bit>,
    lab: Signal<Local, Bits<16>>,
    taken: Signal<Local, Bit>,
    room_ok: Signal<Local, Bit>,
    lab_nz: Signal<Local, Bit>,
    l_nz: Signal<Local, Bit>,
    f_nz: Signal<Local, Bit>,
    held: Signal<Local, Bit>,
    l_lab: Signal<Local, Bits<16>>,
    f_lab: Signal<Local, Bits<16>>,
    h_lab: Signal<Local, Bits<16>>,
    changed: Signal<Local, Bit>,
    zero16: Constant<Bits<16>>,
}

impl Default for FccRunDecide {
    fn default() -> Self {
        Self {
            ctl: Default::default(),
            near_hit: Default::default(),
            ring_hit: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            start_ok: Default::default(),
            left_ok: Default::default(),
            take: Default::default(),
            labs: Default::default(),
            out: Default::default(),
            point: Default::default(),
            newrun: Default::default(),
            lab: Default::default(),
            taken: Default::default(),
            room_ok: Default::default(),
            lab_nz: Default::default(),
            l_nz: Default::default(),
            f_nz: Default::default(),
            held: Default::default(),
            l_lab: Default::default(),
            f_lab: Default::default(),
            h_lab: Default::default(),
            changed: Default::default(),
            zero16: kb(0),
        }
    }
}

impl Logic for FccRunDecide {
    #[hdl_gen]
    fn update(&mut self) {
        self.point.next = self.ctl.val().valid & self.ctl.val().ok;
        self.newrun.next = self.point.val() & !self.near_hit.val();
        self.room_ok.next = self.left_ok.val();
        if self.ctl.val().col_first {
            self.room_ok.next = self.start_ok.val();
        }
        self.taken.next = self.newrun.val() & self.free_ok.val() & self.room_ok.val();
        self.take.next = self.taken.val();
        self.lab.next = self.zero16.val();
        if self.near_hit.val() {
            self.lab.next = self.ctl.val().l_lab;
        }
        if self.taken.val() {
            self.lab.next = self.free_label.val();
        }
        // Free labels are never 0.
        self.lab_nz.next = (self.near_hit.val() & self.ctl.val().l_nz) | self.taken.val();
        // ---- The row's labels after this pixel.
        self.l_lab.next = self.ctl.val().l_lab;
        self.l_nz.next = self.ctl.val().l_nz;
        if self.point.val() {
            self.l_lab.next = self.lab.val();
            self.l_nz.next = self.lab_nz.val();
        }
        self.f_lab.next = self.ctl.val().f_lab;
        self.f_nz.next = self.ctl.val().f_nz;
        if self.ctl.val().first_here {
            self.f_lab.next = self.lab.val();
            self.f_nz.next = self.lab_nz.val();
        }
        self.held.next = (self.ctl.val().bridge_h | (self.ctl.val().ring_geom & self.f_nz.val()))
            & self.l_nz.val();
        self.h_lab.next = self.zero16.val();
        if self.held.val() {
            self.h_lab.next = self.l_lab.val();
        }
        // The held label changes: to a label just taken (never one in use),
        // or from the row's latest label to another, or to none.
        self.changed.next = self.ctl.val().h_nz;
        if self.held.val() {
            self.changed.next = self.taken.val() | self.ctl.val().l_ne_h;
        }
        self.labs.next.l_lab = self.l_lab.val();
        self.labs.next.f_lab = self.f_lab.val();
        self.labs.next.h_lab = self.h_lab.val();
        // ---- The pixel out.
        self.out.next.valid = self.ctl.val().valid;
        self.out.next.ok = self.ctl.val().ok;
        self.out.next.lok = self.point.val() & self.lab_nz.val();
        self.out.next.x = self.ctl.val().x;
        self.out.next.y = self.ctl.val().y;
        self.out.next.z = self.ctl.val().z;
        self.out.next.row = self.ctl.val().row;
        self.out.next.col = self.ctl.val().col;
        self.out.next.first = self.ctl.val().first;
        self.out.next.last = self.ctl.val().last;
        self.out.next.last_col = self.ctl.val().last_col;
        self.out.next.key = self.ctl.val().key;
        self.out.next.cv = self.ctl.val().cv;
        self.out.next.label = self.lab.val();
        self.out.next.start = self.taken.val();
        self.out.next.refused = self.newrun.val() & !self.taken.val();
        self.out.next.ring_first =
            self.ctl.val().first_here & self.ctl.val().first_reach & self.lab_nz.val();
        // The ring pair differs unless the first pixel is this one; a label
        // just taken differs from the first run's (held open by hold 3).
        self.out.next.ring = self.ctl.val().valid
            & self.ctl.val().last_col
            & self.ctl.val().ring_geom
            & self.ring_hit.val()
            & self.f_nz.val()
            & self.l_nz.val()
            & !self.ctl.val().first_here
            & (self.taken.val() | self.ctl.val().f_ne_l);
        self.out.next.ring_a = self.f_lab.val();
        self.out.next.ring_b = self.l_lab.val();
        self.out.next.ring_hold = self.ctl.val().last_col & self.held.val();
        self.out.next.hold_drop = self.zero16.val();
        self.out.next.hold_add = self.zero16.val();
        self.out.next.hold_rep = self.zero16.val();
        if self.ctl.val().valid & self.changed.val() {
            self.out.next.hold_drop = self.ctl.val().h_lab;
            self.out.next.hold_add = self.h_lab.val();
            self.out.next.hold_rep = self.ctl.val().h_lab;
        }
    }
}
