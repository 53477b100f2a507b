//! `FccStreamFifo`: a first-word-fall-through FIFO of `2^A` entries in
//! block RAM (`AP1 = A + 1` pointer bits) that gives an entry every cycle.
//!
//! `FccFifo` keeps one read in flight, so after a `take` its next entry
//! shows two cycles later. This one reads the RAM every cycle while it has
//! entries not yet read and room ahead: the words read wait in [`AHEAD`]
//! flip-flop entries (the head in entry 0: `valid`, `dout`), and a read is
//! issued while the entries held and the reads on their way (two cycles'
//! latency) are fewer than `AHEAD`, counted from flip-flops, so that no
//! output waits on this cycle's `take`. With `take` every cycle the head
//! stays valid: one entry held, two reads on their way.
//!
//! Write side: `push` writes `din` (the caller makes sure there is room:
//! `level`, registered, counts the entries pushed and not yet taken, one
//! cycle late). A word pushed at cycle `t` shows at `t + 4` at the soonest.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::types::{kb, vec_of};

/// Entries held ahead of the RAM.
pub const AHEAD: usize = 4;

#[derive(LogicBlock)]
pub struct FccStreamFifo<T: Synth, const A: usize, const AP1: usize> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub din: Signal<In, T>,
    pub valid: Signal<Out, Bit>,
    pub dout: Signal<Out, T>,
    pub take: Signal<In, Bit>,
    pub level: Signal<Out, Bits<AP1>>,
    ram: FccRam<T, A>,
    ahead: Vec<FccFanoutReg<T>>,
    /// Entries held ahead (0 to 4), and whether any is.
    held: DFF<Bits<3>>,
    held_any: FccFanoutReg<Bit>,
    /// Reads issued one and two cycles ago (the latter's word shows now).
    r1: FccFanoutReg<Bit>,
    r2: FccFanoutReg<Bit>,
    wp: FccFanoutReg<Bits<AP1>>,
    rp: FccFanoutReg<Bits<AP1>>,
    tp: DFF<Bits<AP1>>,
    level_q: DFF<Bits<AP1>>,
    issue: Signal<Local, Bit>,
    /// `issue`, replicated by Vivado (it reaches many loads).
    issue_net: FccFanoutNet<Bit>,
    pop: Signal<Local, Bit>,
    /// Entries held after this cycle's pop: where an arriving word goes.
    kept: Signal<Local, Bits<3>>,
    held_m1: Signal<Local, Bits<3>>,
    /// `held_m1`, replicated by Vivado (it reaches many loads).
    held_m1_net: FccFanoutNet<Bits<3>>,
    held_p1: Signal<Local, Bits<3>>,
    /// Entries held and reads on their way.
    claimed: Signal<Local, Bits<3>>,
    _n: usize,
    idx: Vec<Constant<Bits<3>>>,
    room: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    one: Constant<Bits<AP1>>,
    zero: Constant<Bits<AP1>>,
}

impl<T: Synth, const A: usize, const AP1: usize> Default for FccStreamFifo<T, A, AP1> {
    fn default() -> Self {
        assert_eq!(AP1, A + 1);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            din: Default::default(),
            valid: Default::default(),
            dout: Default::default(),
            take: Default::default(),
            level: Default::default(),
            ram: FccRam::new(1 << A),
            ahead: vec_of(AHEAD),
            held: Default::default(),
            held_any: Default::default(),
            r1: Default::default(),
            r2: Default::default(),
            wp: Default::default(),
            rp: Default::default(),
            tp: Default::default(),
            level_q: Default::default(),
            issue: Default::default(),
            issue_net: Default::default(),
            pop: Default::default(),
            kept: Default::default(),
            held_m1: Default::default(),
            held_m1_net: Default::default(),
            held_p1: Default::default(),
            claimed: Default::default(),
            _n: AHEAD,
            idx: (0..AHEAD).map(|i| kb(i as u64)).collect(),
            room: kb(AHEAD as u64),
            one3: kb(1),
            zero3: kb(0),
            one: kb(1),
            zero: kb(0),
        }
    }
}

impl<T: Synth, const A: usize, const AP1: usize> Logic for FccStreamFifo<T, A, AP1> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, held, held_any, r1, r2, wp, rp, tp, level_q);
        for i in 0..(self._n) {
            self.ahead[i].clock.next = self.clk.val();
            self.ahead[i].d.next = self.ahead[i].q.val();
        }
        self.ram.clk.next = self.clk.val();
        self.valid.next = self.held_any.q.val();
        self.dout.next = self.ahead[0].q.val();
        self.pop.next = self.take.val() & self.held_any.q.val();
        // A read while the RAM has a word not read and the entries held
        // and on their way leave room (from flip-flops: not this cycle's
        // pop).
        self.claimed.next = self.held.q.val();
        if self.r1.q.val() {
            self.claimed.next = self.held.q.val() + self.one3.val();
        }
        if self.r2.q.val() {
            self.claimed.next = self.claimed.val() + self.one3.val();
        }
        self.issue.next =
            (self.rp.q.val() != self.wp.q.val()) & (self.claimed.val() < self.room.val());
        self.issue_net.x.next = self.issue.val();
        self.ram.read_en.next = self.issue_net.y.val();
        self.ram.read_addr.next = self.rp.q.val().get_bits::<A>(0);
        if self.issue_net.y.val() {
            self.rp.d.next = self.rp.q.val() + self.one.val();
        }
        self.r1.d.next = self.issue_net.y.val();
        self.r2.d.next = self.r1.q.val();
        // The entries: a pop moves them up, an arriving word goes after
        // the last one kept.
        // The counts one less and one more come from the flip-flops, so
        // that the late `pop` only chooses among them.
        self.held_m1.next = self.held.q.val() - self.one3.val();
        self.held_m1_net.x.next = self.held_m1.val();
        self.held_p1.next = self.held.q.val() + self.one3.val();
        self.kept.next = self.held.q.val();
        if self.pop.val() {
            self.kept.next = self.held_m1_net.y.val();
        }
        for i in 0..(self._n - 1) {
            if self.pop.val() {
                self.ahead[i].d.next = self.ahead[i + 1].q.val();
            }
        }
        for i in 0..(self._n) {
            if self.r2.q.val() & (self.kept.val() == self.idx[i].val()) {
                self.ahead[i].d.next = self.ram.read_data.val();
            }
        }
        self.held.d.next = self.held.q.val();
        if self.pop.val() & !self.r2.q.val() {
            self.held.d.next = self.held_m1_net.y.val();
        }
        if !self.pop.val() & self.r2.q.val() {
            self.held.d.next = self.held_p1.val();
        }
        self.held_any.d.next = (self.kept.val() != self.zero3.val()) | self.r2.q.val();
        // The write side and the level.
        self.ram.write_en.next = self.push.val();
        self.ram.write_addr.next = self.wp.q.val().get_bits::<A>(0);
        self.ram.write_data.next = self.din.val();
        if self.push.val() {
            self.wp.d.next = self.wp.q.val() + self.one.val();
        }
        if self.pop.val() {
            self.tp.d.next = self.tp.q.val() + self.one.val();
        }
        self.level_q.d.next = self.wp.q.val() - self.tp.q.val();
        self.level.next = self.level_q.q.val();
        if self.rst.val() {
            self.held.d.next = self.zero3.val();
            self.held_any.d.next = false;
            self.r1.d.next = false;
            self.r2.d.next = false;
            self.wp.d.next = self.zero.val();
            self.rp.d.next = self.zero.val();
            self.tp.d.next = self.zero.val();
            self.level_q.d.next = self.zero.val();
        }
    }
}
