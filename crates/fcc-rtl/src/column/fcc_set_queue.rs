//! `FccSetQueue`: the union-find's queue (docs/column-core.md, item 3).
//! The slot table's ops come in pixel order, a pixel slot's at once, one
//! slot a cycle at most (`in_*`, while `room`): its run's flush (*find*: a
//! label of its cluster), its run's start (*make*: its label, its row and
//! ring flag), a join of two labels' clusters (`in_under`: the first a run
//! just started, filed under the second's cluster), and the column's marker
//! (every op of the column is in), any of them, in that order (a slot's
//! second join comes as a slot of its own). They wait in a FIFO in block
//! RAM (`2^SET_QUEUE_BITS` slots' ops; `room` is low with fewer than
//! [`SET_QUEUE_ROOM`] free), go out of it one op a cycle at most
//! (`FccSetPick`: the part of the head's entry that goes next), through
//! `FccLabelSets` (a make with a
//! free slot, `slot_*`, from the slot pool) and come out in the same order
//! with what they became (`ev_*`): a make's label and slot; a find's root
//! and slot; a join's slot kept and slot gone, `merged` when they were two
//! clusters; a marker as it came. So a column's marker follows every op
//! of the column, and the record store sees each op's slots as the
//! union-find had them when it took the op. The FIFO gives an op a cycle
//! (`FccStreamFifo`), so that the union-find can take one a cycle after
//! the one before and makes and markers go one a cycle. The head's issue
//! is `FccSetGate`'s (what it became, registered, `FccSetTook`'s), the
//! order `FccSetOrder`'s; this block is wiring.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_label_sets::{FccLabelSets, SLOT_BITS};
use super::fcc_set_gate::FccSetGate;
use super::fcc_set_order::FccSetOrder;
use super::fcc_set_pick::FccSetPick;
use super::fcc_set_took::FccSetTook;
use crate::fcc_stream_fifo::FccStreamFifo;
use crate::types::kb;

/// The queue holds `2^SET_QUEUE_BITS` ops.
pub const SET_QUEUE_BITS: usize = 9;

/// `room` is low with fewer than this many places free: the ops of the
/// pixels in flight in front of the queue.
pub const SET_QUEUE_ROOM: usize = 64;

/// A pixel slot's ops, an entry of the queue: a find of `f`; a make of
/// `m` (its first pixel `col` and `row`, its ring flag `ring`); a join of
/// `ja` and `jb` (`under`: `ja` a run just started, filed under `jb`'s
/// cluster; `seam`: the ring check's); the marker of column `col`. Each at
/// the column of the pixel slot that caused it. The frame end's entries
/// (`FccColEnd`) use `ring` for more: a find's, its run held by hold 4;
/// the frame end's marker's, the frame's overflow (and `row` bit 0, its
/// input error).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetQBundle {
    pub find: Bit,
    pub make: Bit,
    pub join: Bit,
    pub mark: Bit,
    pub ring: Bit,
    pub under: Bit,
    pub seam: Bit,
    pub f: Bits<16>,
    pub m: Bits<16>,
    pub ja: Bits<16>,
    pub jb: Bits<16>,
    pub col: Bits<12>,
    pub row: Bits<7>,
}

/// One op of an entry. A make: `a` its label, `col` and `row` its first
/// pixel, `ring` its ring flag; a find: `a`; a join: `a` and `b`, `under`
/// as the entry's; a marker: `col`.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetQOp {
    pub make: Bit,
    pub join: Bit,
    pub mark: Bit,
    pub ring: Bit,
    pub under: Bit,
    pub a: Bits<16>,
    pub b: Bits<16>,
    pub col: Bits<12>,
    pub row: Bits<7>,
}

/// An op out, with what it became: `label` a make's label or the root
/// found (kept), `slot` its slot, `other` a join's slot gone.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetQEv {
    pub make: Bit,
    pub join: Bit,
    pub mark: Bit,
    pub ring: Bit,
    pub merged: Bit,
    pub label: Bits<16>,
    pub slot: Bits<SLOT_BITS>,
    pub other: Bits<SLOT_BITS>,
    pub col: Bits<12>,
    pub row: Bits<7>,
}

#[derive(LogicBlock)]
pub struct FccSetQueue {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub in_valid: Signal<In, Bit>,
    pub in_find: Signal<In, Bit>,
    pub in_make: Signal<In, Bit>,
    pub in_join: Signal<In, Bit>,
    pub in_mark: Signal<In, Bit>,
    pub in_ring: Signal<In, Bit>,
    pub in_under: Signal<In, Bit>,
    pub in_seam: Signal<In, Bit>,
    pub in_f: Signal<In, Bits<16>>,
    pub in_m: Signal<In, Bits<16>>,
    pub in_ja: Signal<In, Bits<16>>,
    pub in_jb: Signal<In, Bits<16>>,
    pub in_col: Signal<In, Bits<12>>,
    pub in_row: Signal<In, Bits<7>>,
    pub room: Signal<Out, Bit>,
    pub slot_ok: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    pub slot_take: Signal<Out, Bit>,
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
    /// Nothing pushed, queued, in the union-find or waiting to go out.
    pub idle: Signal<Out, Bit>,
    slot_in: Signal<Local, SetQBundle>,
    queue: FccStreamFifo<SetQBundle, SET_QUEUE_BITS, { SET_QUEUE_BITS + 1 }>,
    sets: FccLabelSets,
    pick: FccSetPick,
    /// The part of the head's entry that goes next (`FccSetPick`).
    part: DFF<Bits<2>>,
    gate: FccSetGate,
    taken: FccSetTook,
    order: FccSetOrder,
    room_q: DFF<Bit>,
    /// An op was pushed a cycle ago (not yet in the FIFO's level).
    pushed: DFF<Bit>,
    /// The level at which `room` goes low.
    high: Constant<Bits<{ SET_QUEUE_BITS + 1 }>>,
    zero: Constant<Bits<{ SET_QUEUE_BITS + 1 }>>,
    zero2: Constant<Bits<2>>,
}

impl FccSetQueue {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            in_valid: Default::default(),
            in_find: Default::default(),
            in_make: Default::default(),
            in_join: Default::default(),
            in_mark: Default::default(),
            in_ring: Default::default(),
            in_under: Default::default(),
            in_seam: Default::default(),
            in_f: Default::default(),
            in_m: Default::default(),
            in_ja: Default::default(),
            in_jb: Default::default(),
            in_col: Default::default(),
            in_row: Default::default(),
            room: Default::default(),
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
            idle: Default::default(),
            slot_in: Default::default(),
            queue: Default::default(),
            sets: FccLabelSets::new(p),
            pick: Default::default(),
            part: Default::default(),
            gate: Default::default(),
            taken: Default::default(),
            order: Default::default(),
            room_q: Default::default(),
            pushed: Default::default(),
            high: kb(((1 << SET_QUEUE_BITS) - SET_QUEUE_ROOM) as u64),
            zero: kb(0),
            zero2: kb(0),
        }
    }
}

impl Logic for FccSetQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, room_q, pushed, part);
        self.queue.clk.next = self.clk.val();
        self.sets.clk.next = self.clk.val();
        self.order.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.sets.rst.next = self.rst.val();
        self.order.rst.next = self.rst.val();
        self.slot_in.next.find = self.in_find.val();
        self.slot_in.next.make = self.in_make.val();
        self.slot_in.next.join = self.in_join.val();
        self.slot_in.next.mark = self.in_mark.val();
        self.slot_in.next.ring = self.in_ring.val();
        self.slot_in.next.under = self.in_under.val();
        self.slot_in.next.seam = self.in_seam.val();
        self.slot_in.next.f = self.in_f.val();
        self.slot_in.next.m = self.in_m.val();
        self.slot_in.next.ja = self.in_ja.val();
        self.slot_in.next.jb = self.in_jb.val();
        self.slot_in.next.col = self.in_col.val();
        self.slot_in.next.row = self.in_row.val();
        self.queue.push.next = self.in_valid.val();
        self.queue.din.next = self.slot_in.val();
        self.room_q.d.next = self.queue.level.val() < self.high.val();
        self.room.next = self.room_q.q.val();
        // The head's next op through the gate into the union-find and the
        // order; the entry leaves with its last op.
        self.taken.clk.next = self.clk.val();
        self.taken.rst.next = self.rst.val();
        self.pick.bundle.next = self.queue.dout.val();
        self.pick.part.next = self.part.q.val();
        self.gate.h_valid.next = self.queue.valid.val();
        self.gate.h_op.next = self.pick.op.val();
        self.queue.take.next = self.taken.h_take.val();
        self.taken.last.next = self.pick.last.val();
        self.taken.after.next = self.pick.after.val();
        self.taken.part.next = self.part.q.val();
        self.part.d.next = self.taken.part_d.val();
        if self.rst.val() {
            self.part.d.next = self.zero2.val();
        }
        self.gate.space.next = self.order.space.val();
        self.gate.slot_ok.next = self.slot_ok.val();
        self.gate.slot.next = self.slot.val();
        self.gate.mk_ready.next = self.sets.mk_ready.val();
        self.slot_take.next = self.gate.slot_take.val();
        self.sets.mk_valid.next = self.gate.slot_take.val();
        self.sets.mk_label.next = self.pick.op.val().a;
        self.sets.mk_slot.next = self.slot.val();
        self.sets.op_valid.next = self.gate.op_valid.val();
        self.sets.op_join.next = self.pick.op.val().join;
        self.sets.op_under.next = self.pick.op.val().under;
        self.sets.op_a.next = self.pick.op.val().a;
        self.sets.op_b.next = self.pick.op.val().b;
        self.taken.direct.next = self.gate.direct.val();
        self.taken.op_take.next = self.sets.op_take.val();
        self.taken.tag.next = self.gate.tag.val();
        self.taken.made.next = self.gate.made.val();
        self.order.took.next = self.taken.took.val();
        self.order.took_op.next = self.taken.took_op.val();
        self.order.took_direct.next = self.taken.took_direct.val();
        self.order.took_tag.next = self.taken.took_tag.val();
        self.order.took_made.next = self.taken.took_made.val();
        self.order.s_valid.next = self.sets.ev_valid.val();
        self.order.s_merged.next = self.sets.ev_merged.val();
        self.order.s_keep.next = self.sets.ev_keep.val();
        self.order.s_keep_slot.next = self.sets.ev_keep_slot.val();
        self.order.s_gone_slot.next = self.sets.ev_gone_slot.val();
        // Out.
        self.ev_valid.next = self.order.ev_valid.val();
        self.ev_make.next = self.order.ev.val().make;
        self.ev_join.next = self.order.ev.val().join;
        self.ev_mark.next = self.order.ev.val().mark;
        self.ev_ring.next = self.order.ev.val().ring;
        self.ev_merged.next = self.order.ev.val().merged;
        self.ev_label.next = self.order.ev.val().label;
        self.ev_slot.next = self.order.ev.val().slot;
        self.ev_other.next = self.order.ev.val().other;
        self.ev_col.next = self.order.ev.val().col;
        self.ev_row.next = self.order.ev.val().row;
        self.order.ev_take.next = self.ev_take.val();
        // The FIFO's level counts an op from two cycles after its push.
        self.pushed.d.next = self.in_valid.val();
        self.idle.next = !self.in_valid.val()
            & !self.pushed.q.val()
            & (self.queue.level.val() == self.zero.val())
            & !self.taken.took.val()
            & !self.order.busy.val()
            & self.sets.idle.val();
    }
}
