//! `FccStreamFifo`: a first-word-fall-through FIFO of `2^A` entries in
//! block RAM (`AP1 = A + 1` pointer bits) that gives an entry every cycle.
//!
//! `FccFifo` keeps one read in flight, so after a `take` its next entry
//! shows two cycles later. This one reads the RAM every cycle while it has
//! entries not yet read and room ahead: the words read wait in
//! [`AHEAD`](crate::fcc_stream_ctl::AHEAD) flip-flop entries (the head in entry 0: `valid`, `dout`). Its control
//! (`FccStreamCtl`) and its words (`FccStreamLane`) are blocks of their
//! own, so that a FIFO of several lanes (`FccColSlotBuf`) shares one
//! control.
//!
//! Write side: `push` writes `din` (the caller makes sure there is room:
//! `level`, registered, counts the entries pushed and not yet taken, one
//! cycle late). A word pushed at cycle `t` shows at `t + 4` at the soonest.

use rust_hdl::prelude::*;

use crate::fcc_stream_ctl::FccStreamCtl;
use crate::fcc_stream_lane::FccStreamLane;

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
    ctl: FccStreamCtl<A, AP1>,
    lane: FccStreamLane<T, A>,
}

impl<T: Synth, const A: usize, const AP1: usize> Default for FccStreamFifo<T, A, AP1> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            din: Default::default(),
            valid: Default::default(),
            dout: Default::default(),
            take: Default::default(),
            level: Default::default(),
            ctl: Default::default(),
            lane: Default::default(),
        }
    }
}

impl<T: Synth, const A: usize, const AP1: usize> Logic for FccStreamFifo<T, A, AP1> {
    #[hdl_gen]
    fn update(&mut self) {
        self.ctl.clk.next = self.clk.val();
        self.ctl.rst.next = self.rst.val();
        self.ctl.push.next = self.push.val();
        self.ctl.take.next = self.take.val();
        self.valid.next = self.ctl.valid.val();
        self.level.next = self.ctl.level.val();
        self.lane.clk.next = self.clk.val();
        self.lane.we.next = self.push.val();
        self.lane.waddr.next = self.ctl.ram_waddr.val();
        self.lane.din.next = self.din.val();
        self.lane.re.next = self.ctl.ram_re.val();
        self.lane.raddr.next = self.ctl.ram_raddr.val();
        self.lane.shift.next = self.ctl.shift.val();
        self.lane.load.next = self.ctl.load.val();
        self.dout.next = self.lane.dout.val();
    }
}
