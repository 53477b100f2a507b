//! `FccFifo`: a synchronous first-word-fall-through FIFO of `2^A` entries in
//! block RAM (`AP1 = A + 1` pointer bits), registered on both sides.
//!
//! Write side: `push` writes `din` (the caller makes sure there is room). Read side: `valid` and `dout` come straight from
//! flip-flops (the RAM's fabric output register); `take` accepts the head.
//! The RAM is read two cycles ahead, so after a `take` the next entry shows
//! two cycles later: at most one entry every other cycle leaves the FIFO,
//! which is as fast as its users (the join serializer and the union engine)
//! consume. The RAM's ports are
//! outputs too, so that side RAMs (`FccRam` of the same depth) can hold more
//! fields of each entry and show them beside `dout`.
//!
//! The pointers, the read in flight, the output's flag and the read issue
//! are built for Vivado to replicate (`FccFanoutReg`, `FccFanoutNet`): in
//! LUT RAM a wide entry makes each of them reach every word's bits.

use rust_hdl::prelude::*;

use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccFifo<T: Synth, const A: usize, const AP1: usize> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Write side.
    pub push: Signal<In, Bit>,
    pub din: Signal<In, T>,
    // Read side.
    pub valid: Signal<Out, Bit>,
    pub dout: Signal<Out, T>,
    pub take: Signal<In, Bit>,
    /// Entries written and not yet taken, one cycle late (registered).
    pub level: Signal<Out, Bits<AP1>>,
    // The RAM's ports, for side RAMs that hold more of each entry.
    pub ram_re: Signal<Out, Bit>,
    pub ram_raddr: Signal<Out, Bits<A>>,
    pub ram_we: Signal<Out, Bit>,
    pub ram_waddr: Signal<Out, Bits<A>>,
    ram: FccRam<T, A>,
    wp: FccFanoutReg<Bits<AP1>>,
    rp: FccFanoutReg<Bits<AP1>>,
    tp: DFF<Bits<AP1>>,
    level_q: DFF<Bits<AP1>>,
    r1: FccFanoutReg<Bit>,
    ov: FccFanoutReg<Bit>,
    empty: Signal<Local, Bit>,
    issue: Signal<Local, Bit>,
    /// `issue`, replicated by Vivado (it reaches many loads).
    issue_net: FccFanoutNet<Bit>,
    one: Constant<Bits<AP1>>,
    zero: Constant<Bits<AP1>>,
}

impl<T: Synth, const A: usize, const AP1: usize> FccFifo<T, A, AP1> {
    /// A FIFO storing the low `stored_bits` bits of each entry.
    pub fn with_stored_bits(stored_bits: usize) -> Self {
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
            ram_re: Default::default(),
            ram_raddr: Default::default(),
            ram_we: Default::default(),
            ram_waddr: Default::default(),
            ram: FccRam::with_stored_bits(1 << A, stored_bits),
            wp: Default::default(),
            rp: Default::default(),
            tp: Default::default(),
            level_q: Default::default(),
            r1: Default::default(),
            ov: Default::default(),
            empty: Default::default(),
            issue: Default::default(),
            issue_net: Default::default(),
            one: kb(1),
            zero: kb(0),
        }
    }
}

impl<T: Synth, const A: usize, const AP1: usize> FccFifo<T, A, AP1> {
    /// Its entries in LUT RAM (`FccRam::in_lut_ram`).
    pub fn in_lut_ram(mut self) -> Self {
        self.ram = self.ram.in_lut_ram();
        self
    }
}

impl<T: Synth, const A: usize, const AP1: usize> Default for FccFifo<T, A, AP1> {
    fn default() -> Self {
        Self::with_stored_bits(T::BITS)
    }
}

impl<T: Synth, const A: usize, const AP1: usize> Logic for FccFifo<T, A, AP1> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, wp, rp, tp, level_q, r1, ov);
        self.ram.clk.next = self.clk.val();
        // A word written in cycle t is in the RAM for a read issued in t+1.
        self.empty.next = self.rp.q.val() == self.wp.q.val();
        // At most one read in flight, and only into a free output register.
        self.issue.next =
            !self.empty.val() & !self.r1.q.val() & (!self.ov.q.val() | self.take.val());
        self.issue_net.x.next = self.issue.val();
        self.ram.read_en.next = self.issue_net.y.val();
        self.ram.read_addr.next = self.rp.q.val().get_bits::<A>(0);
        if self.issue_net.y.val() {
            self.rp.d.next = self.rp.q.val() + self.one.val();
        }
        self.r1.d.next = self.issue_net.y.val();
        self.ov.d.next = self.r1.q.val() | (self.ov.q.val() & !self.take.val());
        self.ram.write_en.next = self.push.val();
        self.ram.write_addr.next = self.wp.q.val().get_bits::<A>(0);
        self.ram.write_data.next = self.din.val();
        if self.push.val() {
            self.wp.d.next = self.wp.q.val() + self.one.val();
        }
        if self.ov.q.val() & self.take.val() {
            self.tp.d.next = self.tp.q.val() + self.one.val();
        }
        self.level_q.d.next = self.wp.q.val() - self.tp.q.val();
        self.level.next = self.level_q.q.val();
        self.ram_re.next = self.issue_net.y.val();
        self.ram_raddr.next = self.rp.q.val().get_bits::<A>(0);
        self.ram_we.next = self.push.val();
        self.ram_waddr.next = self.wp.q.val().get_bits::<A>(0);
        self.valid.next = self.ov.q.val();
        self.dout.next = self.ram.read_data.val();
        if self.rst.val() {
            self.wp.d.next = self.zero.val();
            self.rp.d.next = self.zero.val();
            self.tp.d.next = self.zero.val();
            self.level_q.d.next = self.zero.val();
            self.r1.d.next = false;
            self.ov.d.next = false;
        }
    }
}
