//! `fcc_thr_window`: the inter-channel thresholds of the window's points
//! (spec §2, range-adaptive), a window of the same shape as `fcc_window`'s
//! that runs `THR_WIN_LAG` cycles behind it, so that its entries meet the
//! distance units when they pick each pair's addend (one cycle before
//! `FccSqDist` adds it).
//!
//! Each pixel's key and addend `-T'_V` (kept as its low 32 bits: bits
//! 35..32 are always set, `FccPointThr`) come from `fcc_pix_thr` eight
//! cycles before the pixel leaves `fcc_intra` (`fcc_intra` takes ten cycles,
//! its thresholds follow it by two) and waits here until T0 = W2, where the
//! window's controls (`valid`, `col`, `rdcol`, taken at W0) meet it. From T0
//! on, everything is `fcc_window`'s main path: T0 reads column `rdcol` of
//! every line buffer, T2 shifts the window and writes the cascade (buffer 0
//! takes the pixel, buffer j the centre column of row j), T3 = W5 presents
//! `ent_*` (entry e = r*K + n as in `fcc_window`) and the centre's own word.
//! No masks: `fcc_window`'s `ent_ok` masks the distance units. The keys and
//! the addends are two `FccWordWindow` lanes that share this block's write
//! and shift enables.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_pix_thr::THR_LAG;
use crate::fcc_word_window::FccWordWindow;
use crate::types::{kb, vec_of};

/// Cycles between `fcc_window`'s entries and this window's.
pub const THR_WIN_LAG: usize = 2;

/// Cycles from a pixel entering `fcc_intra` (N0) to leaving it (W0).
const INTRA_LATENCY: usize = 10;

/// Cycles a pixel's threshold word waits for its controls (from fcc_intra's
/// N2 to W2).
const WORD_WAIT: usize = INTRA_LATENCY - THR_LAG + THR_WIN_LAG;

// The delay lines below are written out for these lags.
const _: () = assert!(THR_WIN_LAG == 2 && WORD_WAIT == 10);

#[derive(LogicBlock)]
pub struct FccThrWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // W0: the labelled pixel's slot (as `fcc_window` takes it).
    pub valid: Signal<In, Bit>,
    pub col: Signal<In, Bits<12>>,
    pub rdcol: Signal<In, Bits<12>>,
    // The pixel's key and addend, eight cycles before its W0.
    pub key: Signal<In, Bits<16>>,
    pub cv: Signal<In, Bits<36>>,
    // T3 = W5: the centre's word and its window's.
    pub centre_key: Signal<Out, Bits<16>>,
    pub centre_cv: Signal<Out, Bits<36>>,
    pub ent_key: Vec<Signal<Out, Bits<16>>>,
    pub ent_cv: Vec<Signal<Out, Bits<36>>>,
    wait_key: Vec<DFF<Bits<16>>>,
    wait_cv: Vec<DFF<Bits<36>>>,
    cv_valid: Vec<DFF<Bit>>,
    cv_col: Vec<DFF<Bits<12>>>,
    cv_rdcol: Vec<DFF<Bits<12>>>,
    t1_valid: DFF<Bit>,
    t1_col: DFF<Bits<12>>,
    t1_key: DFF<Bits<16>>,
    t2_key: DFF<Bits<16>>,
    t3_key: DFF<Bits<16>>,
    t1_cv: DFF<Bits<36>>,
    t2_cv: DFF<Bits<36>>,
    t3_cv: DFF<Bits<36>>,
    /// The line buffers: keys and addends (their low 32 bits; the upper
    /// bits of the addends are cleared on entry and set on the way out).
    lane_key: FccWordWindow<Bits<16>, 12>,
    lane_cv: FccWordWindow<Bits<36>, 12>,
    shift_en: Vec<FccKeepReg<Bit>>,
    lb_write_en: Vec<FccKeepReg<Bit>>,
    lb_write_addr: Vec<FccKeepReg<Bits<12>>>,
    /// Bits 35..32 of every addend (set), and the bits kept (31..0).
    cv_high: Constant<Bits<36>>,
    cv_low: Constant<Bits<36>>,
    zero12: Constant<Bits<12>>,
    zero16: Constant<Bits<16>>,
    zero36: Constant<Bits<36>>,
    _k: usize,
    _h: usize,
}

impl FccThrWindow {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            col: Default::default(),
            rdcol: Default::default(),
            key: Default::default(),
            cv: Default::default(),
            centre_key: Default::default(),
            centre_cv: Default::default(),
            ent_key: vec_of(n),
            ent_cv: vec_of(n),
            wait_key: vec_of(WORD_WAIT),
            wait_cv: vec_of(WORD_WAIT),
            cv_valid: vec_of(THR_WIN_LAG),
            cv_col: vec_of(THR_WIN_LAG),
            cv_rdcol: vec_of(THR_WIN_LAG),
            t1_valid: Default::default(),
            t1_col: Default::default(),
            t1_key: Default::default(),
            t2_key: Default::default(),
            t3_key: Default::default(),
            t1_cv: Default::default(),
            t2_cv: Default::default(),
            t3_cv: Default::default(),
            lane_key: FccWordWindow::new(k, h, p.cols, 16),
            lane_cv: FccWordWindow::new(k, h, p.cols, 32),
            shift_en: vec_of(n),
            lb_write_en: vec_of(h),
            lb_write_addr: vec_of(h),
            cv_high: kb(0xf_0000_0000),
            cv_low: kb(0xffff_ffff),
            zero12: kb(0),
            zero16: kb(0),
            zero36: kb(0),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccThrWindow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, t1_valid, t1_col, t1_key, t2_key, t3_key, t1_cv, t2_cv, t3_cv);
        // ---- The word waits for its controls; the controls wait two cycles.
        for i in 0..10 {
            self.wait_key[i].clock.next = self.clk.val();
            self.wait_cv[i].clock.next = self.clk.val();
        }
        self.wait_key[0].d.next = self.key.val();
        self.wait_cv[0].d.next = self.cv.val() & self.cv_low.val();
        for i in 1..10 {
            self.wait_key[i].d.next = self.wait_key[i - 1].q.val();
            self.wait_cv[i].d.next = self.wait_cv[i - 1].q.val();
        }
        for i in 0..2 {
            self.cv_valid[i].clock.next = self.clk.val();
            self.cv_col[i].clock.next = self.clk.val();
            self.cv_rdcol[i].clock.next = self.clk.val();
        }
        self.cv_valid[0].d.next = self.valid.val();
        self.cv_col[0].d.next = self.col.val();
        self.cv_rdcol[0].d.next = self.rdcol.val();
        self.cv_valid[1].d.next = self.cv_valid[0].q.val();
        self.cv_col[1].d.next = self.cv_col[0].q.val();
        self.cv_rdcol[1].d.next = self.cv_rdcol[0].q.val();
        // ---- T0 (= W2): read column rdcol of every line buffer; T2 writes
        // buffer 0 and the cascade, and shifts.
        self.lane_key.clk.next = self.clk.val();
        self.lane_cv.clk.next = self.clk.val();
        self.lane_key.read_en.next = self.cv_valid[1].q.val();
        self.lane_cv.read_en.next = self.cv_valid[1].q.val();
        self.lane_key.read_addr.next = self.cv_rdcol[1].q.val();
        self.lane_cv.read_addr.next = self.cv_rdcol[1].q.val();
        for j in 0..self._h {
            self.lane_key.cas_en[j].next = self.lb_write_en[j].q.val();
            self.lane_cv.cas_en[j].next = self.lb_write_en[j].q.val();
            self.lane_key.cas_addr[j].next = self.lb_write_addr[j].q.val();
            self.lane_cv.cas_addr[j].next = self.lb_write_addr[j].q.val();
            self.lb_write_en[j].clock.next = self.clk.val();
            self.lb_write_en[j].d.next = self.t1_valid.q.val() & !self.rst.val();
            self.lb_write_addr[j].clock.next = self.clk.val();
            self.lb_write_addr[j].d.next = self.t1_col.q.val();
            if self.rst.val() {
                self.lb_write_addr[j].d.next = self.zero12.val();
            }
        }
        self.t1_valid.d.next = self.cv_valid[1].q.val();
        self.t1_col.d.next = self.cv_col[1].q.val();
        self.t1_key.d.next = self.wait_key[9].q.val();
        self.t1_cv.d.next = self.wait_cv[9].q.val();
        self.t2_key.d.next = self.t1_key.q.val();
        self.t2_cv.d.next = self.t1_cv.q.val();
        self.t3_key.d.next = self.t2_key.q.val();
        self.t3_cv.d.next = self.t2_cv.q.val();
        self.lane_key.in_data.next = self.t2_key.q.val();
        self.lane_cv.in_data.next = self.t2_cv.q.val();
        for e in 0..(self._k * self._h) {
            self.shift_en[e].clock.next = self.clk.val();
            self.shift_en[e].d.next = self.t1_valid.q.val() & !self.rst.val();
            self.lane_key.shift_en[e].next = self.shift_en[e].q.val();
            self.lane_cv.shift_en[e].next = self.shift_en[e].q.val();
            // ---- T3: the entries.
            self.ent_key[e].next = self.lane_key.ent[e].val();
            self.ent_cv[e].next = self.cv_high.val() | self.lane_cv.ent[e].val();
        }
        if self.rst.val() {
            self.cv_valid[0].d.next = false;
            self.cv_valid[1].d.next = false;
            self.t1_valid.d.next = false;
            // The centre's word feeds every distance unit: a reset keeps it a
            // flip-flop, not the end of a shift register (slow clock-to-out).
            self.t3_key.d.next = self.zero16.val();
            self.t3_cv.d.next = self.zero36.val();
        }
        self.centre_key.next = self.t3_key.q.val();
        self.centre_cv.next = self.cv_high.val() | self.t3_cv.q.val();
    }
}
