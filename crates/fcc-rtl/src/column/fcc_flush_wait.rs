//! `FccFlushWait`: the flushes' accumulators waiting for their find
//! (docs/column-core.md, item 3, "On a captured frame" and "Chained").
//!
//! A run's flush leaves `FccRunAcc` with its accumulator (501 bits) long
//! before the union-find's queue gives the find that names the run's
//! cluster's slot: the accumulator waits here, in flush order, which is the
//! order of the queue's finds (both follow the pixels; the frame end's
//! flushes go row by row in both). The head is taken (`take`) with its
//! find's event, and the record store adds it to that slot.
//!
//! [`FLUSH_WAIT`] places, a FIFO (`FccFifo`, in LUT RAM: a few words too
//! wide for block RAM to be worth it; the head in flip-flops; after a take
//! the next head shows two cycles later). Upstream holds what could flush
//! while `room` is low: `room` (read off the places held, a register) says
//! that the places held after the last cycle's push and take, and `margin`
//! flushes more, and the one decided in the cycle `room` is seen, fit.
//! `margin` is how many cycles after being let in a pixel (or a frame-end
//! step) can flush, one flush each, at most: so while upstream honours
//! `room` the places never overflow. If one does
//! anyway (a push with every place held and none taken), or a take finds
//! no head, `bad` says so until reset.

use rust_hdl::prelude::*;

use super::AccWord;
use crate::fcc_fifo::FccFifo;
use crate::types::kb;

/// Places for accumulators waiting (the measured plan's 128).
pub const FLUSH_WAIT: usize = 128;

#[derive(LogicBlock)]
pub struct FccFlushWait {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A run is over: its accumulator (`FccRunAcc`'s `f_valid`, `f_acc`).
    pub push: Signal<In, Bit>,
    pub din: Signal<In, AccWord>,
    /// The oldest accumulator waiting.
    pub valid: Signal<Out, Bit>,
    pub dout: Signal<Out, AccWord>,
    pub take: Signal<In, Bit>,
    /// Upstream may let in what can flush.
    pub room: Signal<Out, Bit>,
    /// No accumulator waits (from the places held, a register).
    pub idle: Signal<Out, Bit>,
    /// Sticky until reset: a push with every place held and none taken, or
    /// a take with no head.
    pub bad: Signal<Out, Bit>,
    queue: FccFifo<AccWord, 7, 8>,
    /// Places held (exact, unlike the FIFO's registered level).
    held: DFF<Bits<8>>,
    held_next: Signal<Local, Bits<8>>,
    bad_q: DFF<Bit>,
    /// The most places held after a cycle with `room` still high.
    limit: Constant<Bits<8>>,
    full: Constant<Bits<8>>,
    one: Constant<Bits<8>>,
    zero: Constant<Bits<8>>,
}

impl FccFlushWait {
    /// For an upstream whose flushes come at most `margin` cycles after
    /// it is let in (`FccRunAcc`: [`super::fcc_run_acc::RUN_ACC_LATENCY`]).
    pub fn new(margin: usize) -> Self {
        assert!(
            margin + 2 <= FLUSH_WAIT,
            "a margin of {margin} leaves no place"
        );
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            din: Default::default(),
            valid: Default::default(),
            dout: Default::default(),
            take: Default::default(),
            room: Default::default(),
            idle: Default::default(),
            bad: Default::default(),
            queue: FccFifo::default().in_lut_ram(),
            held: Default::default(),
            held_next: Default::default(),
            bad_q: Default::default(),
            limit: kb((FLUSH_WAIT - margin - 1) as u64),
            full: kb(FLUSH_WAIT as u64),
            one: kb(1),
            zero: kb(0),
        }
    }
}

impl Logic for FccFlushWait {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, held, bad_q);
        self.queue.clk.next = self.clk.val();
        self.queue.rst.next = self.rst.val();
        self.queue.push.next = self.push.val();
        self.queue.din.next = self.din.val();
        self.queue.take.next = self.take.val();
        self.valid.next = self.queue.valid.val();
        self.dout.next = self.queue.dout.val();
        // The places held after this cycle: `room` for the next says that
        // `margin` more pushes, and one more let in as it falls, fit.
        self.held_next.next = self.held.q.val();
        if self.push.val() & !(self.take.val() & self.queue.valid.val()) {
            self.held_next.next = self.held.q.val() + self.one.val();
        }
        if !self.push.val() & self.take.val() & self.queue.valid.val() {
            self.held_next.next = self.held.q.val() - self.one.val();
        }
        self.held.d.next = self.held_next.val();
        self.room.next = self.held.q.val() <= self.limit.val();
        self.idle.next = self.held.q.val() == self.zero.val();
        self.bad_q.d.next = self.bad_q.q.val();
        if (self.push.val()
            & (self.held.q.val() == self.full.val())
            & !(self.take.val() & self.queue.valid.val()))
            | (self.take.val() & !self.queue.valid.val())
        {
            self.bad_q.d.next = true;
        }
        self.bad.next = self.bad_q.q.val();
        if self.rst.val() {
            self.held.d.next = self.zero.val();
            self.bad_q.d.next = false;
        }
    }
}
