//! `FccStreamCtl`: the control of a stream FIFO (`FccStreamFifo`): its
//! pointers, the reads on their way and the entries held ahead of the RAM,
//! for one or more data lanes (`FccStreamLane`) pushed and taken together.
//!
//! The lanes hold the words (a RAM each and [`AHEAD`] flip-flop entries);
//! this block says, once for all of them, when the RAM is read and where
//! (`ram_re`, `ram_raddr`), where a push writes (`ram_waddr`), when the
//! entries move up (`shift`, a pop) and which entry takes the word the RAM
//! gives (one bit an entry: `load_pop` in a cycle with a pop,
//! `load_keep` in one without; both registers, worked out a cycle ahead
//! for either case, so that each lane bit's multiplexer takes them and
//! `shift` straight). So the lanes share one set of these registers
//! rather than holding equal copies, and each signal that reaches every
//! lane's bits is built for Vivado to replicate (`FccFanoutReg`,
//! `FccFanoutNet`).
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
    /// Entry `i` takes the word the RAM gives (bit `i`, after `shift`):
    /// `load_pop` while `shift`, `load_keep` otherwise.
    pub load_pop: Signal<Out, Bits<AHEAD>>,
    pub load_keep: Signal<Out, Bits<AHEAD>>,
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
    /// `held_m1`, replicated by Vivado (it reaches many loads).
    held_m1_net: FccFanoutNet<Bits<3>>,
    held_p1: Signal<Local, Bits<3>>,
    /// Entries held and reads on their way.
    claimed: Signal<Local, Bits<3>>,
    /// The entries held after this cycle (where next cycle's word goes
    /// if no pop comes with it), and the selects worked out from them.
    held_next: Signal<Local, Bits<3>>,
    lp_next: Signal<Local, Bits<AHEAD>>,
    lk_next: Signal<Local, Bits<AHEAD>>,
    lp: FccFanoutReg<Bits<AHEAD>>,
    lk: FccFanoutReg<Bits<AHEAD>>,
    _n: usize,
    idx: Vec<Constant<Bits<3>>>,
    onehot: Vec<Constant<Bits<AHEAD>>>,
    room: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    zero_load: Constant<Bits<AHEAD>>,
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
            load_pop: Default::default(),
            load_keep: Default::default(),
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
            held_m1_net: Default::default(),
            held_p1: Default::default(),
            claimed: Default::default(),
            held_next: Default::default(),
            lp_next: Default::default(),
            lk_next: Default::default(),
            lp: Default::default(),
            lk: Default::default(),
            _n: AHEAD,
            idx: (0..AHEAD).map(|i| kb(i as u64)).collect(),
            onehot: (0..AHEAD).map(|i| kb(1u64 << i)).collect(),
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
        dff_setup!(self, clk, held, held_any, r1, r2, wp, rp, tp, level_q, lp, lk);
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
        self.held_m1_net.x.next = self.held_m1.val();
        self.held_p1.next = self.held.q.val() + self.one3.val();
        self.held_next.next = self.held.q.val();
        if self.pop.val() & !self.r2.q.val() {
            self.held_next.next = self.held_m1_net.y.val();
        }
        if !self.pop.val() & self.r2.q.val() {
            self.held_next.next = self.held_p1.val();
        }
        self.held.d.next = self.held_next.val();
        // The entries held after this cycle and any word arriving now.
        self.held_any.d.next = (self.held_next.val() != self.zero3.val()) | self.r2.q.val();
        // Next cycle's word (read now, `r1`) goes to entry `held_next - 1`
        // if a pop comes with it, else to entry `held_next`.
        self.lp_next.next = self.zero_load.val();
        self.lk_next.next = self.zero_load.val();
        for i in 0..(self._n) {
            if self.r1.q.val() & (self.held_next.val() == self.idx[i].val()) {
                self.lk_next.next = self.lk_next.val() | self.onehot[i].val();
            }
            if self.r1.q.val() & (self.held_next.val() == (self.idx[i].val() + self.one3.val())) {
                self.lp_next.next = self.lp_next.val() | self.onehot[i].val();
            }
        }
        self.lp.d.next = self.lp_next.val();
        self.lk.d.next = self.lk_next.val();
        self.load_pop.next = self.lp.q.val();
        self.load_keep.next = self.lk.q.val();
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
            self.lp.d.next = self.zero_load.val();
            self.lk.d.next = self.zero_load.val();
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
