//! `FccWinEdge`: the edge masks of `fcc_window`, registered in W2 for the
//! pixel that becomes the centre in W3. Window row r (h - r rows above the
//! centre) is inside when the centre's row is at least h - r and the run's K
//! reaches that far; window column n (n - h columns beside the centre) is
//! inside when the column j + n - h lies in 0 ..= C - 1 (no wrap-around) and
//! the run's K reaches it. C - 1 is `last_col`, registered once more here as
//! C - 2 - t for the columns right of the centre (constant while a frame runs).

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccWinEdge {
    pub clk: Signal<In, Clock>,
    /// The W2 pixel's row and column.
    pub row: Signal<In, Bits<8>>,
    pub col: Signal<In, Bits<12>>,
    /// The frame's last column, C - 1.
    pub last_col: Signal<In, Bits<12>>,
    /// The frame's filter size K.
    pub run_k: Signal<In, Bits<4>>,
    /// Window row r, and column n, lie inside (for the W3 centre).
    pub row_in: Vec<Signal<Out, Bit>>,
    pub col_in: Vec<Signal<Out, Bit>>,
    row_q: Vec<DFF<Bit>>,
    col_q: Vec<DFF<Bit>>,
    /// Column offset n < h: the lowest centre column with j+n-h >= 0.
    col_lo: Vec<Constant<Bits<12>>>,
    /// Column offset n = h+1+t: the highest centre column with j+n-h <= C-1
    /// (C - 1 = `last_col`), i.e. C - 2 - t.
    col_hi: Vec<DFF<Bits<12>>>,
    hi_off: Vec<Constant<Bits<12>>>,
    /// Per window row r: lowest centre row with a row h-r above it.
    row_lo: Vec<Constant<Bits<8>>>,
    /// Per window row r: the smallest K whose window reaches it, 2(h-r)+1.
    row_k: Vec<Constant<Bits<4>>>,
    /// Per window column n: the smallest K whose window reaches it, 2|n-h|+1.
    col_k: Vec<Constant<Bits<4>>>,
    _k: usize,
    _h: usize,
}

impl FccWinEdge {
    /// The masks of a window K wide and h rows high.
    pub fn new(k: usize, h: usize) -> Self {
        Self {
            clk: Default::default(),
            row: Default::default(),
            col: Default::default(),
            last_col: Default::default(),
            run_k: Default::default(),
            row_in: vec_of(h),
            col_in: vec_of(k),
            row_q: vec_of(h),
            col_q: vec_of(k),
            col_lo: (0..h).map(|n| kb((h - n) as u64)).collect(),
            col_hi: vec_of(h),
            hi_off: (0..h).map(|t| kb(1 + t as u64)).collect(),
            row_lo: (0..h).map(|r| kb((h - r) as u64)).collect(),
            row_k: (0..h).map(|r| kb((2 * (h - r) + 1) as u64)).collect(),
            col_k: (0..k).map(|n| kb((2 * n.abs_diff(h) + 1) as u64)).collect(),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccWinEdge {
    #[hdl_gen]
    fn update(&mut self) {
        for r in 0..self._h {
            self.row_q[r].clock.next = self.clk.val();
            self.row_q[r].d.next = (self.row.val() >= self.row_lo[r].val())
                & (self.run_k.val() >= self.row_k[r].val());
            self.row_in[r].next = self.row_q[r].q.val();
        }
        for n in 0..self._k {
            self.col_q[n].clock.next = self.clk.val();
            self.col_q[n].d.next = self.run_k.val() >= self.col_k[n].val();
            self.col_in[n].next = self.col_q[n].q.val();
        }
        for t in 0..self._h {
            self.col_hi[t].clock.next = self.clk.val();
            self.col_hi[t].d.next = self.last_col.val() - self.hi_off[t].val();
        }
        for hh in self._h..(self._h + 1) {
            for n in 0..self._h {
                self.col_q[n].d.next = (self.col.val() >= self.col_lo[n].val())
                    & (self.run_k.val() >= self.col_k[n].val());
            }
            for n in (self._h + 1)..self._k {
                self.col_q[n].d.next = (self.col.val() <= self.col_hi[n - hh - 1].q.val())
                    & (self.run_k.val() >= self.col_k[n].val());
            }
        }
    }
}
