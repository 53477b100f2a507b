//! `FccFifo`: a synchronous first-word-fall-through FIFO of `2^A` entries in
//! block RAM (`AP1 = A + 1` pointer bits). `dout` shows the head whenever
//! `empty` is low; `pop` takes it. A pushed entry becomes visible one cycle
//! after the push (the RAM read is registered); `count` counts it at once.

use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccFifo<T: Synth, const A: usize, const AP1: usize> {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Write side.
    pub push: Signal<In, Bit>,
    pub din: Signal<In, T>,
    pub count: Signal<Out, Bits<AP1>>,
    // Read side.
    pub pop: Signal<In, Bit>,
    pub dout: Signal<Out, T>,
    pub empty: Signal<Out, Bit>,
    ram: FccRam<T, A>,
    wp: DFF<Bits<AP1>>,
    wp_d: DFF<Bits<AP1>>,
    rp: DFF<Bits<AP1>>,
    rp_next: Signal<Local, Bits<AP1>>,
    full: Signal<Local, Bit>,
    one: Constant<Bits<AP1>>,
    zero: Constant<Bits<AP1>>,
    full_pattern: Constant<Bits<AP1>>,
}

impl<T: Synth, const A: usize, const AP1: usize> Default for FccFifo<T, A, AP1> {
    fn default() -> Self {
        assert_eq!(AP1, A + 1);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            din: Default::default(),
            full: Default::default(),
            count: Default::default(),
            pop: Default::default(),
            dout: Default::default(),
            empty: Default::default(),
            ram: FccRam::new(1 << A),
            wp: Default::default(),
            wp_d: Default::default(),
            rp: Default::default(),
            rp_next: Default::default(),
            one: kb(1),
            zero: kb(0),
            full_pattern: kb(1 << A),
        }
    }
}

impl<T: Synth, const A: usize, const AP1: usize> Logic for FccFifo<T, A, AP1> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, wp, wp_d, rp);
        self.ram.clk.next = self.clk.val();
        self.empty.next = self.rp.q.val() == self.wp_d.q.val();
        self.full.next = (self.wp.q.val() ^ self.rp.q.val()) == self.full_pattern.val();
        self.count.next = self.wp.q.val() - self.rp.q.val();
        self.rp_next.next = self.rp.q.val();
        if self.pop.val() & !self.empty.val() {
            self.rp_next.next = self.rp.q.val() + self.one.val();
        }
        self.rp.d.next = self.rp_next.val();
        self.ram.read_en.next = true;
        self.ram.read_addr.next = self.rp_next.val().get_bits::<A>(0);
        self.ram.write_en.next = self.push.val() & !self.full.val();
        self.ram.write_addr.next = self.wp.q.val().get_bits::<A>(0);
        self.ram.write_data.next = self.din.val();
        if self.push.val() & !self.full.val() {
            self.wp.d.next = self.wp.q.val() + self.one.val();
        }
        self.wp_d.d.next = self.wp.q.val();
        self.dout.next = self.ram.read_data.val();
        if self.rst.val() {
            self.wp.d.next = self.zero.val();
            self.wp_d.d.next = self.zero.val();
            self.rp.d.next = self.zero.val();
        }
    }
}
