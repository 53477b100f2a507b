//! `FccRegFrameStatus`: the frame-status registers of the register file,
//! each a field block of its access type: FRAME_COUNT (`FccRegCounter`),
//! STATUS.FRAME_DONE (`FccRegW1c`), CLUSTERS .. GEAR_STALLS and the
//! FRAME_FLAGS bits (`FccRegSnapshot`).
//!
//! In the cycle `frame_end` is high (the last label beat leaves in phase
//! Out: `frame_sent` with `out_next` one cycle earlier) the live counters of
//! the blocks are latched, the frame counter counts, the sticky FRAME_DONE
//! bit is set and, one cycle later, `frame_done` pulses with the latched
//! values already on `st_*`. CONTROL.CLEAR zeroes them in its three groups
//! (`clear_count`, `clear_frame`, `clear_stalls`, see `FccRegControl`).
//! The phase flag `out_next` is registered here in kept copies, one per
//! group of at most 64 loads: `out_status` for FRAME_COUNT, FRAME_DONE,
//! `frame_done`, CLUSTERS, PROVISIONAL, UNLABELLED, FRAME_FLAGS and
//! `out_perf` for JOINS and GEAR_STALLS, so that the frame end is not one net
//! of a hundred enables; `frame_end` is the frame counter's addend, not its
//! enable.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_reg_counter::FccRegCounter;
use crate::fcc_reg_snapshot::FccRegSnapshot;
use crate::fcc_reg_w1c::FccRegW1c;

#[derive(LogicBlock)]
pub struct FccRegFrameStatus {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // From the core.
    /// The frame's last label beat is accepted (a frame end in phase Out).
    pub frame_sent: Signal<In, Bit>,
    /// The core is in phase Out in the next cycle.
    pub out_next: Signal<In, Bit>,
    pub clusters: Signal<In, Bits<16>>,
    pub provisional: Signal<In, Bits<16>>,
    pub overflow: Signal<In, Bit>,
    pub unlabelled: Signal<In, Bits<20>>,
    pub frame_error: Signal<In, Bit>,
    pub joins: Signal<In, Bits<24>>,
    pub gear_stalls: Signal<In, Bits<24>>,
    // Writes: STATUS (W1C) and CONTROL.CLEAR.
    pub we_status: Signal<In, Bit>,
    pub wdata: Signal<In, Bits<32>>,
    pub clear_count: Signal<In, Bit>,
    pub clear_frame: Signal<In, Bit>,
    pub clear_stalls: Signal<In, Bit>,
    // The registers.
    pub frame_done: Signal<Out, Bit>,
    /// STATUS.FRAME_DONE.
    pub done: Signal<Out, Bit>,
    pub count: Signal<Out, Bits<32>>,
    pub st_clusters: Signal<Out, Bits<16>>,
    pub st_provisional: Signal<Out, Bits<16>>,
    pub st_overflow: Signal<Out, Bit>,
    pub st_unlabelled: Signal<Out, Bits<20>>,
    pub st_frame_error: Signal<Out, Bit>,
    pub st_joins: Signal<Out, Bits<24>>,
    pub st_gear_stalls: Signal<Out, Bits<24>>,
    status: FccRegW1c,
    frame_count: FccRegCounter,
    snap_clusters: FccRegSnapshot<Bits<16>>,
    snap_provisional: FccRegSnapshot<Bits<16>>,
    snap_unlabelled: FccRegSnapshot<Bits<20>>,
    snap_overflow: FccRegSnapshot<Bit>,
    snap_frame_error: FccRegSnapshot<Bit>,
    snap_joins: FccRegSnapshot<Bits<24>>,
    snap_gear_stalls: FccRegSnapshot<Bits<24>>,
    done_q: DFF<Bit>,
    out_status: FccKeepReg<Bit>,
    out_perf: FccKeepReg<Bit>,
    frame_end: Signal<Local, Bit>,
    frame_end_perf: Signal<Local, Bit>,
}

impl FccRegFrameStatus {
    /// `done_lsb`: the bit of STATUS.FRAME_DONE.
    pub fn new(done_lsb: u32) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            frame_sent: Default::default(),
            out_next: Default::default(),
            clusters: Default::default(),
            provisional: Default::default(),
            overflow: Default::default(),
            unlabelled: Default::default(),
            frame_error: Default::default(),
            joins: Default::default(),
            gear_stalls: Default::default(),
            we_status: Default::default(),
            wdata: Default::default(),
            clear_count: Default::default(),
            clear_frame: Default::default(),
            clear_stalls: Default::default(),
            frame_done: Default::default(),
            done: Default::default(),
            count: Default::default(),
            st_clusters: Default::default(),
            st_provisional: Default::default(),
            st_overflow: Default::default(),
            st_unlabelled: Default::default(),
            st_frame_error: Default::default(),
            st_joins: Default::default(),
            st_gear_stalls: Default::default(),
            status: FccRegW1c::new(&[done_lsb]),
            frame_count: FccRegCounter::new(),
            snap_clusters: Default::default(),
            snap_provisional: Default::default(),
            snap_unlabelled: Default::default(),
            snap_overflow: Default::default(),
            snap_frame_error: Default::default(),
            snap_joins: Default::default(),
            snap_gear_stalls: Default::default(),
            done_q: Default::default(),
            out_status: Default::default(),
            out_perf: Default::default(),
            frame_end: Default::default(),
            frame_end_perf: Default::default(),
        }
    }
}

impl Logic for FccRegFrameStatus {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, done_q);
        self.out_status.clock.next = self.clk.val();
        self.out_perf.clock.next = self.clk.val();
        self.out_status.d.next = self.out_next.val();
        self.out_perf.d.next = self.out_next.val();
        self.frame_end.next = self.out_status.q.val() & self.frame_sent.val();
        self.frame_end_perf.next = self.out_perf.q.val() & self.frame_sent.val();
        self.done_q.d.next = self.frame_end.val();
        if self.rst.val() {
            self.done_q.d.next = false;
        }
        self.status.clk.next = self.clk.val();
        self.status.rst.next = self.rst.val();
        self.status.we.next = self.we_status.val();
        self.status.wdata.next = self.wdata.val();
        self.status.set[0].next = self.frame_end.val();
        self.status.clear.next = self.clear_count.val();
        self.frame_count.clk.next = self.clk.val();
        self.frame_count.rst.next = self.rst.val();
        self.frame_count.inc.next = self.frame_end.val();
        self.frame_count.clear.next = self.clear_count.val();
        self.snap_clusters.clk.next = self.clk.val();
        self.snap_clusters.rst.next = self.rst.val();
        self.snap_clusters.latch.next = self.frame_end.val();
        self.snap_clusters.value.next = self.clusters.val();
        self.snap_clusters.clear.next = self.clear_count.val();
        self.snap_provisional.clk.next = self.clk.val();
        self.snap_provisional.rst.next = self.rst.val();
        self.snap_provisional.latch.next = self.frame_end.val();
        self.snap_provisional.value.next = self.provisional.val();
        self.snap_provisional.clear.next = self.clear_frame.val();
        self.snap_unlabelled.clk.next = self.clk.val();
        self.snap_unlabelled.rst.next = self.rst.val();
        self.snap_unlabelled.latch.next = self.frame_end.val();
        self.snap_unlabelled.value.next = self.unlabelled.val();
        self.snap_unlabelled.clear.next = self.clear_frame.val();
        self.snap_overflow.clk.next = self.clk.val();
        self.snap_overflow.rst.next = self.rst.val();
        self.snap_overflow.latch.next = self.frame_end.val();
        self.snap_overflow.value.next = self.overflow.val();
        self.snap_overflow.clear.next = self.clear_count.val();
        self.snap_frame_error.clk.next = self.clk.val();
        self.snap_frame_error.rst.next = self.rst.val();
        self.snap_frame_error.latch.next = self.frame_end.val();
        self.snap_frame_error.value.next = self.frame_error.val();
        self.snap_frame_error.clear.next = self.clear_count.val();
        self.snap_joins.clk.next = self.clk.val();
        self.snap_joins.rst.next = self.rst.val();
        self.snap_joins.latch.next = self.frame_end_perf.val();
        self.snap_joins.value.next = self.joins.val();
        self.snap_joins.clear.next = self.clear_frame.val();
        self.snap_gear_stalls.clk.next = self.clk.val();
        self.snap_gear_stalls.rst.next = self.rst.val();
        self.snap_gear_stalls.latch.next = self.frame_end_perf.val();
        self.snap_gear_stalls.value.next = self.gear_stalls.val();
        self.snap_gear_stalls.clear.next = self.clear_stalls.val();
        self.frame_done.next = self.done_q.q.val();
        self.done.next = self.status.q[0].val();
        self.count.next = self.frame_count.q.val();
        self.st_clusters.next = self.snap_clusters.q.val();
        self.st_provisional.next = self.snap_provisional.q.val();
        self.st_overflow.next = self.snap_overflow.q.val();
        self.st_unlabelled.next = self.snap_unlabelled.q.val();
        self.st_frame_error.next = self.snap_frame_error.q.val();
        self.st_joins.next = self.snap_joins.q.val();
        self.st_gear_stalls.next = self.snap_gear_stalls.q.val();
    }
}
