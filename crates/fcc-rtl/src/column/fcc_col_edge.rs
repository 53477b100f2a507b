//! `FccColEdge`: the edge masks of `FccColWindow`, registered (when `en`)
//! for the pixel that becomes the centre one cycle later. In column order
//! the window's lines are columns: window line `r` (column `c - h + r`) is
//! inside when `c >= h - r` (no wrap-around) and the run's K reaches `h - r`
//! columns back; window position `n` (row `i - h + n`) is inside when that
//! row lies in `0 ..= R - 1` and the run's K reaches `|n - h|` rows. The
//! centre's own row (`n = h`) is never a pair (pairs in one row belong to
//! pass 1), so only the `K - 1` other positions have a mask: `pos_in[p]`
//! is position `n = p` for `p < h`, `n = p + 1` after. `R - 1` is
//! `last_row`, registered once more here as `R - 2 - t` for the rows below
//! the centre (constant while a frame runs).

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccColEdge {
    pub clk: Signal<In, Clock>,
    pub en: Signal<In, Bit>,
    /// The pixel's row and column.
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    /// The frame's last row, R - 1.
    pub last_row: Signal<In, Bits<7>>,
    /// The frame's filter size K.
    pub run_k: Signal<In, Bits<4>>,
    /// Window line r, and position p, lie inside.
    pub line_in: Vec<Signal<Out, Bit>>,
    pub pos_in: Vec<Signal<Out, Bit>>,
    line_q: Vec<DFF<Bit>>,
    pos_q: Vec<DFF<Bit>>,
    /// Line r: the lowest column with a column h - r before it.
    line_lo: Vec<Constant<Bits<12>>>,
    /// Line r: the smallest K whose window reaches it, 2(h-r)+1.
    line_k: Vec<Constant<Bits<4>>>,
    /// Position p < h: the lowest row with a row h - p above it.
    pos_lo: Vec<Constant<Bits<7>>>,
    /// Position p = h + t: the highest row with a row t + 1 below it,
    /// R - 2 - t.
    pos_hi: Vec<DFF<Bits<7>>>,
    hi_off: Vec<Constant<Bits<7>>>,
    /// Position p: the smallest K whose window reaches it, 2|n-h|+1.
    pos_k: Vec<Constant<Bits<4>>>,
    _k: usize,
    _h: usize,
}

impl FccColEdge {
    /// The masks of a window of h lines, K positions each.
    pub fn new(k: usize, h: usize) -> Self {
        Self {
            clk: Default::default(),
            en: Default::default(),
            row: Default::default(),
            col: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            line_in: vec_of(h),
            pos_in: vec_of(k - 1),
            line_q: vec_of(h),
            pos_q: vec_of(k - 1),
            line_lo: (0..h).map(|r| kb((h - r) as u64)).collect(),
            line_k: (0..h).map(|r| kb((2 * (h - r) + 1) as u64)).collect(),
            pos_lo: (0..h).map(|p| kb((h - p) as u64)).collect(),
            pos_hi: vec_of(h),
            hi_off: (0..h).map(|t| kb(1 + t as u64)).collect(),
            pos_k: (0..k - 1)
                .map(|p| {
                    let n = if p < h { p } else { p + 1 };
                    kb((2 * n.abs_diff(h) + 1) as u64)
                })
                .collect(),
            _k: k,
            _h: h,
        }
    }
}

impl Logic for FccColEdge {
    #[hdl_gen]
    fn update(&mut self) {
        for r in 0..self._h {
            self.line_q[r].clock.next = self.clk.val();
            self.line_q[r].d.next = self.line_q[r].q.val();
            if self.en.val() {
                self.line_q[r].d.next = (self.col.val() >= self.line_lo[r].val())
                    & (self.run_k.val() >= self.line_k[r].val());
            }
            self.line_in[r].next = self.line_q[r].q.val();
        }
        for p in 0..(self._k - 1) {
            self.pos_q[p].clock.next = self.clk.val();
            self.pos_q[p].d.next = self.pos_q[p].q.val();
            self.pos_in[p].next = self.pos_q[p].q.val();
        }
        for t in 0..self._h {
            self.pos_hi[t].clock.next = self.clk.val();
            self.pos_hi[t].d.next = self.last_row.val() - self.hi_off[t].val();
        }
        for hh in self._h..(self._h + 1) {
            if self.en.val() {
                for p in 0..self._h {
                    self.pos_q[p].d.next = (self.row.val() >= self.pos_lo[p].val())
                        & (self.run_k.val() >= self.pos_k[p].val());
                }
                for p in self._h..(self._k - 1) {
                    self.pos_q[p].d.next = (self.row.val() <= self.pos_hi[p - hh].q.val())
                        & (self.run_k.val() >= self.pos_k[p].val());
                }
            }
        }
    }
}
