//! `FccRowRoots`: the front of the column core's slot table
//! (docs/column-core.md, "Row roots"). Pixels arrive in column order with
//! their run's label (`FccRowRuns`) and their pass-2 hits (`FccColDist`:
//! per window entry, a hit and the label of the entry's run); out come the
//! same pixels with the record slots of the clusters they name, and the
//! merges between clusters, as one ordered stream of events: in a cycle,
//! the pixel event (`out`, `out_*`), then the merge (`m_*`).
//!
//! Each row keeps its last `h + 1` runs' labels and their clusters' slots
//! (`FccRootTable`); the `K` rows around the pixel travel beside it in
//! `FccRootWindow`. A window row spans `h + 1` columns, so every run a hit
//! names is among them and no label is ever looked up in block RAM. Every
//! slot lives in flip-flops, and a merge of slot `a` into `b` rewrites every
//! `a` at the edge after it is decided, so the slots a pixel finds are
//! current but for the merge being broadcast in its cycle, which
//! `FccRootMatch` applies on the way. `FccJoinPick` picks the merge the
//! pixel asks for; a pixel that joins more than one other cluster stays a
//! cycle for each more (`ready` low), which docs/column-core.md measures
//! at about 1 % of the slots.
//!
//! Stages: P0 takes the input while `ready` and works out the table row
//! that enters the window with it, `(i + h) mod R`; A holds the pixel whose
//! window is in `FccRootWindow`, looks its labels up and asks for a merge
//! (`m_*` next cycle). A pixel that completes pushes a run it starts into
//! the table and the window with `new_slot` (`take`): the slot pool's head,
//! which must not change until taken and must not be empty when a run
//! starts (spec §9.1's open limit keeps it so). `miss` (sticky until reset)
//! says a label named was not found.

use rust_hdl::prelude::*;

use super::fcc_join_pick::FccJoinPick;
use super::fcc_root_match::FccRootMatch;
use super::fcc_root_table::FccRootTable;
use super::fcc_root_window::FccRootWindow;
use super::{RunPix, SLOT_BITS};
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRowRoots {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Pixels in, while `ready`.
    pub inp: Signal<In, RunPix>,
    pub inp_hit: Vec<Signal<In, Bit>>,
    pub inp_label: Vec<Signal<In, Bits<16>>>,
    pub ready: Signal<Out, Bit>,
    /// The frame's last row, R - 1 (constant while a frame runs).
    pub last_row: Signal<In, Bits<7>>,
    // The slot pool's head, and `take` pops it.
    pub new_slot: Signal<In, Bits<SLOT_BITS>>,
    pub take: Signal<Out, Bit>,
    // The pixel event: the pixel, its run's slot, its row's hold changes.
    pub out: Signal<Out, RunPix>,
    pub out_own: Signal<Out, Bits<SLOT_BITS>>,
    pub out_drop_ok: Signal<Out, Bit>,
    pub out_drop: Signal<Out, Bits<SLOT_BITS>>,
    pub out_add_ok: Signal<Out, Bit>,
    pub out_add: Signal<Out, Bits<SLOT_BITS>>,
    // The merge of slot `m_from` into `m_into`, being broadcast.
    pub m_valid: Signal<Out, Bit>,
    pub m_from: Signal<Out, Bits<SLOT_BITS>>,
    pub m_into: Signal<Out, Bits<SLOT_BITS>>,
    pub miss: Signal<Out, Bit>,
    row_table: FccRootTable,
    window: FccRootWindow,
    matcher: FccRootMatch,
    pick: FccJoinPick,
    p0_pix: DFF<RunPix>,
    p0_hit: Vec<DFF<Bit>>,
    p0_label: Vec<DFF<Bits<16>>>,
    p0_row: DFF<Bits<7>>,
    a_pix: DFF<RunPix>,
    a_hit: Vec<DFF<Bit>>,
    a_label: Vec<DFF<Bits<16>>>,
    stall: Signal<Local, Bit>,
    done: Signal<Local, Bit>,
    /// `R - h`: from this row on, `i + h` is the next column's row
    /// `i + h - R`.
    wrap_at: Signal<Local, Bits<7>>,
    m_q: DFF<Bit>,
    from_q: DFF<Bits<SLOT_BITS>>,
    into_q: DFF<Bits<SLOT_BITS>>,
    out_q: DFF<RunPix>,
    own_q: DFF<Bits<SLOT_BITS>>,
    drop_ok_q: DFF<Bit>,
    drop_q: DFF<Bits<SLOT_BITS>>,
    add_ok_q: DFF<Bit>,
    add_q: DFF<Bits<SLOT_BITS>>,
    miss_q: DFF<Bit>,
    h7: Constant<Bits<7>>,
    hm1: Constant<Bits<7>>,
    pix_zero: Constant<RunPix>,
}

impl FccRowRoots {
    /// For frames of at most `rows` rows and filter size `k`.
    pub fn new(rows: usize, k: usize) -> Self {
        let h = (k - 1) / 2;
        let ne = k * h;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            inp_hit: vec_of(ne),
            inp_label: vec_of(ne),
            ready: Default::default(),
            last_row: Default::default(),
            new_slot: Default::default(),
            take: Default::default(),
            out: Default::default(),
            out_own: Default::default(),
            out_drop_ok: Default::default(),
            out_drop: Default::default(),
            out_add_ok: Default::default(),
            out_add: Default::default(),
            m_valid: Default::default(),
            m_from: Default::default(),
            m_into: Default::default(),
            miss: Default::default(),
            row_table: FccRootTable::new(rows, h + 1),
            window: FccRootWindow::new(k),
            matcher: FccRootMatch::new(k),
            pick: FccJoinPick::new(ne),
            p0_pix: Default::default(),
            p0_hit: vec_of(ne),
            p0_label: vec_of(ne),
            p0_row: Default::default(),
            a_pix: Default::default(),
            a_hit: vec_of(ne),
            a_label: vec_of(ne),
            stall: Default::default(),
            done: Default::default(),
            wrap_at: Default::default(),
            m_q: Default::default(),
            from_q: Default::default(),
            into_q: Default::default(),
            out_q: Default::default(),
            own_q: Default::default(),
            drop_ok_q: Default::default(),
            drop_q: Default::default(),
            add_ok_q: Default::default(),
            add_q: Default::default(),
            miss_q: Default::default(),
            h7: kb(h as u64),
            hm1: kb(h as u64 - 1),
            pix_zero: Constant::new(RunPix::default()),
        }
    }
}

impl Logic for FccRowRoots {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, p0_pix, p0_row, a_pix, m_q, from_q, into_q, out_q, own_q, drop_ok_q, drop_q,
            add_ok_q, add_q, miss_q
        );
        // A holds its pixel while it asks for one merge more.
        self.stall.next = self.a_pix.q.val().valid & self.pick.more.val();
        self.done.next = self.a_pix.q.val().valid & !self.pick.more.val();
        self.ready.next = !self.stall.val();
        // P0: the input, and the table row entering the window with it.
        self.wrap_at.next = self.last_row.val() - self.hm1.val();
        if !self.stall.val() {
            self.p0_pix.d.next = self.inp.val();
            self.p0_row.d.next = self.inp.val().row + self.h7.val();
            if self.inp.val().row >= self.wrap_at.val() {
                self.p0_row.d.next = self.inp.val().row - self.wrap_at.val();
            }
            self.a_pix.d.next = self.p0_pix.q.val();
        }
        for e in 0..self.p0_hit.len() {
            self.p0_hit[e].clock.next = self.clk.val();
            self.p0_label[e].clock.next = self.clk.val();
            self.a_hit[e].clock.next = self.clk.val();
            self.a_label[e].clock.next = self.clk.val();
            self.p0_hit[e].d.next = self.p0_hit[e].q.val();
            self.p0_label[e].d.next = self.p0_label[e].q.val();
            self.a_hit[e].d.next = self.a_hit[e].q.val();
            self.a_label[e].d.next = self.a_label[e].q.val();
            if !self.stall.val() {
                self.p0_hit[e].d.next = self.inp_hit[e].val();
                self.p0_label[e].d.next = self.inp_label[e].val();
                self.a_hit[e].d.next = self.p0_hit[e].q.val();
                self.a_label[e].d.next = self.p0_label[e].q.val();
            }
            self.matcher.ent_hit[e].next = self.a_hit[e].q.val();
            self.matcher.ent_label[e].next = self.a_label[e].q.val();
            self.pick.ent_ok[e].next = self.matcher.ent_ok[e].val();
            self.pick.ent_slot[e].next = self.matcher.ent_slot[e].val();
        }
        // The table and the window: the row entering, the run pushed, the
        // merge broadcast.
        self.row_table.clk.next = self.clk.val();
        self.row_table.rst.next = self.rst.val();
        self.window.clk.next = self.clk.val();
        self.window.rst.next = self.rst.val();
        self.row_table.rd_row.next = self.p0_row.q.val();
        self.window.shift.next = !self.stall.val() & self.p0_pix.q.val().valid;
        for k in 0..self.row_table.rd_label.len() {
            self.window.load_label[k].next = self.row_table.rd_label[k].val();
            self.window.load_slot[k].next = self.row_table.rd_slot[k].val();
        }
        self.window.load_first.next = self.row_table.rd_first.val();
        self.row_table.push.next = self.done.val() & self.a_pix.q.val().start;
        self.row_table.push_first.next = self.a_pix.q.val().ring_first;
        self.row_table.push_row.next = self.a_pix.q.val().row;
        self.row_table.push_label.next = self.a_pix.q.val().label;
        self.row_table.push_slot.next = self.new_slot.val();
        self.window.push.next = self.done.val() & self.a_pix.q.val().start;
        self.window.push_first.next = self.a_pix.q.val().ring_first;
        self.window.push_label.next = self.a_pix.q.val().label;
        self.window.push_slot.next = self.new_slot.val();
        self.take.next = self.done.val() & self.a_pix.q.val().start;
        self.row_table.rw_valid.next = self.m_q.q.val();
        self.row_table.rw_from.next = self.from_q.q.val();
        self.row_table.rw_into.next = self.into_q.q.val();
        self.window.rw_valid.next = self.m_q.q.val();
        self.window.rw_from.next = self.from_q.q.val();
        self.window.rw_into.next = self.into_q.q.val();
        // A: the pixel's lookups and its merge.
        for j in 0..self.window.label.len() {
            self.matcher.label[j].next = self.window.label[j].val();
            self.matcher.slot[j].next = self.window.slot[j].val();
        }
        self.matcher.centre_first.next = self.window.centre_first.val();
        self.matcher.lok.next = self.a_pix.q.val().lok;
        self.matcher.own_label.next = self.a_pix.q.val().label;
        self.matcher.start.next = self.a_pix.q.val().start;
        self.matcher.new_slot.next = self.new_slot.val();
        self.matcher.drop_label.next = self.a_pix.q.val().hold_drop;
        self.matcher.add_label.next = self.a_pix.q.val().hold_add;
        self.matcher.ring.next = self.a_pix.q.val().ring;
        self.matcher.ring_b_label.next = self.a_pix.q.val().ring_b;
        self.matcher.rw_valid.next = self.m_q.q.val();
        self.matcher.rw_from.next = self.from_q.q.val();
        self.matcher.rw_into.next = self.into_q.q.val();
        self.pick.own_slot.next = self.matcher.own_slot.val();
        self.pick.ring.next = self.a_pix.q.val().ring;
        self.pick.ring_a_slot.next = self.matcher.ring_a_slot.val();
        self.pick.ring_b_slot.next = self.matcher.ring_b_slot.val();
        self.m_q.d.next = self.a_pix.q.val().valid & self.pick.m_valid.val();
        self.from_q.d.next = self.pick.m_from.val();
        self.into_q.d.next = self.pick.m_into.val();
        self.m_valid.next = self.m_q.q.val();
        self.m_from.next = self.from_q.q.val();
        self.m_into.next = self.into_q.q.val();
        // The pixel event.
        self.out_q.d.next = self.pix_zero.val();
        if self.done.val() {
            self.out_q.d.next = self.a_pix.q.val();
        }
        self.own_q.d.next = self.matcher.own_slot.val();
        self.drop_ok_q.d.next = self.matcher.drop_ok.val();
        self.drop_q.d.next = self.matcher.drop_slot.val();
        self.add_ok_q.d.next = self.matcher.add_ok.val();
        self.add_q.d.next = self.matcher.add_slot.val();
        self.out.next = self.out_q.q.val();
        self.out_own.next = self.own_q.q.val();
        self.out_drop_ok.next = self.drop_ok_q.q.val();
        self.out_drop.next = self.drop_q.q.val();
        self.out_add_ok.next = self.add_ok_q.q.val();
        self.out_add.next = self.add_q.q.val();
        if self.a_pix.q.val().valid & self.matcher.miss.val() {
            self.miss_q.d.next = true;
        }
        self.miss.next = self.miss_q.q.val();
        if self.rst.val() {
            self.p0_pix.d.next = self.pix_zero.val();
            self.a_pix.d.next = self.pix_zero.val();
            self.m_q.d.next = false;
            self.out_q.d.next = self.pix_zero.val();
            self.miss_q.d.next = false;
        }
    }
}
