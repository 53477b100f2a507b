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

use crate::fcc_dist_tree::FccDistTree;
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_intra::FccIntra;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_label_update::FccLabelUpdate;
use crate::fcc_merge_table::FccMergeTable;
use crate::fcc_pix_thr::FccPixThr;
use crate::fcc_regs::FccRegs;
use crate::fcc_sort_net::{FccSortNet, CB_BITS};
use crate::fcc_thr_window::FccThrWindow;
use crate::fcc_window::FccWindow;
use crate::regmap::ADDR_BITS;
use crate::types::{kb, Pix};

/// Pixel slots that may be between the input and the centre buffer's output:
/// the buffer's size less a margin for the registered `s_axis_tready`.
pub const CREDITS: usize = (1 << CB_BITS) - 16;

/// Phase of a frame (see the module doc).
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum Phase {
    /// After reset, until the merge table is initialised.
    Init,
    /// Pixels are taken.
    Run,
    /// The frame's pixels are in; the last joins are merged.
    Drain,
    /// Flatten and read-back: the frame's labels leave.
    Out,
}

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
    phase: DFF<Phase>,
    tready_q: DFF<Bit>,
    pad_go: DFF<Bit>,
    slot_q: DFF<Pix>,
    row: DFF<Bits<8>>,
    col: DFF<Bits<12>>,
    col0: DFF<Bit>,
    col_last: DFF<Bit>,
    row_last: DFF<Bit>,
    first: DFF<Bit>,
    pad: DFF<Bit>,
    discard: DFF<Bit>,
    in_done: DFF<Bit>,
    err: DFF<Bit>,
    credits: DFF<Bits<10>>,
    room: DFF<Bit>,
    last_seen: DFF<Bit>,
    /// Run size of the frame: `run_cols - 1`, `run_cols - 2`, `run_rows - 2`,
    /// `run_rows == 1`.
    last_col: DFF<Bits<12>>,
    pen_col: DFF<Bits<12>>,
    pen_row: DFF<Bits<8>>,
    one_row: DFF<Bit>,
    // Combinational.
    /// Rows and columns of the frame (the run registers).
    run_rows: Signal<Local, Bits<8>>,
    run_cols: Signal<Local, Bits<13>>,
    accept: Signal<Local, Bit>,
    beat: Signal<Local, Bit>,
    slot: Signal<Local, Bit>,
    is_last: Signal<Local, Bit>,
    nxt_pad: Signal<Local, Bit>,
    nxt_discard: Signal<Local, Bit>,
    nxt_in_done: Signal<Local, Bit>,
    nxt_run: Signal<Local, Bit>,
    drained: Signal<Local, Bit>,
    /// The output phase starts: flatten and the read-back start (one net
    /// that reaches some 90 registers at K = 11; Vivado replicates it).
    out_start: Signal<Local, Bit>,
    out_start_net: FccFanoutNet<Bit>,
    // Constants.
    sign16: Constant<Bits<16>>,
    zero8: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
    zero12: Constant<Bits<12>>,
    one12: Constant<Bits<12>>,
    two8: Constant<Bits<8>>,
    two12: Constant<Bits<12>>,
    one10: Constant<Bits<10>>,
    two10: Constant<Bits<10>>,
    zero10: Constant<Bits<10>>,
    limit: Constant<Bits<10>>,
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
            phase: Default::default(),
            tready_q: Default::default(),
            pad_go: Default::default(),
            slot_q: Default::default(),
            row: Default::default(),
            col: Default::default(),
            col0: Default::default(),
            col_last: Default::default(),
            row_last: Default::default(),
            first: Default::default(),
            pad: Default::default(),
            discard: Default::default(),
            in_done: Default::default(),
            err: Default::default(),
            credits: Default::default(),
            room: Default::default(),
            last_seen: Default::default(),
            last_col: Default::default(),
            pen_col: Default::default(),
            pen_row: Default::default(),
            one_row: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            accept: Default::default(),
            beat: Default::default(),
            slot: Default::default(),
            is_last: Default::default(),
            nxt_pad: Default::default(),
            nxt_discard: Default::default(),
            nxt_in_done: Default::default(),
            nxt_run: Default::default(),
            drained: Default::default(),
            out_start: Default::default(),
            out_start_net: Default::default(),
            sign16: kb(0x8000),
            zero8: kb(0),
            one8: kb(1),
            zero12: kb(0),
            one12: kb(1),
            two8: kb(2),
            two12: kb(2),
            one10: kb(1),
            two10: kb(2),
            zero10: kb(0),
            limit: kb(CREDITS as u64),
        }
    }
}

impl Logic for FccTop {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, phase, tready_q, pad_go, slot_q, row, col, col0, col_last, row_last, first,
            pad, discard, in_done, err, credits, room, last_seen, last_col, pen_col, pen_row,
            one_row
        );
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
        self.regs.frame_error.next = self.err.q.val();
        self.regs.joins.next = self.sort_net.joins.val();
        self.regs.gear_stalls.next = self.label_update.gear_stalls.val();
        // ---- Run size of the frame (stable while a frame runs); derived
        // values registered, so the counters compare with flip-flops.
        self.run_rows.next = self.regs.run_rows.val();
        self.run_cols.next = self.regs.run_cols.val();
        // Modulo 4096: C = 4096 has C - 1 = 4095 in 12 bits.
        self.last_col.d.next = self.run_cols.val().get_bits::<12>(0) - self.one12.val();
        self.pen_col.d.next = self.run_cols.val().get_bits::<12>(0) - self.two12.val();
        self.pen_row.d.next = self.run_rows.val() - self.two8.val();
        self.one_row.d.next = self.run_rows.val() == self.one8.val();
        // ---- Input stage: pixel slots, padding of a short frame, dropping of a long one.
        self.accept.next = self.s_axis_tvalid.val() & self.tready_q.q.val();
        self.beat.next = self.accept.val() & !self.discard.q.val();
        self.slot.next = self.beat.val() | self.pad_go.q.val();
        self.is_last.next = self.col_last.q.val() & self.row_last.q.val();
        self.slot_q.d.next.valid = self.slot.val();
        self.slot_q.d.next.ok = self.beat.val() & self.s_axis_tdata.val().get_bit(48);
        self.slot_q.d.next.x = self.s_axis_tdata.val().get_bits::<16>(0) ^ self.sign16.val();
        self.slot_q.d.next.y = self.s_axis_tdata.val().get_bits::<16>(16) ^ self.sign16.val();
        self.slot_q.d.next.z = self.s_axis_tdata.val().get_bits::<16>(32) ^ self.sign16.val();
        self.slot_q.d.next.row = self.row.q.val();
        self.slot_q.d.next.col = self.col.q.val();
        self.slot_q.d.next.first = self.first.q.val();
        self.slot_q.d.next.last = self.is_last.val();
        self.slot_q.d.next.col0 = self.col0.q.val();
        self.slot_q.d.next.coln = self.col_last.q.val();
        self.nxt_pad.next = self.pad.q.val();
        self.nxt_discard.next = self.discard.q.val();
        self.nxt_in_done.next = self.in_done.q.val();
        // Row 0 is the last row of a one-row frame. The run registers may
        // change up to the frame's first pixel; `one_row` follows them two
        // cycles later, long before row 0's last pixel (C >= 3).
        if self.row.q.val() == self.zero8.val() {
            self.row_last.d.next = self.one_row.q.val();
        }
        if self.slot.val() {
            self.first.d.next = false;
            self.col0.d.next = self.col_last.q.val();
            self.col.d.next = self.col.q.val() + self.one12.val();
            self.col_last.d.next = self.col.q.val() == self.pen_col.q.val();
            if self.col_last.q.val() {
                self.col.d.next = self.zero12.val();
                self.col_last.d.next = false;
                self.row.d.next = self.row.q.val() + self.one8.val();
                self.row_last.d.next = self.row.q.val() == self.pen_row.q.val();
            }
            if self.is_last.val() {
                self.row.d.next = self.zero8.val();
                self.row_last.d.next = self.one_row.q.val();
                self.first.d.next = true;
                self.nxt_in_done.next = true;
                self.nxt_pad.next = false;
            }
        }
        if self.beat.val() {
            if self.s_axis_tlast.val() & !self.is_last.val() {
                self.err.d.next = true;
                self.nxt_pad.next = true;
            }
            if self.is_last.val() & !self.s_axis_tlast.val() {
                self.err.d.next = true;
                self.nxt_discard.next = true;
            }
        }
        if self.discard.q.val() & self.accept.val() & self.s_axis_tlast.val() {
            self.nxt_discard.next = false;
        }
        // ---- Credits: one per slot, returned by the sort network.
        self.credits.d.next = self.credits.q.val();
        if self.slot.val() {
            self.credits.d.next = self.credits.q.val() + self.one10.val();
            if self.sort_net.drop.val() ^ self.sort_net.take.val() {
                self.credits.d.next = self.credits.q.val();
            }
            if self.sort_net.drop.val() & self.sort_net.take.val() {
                self.credits.d.next = self.credits.q.val() - self.one10.val();
            }
        } else {
            if self.sort_net.drop.val() ^ self.sort_net.take.val() {
                self.credits.d.next = self.credits.q.val() - self.one10.val();
            }
            if self.sort_net.drop.val() & self.sort_net.take.val() {
                self.credits.d.next = self.credits.q.val() - self.two10.val();
            }
        }
        self.room.d.next = self.credits.q.val() < self.limit.val();
        // ---- Frame phases.
        if self.sort_net.last_done.val() {
            self.last_seen.d.next = true;
        }
        self.drained.next = self.last_seen.q.val()
            & self.merge_table.union_idle.val()
            & self.sort_net.jq_empty.val();
        self.out_start.next = false;
        if (self.phase.q.val() == Phase::Init) & !self.merge_table.init_busy.val() {
            self.phase.d.next = Phase::Run;
        }
        if (self.phase.q.val() == Phase::Run) & self.in_done.q.val() {
            self.phase.d.next = Phase::Drain;
        }
        if (self.phase.q.val() == Phase::Drain) & self.drained.val() {
            self.out_start.next = true;
            self.phase.d.next = Phase::Out;
        }
        self.out_start_net.x.next = self.out_start.val();
        self.merge_table.flat_start.next = self.out_start_net.y.val();
        self.label_update.rb_start.next = self.out_start_net.y.val();
        self.nxt_run.next = self.phase.q.val() == Phase::Run;
        if (self.phase.q.val() == Phase::Out) & self.label_update.rb_done.val() {
            self.phase.d.next = Phase::Run;
            self.nxt_run.next = true;
            self.nxt_in_done.next = false;
            self.last_seen.d.next = false;
            self.err.d.next = false;
        }
        self.pad.d.next = self.nxt_pad.val();
        self.discard.d.next = self.nxt_discard.val();
        self.in_done.d.next = self.nxt_in_done.val();
        // Next cycle's ready and padding slot, from registers and this cycle's events.
        self.tready_q.d.next = self.nxt_discard.val()
            | (self.nxt_run.val()
                & !self.nxt_in_done.val()
                & !self.nxt_pad.val()
                & self.room.q.val());
        self.pad_go.d.next =
            self.nxt_pad.val() & self.nxt_run.val() & !self.nxt_in_done.val() & self.room.q.val();
        // The pipeline's reset is one cycle behind `rst` and the soft reset:
        // `s_axis_tready` goes low in the cycle before it, so a beat offered
        // right after a short reset waits instead of being taken and lost.
        if self.regs.core_rst_next.val() {
            self.tready_q.d.next = false;
            self.pad_go.d.next = false;
        }
        if self.regs.core_rst.val() {
            self.phase.d.next = Phase::Init;
            self.tready_q.d.next = false;
            self.pad_go.d.next = false;
            self.slot_q.d.next.valid = false;
            self.row.d.next = self.zero8.val();
            self.col.d.next = self.zero12.val();
            self.col0.d.next = true;
            self.col_last.d.next = false;
            self.row_last.d.next = false;
            self.first.d.next = true;
            self.pad.d.next = false;
            self.discard.d.next = false;
            self.in_done.d.next = false;
            self.err.d.next = false;
            self.credits.d.next = self.zero10.val();
            self.room.d.next = true;
            self.last_seen.d.next = false;
        }
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
        self.pix_thr.pix.next = self.slot_q.q.val();
        self.pix_thr.sh.next = self.regs.run_sl_h.val();
        self.pix_thr.sv.next = self.regs.run_sl_v.val();
        self.pix_thr.ch_t.next = self.regs.run_th_h_c.val();
        self.pix_thr.cv_t.next = self.regs.run_th_v_c.val();
        self.intra.rst.next = self.intra_rst.q.val();
        self.intra.pix.next = self.pix_thr.out.val();
        self.intra.key.next = self.pix_thr.key.val();
        self.intra.ch.next = self.pix_thr.ch.val();
        self.intra.last_col.next = self.last_col.q.val();
        self.window.last_col.next = self.last_col.q.val();
        self.window.rst.next = self.window_rst.q.val();
        self.window.run_k.next = self.regs.run_k.val();
        self.window.inp.next.valid = self.intra.out.val().valid;
        self.window.inp.next.lok = self.intra.out.val().lok;
        self.window.inp.next.x = self.intra.out.val().x;
        self.window.inp.next.y = self.intra.out.val().y;
        self.window.inp.next.z = self.intra.out.val().z;
        self.window.inp.next.label = self.intra.out.val().label;
        self.window.inp.next.row = self.intra.out.val().row;
        self.window.inp.next.col = self.intra.out.val().col;
        self.window.inp.next.rdcol = self.intra.out.val().rdcol;
        self.window.inp.next.last = self.intra.out.val().last;
        self.window.inp.next.ring = self.intra.out.val().ring;
        self.window.inp.next.ring_a = self.intra.out.val().ring_a;
        self.window.inp.next.ring_b = self.intra.out.val().ring_b;
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
        self.label_update.wr_state.next = self.intra.out.val().state;
        self.label_update.wr_last.next = self.intra.out.val().last;
        self.label_update.fv.next = self.merge_table.fv.val();
        self.label_update.fval.next = self.merge_table.fval.val();
        self.label_update.m_axis_tready.next = self.m_axis_tready.val();
        self.m_axis_tdata.next = self.label_update.m_axis_tdata.val();
        self.m_axis_tkeep.next = self.label_update.m_axis_tkeep.val();
        self.m_axis_tvalid.next = self.label_update.m_axis_tvalid.val();
        self.m_axis_tlast.next = self.label_update.m_axis_tlast.val();
        self.s_axis_tready.next = self.tready_q.q.val();
        self.status_clusters.next = self.regs.st_clusters.val();
        self.status_provisional.next = self.regs.st_provisional.val();
        self.status_overflow.next = self.regs.st_overflow.val();
        self.status_unlabelled.next = self.regs.st_unlabelled.val();
        self.status_frame_error.next = self.regs.st_frame_error.val();
        self.status_joins.next = self.regs.st_joins.val();
        self.status_gear_stalls.next = self.regs.st_gear_stalls.val();
        self.status_frame_done.next = self.regs.frame_done.val();
        self.status_idle.next =
            (self.phase.q.val() == Phase::Run) & !self.in_done.q.val() & self.first.q.val();
        // The register file registers the phase flags it needs from their
        // next-cycle values (the flip-flops' inputs, final here).
        self.regs.frame_sent.next = self.label_update.rb_done.val();
        self.regs.out_next.next = self.phase.d.val() == Phase::Out;
        self.regs.idle_next.next =
            (self.phase.d.val() == Phase::Run) & !self.in_done.d.val() & self.first.d.val();
    }
}
