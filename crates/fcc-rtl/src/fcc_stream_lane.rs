//! `FccStreamLane`: the words of a stream FIFO lane, moved by its control
//! (`FccStreamCtl`): a RAM of `2^A` words and [`AHEAD`] flip-flop entries
//! ahead of it, the head in entry 0 (`dout`).
//!
//! A push (`we`) writes `din` at `waddr`; a read (`re`, `raddr`) gives its
//! word two cycles later, which the entry `load` names takes (bit `i + 1`
//! names entry `i` with `shift`, bit `i` without); `shift` moves each entry
//! up to the one before it (the head is taken). The lanes of one FIFO take
//! the same control, so they stay in step.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_ram::FccRam;
use crate::fcc_stream_ctl::{AHEAD, LOAD};
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccStreamLane<T: Synth, const A: usize> {
    pub clk: Signal<In, Clock>,
    pub we: Signal<In, Bit>,
    pub waddr: Signal<In, Bits<A>>,
    pub din: Signal<In, T>,
    pub re: Signal<In, Bit>,
    pub raddr: Signal<In, Bits<A>>,
    pub shift: Signal<In, Bit>,
    pub load: Signal<In, Bits<LOAD>>,
    /// The head's word.
    pub dout: Signal<Out, T>,
    ram: FccRam<T, A>,
    ahead: Vec<FccFanoutReg<T>>,
    _n: usize,
}

impl<T: Synth, const A: usize> Default for FccStreamLane<T, A> {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            we: Default::default(),
            waddr: Default::default(),
            din: Default::default(),
            re: Default::default(),
            raddr: Default::default(),
            shift: Default::default(),
            load: Default::default(),
            dout: Default::default(),
            ram: FccRam::new(1 << A),
            ahead: vec_of(AHEAD),
            _n: AHEAD,
        }
    }
}

impl<T: Synth, const A: usize> Logic for FccStreamLane<T, A> {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..(self._n) {
            self.ahead[i].clock.next = self.clk.val();
            self.ahead[i].d.next = self.ahead[i].q.val();
        }
        self.ram.clk.next = self.clk.val();
        self.ram.read_en.next = self.re.val();
        self.ram.read_addr.next = self.raddr.val();
        self.ram.write_en.next = self.we.val();
        self.ram.write_addr.next = self.waddr.val();
        self.ram.write_data.next = self.din.val();
        for i in 0..(self._n - 1) {
            if self.shift.val() {
                self.ahead[i].d.next = self.ahead[i + 1].q.val();
            }
        }
        for i in 0..(self._n) {
            if (self.shift.val() & self.load.val().get_bit(i + 1))
                | (!self.shift.val() & self.load.val().get_bit(i))
            {
                self.ahead[i].d.next = self.ram.read_data.val();
            }
        }
        self.dout.next = self.ahead[0].q.val();
    }
}
