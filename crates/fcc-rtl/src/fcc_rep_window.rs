//! `FccRepWindow`: the window of representatives beside `fcc_window`'s
//! point window (see its module documentation). The pixel that was W3 in
//! the point window (`valid`, `col`, `rdcol`) runs through a delay W4 .. W9;
//! at R0 = W7 (delay stage 3) every representative buffer is read at
//! `rdcol`; at R2 = W9 (stage 5) the window shifts by one column, the new
//! column from the buffers, and the buffers cascade (the centre column of
//! row j, held by buffer j-1, into buffer j at `col`); R3 = W10 shows the
//! entries `ent_rep`, `REP_LAG` cycles after the point window's. Buffer 0 is
//! written by the sort network (`rep_*`: the centre's representative at its
//! column). `rst` clears the delay's valid flags and the shift enables.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_ram::FccRam;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The point window's W3 pixel: present, its column, its read column.
    pub valid: Signal<In, Bit>,
    pub col: Signal<In, Bits<12>>,
    pub rdcol: Signal<In, Bits<12>>,
    /// The centre pixel's representative, from the sort network.
    pub rep_we: Signal<In, Bit>,
    pub rep_waddr: Signal<In, Bits<12>>,
    pub rep_wdata: Signal<In, Bits<16>>,
    /// The entries' representatives, row-major from the top row.
    pub ent_rep: Vec<Signal<Out, Bits<16>>>,
    rv_valid: Vec<DFF<Bit>>,
    rv_col: Vec<DFF<Bits<12>>>,
    rv_rdcol: Vec<DFF<Bits<12>>>,
    rlb: Vec<FccRam<Bits<16>, 12>>,
    rwin: Vec<DFF<Bits<16>>>,
    /// Copies of R2's `valid` (`rv_valid[5]`), one per entry.
    rep_shift_en: Vec<FccKeepReg<Bit>>,
    rview: Vec<Signal<Local, Bits<16>>>,
    _k: usize,
    _h: usize,
}

impl FccRepWindow {
    /// The window of a K x h block of entries over rows of `cols` pixels.
    pub fn new(k: usize, h: usize, cols: usize) -> Self {
        let n = k * h;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            col: Default::default(),
            rdcol: Default::default(),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            ent_rep: vec_of(n),
            rv_valid: vec_of(6),
            rv_col: vec_of(6),
            rv_rdcol: vec_of(4),
            rlb: (0..h).map(|_| FccRam::new(cols)).collect(),
            rwin: vec_of(n),
            rep_shift_en: vec_of(n),
            rview: vec_of(n),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccRepWindow {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..6 {
            self.rv_valid[i].clock.next = self.clk.val();
            self.rv_col[i].clock.next = self.clk.val();
        }
        for i in 0..4 {
            self.rv_rdcol[i].clock.next = self.clk.val();
        }
        self.rv_valid[0].d.next = self.valid.val();
        self.rv_col[0].d.next = self.col.val();
        self.rv_rdcol[0].d.next = self.rdcol.val();
        for i in 1..6 {
            self.rv_valid[i].d.next = self.rv_valid[i - 1].q.val();
            self.rv_col[i].d.next = self.rv_col[i - 1].q.val();
        }
        for i in 1..4 {
            self.rv_rdcol[i].d.next = self.rv_rdcol[i - 1].q.val();
        }
        // R0 = W7 (stage 3 of the delay) reads, R2 = W9 (stage 5) shifts and
        // writes the cascade.
        for j in 0..self._h {
            self.rlb[j].clk.next = self.clk.val();
            self.rlb[j].read_en.next = self.rv_valid[3].q.val();
            self.rlb[j].read_addr.next = self.rv_rdcol[3].q.val();
            self.rlb[j].write_en.next = self.rv_valid[5].q.val();
            self.rlb[j].write_addr.next = self.rv_col[5].q.val();
        }
        self.rlb[0].write_en.next = self.rep_we.val();
        self.rlb[0].write_addr.next = self.rep_waddr.val();
        self.rlb[0].write_data.next = self.rep_wdata.val();
        for kk in self._k..(self._k + 1) {
            for hh in self._h..(self._h + 1) {
                for r in 0..self._h {
                    for n in 0..(self._k - 1) {
                        self.rview[r * kk + n].next = self.rwin[r * kk + n + 1].q.val();
                    }
                    self.rview[r * kk + kk - 1].next = self.rlb[hh - 1 - r].read_data.val();
                }
                for j in 1..self._h {
                    self.rlb[j].write_data.next = self.rview[(hh - j) * kk + hh].val();
                }
            }
        }
        for e in 0..(self._k * self._h) {
            self.rwin[e].clock.next = self.clk.val();
            self.rwin[e].d.next = self.rwin[e].q.val();
            self.rep_shift_en[e].clock.next = self.clk.val();
            self.rep_shift_en[e].d.next = self.rv_valid[4].q.val() & !self.rst.val();
            if self.rep_shift_en[e].q.val() {
                self.rwin[e].d.next = self.rview[e].val();
            }
            self.ent_rep[e].next = self.rwin[e].q.val();
        }
        if self.rst.val() {
            for i in 0..6 {
                self.rv_valid[i].d.next = false;
            }
        }
    }
}
