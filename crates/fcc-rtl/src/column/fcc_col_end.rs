//! `FccColEnd`: the union-find queue's input and the frame end's ops
//! (docs/column-core.md, item 8, "The slot table half"). While pixels
//! come, the queue takes the packer's entries (`pk_*`). The packer's
//! marker of the frame's last column starts the frame end and is held
//! back (its entry goes without it): `FccRunAcc` may then flush the rows'
//! runs still open (`drain_ok`); each of those flushes (`f_end`) becomes a
//! find of its run's label, in the flushes' order, so that the finds meet
//! their accumulators in `FccFlushWait`; after the last (`done`) come the
//! last column's marker and the frame end's, column `C`. So the clusters
//! those finds leave quiet are reported before the last column is passed
//! and close there (spec §9.2: holds 1 and 2 end with it), and those held
//! by hold 4 (the find's `ring`, `f_ring`) wait for the frame end. From
//! the last column's marker to the frame end's, `busy` keeps the next
//! frame's pixels out (`FccColTable`), so the packer sends nothing while
//! the frame end's ops go (a frame-end flush cannot wait: `FccRunAcc` is
//! not held); `FccRunAcc` is busy with the frame end meanwhile anyway, so
//! this costs the cycles of the markers at most.
//!
//! The frame end's marker carries the frame's flags (spec §9.4's end
//! beat): `ring`, a run of the frame refused a label (`refused`, a pixel
//! taken that was, kept since the last frame end's marker); `row` bit 0,
//! the frame's input error (`frame_err`, the input's flag of its last
//! frame, read as the marker goes).

use rust_hdl::prelude::*;

use super::fcc_set_queue::SetQBundle;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColEnd {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The frame's last column, `C - 1` (constant while a frame runs).
    pub last_col: Signal<In, Bits<12>>,
    /// The packer's entry.
    pub pk_valid: Signal<In, Bit>,
    pub pk: Signal<In, SetQBundle>,
    /// `FccRunAcc`'s flushes (`f_end`: the frame end's) and `done`.
    pub f_valid: Signal<In, Bit>,
    pub f_end: Signal<In, Bit>,
    pub f_label: Signal<In, Bits<16>>,
    /// The frame end's flush is of a run held by hold 4: its find carries
    /// `ring`, so that its cluster is held to the frame end.
    pub f_ring: Signal<In, Bit>,
    pub done: Signal<In, Bit>,
    /// A pixel taken whose run was refused a label; the input's error
    /// flag of the frame.
    pub refused: Signal<In, Bit>,
    pub frame_err: Signal<In, Bit>,
    /// The frame-end flush may read rows.
    pub drain_ok: Signal<Out, Bit>,
    /// The frame end's ops are under way: no pixel may enter.
    pub busy: Signal<Out, Bit>,
    /// The queue's entry.
    pub e_valid: Signal<Out, Bit>,
    pub e: Signal<Out, SetQBundle>,
    tail: DFF<Bit>,
    owed: DFF<Bit>,
    owed_end: DFF<Bit>,
    strip: Signal<Local, Bit>,
    free: Signal<Local, Bit>,
    mark_last: Signal<Local, Bit>,
    mark_end: Signal<Local, Bit>,
    ovf: DFF<Bit>,
    end_find: Signal<Local, Bit>,
    none: Constant<SetQBundle>,
    one: Constant<Bits<12>>,
    one7: Constant<Bits<7>>,
}

impl Default for FccColEnd {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_col: Default::default(),
            pk_valid: Default::default(),
            pk: Default::default(),
            f_valid: Default::default(),
            f_end: Default::default(),
            f_label: Default::default(),
            f_ring: Default::default(),
            done: Default::default(),
            refused: Default::default(),
            frame_err: Default::default(),
            drain_ok: Default::default(),
            busy: Default::default(),
            e_valid: Default::default(),
            e: Default::default(),
            tail: Default::default(),
            owed: Default::default(),
            owed_end: Default::default(),
            strip: Default::default(),
            free: Default::default(),
            mark_last: Default::default(),
            mark_end: Default::default(),
            ovf: Default::default(),
            end_find: Default::default(),
            none: Constant::new(SetQBundle::default()),
            one: kb(1),
            one7: kb(1),
        }
    }
}

impl Logic for FccColEnd {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tail, owed, owed_end, ovf);
        self.ovf.d.next = self.ovf.q.val() | self.refused.val();
        // The last column's marker: the frame end starts, the marker waits.
        self.strip.next =
            self.pk_valid.val() & self.pk.val().mark & (self.pk.val().col == self.last_col.val());
        self.tail.d.next = self.tail.q.val() | self.strip.val();
        if self.done.val() {
            self.tail.d.next = false;
        }
        self.drain_ok.next = self.tail.q.val();
        self.busy.next = self.tail.q.val() | self.owed.q.val() | self.owed_end.q.val();
        self.end_find.next = self.f_valid.val() & self.f_end.val();
        // The markers are owed from the cycle after `done` until they go,
        // the last column's, then the frame end's.
        self.free.next = !self.pk_valid.val() & !self.end_find.val();
        self.mark_last.next = self.free.val() & self.owed.q.val();
        self.mark_end.next = self.free.val() & !self.owed.q.val() & self.owed_end.q.val();
        self.owed.d.next = self.done.val() | (self.owed.q.val() & !self.mark_last.val());
        self.owed_end.d.next =
            self.mark_last.val() | (self.owed_end.q.val() & !self.mark_end.val());
        self.e_valid.next = (self.pk_valid.val()
            & (self.pk.val().find
                | self.pk.val().make
                | self.pk.val().join
                | (self.pk.val().mark & !self.strip.val())))
            | self.end_find.val()
            | self.owed.q.val()
            | self.owed_end.q.val();
        self.e.next = self.pk.val();
        if self.strip.val() {
            self.e.next.mark = false;
        }
        if !self.pk_valid.val() {
            self.e.next = self.none.val();
            if self.end_find.val() {
                self.e.next.find = true;
                self.e.next.f = self.f_label.val();
                self.e.next.ring = self.f_ring.val();
                self.e.next.col = self.last_col.val();
            } else if self.owed.q.val() {
                self.e.next.mark = true;
                self.e.next.col = self.last_col.val();
            } else if self.owed_end.q.val() {
                self.e.next.mark = true;
                self.e.next.col = self.last_col.val() + self.one.val();
                self.e.next.ring = self.ovf.q.val();
                if self.frame_err.val() {
                    self.e.next.row = self.one7.val();
                }
                self.ovf.d.next = false;
            }
        }
        if self.rst.val() {
            self.tail.d.next = false;
            self.owed.d.next = false;
            self.owed_end.d.next = false;
            self.ovf.d.next = false;
        }
    }
}
