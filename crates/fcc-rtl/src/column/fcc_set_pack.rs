//! `FccSetPack`: a pixel slot's ops packed into the entries of the
//! union-find's queue (`FccSetQueue`, docs/column-core.md, item 3).
//! In come the pixels out of `FccRepJoins` (`p_*`, a slot a cycle at
//! most) and its joins (`j_*`): a pixel's first join in the pixel's
//! cycle, its others in the cycles after it while `j_more` is high, all
//! before the next pixel. Out go the entries (`q_*`, registered), in the
//! queue's part order:
//!
//! * the pixel's cycle: the flush of the run its row stops holding (a
//!   find of `p_hold_rep`, a label of the run's cluster, when
//!   `p_hold_drop` names one), the make of the run it starts (`p_start`:
//!   `p_label`, its first pixel `p_col`, `p_row`, its ring flag), its
//!   first join (`j_under`: the join files the run the pixel started under
//!   its neighbours' cluster), and at the column's last row, with no join
//!   to come, the column's marker;
//! * each further join in an entry of its own; the last row's marker
//!   with the join after which `j_more` falls, or alone in the first
//!   cycle it is low (no pixel comes out then: `FccRepJoins` takes its
//!   next pixel in that cycle).
//!
//! A cycle with no op makes no entry.

use rust_hdl::prelude::*;

use super::fcc_set_queue::SetQBundle;
use crate::fcc_fanout_reg::FccFanoutReg;

#[derive(LogicBlock, Default)]
pub struct FccSetPack {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub p_valid: Signal<In, Bit>,
    pub p_row: Signal<In, Bits<7>>,
    pub p_col: Signal<In, Bits<12>>,
    pub p_start: Signal<In, Bit>,
    pub p_label: Signal<In, Bits<16>>,
    pub p_ring_first: Signal<In, Bit>,
    pub p_hold_drop: Signal<In, Bits<16>>,
    pub p_hold_rep: Signal<In, Bits<16>>,
    pub j_valid: Signal<In, Bit>,
    pub j_a: Signal<In, Bits<16>>,
    pub j_b: Signal<In, Bits<16>>,
    pub j_under: Signal<In, Bit>,
    /// The join is the ring check's.
    pub j_seam: Signal<In, Bit>,
    /// The pixel out last has joins still to come after this cycle's.
    pub j_more: Signal<In, Bit>,
    /// The frame's last row, `R - 1` (constant while a frame runs).
    pub last_row: Signal<In, Bits<7>>,
    pub q_valid: Signal<Out, Bit>,
    pub q_find: Signal<Out, Bit>,
    pub q_make: Signal<Out, Bit>,
    pub q_join: Signal<Out, Bit>,
    pub q_mark: Signal<Out, Bit>,
    pub q_ring: Signal<Out, Bit>,
    pub q_under: Signal<Out, Bit>,
    pub q_seam: Signal<Out, Bit>,
    pub q_f: Signal<Out, Bits<16>>,
    pub q_m: Signal<Out, Bits<16>>,
    pub q_ja: Signal<Out, Bits<16>>,
    pub q_jb: Signal<Out, Bits<16>>,
    pub q_col: Signal<Out, Bits<12>>,
    pub q_row: Signal<Out, Bits<7>>,
    /// The entry and whether it holds an op.
    e: DFF<SetQBundle>,
    ev: FccFanoutReg<Bit>,
    /// The last row's marker waits for the pixel's joins; its column.
    pend: DFF<Bit>,
    mcol: DFF<Bits<12>>,
    /// A marker is owed: the pixel is the column's last row's, or one was.
    owed: Signal<Local, Bit>,
    ent: Signal<Local, SetQBundle>,
}

impl Logic for FccSetPack {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, e, ev, pend, mcol);
        self.owed.next =
            (self.p_valid.val() & (self.p_row.val() == self.last_row.val())) | self.pend.q.val();
        self.pend.d.next = self.owed.val() & self.j_more.val();
        self.mcol.d.next = self.mcol.q.val();
        if self.p_valid.val() {
            self.mcol.d.next = self.p_col.val();
        }
        self.ent.next.find = self.p_valid.val() & self.p_hold_drop.val().any();
        self.ent.next.make = self.p_valid.val() & self.p_start.val();
        self.ent.next.join = self.j_valid.val();
        self.ent.next.mark = self.owed.val() & !self.j_more.val();
        self.ent.next.ring = self.p_ring_first.val();
        self.ent.next.under = self.j_valid.val() & self.j_under.val();
        self.ent.next.seam = self.j_valid.val() & self.j_seam.val();
        self.ent.next.f = self.p_hold_rep.val();
        self.ent.next.m = self.p_label.val();
        self.ent.next.ja = self.j_a.val();
        self.ent.next.jb = self.j_b.val();
        self.ent.next.col = self.mcol.q.val();
        if self.p_valid.val() {
            self.ent.next.col = self.p_col.val();
        }
        self.ent.next.row = self.p_row.val();
        self.e.d.next = self.ent.val();
        self.ev.d.next =
            self.ent.val().find | self.ent.val().make | self.ent.val().join | self.ent.val().mark;
        self.q_valid.next = self.ev.q.val();
        self.q_find.next = self.e.q.val().find;
        self.q_make.next = self.e.q.val().make;
        self.q_join.next = self.e.q.val().join;
        self.q_mark.next = self.e.q.val().mark;
        self.q_ring.next = self.e.q.val().ring;
        self.q_under.next = self.e.q.val().under;
        self.q_seam.next = self.e.q.val().seam;
        self.q_f.next = self.e.q.val().f;
        self.q_m.next = self.e.q.val().m;
        self.q_ja.next = self.e.q.val().ja;
        self.q_jb.next = self.e.q.val().jb;
        self.q_col.next = self.e.q.val().col;
        self.q_row.next = self.e.q.val().row;
        if self.rst.val() {
            self.ev.d.next = false;
            self.pend.d.next = false;
        }
    }
}
