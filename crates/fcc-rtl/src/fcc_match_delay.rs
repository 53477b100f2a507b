//! `FccMatchDelay`: the delay lines that carry each window position's match
//! flag (`hit`), adjacency flag and representative through the sort filter's
//! stages, with a tap at each stage that reads them (see `fcc_sort_filter`;
//! L = levels of the minimum tree, SM = S(L+1)).
//!
//! `adj` (computed in S0): the position to the left in the same window row
//! matched too and has the same representative, so a join of this position
//! would repeat that one's.
//!
//! The representatives compared in SM are reset, so that this stage stays a
//! flip-flop (a shift-register LUT's output is slow). `rst` is that reset one
//! cycle ahead: each group of `MAX_FANOUT / 16` positions registers its own
//! copy (`rep_rst`), so no copy drives more than `MAX_FANOUT` loads.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::MAX_FANOUT;
use crate::fcc_keep_reg::FccKeepReg;
use crate::types::{kb, vec_of};

/// Positions per reset copy: each resets one 16-bit representative.
const POSITIONS_PER_RESET: usize = MAX_FANOUT / 16;

#[derive(LogicBlock)]
pub struct FccMatchDelay {
    pub clk: Signal<In, Clock>,
    /// Reset, one cycle ahead (see the module doc).
    pub rst: Signal<In, Bit>,
    // S0, from the distance tree and the window.
    pub hit: Vec<Signal<In, Bit>>,
    pub rep: Vec<Signal<In, Bits<16>>>,
    // Taps.
    pub hit_s1: Vec<Signal<Out, Bit>>,
    pub hit_sm: Vec<Signal<Out, Bit>>,
    pub rep_sm: Vec<Signal<Out, Bits<16>>>,
    pub hit_sm1: Vec<Signal<Out, Bit>>,
    pub adj_sm1: Vec<Signal<Out, Bit>>,
    pub rep_sm3: Vec<Signal<Out, Bits<16>>>,
    /// Position e's stages at `e * depth ..`: flags S1 .. SM+1,
    /// representatives S1 .. SM+3.
    hit_line: Vec<DFF<Bit>>,
    adj_line: Vec<DFF<Bit>>,
    rep_line: Vec<DFF<Bits<16>>>,
    /// Position e's SM representative is reset by `rep_rst[e / _group]`.
    rep_rst: Vec<FccKeepReg<Bit>>,
    zero16: Constant<Bits<16>>,
    _k: usize,
    _h: usize,
    _n: usize,
    _l: usize,
    /// Depth of the representative line and of the flag lines.
    _dp: usize,
    _dh: usize,
    /// K times `_dp` and `_dh`: the stride of a window row in the lines.
    _kd: usize,
    _kh: usize,
    /// Positions per reset copy, and the copies.
    _group: usize,
    _copies: usize,
}

impl FccMatchDelay {
    /// A window of `h` rows of `k` positions; `l` levels of minimum tree.
    pub fn new(k: usize, h: usize, l: usize) -> Self {
        assert!(k >= 2 && h >= 1 && l >= 1);
        let n = k * h;
        let dp = l + 4;
        let dh = l + 2;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            hit: vec_of(n),
            rep: vec_of(n),
            hit_s1: vec_of(n),
            hit_sm: vec_of(n),
            rep_sm: vec_of(n),
            hit_sm1: vec_of(n),
            adj_sm1: vec_of(n),
            rep_sm3: vec_of(n),
            hit_line: vec_of(n * dh),
            adj_line: vec_of(n * dh),
            rep_line: vec_of(n * dp),
            rep_rst: vec_of(n.div_ceil(POSITIONS_PER_RESET)),
            zero16: kb(0),
            _k: k,
            _h: h,
            _n: n,
            _l: l,
            _dp: dp,
            _dh: dh,
            _kd: k * dp,
            _kh: k * dh,
            _group: POSITIONS_PER_RESET,
            _copies: n.div_ceil(POSITIONS_PER_RESET),
        }
    }
}

impl Logic for FccMatchDelay {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..(self._n * self._dp) {
            self.rep_line[i].clock.next = self.clk.val();
        }
        for i in 0..(self._n * self._dh) {
            self.hit_line[i].clock.next = self.clk.val();
            self.adj_line[i].clock.next = self.clk.val();
        }
        for g in 0..self._copies {
            self.rep_rst[g].clock.next = self.clk.val();
            self.rep_rst[g].d.next = self.rst.val();
        }
        for kk in self._k..(self._k + 1) {
            for kd in self._kd..(self._kd + 1) {
                for dd in self._dp..(self._dp + 1) {
                    for r in 0..self._h {
                        for n in 0..self._k {
                            self.rep_line[r * kd + n * dd].d.next = self.rep[r * kk + n].val();
                        }
                    }
                }
            }
            for kh in self._kh..(self._kh + 1) {
                for dh in self._dh..(self._dh + 1) {
                    for r in 0..self._h {
                        self.hit_line[r * kh].d.next = self.hit[r * kk].val();
                        self.adj_line[r * kh].d.next = false;
                        for n in 1..self._k {
                            self.hit_line[r * kh + n * dh].d.next = self.hit[r * kk + n].val();
                            self.adj_line[r * kh + n * dh].d.next = self.hit[r * kk + n - 1].val()
                                & (self.rep[r * kk + n].val() == self.rep[r * kk + n - 1].val());
                        }
                    }
                }
            }
        }
        for l in self._l..(self._l + 1) {
            for dd in self._dp..(self._dp + 1) {
                for dh in self._dh..(self._dh + 1) {
                    for e in 0..self._n {
                        for i in 1..self._dp {
                            self.rep_line[e * dd + i].d.next =
                                self.rep_line[e * dd + i - 1].q.val();
                        }
                        for i in 1..self._dh {
                            self.hit_line[e * dh + i].d.next =
                                self.hit_line[e * dh + i - 1].q.val();
                            self.adj_line[e * dh + i].d.next =
                                self.adj_line[e * dh + i - 1].q.val();
                        }
                        self.hit_s1[e].next = self.hit_line[e * dh].q.val();
                        self.hit_sm[e].next = self.hit_line[e * dh + l].q.val();
                        self.rep_sm[e].next = self.rep_line[e * dd + l].q.val();
                        self.hit_sm1[e].next = self.hit_line[e * dh + l + 1].q.val();
                        self.adj_sm1[e].next = self.adj_line[e * dh + l + 1].q.val();
                        self.rep_sm3[e].next = self.rep_line[e * dd + dd - 1].q.val();
                    }
                }
            }
        }
        // The SM representatives' reset, each from its group's copy (last:
        // it overrides the shift).
        for l in self._l..(self._l + 1) {
            for dd in self._dp..(self._dp + 1) {
                for gg in self._group..(self._group + 1) {
                    for e in 0..self._n {
                        if self.rep_rst[e / gg].q.val() {
                            self.rep_line[e * dd + l].d.next = self.zero16.val();
                        }
                    }
                }
            }
        }
    }
}
