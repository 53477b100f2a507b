//! `FccRepWindow`: the window of representatives beside `fcc_window`'s
//! point window (see its module documentation). The pixel that was W3 in
//! the point window (`valid`, `rdcol`, `cascade_col`) runs through a delay W4 .. W9;
//! at R0 = W7 (delay stage 3) every representative buffer is read at
//! `rdcol`; at R2 = W9 (stage 5) the window shifts by one column, the new
//! column from the buffers, and the buffers cascade (the centre column of
//! row j, held by buffer j-1, into buffer j at `cascade_col`); R3 = W10 shows the
//! entries `ent_rep`, `REP_LAG` cycles after the point window's. Buffer 0 is
//! written by the sort network (`rep_*`: the centre's representative at its
//! column). `rst` clears the delay's valid flags and the shift enables. The
//! window and its buffers are an `FccWordWindow` lane; this block holds the
//! delay and the enables.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_word_window::FccWordWindow;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The point window's W3 pixel: present, its read column, its column
    /// (which addresses the cascade's writes only: not read at K = 3).
    pub valid: Signal<In, Bit>,
    pub rdcol: Signal<In, Bits<12>>,
    pub cascade_col: Signal<In, Bits<12>>,
    /// The centre pixel's representative, from the sort network.
    pub rep_we: Signal<In, Bit>,
    pub rep_waddr: Signal<In, Bits<12>>,
    pub rep_wdata: Signal<In, Bits<16>>,
    /// The entries' representatives, row-major from the top row.
    pub ent_rep: Vec<Signal<Out, Bits<16>>>,
    rv_valid: Vec<DFF<Bit>>,
    rv_col: Vec<DFF<Bits<12>>>,
    rv_rdcol: Vec<DFF<Bits<12>>>,
    lane: FccWordWindow<Bits<16>, 12>,
    /// Copies of R2's `valid` (`rv_valid[5]`), one per entry.
    rep_shift_en: Vec<FccKeepReg<Bit>>,
    _k: usize,
    _h: usize,
    _rv_len: usize,
    _col_len: usize,
    /// 1 when there are column stages, else 0.
    _col_in: usize,
}

impl FccRepWindow {
    /// The window of a K x h block of entries over rows of `cols` pixels.
    pub fn new(k: usize, h: usize, cols: usize) -> Self {
        let n = k * h;
        // The columns and stage 5 (R2) only feed the cascade, which one
        // buffer lacks.
        let (rv_len, col_len) = if h > 1 { (6, 6) } else { (5, 0) };
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            rdcol: Default::default(),
            cascade_col: Default::default(),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            ent_rep: vec_of(n),
            rv_valid: vec_of(rv_len),
            rv_col: vec_of(col_len),
            rv_rdcol: vec_of(4),
            lane: FccWordWindow::new(k, h, cols, 16),
            rep_shift_en: vec_of(n),
            _k: k,
            _h: h,
            _rv_len: rv_len,
            _col_len: col_len,
            _col_in: col_len.min(1),
        }
    }
}

impl Logic for FccRepWindow {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..self._rv_len {
            self.rv_valid[i].clock.next = self.clk.val();
        }
        for i in 0..self._col_len {
            self.rv_col[i].clock.next = self.clk.val();
        }
        for i in 0..4 {
            self.rv_rdcol[i].clock.next = self.clk.val();
        }
        self.rv_valid[0].d.next = self.valid.val();
        for i in 0..self._col_in {
            self.rv_col[i].d.next = self.cascade_col.val();
        }
        self.rv_rdcol[0].d.next = self.rdcol.val();
        for i in 1..self._rv_len {
            self.rv_valid[i].d.next = self.rv_valid[i - 1].q.val();
        }
        for i in 1..self._col_len {
            self.rv_col[i].d.next = self.rv_col[i - 1].q.val();
        }
        for i in 1..4 {
            self.rv_rdcol[i].d.next = self.rv_rdcol[i - 1].q.val();
        }
        // R0 = W7 (stage 3 of the delay) reads, R2 = W9 (stage 5) shifts and
        // writes the cascade; buffer 0 takes the sort network's writes.
        self.lane.clk.next = self.clk.val();
        self.lane.read_en.next = self.rv_valid[3].q.val();
        self.lane.read_addr.next = self.rv_rdcol[3].q.val();
        for j in 1..self._h {
            self.lane.cas_en[j].next = self.rv_valid[5].q.val();
            self.lane.cas_addr[j].next = self.rv_col[5].q.val();
        }
        self.lane.cas_en[0].next = self.rep_we.val();
        self.lane.cas_addr[0].next = self.rep_waddr.val();
        self.lane.in_data.next = self.rep_wdata.val();
        for e in 0..(self._k * self._h) {
            self.rep_shift_en[e].clock.next = self.clk.val();
            self.rep_shift_en[e].d.next = self.rv_valid[4].q.val() & !self.rst.val();
            self.lane.shift_en[e].next = self.rep_shift_en[e].q.val();
            self.ent_rep[e].next = self.lane.ent[e].val();
        }
        if self.rst.val() {
            for i in 0..self._rv_len {
                self.rv_valid[i].d.next = false;
            }
        }
    }
}
