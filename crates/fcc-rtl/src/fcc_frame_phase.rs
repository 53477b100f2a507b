//! `FccFramePhase`: the phase of a frame in the row-major core.
//!
//! INIT (after a reset, until the merge table is initialised), RUN (pixels
//! are taken; `in_done` ends it), DRAIN (until the sort network has sent the
//! frame's last join, `last_done`, and the union engine and the join queue
//! are idle), OUT (flatten and read-back; the read-back's `rb_done` starts
//! the next frame's RUN). `out_start` pulses in the cycle DRAIN becomes OUT
//! and reaches some 90 registers at K = 11, so it leaves through a net that
//! Vivado replicates. `rst` (the pipeline's reset) returns to INIT.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;

/// Phase of a frame (see the module doc).
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum Phase {
    /// After reset, until the merge table is initialised.
    Init,
    /// Pixels are taken.
    Run,
    /// The frame's pixels are in; the last joins are merged.
    Drain,
    /// Flatten and read-back: the frame's labels leave.
    Out,
}

#[derive(LogicBlock, Default)]
pub struct FccFramePhase {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The frame's last pixel slot has entered (registered).
    pub in_done: Signal<In, Bit>,
    /// The merge table is initialising.
    pub init_busy: Signal<In, Bit>,
    /// The sort network has sent the frame's last pixel's joins.
    pub last_done: Signal<In, Bit>,
    pub union_idle: Signal<In, Bit>,
    pub jq_empty: Signal<In, Bit>,
    /// The read-back has sent the frame's last label.
    pub rb_done: Signal<In, Bit>,
    /// The phase is RUN.
    pub run: Signal<Out, Bit>,
    /// OUT ends this cycle: the next frame's RUN starts at the clock edge.
    pub restart: Signal<Out, Bit>,
    /// One-cycle pulse: flatten and read-back start.
    pub out_start: Signal<Out, Bit>,
    /// The phase after the clock edge is RUN, and is OUT.
    pub run_next: Signal<Out, Bit>,
    pub out_next: Signal<Out, Bit>,
    phase: DFF<Phase>,
    last_seen: DFF<Bit>,
    drained: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    start_net: FccFanoutNet<Bit>,
}

impl Logic for FccFramePhase {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, phase, last_seen);
        if self.last_done.val() {
            self.last_seen.d.next = true;
        }
        self.drained.next = self.last_seen.q.val() & self.union_idle.val() & self.jq_empty.val();
        self.start.next = false;
        self.restart.next = false;
        if (self.phase.q.val() == Phase::Init) & !self.init_busy.val() {
            self.phase.d.next = Phase::Run;
        }
        if (self.phase.q.val() == Phase::Run) & self.in_done.val() {
            self.phase.d.next = Phase::Drain;
        }
        if (self.phase.q.val() == Phase::Drain) & self.drained.val() {
            self.start.next = true;
            self.phase.d.next = Phase::Out;
        }
        if (self.phase.q.val() == Phase::Out) & self.rb_done.val() {
            self.phase.d.next = Phase::Run;
            self.restart.next = true;
            self.last_seen.d.next = false;
        }
        if self.rst.val() {
            self.phase.d.next = Phase::Init;
            self.last_seen.d.next = false;
        }
        self.start_net.x.next = self.start.val();
        self.out_start.next = self.start_net.y.val();
        self.run.next = self.phase.q.val() == Phase::Run;
        self.run_next.next = self.phase.d.val() == Phase::Run;
        self.out_next.next = self.phase.d.val() == Phase::Out;
    }
}
