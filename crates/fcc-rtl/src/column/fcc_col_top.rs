//! `fcc_top` of the column-streaming core (`fcc gen --scan column`,
//! docs/column-core.md): the same ports, register file and pixel beats as
//! the row-major `FccTop`, with the frame in column order in and one record
//! per cluster out as it closes, then an end beat per frame (spec §9.4).
//!
//! Input beat (64-bit `s_axis_tdata`, one pixel, column order: rows
//! `0 .. R-1` of column 0, then of column 1, ...; `tlast` on the frame's
//! last pixel): bits 15:0 x, 31:16 y, 47:32 z (Q7.8), bit 48 valid, bits
//! 63:49 ignored. Early and late `tlast` as in the row-major core: the
//! frame's end beat has `frame_error` set.
//!
//! Output: 64-bit beats, `tkeep` all ones; a record is 11 beats, the end
//! beat has `tlast` (one frame is one packet).
//!
//! The register file is `FccRegs` with the column core's map (its stream
//! limits RUN_BRIDGE, RUN_RING_REACH, RUN_OPEN_LIMIT); the frame status is
//! taken from the end beat (`FccColStats`); the run registers load only
//! while the core is idle and quiet (`FccColFlow`), and `FccColLimits`
//! turns them into the datapath's form. This block is wiring.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_core::FccColCore;
use super::fcc_col_flow::FccColFlow;
use super::fcc_col_limits::FccColLimits;
use super::fcc_col_stats::FccColStats;
use crate::fcc_regs::FccRegs;
use crate::regmap::ADDR_BITS;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColTop {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // AXI4-Stream slave: pixels, in column order.
    pub s_axis_tdata: Signal<In, Bits<64>>,
    /// Ignored (every beat is one whole pixel); present so that an AXI DMA's
    /// MM2S stream connects without a validation warning.
    pub s_axis_tkeep: Signal<In, Bits<8>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    // AXI4-Stream master: records (spec §9.4).
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tkeep: Signal<Out, Bits<8>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    // AXI4-Lite slave: the register file (map in `regmap`).
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
    /// Level-high interrupt: STATUS.FRAME_DONE while CONTROL.IRQ_ENABLE.
    pub irq: Signal<Out, Bit>,
    // Status of the last completed frame (stable from `status_frame_done`).
    pub status_clusters: Signal<Out, Bits<16>>,
    pub status_provisional: Signal<Out, Bits<16>>,
    pub status_overflow: Signal<Out, Bit>,
    pub status_unlabelled: Signal<Out, Bits<20>>,
    pub status_frame_error: Signal<Out, Bit>,
    pub status_joins: Signal<Out, Bits<24>>,
    pub status_gear_stalls: Signal<Out, Bits<24>>,
    /// One-cycle pulse when the frame's end beat is accepted.
    pub status_frame_done: Signal<Out, Bit>,
    /// The core is waiting for the first pixel of a frame, and every frame
    /// before has sent its end beat.
    pub status_idle: Signal<Out, Bit>,
    regs: FccRegs,
    limits: FccColLimits,
    core: FccColCore,
    flow: FccColFlow,
    stats: FccColStats,
    /// An end beat is taken.
    end_sent: Signal<Local, Bit>,
    keep_all: Constant<Bits<8>>,
    zero20: Constant<Bits<20>>,
    zero24: Constant<Bits<24>>,
}

impl FccColTop {
    /// Build the core for `p` (validated for hardware, `scan` column).
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            s_axis_tdata: Default::default(),
            s_axis_tkeep: Default::default(),
            s_axis_tvalid: Default::default(),
            s_axis_tready: Default::default(),
            s_axis_tlast: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tkeep: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tready: Default::default(),
            m_axis_tlast: Default::default(),
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
            irq: Default::default(),
            status_clusters: Default::default(),
            status_provisional: Default::default(),
            status_overflow: Default::default(),
            status_unlabelled: Default::default(),
            status_frame_error: Default::default(),
            status_joins: Default::default(),
            status_gear_stalls: Default::default(),
            status_frame_done: Default::default(),
            status_idle: Default::default(),
            regs: FccRegs::new(p),
            limits: Default::default(),
            core: FccColCore::new(p),
            flow: Default::default(),
            stats: FccColStats::new(p),
            end_sent: Default::default(),
            keep_all: kb(0xFF),
            zero20: kb(0),
            zero24: kb(0),
        }
    }
}

impl Logic for FccColTop {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- Register file; the datapath's reset is its `core_rst`.
        self.regs.clk.next = self.clk.val();
        self.regs.rst.next = self.rst.val();
        self.regs.s_axil_awaddr.next = self.s_axil_awaddr.val();
        self.regs.s_axil_awvalid.next = self.s_axil_awvalid.val();
        self.regs.s_axil_wdata.next = self.s_axil_wdata.val();
        self.regs.s_axil_wstrb.next = self.s_axil_wstrb.val();
        self.regs.s_axil_wvalid.next = self.s_axil_wvalid.val();
        self.regs.s_axil_bready.next = self.s_axil_bready.val();
        self.regs.s_axil_araddr.next = self.s_axil_araddr.val();
        self.regs.s_axil_arvalid.next = self.s_axil_arvalid.val();
        self.regs.s_axil_rready.next = self.s_axil_rready.val();
        self.s_axil_awready.next = self.regs.s_axil_awready.val();
        self.s_axil_wready.next = self.regs.s_axil_wready.val();
        self.s_axil_bresp.next = self.regs.s_axil_bresp.val();
        self.s_axil_bvalid.next = self.regs.s_axil_bvalid.val();
        self.s_axil_arready.next = self.regs.s_axil_arready.val();
        self.s_axil_rdata.next = self.regs.s_axil_rdata.val();
        self.s_axil_rresp.next = self.regs.s_axil_rresp.val();
        self.s_axil_rvalid.next = self.regs.s_axil_rvalid.val();
        self.irq.next = self.regs.irq.val();
        // The frame status, snapshot as the end beat leaves (any cycle: the
        // core has no output phase).
        self.end_sent.next =
            self.core.m_axis_tvalid.val() & self.m_axis_tready.val() & self.core.m_axis_tlast.val();
        self.regs.frame_sent.next = self.end_sent.val();
        self.regs.out_next.next = true;
        self.regs.idle_next.next = self.flow.load_next.val();
        self.regs.clusters.next = self.stats.clusters.val();
        self.regs.provisional.next = self.stats.provisional.val();
        self.regs.overflow.next = self.stats.overflow.val();
        self.regs.unlabelled.next = self.zero20.val();
        self.regs.frame_error.next = self.stats.frame_error.val();
        self.regs.joins.next = self.zero24.val();
        self.regs.gear_stalls.next = self.stats.held.val();
        // ---- The run parameters in the datapath's form.
        self.limits.clk.next = self.clk.val();
        self.limits.run_rows.next = self.regs.run_rows.val().get_bits::<7>(0);
        self.limits.run_cols.next = self.regs.run_cols.val();
        self.limits.half_k.next = self.regs.run_k.val().get_bits::<3>(1);
        self.limits.bridge.next = self.regs.run_lims[0].val();
        self.limits.ring_reach.next = self.regs.run_lims[1].val();
        self.limits.open_limit.next = self.regs.run_lims[2].val();
        // ---- Frame sequence and status.
        self.flow.clk.next = self.clk.val();
        self.flow.rst.next = self.regs.core_rst.val();
        self.flow.in_done.next = self.core.in_done.val();
        self.flow.idle.next = self.core.idle.val();
        self.flow.idle_next.next = self.core.idle_next.val();
        self.flow.end_sent.next = self.end_sent.val();
        self.flow.written.next = self.regs.written[0].val();
        self.stats.clk.next = self.clk.val();
        self.stats.rst.next = self.regs.core_rst.val();
        self.stats.end_sent.next = self.end_sent.val();
        self.stats.end_word.next = self.core.m_axis_tdata.val().get_bits::<22>(20);
        self.stats.labels_free.next = self.core.labels_free.val();
        self.stats.col_held.next = self.core.col_held.val();
        // ---- The datapath.
        self.core.clk.next = self.clk.val();
        self.core.rst.next = self.regs.core_rst.val() | self.flow.reload.val();
        self.core.rst_next.next = self.regs.core_rst_next.val() | self.flow.reload_next.val();
        self.core.s_axis_tdata.next = self.s_axis_tdata.val().get_bits::<49>(0);
        self.core.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.core.s_axis_tlast.next = self.s_axis_tlast.val();
        self.s_axis_tready.next = self.core.s_axis_tready.val();
        self.core.run.next = true;
        self.core.run_next.next = true;
        self.core.start_hold.next = self.flow.start_hold.val();
        self.core.restart.next = self.flow.restart.val();
        self.core.run_rows.next = self.regs.run_rows.val();
        self.core.run_cols.next = self.limits.cols.val();
        self.core.last_row.next = self.limits.last_row.val();
        self.core.last_col.next = self.limits.last_col.val();
        self.core.col_half.next = self.limits.col_half.val();
        self.core.run_k.next = self.regs.run_k.val();
        self.core.h.next = self.limits.h.val();
        self.core.sh.next = self.regs.run_sl_h.val();
        self.core.sv.next = self.regs.run_sl_v.val();
        self.core.ch_t.next = self.regs.run_th_h_c.val();
        self.core.cv_t.next = self.regs.run_th_v_c.val();
        self.core.reach.next = self.limits.reach.val();
        self.core.ring_on.next = self.limits.ring_on.val();
        self.core.ring_f_max.next = self.limits.ring_f_max.val();
        self.core.ring_l_min.next = self.limits.ring_l_min.val();
        self.core.n_o.next = self.limits.n_o.val();
        self.m_axis_tdata.next = self.core.m_axis_tdata.val();
        self.m_axis_tkeep.next = self.keep_all.val();
        self.m_axis_tvalid.next = self.core.m_axis_tvalid.val();
        self.m_axis_tlast.next = self.core.m_axis_tlast.val();
        self.core.m_axis_tready.next = self.m_axis_tready.val();
        // ---- Status ports.
        self.status_clusters.next = self.regs.st_clusters.val();
        self.status_provisional.next = self.regs.st_provisional.val();
        self.status_overflow.next = self.regs.st_overflow.val();
        self.status_unlabelled.next = self.regs.st_unlabelled.val();
        self.status_frame_error.next = self.regs.st_frame_error.val();
        self.status_joins.next = self.regs.st_joins.val();
        self.status_gear_stalls.next = self.regs.st_gear_stalls.val();
        self.status_frame_done.next = self.regs.frame_done.val();
        self.status_idle.next = self.flow.quiet.val() & self.core.idle.val();
    }
}
