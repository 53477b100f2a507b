//! `FccColTable`: the column core's slot table half (docs/column-core.md,
//! item 8, "The slot table half"): the slot buffer's head (a pixel with
//! its run and joins, `FccColIn`) into the representative rows
//! (`FccRepJoins`) and the run accumulators (`FccRunAcc`) together, the
//! packer (`FccSetPack`) and the frame end's ops (`FccColEnd`) into the
//! union-find's queue (`FccSetQueue`), the flushes' accumulators into
//! their wait (`FccFlushWait`). Out of it: the queue's events (a make's
//! label and slot, a find's root and slot, a join's slots kept and gone,
//! a column's marker) and the oldest accumulator waiting for its find,
//! for the record store. `ev_ring` is a make's ring flag, a join's seam
//! (the ring check's join), a frame-end find's hold 4, and the frame end
//! marker's overflow (a pixel taken whose run was refused a label), whose
//! `ev_row` bit 0 is the input's error flag of the frame (`frame_err`).
//!
//! A pixel is taken only when both blocks take it, the flushes' wait and
//! the queue have room and the frame end's ops are not under way
//! (`FccColEnd.busy`); the frame end's flush reads its rows under the same
//! rooms. The frame is done when its marker of column `C` is out. Wiring
//! only.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_end::FccColEnd;
use super::fcc_flush_wait::FccFlushWait;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_rep_joins::FccRepJoins;
use super::fcc_run_acc::{FccRunAcc, RUN_ACC_LATENCY};
use super::fcc_set_pack::FccSetPack;
use super::fcc_set_queue::FccSetQueue;
use super::{AccWord, RunPix};
use crate::fcc_fanout_net::FccFanoutNet;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccColTable {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The frame's `R - 1`, `C - 1` and `C / 2` (run parameters).
    pub last_row: Signal<In, Bits<7>>,
    pub last_col: Signal<In, Bits<12>>,
    pub half: Signal<In, Bits<12>>,
    /// The slot buffer's head; `take` lets it go.
    pub valid: Signal<In, Bit>,
    pub centre: Signal<In, RunPix>,
    pub hit: Vec<Signal<In, Bit>>,
    pub hit_label: Vec<Signal<In, Bits<16>>>,
    pub take: Signal<Out, Bit>,
    /// The slot pool's head, and `slot_take` pops it.
    /// The input's error flag of its last frame (read at the frame end).
    pub frame_err: Signal<In, Bit>,
    pub slot_ok: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    pub slot_take: Signal<Out, Bit>,
    /// The queue's events (as `FccSetQueue`'s `ev_*`), taken by `ev_take`.
    pub ev_valid: Signal<Out, Bit>,
    pub ev_make: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_mark: Signal<Out, Bit>,
    pub ev_ring: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_label: Signal<Out, Bits<16>>,
    pub ev_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_other: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_col: Signal<Out, Bits<12>>,
    pub ev_row: Signal<Out, Bits<7>>,
    pub ev_take: Signal<In, Bit>,
    /// The oldest flush's accumulator, taken by `acc_take` with its find.
    pub acc_valid: Signal<Out, Bit>,
    pub acc: Signal<Out, AccWord>,
    pub acc_take: Signal<In, Bit>,
    /// A label named that its row does not hold (`FccRepJoins`' `miss`);
    /// sticky: a run continued without its start, a flush with no place or
    /// a take with no accumulator.
    pub miss: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
    go: Signal<Local, Bit>,
    /// `go` reaches every lane of the slot buffer and both blocks'
    /// pipelines: its logic is replicated.
    go_net: FccFanoutNet<Bit>,
    joins: FccRepJoins,
    runs: FccRunAcc,
    pack: FccSetPack,
    ends: FccColEnd,
    queue: FccSetQueue,
    flushes: FccFlushWait,
}

impl FccColTable {
    /// The half of the build's rows and K.
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_row: Default::default(),
            last_col: Default::default(),
            half: Default::default(),
            valid: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            hit_label: vec_of(n),
            take: Default::default(),
            frame_err: Default::default(),
            slot_ok: Default::default(),
            slot: Default::default(),
            slot_take: Default::default(),
            ev_valid: Default::default(),
            ev_make: Default::default(),
            ev_join: Default::default(),
            ev_mark: Default::default(),
            ev_ring: Default::default(),
            ev_merged: Default::default(),
            ev_label: Default::default(),
            ev_slot: Default::default(),
            ev_other: Default::default(),
            ev_col: Default::default(),
            ev_row: Default::default(),
            ev_take: Default::default(),
            acc_valid: Default::default(),
            acc: Default::default(),
            acc_take: Default::default(),
            miss: Default::default(),
            bad: Default::default(),
            go: Default::default(),
            go_net: Default::default(),
            joins: FccRepJoins::new(p.rows, p.fsize),
            runs: FccRunAcc::new(p.rows),
            pack: Default::default(),
            ends: Default::default(),
            queue: FccSetQueue::new(p),
            flushes: FccFlushWait::new(RUN_ACC_LATENCY),
        }
    }
}

impl Logic for FccColTable {
    #[hdl_gen]
    fn update(&mut self) {
        // The head goes into both blocks together, while both and the
        // rooms behind them allow.
        self.go_net.x.next = self.valid.val()
            & self.joins.ready.val()
            & self.runs.ready.val()
            & self.flushes.room.val()
            & self.queue.room.val()
            & !self.ends.busy.val();
        self.go.next = self.go_net.y.val();
        self.take.next = self.go.val();
        self.joins.clk.next = self.clk.val();
        self.joins.rst.next = self.rst.val();
        self.joins.inp.next = self.centre.val();
        self.joins.inp.next.valid = self.go.val();
        for e in 0..self.hit.len() {
            self.joins.inp_hit[e].next = self.hit[e].val();
            self.joins.inp_label[e].next = self.hit_label[e].val();
        }
        self.joins.last_row.next = self.last_row.val();
        self.miss.next = self.joins.miss.val();
        self.runs.clk.next = self.clk.val();
        self.runs.rst.next = self.rst.val();
        self.runs.inp.next = self.centre.val();
        self.runs.inp.next.valid = self.go.val();
        self.runs.half.next = self.half.val();
        self.runs.last_row.next = self.last_row.val();
        self.runs.drain_go.next =
            self.ends.drain_ok.val() & self.flushes.room.val() & self.queue.room.val();
        // The packer, from the representative rows' pixels and joins.
        self.pack.clk.next = self.clk.val();
        self.pack.rst.next = self.rst.val();
        self.pack.p_valid.next = self.joins.out.val().valid;
        self.pack.p_row.next = self.joins.out.val().row;
        self.pack.p_col.next = self.joins.out.val().col;
        self.pack.p_start.next = self.joins.out.val().start;
        self.pack.p_label.next = self.joins.out.val().label;
        self.pack.p_ring_first.next = self.joins.out.val().ring_first;
        self.pack.p_hold_drop.next = self.joins.out.val().hold_drop;
        self.pack.p_hold_rep.next = self.joins.out.val().hold_rep;
        self.pack.j_valid.next = self.joins.j_valid.val();
        self.pack.j_a.next = self.joins.j_a.val();
        self.pack.j_b.next = self.joins.j_b.val();
        self.pack.j_under.next = self.joins.j_under.val();
        self.pack.j_seam.next = self.joins.j_seam.val();
        self.pack.j_more.next = self.joins.j_more.val();
        self.pack.last_row.next = self.last_row.val();
        // The queue's input: the packer's entries, the frame end's.
        self.ends.clk.next = self.clk.val();
        self.ends.rst.next = self.rst.val();
        self.ends.last_col.next = self.last_col.val();
        self.ends.pk_valid.next = self.pack.q_valid.val();
        self.ends.pk.next.find = self.pack.q_find.val();
        self.ends.pk.next.make = self.pack.q_make.val();
        self.ends.pk.next.join = self.pack.q_join.val();
        self.ends.pk.next.mark = self.pack.q_mark.val();
        self.ends.pk.next.ring = self.pack.q_ring.val();
        self.ends.pk.next.under = self.pack.q_under.val();
        self.ends.pk.next.seam = self.pack.q_seam.val();
        self.ends.pk.next.f = self.pack.q_f.val();
        self.ends.pk.next.m = self.pack.q_m.val();
        self.ends.pk.next.ja = self.pack.q_ja.val();
        self.ends.pk.next.jb = self.pack.q_jb.val();
        self.ends.pk.next.col = self.pack.q_col.val();
        self.ends.pk.next.row = self.pack.q_row.val();
        self.ends.f_valid.next = self.runs.f_valid.val();
        self.ends.f_end.next = self.runs.f_end.val();
        self.ends.f_label.next = self.runs.f_label.val();
        self.ends.f_ring.next = self.runs.f_ring.val();
        self.ends.done.next = self.runs.done.val();
        self.ends.refused.next = self.go.val() & self.centre.val().refused;
        self.ends.frame_err.next = self.frame_err.val();
        self.queue.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.queue.in_valid.next = self.ends.e_valid.val();
        self.queue.in_find.next = self.ends.e.val().find;
        self.queue.in_make.next = self.ends.e.val().make;
        self.queue.in_join.next = self.ends.e.val().join;
        self.queue.in_mark.next = self.ends.e.val().mark;
        self.queue.in_ring.next = self.ends.e.val().ring;
        self.queue.in_under.next = self.ends.e.val().under;
        self.queue.in_seam.next = self.ends.e.val().seam;
        self.queue.in_f.next = self.ends.e.val().f;
        self.queue.in_m.next = self.ends.e.val().m;
        self.queue.in_ja.next = self.ends.e.val().ja;
        self.queue.in_jb.next = self.ends.e.val().jb;
        self.queue.in_col.next = self.ends.e.val().col;
        self.queue.in_row.next = self.ends.e.val().row;
        self.queue.slot_ok.next = self.slot_ok.val();
        self.queue.slot.next = self.slot.val();
        self.slot_take.next = self.queue.slot_take.val();
        self.ev_valid.next = self.queue.ev_valid.val();
        self.ev_make.next = self.queue.ev_make.val();
        self.ev_join.next = self.queue.ev_join.val();
        self.ev_mark.next = self.queue.ev_mark.val();
        self.ev_ring.next = self.queue.ev_ring.val();
        self.ev_merged.next = self.queue.ev_merged.val();
        self.ev_label.next = self.queue.ev_label.val();
        self.ev_slot.next = self.queue.ev_slot.val();
        self.ev_other.next = self.queue.ev_other.val();
        self.ev_col.next = self.queue.ev_col.val();
        self.ev_row.next = self.queue.ev_row.val();
        self.queue.ev_take.next = self.ev_take.val();
        // The flushes' accumulators wait for their finds.
        self.flushes.clk.next = self.clk.val();
        self.flushes.rst.next = self.rst.val();
        self.flushes.push.next = self.runs.f_valid.val();
        self.flushes.din.next = self.runs.f_acc.val();
        self.flushes.take.next = self.acc_take.val();
        self.acc_valid.next = self.flushes.valid.val();
        self.acc.next = self.flushes.dout.val();
        self.bad.next = self.runs.bad.val() | self.flushes.bad.val();
    }
}
