//! `FccRegs`: the AXI4-Lite register file of `fcc_top` (map in `regmap`).
//!
//! Write channel: the address (AW) and the data (W) are each taken into a
//! holding register whenever it is empty (`awready = !aw_v`, `wready =
//! !w_v`), in either order; the write is performed in the cycle after both
//! are held and no response is pending, and its response (always OKAY) is held
//! on B until `bready`. Read channel: `arready = !rvalid`; the addressed word
//! is registered into `rdata` with `rvalid` and held until `rready`. Every
//! output comes from a flip-flop or one gate after flip-flops.
//!
//! Frame status: in the cycle `frame_end` is high (the last label beat
//! leaves) the live counters of the blocks are latched, the frame counter
//! counts, the sticky FRAME_DONE bit is set and, one cycle later,
//! `frame_done` pulses with the latched values already on `st_*`. `irq` is
//! FRAME_DONE and IRQ_ENABLE. `core_rst` (registered) resets the pixel
//! pipeline on `rst` and for one cycle after a write of CONTROL.SOFT_RESET;
//! the register file itself is reset by `rst` only.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_reg_mux::{FccRegMux, MuxSrc, WORD_BITS};
use crate::regmap::{self, bits, offset, ADDR_BITS};
use crate::types::kb;

/// A `MuxSrc::Flags` list from (field mask, flag input) pairs.
fn flags(f: &[(u32, usize)]) -> Vec<Option<usize>> {
    let top = f
        .iter()
        .map(|(m, _)| 32 - m.leading_zeros())
        .max()
        .unwrap_or(0);
    (0..top)
        .map(|b| f.iter().find(|(m, _)| *m == 1 << b).map(|(_, i)| *i))
        .collect()
}

fn word(off: u32) -> Constant<Bits<WORD_BITS>> {
    kb((off / 4) as u64)
}

#[derive(LogicBlock)]
pub struct FccRegs {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // AXI4-Lite slave.
    pub s_axil_awaddr: Signal<In, Bits<ADDR_BITS>>,
    pub s_axil_awvalid: Signal<In, Bit>,
    pub s_axil_awready: Signal<Out, Bit>,
    pub s_axil_wdata: Signal<In, Bits<32>>,
    pub s_axil_wstrb: Signal<In, Bits<4>>,
    pub s_axil_wvalid: Signal<In, Bit>,
    pub s_axil_wready: Signal<Out, Bit>,
    pub s_axil_bresp: Signal<Out, Bits<2>>,
    pub s_axil_bvalid: Signal<Out, Bit>,
    pub s_axil_bready: Signal<In, Bit>,
    pub s_axil_araddr: Signal<In, Bits<ADDR_BITS>>,
    pub s_axil_arvalid: Signal<In, Bit>,
    pub s_axil_arready: Signal<Out, Bit>,
    pub s_axil_rdata: Signal<Out, Bits<32>>,
    pub s_axil_rresp: Signal<Out, Bits<2>>,
    pub s_axil_rvalid: Signal<Out, Bit>,
    pub s_axil_rready: Signal<In, Bit>,
    // From the core: the frame's end and its live counters.
    pub frame_end: Signal<In, Bit>,
    pub idle: Signal<In, Bit>,
    pub clusters: Signal<In, Bits<16>>,
    pub provisional: Signal<In, Bits<16>>,
    pub overflow: Signal<In, Bit>,
    pub unlabelled: Signal<In, Bits<20>>,
    pub frame_error: Signal<In, Bit>,
    pub joins: Signal<In, Bits<24>>,
    pub gear_stalls: Signal<In, Bits<24>>,
    // To the core and the top's ports.
    pub core_rst: Signal<Out, Bit>,
    pub irq: Signal<Out, Bit>,
    pub frame_done: Signal<Out, Bit>,
    pub st_clusters: Signal<Out, Bits<16>>,
    pub st_provisional: Signal<Out, Bits<16>>,
    pub st_overflow: Signal<Out, Bit>,
    pub st_unlabelled: Signal<Out, Bits<20>>,
    pub st_frame_error: Signal<Out, Bit>,
    pub st_joins: Signal<Out, Bits<24>>,
    pub st_gear_stalls: Signal<Out, Bits<24>>,
    mux: FccRegMux,
    // Write channel.
    aw_v: DFF<Bit>,
    aw_a: DFF<Bits<WORD_BITS>>,
    w_v: DFF<Bit>,
    w_d: DFF<Bits<32>>,
    b_v: DFF<Bit>,
    // Read channel.
    r_v: DFF<Bit>,
    r_d: DFF<Bits<32>>,
    // Registers.
    irq_en: DFF<Bit>,
    done_sticky: DFF<Bit>,
    soft_q: DFF<Bit>,
    core_rst_q: DFF<Bit>,
    count: DFF<Bits<32>>,
    done_q: DFF<Bit>,
    s_clusters: DFF<Bits<16>>,
    s_prov: DFF<Bits<16>>,
    s_ovf: DFF<Bit>,
    s_unl: DFF<Bits<20>>,
    s_err: DFF<Bit>,
    s_joins: DFF<Bits<24>>,
    s_gstall: DFF<Bits<24>>,
    wr: Signal<Local, Bit>,
    clear: Signal<Local, Bit>,
    a_control: Constant<Bits<WORD_BITS>>,
    a_status: Constant<Bits<WORD_BITS>>,
    bit_soft: Constant<Bits<32>>,
    bit_irq: Constant<Bits<32>>,
    bit_clear: Constant<Bits<32>>,
    bit_done: Constant<Bits<32>>,
    one32: Constant<Bits<32>>,
    zero32: Constant<Bits<32>>,
    zero16: Constant<Bits<16>>,
    zero20: Constant<Bits<20>>,
    zero24: Constant<Bits<24>>,
    okay: Constant<Bits<2>>,
}

impl FccRegs {
    pub fn new(p: &FccParams) -> Self {
        let mut entries: Vec<(u32, MuxSrc)> = vec![];
        for r in regmap::registers(p) {
            // The inputs are wired in `update` in the same numbering.
            let src = match r.offset {
                offset::FRAME_COUNT => MuxSrc::W32(0),
                offset::CLUSTERS => MuxSrc::W16(0),
                offset::PROVISIONAL => MuxSrc::W16(1),
                offset::UNLABELLED => MuxSrc::W20(0),
                offset::JOINS => MuxSrc::W24(0),
                offset::GEAR_STALLS => MuxSrc::W24(1),
                // Flags: 0 irq_en, 1 done_sticky, 2 idle, 3 overflow, 4 frame_error.
                offset::CONTROL => MuxSrc::Flags(flags(&[(bits::CONTROL_IRQ_ENABLE, 0)])),
                offset::STATUS => MuxSrc::Flags(flags(&[
                    (bits::STATUS_FRAME_DONE, 1),
                    (bits::STATUS_IDLE, 2),
                ])),
                offset::FRAME_FLAGS => MuxSrc::Flags(flags(&[
                    (bits::FLAGS_OVERFLOW, 3),
                    (bits::FLAGS_FRAME_ERROR, 4),
                ])),
                _ => {
                    assert!(r.build_constant, "{} has no source", r.name);
                    MuxSrc::Const(r.reset)
                }
            };
            entries.push((r.offset, src));
        }
        Self {
            clk: Default::default(),
            rst: Default::default(),
            s_axil_awaddr: Default::default(),
            s_axil_awvalid: Default::default(),
            s_axil_awready: Default::default(),
            s_axil_wdata: Default::default(),
            s_axil_wstrb: Default::default(),
            s_axil_wvalid: Default::default(),
            s_axil_wready: Default::default(),
            s_axil_bresp: Default::default(),
            s_axil_bvalid: Default::default(),
            s_axil_bready: Default::default(),
            s_axil_araddr: Default::default(),
            s_axil_arvalid: Default::default(),
            s_axil_arready: Default::default(),
            s_axil_rdata: Default::default(),
            s_axil_rresp: Default::default(),
            s_axil_rvalid: Default::default(),
            s_axil_rready: Default::default(),
            frame_end: Default::default(),
            idle: Default::default(),
            clusters: Default::default(),
            provisional: Default::default(),
            overflow: Default::default(),
            unlabelled: Default::default(),
            frame_error: Default::default(),
            joins: Default::default(),
            gear_stalls: Default::default(),
            core_rst: Default::default(),
            irq: Default::default(),
            frame_done: Default::default(),
            st_clusters: Default::default(),
            st_provisional: Default::default(),
            st_overflow: Default::default(),
            st_unlabelled: Default::default(),
            st_frame_error: Default::default(),
            st_joins: Default::default(),
            st_gear_stalls: Default::default(),
            mux: FccRegMux::new(entries),
            aw_v: Default::default(),
            aw_a: Default::default(),
            w_v: Default::default(),
            w_d: Default::default(),
            b_v: Default::default(),
            r_v: Default::default(),
            r_d: Default::default(),
            irq_en: Default::default(),
            done_sticky: Default::default(),
            soft_q: Default::default(),
            core_rst_q: Default::default(),
            count: Default::default(),
            done_q: Default::default(),
            s_clusters: Default::default(),
            s_prov: Default::default(),
            s_ovf: Default::default(),
            s_unl: Default::default(),
            s_err: Default::default(),
            s_joins: Default::default(),
            s_gstall: Default::default(),
            wr: Default::default(),
            clear: Default::default(),
            a_control: word(offset::CONTROL),
            a_status: word(offset::STATUS),
            bit_soft: kb(u64::from(bits::CONTROL_SOFT_RESET)),
            bit_irq: kb(u64::from(bits::CONTROL_IRQ_ENABLE)),
            bit_clear: kb(u64::from(bits::CONTROL_CLEAR)),
            bit_done: kb(u64::from(bits::STATUS_FRAME_DONE)),
            one32: kb(1),
            zero32: kb(0),
            zero16: kb(0),
            zero20: kb(0),
            zero24: kb(0),
            okay: kb(0),
        }
    }
}

impl Logic for FccRegs {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            aw_v,
            aw_a,
            w_v,
            w_d,
            b_v,
            r_v,
            r_d,
            irq_en,
            done_sticky,
            soft_q,
            core_rst_q,
            count,
            done_q,
            s_clusters,
            s_prov,
            s_ovf,
            s_unl,
            s_err,
            s_joins,
            s_gstall
        );
        // ---- Write channel: AW and W held in either order, then one write.
        self.wr.next = self.aw_v.q.val() & self.w_v.q.val() & !self.b_v.q.val();
        if self.s_axil_awvalid.val() & !self.aw_v.q.val() {
            self.aw_v.d.next = true;
            self.aw_a.d.next = self.s_axil_awaddr.val().get_bits::<WORD_BITS>(2);
        }
        if self.s_axil_wvalid.val() & !self.w_v.q.val() {
            self.w_v.d.next = true;
            self.w_d.d.next = self.s_axil_wdata.val();
        }
        if self.b_v.q.val() & self.s_axil_bready.val() {
            self.b_v.d.next = false;
        }
        self.soft_q.d.next = false;
        self.clear.next = false;
        if self.wr.val() {
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = true;
            if self.aw_a.q.val() == self.a_control.val() {
                self.irq_en.d.next = (self.w_d.q.val() & self.bit_irq.val()) != self.zero32.val();
                self.soft_q.d.next = (self.w_d.q.val() & self.bit_soft.val()) != self.zero32.val();
                self.clear.next = (self.w_d.q.val() & self.bit_clear.val()) != self.zero32.val();
            }
            if (self.aw_a.q.val() == self.a_status.val())
                & ((self.w_d.q.val() & self.bit_done.val()) != self.zero32.val())
            {
                self.done_sticky.d.next = false;
            }
        }
        // ---- Frame end: latch the status, count, set FRAME_DONE.
        self.done_q.d.next = self.frame_end.val();
        if self.frame_end.val() {
            self.done_sticky.d.next = true;
            self.count.d.next = self.count.q.val() + self.one32.val();
            self.s_clusters.d.next = self.clusters.val();
            self.s_prov.d.next = self.provisional.val();
            self.s_ovf.d.next = self.overflow.val();
            self.s_unl.d.next = self.unlabelled.val();
            self.s_err.d.next = self.frame_error.val();
            self.s_joins.d.next = self.joins.val();
            self.s_gstall.d.next = self.gear_stalls.val();
        }
        if self.clear.val() {
            self.done_sticky.d.next = false;
            self.count.d.next = self.zero32.val();
            self.s_clusters.d.next = self.zero16.val();
            self.s_prov.d.next = self.zero16.val();
            self.s_ovf.d.next = false;
            self.s_unl.d.next = self.zero20.val();
            self.s_err.d.next = false;
            self.s_joins.d.next = self.zero24.val();
            self.s_gstall.d.next = self.zero24.val();
        }
        // ---- Read channel.
        self.mux.addr.next = self.s_axil_araddr.val().get_bits::<WORD_BITS>(2);
        self.mux.w32[0].next = self.count.q.val();
        self.mux.w16[0].next = self.s_clusters.q.val();
        self.mux.w16[1].next = self.s_prov.q.val();
        self.mux.w20[0].next = self.s_unl.q.val();
        self.mux.w24[0].next = self.s_joins.q.val();
        self.mux.w24[1].next = self.s_gstall.q.val();
        self.mux.flags[0].next = self.irq_en.q.val();
        self.mux.flags[1].next = self.done_sticky.q.val();
        self.mux.flags[2].next = self.idle.val();
        self.mux.flags[3].next = self.s_ovf.q.val();
        self.mux.flags[4].next = self.s_err.q.val();
        if self.s_axil_arvalid.val() & !self.r_v.q.val() {
            self.r_v.d.next = true;
            self.r_d.d.next = self.mux.data.val();
        }
        if self.r_v.q.val() & self.s_axil_rready.val() {
            self.r_v.d.next = false;
        }
        // ---- Reset of the pipeline: power-on reset or a soft reset.
        self.core_rst_q.d.next = self.rst.val() | self.soft_q.q.val();
        if self.rst.val() {
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = false;
            self.r_v.d.next = false;
            self.irq_en.d.next = false;
            self.done_sticky.d.next = false;
            self.soft_q.d.next = false;
            self.count.d.next = self.zero32.val();
            self.done_q.d.next = false;
            self.s_clusters.d.next = self.zero16.val();
            self.s_prov.d.next = self.zero16.val();
            self.s_ovf.d.next = false;
            self.s_unl.d.next = self.zero20.val();
            self.s_err.d.next = false;
            self.s_joins.d.next = self.zero24.val();
            self.s_gstall.d.next = self.zero24.val();
        }
        // ---- Outputs.
        self.s_axil_awready.next = !self.aw_v.q.val();
        self.s_axil_wready.next = !self.w_v.q.val();
        self.s_axil_bvalid.next = self.b_v.q.val();
        self.s_axil_bresp.next = self.okay.val();
        self.s_axil_arready.next = !self.r_v.q.val();
        self.s_axil_rvalid.next = self.r_v.q.val();
        self.s_axil_rdata.next = self.r_d.q.val();
        self.s_axil_rresp.next = self.okay.val();
        self.core_rst.next = self.core_rst_q.q.val();
        self.irq.next = self.done_sticky.q.val() & self.irq_en.q.val();
        self.frame_done.next = self.done_q.q.val();
        self.st_clusters.next = self.s_clusters.q.val();
        self.st_provisional.next = self.s_prov.q.val();
        self.st_overflow.next = self.s_ovf.q.val();
        self.st_unlabelled.next = self.s_unl.q.val();
        self.st_frame_error.next = self.s_err.q.val();
        self.st_joins.next = self.s_joins.q.val();
        self.st_gear_stalls.next = self.s_gstall.q.val();
    }
}
