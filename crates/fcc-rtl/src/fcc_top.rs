//! `fcc_top`: the FCC core. AXI4-Stream pixels in, AXI4-Stream labels out.
//!
//! Input beat (64-bit `s_axis_tdata`, one pixel, raster order, `tlast` on the
//! frame's last pixel): bits 15:0 x, 31:16 y, 47:32 z (Q7.8 two's complement),
//! bit 48 valid (1 = the pixel holds a point), bits 63:49 reserved (ignored).
//!
//! Frame control: a `tlast` before the frame's last pixel ends the frame early
//! (the remaining pixels count as empty); a missing `tlast` on the last pixel
//! makes the core drop the following beats up to and including the next
//! `tlast`. Either sets `status_frame_error` for that frame, whose labels are
//! still emitted in full; the next frame needs no reset.
//!
//! Phases of a frame: RUN (one pixel per cycle through intra -> window ->
//! distance tree -> sort network -> centre buffer -> union engine), DRAIN (the
//! last joins are merged), OUT (flatten and read-back run together). After a
//! reset the core first initialises the merge table (INIT).
//!
//! Flow control: the front end (input stage to the centre buffer) never
//! stalls. Every pixel slot taken holds a credit until the sort network either
//! drops it (no record needed) or takes its record out of the centre buffer;
//! `s_axis_tready` is a register that is high while fewer than `CREDITS`
//! credits are out, so the buffer can never overflow and no enable fans out
//! across the pipeline.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_credits::FccCredits;
use crate::fcc_dist_tree::FccDistTree;
use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_frame_phase::FccFramePhase;
use crate::fcc_input_stage::FccInputStage;
use crate::fcc_intra::FccIntra;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_label_update::FccLabelUpdate;
use crate::fcc_merge_table::FccMergeTable;
use crate::fcc_pix_thr::FccPixThr;
use crate::fcc_regs::FccRegs;
use crate::fcc_sort_net::FccSortNet;
use crate::fcc_thr_window::FccThrWindow;
use crate::fcc_window::FccWindow;
use crate::regmap::ADDR_BITS;

pub use crate::fcc_credits::CREDITS;

#[derive(LogicBlock)]
pub struct FccTop {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // AXI4-Stream slave: pixels.
    pub s_axis_tdata: Signal<In, Bits<64>>,
    /// Ignored (every beat is one whole pixel); present so that an AXI DMA's
    /// MM2S stream connects without a validation warning.
    pub s_axis_tkeep: Signal<In, Bits<8>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    // AXI4-Stream master: labels.
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
    /// One-cycle pulse when the frame's last label beat is accepted.
    pub status_frame_done: Signal<Out, Bit>,
    /// The core is waiting for the first pixel of a frame.
    pub status_idle: Signal<Out, Bit>,
    pix_thr: FccPixThr,
    intra: FccIntra,
    window: FccWindow,
    thr_window: FccThrWindow,
    dist_tree: FccDistTree,
    sort_net: FccSortNet,
    merge_table: FccMergeTable,
    label_update: FccLabelUpdate,
    regs: FccRegs,
    // The pipeline's reset tree: one copy of the register file's `core_rst`
    // per block (the top's own registers use `core_rst` itself; `sort_net`
    // and `label_update` make their own copies from `core_rst_next`).
    intra_rst: FccKeepReg<Bit>,
    window_rst: FccKeepReg<Bit>,
    dist_tree_rst: FccKeepReg<Bit>,
    merge_table_rst: FccKeepReg<Bit>,
    in_stage: FccInputStage,
    credits: FccCredits,
    phase: FccFramePhase,
}

impl FccTop {
    /// Build the core for `p`. The caller validates `p` for hardware first.
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
            pix_thr: FccPixThr::new(),
            intra: FccIntra::new(p),
            window: FccWindow::new(p),
            thr_window: FccThrWindow::new(p),
            dist_tree: FccDistTree::new(p),
            sort_net: FccSortNet::new(p),
            merge_table: FccMergeTable::new(p),
            label_update: FccLabelUpdate::new(p),
            regs: FccRegs::new(p),
            intra_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            window_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            dist_tree_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            merge_table_rst: FccKeepReg::with_max_fanout(MAX_FANOUT),
            in_stage: Default::default(),
            credits: Default::default(),
            phase: Default::default(),
        }
    }
}

impl Logic for FccTop {
    #[hdl_gen]
    fn update(&mut self) {
        self.in_stage.clk.next = self.clk.val();
        self.credits.clk.next = self.clk.val();
        self.phase.clk.next = self.clk.val();
        self.pix_thr.clk.next = self.clk.val();
        self.intra.clk.next = self.clk.val();
        self.window.clk.next = self.clk.val();
        self.thr_window.clk.next = self.clk.val();
        self.dist_tree.clk.next = self.clk.val();
        self.sort_net.clk.next = self.clk.val();
        self.merge_table.clk.next = self.clk.val();
        self.label_update.clk.next = self.clk.val();
        self.regs.clk.next = self.clk.val();
        // ---- Register file; the pipeline's reset is its `core_rst`.
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
        self.regs.clusters.next = self.merge_table.clusters.val();
        self.regs.provisional.next = self.intra.provisional.val().get_bits::<16>(0);
        self.regs.overflow.next = self.intra.overflow.val();
        self.regs.unlabelled.next = self.intra.unlabelled.val();
        self.regs.frame_error.next = self.in_stage.err.val();
        self.regs.joins.next = self.sort_net.joins.val();
        self.regs.gear_stalls.next = self.label_update.gear_stalls.val();
        // The register file registers the phase flags it needs from their
        // next-cycle values.
        self.regs.frame_sent.next = self.label_update.rb_done.val();
        self.regs.out_next.next = self.phase.out_next.val();
        self.regs.idle_next.next = self.in_stage.idle_next.val();
        // ---- Input stage, credits and frame phase (the top's own
        // registers, reset by `core_rst` itself).
        self.in_stage.rst.next = self.regs.core_rst.val();
        self.in_stage.rst_next.next = self.regs.core_rst_next.val();
        self.in_stage.s_axis_tdata.next = self.s_axis_tdata.val().get_bits::<49>(0);
        self.in_stage.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.in_stage.s_axis_tlast.next = self.s_axis_tlast.val();
        self.s_axis_tready.next = self.in_stage.s_axis_tready.val();
        self.in_stage.run_rows.next = self.regs.run_rows.val();
        self.in_stage.run_cols.next = self.regs.run_cols.val().get_bits::<12>(0);
        self.in_stage.run.next = self.phase.run.val();
        self.in_stage.restart.next = self.phase.restart.val();
        self.in_stage.run_next.next = self.phase.run_next.val();
        self.in_stage.room.next = self.credits.room.val();
        // Raster order: no column waits.
        self.in_stage.col_hold.next = false;
        self.credits.rst.next = self.regs.core_rst.val();
        self.credits.slot.next = self.in_stage.slot_now.val();
        self.credits.drop.next = self.sort_net.drop.val();
        self.credits.take.next = self.sort_net.take.val();
        self.phase.rst.next = self.regs.core_rst.val();
        self.phase.in_done.next = self.in_stage.in_done.val();
        self.phase.init_busy.next = self.merge_table.init_busy.val();
        self.phase.last_done.next = self.sort_net.last_done.val();
        self.phase.union_idle.next = self.merge_table.union_idle.val();
        self.phase.jq_empty.next = self.sort_net.jq_empty.val();
        self.phase.rb_done.next = self.label_update.rb_done.val();
        self.merge_table.flat_start.next = self.phase.out_start.val();
        self.label_update.rb_start.next = self.phase.out_start.val();
        // ---- Reset tree: each copy is `core_rst`'s flip-flop again (same
        // input, same cycle), so every block leaves reset in the same cycle.
        self.intra_rst.clock.next = self.clk.val();
        self.window_rst.clock.next = self.clk.val();
        self.dist_tree_rst.clock.next = self.clk.val();
        self.merge_table_rst.clock.next = self.clk.val();
        self.intra_rst.d.next = self.regs.core_rst_next.val();
        self.window_rst.d.next = self.regs.core_rst_next.val();
        self.dist_tree_rst.d.next = self.regs.core_rst_next.val();
        self.merge_table_rst.d.next = self.regs.core_rst_next.val();
        // ---- Blocks.
        self.pix_thr.rst.next = self.intra_rst.q.val();
        self.pix_thr.pix.next = self.in_stage.slot.val();
        self.pix_thr.sh.next = self.regs.run_sl_h.val();
        self.pix_thr.sv.next = self.regs.run_sl_v.val();
        self.pix_thr.ch_t.next = self.regs.run_th_h_c.val();
        self.pix_thr.cv_t.next = self.regs.run_th_v_c.val();
        self.intra.rst.next = self.intra_rst.q.val();
        self.intra.pix.next = self.pix_thr.out.val();
        self.intra.key.next = self.pix_thr.key.val();
        self.intra.ch.next = self.pix_thr.ch.val();
        self.intra.last_col.next = self.in_stage.last_col.val();
        self.window.last_col.next = self.in_stage.last_col.val();
        self.window.rst.next = self.window_rst.q.val();
        self.window.run_k.next = self.regs.run_k.val();
        self.window.inp.next = self.intra.out.val();
        self.window.rep_we.next = self.sort_net.rep_we.val();
        self.window.rep_waddr.next = self.sort_net.rep_waddr.val();
        self.window.rep_wdata.next = self.sort_net.rep_wdata.val();
        self.dist_tree.rst.next = self.dist_tree_rst.q.val();
        self.thr_window.rst.next = self.window_rst.q.val();
        self.thr_window.valid.next = self.intra.out.val().valid;
        self.thr_window.col.next = self.intra.out.val().col;
        self.thr_window.rdcol.next = self.intra.out.val().rdcol;
        self.thr_window.key.next = self.pix_thr.key.val();
        self.thr_window.cv.next = self.pix_thr.cv.val();
        self.dist_tree.centre_key.next = self.thr_window.centre_key.val();
        self.dist_tree.centre_cv.next = self.thr_window.centre_cv.val();
        self.dist_tree.centre_in.next = self.window.centre.val();
        for e in 0..self.window.ent_ok.len() {
            self.dist_tree.ent_ok[e].next = self.window.ent_ok[e].val();
            self.dist_tree.ent_x[e].next = self.window.ent_x[e].val();
            self.dist_tree.ent_y[e].next = self.window.ent_y[e].val();
            self.dist_tree.ent_z[e].next = self.window.ent_z[e].val();
            self.dist_tree.ent_key[e].next = self.thr_window.ent_key[e].val();
            self.dist_tree.ent_cv[e].next = self.thr_window.ent_cv[e].val();
            self.sort_net.hit[e].next = self.dist_tree.hit[e].val();
            self.sort_net.rep[e].next = self.window.ent_rep[e].val();
        }
        // `sort_net` registers its sub-blocks' copies itself.
        self.sort_net.rst.next = self.regs.core_rst_next.val();
        self.sort_net.clear.next = self.label_update.rb_done.val();
        self.sort_net.centre.next = self.dist_tree.centre.val();
        self.sort_net.jtake.next = self.merge_table.jtake.val();
        self.merge_table.rst.next = self.merge_table_rst.q.val();
        self.merge_table.jv.next = self.sort_net.jv.val();
        self.merge_table.ja.next = self.sort_net.ja.val();
        self.merge_table.jb.next = self.sort_net.jb.val();
        self.merge_table.jsame.next = self.sort_net.jsame.val();
        self.merge_table.provisional.next = self.intra.provisional.val();
        self.merge_table.gear_used.next = self.label_update.gear_used.val();
        self.label_update.rst.next = self.regs.core_rst_next.val();
        self.label_update.wr_valid.next = self.intra.out.val().valid;
        self.label_update.wr_state.next = self.intra.state.val();
        self.label_update.wr_last.next = self.intra.out.val().last;
        self.label_update.fv.next = self.merge_table.fv.val();
        self.label_update.fval.next = self.merge_table.fval.val();
        self.label_update.m_axis_tready.next = self.m_axis_tready.val();
        self.m_axis_tdata.next = self.label_update.m_axis_tdata.val();
        self.m_axis_tkeep.next = self.label_update.m_axis_tkeep.val();
        self.m_axis_tvalid.next = self.label_update.m_axis_tvalid.val();
        self.m_axis_tlast.next = self.label_update.m_axis_tlast.val();
        self.status_clusters.next = self.regs.st_clusters.val();
        self.status_provisional.next = self.regs.st_provisional.val();
        self.status_overflow.next = self.regs.st_overflow.val();
        self.status_unlabelled.next = self.regs.st_unlabelled.val();
        self.status_frame_error.next = self.regs.st_frame_error.val();
        self.status_joins.next = self.regs.st_joins.val();
        self.status_gear_stalls.next = self.regs.st_gear_stalls.val();
        self.status_frame_done.next = self.regs.frame_done.val();
        self.status_idle.next = self.in_stage.idle.val();
    }
}
