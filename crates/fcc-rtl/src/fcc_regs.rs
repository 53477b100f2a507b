//! `FccRegs`: the AXI4-Lite register file of `fcc_top` (map in `regmap`).
//!
//! Write channel: the address (AW) and the data (W) are each taken into a
//! holding register whenever it is empty (`awready = !aw_v`, `wready =
//! !w_v`), in either order; the write is performed in the cycle after both
//! are held and no response is pending, and its response (always OKAY) is held
//! on B until `bready`. Read channel (one read outstanding): `arready` is
//! high while no read is held (`ar_pend_q` clear, `rvalid` low); the word
//! address is registered at the AR handshake (`ar_word_q` and its copy
//! `ar_word_hi_q`, so that the `araddr` port drives two flip-flops per bit
//! rather than the read multiplexer), the addressed word is registered into
//! `rdata` with `rvalid` in the next cycle (two cycles from the handshake to
//! `rvalid`) and held until `rready`. Every output comes from a flip-flop or one gate after
//! flip-flops.
//!
//! Frame status: in the cycle `frame_end` is high (the last label beat
//! leaves in phase Out: `frame_sent` with `out_next` one cycle earlier) the
//! live counters of the blocks are latched, the frame counter
//! counts, the sticky FRAME_DONE bit is set and, one cycle later,
//! `frame_done` pulses with the latched values already on `st_*`. `irq` is
//! FRAME_DONE and IRQ_ENABLE. `core_rst` (registered) resets the pixel
//! pipeline on `rst` and for one cycle after a write of CONTROL.SOFT_RESET;
//! `core_rst_next` is the same one cycle earlier. The register file itself
//! is reset by `rst` only; its run registers (shadow and active) one cycle
//! later, from kept copies of `rst` (one per group of at most 64 flip-flops,
//! so that `rst` drives few loads), and `arready` is low in that cycle, so no
//! read is taken before they are reset. A read offered in the first cycle
//! after `rst` falls is taken one cycle later.
//!
//! Fanout: CONTROL.CLEAR is held as W is taken in one kept copy per group of
//! status registers, so no clear enable drives more than 64 flip-flops;
//! `frame_end` is the frame counter's addend, not its enable. The core's
//! phase flags come one cycle early (`out_next`, `idle_next`) and are
//! registered here in kept copies, one per group of at most 64 loads, so
//! that neither the frame end nor idle is one net of a hundred enables.
//!
//! Run parameters: a write to RUN_K .. RUN_COLS is checked against
//! `regmap::run_range` (every range ends below 2^16; the checks are
//! registered with the write data as W is taken, one comparator per flag,
//! `w_hi_zero` for bits 31:16 and `w_ge_*` / `w_le_*` for bits 15:0 against
//! each end of each range, and combined in the write's cycle (`ok_*`), so no
//! chain of range comparators follows the write data and none lies
//! between the held data and the registers the write sets); a value outside
//! it is refused (the register keeps its
//! value, the register's ERROR bit is set). An accepted value goes into the
//! register software reads back (the shadow); the core uses the *active* copy
//! (`run_*` outputs), loaded from the shadow in every cycle the core is idle
//! (waiting for a frame's first pixel), so a frame never sees a change. A
//! threshold is also squared for the distance units, serially (shift and add,
//! at most 19 cycles, no DSP) before the write's response is given: the
//! shadow threshold and its square change together. `run_th_h_c` =
//! -(tH^2 + 1) and `run_th_v_c` = -tV^2 (36-bit two's complement) are the
//! addends of the distance units' first DSP, so that a hit is the sign of the
//! sum (`d2 <= tH^2` and `d2 < tV^2`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::{FccFanoutReg, MAX_FANOUT};
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_reg_mux::{FccRegMux, MuxSrc, WORD_BITS};
use crate::fcc_th_square::FccThSquare;
use crate::regmap::{self, bits, offset, ADDR_BITS};
use crate::types::kb;

/// `-(v)` in 36-bit two's complement.
fn neg36(v: u64) -> u64 {
    (1u64 << 36).wrapping_sub(v) & ((1u64 << 36) - 1)
}

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
    mux: FccRegMux,
    // Write channel.
    aw_v: DFF<Bit>,
    // The held address, decoded as AW is taken: one flag per register a
    // write acts on (no address comparator in the write's cycle).
    aw_control: DFF<Bit>,
    aw_status: DFF<Bit>,
    aw_error: DFF<Bit>,
    aw_run_k: DFF<Bit>,
    aw_run_thh: DFF<Bit>,
    aw_run_thv: DFF<Bit>,
    aw_run_rows: DFF<Bit>,
    aw_run_cols: DFF<Bit>,
    w_v: DFF<Bit>,
    w_d: DFF<Bits<32>>,
    // `w_d` checked as W is taken: bits 31:16 zero, and bits 15:0 against
    // the lower (`w_ge_*`) and upper (`w_le_*`) end of the run ranges of
    // RUN_K, RUN_TH_H / RUN_TH_V, RUN_ROWS, RUN_COLS.
    w_hi_zero: DFF<Bit>,
    w_ge_k: DFF<Bit>,
    w_le_k: DFF<Bit>,
    w_ge_th: DFF<Bit>,
    w_le_th: DFF<Bit>,
    w_ge_rows: DFF<Bit>,
    w_le_rows: DFF<Bit>,
    w_ge_cols: DFF<Bit>,
    w_le_cols: DFF<Bit>,
    // CONTROL.CLEAR of the held write data, one kept copy per group of
    // status registers it clears (at most 64 flip-flops each): `count`,
    // `done_sticky`, `s_clusters`, `s_ovf`, `s_err`; `s_prov`, `s_unl`,
    // `s_joins`; `s_gstall`.
    w_clear_count: FccKeepReg<Bit>,
    w_clear_frame: FccKeepReg<Bit>,
    w_clear_stalls: FccKeepReg<Bit>,
    b_v: DFF<Bit>,
    // Read channel.
    /// The word address of the read taken at the AR handshake, and the
    /// read waiting for its data (set in the cycle after the handshake).
    /// `ar_word_q` selects the read word's bits 15:0, its copy
    /// `ar_word_hi_q` bits 31:16 (under 64 loads a bit each; both kept, or
    /// synthesis would merge them).
    ar_word_q: FccKeepReg<Bits<WORD_BITS>>,
    ar_word_hi_q: FccKeepReg<Bits<WORD_BITS>>,
    ar_pend_q: FccFanoutReg<Bit>,
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
    // Run parameters: shadow (written, read back) and active (used).
    sh_k: DFF<Bits<16>>,
    sh_thh: DFF<Bits<16>>,
    sh_thv: DFF<Bits<16>>,
    sh_thh_c: DFF<Bits<36>>,
    sh_thv_c: DFF<Bits<36>>,
    sh_rows: DFF<Bits<16>>,
    sh_cols: DFF<Bits<16>>,
    act_k: DFF<Bits<4>>,
    act_thh_c: DFF<Bits<36>>,
    act_thv_c: DFF<Bits<36>>,
    act_rows: DFF<Bits<8>>,
    act_cols: DFF<Bits<13>>,
    err_k: DFF<Bit>,
    err_thh: DFF<Bit>,
    err_thv: DFF<Bit>,
    err_rows: DFF<Bit>,
    err_cols: DFF<Bit>,
    // The run registers' reset: `rst` one cycle late, one kept copy per group
    // of at most 64 flip-flops: `sh_k`, `sh_rows`, `sh_cols` and their active
    // copies; `sh_thh`, `sh_thh_c`; `sh_thv`, `sh_thv_c`; `act_thh_c`;
    // `act_thv_c`.
    run_rst_dims: FccKeepReg<Bit>,
    run_rst_th_h: FccKeepReg<Bit>,
    run_rst_th_v: FccKeepReg<Bit>,
    run_rst_act_h: FccKeepReg<Bit>,
    run_rst_act_v: FccKeepReg<Bit>,
    // Squarer of a threshold write; `sq_v`: TH_V (else TH_H); `sq_a`: the
    // value; `sq_start`: the write, one cycle late, starts the squarer on
    // `sq_a` (so the write data's range check does not reach the squarer's
    // registers); `sq_busy_q`: `sq.busy` one cycle late (its fall is the end).
    sq: FccThSquare,
    sq_v: DFF<Bit>,
    sq_a: DFF<Bits<16>>,
    sq_start: FccKeepReg<Bit>,
    /// `sq_start` again (kept apart): clears the squarer's sum, so that no
    /// start net drives all of its registers.
    sq_start_acc: FccKeepReg<Bit>,
    sq_start_next: Signal<Local, Bit>,
    sq_busy_q: DFF<Bit>,
    aw_word: Signal<Local, Bits<WORD_BITS>>,
    ok_k: Signal<Local, Bit>,
    ok_th: Signal<Local, Bit>,
    ok_rows: Signal<Local, Bit>,
    ok_cols: Signal<Local, Bit>,
    wr: Signal<Local, Bit>,
    wr_control: Signal<Local, Bit>,
    clear_count: Signal<Local, Bit>,
    clear_frame: Signal<Local, Bit>,
    clear_stalls: Signal<Local, Bit>,
    // The core's phase flags, each registered from its next-cycle value in
    // one kept copy per group of at most 64 loads: phase Out for the frame
    // end of `count`, `done_sticky`, `done_q`, `s_clusters`, `s_prov`,
    // `s_ovf`, `s_unl`, `s_err` (`out_status`) and of `s_joins`, `s_gstall`
    // (`out_perf`); idle for the loads of `act_k`, `act_rows`, `act_cols`,
    // `act_thh_c` (`idle_dims`) and of `act_thv_c` and STATUS.IDLE
    // (`idle_th_v`).
    out_status: FccKeepReg<Bit>,
    out_perf: FccKeepReg<Bit>,
    idle_dims: FccKeepReg<Bit>,
    idle_th_v: FccKeepReg<Bit>,
    frame_end: Signal<Local, Bit>,
    frame_end_perf: Signal<Local, Bit>,
    /// `frame_end` as the frame counter's addend (no enable on `count`).
    count_inc: Signal<Local, Bits<32>>,
    ar_take: Signal<Local, Bit>,
    a_control: Constant<Bits<WORD_BITS>>,
    a_status: Constant<Bits<WORD_BITS>>,
    a_error: Constant<Bits<WORD_BITS>>,
    a_run_k: Constant<Bits<WORD_BITS>>,
    a_run_thh: Constant<Bits<WORD_BITS>>,
    a_run_thv: Constant<Bits<WORD_BITS>>,
    a_run_rows: Constant<Bits<WORD_BITS>>,
    a_run_cols: Constant<Bits<WORD_BITS>>,
    bit_err_k: Constant<Bits<32>>,
    bit_err_thh: Constant<Bits<32>>,
    bit_err_thv: Constant<Bits<32>>,
    bit_err_rows: Constant<Bits<32>>,
    bit_err_cols: Constant<Bits<32>>,
    k_min: Constant<Bits<16>>,
    k_max: Constant<Bits<16>>,
    th_min: Constant<Bits<16>>,
    th_max: Constant<Bits<16>>,
    rows_min: Constant<Bits<16>>,
    rows_max: Constant<Bits<16>>,
    cols_min: Constant<Bits<16>>,
    cols_max: Constant<Bits<16>>,
    def_k: Constant<Bits<4>>,
    def_thh: Constant<Bits<16>>,
    def_thv: Constant<Bits<16>>,
    def_thh_c: Constant<Bits<36>>,
    def_thv_c: Constant<Bits<36>>,
    def_rows: Constant<Bits<8>>,
    def_cols: Constant<Bits<13>>,
    def_k16: Constant<Bits<16>>,
    def_rows16: Constant<Bits<16>>,
    def_cols16: Constant<Bits<16>>,
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
                // Read back: the shadow values.
                offset::RUN_K => MuxSrc::W16(2),
                offset::RUN_TH_H => MuxSrc::W16(3),
                offset::RUN_TH_V => MuxSrc::W16(4),
                offset::RUN_ROWS => MuxSrc::W16(5),
                offset::RUN_COLS => MuxSrc::W16(6),
                // Flags: 0 irq_en, 1 done_sticky, 2 idle, 3 overflow,
                // 4 frame_error, 5 .. 9 the ERROR bits.
                offset::ERROR => MuxSrc::Flags(flags(&[
                    (bits::ERROR_K, 5),
                    (bits::ERROR_TH_H, 6),
                    (bits::ERROR_TH_V, 7),
                    (bits::ERROR_ROWS, 8),
                    (bits::ERROR_COLS, 9),
                ])),
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
        let range = |off| {
            let r = regmap::run_range(p, off).expect("a run register");
            assert!(
                r.max < 1 << 16,
                "run range of {off:#x} ends at or above 2^16"
            );
            (kb(u64::from(r.min)), kb(u64::from(r.max)))
        };
        let (k_min, k_max) = range(offset::RUN_K);
        let (th_min, th_max) = range(offset::RUN_TH_H);
        assert_eq!(
            regmap::run_range(p, offset::RUN_TH_H),
            regmap::run_range(p, offset::RUN_TH_V)
        );
        let (rows_min, rows_max) = range(offset::RUN_ROWS);
        let (cols_min, cols_max) = range(offset::RUN_COLS);
        let bit = |b: u32| kb(u64::from(b));
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
            mux: FccRegMux::new(entries),
            aw_v: Default::default(),
            aw_control: Default::default(),
            aw_status: Default::default(),
            aw_error: Default::default(),
            aw_run_k: Default::default(),
            aw_run_thh: Default::default(),
            aw_run_thv: Default::default(),
            aw_run_rows: Default::default(),
            aw_run_cols: Default::default(),
            w_v: Default::default(),
            w_d: Default::default(),
            w_hi_zero: Default::default(),
            w_ge_k: Default::default(),
            w_le_k: Default::default(),
            w_ge_th: Default::default(),
            w_le_th: Default::default(),
            w_ge_rows: Default::default(),
            w_le_rows: Default::default(),
            w_ge_cols: Default::default(),
            w_le_cols: Default::default(),
            w_clear_count: Default::default(),
            w_clear_frame: Default::default(),
            w_clear_stalls: Default::default(),
            b_v: Default::default(),
            ar_word_q: FccKeepReg::with_max_fanout(MAX_FANOUT),
            ar_word_hi_q: FccKeepReg::with_max_fanout(MAX_FANOUT),
            ar_pend_q: Default::default(),
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
            sh_k: Default::default(),
            sh_thh: Default::default(),
            sh_thv: Default::default(),
            sh_thh_c: Default::default(),
            sh_thv_c: Default::default(),
            sh_rows: Default::default(),
            sh_cols: Default::default(),
            act_k: Default::default(),
            act_thh_c: Default::default(),
            act_thv_c: Default::default(),
            act_rows: Default::default(),
            act_cols: Default::default(),
            err_k: Default::default(),
            err_thh: Default::default(),
            err_thv: Default::default(),
            err_rows: Default::default(),
            err_cols: Default::default(),
            run_rst_dims: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_th_h: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_th_v: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_act_h: FccKeepReg::with_max_fanout(MAX_FANOUT),
            run_rst_act_v: FccKeepReg::with_max_fanout(MAX_FANOUT),
            sq: FccThSquare::new(),
            sq_v: Default::default(),
            sq_a: Default::default(),
            sq_start: Default::default(),
            sq_start_acc: Default::default(),
            sq_start_next: Default::default(),
            sq_busy_q: Default::default(),
            aw_word: Default::default(),
            ok_k: Default::default(),
            ok_th: Default::default(),
            ok_rows: Default::default(),
            ok_cols: Default::default(),
            wr: Default::default(),
            wr_control: Default::default(),
            clear_count: Default::default(),
            clear_frame: Default::default(),
            clear_stalls: Default::default(),
            out_status: Default::default(),
            out_perf: Default::default(),
            idle_dims: Default::default(),
            idle_th_v: Default::default(),
            frame_end: Default::default(),
            frame_end_perf: Default::default(),
            count_inc: Default::default(),
            ar_take: Default::default(),
            a_control: word(offset::CONTROL),
            a_status: word(offset::STATUS),
            a_error: word(offset::ERROR),
            a_run_k: word(offset::RUN_K),
            a_run_thh: word(offset::RUN_TH_H),
            a_run_thv: word(offset::RUN_TH_V),
            a_run_rows: word(offset::RUN_ROWS),
            a_run_cols: word(offset::RUN_COLS),
            bit_err_k: bit(bits::ERROR_K),
            bit_err_thh: bit(bits::ERROR_TH_H),
            bit_err_thv: bit(bits::ERROR_TH_V),
            bit_err_rows: bit(bits::ERROR_ROWS),
            bit_err_cols: bit(bits::ERROR_COLS),
            k_min,
            k_max,
            th_min,
            th_max,
            rows_min,
            rows_max,
            cols_min,
            cols_max,
            def_k: kb(p.fsize as u64),
            def_thh: kb(p.th_h_q() as u64),
            def_thv: kb(p.th_v_q() as u64),
            def_thh_c: kb(neg36(p.th_h_sq() as u64 + 1)),
            def_thv_c: kb(neg36(p.th_v_sq() as u64)),
            def_rows: kb(p.rows as u64),
            def_cols: kb(p.cols as u64),
            def_k16: kb(p.fsize as u64),
            def_rows16: kb(p.rows as u64),
            def_cols16: kb(p.cols as u64),
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
            aw_control,
            aw_status,
            aw_error,
            aw_run_k,
            aw_run_thh,
            aw_run_thv,
            aw_run_rows,
            aw_run_cols,
            w_v,
            w_d,
            w_hi_zero,
            w_ge_k,
            w_le_k,
            w_ge_th,
            w_le_th,
            w_ge_rows,
            w_le_rows,
            w_ge_cols,
            w_le_cols,
            b_v,
            ar_pend_q,
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
            s_gstall,
            sh_k,
            sh_thh,
            sh_thv,
            sh_thh_c,
            sh_thv_c,
            sh_rows,
            sh_cols,
            act_k,
            act_thh_c,
            act_thv_c,
            act_rows,
            act_cols,
            err_k,
            err_thh,
            err_thv,
            err_rows,
            err_cols,
            sq_v,
            sq_a,
            sq_busy_q
        );
        self.w_clear_count.clock.next = self.clk.val();
        self.w_clear_frame.clock.next = self.clk.val();
        self.w_clear_stalls.clock.next = self.clk.val();
        self.run_rst_dims.clock.next = self.clk.val();
        self.run_rst_th_h.clock.next = self.clk.val();
        self.run_rst_th_v.clock.next = self.clk.val();
        self.run_rst_act_h.clock.next = self.clk.val();
        self.run_rst_act_v.clock.next = self.clk.val();
        self.out_status.clock.next = self.clk.val();
        self.out_perf.clock.next = self.clk.val();
        self.idle_dims.clock.next = self.clk.val();
        self.idle_th_v.clock.next = self.clk.val();
        self.out_status.d.next = self.out_next.val();
        self.out_perf.d.next = self.out_next.val();
        self.idle_dims.d.next = self.idle_next.val();
        self.idle_th_v.d.next = self.idle_next.val();
        self.sq.clk.next = self.clk.val();
        self.sq.rst.next = self.rst.val();
        self.sq.a.next = self.sq_a.q.val();
        self.sq.start.next = self.sq_start.q.val();
        self.sq.start_acc.next = self.sq_start_acc.q.val();
        self.sq_start.clock.next = self.clk.val();
        self.sq_start_acc.clock.next = self.clk.val();
        self.sq_start_next.next = false;
        // ---- Write channel: AW and W held in either order, then one write.
        // (A threshold write is answered when its square is ready: no write
        // is performed while the squarer starts or runs.)
        self.wr.next = self.aw_v.q.val()
            & self.w_v.q.val()
            & !self.b_v.q.val()
            & !self.sq_start.q.val()
            & !self.sq.busy.val()
            & !self.sq_busy_q.q.val();
        self.aw_word.next = self.s_axil_awaddr.val().get_bits::<WORD_BITS>(2);
        if self.s_axil_awvalid.val() & !self.aw_v.q.val() {
            self.aw_v.d.next = true;
            self.aw_control.d.next = self.aw_word.val() == self.a_control.val();
            self.aw_status.d.next = self.aw_word.val() == self.a_status.val();
            self.aw_error.d.next = self.aw_word.val() == self.a_error.val();
            self.aw_run_k.d.next = self.aw_word.val() == self.a_run_k.val();
            self.aw_run_thh.d.next = self.aw_word.val() == self.a_run_thh.val();
            self.aw_run_thv.d.next = self.aw_word.val() == self.a_run_thv.val();
            self.aw_run_rows.d.next = self.aw_word.val() == self.a_run_rows.val();
            self.aw_run_cols.d.next = self.aw_word.val() == self.a_run_cols.val();
        }
        self.w_clear_count.d.next = self.w_clear_count.q.val();
        self.w_clear_frame.d.next = self.w_clear_frame.q.val();
        self.w_clear_stalls.d.next = self.w_clear_stalls.q.val();
        if self.s_axil_wvalid.val() & !self.w_v.q.val() {
            self.w_v.d.next = true;
            self.w_d.d.next = self.s_axil_wdata.val();
            self.w_clear_count.d.next =
                (self.s_axil_wdata.val() & self.bit_clear.val()) != self.zero32.val();
            self.w_clear_frame.d.next =
                (self.s_axil_wdata.val() & self.bit_clear.val()) != self.zero32.val();
            self.w_clear_stalls.d.next =
                (self.s_axil_wdata.val() & self.bit_clear.val()) != self.zero32.val();
            self.w_hi_zero.d.next = self.s_axil_wdata.val().get_bits::<16>(16) == self.zero16.val();
            self.w_ge_k.d.next = self.s_axil_wdata.val().get_bits::<16>(0) >= self.k_min.val();
            self.w_le_k.d.next = self.s_axil_wdata.val().get_bits::<16>(0) <= self.k_max.val();
            self.w_ge_th.d.next = self.s_axil_wdata.val().get_bits::<16>(0) >= self.th_min.val();
            self.w_le_th.d.next = self.s_axil_wdata.val().get_bits::<16>(0) <= self.th_max.val();
            self.w_ge_rows.d.next =
                self.s_axil_wdata.val().get_bits::<16>(0) >= self.rows_min.val();
            self.w_le_rows.d.next =
                self.s_axil_wdata.val().get_bits::<16>(0) <= self.rows_max.val();
            self.w_ge_cols.d.next =
                self.s_axil_wdata.val().get_bits::<16>(0) >= self.cols_min.val();
            self.w_le_cols.d.next =
                self.s_axil_wdata.val().get_bits::<16>(0) <= self.cols_max.val();
        }
        if self.b_v.q.val() & self.s_axil_bready.val() {
            self.b_v.d.next = false;
        }
        self.soft_q.d.next = false;
        // The held value in range (RUN_K also odd).
        self.ok_k.next = self.w_hi_zero.q.val()
            & self.w_ge_k.q.val()
            & self.w_le_k.q.val()
            & self.w_d.q.val().get_bit(0);
        self.ok_th.next = self.w_hi_zero.q.val() & self.w_ge_th.q.val() & self.w_le_th.q.val();
        self.ok_rows.next =
            self.w_hi_zero.q.val() & self.w_ge_rows.q.val() & self.w_le_rows.q.val();
        self.ok_cols.next =
            self.w_hi_zero.q.val() & self.w_ge_cols.q.val() & self.w_le_cols.q.val();
        if self.wr.val() {
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = true;
            if self.aw_control.q.val() {
                self.irq_en.d.next = (self.w_d.q.val() & self.bit_irq.val()) != self.zero32.val();
                self.soft_q.d.next = (self.w_d.q.val() & self.bit_soft.val()) != self.zero32.val();
            }
            if self.aw_status.q.val()
                & ((self.w_d.q.val() & self.bit_done.val()) != self.zero32.val())
            {
                self.done_sticky.d.next = false;
            }
            // ERROR: write 1 to clear.
            if self.aw_error.q.val() {
                if (self.w_d.q.val() & self.bit_err_k.val()) != self.zero32.val() {
                    self.err_k.d.next = false;
                }
                if (self.w_d.q.val() & self.bit_err_thh.val()) != self.zero32.val() {
                    self.err_thh.d.next = false;
                }
                if (self.w_d.q.val() & self.bit_err_thv.val()) != self.zero32.val() {
                    self.err_thv.d.next = false;
                }
                if (self.w_d.q.val() & self.bit_err_rows.val()) != self.zero32.val() {
                    self.err_rows.d.next = false;
                }
                if (self.w_d.q.val() & self.bit_err_cols.val()) != self.zero32.val() {
                    self.err_cols.d.next = false;
                }
            }
            // Run parameters: taken if in range, else refused with an error bit.
            if self.aw_run_k.q.val() {
                if self.ok_k.val() {
                    self.sh_k.d.next = self.w_d.q.val().get_bits::<16>(0);
                } else {
                    self.err_k.d.next = true;
                }
            }
            if self.aw_run_rows.q.val() {
                if self.ok_rows.val() {
                    self.sh_rows.d.next = self.w_d.q.val().get_bits::<16>(0);
                } else {
                    self.err_rows.d.next = true;
                }
            }
            if self.aw_run_cols.q.val() {
                if self.ok_cols.val() {
                    self.sh_cols.d.next = self.w_d.q.val().get_bits::<16>(0);
                } else {
                    self.err_cols.d.next = true;
                }
            }
            // A threshold starts the squarer; the response waits for it.
            if self.aw_run_thh.q.val() {
                if self.ok_th.val() {
                    self.b_v.d.next = false;
                    self.sq_start_next.next = true;
                    self.sq_v.d.next = false;
                } else {
                    self.err_thh.d.next = true;
                }
            }
            if self.aw_run_thv.q.val() {
                if self.ok_th.val() {
                    self.b_v.d.next = false;
                    self.sq_start_next.next = true;
                    self.sq_v.d.next = true;
                } else {
                    self.err_thv.d.next = true;
                }
            }
            self.sq_a.d.next = self.w_d.q.val().get_bits::<16>(0);
        }
        // ---- Squarer done: the shadow threshold and its square together.
        self.sq_busy_q.d.next = self.sq.busy.val();
        if self.sq_busy_q.q.val() & !self.sq.busy.val() {
            self.b_v.d.next = true;
            if self.sq_v.q.val() {
                self.sh_thv.d.next = self.sq_a.q.val();
                self.sh_thv_c.d.next = self.sq.c_lt.val();
            } else {
                self.sh_thh.d.next = self.sq_a.q.val();
                self.sh_thh_c.d.next = self.sq.c_le.val();
            }
        }
        // ---- Active run parameters: loaded while the core waits for a frame.
        if self.idle_dims.q.val() {
            self.act_k.d.next = self.sh_k.q.val().get_bits::<4>(0);
            self.act_thh_c.d.next = self.sh_thh_c.q.val();
            self.act_rows.d.next = self.sh_rows.q.val().get_bits::<8>(0);
            self.act_cols.d.next = self.sh_cols.q.val().get_bits::<13>(0);
        }
        if self.idle_th_v.q.val() {
            self.act_thv_c.d.next = self.sh_thv_c.q.val();
        }
        // ---- Frame end: latch the status, count, set FRAME_DONE.
        self.frame_end.next = self.out_status.q.val() & self.frame_sent.val();
        self.frame_end_perf.next = self.out_perf.q.val() & self.frame_sent.val();
        self.done_q.d.next = self.frame_end.val();
        self.count_inc.next = self.zero32.val();
        if self.frame_end.val() {
            self.count_inc.next = self.one32.val();
        }
        self.count.d.next = self.count.q.val() + self.count_inc.val();
        if self.frame_end.val() {
            self.done_sticky.d.next = true;
            self.s_clusters.d.next = self.clusters.val();
            self.s_prov.d.next = self.provisional.val();
            self.s_ovf.d.next = self.overflow.val();
            self.s_unl.d.next = self.unlabelled.val();
            self.s_err.d.next = self.frame_error.val();
        }
        if self.frame_end_perf.val() {
            self.s_joins.d.next = self.joins.val();
            self.s_gstall.d.next = self.gear_stalls.val();
        }
        // CONTROL.CLEAR, in its groups.
        self.wr_control.next = self.wr.val() & self.aw_control.q.val();
        self.clear_count.next = self.wr_control.val() & self.w_clear_count.q.val();
        self.clear_frame.next = self.wr_control.val() & self.w_clear_frame.q.val();
        self.clear_stalls.next = self.wr_control.val() & self.w_clear_stalls.q.val();
        if self.clear_count.val() {
            self.done_sticky.d.next = false;
            self.count.d.next = self.zero32.val();
            self.s_clusters.d.next = self.zero16.val();
            self.s_ovf.d.next = false;
            self.s_err.d.next = false;
        }
        if self.clear_frame.val() {
            self.s_prov.d.next = self.zero16.val();
            self.s_unl.d.next = self.zero20.val();
            self.s_joins.d.next = self.zero24.val();
        }
        if self.clear_stalls.val() {
            self.s_gstall.d.next = self.zero24.val();
        }
        // ---- Read channel.
        self.mux.addr.next = self.ar_word_q.q.val();
        self.mux.addr_hi.next = self.ar_word_hi_q.q.val();
        self.mux.w32[0].next = self.count.q.val();
        self.mux.w16[0].next = self.s_clusters.q.val();
        self.mux.w16[1].next = self.s_prov.q.val();
        self.mux.w20[0].next = self.s_unl.q.val();
        self.mux.w24[0].next = self.s_joins.q.val();
        self.mux.w24[1].next = self.s_gstall.q.val();
        self.mux.flags[0].next = self.irq_en.q.val();
        self.mux.flags[1].next = self.done_sticky.q.val();
        self.mux.flags[2].next = self.idle_th_v.q.val();
        self.mux.flags[3].next = self.s_ovf.q.val();
        self.mux.flags[4].next = self.s_err.q.val();
        self.mux.flags[5].next = self.err_k.q.val();
        self.mux.flags[6].next = self.err_thh.q.val();
        self.mux.flags[7].next = self.err_thv.q.val();
        self.mux.flags[8].next = self.err_rows.q.val();
        self.mux.flags[9].next = self.err_cols.q.val();
        self.mux.w16[2].next = self.sh_k.q.val();
        self.mux.w16[3].next = self.sh_thh.q.val();
        self.mux.w16[4].next = self.sh_thv.q.val();
        self.mux.w16[5].next = self.sh_rows.q.val();
        self.mux.w16[6].next = self.sh_cols.q.val();
        // No read is taken while the run registers are still in reset.
        self.ar_take.next = self.s_axil_arvalid.val()
            & !self.ar_pend_q.q.val()
            & !self.r_v.q.val()
            & !self.run_rst_dims.q.val();
        self.ar_pend_q.d.next = self.ar_take.val();
        self.ar_word_q.clock.next = self.clk.val();
        self.ar_word_q.d.next = self.ar_word_q.q.val();
        self.ar_word_hi_q.clock.next = self.clk.val();
        self.ar_word_hi_q.d.next = self.ar_word_hi_q.q.val();
        if self.ar_take.val() {
            self.ar_word_q.d.next = self.s_axil_araddr.val().get_bits::<WORD_BITS>(2);
            self.ar_word_hi_q.d.next = self.s_axil_araddr.val().get_bits::<WORD_BITS>(2);
        }
        if self.ar_pend_q.q.val() {
            self.r_v.d.next = true;
            self.r_d.d.next = self.mux.data.val();
        }
        if self.r_v.q.val() & self.s_axil_rready.val() {
            self.r_v.d.next = false;
        }
        // ---- Reset of the pipeline: power-on reset or a soft reset.
        self.core_rst_q.d.next = self.rst.val() | self.soft_q.q.val();
        self.core_rst_next.next = self.rst.val() | self.soft_q.q.val();
        if self.rst.val() {
            self.sq_start_next.next = false;
            self.aw_v.d.next = false;
            self.w_v.d.next = false;
            self.b_v.d.next = false;
            self.ar_pend_q.d.next = false;
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
            self.err_k.d.next = false;
            self.err_thh.d.next = false;
            self.err_thv.d.next = false;
            self.err_rows.d.next = false;
            self.err_cols.d.next = false;
            self.sq_busy_q.d.next = false;
        }
        self.sq_start.d.next = self.sq_start_next.val();
        self.sq_start_acc.d.next = self.sq_start_next.val();
        // The run registers, one cycle after `rst`: nothing can change them
        // in that cycle (no write is held, the squarer is in reset, the
        // pipeline reads them only after its merge table is initialised) and
        // no read is taken in it.
        self.run_rst_dims.d.next = self.rst.val();
        self.run_rst_th_h.d.next = self.rst.val();
        self.run_rst_th_v.d.next = self.rst.val();
        self.run_rst_act_h.d.next = self.rst.val();
        self.run_rst_act_v.d.next = self.rst.val();
        if self.run_rst_dims.q.val() {
            self.sh_k.d.next = self.def_k16.val();
            self.sh_rows.d.next = self.def_rows16.val();
            self.sh_cols.d.next = self.def_cols16.val();
            self.act_k.d.next = self.def_k.val();
            self.act_rows.d.next = self.def_rows.val();
            self.act_cols.d.next = self.def_cols.val();
        }
        if self.run_rst_th_h.q.val() {
            self.sh_thh.d.next = self.def_thh.val();
            self.sh_thh_c.d.next = self.def_thh_c.val();
        }
        if self.run_rst_th_v.q.val() {
            self.sh_thv.d.next = self.def_thv.val();
            self.sh_thv_c.d.next = self.def_thv_c.val();
        }
        if self.run_rst_act_h.q.val() {
            self.act_thh_c.d.next = self.def_thh_c.val();
        }
        if self.run_rst_act_v.q.val() {
            self.act_thv_c.d.next = self.def_thv_c.val();
        }
        // ---- Outputs.
        self.s_axil_awready.next = !self.aw_v.q.val();
        self.s_axil_wready.next = !self.w_v.q.val();
        self.s_axil_bvalid.next = self.b_v.q.val();
        self.s_axil_bresp.next = self.okay.val();
        self.s_axil_arready.next =
            !self.ar_pend_q.q.val() & !self.r_v.q.val() & !self.run_rst_dims.q.val();
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
        self.run_k.next = self.act_k.q.val();
        self.run_th_h_c.next = self.act_thh_c.q.val();
        self.run_th_v_c.next = self.act_thv_c.q.val();
        self.run_rows.next = self.act_rows.q.val();
        self.run_cols.next = self.act_cols.q.val();
    }
}
