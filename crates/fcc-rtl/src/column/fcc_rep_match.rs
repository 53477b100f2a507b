//! `FccRepMatch`: the run slots a pixel names in `FccRowReps`'s `K`
//! window rows, as a mask (combinational; docs/column-core.md, item 3,
//! "How the next pixel sees the rewrite"). Each hit's label was compared
//! with its row's `h + 1` runs' a cycle before (`FccRepEq`, registered);
//! the newest match wins (a label freed and reused names the newer run).
//! The pixel's own run is the one it pushed if it starts one (its row's
//! newest), else its label's newest match in the centre row.
//!
//! * In: the window rows' ages (row `w` is `i - h + w`; run slot `k` of
//!   row `w` at `w * (h + 1) + k`), and per entry of `FccColWindow`'s order
//!   (line `r`, position `p`: row `p` for `p < h`, `p + 1` after, at
//!   `r (K - 1) + p`; then row `h - m` of the pixel's column at
//!   `2 h^2 + m - 1`) its hit and its label's matches `eq`.
//! * Out: `mask`, by run slot; `miss`: a labelled pixel whose own label or
//!   hit's label its row does not hold (a broken invariant: the bench
//!   checks it never is).

use rust_hdl::prelude::*;

use super::REP_AGE_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepMatch {
    pub age: Vec<Signal<In, Bits<REP_AGE_BITS>>>,
    pub lok: Signal<In, Bit>,
    /// The pixel starts a run (pushed into the centre row).
    pub start: Signal<In, Bit>,
    pub ent_hit: Vec<Signal<In, Bit>>,
    /// Entry `e`'s label equals run slot `k` of its row, at `e * (h + 1) +
    /// k`; the pixel's own label, the centre row's slot `k`.
    pub eq: Vec<Signal<In, Bit>>,
    pub own_eq: Vec<Signal<In, Bit>>,
    pub mask: Vec<Signal<Out, Bit>>,
    pub miss: Signal<Out, Bit>,
    /// Row `w`'s run slot `k` is newer than its slot `k2`, at
    /// `(w * (h + 1) + k) * (h + 1) + k2`.
    newer: Vec<Signal<Local, Bit>>,
    /// Entry `e`'s newest match; any.
    found: Vec<Signal<Local, Bit>>,
    any: Vec<Signal<Local, Bit>>,
    /// The pixel's own run slot; any.
    own_found: Vec<Signal<Local, Bit>>,
    own_any: Signal<Local, Bit>,
    zero_age: Constant<Bits<REP_AGE_BITS>>,
    _k: usize,
    _h: usize,
    _n: usize,
    /// `2 h^2`: the first entry of the pixel's own column.
    _same: usize,
}

impl FccRepMatch {
    /// The window of filter size `k`.
    pub fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let ne = k * h;
        Self {
            age: vec_of(k * n),
            lok: Default::default(),
            start: Default::default(),
            ent_hit: vec_of(ne),
            eq: vec_of(ne * n),
            own_eq: vec_of(n),
            mask: vec_of(k * n),
            miss: Default::default(),
            newer: vec_of(k * n * n),
            found: vec_of(ne * n),
            any: vec_of(ne),
            own_found: vec_of(n),
            own_any: Default::default(),
            zero_age: kb(0),
            _k: k,
            _h: h,
            _n: n,
            _same: 2 * h * h,
        }
    }
}

impl Logic for FccRepMatch {
    #[hdl_gen]
    fn update(&mut self) {
        for nn in self._n..(self._n + 1) {
            // Which run slot is newer than which, per row.
            for w in 0..self._k {
                for k in 0..self._n {
                    for k2 in 0..self._n {
                        self.newer[(w * nn + k) * nn + k2].next =
                            self.age[w * nn + k].val() < self.age[w * nn + k2].val();
                    }
                }
            }
            for w in 0..self.mask.len() {
                self.mask[w].next = false;
            }
            // The newest match of each entry (`newer` of its row).
            for km in (self._k - 1)..self._k {
                for r in 0..self._h {
                    for p in 0..self._h {
                        for k in 0..self._n {
                            self.found[(r * km + p) * nn + k].next =
                                self.eq[(r * km + p) * nn + k].val();
                            for k2 in 0..self._n {
                                if self.eq[(r * km + p) * nn + k2].val()
                                    & self.newer[(p * nn + k2) * nn + k].val()
                                {
                                    self.found[(r * km + p) * nn + k].next = false;
                                }
                            }
                        }
                    }
                    for p in self._h..(self._k - 1) {
                        for k in 0..self._n {
                            self.found[(r * km + p) * nn + k].next =
                                self.eq[(r * km + p) * nn + k].val();
                            for k2 in 0..self._n {
                                if self.eq[(r * km + p) * nn + k2].val()
                                    & self.newer[((p + 1) * nn + k2) * nn + k].val()
                                {
                                    self.found[(r * km + p) * nn + k].next = false;
                                }
                            }
                        }
                    }
                }
            }
            for q in self._same..(self._same + 1) {
                for hh in self._h..(self._h + 1) {
                    for m in 1..(self._h + 1) {
                        for k in 0..self._n {
                            self.found[(q + m - 1) * nn + k].next =
                                self.eq[(q + m - 1) * nn + k].val();
                            for k2 in 0..self._n {
                                if self.eq[(q + m - 1) * nn + k2].val()
                                    & self.newer[((hh - m) * nn + k2) * nn + k].val()
                                {
                                    self.found[(q + m - 1) * nn + k].next = false;
                                }
                            }
                        }
                    }
                }
            }
            // The mask: every hit's run slot, and the pixel's own.
            self.miss.next = false;
            for e in 0..self.ent_hit.len() {
                self.any[e].next = false;
                for k in 0..self._n {
                    if self.eq[e * nn + k].val() {
                        self.any[e].next = true;
                    }
                }
                if self.lok.val() & self.ent_hit[e].val() & !self.any[e].val() {
                    self.miss.next = true;
                }
            }
            for km in (self._k - 1)..self._k {
                for r in 0..self._h {
                    for p in 0..self._h {
                        for k in 0..self._n {
                            if self.lok.val()
                                & self.ent_hit[r * km + p].val()
                                & self.found[(r * km + p) * nn + k].val()
                            {
                                self.mask[p * nn + k].next = true;
                            }
                        }
                    }
                    for p in self._h..(self._k - 1) {
                        for k in 0..self._n {
                            if self.lok.val()
                                & self.ent_hit[r * km + p].val()
                                & self.found[(r * km + p) * nn + k].val()
                            {
                                self.mask[(p + 1) * nn + k].next = true;
                            }
                        }
                    }
                }
            }
            for q in self._same..(self._same + 1) {
                for hh in self._h..(self._h + 1) {
                    for m in 1..(self._h + 1) {
                        for k in 0..self._n {
                            if self.lok.val()
                                & self.ent_hit[q + m - 1].val()
                                & self.found[(q + m - 1) * nn + k].val()
                            {
                                self.mask[(hh - m) * nn + k].next = true;
                            }
                        }
                    }
                    // The pixel's own run: the run it pushed if it starts
                    // one (the centre row's newest), else its label among
                    // the centre row's, the newest first.
                    self.own_any.next = false;
                    for k in 0..self._n {
                        if self.own_eq[k].val() {
                            self.own_any.next = true;
                        }
                        self.own_found[k].next = self.own_eq[k].val();
                        for k2 in 0..self._n {
                            if self.own_eq[k2].val() & self.newer[(hh * nn + k2) * nn + k].val() {
                                self.own_found[k].next = false;
                            }
                        }
                        if self.start.val() {
                            self.own_found[k].next =
                                self.age[hh * nn + k].val() == self.zero_age.val();
                            self.own_any.next = true;
                        }
                        if self.lok.val() & self.own_found[k].val() {
                            self.mask[hh * nn + k].next = true;
                        }
                    }
                    if self.lok.val() & !self.own_any.val() {
                        self.miss.next = true;
                    }
                }
            }
        }
    }
}
