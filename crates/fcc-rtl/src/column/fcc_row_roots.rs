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
//! names is among them and no label is ever looked up in block RAM. A merge
//! of slot `a` into `b` is broadcast for a cycle and rewrites every `a`, in
//! the table, the window and every stage (`FccSlotBank`), at the edge that
//! ends it.
//!
//! Stages (every stage holds while R holds a pixel, from a flip-flop; no
//! stage waits on a decision made in its own cycle):
//! * IN takes the input while `ready` and works out the table row that
//!   enters the window with the pixel, `(i + h) mod R`; P0 holds that row,
//!   read (an OR of masked rows, its slots kept current by a `late` bank).
//! * A1: the window shifts, the row enters it, and a run the pixel starts
//!   is pushed with `new_slot` (`take`: the slot pool's head, never empty
//!   when a run starts: spec §9.1's open limit keeps it so); `FccRootMatch`
//!   looks the pixel's labels up.
//! * A2 (a `late` bank): the slots found, with the merge they missed.
//! * B: `FccJoinFlags`, which joins cross clusters.
//! * C: `FccJoinPick` asks for the first such merge (into the pixel's
//!   cluster), broadcast next cycle; flags a cycle old may ask for a slot
//!   into itself, which is dropped from the output.
//! * D: the joins still crossing clusters after it (a pixel joining two
//!   clusters or more, or a ring pair besides), registered in R0.
//! * R: a pixel with joins left holds the pipeline (`ready` low) and asks
//!   for them itself: ask, then check (its flags again, with that merge
//!   applied), until none is left; then, as every pixel, it leaves as an
//!   event, with its slots as they are after the merges before it.
//!
//! The replay's few registers (`r_left`, `r_check`, `r_flags_hold`) stay in
//! this block rather than a sub-block of their own: the stages' holds must
//! be those flip-flops' outputs as they are, since a hold computed in a
//! sub-block that also reads the stages' flags makes Verilator see a
//! combinational loop through every stage (`UNOPTFLAT`).
//!
//! `miss` (sticky until reset) says a label named was not found.

use rust_hdl::prelude::*;

use super::fcc_hold_bank::FccHoldBank;
use super::fcc_join_flags::FccJoinFlags;
use super::fcc_join_pick::FccJoinPick;
use super::fcc_root_match::FccRootMatch;
use super::fcc_root_table::FccRootTable;
use super::fcc_root_window::FccRootWindow;
use super::fcc_slot_bank::FccSlotBank;
use super::{slot_index, RunPix, SLOT_BITS};
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
    // A merge of slot `m_from` into `m_into`.
    pub m_valid: Signal<Out, Bit>,
    pub m_from: Signal<Out, Bits<SLOT_BITS>>,
    pub m_into: Signal<Out, Bits<SLOT_BITS>>,
    pub miss: Signal<Out, Bit>,
    row_table: FccRootTable,
    window: FccRootWindow,
    matcher: FccRootMatch,
    bank_a2: FccSlotBank,
    bank_b: FccSlotBank,
    bank_c: FccSlotBank,
    bank_d: FccSlotBank,
    bank_r0: FccSlotBank,
    bank_r: FccSlotBank,
    flags_b: FccJoinFlags,
    flags_d: FccJoinFlags,
    flags_r: FccJoinFlags,
    pick_c: FccJoinPick,
    pick_r: FccJoinPick,
    /// Each stage's hits; C's and R's with the joins flagged after them
    /// (entries, then the ring pair).
    hit_a2: FccHoldBank<Bit>,
    hit_b: FccHoldBank<Bit>,
    hit_c: FccHoldBank<Bit>,
    hit_d: FccHoldBank<Bit>,
    hit_r0: FccHoldBank<Bit>,
    hit_r: FccHoldBank<Bit>,
    in_pix: DFF<RunPix>,
    in_hit: Vec<DFF<Bit>>,
    in_label: Vec<DFF<Bits<16>>>,
    in_row: DFF<Bits<7>>,
    p0_pix: DFF<RunPix>,
    p0_hit: Vec<DFF<Bit>>,
    p0_label: Vec<DFF<Bits<16>>>,
    /// P0: the table row that enters the window with the pixel, read in
    /// the cycle before (its slots a `late` bank).
    rd_labels: FccHoldBank<Bits<16>>,
    rd_slots: FccSlotBank,
    a1_pix: DFF<RunPix>,
    a1_hit: Vec<DFF<Bit>>,
    a1_label: Vec<DFF<Bits<16>>>,
    a2_pix: DFF<RunPix>,
    b_pix: DFF<RunPix>,
    c_pix: DFF<RunPix>,
    d_pix: DFF<RunPix>,
    r0_pix: DFF<RunPix>,
    r_pix: DFF<RunPix>,
    /// R's pixel has joins left; R asks next (else it checks).
    r_left: DFF<Bit>,
    r_check: DFF<Bit>,
    /// R holds its flags: `r_left` but not `r_check`, registered beside
    /// them, so that every bank's hold is a flip-flop as it is.
    r_flags_hold: DFF<Bit>,
    adv: Signal<Local, Bit>,
    any_r0: Signal<Local, Bit>,
    push: Signal<Local, Bit>,
    r_ask: Signal<Local, Bit>,
    c_ask: Signal<Local, Bit>,
    /// `R - h`: from this row on, `i + h` is the next column's row
    /// `i + h - R`.
    wrap_at: Signal<Local, Bits<7>>,
    m_q: DFF<Bit>,
    from_q: DFF<Bits<SLOT_BITS>>,
    into_q: DFF<Bits<SLOT_BITS>>,
    mo_q: DFF<Bit>,
    mo_from: DFF<Bits<SLOT_BITS>>,
    mo_into: DFF<Bits<SLOT_BITS>>,
    e1_pix: DFF<RunPix>,
    e1_own: DFF<Bits<SLOT_BITS>>,
    e1_drop: DFF<Bits<SLOT_BITS>>,
    e1_add: DFF<Bits<SLOT_BITS>>,
    e2_pix: DFF<RunPix>,
    e2_own: DFF<Bits<SLOT_BITS>>,
    e2_drop: DFF<Bits<SLOT_BITS>>,
    e2_add: DFF<Bits<SLOT_BITS>>,
    miss_q: DFF<Bit>,
    h7: Constant<Bits<7>>,
    hm1: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    pix_zero: Constant<RunPix>,
    _ne: usize,
    /// Runs a row keeps, `h + 1`.
    _rn: usize,
    _n: usize,
    _joins: usize,
    _own: usize,
    _drop: usize,
    _add: usize,
}

impl FccRowRoots {
    /// For frames of at most `rows` rows and filter size `k`.
    pub fn new(rows: usize, k: usize) -> Self {
        let h = (k - 1) / 2;
        let ne = k * h;
        let ix = slot_index(ne);
        let n = ix.count;
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
            bank_a2: FccSlotBank::new(n, true),
            bank_b: FccSlotBank::new(n, false),
            bank_c: FccSlotBank::new(n, false),
            bank_d: FccSlotBank::new(n, false),
            bank_r0: FccSlotBank::new(n, false),
            bank_r: FccSlotBank::new(n, false),
            flags_b: FccJoinFlags::new(ne),
            flags_d: FccJoinFlags::new(ne),
            flags_r: FccJoinFlags::new(ne),
            pick_c: FccJoinPick::new(ne),
            pick_r: FccJoinPick::new(ne),
            hit_a2: FccHoldBank::new(ne),
            hit_b: FccHoldBank::new(ne),
            hit_c: FccHoldBank::new(2 * ne + 1),
            hit_d: FccHoldBank::new(ne),
            hit_r0: FccHoldBank::new(2 * ne + 1),
            hit_r: FccHoldBank::new(2 * ne + 1),
            in_pix: Default::default(),
            in_hit: vec_of(ne),
            in_label: vec_of(ne),
            in_row: Default::default(),
            p0_pix: Default::default(),
            p0_hit: vec_of(ne),
            p0_label: vec_of(ne),
            rd_labels: FccHoldBank::new(h + 1),
            rd_slots: FccSlotBank::new(h + 2, true),
            a1_pix: Default::default(),
            a1_hit: vec_of(ne),
            a1_label: vec_of(ne),
            a2_pix: Default::default(),
            b_pix: Default::default(),
            c_pix: Default::default(),
            d_pix: Default::default(),
            r0_pix: Default::default(),
            r_pix: Default::default(),
            r_left: Default::default(),
            r_check: Default::default(),
            r_flags_hold: Default::default(),
            adv: Default::default(),
            any_r0: Default::default(),
            push: Default::default(),
            r_ask: Default::default(),
            c_ask: Default::default(),
            wrap_at: Default::default(),
            m_q: Default::default(),
            from_q: Default::default(),
            into_q: Default::default(),
            mo_q: Default::default(),
            mo_from: Default::default(),
            mo_into: Default::default(),
            e1_pix: Default::default(),
            e1_own: Default::default(),
            e1_drop: Default::default(),
            e1_add: Default::default(),
            e2_pix: Default::default(),
            e2_own: Default::default(),
            e2_drop: Default::default(),
            e2_add: Default::default(),
            miss_q: Default::default(),
            h7: kb(h as u64),
            hm1: kb(h as u64 - 1),
            zero16: kb(0),
            pix_zero: Constant::new(RunPix::default()),
            _ne: ne,
            _rn: h + 1,
            _n: n,
            _joins: ix.joins,
            _own: ix.own,
            _drop: ix.drop,
            _add: ix.add,
        }
    }
}

impl Logic for FccRowRoots {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            in_pix,
            in_row,
            p0_pix,
            a1_pix,
            a2_pix,
            b_pix,
            c_pix,
            d_pix,
            r0_pix,
            r_pix,
            r_left,
            r_check,
            r_flags_hold,
            m_q,
            from_q,
            into_q,
            mo_q,
            mo_from,
            mo_into,
            e1_pix,
            e1_own,
            e1_drop,
            e1_add,
            e2_pix,
            e2_own,
            e2_drop,
            e2_add,
            miss_q
        );
        // Every stage moves on unless R holds a pixel with joins left.
        self.adv.next = !self.r_left.q.val();
        self.ready.next = self.adv.val();
        self.wrap_at.next = self.last_row.val() - self.hm1.val();
        if self.adv.val() {
            self.in_pix.d.next = self.inp.val();
            self.in_row.d.next = self.inp.val().row + self.h7.val();
            if self.inp.val().row >= self.wrap_at.val() {
                self.in_row.d.next = self.inp.val().row - self.wrap_at.val();
            }
            self.p0_pix.d.next = self.in_pix.q.val();
            self.a1_pix.d.next = self.p0_pix.q.val();
            self.a2_pix.d.next = self.a1_pix.q.val();
            self.b_pix.d.next = self.a2_pix.q.val();
            self.c_pix.d.next = self.b_pix.q.val();
            self.d_pix.d.next = self.c_pix.q.val();
            self.r0_pix.d.next = self.d_pix.q.val();
            self.r_pix.d.next = self.r0_pix.q.val();
        }
        for e in 0..self._ne {
            self.in_hit[e].clock.next = self.clk.val();
            self.in_label[e].clock.next = self.clk.val();
            self.in_hit[e].d.next = self.in_hit[e].q.val();
            self.in_label[e].d.next = self.in_label[e].q.val();
            self.p0_hit[e].clock.next = self.clk.val();
            self.p0_label[e].clock.next = self.clk.val();
            self.a1_hit[e].clock.next = self.clk.val();
            self.a1_label[e].clock.next = self.clk.val();
            self.p0_hit[e].d.next = self.p0_hit[e].q.val();
            self.p0_label[e].d.next = self.p0_label[e].q.val();
            self.a1_hit[e].d.next = self.a1_hit[e].q.val();
            self.a1_label[e].d.next = self.a1_label[e].q.val();
            if self.adv.val() {
                self.in_hit[e].d.next = self.inp_hit[e].val();
                self.in_label[e].d.next = self.inp_label[e].val();
                self.p0_hit[e].d.next = self.in_hit[e].q.val();
                self.p0_label[e].d.next = self.in_label[e].q.val();
                self.a1_hit[e].d.next = self.p0_hit[e].q.val();
                self.a1_label[e].d.next = self.p0_label[e].q.val();
            }
            self.matcher.ent_hit[e].next = self.a1_hit[e].q.val();
            self.matcher.ent_label[e].next = self.a1_label[e].q.val();
        }
        // Into A1: the window shifts, the table's row enters it, a run the
        // pixel starts is pushed.
        self.push.next = self.adv.val() & self.p0_pix.q.val().valid & self.p0_pix.q.val().start;
        self.take.next = self.push.val();
        self.row_table.clk.next = self.clk.val();
        self.row_table.rst.next = self.rst.val();
        self.window.clk.next = self.clk.val();
        self.window.rst.next = self.rst.val();
        self.row_table.rd_row.next = self.in_row.q.val();
        self.rd_labels.clk.next = self.clk.val();
        self.rd_slots.clk.next = self.clk.val();
        self.rd_labels.hold.next = self.r_left.q.val();
        self.rd_slots.hold.next = self.r_left.q.val();
        self.rd_slots.rw_valid.next = self.m_q.q.val();
        self.rd_slots.rw_from.next = self.from_q.q.val();
        self.rd_slots.rw_into.next = self.into_q.q.val();
        self.window.shift.next = self.adv.val() & self.p0_pix.q.val().valid;
        for nn in self._rn..(self._rn + 1) {
            for k in 0..self._rn {
                self.rd_labels.d[k].next = self.row_table.rd_label[k].val();
                self.rd_slots.d[k].next = self.row_table.rd_slot[k].val();
                self.window.load_label[k].next = self.rd_labels.q[k].val();
                self.window.load_slot[k].next = self.rd_slots.eff[k].val();
            }
            self.rd_slots.d[nn].next = self.row_table.rd_first.val();
            self.window.load_first.next = self.rd_slots.eff[nn].val();
        }
        self.row_table.push.next = self.push.val();
        self.row_table.push_first.next = self.p0_pix.q.val().ring_first;
        self.row_table.push_row.next = self.p0_pix.q.val().row;
        self.row_table.push_label.next = self.p0_pix.q.val().label;
        self.row_table.push_slot.next = self.new_slot.val();
        self.window.push.next = self.push.val();
        self.window.push_first.next = self.p0_pix.q.val().ring_first;
        self.window.push_label.next = self.p0_pix.q.val().label;
        self.window.push_slot.next = self.new_slot.val();
        // The merge broadcast.
        self.row_table.rw_valid.next = self.m_q.q.val();
        self.row_table.rw_from.next = self.from_q.q.val();
        self.row_table.rw_into.next = self.into_q.q.val();
        self.window.rw_valid.next = self.m_q.q.val();
        self.window.rw_from.next = self.from_q.q.val();
        self.window.rw_into.next = self.into_q.q.val();
        // A1: the lookups.
        for j in 0..self.window.label.len() {
            self.matcher.label[j].next = self.window.label[j].val();
            self.matcher.slot[j].next = self.window.slot[j].val();
        }
        self.matcher.centre_first.next = self.window.centre_first.val();
        self.matcher.lok.next = self.a1_pix.q.val().lok;
        self.matcher.own_label.next = self.a1_pix.q.val().label;
        self.matcher.drop_label.next = self.a1_pix.q.val().hold_drop;
        self.matcher.add_label.next = self.a1_pix.q.val().hold_add;
        self.matcher.ring.next = self.a1_pix.q.val().ring;
        self.matcher.ring_b_label.next = self.a1_pix.q.val().ring_b;
        // The banks: A2 to R.
        self.bank_a2.clk.next = self.clk.val();
        self.bank_b.clk.next = self.clk.val();
        self.bank_c.clk.next = self.clk.val();
        self.bank_d.clk.next = self.clk.val();
        self.bank_r0.clk.next = self.clk.val();
        self.bank_r.clk.next = self.clk.val();
        self.hit_a2.clk.next = self.clk.val();
        self.hit_b.clk.next = self.clk.val();
        self.hit_c.clk.next = self.clk.val();
        self.hit_d.clk.next = self.clk.val();
        self.hit_r0.clk.next = self.clk.val();
        self.hit_r.clk.next = self.clk.val();
        self.bank_a2.hold.next = self.r_left.q.val();
        self.bank_b.hold.next = self.r_left.q.val();
        self.bank_c.hold.next = self.r_left.q.val();
        self.bank_d.hold.next = self.r_left.q.val();
        self.bank_r0.hold.next = self.r_left.q.val();
        self.bank_r.hold.next = self.r_left.q.val();
        self.hit_a2.hold.next = self.r_left.q.val();
        self.hit_b.hold.next = self.r_left.q.val();
        self.hit_c.hold.next = self.r_left.q.val();
        self.hit_d.hold.next = self.r_left.q.val();
        self.hit_r0.hold.next = self.r_left.q.val();
        self.hit_r.hold.next = self.r_flags_hold.q.val();
        self.bank_a2.rw_valid.next = self.m_q.q.val();
        self.bank_a2.rw_from.next = self.from_q.q.val();
        self.bank_a2.rw_into.next = self.into_q.q.val();
        self.bank_b.rw_valid.next = self.m_q.q.val();
        self.bank_b.rw_from.next = self.from_q.q.val();
        self.bank_b.rw_into.next = self.into_q.q.val();
        self.bank_c.rw_valid.next = self.m_q.q.val();
        self.bank_c.rw_from.next = self.from_q.q.val();
        self.bank_c.rw_into.next = self.into_q.q.val();
        self.bank_d.rw_valid.next = self.m_q.q.val();
        self.bank_d.rw_from.next = self.from_q.q.val();
        self.bank_d.rw_into.next = self.into_q.q.val();
        self.bank_r0.rw_valid.next = self.m_q.q.val();
        self.bank_r0.rw_from.next = self.from_q.q.val();
        self.bank_r0.rw_into.next = self.into_q.q.val();
        self.bank_r.rw_valid.next = self.m_q.q.val();
        self.bank_r.rw_from.next = self.from_q.q.val();
        self.bank_r.rw_into.next = self.into_q.q.val();
        for j in 0..self._n {
            self.bank_a2.d[j].next = self.matcher.found[j].val();
            self.bank_b.d[j].next = self.bank_a2.eff[j].val();
            self.bank_c.d[j].next = self.bank_b.eff[j].val();
            self.bank_d.d[j].next = self.bank_c.eff[j].val();
            self.bank_r0.d[j].next = self.bank_d.eff[j].val();
            self.bank_r.d[j].next = self.bank_r0.eff[j].val();
        }
        for j in 0..self._joins {
            self.flags_b.slot[j].next = self.bank_b.held[j].val();
            self.flags_d.slot[j].next = self.bank_d.held[j].val();
            self.flags_r.slot[j].next = self.bank_r.held[j].val();
            self.pick_c.slot[j].next = self.bank_c.eff[j].val();
            self.pick_r.slot[j].next = self.bank_r.eff[j].val();
        }
        self.flags_b.rw_valid.next = self.m_q.q.val();
        self.flags_b.rw_from.next = self.from_q.q.val();
        self.flags_b.rw_into.next = self.into_q.q.val();
        self.flags_d.rw_valid.next = self.m_q.q.val();
        self.flags_d.rw_from.next = self.from_q.q.val();
        self.flags_d.rw_into.next = self.into_q.q.val();
        self.flags_r.rw_valid.next = self.m_q.q.val();
        self.flags_r.rw_from.next = self.from_q.q.val();
        self.flags_r.rw_into.next = self.into_q.q.val();
        self.flags_b.ring.next = self.b_pix.q.val().ring;
        self.flags_d.ring.next = self.d_pix.q.val().ring;
        self.flags_r.ring.next = self.r_pix.q.val().ring;
        for ne in self._ne..(self._ne + 1) {
            for e in 0..self._ne {
                self.hit_a2.d[e].next = self.matcher.ent_ok[e].val();
                self.hit_b.d[e].next = self.hit_a2.q[e].val();
                self.flags_b.hit[e].next = self.hit_b.q[e].val();
                self.hit_c.d[e].next = self.hit_b.q[e].val();
                self.hit_c.d[ne + e].next = self.flags_b.flag[e].val();
                self.pick_c.flag[e].next = self.hit_c.q[ne + e].val();
                self.hit_d.d[e].next = self.hit_c.q[e].val();
                self.flags_d.hit[e].next = self.hit_d.q[e].val();
                self.flags_r.hit[e].next = self.hit_r.q[e].val();
                self.pick_r.flag[e].next = self.hit_r.q[ne + e].val();
                self.hit_r0.d[e].next = self.hit_d.q[e].val();
                self.hit_r0.d[ne + e].next = self.flags_d.flag[e].val();
                self.hit_r.d[e].next = self.hit_r.q[e].val();
                self.hit_r.d[ne + e].next = self.flags_r.flag[e].val();
                if self.adv.val() {
                    self.hit_r.d[e].next = self.hit_r0.q[e].val();
                    self.hit_r.d[ne + e].next = self.hit_r0.q[ne + e].val();
                }
            }
            self.hit_c.d[ne + ne].next = self.flags_b.ring_flag.val();
            self.pick_c.ring_flag.next = self.hit_c.q[ne + ne].val();
            self.pick_r.ring_flag.next = self.hit_r.q[ne + ne].val();
            self.hit_r0.d[ne + ne].next = self.flags_d.ring_flag.val();
            self.hit_r.d[ne + ne].next = self.flags_r.ring_flag.val();
            if self.adv.val() {
                self.hit_r.d[ne + ne].next = self.hit_r0.q[ne + ne].val();
            }
        }
        // R: joins left hold the pipeline. R asks for one from its flags (none
        // left: it lets go), then loads its flags again with that merge
        // applied (check), and so on. R0's flags, registered, say whether a
        // pixel has joins left as it enters R.
        for ne in self._ne..(self._ne + 1) {
            self.any_r0.next = self.hit_r0.q[ne + ne].val();
            for e in 0..self._ne {
                if self.hit_r0.q[ne + e].val() {
                    self.any_r0.next = true;
                }
            }
        }
        self.r_left.d.next = self.r_left.q.val();
        self.r_check.d.next = false;
        if self.adv.val() {
            self.r_left.d.next = self.r0_pix.q.val().valid & self.any_r0.val();
        } else if !self.r_check.q.val() {
            self.r_left.d.next = self.pick_r.m_valid.val();
            self.r_check.d.next = self.pick_r.m_valid.val();
        }
        self.r_flags_hold.d.next = self.r_left.d.val() & !self.r_check.d.val();
        self.r_ask.next = self.r_left.q.val() & !self.r_check.q.val() & self.pick_r.m_valid.val();
        self.c_ask.next = self.adv.val() & self.c_pix.q.val().valid & self.pick_c.m_valid.val();
        self.m_q.d.next = self.r_ask.val() | self.c_ask.val();
        self.from_q.d.next = self.pick_c.m_from.val();
        self.into_q.d.next = self.pick_c.m_into.val();
        if self.r_left.q.val() {
            self.from_q.d.next = self.pick_r.m_from.val();
            self.into_q.d.next = self.pick_r.m_into.val();
        }
        // The merge out, without those of a slot into itself.
        self.mo_q.d.next = self.m_q.q.val() & (self.from_q.q.val() != self.into_q.q.val());
        self.mo_from.d.next = self.from_q.q.val();
        self.mo_into.d.next = self.into_q.q.val();
        self.m_valid.next = self.mo_q.q.val();
        self.m_from.next = self.mo_from.q.val();
        self.m_into.next = self.mo_into.q.val();
        // The pixel event: R's pixel once it has no joins left, its slots as
        // they are in this cycle's broadcast; one cycle more to stay behind
        // the merge out.
        self.e1_pix.d.next = self.pix_zero.val();
        if self.adv.val() {
            self.e1_pix.d.next = self.r_pix.q.val();
        }
        for own in self._own..(self._own + 1) {
            self.e1_own.d.next = self.bank_r.eff[own].val();
        }
        for dr in self._drop..(self._drop + 1) {
            self.e1_drop.d.next = self.bank_r.eff[dr].val();
        }
        for ad in self._add..(self._add + 1) {
            self.e1_add.d.next = self.bank_r.eff[ad].val();
        }
        self.e2_pix.d.next = self.e1_pix.q.val();
        self.e2_own.d.next = self.e1_own.q.val();
        self.e2_drop.d.next = self.e1_drop.q.val();
        self.e2_add.d.next = self.e1_add.q.val();
        self.out.next = self.e2_pix.q.val();
        self.out_own.next = self.e2_own.q.val();
        self.out_drop_ok.next = self.e2_pix.q.val().hold_drop != self.zero16.val();
        self.out_drop.next = self.e2_drop.q.val();
        self.out_add_ok.next = self.e2_pix.q.val().hold_add != self.zero16.val();
        self.out_add.next = self.e2_add.q.val();
        if self.a1_pix.q.val().valid & self.matcher.miss.val() {
            self.miss_q.d.next = true;
        }
        self.miss.next = self.miss_q.q.val();
        if self.rst.val() {
            self.in_pix.d.next = self.pix_zero.val();
            self.p0_pix.d.next = self.pix_zero.val();
            self.a1_pix.d.next = self.pix_zero.val();
            self.a2_pix.d.next = self.pix_zero.val();
            self.b_pix.d.next = self.pix_zero.val();
            self.c_pix.d.next = self.pix_zero.val();
            self.d_pix.d.next = self.pix_zero.val();
            self.r0_pix.d.next = self.pix_zero.val();
            self.r_pix.d.next = self.pix_zero.val();
            self.r_left.d.next = false;
            self.r_check.d.next = false;
            self.r_flags_hold.d.next = false;
            self.m_q.d.next = false;
            self.mo_q.d.next = false;
            self.e1_pix.d.next = self.pix_zero.val();
            self.e2_pix.d.next = self.pix_zero.val();
            self.miss_q.d.next = false;
        }
    }
}
