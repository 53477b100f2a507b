//! `FccStreamCtl`: the control of a stream FIFO (`FccStreamFifo`): its
//! pointers, the reads on their way and the entries held ahead of the RAM,
//! for one or more data lanes (`FccStreamLane`) pushed and taken together.
//!
//! The lanes hold the words (a RAM each and [`AHEAD`] flip-flop entries);
//! this block says, once for all of them, when the RAM is read and where
//! (`ram_re`, `ram_raddr`), where a push writes (`ram_waddr`), when the
//! entries move up (`shift`, a pop) and which entry takes the word the RAM
//! gives (`load`, one-hot over the [`LOAD`] places counted before this
//! cycle's pop: entry `i` takes the word at bit `i + 1` with `shift` and at
//! bit `i` without; a register, worked out a cycle ahead, so that each lane
//! bit's multiplexer takes it and `shift` straight). So the lanes share
//! one set of these registers rather than holding equal copies, and each
//! signal that reaches every lane's bits is built for Vivado to replicate
//! (`FccFanoutReg`, `FccFanoutNet`).
//!
//! A read is issued while the RAM has a word not read and the entries held
//! and the reads on their way (two cycles' latency) are fewer than
//! [`AHEAD`], counted from flip-flops, so that no output waits on this
//! cycle's `take`. With `take` every cycle the head stays valid: one entry
//! held, two reads on their way. `level`, registered, counts the entries
//! pushed and not yet taken, one cycle late.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::kb;

/// Entries held ahead of the RAM.
pub const AHEAD: usize = 4;
/// Places the RAM's next word can go, counted before a pop: `0..=AHEAD`.
pub const LOAD: usize = AHEAD + 1;

#[derive(LogicBlock)]
pub struct FccStreamCtl<const A: usize, const AP1: usize> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    /// An entry is at the head (entry 0).
    pub valid: Signal<Out, Bit>,
    pub level: Signal<Out, Bits<AP1>>,
    /// The lanes' RAM read (its word shows two cycles later) and write.
    pub ram_re: Signal<Out, Bit>,
    pub ram_raddr: Signal<Out, Bits<A>>,
    pub ram_waddr: Signal<Out, Bits<A>>,
    /// The head is taken: each entry takes the one after it.
    pub shift: Signal<Out, Bit>,
    /// Where the word the RAM gives now goes, one-hot, counted before
    /// this cycle's pop: entry `i` takes it at bit `i + 1` while `shift`,
    /// at bit `i` otherwise (none: no word).
    pub load: Signal<Out, Bits<LOAD>>,
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
    /// `pop`, replicated by Vivado (every lane's entries).
    pop_net: FccFanoutNet<Bit>,
    held_m1: Signal<Local, Bits<3>>,
    held_p1: Signal<Local, Bits<3>>,
    /// Entries held and reads on their way.
    claimed: Signal<Local, Bits<3>>,
    /// The entries held after this cycle: where next cycle's word goes,
    /// counted before next cycle's pop, and that place one-hot.
    held_next: Signal<Local, Bits<3>>,
    load_next: Signal<Local, Bits<LOAD>>,
    load_q: FccFanoutReg<Bits<LOAD>>,
    _n: usize,
    idx: Vec<Constant<Bits<3>>>,
    onehot: Vec<Constant<Bits<LOAD>>>,
    room: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    zero_load: Constant<Bits<LOAD>>,
    one: Constant<Bits<AP1>>,
    zero: Constant<Bits<AP1>>,
}

impl<const A: usize, const AP1: usize> Default for FccStreamCtl<A, AP1> {
    fn default() -> Self {
        assert_eq!(AP1, A + 1);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            take: Default::default(),
            valid: Default::default(),
            level: Default::default(),
            ram_re: Default::default(),
            ram_raddr: Default::default(),
            ram_waddr: Default::default(),
            shift: Default::default(),
            load: Default::default(),
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
            pop_net: Default::default(),
            held_m1: Default::default(),
            held_p1: Default::default(),
            claimed: Default::default(),
            held_next: Default::default(),
            load_next: Default::default(),
            load_q: Default::default(),
            _n: LOAD,
            idx: (0..LOAD).map(|i| kb(i as u64)).collect(),
            onehot: (0..LOAD).map(|i| kb(1u64 << i)).collect(),
            room: kb(AHEAD as u64),
            one3: kb(1),
            zero3: kb(0),
            zero_load: kb(0),
            one: kb(1),
            zero: kb(0),
        }
    }
}

impl<const A: usize, const AP1: usize> Logic for FccStreamCtl<A, AP1> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, held, held_any, r1, r2, wp, rp, tp, level_q, load_q);
        self.valid.next = self.held_any.q.val();
        self.pop.next = self.take.val() & self.held_any.q.val();
        self.pop_net.x.next = self.pop.val();
        self.shift.next = self.pop_net.y.val();
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
        self.ram_re.next = self.issue_net.y.val();
        self.ram_raddr.next = self.rp.q.val().get_bits::<A>(0);
        if self.issue_net.y.val() {
            self.rp.d.next = self.rp.q.val() + self.one.val();
        }
        self.r1.d.next = self.issue_net.y.val();
        self.r2.d.next = self.r1.q.val();
        // The entries: a pop moves them up, an arriving word goes after
        // the last one kept. The counts one less and one more come from
        // the flip-flops, so that the late `pop` only chooses among them.
        self.held_m1.next = self.held.q.val() - self.one3.val();
        self.held_p1.next = self.held.q.val() + self.one3.val();
        self.held_next.next = self.held.q.val();
        if self.pop.val() & !self.r2.q.val() {
            self.held_next.next = self.held_m1.val();
        }
        if !self.pop.val() & self.r2.q.val() {
            self.held_next.next = self.held_p1.val();
        }
        self.held.d.next = self.held_next.val();
        // The entries held after this cycle and any word arriving now.
        self.held_any.d.next = (self.held_next.val() != self.zero3.val()) | self.r2.q.val();
        // Next cycle's word (read now, `r1`) goes to place `held_next`:
        // entry `held_next - 1` if a pop comes with it, else `held_next`.
        self.load_next.next = self.zero_load.val();
        for i in 0..(self._n) {
            if self.r1.q.val() & (self.held_next.val() == self.idx[i].val()) {
                self.load_next.next = self.onehot[i].val();
            }
        }
        self.load_q.d.next = self.load_next.val();
        self.load.next = self.load_q.q.val();
        // The write side and the level.
        self.ram_waddr.next = self.wp.q.val().get_bits::<A>(0);
        if self.push.val() {
            self.wp.d.next = self.wp.q.val() + self.one.val();
        }
        if self.pop.val() {
            self.tp.d.next = self.tp.q.val() + self.one.val();
        }
        self.level_q.d.next = self.wp.q.val() - self.tp.q.val();
        self.level.next = self.level_q.q.val();
        if self.rst.val() {
            self.load_q.d.next = self.zero_load.val();
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
