//! `FccSetQueue`: the union-find's queue (docs/column-core.md, item 3).
//! The slot table's ops come in pixel order, one a cycle at most (`in_*`,
//! while `room`): a run's start (*make*: its label, its row and ring flag),
//! a run's flush (*find*: a label of its cluster), a join of two labels'
//! clusters, and a column marker (every op of the column is in). They wait
//! in a FIFO in block RAM (`2^SET_QUEUE_BITS` ops; `room` is low with fewer
//! than [`SET_QUEUE_ROOM`] free), go through `FccLabelSets` (a make with a
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
use super::fcc_set_took::FccSetTook;
use crate::fcc_stream_fifo::FccStreamFifo;
use crate::types::kb;

/// The queue holds `2^SET_QUEUE_BITS` ops.
pub const SET_QUEUE_BITS: usize = 9;

/// `room` is low with fewer than this many places free: the ops of the
/// pixels in flight in front of the queue.
pub const SET_QUEUE_ROOM: usize = 64;

/// An op in the queue. A make: `a` its label, `col` and `row` its first
/// pixel, `ring` its ring flag; a find: `a`; a join: `a` and `b`; a
/// marker: `col`. Each at the column of the pixel slot that caused it.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetQOp {
    pub make: Bit,
    pub join: Bit,
    pub mark: Bit,
    pub ring: Bit,
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
    pub in_make: Signal<In, Bit>,
    pub in_join: Signal<In, Bit>,
    pub in_mark: Signal<In, Bit>,
    pub in_ring: Signal<In, Bit>,
    pub in_a: Signal<In, Bits<16>>,
    pub in_b: Signal<In, Bits<16>>,
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
    op: Signal<Local, SetQOp>,
    queue: FccStreamFifo<SetQOp, SET_QUEUE_BITS, { SET_QUEUE_BITS + 1 }>,
    sets: FccLabelSets,
    gate: FccSetGate,
    taken: FccSetTook,
    order: FccSetOrder,
    room_q: DFF<Bit>,
    /// An op was pushed a cycle ago (not yet in the FIFO's level).
    pushed: DFF<Bit>,
    /// The level at which `room` goes low.
    high: Constant<Bits<{ SET_QUEUE_BITS + 1 }>>,
    zero: Constant<Bits<{ SET_QUEUE_BITS + 1 }>>,
}

impl FccSetQueue {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            in_valid: Default::default(),
            in_make: Default::default(),
            in_join: Default::default(),
            in_mark: Default::default(),
            in_ring: Default::default(),
            in_a: Default::default(),
            in_b: Default::default(),
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
            op: Default::default(),
            queue: Default::default(),
            sets: FccLabelSets::new(p),
            gate: Default::default(),
            taken: Default::default(),
            order: Default::default(),
            room_q: Default::default(),
            pushed: Default::default(),
            high: kb(((1 << SET_QUEUE_BITS) - SET_QUEUE_ROOM) as u64),
            zero: kb(0),
        }
    }
}

impl Logic for FccSetQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, room_q, pushed);
        self.queue.clk.next = self.clk.val();
        self.sets.clk.next = self.clk.val();
        self.order.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.sets.rst.next = self.rst.val();
        self.order.rst.next = self.rst.val();
        self.op.next.make = self.in_make.val();
        self.op.next.join = self.in_join.val();
        self.op.next.mark = self.in_mark.val();
        self.op.next.ring = self.in_ring.val();
        self.op.next.a = self.in_a.val();
        self.op.next.b = self.in_b.val();
        self.op.next.col = self.in_col.val();
        self.op.next.row = self.in_row.val();
        self.queue.push.next = self.in_valid.val();
        self.queue.din.next = self.op.val();
        self.room_q.d.next = self.queue.level.val() < self.high.val();
        self.room.next = self.room_q.q.val();
        // The head through the gate into the union-find and the order.
        self.taken.clk.next = self.clk.val();
        self.taken.rst.next = self.rst.val();
        self.gate.h_valid.next = self.queue.valid.val();
        self.gate.h_op.next = self.queue.dout.val();
        self.queue.take.next = self.taken.h_take.val();
        self.gate.space.next = self.order.space.val();
        self.gate.slot_ok.next = self.slot_ok.val();
        self.gate.slot.next = self.slot.val();
        self.slot_take.next = self.gate.slot_take.val();
        self.sets.mk_valid.next = self.gate.slot_take.val();
        self.sets.mk_label.next = self.queue.dout.val().a;
        self.sets.mk_slot.next = self.slot.val();
        self.sets.op_valid.next = self.gate.op_valid.val();
        self.sets.op_join.next = self.queue.dout.val().join;
        self.sets.op_a.next = self.queue.dout.val().a;
        self.sets.op_b.next = self.queue.dout.val().b;
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
