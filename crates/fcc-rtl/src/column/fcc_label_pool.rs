//! `FccLabelPool`: the column core's free provisional labels (spec §9.1), one
//! handed out per cycle at most, any number returned one per cycle.
//!
//! Labels are `1 ..= 2^B - 1`. After a reset or `clear` (a frame start) all
//! are free. A label never handed out since comes from a counter (`fresh`);
//! a returned one goes into a FIFO in block RAM (`2^B` words) and comes back
//! out in the order returned. Which free label is handed out does not
//! matter to the result (records are numbered by closing order); that one
//! is free whenever the golden stream has one free does, which is what this
//! block keeps:
//!
//! * The labels ready to hand out wait in a queue of four flip-flop entries,
//!   the head in entry 0 (`free_label`, `free_ok`), so the decision that
//!   pops it (`take`, combinational in `FccRowRuns`) reads flip-flops.
//!   `take` while the queue is empty is ignored.
//! * The queue is refilled every cycle it has room: from the FIFO (a read,
//!   two cycles' latency, its room reserved when issued) and, in a cycle no
//!   read arrives, from the counter. So the queue sustains one label a
//!   cycle while labels are free, and is empty only while every free label
//!   became free within the last [`POOL_LATENCY`] cycles (its bench checks
//!   this): a label returned at cycle `t` can be taken from `t + 4`, a
//!   fresh label two cycles after the reset or `clear`.
//! * Every decision reads flags kept beside the counters (`queue_any`,
//!   `in_fifo_any`, `fresh_any`, `reserved`), not the counters' carry chains.
//! * `free_count` is the labels free (in the queue, the reads under way, the
//!   FIFO and the counter's), registered: it counts the returns and takes
//!   of the cycles before. The core's column-start check compares it with
//!   the rows a column can start runs in (docs/column-core.md).
//!
//! The same block, 9 bits wide, hands out the record slots (`with_bits`).
//!
//! The slot table returns a closing cluster's labels (`ret`, `ret_label`)
//! one per cycle; a label is returned once, after it was handed out.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::types::{kb, vec_of};

/// Entries of the queue of labels ready to hand out.
const QUEUE: usize = 4;

/// A label returned at cycle `t` (or fresh after a reset or `clear` at
/// `t - 2`) can be taken from cycle `t + POOL_LATENCY`.
pub const POOL_LATENCY: usize = 4;

#[derive(LogicBlock)]
pub struct FccLabelPool {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A frame starts: every label is free again.
    pub clear: Signal<In, Bit>,
    // The queue's head: a free label (never 0), and `take` pops it.
    pub free_ok: Signal<Out, Bit>,
    pub free_label: Signal<Out, Bits<16>>,
    pub take: Signal<In, Bit>,
    // A label returned.
    pub ret: Signal<In, Bit>,
    pub ret_label: Signal<In, Bits<16>>,
    /// Labels free, one cycle late.
    pub free_count: Signal<Out, Bits<16>>,
    fifo: FccRam<Bits<16>, 16>,
    queue: Vec<DFF<Bits<16>>>,
    queued: DFF<Bits<3>>,
    queue_any: FccFanoutReg<Bit>,
    /// Reads of the FIFO issued one and two cycles ago (the latter's word
    /// shows now).
    read_s1: DFF<Bit>,
    read_s2: DFF<Bit>,
    write_at: DFF<Bits<16>>,
    read_at: DFF<Bits<16>>,
    /// Labels in the FIFO not yet read; `in_fifo_any`: it is not 0.
    in_fifo: DFF<Bits<16>>,
    in_fifo_any: DFF<Bit>,
    /// The next label never handed out since the clear; `fresh_any`: it is
    /// at most `2^B - 1`.
    fresh: DFF<Bits<16>>,
    fresh_any: DFF<Bit>,
    free: DFF<Bits<16>>,
    /// The queue's entries and the reads that will fill them (at most 4).
    reserved: DFF<Bits<3>>,
    pop: Signal<Local, Bit>,
    issue: Signal<Local, Bit>,
    /// `reserved` with this cycle's read.
    filled: Signal<Local, Bits<3>>,
    fresh_push: Signal<Local, Bit>,
    push: Signal<Local, Bit>,
    push_label: Signal<Local, Bits<16>>,
    /// Where a pushed label goes: the entry after the last, after the pop.
    push_at: Signal<Local, Bits<3>>,
    entry_is: Vec<Constant<Bits<3>>>,
    queue_size: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    one16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    /// `2^B - 1`: the largest label, the FIFO's address mask.
    max_label: Constant<Bits<16>>,
}

impl FccLabelPool {
    /// The pool of the build's provisional labels (`FccParams::label_bits`).
    pub fn new(p: &FccParams) -> Self {
        Self::with_bits(super::label_bits(p))
    }

    /// A pool of `b`-bit labels, `1 ..= 2^b - 1`: with `b` =
    /// [`SLOT_BITS`](super::fcc_label_sets::SLOT_BITS), the free record
    /// slots (slot 0 is never handed out).
    pub fn with_bits(b: usize) -> Self {
        assert!((1..=16).contains(&b), "labels of 1 to 16 bits");
        let max = (1u64 << b) - 1;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            take: Default::default(),
            ret: Default::default(),
            ret_label: Default::default(),
            free_count: Default::default(),
            fifo: FccRam::with_stored_bits(1 << b, b),
            queue: vec_of(QUEUE),
            queued: Default::default(),
            queue_any: Default::default(),
            read_s1: Default::default(),
            read_s2: Default::default(),
            write_at: Default::default(),
            read_at: Default::default(),
            in_fifo: Default::default(),
            in_fifo_any: Default::default(),
            fresh: Default::default(),
            fresh_any: Default::default(),
            free: Default::default(),
            reserved: Default::default(),
            pop: Default::default(),
            issue: Default::default(),
            filled: Default::default(),
            fresh_push: Default::default(),
            push: Default::default(),
            push_label: Default::default(),
            push_at: Default::default(),
            entry_is: (0..QUEUE).map(|n| kb(n as u64)).collect(),
            queue_size: kb(QUEUE as u64),
            one3: kb(1),
            one16: kb(1),
            zero16: kb(0),
            max_label: kb(max),
        }
    }

    /// Its FIFO in LUT RAM ([`FccRam::in_lut_ram`]): for a small pool
    /// (the 511 record slots), whose FIFO would take a block RAM alone.
    pub fn in_lut_ram(mut self) -> Self {
        self.fifo = self.fifo.in_lut_ram();
        self
    }
}

impl Logic for FccLabelPool {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            queued,
            queue_any,
            read_s1,
            read_s2,
            write_at,
            read_at,
            in_fifo,
            in_fifo_any,
            fresh,
            fresh_any,
            free,
            reserved
        );
        for i in 0..4 {
            self.queue[i].clock.next = self.clk.val();
            self.queue[i].d.next = self.queue[i].q.val();
        }
        self.free_ok.next = self.queue_any.q.val();
        self.free_label.next = self.queue[0].q.val();
        self.free_count.next = self.free.q.val();
        self.pop.next = self.take.val() & self.queue_any.q.val();
        // Room counts the entries taken and the reads on their way before
        // this cycle's pop (so a full queue refills a cycle after the pop):
        // a read when there is room, then a fresh label in the room left,
        // in a cycle no read's word arrives. Every decision reads flags.
        self.issue.next =
            self.in_fifo_any.q.val() & (self.reserved.q.val() != self.queue_size.val());
        self.filled.next = self.reserved.q.val();
        if self.issue.val() {
            self.filled.next = self.reserved.q.val() + self.one3.val();
        }
        self.fresh_push.next = self.fresh_any.q.val()
            & !self.read_s2.q.val()
            & (self.filled.val() != self.queue_size.val());
        self.push.next = self.read_s2.q.val() | self.fresh_push.val();
        self.push_label.next = self.fifo.read_data.val();
        if self.fresh_push.val() {
            self.push_label.next = self.fresh.q.val();
        }
        // Reserved: + a read issued, + a fresh label, - a pop.
        self.reserved.d.next = self.filled.val();
        if self.fresh_push.val() {
            self.reserved.d.next = self.filled.val() + self.one3.val();
        }
        if self.pop.val() {
            self.reserved.d.next = self.filled.val() - self.one3.val();
            if self.fresh_push.val() {
                self.reserved.d.next = self.filled.val();
            }
        }
        // The FIFO: returns written at `write_at`, reads issued at `read_at`.
        self.fifo.clk.next = self.clk.val();
        self.fifo.write_en.next = self.ret.val();
        self.fifo.write_addr.next = self.write_at.q.val();
        self.fifo.write_data.next = self.ret_label.val();
        self.fifo.read_en.next = self.issue.val();
        self.fifo.read_addr.next = self.read_at.q.val();
        if self.ret.val() {
            self.write_at.d.next =
                (self.write_at.q.val() + self.one16.val()) & self.max_label.val();
        }
        if self.issue.val() {
            self.read_at.d.next = (self.read_at.q.val() + self.one16.val()) & self.max_label.val();
        }
        if self.ret.val() & !self.issue.val() {
            self.in_fifo.d.next = self.in_fifo.q.val() + self.one16.val();
            self.in_fifo_any.d.next = true;
        }
        if !self.ret.val() & self.issue.val() {
            self.in_fifo.d.next = self.in_fifo.q.val() - self.one16.val();
            self.in_fifo_any.d.next = self.in_fifo.q.val() != self.one16.val();
        }
        self.read_s1.d.next = self.issue.val();
        self.read_s2.d.next = self.read_s1.q.val();
        if self.fresh_push.val() {
            self.fresh.d.next = self.fresh.q.val() + self.one16.val();
            self.fresh_any.d.next = self.fresh.q.val() != self.max_label.val();
        }
        if self.ret.val() & !self.pop.val() {
            self.free.d.next = self.free.q.val() + self.one16.val();
        }
        if !self.ret.val() & self.pop.val() {
            self.free.d.next = self.free.q.val() - self.one16.val();
        }
        // The queue: a pop moves every entry up one; a push fills the entry
        // after the last one left.
        self.push_at.next = self.queued.q.val();
        if self.pop.val() {
            self.push_at.next = self.queued.q.val() - self.one3.val();
            for i in 0..3 {
                self.queue[i].d.next = self.queue[i + 1].q.val();
            }
        }
        if self.push.val() {
            for i in 0..4 {
                if self.push_at.val() == self.entry_is[i].val() {
                    self.queue[i].d.next = self.push_label.val();
                }
            }
        }
        if self.push.val() & !self.pop.val() {
            self.queued.d.next = self.queued.q.val() + self.one3.val();
            self.queue_any.d.next = true;
        }
        if !self.push.val() & self.pop.val() {
            self.queued.d.next = self.queued.q.val() - self.one3.val();
            self.queue_any.d.next = self.queued.q.val() != self.one3.val();
        }
        if self.rst.val() | self.clear.val() {
            self.queued.d.next = self.entry_is[0].val();
            self.queue_any.d.next = false;
            self.read_s1.d.next = false;
            self.read_s2.d.next = false;
            self.write_at.d.next = self.zero16.val();
            self.read_at.d.next = self.zero16.val();
            self.in_fifo.d.next = self.zero16.val();
            self.in_fifo_any.d.next = false;
            self.fresh.d.next = self.one16.val();
            self.fresh_any.d.next = true;
            self.free.d.next = self.max_label.val();
            self.reserved.d.next = self.entry_is[0].val();
        }
    }
}
