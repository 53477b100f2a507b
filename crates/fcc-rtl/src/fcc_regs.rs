//! `FccRegs`: the AXI4-Lite register file of `fcc_top`, built from its map
//! (`regmap::registers`) as OpenTitan's register tops are: a bus adapter
//! (`FccAxilAdapter`: handshakes, address decode, one write-enable per
//! writable register, the read's address and data), one field block per
//! register of its access type, and the read multiplexer (`FccRegMux`). This
//! block only wires them.
//!
//! | Register | Access | Block |
//! |---|---|---|
//! | CONTROL | RW, self-clearing bits | `FccRegControl` (also the pipeline's reset) |
//! | STATUS.FRAME_DONE | W1C, sticky | `FccRegW1c` in `FccRegFrameStatus` |
//! | FRAME_COUNT | RO counter | `FccRegCounter` in `FccRegFrameStatus` |
//! | CLUSTERS .. GEAR_STALLS | RO, latched at the frame's end | `FccRegSnapshot` in `FccRegFrameStatus` |
//! | RUN_K, RUN_ROWS, RUN_COLS | RW, range-checked, shadow and active copy | `FccRegRun` in `FccRegRunParams` |
//! | RUN_TH_H, RUN_TH_V, RUN_SLOPE_H, RUN_SLOPE_V | the same, squared by a shared squarer | `FccRegSquared` in `FccRegThresholds` in `FccRegRunParams` |
//! | ERROR | W1C, sticky, set by a refused write | `FccRegW1c` in `FccRegRunParams` |
//! | STATUS.IDLE | RO | the core's idle flag, registered in `FccRegRunParams` |
//! | build constants | RO | literals of the multiplexer |
//!
//! The write-enable of each writable register, its reset value, its range
//! and the bit of every field are taken from the map; a writable register
//! of the map that no field block serves is an error at elaboration.
//!
//! Frame status (`FccRegFrameStatus`): latched in the cycle the frame's
//! last label beat leaves, with FRAME_DONE set; `frame_done` pulses one cycle
//! later. `irq` is FRAME_DONE and IRQ_ENABLE. The register file itself is
//! reset by `rst` only; its run registers (shadow and active) one cycle
//! later, from kept copies of `rst` (`FccRegRunParams`), and `arready` is
//! low in that cycle, so no read is taken before they are reset. A read
//! offered in the first cycle after `rst` falls is taken one cycle later.
//! The core's phase flags come one cycle early (`out_next`, `idle_next`) and
//! are registered in kept copies in the blocks that use them, one per group
//! of at most 64 loads, so that neither the frame end nor idle is one net of
//! a hundred enables.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_axil_adapter::FccAxilAdapter;
use crate::fcc_reg_control::FccRegControl;
use crate::fcc_reg_frame_status::FccRegFrameStatus;
use crate::fcc_reg_mux::{FccRegMux, MuxSrc};
use crate::fcc_reg_run_params::{find, FccRegRunParams};
use crate::fcc_reg_stream_limits::FccRegStreamLimits;
use crate::regmap::{self, bits, offset, Access, ADDR_BITS};

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
    /// The frame's last label beat is accepted (a frame end in phase Out).
    pub frame_sent: Signal<In, Bit>,
    /// The core is in phase Out in the next cycle.
    pub out_next: Signal<In, Bit>,
    /// The core waits for a frame's first pixel in the next cycle.
    pub idle_next: Signal<In, Bit>,
    pub clusters: Signal<In, Bits<16>>,
    pub provisional: Signal<In, Bits<16>>,
    pub overflow: Signal<In, Bit>,
    pub unlabelled: Signal<In, Bits<20>>,
    pub frame_error: Signal<In, Bit>,
    pub joins: Signal<In, Bits<24>>,
    pub gear_stalls: Signal<In, Bits<24>>,
    // To the core and the top's ports.
    pub core_rst: Signal<Out, Bit>,
    /// `core_rst` one cycle ahead (its flip-flop's input): lets the top drop
    /// `s_axis_tready` before the pipeline's reset cycle, so no beat is
    /// taken while the pipeline is in reset.
    pub core_rst_next: Signal<Out, Bit>,
    pub irq: Signal<Out, Bit>,
    /// A write to any register is performed (the column core's frame
    /// sequence waits for its run registers to load).
    /// (A column core's map only.)
    pub written: Vec<Signal<Out, Bit>>,
    pub frame_done: Signal<Out, Bit>,
    pub st_clusters: Signal<Out, Bits<16>>,
    pub st_provisional: Signal<Out, Bits<16>>,
    pub st_overflow: Signal<Out, Bit>,
    pub st_unlabelled: Signal<Out, Bits<20>>,
    pub st_frame_error: Signal<Out, Bit>,
    pub st_joins: Signal<Out, Bits<24>>,
    pub st_gear_stalls: Signal<Out, Bits<24>>,
    // Active run parameters (constant during a frame).
    pub run_k: Signal<Out, Bits<4>>,
    /// -(tH^2 + 1), 36-bit two's complement.
    pub run_th_h_c: Signal<Out, Bits<36>>,
    /// -tV^2, 36-bit two's complement.
    pub run_th_v_c: Signal<Out, Bits<36>>,
    pub run_rows: Signal<Out, Bits<8>>,
    pub run_cols: Signal<Out, Bits<13>>,
    /// Squared threshold slopes `A^2 >> 8` (UQ0.24, spec §2).
    pub run_sl_h: Signal<Out, Bits<24>>,
    pub run_sl_v: Signal<Out, Bits<24>>,
    /// The column core's stream limits (active; none in a row-major
    /// build): RUN_BRIDGE, RUN_RING_REACH, RUN_OPEN_LIMIT (9 bits).
    pub run_lims: Vec<Signal<Out, Bits<12>>>,
    bus: FccAxilAdapter,
    mux: FccRegMux,
    // Field blocks.
    control: FccRegControl,
    frame_status: FccRegFrameStatus,
    run: FccRegRunParams,
    /// RUN_BRIDGE, RUN_RING_REACH, RUN_OPEN_LIMIT: one block in a column
    /// core's map, none in a row-major one.
    lims: Vec<FccRegStreamLimits>,
    // The position of each writable register among the bus adapter's
    // write-enables, in the map.
    _we_control: usize,
    _we_status: usize,
    _we_error: usize,
    _we_k: usize,
    _we_th_h: usize,
    _we_th_v: usize,
    _we_rows: usize,
    _we_cols: usize,
    _we_sl_h: usize,
    _we_sl_v: usize,
    // The stream limits' write-enables (`lims` empty: never read).
    _we_bridge: usize,
    _we_reach: usize,
    _we_open: usize,
}

impl FccRegs {
    pub fn new(p: &FccParams) -> Self {
        let regs = regmap::registers(p);
        let column = regs.iter().any(|r| r.offset == offset::RUN_BRIDGE);
        let mut entries: Vec<(u32, MuxSrc)> = vec![];
        for r in &regs {
            // The inputs are wired in `update` in the same numbering.
            let src = match r.offset {
                offset::FRAME_COUNT => MuxSrc::W32(0),
                offset::CLUSTERS => MuxSrc::W16(0),
                offset::PROVISIONAL => MuxSrc::W16(1),
                offset::UNLABELLED => MuxSrc::W20(0),
                offset::JOINS => MuxSrc::W24(0),
                offset::GEAR_STALLS => MuxSrc::W24(1),
                // Read back: the shadow values.
                offset::RUN_K => MuxSrc::W16(2),
                offset::RUN_TH_H => MuxSrc::W16(3),
                offset::RUN_TH_V => MuxSrc::W16(4),
                offset::RUN_ROWS => MuxSrc::W16(5),
                offset::RUN_COLS => MuxSrc::W16(6),
                offset::RUN_SLOPE_H => MuxSrc::W16(7),
                offset::RUN_SLOPE_V => MuxSrc::W16(8),
                offset::RUN_BRIDGE => MuxSrc::W16(9),
                offset::RUN_RING_REACH => MuxSrc::W16(10),
                offset::RUN_OPEN_LIMIT => MuxSrc::W16(11),
                // Flags: 0 irq_en, 1 done_sticky, 2 idle, 3 overflow,
                // 4 frame_error, 5 .. 11 the ERROR bits, 12 .. 14 the
                // stream limits' ERROR bits (a column core's).
                offset::ERROR => MuxSrc::Flags(flags(
                    &[
                        (bits::ERROR_K, 5),
                        (bits::ERROR_TH_H, 6),
                        (bits::ERROR_TH_V, 7),
                        (bits::ERROR_ROWS, 8),
                        (bits::ERROR_COLS, 9),
                        (bits::ERROR_SLOPE_H, 10),
                        (bits::ERROR_SLOPE_V, 11),
                        (bits::ERROR_BRIDGE, 12),
                        (bits::ERROR_RING_REACH, 13),
                        (bits::ERROR_OPEN_LIMIT, 14),
                    ][..if column { 10 } else { 7 }],
                )),
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
        // The bus adapter's write-enables: every writable register of the
        // map, in map order; each must be served by a field block below.
        let writable = regmap::writable_offsets(p);
        let served = [
            offset::CONTROL,
            offset::STATUS,
            offset::ERROR,
            offset::RUN_K,
            offset::RUN_TH_H,
            offset::RUN_TH_V,
            offset::RUN_ROWS,
            offset::RUN_COLS,
            offset::RUN_SLOPE_H,
            offset::RUN_SLOPE_V,
            offset::RUN_BRIDGE,
            offset::RUN_RING_REACH,
            offset::RUN_OPEN_LIMIT,
        ];
        for off in &writable {
            assert!(served.contains(off), "no field block serves {off:#x}");
        }
        let we = |off: u32| {
            writable
                .iter()
                .position(|a| *a == off)
                .unwrap_or_else(|| panic!("{off:#x} is not writable in the map"))
        };
        // The W1C registers' bits, from their fields (STATUS.IDLE is
        // read-only status, not sticky).
        find(&regs, offset::CONTROL, Access::ReadWrite);
        find(&regs, offset::ERROR, Access::WriteOneToClear);
        let status = find(&regs, offset::STATUS, Access::WriteOneToClear);
        let done_lsb = status
            .fields
            .iter()
            .find(|f| f.name == "FRAME_DONE" && 1 << f.lsb == bits::STATUS_FRAME_DONE)
            .expect("STATUS.FRAME_DONE")
            .lsb;
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
            frame_sent: Default::default(),
            out_next: Default::default(),
            idle_next: Default::default(),
            clusters: Default::default(),
            provisional: Default::default(),
            overflow: Default::default(),
            unlabelled: Default::default(),
            frame_error: Default::default(),
            joins: Default::default(),
            gear_stalls: Default::default(),
            core_rst: Default::default(),
            core_rst_next: Default::default(),
            irq: Default::default(),
            written: (0..if column { 1 } else { 0 })
                .map(|_| Default::default())
                .collect(),
            frame_done: Default::default(),
            st_clusters: Default::default(),
            st_provisional: Default::default(),
            st_overflow: Default::default(),
            st_unlabelled: Default::default(),
            st_frame_error: Default::default(),
            st_joins: Default::default(),
            st_gear_stalls: Default::default(),
            run_k: Default::default(),
            run_th_h_c: Default::default(),
            run_th_v_c: Default::default(),
            run_rows: Default::default(),
            run_cols: Default::default(),
            run_sl_h: Default::default(),
            run_sl_v: Default::default(),
            run_lims: (0..if column { 3 } else { 0 })
                .map(|_| Default::default())
                .collect(),
            bus: FccAxilAdapter::new(&writable),
            mux: FccRegMux::new(entries),
            control: FccRegControl::new(),
            frame_status: FccRegFrameStatus::new(done_lsb),
            run: FccRegRunParams::new(&regs),
            lims: if column {
                vec![FccRegStreamLimits::new(&regs)]
            } else {
                vec![]
            },
            _we_control: we(offset::CONTROL),
            _we_status: we(offset::STATUS),
            _we_error: we(offset::ERROR),
            _we_k: we(offset::RUN_K),
            _we_th_h: we(offset::RUN_TH_H),
            _we_th_v: we(offset::RUN_TH_V),
            _we_rows: we(offset::RUN_ROWS),
            _we_cols: we(offset::RUN_COLS),
            _we_sl_h: we(offset::RUN_SLOPE_H),
            _we_sl_v: we(offset::RUN_SLOPE_V),
            _we_bridge: if column { we(offset::RUN_BRIDGE) } else { 0 },
            _we_reach: if column {
                we(offset::RUN_RING_REACH)
            } else {
                0
            },
            _we_open: if column {
                we(offset::RUN_OPEN_LIMIT)
            } else {
                0
            },
        }
    }
}

impl Logic for FccRegs {
    #[hdl_gen]
    fn update(&mut self) {
        // ---- The bus adapter.
        self.bus.clk.next = self.clk.val();
        self.bus.rst.next = self.rst.val();
        self.bus.s_axil_awaddr.next = self.s_axil_awaddr.val();
        self.bus.s_axil_awvalid.next = self.s_axil_awvalid.val();
        self.bus.s_axil_wdata.next = self.s_axil_wdata.val();
        self.bus.s_axil_wvalid.next = self.s_axil_wvalid.val();
        self.bus.s_axil_bready.next = self.s_axil_bready.val();
        self.bus.s_axil_araddr.next = self.s_axil_araddr.val();
        self.bus.s_axil_arvalid.next = self.s_axil_arvalid.val();
        self.bus.s_axil_rready.next = self.s_axil_rready.val();
        self.s_axil_awready.next = self.bus.s_axil_awready.val();
        self.s_axil_wready.next = self.bus.s_axil_wready.val();
        self.s_axil_bresp.next = self.bus.s_axil_bresp.val();
        self.s_axil_bvalid.next = self.bus.s_axil_bvalid.val();
        self.s_axil_arready.next = self.bus.s_axil_arready.val();
        self.s_axil_rdata.next = self.bus.s_axil_rdata.val();
        self.s_axil_rresp.next = self.bus.s_axil_rresp.val();
        self.s_axil_rvalid.next = self.bus.s_axil_rvalid.val();
        // A threshold write is answered when its square is ready: no write
        // is performed while the squarer starts or runs.
        self.bus.hold.next = self.run.hold.val();
        self.bus.defer.next = self.run.defer.val();
        self.bus.done.next = self.run.done.val();
        // No read is taken while the run registers are still in reset.
        self.bus.read_block.next = self.run.read_block.val();
        self.bus.read_data.next = self.mux.data.val();
        // ---- CONTROL and the pipeline's reset.
        self.control.clk.next = self.clk.val();
        self.control.rst.next = self.rst.val();
        self.control.w_take.next = self.bus.w_take.val();
        self.control.bus_wdata.next = self.s_axil_wdata.val();
        self.control.wdata.next = self.bus.wdata.val();
        for w in self._we_control..(self._we_control + 1) {
            self.control.we.next = self.bus.we[w].val();
        }
        self.core_rst.next = self.control.core_rst.val();
        self.core_rst_next.next = self.control.core_rst_next.val();
        // ---- Frame status.
        self.frame_status.clk.next = self.clk.val();
        self.frame_status.rst.next = self.rst.val();
        self.frame_status.frame_sent.next = self.frame_sent.val();
        self.frame_status.out_next.next = self.out_next.val();
        self.frame_status.clusters.next = self.clusters.val();
        self.frame_status.provisional.next = self.provisional.val();
        self.frame_status.overflow.next = self.overflow.val();
        self.frame_status.unlabelled.next = self.unlabelled.val();
        self.frame_status.frame_error.next = self.frame_error.val();
        self.frame_status.joins.next = self.joins.val();
        self.frame_status.gear_stalls.next = self.gear_stalls.val();
        self.frame_status.wdata.next = self.bus.wdata.val();
        for w in self._we_status..(self._we_status + 1) {
            self.frame_status.we_status.next = self.bus.we[w].val();
        }
        self.frame_status.clear_count.next = self.control.clear_count.val();
        self.frame_status.clear_frame.next = self.control.clear_frame.val();
        self.frame_status.clear_stalls.next = self.control.clear_stalls.val();
        // ---- Run parameters and ERROR.
        self.run.clk.next = self.clk.val();
        self.run.rst.next = self.rst.val();
        self.run.w_take.next = self.bus.w_take.val();
        self.run.bus_wdata.next = self.s_axil_wdata.val();
        self.run.wr.next = self.bus.wr.val();
        self.run.wdata.next = self.bus.wdata.val();
        self.run.idle_next.next = self.idle_next.val();
        for w in self._we_error..(self._we_error + 1) {
            self.run.we_error.next = self.bus.we[w].val();
        }
        for w in self._we_k..(self._we_k + 1) {
            self.run.we_k.next = self.bus.we[w].val();
        }
        for w in self._we_th_h..(self._we_th_h + 1) {
            self.run.we_th_h.next = self.bus.we[w].val();
        }
        for w in self._we_th_v..(self._we_th_v + 1) {
            self.run.we_th_v.next = self.bus.we[w].val();
        }
        for w in self._we_rows..(self._we_rows + 1) {
            self.run.we_rows.next = self.bus.we[w].val();
        }
        for w in self._we_cols..(self._we_cols + 1) {
            self.run.we_cols.next = self.bus.we[w].val();
        }
        for w in self._we_sl_h..(self._we_sl_h + 1) {
            self.run.we_sl_h.next = self.bus.we[w].val();
        }
        for w in self._we_sl_v..(self._we_sl_v + 1) {
            self.run.we_sl_v.next = self.bus.we[w].val();
        }
        // ---- The stream limits (a column core's; the loop binds the
        // write-enables' positions).
        for l in 0..self.lims.len() {
            self.lims[l].clk.next = self.clk.val();
            self.lims[l].rst.next = self.rst.val();
            self.lims[l].w_take.next = self.bus.w_take.val();
            self.lims[l].bus_wdata.next = self.s_axil_wdata.val();
            self.lims[l].wdata.next = self.bus.wdata.val();
            self.lims[l].idle_next.next = self.idle_next.val();
            for w in self._we_error..(self._we_error + 1) {
                self.lims[l].we_error.next = self.bus.we[w].val();
            }
            for w in self._we_bridge..(self._we_bridge + 1) {
                self.lims[l].we_bridge.next = self.bus.we[w].val();
            }
            for w in self._we_reach..(self._we_reach + 1) {
                self.lims[l].we_reach.next = self.bus.we[w].val();
            }
            for w in self._we_open..(self._we_open + 1) {
                self.lims[l].we_open.next = self.bus.we[w].val();
            }
            self.mux.flags[12].next = self.lims[l].err_bridge.val();
            self.mux.flags[13].next = self.lims[l].err_reach.val();
            self.mux.flags[14].next = self.lims[l].err_open.val();
            self.mux.w16[9].next = self.lims[l].shadow_bridge.val();
            self.mux.w16[10].next = self.lims[l].shadow_reach.val();
            self.mux.w16[11].next = self.lims[l].shadow_open.val();
            self.run_lims[0].next = self.lims[l].run_bridge.val();
            self.run_lims[1].next = self.lims[l].run_reach.val();
            self.run_lims[2].next = self.lims[l].run_open.val();
            self.written[0].next = self.bus.wr.val();
        }
        // ---- Read multiplexer (inputs numbered as in `new`).
        self.mux.flags[5].next = self.run.err_k.val();
        self.mux.flags[6].next = self.run.err_th_h.val();
        self.mux.flags[7].next = self.run.err_th_v.val();
        self.mux.flags[8].next = self.run.err_rows.val();
        self.mux.flags[9].next = self.run.err_cols.val();
        self.mux.flags[10].next = self.run.err_sl_h.val();
        self.mux.flags[11].next = self.run.err_sl_v.val();
        self.mux.addr.next = self.bus.raddr.val();
        self.mux.addr_hi.next = self.bus.raddr_hi.val();
        self.mux.w32[0].next = self.frame_status.count.val();
        self.mux.w16[0].next = self.frame_status.st_clusters.val();
        self.mux.w16[1].next = self.frame_status.st_provisional.val();
        self.mux.w20[0].next = self.frame_status.st_unlabelled.val();
        self.mux.w24[0].next = self.frame_status.st_joins.val();
        self.mux.w24[1].next = self.frame_status.st_gear_stalls.val();
        self.mux.flags[0].next = self.control.irq_enable.val();
        self.mux.flags[1].next = self.frame_status.done.val();
        self.mux.flags[2].next = self.run.idle.val();
        self.mux.flags[3].next = self.frame_status.st_overflow.val();
        self.mux.flags[4].next = self.frame_status.st_frame_error.val();
        self.mux.w16[2].next = self.run.shadow_k.val();
        self.mux.w16[3].next = self.run.shadow_th_h.val();
        self.mux.w16[4].next = self.run.shadow_th_v.val();
        self.mux.w16[5].next = self.run.shadow_rows.val();
        self.mux.w16[6].next = self.run.shadow_cols.val();
        self.mux.w16[7].next = self.run.shadow_sl_h.val();
        self.mux.w16[8].next = self.run.shadow_sl_v.val();
        // ---- Outputs.
        self.irq.next = self.frame_status.done.val() & self.control.irq_enable.val();
        self.frame_done.next = self.frame_status.frame_done.val();
        self.st_clusters.next = self.frame_status.st_clusters.val();
        self.st_provisional.next = self.frame_status.st_provisional.val();
        self.st_overflow.next = self.frame_status.st_overflow.val();
        self.st_unlabelled.next = self.frame_status.st_unlabelled.val();
        self.st_frame_error.next = self.frame_status.st_frame_error.val();
        self.st_joins.next = self.frame_status.st_joins.val();
        self.st_gear_stalls.next = self.frame_status.st_gear_stalls.val();
        self.run_k.next = self.run.run_k.val();
        self.run_th_h_c.next = self.run.run_th_h_c.val();
        self.run_th_v_c.next = self.run.run_th_v_c.val();
        self.run_rows.next = self.run.run_rows.val();
        self.run_cols.next = self.run.run_cols.val();
        self.run_sl_h.next = self.run.run_sl_h.val();
        self.run_sl_v.next = self.run.run_sl_v.val();
    }
}
