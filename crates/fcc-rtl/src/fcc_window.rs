//! `fcc_window`: the line-buffered connection filter.
//!
//! `h = (K-1)/2` line buffers hold the `h` rows above the current row (point
//! and provisional label per column). For each centre pixel (i, j) the window
//! registers hold rows i-h .. i-1, columns j-h .. j+h. Only rows above are
//! needed, so no look-ahead into the input stream is required: when pixel
//! (i, j) arrives, column (j+h) mod C of every line buffer is read (wrapped
//! reads at the end of a row already serve the next row) and shifted in.
//! The line buffers are a cascade: when pixel (i, j) leaves the window stage it
//! is written into buffer 0 (the row above for the next row), and the word
//! that buffer m held at column j, which sits in the window's centre column,
//! moves into buffer m+1. Each address is read before it is overwritten, and
//! every write lags the read of the same item by one cycle, so a read and a
//! write never meet on one address.
//!
//! Timing: W0 = `inp` (issue reads), W1 (read data; the shifted window is
//! formed and the cascade written), W2 = `centre` with `ent_*`. Positions
//! outside the image (rows above row 0, columns beyond either edge, no
//! wrap-around) and unlabelled points are masked out of `ent_ok`.
//! Entry e = r*K + n: r = 0 is the top row (i-h), n = 0 the left column (j-h).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_line_buf::FccLineBuf;
use crate::types::{kb, Centre, WinPix};

#[derive(LogicBlock)]
pub struct FccWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub en: Signal<In, Bit>,
    /// Labelled pixel stream (stage W0).
    pub inp: Signal<In, WinPix>,
    /// Centre pixel of the window (stage W2).
    pub centre: Signal<Out, Centre>,
    // Window entries for `centre`, row-major from the top row.
    pub ent_ok: Vec<Signal<Out, Bit>>,
    pub ent_x: Vec<Signal<Out, Bits<16>>>,
    pub ent_y: Vec<Signal<Out, Bits<16>>>,
    pub ent_z: Vec<Signal<Out, Bits<16>>>,
    pub ent_label: Vec<Signal<Out, Bits<16>>>,
    /// `lbs[j]` holds the row j+1 above the current one.
    lbs: Vec<FccLineBuf>,
    win_ok: Vec<DFF<Bit>>,
    win_x: Vec<DFF<Bits<16>>>,
    win_y: Vec<DFF<Bits<16>>>,
    win_z: Vec<DFF<Bits<16>>>,
    win_label: Vec<DFF<Bits<16>>>,
    view_ok: Vec<Signal<Local, Bit>>,
    view_x: Vec<Signal<Local, Bits<16>>>,
    view_y: Vec<Signal<Local, Bits<16>>>,
    view_z: Vec<Signal<Local, Bits<16>>>,
    view_label: Vec<Signal<Local, Bits<16>>>,
    w1: DFF<WinPix>,
    w2: DFF<WinPix>,
    raddr: Signal<Local, Bits<12>>,
    /// Column offset n < h: the lowest centre column with j+n-h >= 0.
    col_lo: Vec<Constant<Bits<12>>>,
    /// Column offset n = h+1+t: the highest centre column with j+n-h <= C-1.
    col_hi: Vec<Constant<Bits<12>>>,
    /// Per window row r: lowest centre row with a row h-r above it.
    row_lo: Vec<Constant<Bits<8>>>,
    wrap_col: Constant<Bits<12>>,
    half: Constant<Bits<12>>,
    zero16: Constant<Bits<16>>,
    _k: usize,
    _h: usize,
}

fn vec_of<T: Default>(n: usize) -> Vec<T> {
    (0..n).map(|_| T::default()).collect()
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
            en: Default::default(),
            inp: Default::default(),
            centre: Default::default(),
            ent_ok: vec_of(n),
            ent_x: vec_of(n),
            ent_y: vec_of(n),
            ent_z: vec_of(n),
            ent_label: vec_of(n),
            lbs: (0..h).map(|_| FccLineBuf::new(c)).collect(),
            win_ok: vec_of(n),
            win_x: vec_of(n),
            win_y: vec_of(n),
            win_z: vec_of(n),
            win_label: vec_of(n),
            view_ok: vec_of(n),
            view_x: vec_of(n),
            view_y: vec_of(n),
            view_z: vec_of(n),
            view_label: vec_of(n),
            w1: Default::default(),
            w2: Default::default(),
            raddr: Default::default(),
            col_lo: (0..h).map(|n| kb((h - n) as u64)).collect(),
            col_hi: (0..h).map(|t| kb((c - 2 - t) as u64)).collect(),
            row_lo: (0..h).map(|r| kb((h - r) as u64)).collect(),
            wrap_col: kb((c - h) as u64),
            half: kb(h as u64),
            zero16: kb(0),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccWindow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, w1, w2);
        // ---- W0: read column (j + h) mod C of every line buffer.
        self.raddr.next = self.inp.val().col + self.half.val();
        if self.inp.val().col >= self.wrap_col.val() {
            self.raddr.next = self.inp.val().col - self.wrap_col.val();
        }
        for j in 0..self._h {
            self.lbs[j].clk.next = self.clk.val();
            self.lbs[j].read_en.next = self.en.val() & self.inp.val().valid;
            self.lbs[j].read_addr.next = self.raddr.val();
            self.lbs[j].write_en.next = self.en.val() & self.w1.q.val().valid;
            self.lbs[j].write_addr.next = self.w1.q.val().col;
        }
        // ---- W1: the window shifted by one column, the new column from the buffers.
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..(self._k - 1) {
                        self.view_ok[r * kk + n].next = self.win_ok[r * kk + n + 1].q.val();
                        self.view_x[r * kk + n].next = self.win_x[r * kk + n + 1].q.val();
                        self.view_y[r * kk + n].next = self.win_y[r * kk + n + 1].q.val();
                        self.view_z[r * kk + n].next = self.win_z[r * kk + n + 1].q.val();
                        self.view_label[r * kk + n].next = self.win_label[r * kk + n + 1].q.val();
                    }
                    self.view_ok[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_ok.val();
                    self.view_x[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_x.val();
                    self.view_y[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_y.val();
                    self.view_z[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_z.val();
                    self.view_label[r * kk + kk - 1].next = self.lbs[hh - 1 - r].rd_label.val();
                }
                // Cascade: the current pixel into buffer 0, the centre column of
                // row j (held by buffer j-1) into buffer j.
                for j in 1..self._h {
                    self.lbs[j].wr_ok.next = self.view_ok[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_x.next = self.view_x[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_y.next = self.view_y[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_z.next = self.view_z[(hh - j) * kk + hh].val();
                    self.lbs[j].wr_label.next = self.view_label[(hh - j) * kk + hh].val();
                }
            }
        }
        self.lbs[0].wr_ok.next = self.w1.q.val().ok;
        self.lbs[0].wr_x.next = self.w1.q.val().x;
        self.lbs[0].wr_y.next = self.w1.q.val().y;
        self.lbs[0].wr_z.next = self.w1.q.val().z;
        self.lbs[0].wr_label.next = self.w1.q.val().label;
        for e in 0..(self._k * self._h) {
            self.win_ok[e].clock.next = self.clk.val();
            self.win_x[e].clock.next = self.clk.val();
            self.win_y[e].clock.next = self.clk.val();
            self.win_z[e].clock.next = self.clk.val();
            self.win_label[e].clock.next = self.clk.val();
            self.win_ok[e].d.next = self.win_ok[e].q.val();
            self.win_x[e].d.next = self.win_x[e].q.val();
            self.win_y[e].d.next = self.win_y[e].q.val();
            self.win_z[e].d.next = self.win_z[e].q.val();
            self.win_label[e].d.next = self.win_label[e].q.val();
            if self.en.val() & self.w1.q.val().valid {
                self.win_ok[e].d.next = self.view_ok[e].val();
                self.win_x[e].d.next = self.view_x[e].val();
                self.win_y[e].d.next = self.view_y[e].val();
                self.win_z[e].d.next = self.view_z[e].val();
                self.win_label[e].d.next = self.view_label[e].val();
            }
        }
        if self.en.val() {
            self.w1.d.next = self.inp.val();
            self.w2.d.next = self.w1.q.val();
        }
        if self.rst.val() {
            self.w1.d.next.valid = false;
            self.w2.d.next.valid = false;
        }
        // ---- W2: mask positions outside the image and unlabelled points.
        self.centre.next.x = self.w2.q.val().x;
        self.centre.next.y = self.w2.q.val().y;
        self.centre.next.z = self.w2.q.val().z;
        self.centre.next.valid = self.w2.q.val().valid;
        self.centre.next.ok = self.w2.q.val().ok;
        self.centre.next.label = self.w2.q.val().label;
        self.centre.next.last = self.w2.q.val().last;
        self.centre.next.ring = self.w2.q.val().ring;
        self.centre.next.ring_a = self.w2.q.val().ring_a;
        self.centre.next.ring_b = self.w2.q.val().ring_b;
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..self._k {
                        self.ent_ok[r * kk + n].next = self.win_ok[r * kk + n].q.val()
                            & (self.w2.q.val().row >= self.row_lo[r].val())
                            & (self.win_label[r * kk + n].q.val() != self.zero16.val());
                        self.ent_x[r * kk + n].next = self.win_x[r * kk + n].q.val();
                        self.ent_y[r * kk + n].next = self.win_y[r * kk + n].q.val();
                        self.ent_z[r * kk + n].next = self.win_z[r * kk + n].q.val();
                        self.ent_label[r * kk + n].next = self.win_label[r * kk + n].q.val();
                    }
                    // Left of the centre only the left edge, right of it only the right edge.
                    for n in 0..self._h {
                        if self.w2.q.val().col < self.col_lo[n].val() {
                            self.ent_ok[r * kk + n].next = false;
                        }
                    }
                    for n in (self._h + 1)..self._k {
                        if self.w2.q.val().col > self.col_hi[n - hh - 1].val() {
                            self.ent_ok[r * kk + n].next = false;
                        }
                    }
                }
            }
        }
    }
}
