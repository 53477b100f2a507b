//! `FccColWindow`: the pass-2 window of the column core (spec §4 in column
//! order, §9.1): for the pixel at row `i`, column `c`, every position of
//! an earlier pixel it pairs with. Those are rows `i - h ..= i + h` but `i`
//! of columns `c - h ..= c - 1` (`2h` positions on each of `h` lines) and
//! rows `i - h ..= i - 1` of column `c`: `K x h` in all, as the row-major
//! window.
//!
//! The earlier columns are the row-major word window transposed: an
//! `FccWordWindow` of `h` lines of `K` positions (two lanes: the words,
//! each a point with its pass-2 key and addend and its run's label, and
//! whether each is a labelled point) whose line buffers are `R`
//! words deep, addressed by row, the window's lines being columns. Line
//! buffer 0 takes the pixel's word at its row; the cascade moves each word
//! one column back, and the window reads row `(i + h) mod R` of every
//! buffer for pixel `i` (the reads at the end of a column serve the next
//! one's first rows). The window's centre positions (the pixel's own row)
//! only feed the cascade. The column's rows above the pixel are a shift
//! register of its last `h` words. `ent_ok` says which entries are pairs:
//! labelled points (the words' `lok`) at positions inside the frame and
//! the run's K (`FccColEdge`).
//!
//! Timing (no enable; the window moves on valid slots only, so between
//! them its entries hold): T0 = `inp` (reads issued), T2 (the words arrive,
//! the window shifts, the cascade and the column's register are written,
//! the masks registered), T3 = `centre` with the entries' fields (`ent_*`)
//! and `ent_ok`. Entry order: line `r`
//! (column `c - h + r`) position `p` at `r * (K - 1) + p` (`p`: rows `i - h`
//! .. `i + h` without `i`), then row `i - m` of column `c` at
//! `2h^2 + m - 1`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_edge::FccColEdge;
use super::fcc_col_word_split::FccColWordSplit;
use super::{ColWord, RunPix};
use crate::fcc_fanout_net::FccFanoutNet;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_word_window::FccWordWindow;
use crate::types::{kb, vec_of};

/// Cycles from `inp` to `centre` and its window (T0 to T3).
pub const COL_WINDOW_LATENCY: usize = 3;

// The stages below are written out for it.
const _: () = assert!(COL_WINDOW_LATENCY == 3);

#[derive(LogicBlock)]
pub struct FccColWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Labelled pixels in column order (from `FccRowRuns`).
    pub inp: Signal<In, RunPix>,
    /// The frame's last row, R - 1, and filter size K (constant while a
    /// frame runs).
    pub last_row: Signal<In, Bits<7>>,
    pub run_k: Signal<In, Bits<4>>,
    /// T3: the pixel and its window, field by field.
    pub centre: Signal<Out, RunPix>,
    pub ent_x: Vec<Signal<Out, Bits<16>>>,
    pub ent_y: Vec<Signal<Out, Bits<16>>>,
    pub ent_z: Vec<Signal<Out, Bits<16>>>,
    pub ent_key: Vec<Signal<Out, Bits<16>>>,
    pub ent_cv: Vec<Signal<Out, Bits<36>>>,
    pub ent_label: Vec<Signal<Out, Bits<16>>>,
    /// T3: the entry is a labelled point inside the window (a pair).
    pub ent_ok: Vec<Signal<Out, Bit>>,
    lane: FccWordWindow<ColWord, 7>,
    lok_lane: FccWordWindow<Bit, 7>,
    split: Vec<FccColWordSplit>,
    masks: FccColEdge,
    pd: Vec<FccFanoutReg<RunPix>>,
    up: Vec<DFF<ColWord>>,
    up_lok: Vec<DFF<Bit>>,
    word: Signal<Local, ColWord>,
    /// `R - h`: rows from here read the next column's first rows
    /// (registered: `last_row` is constant while a frame runs).
    wrap_at: DFF<Bits<7>>,
    rd_row: Signal<Local, Bits<7>>,
    /// `rd_row`, replicated by Vivado (it reaches many loads).
    rd_row_net: FccFanoutNet<Bits<7>>,
    /// The reads' enable, replicated by Vivado as `rd_row`.
    rd_en_net: FccFanoutNet<Bit>,
    h7: Constant<Bits<7>>,
    hm1: Constant<Bits<7>>,
    _k: usize,
    _h: usize,
}

impl FccColWindow {
    /// The window of the build's K over columns of `p.rows` rows.
    pub fn new(p: &FccParams) -> Self {
        let (k, h) = (p.fsize, p.half());
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            centre: Default::default(),
            ent_x: vec_of(k * h),
            ent_y: vec_of(k * h),
            ent_z: vec_of(k * h),
            ent_key: vec_of(k * h),
            ent_cv: vec_of(k * h),
            ent_label: vec_of(k * h),
            ent_ok: vec_of(k * h),
            lane: FccWordWindow::new(k, h, p.rows, ColWord::BITS),
            lok_lane: FccWordWindow::new(k, h, p.rows, 1),
            split: (0..k * h).map(|_| FccColWordSplit::default()).collect(),
            masks: FccColEdge::new(k, h),
            pd: vec_of(COL_WINDOW_LATENCY),
            up: vec_of(h + 1),
            up_lok: vec_of(h + 1),
            word: Default::default(),
            wrap_at: Default::default(),
            rd_row: Default::default(),
            rd_row_net: Default::default(),
            rd_en_net: Default::default(),
            h7: kb(h as u64),
            hm1: kb(h as u64 - 1),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccColWindow {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..3 {
            self.pd[i].clock.next = self.clk.val();
        }
        // ---- T0: read row (i + h) mod R of every line buffer.
        dff_setup!(self, clk, wrap_at);
        self.wrap_at.d.next = self.last_row.val() - self.hm1.val();
        self.rd_row.next = self.inp.val().row + self.h7.val();
        if self.inp.val().row >= self.wrap_at.q.val() {
            self.rd_row.next = self.inp.val().row - self.wrap_at.q.val();
        }
        self.rd_row_net.x.next = self.rd_row.val();
        self.lane.clk.next = self.clk.val();
        self.rd_en_net.x.next = self.inp.val().valid;
        self.lane.read_en.next = self.rd_en_net.y.val();
        self.lane.read_addr.next = self.rd_row_net.y.val();
        self.lok_lane.clk.next = self.clk.val();
        self.lok_lane.read_en.next = self.rd_en_net.y.val();
        self.lok_lane.read_addr.next = self.rd_row_net.y.val();
        self.pd[0].d.next = self.inp.val();
        self.pd[1].d.next = self.pd[0].q.val();
        // ---- T2: shift, write the cascade and the column's register.
        self.word.next.x = self.pd[1].q.val().x;
        self.word.next.y = self.pd[1].q.val().y;
        self.word.next.z = self.pd[1].q.val().z;
        self.word.next.key = self.pd[1].q.val().key;
        self.word.next.cv = self.pd[1].q.val().cv;
        self.word.next.label = self.pd[1].q.val().label;
        self.lane.in_data.next = self.word.val();
        self.lok_lane.in_data.next = self.pd[1].q.val().lok;
        for j in 0..self._h {
            self.lane.cas_en[j].next = self.pd[1].q.val().valid;
            self.lane.cas_addr[j].next = self.pd[1].q.val().row;
            self.lok_lane.cas_en[j].next = self.pd[1].q.val().valid;
            self.lok_lane.cas_addr[j].next = self.pd[1].q.val().row;
        }
        for e in 0..(self._k * self._h) {
            self.lane.shift_en[e].next = self.pd[1].q.val().valid;
            self.lok_lane.shift_en[e].next = self.pd[1].q.val().valid;
        }
        for m in 0..(self._h + 1) {
            self.up[m].clock.next = self.clk.val();
            self.up[m].d.next = self.up[m].q.val();
            self.up_lok[m].clock.next = self.clk.val();
            self.up_lok[m].d.next = self.up_lok[m].q.val();
        }
        if self.pd[1].q.val().valid {
            self.up[0].d.next = self.word.val();
            self.up_lok[0].d.next = self.pd[1].q.val().lok;
            for m in 1..(self._h + 1) {
                self.up[m].d.next = self.up[m - 1].q.val();
                self.up_lok[m].d.next = self.up_lok[m - 1].q.val();
            }
        }
        self.masks.clk.next = self.clk.val();
        self.masks.en.next = self.pd[1].q.val().valid;
        self.masks.row.next = self.pd[1].q.val().row;
        self.masks.col.next = self.pd[1].q.val().col;
        self.masks.last_row.next = self.last_row.val();
        self.masks.run_k.next = self.run_k.val();
        self.pd[2].d.next = self.pd[1].q.val();
        // ---- T3: the window, masked.
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..self._h {
                        self.split[r * (kk - 1) + n].word.next = self.lane.ent[r * kk + n].val();
                        self.ent_ok[r * (kk - 1) + n].next = self.lok_lane.ent[r * kk + n].val()
                            & self.masks.line_in[r].val()
                            & self.masks.pos_in[n].val();
                    }
                    for n in (self._h + 1)..self._k {
                        self.split[r * (kk - 1) + n - 1].word.next =
                            self.lane.ent[r * kk + n].val();
                        self.ent_ok[r * (kk - 1) + n - 1].next = self.lok_lane.ent[r * kk + n]
                            .val()
                            & self.masks.line_in[r].val()
                            & self.masks.pos_in[n - 1].val();
                    }
                }
                for m in 1..(self._h + 1) {
                    self.split[2 * hh * hh + m - 1].word.next = self.up[m].q.val();
                    self.ent_ok[2 * hh * hh + m - 1].next =
                        self.up_lok[m].q.val() & self.masks.pos_in[hh - m].val();
                }
            }
        }
        for e in 0..(self._k * self._h) {
            self.ent_x[e].next = self.split[e].x.val();
            self.ent_y[e].next = self.split[e].y.val();
            self.ent_z[e].next = self.split[e].z.val();
            self.ent_key[e].next = self.split[e].key.val();
            self.ent_cv[e].next = self.split[e].cv.val();
            self.ent_label[e].next = self.split[e].label.val();
        }
        if self.rst.val() {
            self.pd[0].d.next.valid = false;
            self.pd[1].d.next.valid = false;
            self.pd[2].d.next.valid = false;
        }
        self.centre.next = self.pd[2].q.val();
    }
}
