//! `FccRegControl`: the CONTROL register (RW): IRQ_ENABLE, and the
//! self-clearing SOFT_RESET and CLEAR (they read 0), and the pipeline's
//! reset.
//!
//! `core_rst` (registered) resets the pixel pipeline on `rst` and for one
//! cycle after a write of SOFT_RESET; `core_rst_next` is the same one cycle
//! earlier. CLEAR is held as W is taken, in one kept copy per group of status
//! registers it clears (`clear_count`: FRAME_COUNT, STATUS.FRAME_DONE,
//! CLUSTERS, FRAME_FLAGS; `clear_frame`: PROVISIONAL, UNLABELLED, JOINS;
//! `clear_stalls`: GEAR_STALLS), so no clear enable drives more than 64
//! flip-flops.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::regmap::bits;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRegControl {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The bus adapter.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// A write to CONTROL is performed.
    pub we: Signal<In, Bit>,
    /// The held write data.
    pub wdata: Signal<In, Bits<32>>,
    // Fields.
    pub irq_enable: Signal<Out, Bit>,
    pub clear_count: Signal<Out, Bit>,
    pub clear_frame: Signal<Out, Bit>,
    pub clear_stalls: Signal<Out, Bit>,
    pub core_rst: Signal<Out, Bit>,
    /// `core_rst` one cycle ahead (its flip-flop's input).
    pub core_rst_next: Signal<Out, Bit>,
    irq_en: DFF<Bit>,
    soft_q: DFF<Bit>,
    core_rst_q: DFF<Bit>,
    w_clear_count: FccKeepReg<Bit>,
    w_clear_frame: FccKeepReg<Bit>,
    w_clear_stalls: FccKeepReg<Bit>,
    bit_soft: Constant<Bits<32>>,
    bit_irq: Constant<Bits<32>>,
    bit_clear: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
}

impl FccRegControl {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            we: Default::default(),
            wdata: Default::default(),
            irq_enable: Default::default(),
            clear_count: Default::default(),
            clear_frame: Default::default(),
            clear_stalls: Default::default(),
            core_rst: Default::default(),
            core_rst_next: Default::default(),
            irq_en: Default::default(),
            soft_q: Default::default(),
            core_rst_q: Default::default(),
            w_clear_count: Default::default(),
            w_clear_frame: Default::default(),
            w_clear_stalls: Default::default(),
            bit_soft: kb(u64::from(bits::CONTROL_SOFT_RESET)),
            bit_irq: kb(u64::from(bits::CONTROL_IRQ_ENABLE)),
            bit_clear: kb(u64::from(bits::CONTROL_CLEAR)),
            zero32: kb(0),
        }
    }
}

impl Default for FccRegControl {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccRegControl {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, irq_en, soft_q, core_rst_q);
        self.w_clear_count.clock.next = self.clk.val();
        self.w_clear_frame.clock.next = self.clk.val();
        self.w_clear_stalls.clock.next = self.clk.val();
        self.w_clear_count.d.next = self.w_clear_count.q.val();
        self.w_clear_frame.d.next = self.w_clear_frame.q.val();
        self.w_clear_stalls.d.next = self.w_clear_stalls.q.val();
        if self.w_take.val() {
            self.w_clear_count.d.next =
                (self.bus_wdata.val() & self.bit_clear.val()) != self.zero32.val();
            self.w_clear_frame.d.next =
                (self.bus_wdata.val() & self.bit_clear.val()) != self.zero32.val();
            self.w_clear_stalls.d.next =
                (self.bus_wdata.val() & self.bit_clear.val()) != self.zero32.val();
        }
        self.soft_q.d.next = false;
        if self.we.val() {
            self.irq_en.d.next = (self.wdata.val() & self.bit_irq.val()) != self.zero32.val();
            self.soft_q.d.next = (self.wdata.val() & self.bit_soft.val()) != self.zero32.val();
        }
        self.clear_count.next = self.we.val() & self.w_clear_count.q.val();
        self.clear_frame.next = self.we.val() & self.w_clear_frame.q.val();
        self.clear_stalls.next = self.we.val() & self.w_clear_stalls.q.val();
        // The pipeline's reset: power-on reset or a soft reset.
        self.core_rst_q.d.next = self.rst.val() | self.soft_q.q.val();
        self.core_rst_next.next = self.rst.val() | self.soft_q.q.val();
        if self.rst.val() {
            self.irq_en.d.next = false;
            self.soft_q.d.next = false;
        }
        self.irq_enable.next = self.irq_en.q.val();
        self.core_rst.next = self.core_rst_q.q.val();
    }
}
