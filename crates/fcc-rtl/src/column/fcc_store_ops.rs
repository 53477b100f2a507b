//! `FccStoreOps`: the record store's op arbiter (docs/column-core.md, item
//! 8, "The record store half"). One op a cycle at most goes to
//! `FccSlotRecords` (`op_*`, taken by `op_take`), chosen in this order:
//!
//! 1. the closer's close (`close_*`), while no close is under way: the
//!    record out has room for its record (`out_idle`), the labels' lists
//!    for its list (`walk_room`), and the close taken before it has come
//!    out of the store and been loaded ([`CLOSE_GAP`] cycles); at the
//!    frame end (`ending`) it is an `End`;
//! 2. at the frame end, a peek of slot `peek_slot` (`peek_valid`, from
//!    `FccStoreEnd`);
//! 3. the union-find queue's event at its head (`ev_*`), while the
//!    closer has `room` for the reports it may cause:
//!    * a make: an `Add` of the run's start (one run open, its ring flag,
//!      its first pixel, its label as the list of one);
//!    * a find: an `Add` of its flush's accumulator (`acc_*`, taken with
//!      it; one run open less), to the root's slot;
//!    * a join that merged: a `Merge` of the gone slot into the kept one,
//!      the gone slot back to the slot pool (`gone_*`);
//!    * a ring check's join (`ev_ring` on a join): first an `Add` of the seam flag to
//!      the kept slot (nothing else: a cluster with a row's first run is
//!      held, so the add reports nothing), then, if merged, the merge.
//!
//! A join that did not merge and a column's marker need no op and are
//! taken at once (the marker then reaches the closer [`MARK_DELAY`]
//! cycles later, after every report of the ops before it). The frame
//! end's marker (`ev_col > last_col`) is `FccStoreEnd`'s: `ev_end` says it
//! is at the head, and it is taken with `end_take`. A close taken keeps
//! its column for its record (`rec_col`); records are numbered in the
//! frame from 1 (`rec_id`, counted as they are loaded, `out_load`, and
//! restarted by `id_clear`).

use rust_hdl::prelude::*;

use super::fcc_close_order::CLOSE_KEY_BITS;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_slot_issue::SlotOp;
use super::fcc_slot_records::SLOT_RECORDS_LATENCY;
use super::{AccWord, SlotHolds, SlotWord};
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::kb;

/// Cycles from a close's taking to the next close: its record out of the
/// store and loaded, so that `out_idle` is its.
pub const CLOSE_GAP: usize = SLOT_RECORDS_LATENCY + 2;

/// Cycles from a marker's taking to the closer: the reports of the ops
/// taken before it are out of the store by then (a merge's a cycle later
/// than an add's).
pub const MARK_DELAY: usize = SLOT_RECORDS_LATENCY + 1;

// The delay's loops are written for four stages (`#[hdl_gen]` takes
// literal bounds).
const _: () = assert!(MARK_DELAY == 4);

#[derive(LogicBlock)]
pub struct FccStoreOps {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub last_col: Signal<In, Bits<12>>,
    /// The union-find queue's head event (`FccColTable`'s `ev_*`).
    pub ev_valid: Signal<In, Bit>,
    pub ev_make: Signal<In, Bit>,
    pub ev_join: Signal<In, Bit>,
    pub ev_mark: Signal<In, Bit>,
    pub ev_ring: Signal<In, Bit>,
    pub ev_merged: Signal<In, Bit>,
    pub ev_label: Signal<In, Bits<16>>,
    pub ev_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ev_other: Signal<In, Bits<SLOT_BITS>>,
    pub ev_col: Signal<In, Bits<12>>,
    pub ev_row: Signal<In, Bits<7>>,
    pub ev_take: Signal<Out, Bit>,
    pub ev_end: Signal<Out, Bit>,
    pub end_take: Signal<In, Bit>,
    pub acc_valid: Signal<In, Bit>,
    pub acc: Signal<In, AccWord>,
    pub acc_take: Signal<Out, Bit>,
    /// The closer's head close.
    pub close_valid: Signal<In, Bit>,
    pub close_slot: Signal<In, Bits<SLOT_BITS>>,
    pub close_key: Signal<In, Bits<CLOSE_KEY_BITS>>,
    pub close_col: Signal<In, Bits<13>>,
    pub close_take: Signal<Out, Bit>,
    pub room: Signal<In, Bit>,
    pub walk_room: Signal<In, Bit>,
    pub out_idle: Signal<In, Bit>,
    /// The frame end (`FccStoreEnd`): closes are ends, peeks go, events wait.
    pub ending: Signal<In, Bit>,
    pub peek_valid: Signal<In, Bit>,
    pub peek_slot: Signal<In, Bits<SLOT_BITS>>,
    pub peek_take: Signal<Out, Bit>,
    /// The frame end's marker (column `end_col`), into the marker's delay.
    pub end_mark: Signal<In, Bit>,
    pub end_col: Signal<In, Bits<12>>,
    /// The op offered to the store.
    pub op_valid: Signal<Out, Bit>,
    pub op_kind: Signal<Out, SlotOp>,
    pub op_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub op_other: Signal<Out, Bits<SLOT_BITS>>,
    pub op_word: Signal<Out, SlotWord>,
    pub op_col: Signal<Out, Bits<12>>,
    pub op_take: Signal<In, Bit>,
    pub gone_valid: Signal<Out, Bit>,
    pub gone_slot: Signal<Out, Bits<SLOT_BITS>>,
    /// The marker to the closer.
    pub mark_valid: Signal<Out, Bit>,
    pub mark_col: Signal<Out, Bits<12>>,
    /// No marker in its delay, no close under way.
    pub calm: Signal<Out, Bit>,
    /// A record leaves the store: its id and column.
    pub out_load: Signal<In, Bit>,
    pub id_clear: Signal<In, Bit>,
    pub rec_id: Signal<Out, Bits<20>>,
    pub rec_col: Signal<Out, Bits<13>>,
    /// A marker taken (the frame end's too).
    pub marked: Signal<Out, Bit>,
    find: Signal<Local, Bit>,
    close_ok: Signal<Local, Bit>,
    peek_ok: Signal<Local, Bit>,
    ev_op: Signal<Local, Bit>,
    ev_skip: Signal<Local, Bit>,
    seam_op: Signal<Local, Bit>,
    ev_go: Signal<Local, Bit>,
    mark_in: Signal<Local, Bit>,
    /// The ring join's seam add is done; its merge is next.
    seamed: FccFanoutReg<Bit>,
    gap: DFF<Bits<3>>,
    mv: Vec<DFF<Bit>>,
    mc: Vec<DFF<Bits<12>>>,
    ids: DFF<Bits<20>>,
    col: DFF<Bits<13>>,
    w_acc: Signal<Local, AccWord>,
    w_holds: Signal<Local, SlotHolds>,
    empty_acc: Constant<AccWord>,
    empty_holds: Constant<SlotHolds>,
    gap_full: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    one20: Constant<Bits<20>>,
    zero3: Constant<Bits<3>>,
    zero20: Constant<Bits<20>>,
    open_one: Constant<Bits<8>>,
    open_less: Constant<Bits<8>>,
}

impl Default for FccStoreOps {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_col: Default::default(),
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
            ev_end: Default::default(),
            end_take: Default::default(),
            acc_valid: Default::default(),
            acc: Default::default(),
            acc_take: Default::default(),
            close_valid: Default::default(),
            close_slot: Default::default(),
            close_key: Default::default(),
            close_col: Default::default(),
            close_take: Default::default(),
            room: Default::default(),
            walk_room: Default::default(),
            out_idle: Default::default(),
            ending: Default::default(),
            peek_valid: Default::default(),
            peek_slot: Default::default(),
            peek_take: Default::default(),
            end_mark: Default::default(),
            end_col: Default::default(),
            op_valid: Default::default(),
            op_kind: Default::default(),
            op_slot: Default::default(),
            op_other: Default::default(),
            op_word: Default::default(),
            op_col: Default::default(),
            op_take: Default::default(),
            gone_valid: Default::default(),
            gone_slot: Default::default(),
            mark_valid: Default::default(),
            mark_col: Default::default(),
            calm: Default::default(),
            out_load: Default::default(),
            id_clear: Default::default(),
            rec_id: Default::default(),
            rec_col: Default::default(),
            marked: Default::default(),
            find: Default::default(),
            close_ok: Default::default(),
            peek_ok: Default::default(),
            ev_op: Default::default(),
            ev_skip: Default::default(),
            seam_op: Default::default(),
            ev_go: Default::default(),
            mark_in: Default::default(),
            seamed: Default::default(),
            gap: Default::default(),
            mv: (0..MARK_DELAY).map(|_| Default::default()).collect(),
            mc: (0..MARK_DELAY).map(|_| Default::default()).collect(),
            ids: Default::default(),
            col: Default::default(),
            w_acc: Default::default(),
            w_holds: Default::default(),
            empty_acc: Constant::new(AccWord::empty()),
            empty_holds: Constant::new(SlotHolds::empty()),
            gap_full: kb(CLOSE_GAP as u64),
            one3: kb(1),
            one20: kb(1),
            zero3: kb(0),
            zero20: kb(0),
            open_one: kb(1),
            open_less: kb(0xff),
        }
    }
}

impl Logic for FccStoreOps {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, seamed, gap, ids, col);
        for i in 0..4 {
            self.mv[i].clock.next = self.clk.val();
            self.mc[i].clock.next = self.clk.val();
        }
        // What the head event needs.
        self.find.next = !self.ev_make.val() & !self.ev_join.val() & !self.ev_mark.val();
        self.ev_end.next =
            self.ev_valid.val() & self.ev_mark.val() & (self.ev_col.val() > self.last_col.val());
        self.ev_op.next = self.ev_valid.val()
            & !self.ending.val()
            & self.room.val()
            & (self.ev_make.val()
                | (self.ev_join.val() & (self.ev_merged.val() | self.ev_ring.val()))
                | (self.find.val() & self.acc_valid.val()));
        self.ev_skip.next = self.ev_valid.val()
            & !self.ending.val()
            & !self.ev_end.val()
            & ((self.ev_join.val() & !self.ev_merged.val() & !self.ev_ring.val())
                | self.ev_mark.val());
        // A ring join's seam add comes before its merge.
        self.seam_op.next = self.ev_join.val() & self.ev_ring.val() & !self.seamed.q.val();
        // The op offered, in order: a close, a peek, the head event's.
        self.close_ok.next = self.close_valid.val()
            & !self.gap.q.val().any()
            & self.out_idle.val()
            & self.walk_room.val();
        self.peek_ok.next = !self.close_ok.val() & self.ending.val() & self.peek_valid.val();
        self.op_valid.next = self.close_ok.val() | self.peek_ok.val() | self.ev_op.val();
        self.op_kind.next = SlotOp::Add;
        self.op_slot.next = self.ev_slot.val();
        self.op_other.next = self.ev_other.val();
        self.op_col.next = self.ev_col.val();
        // The word: a run's start, a flush's accumulator, a seam, or (a
        // close's) the cluster's first pixel.
        self.w_acc.next = self.empty_acc.val();
        self.w_holds.next = self.empty_holds.val();
        if self.ev_make.val() {
            self.w_holds.next.open = self.open_one.val();
            self.w_holds.next.ring = self.ev_ring.val();
            self.w_holds.next.first =
                (bit_cast::<19, 12>(self.ev_col.val()) << 7) | bit_cast::<19, 7>(self.ev_row.val());
            self.w_holds.next.head = self.ev_label.val();
            self.w_holds.next.tail = self.ev_label.val();
        }
        if self.find.val() {
            self.w_acc.next = self.acc.val();
            self.w_holds.next.open = self.open_less.val();
            // The frame end's flush of a run held by hold 4.
            self.w_holds.next.ring = self.ev_ring.val();
        }
        if self.ev_join.val() {
            self.w_acc.next.seam = true;
            if !self.seam_op.val() {
                self.op_kind.next = SlotOp::Merge;
            }
        }
        if self.peek_ok.val() {
            self.op_kind.next = SlotOp::Peek;
            self.op_slot.next = self.peek_slot.val();
            self.w_acc.next = self.empty_acc.val();
            self.w_holds.next = self.empty_holds.val();
        }
        if self.close_ok.val() {
            self.op_kind.next = SlotOp::Close;
            if self.ending.val() {
                self.op_kind.next = SlotOp::End;
            }
            self.op_slot.next = self.close_slot.val();
            self.w_acc.next = self.empty_acc.val();
            self.w_holds.next = self.empty_holds.val();
            self.w_holds.next.first = self.close_key.val();
            self.op_col.next = self.close_col.val().get_bits::<12>(0);
        }
        self.op_word.next.acc = self.w_acc.val();
        self.op_word.next.holds = self.w_holds.val();
        // What is taken.
        self.close_take.next = self.close_ok.val() & self.op_take.val();
        self.peek_take.next = self.peek_ok.val() & self.op_take.val();
        self.ev_go.next = !self.close_ok.val() & self.ev_op.val() & self.op_take.val();
        self.seamed.d.next = self.seamed.q.val();
        if self.ev_go.val() & self.seam_op.val() {
            self.seamed.d.next = true;
        }
        // The event leaves with its last op (a ring join that merged: the
        // merge after the seam add).
        self.ev_take.next = self.end_take.val()
            | self.ev_skip.val()
            | (self.ev_go.val() & !(self.seam_op.val() & self.ev_merged.val()));
        if self.ev_go.val() & !(self.seam_op.val() & self.ev_merged.val()) {
            self.seamed.d.next = false;
        }
        self.acc_take.next = self.ev_go.val() & self.find.val();
        self.gone_valid.next =
            self.ev_go.val() & self.ev_join.val() & self.ev_merged.val() & !self.seam_op.val();
        self.gone_slot.next = self.ev_other.val();
        self.marked.next = (self.ev_skip.val() & self.ev_mark.val()) | self.end_take.val();
        // The marker's delay.
        self.mark_in.next = (self.ev_skip.val() & self.ev_mark.val()) | self.end_mark.val();
        self.mv[0].d.next = self.mark_in.val();
        self.mc[0].d.next = self.ev_col.val();
        if self.end_mark.val() {
            self.mc[0].d.next = self.end_col.val();
        }
        for i in 1..4 {
            self.mv[i].d.next = self.mv[i - 1].q.val();
            self.mc[i].d.next = self.mc[i - 1].q.val();
        }
        self.mark_valid.next = self.mv[3].q.val();
        self.mark_col.next = self.mc[3].q.val();
        // A close keeps the next closes off until its record is loaded.
        self.gap.d.next = self.gap.q.val();
        if self.gap.q.val().any() {
            self.gap.d.next = self.gap.q.val() - self.one3.val();
        }
        if self.close_take.val() {
            self.gap.d.next = self.gap_full.val();
            self.col.d.next = self.close_col.val();
        }
        self.calm.next = !self.gap.q.val().any();
        for i in 0..4 {
            if self.mv[i].q.val() {
                self.calm.next = false;
            }
        }
        self.rec_col.next = self.col.q.val();
        self.ids.d.next = self.ids.q.val();
        if self.out_load.val() {
            self.ids.d.next = self.ids.q.val() + self.one20.val();
        }
        if self.id_clear.val() {
            self.ids.d.next = self.zero20.val();
        }
        self.rec_id.next = self.ids.q.val() + self.one20.val();
        if self.rst.val() {
            self.seamed.d.next = false;
            self.gap.d.next = self.zero3.val();
            self.ids.d.next = self.zero20.val();
            for i in 0..4 {
                self.mv[i].d.next = false;
            }
        }
    }
}
