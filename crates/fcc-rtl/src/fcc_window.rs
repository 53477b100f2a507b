//! `fcc_window`: the line-buffered connection filter.
//!
//! `h = (K-1)/2` line buffers hold the `h` rows above the current row (per
//! column the point and whether it has a provisional label). For each centre
//! pixel (i, j) the window registers hold rows i-h .. i-1, columns j-h .. j+h. Only rows above are
//! needed, so no look-ahead into the input stream is required: when pixel
//! (i, j) arrives, column (j+h) mod C of every line buffer is read (wrapped
//! reads at the end of a row already serve the next row) and shifted in.
//! The line buffers are a cascade: when pixel (i, j) shifts the window it is
//! written into buffer 0 (the row above for the next row), and the word that
//! buffer m held at column j, which sits in the window's centre column, moves
//! into buffer m+1. Each address is read before it is overwritten, and every
//! write comes at least one pixel after the read of the same address, so a
//! read and a write never meet on one address in one cycle.
//!
//! Timing (no enable): W0 = `inp` (reads issued), W1, W2 (read data arrive
//! from the buffers' output registers; the window shifts; the cascade is
//! written; the edge masks of the next centre are registered), W3 = `centre`
//! with `ent_*`. Positions outside the image (rows above row 0, columns beyond
//! either edge, no wrap-around) and unlabelled points are masked out of
//! `ent_ok`. Entry e = r*K + n: r = 0 is the top row (i-h), n = 0 the left
//! column (j-h).
//!
//! The window is built for the build's K (`K_MAX`); a frame run with a
//! smaller odd K (`run_k`, constant during a frame) masks the positions more
//! than (K-1)/2 rows above or columns beside the centre, through the same
//! registered row and column flags as the image edges.
//!
//! A second, narrower window of the same shape holds each upper pixel's
//! *representative* (`ent_rep`): a provisional label already known to be in
//! its component, chosen by `fcc_sort_net` when that pixel was the centre and
//! written back into representative buffer 0 at its column. It runs
//! `REP_LAG` cycles behind the first (reads in R0 = W7, shift in R2, entries
//! in R3 = W10), so its entries line up with the distance tree's results; its
//! buffers cascade like the others. The sort network writes buffer 0 a few
//! cycles after R3, long before the next row reads that column.
//!
//! The edge masks are registered in `FccWinEdge`; the representative window
//! is `FccRepWindow`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_line_buf::FccLineBuf;
use crate::fcc_rep_window::FccRepWindow;
use crate::fcc_sq_dist::SQ_LATENCY;
use crate::fcc_win_edge::FccWinEdge;
use crate::types::{kb, vec_of, Centre, WinPix};

/// Cycles between the window and the representative window.
pub const REP_LAG: usize = SQ_LATENCY;

// The delay line to the representative window is written out for this lag.
const _: () = assert!(REP_LAG == 7);

#[derive(LogicBlock)]
pub struct FccWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Labelled pixel stream (stage W0).
    pub inp: Signal<In, WinPix>,
    /// The frame's last column, C - 1 (stable while a frame runs).
    pub last_col: Signal<In, Bits<12>>,
    /// The frame's filter size K (odd, 3 ..= the build's K).
    pub run_k: Signal<In, Bits<4>>,
    /// Centre pixel of the window (stage W3).
    pub centre: Signal<Out, Centre>,
    // Window entries for `centre`, row-major from the top row.
    pub ent_ok: Vec<Signal<Out, Bit>>,
    pub ent_x: Vec<Signal<Out, Bits<16>>>,
    pub ent_y: Vec<Signal<Out, Bits<16>>>,
    pub ent_z: Vec<Signal<Out, Bits<16>>>,
    /// Representatives of the entries, `REP_LAG` cycles after `ent_*`.
    pub ent_rep: Vec<Signal<Out, Bits<16>>>,
    // The centre pixel's representative, from the sort network.
    pub rep_we: Signal<In, Bit>,
    pub rep_waddr: Signal<In, Bits<12>>,
    pub rep_wdata: Signal<In, Bits<16>>,
    /// `lbs[j]` holds the row j+1 above the current one.
    lbs: Vec<FccLineBuf>,
    win_lok: Vec<DFF<Bit>>,
    win_x: Vec<DFF<Bits<16>>>,
    win_y: Vec<DFF<Bits<16>>>,
    win_z: Vec<DFF<Bits<16>>>,
    view_lok: Vec<Signal<Local, Bit>>,
    view_x: Vec<Signal<Local, Bits<16>>>,
    view_y: Vec<Signal<Local, Bits<16>>>,
    view_z: Vec<Signal<Local, Bits<16>>>,
    w1: DFF<WinPix>,
    w2: DFF<WinPix>,
    w3: FccFanoutReg<WinPix>,
    /// Copies of W2's `valid`, one per window entry: the entry's shift enable.
    shift_en: Vec<FccKeepReg<Bit>>,
    /// Copies of W2's `valid` and `col`, one per line buffer: its write port.
    lb_write_en: Vec<FccKeepReg<Bit>>,
    lb_write_addr: Vec<FccKeepReg<Bits<12>>>,
    /// The representative window, `REP_LAG` cycles behind.
    rep_win: FccRepWindow,
    /// The edge masks of the W3 centre (`edge` is a Verilog keyword).
    edge_mask: FccWinEdge,
    zero8: Constant<Bits<8>>,
    zero12: Constant<Bits<12>>,
    _k: usize,
    _h: usize,
}

impl FccWindow {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        let c = p.cols;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            last_col: Default::default(),
            run_k: Default::default(),
            centre: Default::default(),
            ent_ok: vec_of(n),
            ent_x: vec_of(n),
            ent_y: vec_of(n),
            ent_z: vec_of(n),
            ent_rep: vec_of(n),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            lbs: (0..h).map(|_| FccLineBuf::new(c)).collect(),
            win_lok: vec_of(n),
            win_x: vec_of(n),
            win_y: vec_of(n),
            win_z: vec_of(n),
            view_lok: vec_of(n),
            view_x: vec_of(n),
            view_y: vec_of(n),
            view_z: vec_of(n),
            w1: Default::default(),
            w2: Default::default(),
            w3: Default::default(),
            shift_en: vec_of(n),
            lb_write_en: vec_of(h),
            lb_write_addr: vec_of(h),
            rep_win: FccRepWindow::new(k, h, c),
            edge_mask: FccWinEdge::new(k, h),
            zero8: kb(0),
            zero12: kb(0),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccWindow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, w1, w2, w3);
        // ---- W0: read column (j + h) mod C of every line buffer.
        for j in 0..self._h {
            self.lbs[j].clk.next = self.clk.val();
            self.lbs[j].read_en.next = self.inp.val().valid;
            self.lbs[j].read_addr.next = self.inp.val().rdcol;
            self.lbs[j].write_en.next = self.lb_write_en[j].q.val();
            self.lbs[j].write_addr.next = self.lb_write_addr[j].q.val();
            self.lb_write_en[j].clock.next = self.clk.val();
            self.lb_write_en[j].d.next = self.w1.q.val().valid & !self.rst.val();
            self.lb_write_addr[j].clock.next = self.clk.val();
            self.lb_write_addr[j].d.next = self.w1.q.val().col;
            if self.rst.val() {
                self.lb_write_addr[j].d.next = self.zero12.val();
            }
        }
        self.w1.d.next = self.inp.val();
        self.w2.d.next = self.w1.q.val();
        self.w3.d.next = self.w2.q.val();
        // ---- W2: the window shifted by one column, the new column from the buffers.
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..(self._k - 1) {
                        self.view_lok[r * kk + n].next = self.win_lok[r * kk + n + 1].q.val();
                        self.view_x[r * kk + n].next = self.win_x[r * kk + n + 1].q.val();
                        self.view_y[r * kk + n].next = self.win_y[r * kk + n + 1].q.val();
                        self.view_z[r * kk + n].next = self.win_z[r * kk + n + 1].q.val();
                    }
                    self.view_lok[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_lok.val();
                    self.view_x[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_x.val();
                    self.view_y[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_y.val();
                    self.view_z[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_z.val();
                }
                // Cascade: the current pixel into buffer 0, the centre column of
                // row j (held by buffer j-1) into buffer j.
                for j in 1..self._h {
                    self.lbs[j].wr_lok.next = self.view_lok[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_x.next = self.view_x[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_y.next = self.view_y[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_z.next = self.view_z[(hh - j) * kk + hh].val();
                }
            }
        }
        self.lbs[0].wr_lok.next = self.w2.q.val().lok;
        self.lbs[0].wr_x.next = self.w2.q.val().x;
        self.lbs[0].wr_y.next = self.w2.q.val().y;
        self.lbs[0].wr_z.next = self.w2.q.val().z;
        for e in 0..(self._k * self._h) {
            self.win_lok[e].clock.next = self.clk.val();
            self.win_x[e].clock.next = self.clk.val();
            self.win_y[e].clock.next = self.clk.val();
            self.win_z[e].clock.next = self.clk.val();
            self.win_lok[e].d.next = self.win_lok[e].q.val();
            self.win_x[e].d.next = self.win_x[e].q.val();
            self.win_y[e].d.next = self.win_y[e].q.val();
            self.win_z[e].d.next = self.win_z[e].q.val();
            self.shift_en[e].clock.next = self.clk.val();
            self.shift_en[e].d.next = self.w1.q.val().valid & !self.rst.val();
            if self.shift_en[e].q.val() {
                self.win_lok[e].d.next = self.view_lok[e].val();
                self.win_x[e].d.next = self.view_x[e].val();
                self.win_y[e].d.next = self.view_y[e].val();
                self.win_z[e].d.next = self.view_z[e].val();
            }
        }
        // Edge masks of the pixel that becomes the centre in W3.
        self.edge_mask.clk.next = self.clk.val();
        self.edge_mask.row.next = self.w2.q.val().row;
        self.edge_mask.col.next = self.w2.q.val().col;
        self.edge_mask.last_col.next = self.last_col.val();
        self.edge_mask.run_k.next = self.run_k.val();
        if self.rst.val() {
            self.w1.d.next.valid = false;
            self.w2.d.next.valid = false;
            self.w3.d.next.valid = false;
            // W2's row and column feed the edge compares and the buffers' write
            // address: a reset keeps them flip-flops, not the end of a shift
            // register whose clock-to-out is five times slower.
            self.w2.d.next.row = self.zero8.val();
            self.w2.d.next.col = self.zero12.val();
        }
        // ---- The representative window, REP_LAG cycles behind.
        self.rep_win.clk.next = self.clk.val();
        self.rep_win.rst.next = self.rst.val();
        self.rep_win.valid.next = self.w3.q.val().valid;
        self.rep_win.cascade_col.next = self.w3.q.val().col;
        self.rep_win.rdcol.next = self.w3.q.val().rdcol;
        self.rep_win.rep_we.next = self.rep_we.val();
        self.rep_win.rep_waddr.next = self.rep_waddr.val();
        self.rep_win.rep_wdata.next = self.rep_wdata.val();
        for e in 0..(self._k * self._h) {
            self.ent_rep[e].next = self.rep_win.ent_rep[e].val();
        }
        // ---- W3: the centre and its window, masked.
        self.centre.next.x = self.w3.q.val().x;
        self.centre.next.y = self.w3.q.val().y;
        self.centre.next.z = self.w3.q.val().z;
        self.centre.next.valid = self.w3.q.val().valid;
        self.centre.next.lok = self.w3.q.val().lok;
        self.centre.next.label = self.w3.q.val().label;
        self.centre.next.col = self.w3.q.val().col;
        self.centre.next.last = self.w3.q.val().last;
        self.centre.next.ring = self.w3.q.val().ring;
        self.centre.next.ring_a = self.w3.q.val().ring_a;
        self.centre.next.ring_b = self.w3.q.val().ring_b;
        for kk in self._k..(self._k + 1) {
            for r in 0..self._h {
                for n in 0..self._k {
                    self.ent_ok[r * kk + n].next = self.win_lok[r * kk + n].q.val()
                        & self.edge_mask.row_in[r].val()
                        & self.edge_mask.col_in[n].val();
                    self.ent_x[r * kk + n].next = self.win_x[r * kk + n].q.val();
                    self.ent_y[r * kk + n].next = self.win_y[r * kk + n].q.val();
                    self.ent_z[r * kk + n].next = self.win_z[r * kk + n].q.val();
                }
            }
        }
    }
}
