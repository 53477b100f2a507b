//! `FccLabelLists`: each cluster's labels as a list through the labels,
//! and their return once it closes (docs/column-core.md, items 2 and 3).
//! A cluster's list is its first label to its last (`head`, `tail`, kept
//! with its record); a run that starts a cluster makes a list of one, and
//! a union of two clusters links the kept list's tail to the gone list's
//! head (`link_*`: `next[from] = to`, one a cycle, from the record store's
//! merge). When a cluster closes its list is queued (`walk_*`, in a FIFO
//! of `2^WALK_BITS` lists; `walk_room` low with fewer than `WALK_ROOM`
//! free) and walked, head to tail, each label returned (`ret_*`, to
//! `FccLabelPool`) every other cycle: the next label is read from block
//! RAM (two cycles) as the one before is returned.
//!
//! A list's links are written before it is queued (its merges come before
//! its close); a label returned may be made and linked again, and its old
//! `next` is overwritten before it is read (a walk stops at its tail).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_fifo::FccFifo;
use crate::fcc_ram::FccRam;
use crate::types::kb;

/// Address bits of the queue of lists to walk.
pub const WALK_BITS: usize = 9;
/// Lists kept free in the queue for the closes already under way.
pub const WALK_ROOM: usize = 8;

/// A list's first and last labels, and whether they are one (worked out
/// as it is queued, so that a walk's start compares nothing).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct ListEnds {
    pub head: Bits<16>,
    pub tail: Bits<16>,
    pub single: Bit,
}

#[derive(LogicBlock)]
pub struct FccLabelLists {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub link_valid: Signal<In, Bit>,
    pub link_from: Signal<In, Bits<16>>,
    pub link_to: Signal<In, Bits<16>>,
    pub walk_valid: Signal<In, Bit>,
    pub walk_head: Signal<In, Bits<16>>,
    pub walk_tail: Signal<In, Bits<16>>,
    pub walk_room: Signal<Out, Bit>,
    pub ret_valid: Signal<Out, Bit>,
    pub ret_label: Signal<Out, Bits<16>>,
    /// No list queued or being walked.
    pub idle: Signal<Out, Bit>,
    next: FccRam<Bits<16>, 16>,
    queue: FccFifo<ListEnds, WALK_BITS, { WALK_BITS + 1 }>,
    ends: Signal<Local, ListEnds>,
    /// The queue's head list.
    qd: Signal<Local, ListEnds>,
    start: Signal<Local, Bit>,
    label: Signal<Local, Bits<16>>,
    /// The label returned is not its list's tail: its next is read.
    more: Signal<Local, Bit>,
    emit: Signal<Local, Bit>,
    /// The walk's tail; a read of `next` issued one and two cycles ago.
    tail: DFF<Bits<16>>,
    r1: DFF<Bit>,
    r2: DFF<Bit>,
    /// A list was queued last cycle (the queue's level shows it a cycle
    /// later).
    pushed: DFF<Bit>,
    room_max: Constant<Bits<{ WALK_BITS + 1 }>>,
}

impl FccLabelLists {
    pub fn new(p: &FccParams) -> Self {
        let b = super::label_bits(p);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            link_valid: Default::default(),
            link_from: Default::default(),
            link_to: Default::default(),
            walk_valid: Default::default(),
            walk_head: Default::default(),
            walk_tail: Default::default(),
            walk_room: Default::default(),
            ret_valid: Default::default(),
            ret_label: Default::default(),
            idle: Default::default(),
            next: FccRam::with_stored_bits(1 << b, b),
            queue: FccFifo::with_stored_bits(2 * 16 + 1),
            ends: Default::default(),
            qd: Default::default(),
            start: Default::default(),
            label: Default::default(),
            more: Default::default(),
            emit: Default::default(),
            tail: Default::default(),
            r1: Default::default(),
            r2: Default::default(),
            pushed: Default::default(),
            room_max: kb(((1 << WALK_BITS) - WALK_ROOM) as u64),
        }
    }
}

impl Logic for FccLabelLists {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, tail, r1, r2, pushed);
        self.next.clk.next = self.clk.val();
        self.queue.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.next.write_en.next = self.link_valid.val();
        self.next.write_addr.next = self.link_from.val();
        self.next.write_data.next = self.link_to.val();
        self.queue.push.next = self.walk_valid.val();
        self.ends.next.head = self.walk_head.val();
        self.ends.next.tail = self.walk_tail.val();
        self.ends.next.single = self.walk_head.val() == self.walk_tail.val();
        self.queue.din.next = self.ends.val();
        self.walk_room.next = self.queue.level.val() < self.room_max.val();
        // The label returned this cycle: the next one read, or a queued
        // list's head once no read is in flight.
        self.start.next =
            self.queue.valid.val() & !self.r1.q.val() & !self.r2.q.val() & !self.rst.val();
        self.queue.take.next = self.start.val();
        self.label.next = self.next.read_data.val();
        self.more.next = self.next.read_data.val() != self.tail.q.val();
        self.qd.next = self.queue.dout.val();
        if self.start.val() {
            self.label.next = self.qd.val().head;
            self.more.next = !self.qd.val().single;
            self.tail.d.next = self.qd.val().tail;
        }
        self.emit.next = self.r2.q.val() | self.start.val();
        self.ret_valid.next = self.emit.val();
        self.ret_label.next = self.label.val();
        // Not the tail: read its next.
        self.next.read_en.next = self.emit.val() & self.more.val();
        self.next.read_addr.next = self.label.val();
        self.r1.d.next = self.emit.val() & self.more.val();
        self.r2.d.next = self.r1.q.val();
        self.pushed.d.next = self.walk_valid.val();
        self.idle.next = !self.pushed.q.val()
            & !self.queue.level.val().any()
            & !self.r1.q.val()
            & !self.r2.q.val();
        if self.rst.val() {
            self.r1.d.next = false;
            self.r2.d.next = false;
        }
    }
}
