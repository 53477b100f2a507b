//! `FccRunAcc`: each row's current run's accumulator (docs/column-core.md,
//! item 3, "Built: `FccRunAcc`"). A pixel adds itself to its row's entry, so the
//! slot table never looks a cluster up per pixel: a run's pixels all lie in
//! one row, and its accumulator goes to its cluster once, when the run is
//! over (a *flush*: its label and accumulator, `f_*`).
//!
//! A run is over when its row drops its hold (spec §9.2: `hold_drop`, the
//! bridge passed and not the ring's), when its row starts another run, or
//! at the frame end: after the frame's last pixel (`last`) the block
//! flushes every row's run still open, one row a cycle while `drain_go`
//! (`ready` low meanwhile, so the next frame waits), and says so with
//! `done`.
//!
//! A pixel taken in cycle `t` flushes (if at all) in cycle
//! `t + RUN_ACC_LATENCY`, a frame-end row read in cycle `t` (a cycle with
//! `drain_go` high) sooner: so a place for the accumulator (`FccFlushWait`)
//! can be made sure of before the pixel is let in or the row read.
//!
//! Pipeline (a pixel per cycle, every pixel slot of the frame, empty ones
//! too, since a row drops its hold at any slot):
//! * IN takes the pixel while `ready`; `FccAccPixel` makes its
//!   accumulator ([`ACC_PIXEL_LATENCY`] cycles).
//! * Two cycles before the accumulator is ready the row's entry is read
//!   (`FccRam`, two cycles: LUT RAM of `R` words), and its `live` flag
//!   (flip-flops, so that a reset empties every row; an OR of masked
//!   flags, registered).
//! * D decides: the pixel starts a run (its accumulator is the entry; a
//!   run still open in the row is flushed) or continues one (the entry and
//!   the pixel merged); the run dropped is flushed, the pixel included
//!   when it is its own. D masks the merge's inputs for that.
//! * E merges (`FccAccMerge`, registered: its carry chains fill a cycle).
//! * W writes the entry back and registers the flush.
//!
//! A row's next pixel is `R` slots later (`R >= 5`: the write at W is done
//! before the row's next read), so the read never needs the write before
//! it forwarded.

use rust_hdl::prelude::*;

use super::fcc_acc_merge::FccAccMerge;
use super::fcc_acc_pixel::{FccAccPixel, ACC_PIXEL_LATENCY};
use super::{AccWord, RunPix};
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::types::{kb, vec_of};

/// Row address bits (frames of at most 128 rows).
const ROW_BITS: usize = 7;

/// Cycles from a pixel taken to its flush on `f_valid` (the pixel's
/// accumulator, then D, E, W and the flush's register); a frame-end row
/// flushes five cycles after its read.
pub const RUN_ACC_LATENCY: usize = ACC_PIXEL_LATENCY + 3;

/// A row's entry: its open run's label and accumulator.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RunEntry {
    pub label: Bits<16>,
    /// The row holds the run by hold 4 after the last column.
    pub ring: Bit,
    pub acc: AccWord,
}

/// What travels beside the pixel's accumulator: the pixel's run and row,
/// and whether it is a slot of the frame-end flush (`drain`) instead.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RunStep {
    pub valid: Bit,
    pub drain: Bit,
    pub lok: Bit,
    pub start: Bit,
    pub row: Bits<7>,
    pub label: Bits<16>,
    pub hold_drop: Bits<16>,
    pub ring_hold: Bit,
}

/// What D decided for W: write the row's entry (its label and live flag),
/// flush a run (the entry as read, or the new accumulator), the frame
/// end's flush is complete.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct RunWrite {
    pub write: Bit,
    pub row: Bits<7>,
    pub label: Bits<16>,
    pub live: Bit,
    pub flush: Bit,
    pub flush_old: Bit,
    pub flush_label: Bits<16>,
    /// The flush is the frame end's.
    pub end: Bit,
    /// The entry's hold-4 flag; the frame end's flush is of a run so held.
    pub ring: Bit,
    pub f_ring: Bit,
    pub done: Bit,
}

#[derive(LogicBlock)]
pub struct FccRunAcc {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub inp: Signal<In, RunPix>,
    pub ready: Signal<Out, Bit>,
    /// `C / 2` and the frame's last row `R - 1` (constant while a frame runs).
    pub half: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    /// The frame-end flush may read a row this cycle (a place waits for
    /// its accumulator).
    pub drain_go: Signal<In, Bit>,
    /// A run is over: its label and accumulator.
    pub f_valid: Signal<Out, Bit>,
    pub f_label: Signal<Out, Bits<16>>,
    pub f_acc: Signal<Out, AccWord>,
    /// The flush is the frame end's (a row's run still open after the
    /// frame's last pixel), not a pixel's.
    pub f_end: Signal<Out, Bit>,
    /// A frame-end flush whose run the row holds by hold 4 (its cluster
    /// is held to the frame end).
    pub f_ring: Signal<Out, Bit>,
    /// The frame-end flush is complete (one cycle, with the last row's
    /// flush if it has one).
    pub done: Signal<Out, Bit>,
    /// Sticky until reset: a pixel continued a run its row does not have
    /// open (the input does not follow `FccRowRuns`' runs; the pixel was
    /// taken as a run of its own).
    pub bad: Signal<Out, Bit>,
    pixel: FccAccPixel,
    merger: FccAccMerge,
    entries: FccRam<RunEntry, ROW_BITS>,
    live: Vec<DFF<Bit>>,
    /// IN's step, then the steps to D (`ACC_PIXEL_LATENCY` in all, so
    /// that D meets the pixel's accumulator); the read is issued two steps
    /// before D.
    steps: Vec<DFF<RunStep>>,
    /// The frame-end flush: busy, and the next row it reads.
    busy: DFF<Bit>,
    drain_row: DFF<Bits<7>>,
    /// The step that issues the read, and the read issued: the pixel's
    /// row, or the flush's; that row, a cycle later, whose live flag is
    /// read.
    rd_in: Signal<Local, RunStep>,
    rd_step: Signal<Local, RunStep>,
    /// `rd_step`'s row, the entries' read address, replicated by Vivado
    /// (it reaches every LUT RAM of the entries).
    rd_row_net: FccFanoutNet<Bits<ROW_BITS>>,
    /// A pixel is in the steps up to the read's (the frame end's reads
    /// wait for the last pixel's, so that its flushes come first).
    ahead: Signal<Local, Bit>,
    ahead_step: Signal<Local, RunStep>,
    live_row: DFF<Bits<7>>,
    /// The live flag of `live_row`: the masked flags' running OR, then
    /// registered for D.
    live_or: Vec<Signal<Local, Bit>>,
    old_live_q: DFF<Bit>,
    /// D: its step; the entry read's row is live; a labelled pixel; a
    /// run starts while one is open; what W does.
    dstep: Signal<Local, RunStep>,
    old_live: Signal<Local, Bit>,
    lokv: Signal<Local, Bit>,
    /// The selects of E's two accumulator inputs, replicated by Vivado:
    /// each reaches an accumulator's 501 bits.
    sel_a: FccFanoutNet<Bit>,
    sel_b: FccFanoutNet<Bit>,
    start_flush: Signal<Local, Bit>,
    wr: Signal<Local, RunWrite>,
    /// E: what W does, the merge's inputs, the entry as read.
    e_wr: DFF<RunWrite>,
    e_a: DFF<AccWord>,
    e_b: DFF<AccWord>,
    e_old: DFF<AccWord>,
    /// W: what it does, the row's new accumulator, the entry as read.
    w_wr: FccFanoutReg<RunWrite>,
    w_acc: DFF<AccWord>,
    w_old: DFF<AccWord>,
    w_entry: Signal<Local, RunEntry>,
    f_valid_q: FccFanoutReg<Bit>,
    f_label_q: DFF<Bits<16>>,
    f_acc_q: DFF<AccWord>,
    f_end_q: DFF<Bit>,
    f_ring_q: DFF<Bit>,
    done_q: DFF<Bit>,
    bad_q: DFF<Bit>,
    row_id: Vec<Constant<Bits<7>>>,
    one7: Constant<Bits<7>>,
    zero7: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    step_zero: Constant<RunStep>,
    wr_zero: Constant<RunWrite>,
    empty: Constant<AccWord>,
}

impl FccRunAcc {
    /// For frames of at most `rows` rows.
    pub fn new(rows: usize) -> Self {
        assert!((5..=1 << ROW_BITS).contains(&rows));
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            ready: Default::default(),
            half: Default::default(),
            last_row: Default::default(),
            drain_go: Default::default(),
            f_valid: Default::default(),
            f_label: Default::default(),
            f_acc: Default::default(),
            f_end: Default::default(),
            f_ring: Default::default(),
            done: Default::default(),
            bad: Default::default(),
            pixel: Default::default(),
            merger: Default::default(),
            entries: FccRam::new(rows).in_lut_ram(),
            live: vec_of(rows),
            steps: vec_of(ACC_PIXEL_LATENCY),
            busy: Default::default(),
            drain_row: Default::default(),
            rd_in: Default::default(),
            rd_step: Default::default(),
            rd_row_net: Default::default(),
            ahead: Default::default(),
            ahead_step: Default::default(),
            live_row: Default::default(),
            live_or: vec_of(rows),
            old_live_q: Default::default(),
            dstep: Default::default(),
            old_live: Default::default(),
            lokv: Default::default(),
            sel_a: Default::default(),
            sel_b: Default::default(),
            start_flush: Default::default(),
            wr: Default::default(),
            e_wr: Default::default(),
            e_a: Default::default(),
            e_b: Default::default(),
            e_old: Default::default(),
            w_wr: Default::default(),
            w_acc: Default::default(),
            w_old: Default::default(),
            w_entry: Default::default(),
            f_valid_q: Default::default(),
            f_label_q: Default::default(),
            f_acc_q: Default::default(),
            f_end_q: Default::default(),
            f_ring_q: Default::default(),
            done_q: Default::default(),
            bad_q: Default::default(),
            row_id: (0..rows).map(|r| kb(r as u64)).collect(),
            one7: kb(1),
            zero7: kb(0),
            zero16: kb(0),
            step_zero: Constant::new(RunStep::default()),
            wr_zero: Constant::new(RunWrite::default()),
            empty: Constant::new(AccWord::empty()),
        }
    }
}

impl Logic for FccRunAcc {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, busy, drain_row, live_row, old_live_q, e_wr, e_a, e_b, e_old, w_wr, w_acc,
            w_old, f_valid_q, f_label_q, f_acc_q, f_end_q, f_ring_q, done_q, bad_q
        );
        self.ready.next = !self.busy.q.val();
        // IN: the pixel's step, and its accumulator's inputs.
        for s in 0..self.steps.len() {
            self.steps[s].clock.next = self.clk.val();
        }
        self.steps[0].d.next = self.step_zero.val();
        if !self.busy.q.val() {
            self.steps[0].d.next.valid = self.inp.val().valid;
            self.steps[0].d.next.lok = self.inp.val().lok;
            self.steps[0].d.next.start = self.inp.val().start;
            self.steps[0].d.next.row = self.inp.val().row;
            self.steps[0].d.next.label = self.inp.val().label;
            self.steps[0].d.next.hold_drop = self.inp.val().hold_drop;
            self.steps[0].d.next.ring_hold = self.inp.val().ring_hold;
        }
        self.pixel.clk.next = self.clk.val();
        self.pixel.rst.next = self.rst.val();
        self.pixel.half.next = self.half.val();
        self.pixel.x.next = self.inp.val().x;
        self.pixel.y.next = self.inp.val().y;
        self.pixel.z.next = self.inp.val().z;
        self.pixel.row.next = self.inp.val().row;
        self.pixel.col.next = self.inp.val().col;
        // The step two before D issues the read; while the frame-end flush
        // runs, its rows take the step's place (no pixel enters then), one
        // a cycle while `drain_go`, once the last pixels have issued
        // theirs.
        for ri in (self.steps.len() - 3)..(self.steps.len() - 2) {
            self.rd_in.next = self.steps[ri].q.val();
        }
        self.ahead.next = false;
        for sa in 0..(self.steps.len() - 2) {
            self.ahead_step.next = self.steps[sa].q.val();
            if self.ahead_step.val().valid {
                self.ahead.next = true;
            }
        }
        self.rd_step.next = self.rd_in.val();
        if self.busy.q.val() & !self.ahead.val() & self.drain_go.val() {
            self.rd_step.next = self.step_zero.val();
            self.rd_step.next.drain = true;
            self.rd_step.next.row = self.drain_row.q.val();
        }
        for s in 1..(self.steps.len() - 2) {
            self.steps[s].d.next = self.steps[s - 1].q.val();
        }
        for ri in (self.steps.len() - 3)..(self.steps.len() - 2) {
            self.steps[ri + 1].d.next = self.rd_step.val();
            self.steps[ri + 2].d.next = self.steps[ri + 1].q.val();
        }
        self.entries.clk.next = self.clk.val();
        self.entries.read_en.next = true;
        self.rd_row_net.x.next = self.rd_step.val().row;
        self.entries.read_addr.next = self.rd_row_net.y.val();
        self.live_row.d.next = self.rd_step.val().row;
        // The frame-end flush starts once the last pixel is taken, reads
        // once it has issued its read, and reads the rows 0 ..= R - 1.
        self.busy.d.next = self.busy.q.val();
        self.drain_row.d.next = self.drain_row.q.val();
        if self.inp.val().valid & self.inp.val().last & !self.busy.q.val() {
            self.busy.d.next = true;
            self.drain_row.d.next = self.zero7.val();
        }
        if self.rd_step.val().drain {
            self.drain_row.d.next = self.drain_row.q.val() + self.one7.val();
            if self.drain_row.q.val() == self.last_row.val() {
                self.busy.d.next = false;
            }
        }
        // The row's live flag, read a cycle before D (an OR of the masked
        // flags, not a chain of multiplexers; the row's last write was a
        // column before).
        self.live_or[0].next =
            self.live[0].q.val() & (self.live_row.q.val() == self.row_id[0].val());
        for r in 1..self.row_id.len() {
            self.live_or[r].next = self.live_or[r - 1].val()
                | (self.live[r].q.val() & (self.live_row.q.val() == self.row_id[r].val()));
        }
        for last in (self.row_id.len() - 1)..self.row_id.len() {
            self.old_live_q.d.next = self.live_or[last].val();
        }
        // D: the step at the end of the line decides, with the entry read
        // and the pixel's accumulator. Both merge's inputs are masked here
        // (the empty accumulator is the merge's identity), so that E's merge
        // is the row's new accumulator as it is: a run that starts merges
        // the pixel with nothing, an empty slot the entry with nothing.
        for dd in (self.steps.len() - 1)..self.steps.len() {
            self.dstep.next = self.steps[dd].q.val();
        }
        self.old_live.next = self.old_live_q.q.val();
        self.lokv.next = self.dstep.val().valid & self.dstep.val().lok;
        self.start_flush.next = self.lokv.val() & self.dstep.val().start & self.old_live.val();
        self.wr.next.write = self.dstep.val().valid | self.dstep.val().drain;
        self.wr.next.row = self.dstep.val().row;
        self.wr.next.label = self.entries.read_data.val().label;
        self.wr.next.live = self.old_live.val();
        if self.lokv.val() {
            self.wr.next.label = self.dstep.val().label;
            self.wr.next.live = true;
        }
        // A run that starts ends one still open in the row (its entry as
        // read); a row that drops the run it holds ends it (the new
        // accumulator: with the pixel if it continued it); the frame end's
        // flush ends every run.
        self.wr.next.flush = self.start_flush.val();
        self.wr.next.flush_old = self.start_flush.val();
        self.wr.next.flush_label = self.entries.read_data.val().label;
        if self.dstep.val().valid
            & self.old_live.val()
            & (self.dstep.val().hold_drop != self.zero16.val())
            & (self.dstep.val().hold_drop == self.wr.val().label)
        {
            self.wr.next.live = false;
            self.wr.next.flush = true;
            self.wr.next.flush_label = self.wr.val().label;
        }
        if self.dstep.val().drain {
            self.wr.next.live = false;
            self.wr.next.flush = self.old_live.val();
        }
        self.wr.next.end = self.dstep.val().drain;
        self.wr.next.ring = self.dstep.val().ring_hold;
        self.wr.next.f_ring = self.dstep.val().drain & self.entries.read_data.val().ring;
        self.wr.next.done = self.dstep.val().drain & (self.dstep.val().row == self.last_row.val());
        self.e_wr.d.next = self.wr.val();
        self.sel_a.x.next = self.old_live.val() & !(self.lokv.val() & self.dstep.val().start);
        self.sel_b.x.next = self.lokv.val();
        self.e_a.d.next = self.empty.val();
        if self.sel_a.y.val() {
            self.e_a.d.next = self.entries.read_data.val().acc;
        }
        self.e_b.d.next = self.empty.val();
        if self.sel_b.y.val() {
            self.e_b.d.next = self.pixel.acc.val();
        }
        self.e_old.d.next = self.entries.read_data.val().acc;
        // E: the merge, registered.
        self.merger.a.next = self.e_a.q.val();
        self.merger.b.next = self.e_b.q.val();
        self.w_wr.d.next = self.e_wr.q.val();
        self.w_acc.d.next = self.merger.out.val();
        self.w_old.d.next = self.e_old.q.val();
        // W: the entry written back, the row's live flag, the flush.
        self.entries.write_en.next = self.w_wr.q.val().write;
        self.entries.write_addr.next = self.w_wr.q.val().row;
        self.w_entry.next.label = self.w_wr.q.val().label;
        self.w_entry.next.acc = self.w_acc.q.val();
        self.w_entry.next.ring = self.w_wr.q.val().ring;
        self.entries.write_data.next = self.w_entry.val();
        for r in 0..self.row_id.len() {
            self.live[r].clock.next = self.clk.val();
            self.live[r].d.next = self.live[r].q.val();
            if self.w_wr.q.val().write & (self.w_wr.q.val().row == self.row_id[r].val()) {
                self.live[r].d.next = self.w_wr.q.val().live;
            }
            if self.rst.val() {
                self.live[r].d.next = false;
            }
        }
        self.f_valid_q.d.next = self.w_wr.q.val().flush;
        self.f_label_q.d.next = self.w_wr.q.val().flush_label;
        self.f_acc_q.d.next = self.w_acc.q.val();
        if self.w_wr.q.val().flush_old {
            self.f_acc_q.d.next = self.w_old.q.val();
        }
        self.f_end_q.d.next = self.w_wr.q.val().end;
        self.f_ring_q.d.next = self.w_wr.q.val().f_ring;
        self.done_q.d.next = self.w_wr.q.val().done;
        self.f_valid.next = self.f_valid_q.q.val();
        self.f_label.next = self.f_label_q.q.val();
        self.f_acc.next = self.f_acc_q.q.val();
        self.f_end.next = self.f_end_q.q.val();
        self.f_ring.next = self.f_ring_q.q.val();
        self.done.next = self.done_q.q.val();
        // A pixel that continues a run must find it open in its row.
        self.bad_q.d.next = self.bad_q.q.val();
        if self.lokv.val()
            & !self.dstep.val().start
            & (!self.old_live.val()
                | (self.entries.read_data.val().label != self.dstep.val().label))
        {
            self.bad_q.d.next = true;
        }
        self.bad.next = self.bad_q.q.val();
        if self.rst.val() {
            self.busy.d.next = false;
            self.e_wr.d.next = self.wr_zero.val();
            self.w_wr.d.next = self.wr_zero.val();
            self.f_valid_q.d.next = false;
            self.done_q.d.next = false;
            self.bad_q.d.next = false;
            for s in 0..self.steps.len() {
                self.steps[s].d.next = self.step_zero.val();
            }
        }
    }
}
