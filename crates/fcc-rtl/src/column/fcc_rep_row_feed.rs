//! `FccRepRowFeed`: the representative rows' table and the rows it feeds
//! `FccRowReps` (docs/column-core.md, item 3). The table holds each row's
//! `h + 1` run slots (labels, representatives, ages) in LUT RAM (`FccRam`, two cycles a read). The window takes one row a
//! pixel slot, in order (row `(i + h) mod R` as pixel `i` enters), and
//! gives one back as it leaves (row `i - h - S - 1`, `K + S` rows behind),
//! so the table is read and written by two counters, never by address.
//!
//! * The reader keeps up to four rows ready (`head_*`, `head_ok`): a read
//!   is issued while the rows ready and in flight are fewer than four, so
//!   one row a cycle flows once the first arrive.
//! * `pop` (the window shifts): the head goes, and the row leaving the
//!   window (`wb_*`) is written at the writer's row.
//! * `rst`: the reader starts again at row `h`, the writer `K + S` rows
//!   behind it, nothing ready. Until the reader has passed the frame's
//!   last row once, the rows it reads have not been written since the
//!   reset: they come out empty, ages by slot (no `X` from a RAM never
//!   written).
//!
//! A row is read again `R` slots after it was read, and written back
//! `K + S` slots after; with up to four rows read ahead and two cycles a
//! read, the write comes first while `R >= K + S + 4` (`FccRepJoins`
//! checks it).

use rust_hdl::prelude::*;

use super::REP_AGE_BITS;
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::types::{kb, vec_of};

/// Rows the feed keeps ready.
const FEED_DEPTH: usize = 4;

#[derive(LogicBlock)]
pub struct FccRepRowFeed {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The frame's last row, `R - 1` (constant while a frame runs).
    pub last_row: Signal<In, Bits<7>>,
    pub pop: Signal<In, Bit>,
    pub head_ok: Signal<Out, Bit>,
    pub head_label: Vec<Signal<Out, Bits<16>>>,
    pub head_rep: Vec<Signal<Out, Bits<16>>>,
    pub head_age: Vec<Signal<Out, Bits<REP_AGE_BITS>>>,
    pub wb_label: Vec<Signal<In, Bits<16>>>,
    pub wb_rep: Vec<Signal<In, Bits<16>>>,
    pub wb_age: Vec<Signal<In, Bits<REP_AGE_BITS>>>,
    labels: Vec<FccRam<Bits<16>, 7>>,
    reps: Vec<FccRam<Bits<16>, 7>>,
    ages: Vec<FccRam<Bits<REP_AGE_BITS>, 7>>,
    rd_row: FccFanoutReg<Bits<7>>,
    wr_row: DFF<Bits<7>>,
    fresh: DFF<Bit>,
    /// A read issued one and two cycles ago, and whether it was fresh.
    v1: DFF<Bit>,
    v2: FccFanoutReg<Bit>,
    f1: DFF<Bit>,
    f2: FccFanoutReg<Bit>,
    count: DFF<Bits<3>>,
    /// The rows ready, head first: entry `j`'s slot `k` at `j * (h + 1) + k`.
    q_label: Vec<DFF<Bits<16>>>,
    q_rep: Vec<DFF<Bits<16>>>,
    q_age: Vec<FccFanoutReg<Bits<REP_AGE_BITS>>>,
    issue: Signal<Local, Bit>,
    /// Rows ready and coming.
    infl: Signal<Local, Bits<3>>,
    /// The entry a row arriving takes.
    at: Signal<Local, Bits<3>>,
    /// `at`, replicated by Vivado (it reaches many loads).
    at_net: FccFanoutNet<Bits<3>>,
    in_label: Vec<Signal<Local, Bits<16>>>,
    in_rep: Vec<Signal<Local, Bits<16>>>,
    in_age: Vec<Signal<Local, Bits<REP_AGE_BITS>>>,
    entry_no: Vec<Constant<Bits<3>>>,
    depth: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    one7: Constant<Bits<7>>,
    zero7: Constant<Bits<7>>,
    h7: Constant<Bits<7>>,
    /// `K + S - h - 1`: the writer's first row is `R - 1` less it.
    behind: Constant<Bits<7>>,
    zero16: Constant<Bits<16>>,
    /// Run slot numbers: a fresh row's ages.
    slot_no: Vec<Constant<Bits<REP_AGE_BITS>>>,
    _n: usize,
    _d: usize,
}

impl FccRepRowFeed {
    /// Frames of at most `rows` rows, filter size `k`, `s` rows kept above
    /// the window.
    pub fn new(rows: usize, k: usize, s: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_row: Default::default(),
            pop: Default::default(),
            head_ok: Default::default(),
            head_label: vec_of(n),
            head_rep: vec_of(n),
            head_age: vec_of(n),
            wb_label: vec_of(n),
            wb_rep: vec_of(n),
            wb_age: vec_of(n),
            labels: (0..n).map(|_| FccRam::new(rows)).collect(),
            reps: (0..n).map(|_| FccRam::new(rows)).collect(),
            ages: (0..n).map(|_| FccRam::new(rows)).collect(),
            rd_row: Default::default(),
            wr_row: Default::default(),
            fresh: Default::default(),
            v1: Default::default(),
            v2: Default::default(),
            f1: Default::default(),
            f2: Default::default(),
            count: Default::default(),
            q_label: vec_of(FEED_DEPTH * n),
            q_rep: vec_of(FEED_DEPTH * n),
            q_age: vec_of(FEED_DEPTH * n),
            issue: Default::default(),
            infl: Default::default(),
            at: Default::default(),
            at_net: Default::default(),
            in_label: vec_of(n),
            in_rep: vec_of(n),
            in_age: vec_of(n),
            entry_no: (0..FEED_DEPTH).map(|j| kb(j as u64)).collect(),
            depth: kb(FEED_DEPTH as u64),
            one3: kb(1),
            zero3: kb(0),
            one7: kb(1),
            zero7: kb(0),
            h7: kb(h as u64),
            behind: kb((k + s - h - 1) as u64),
            zero16: kb(0),
            slot_no: (0..n).map(|k| kb(k as u64)).collect(),
            _n: n,
            _d: FEED_DEPTH,
        }
    }
}

impl Logic for FccRepRowFeed {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, rd_row, wr_row, fresh, v1, v2, f1, f2, count);
        for j in 0..self.q_label.len() {
            self.q_label[j].clock.next = self.clk.val();
            self.q_rep[j].clock.next = self.clk.val();
            self.q_age[j].clock.next = self.clk.val();
            self.q_label[j].d.next = self.q_label[j].q.val();
            self.q_rep[j].d.next = self.q_rep[j].q.val();
            self.q_age[j].d.next = self.q_age[j].q.val();
        }
        // The reader: a read while fewer than four rows are ready or coming.
        self.infl.next = self.count.q.val();
        if self.v1.q.val() {
            self.infl.next = self.infl.val() + self.one3.val();
        }
        if self.v2.q.val() {
            self.infl.next = self.infl.val() + self.one3.val();
        }
        self.issue.next = self.infl.val() < self.depth.val();
        self.v1.d.next = self.issue.val();
        self.v2.d.next = self.v1.q.val();
        self.f1.d.next = self.fresh.q.val();
        self.f2.d.next = self.f1.q.val();
        if self.issue.val() {
            self.rd_row.d.next = self.rd_row.q.val() + self.one7.val();
            if self.rd_row.q.val() == self.last_row.val() {
                self.rd_row.d.next = self.zero7.val();
                self.fresh.d.next = false;
            }
        }
        for k in 0..self._n {
            self.labels[k].clk.next = self.clk.val();
            self.reps[k].clk.next = self.clk.val();
            self.labels[k].read_en.next = self.issue.val();
            self.reps[k].read_en.next = self.issue.val();
            self.labels[k].read_addr.next = self.rd_row.q.val();
            self.reps[k].read_addr.next = self.rd_row.q.val();
            self.labels[k].write_en.next = self.pop.val();
            self.reps[k].write_en.next = self.pop.val();
            self.labels[k].write_addr.next = self.wr_row.q.val();
            self.reps[k].write_addr.next = self.wr_row.q.val();
            self.labels[k].write_data.next = self.wb_label[k].val();
            self.reps[k].write_data.next = self.wb_rep[k].val();
            self.ages[k].clk.next = self.clk.val();
            self.ages[k].read_en.next = self.issue.val();
            self.ages[k].read_addr.next = self.rd_row.q.val();
            self.ages[k].write_en.next = self.pop.val();
            self.ages[k].write_addr.next = self.wr_row.q.val();
            self.ages[k].write_data.next = self.wb_age[k].val();
            self.in_label[k].next = self.labels[k].read_data.val();
            self.in_rep[k].next = self.reps[k].read_data.val();
            self.in_age[k].next = self.ages[k].read_data.val();
            if self.f2.q.val() {
                self.in_label[k].next = self.zero16.val();
                self.in_rep[k].next = self.zero16.val();
                self.in_age[k].next = self.slot_no[k].val();
            }
        }
        // The writer.
        if self.pop.val() {
            self.wr_row.d.next = self.wr_row.q.val() + self.one7.val();
            if self.wr_row.q.val() == self.last_row.val() {
                self.wr_row.d.next = self.zero7.val();
            }
        }
        // The rows ready: a pop shifts them on, a row arriving goes last.
        self.at.next = self.count.q.val();
        if self.pop.val() {
            self.at.next = self.count.q.val() - self.one3.val();
            self.count.d.next = self.count.q.val() - self.one3.val();
            for nn in self._n..(self._n + 1) {
                for j in 0..(self._d - 1) {
                    for k in 0..self._n {
                        self.q_label[j * nn + k].d.next = self.q_label[(j + 1) * nn + k].q.val();
                        self.q_rep[j * nn + k].d.next = self.q_rep[(j + 1) * nn + k].q.val();
                        self.q_age[j * nn + k].d.next = self.q_age[(j + 1) * nn + k].q.val();
                    }
                }
            }
        }
        self.at_net.x.next = self.at.val();
        if self.v2.q.val() {
            self.count.d.next = self.at_net.y.val() + self.one3.val();
            for nn in self._n..(self._n + 1) {
                for j in 0..self._d {
                    if self.at_net.y.val() == self.entry_no[j].val() {
                        for k in 0..self._n {
                            self.q_label[j * nn + k].d.next = self.in_label[k].val();
                            self.q_rep[j * nn + k].d.next = self.in_rep[k].val();
                            self.q_age[j * nn + k].d.next = self.in_age[k].val();
                        }
                    }
                }
            }
        }
        self.head_ok.next = self.count.q.val() != self.zero3.val();
        for k in 0..self._n {
            self.head_label[k].next = self.q_label[k].q.val();
            self.head_rep[k].next = self.q_rep[k].q.val();
            self.head_age[k].next = self.q_age[k].q.val();
        }
        if self.rst.val() {
            self.rd_row.d.next = self.h7.val();
            self.wr_row.d.next = self.last_row.val() - self.behind.val();
            self.fresh.d.next = true;
            self.v1.d.next = false;
            self.v2.d.next = false;
            self.count.d.next = self.zero3.val();
        }
    }
}
