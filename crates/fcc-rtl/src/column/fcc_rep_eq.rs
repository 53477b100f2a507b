//! `FccRepEq`: each window entry's label against its row's `h + 1` run
//! slots, and the pixel's own against the centre row's (combinational;
//! docs/column-core.md, item 3). It works a cycle ahead of `FccRepMatch`,
//! on the rows as they will be after the window shifts for the pixel (the
//! window's rows one place up, the table's head row last), so that the
//! match takes registers only. A run the pixel pushes is not among these
//! labels: `FccRepMatch` takes it by age, and no hit names it.
//!
//! Indices as `FccRepMatch`'s: run slot `k` of row `w` at `w (h + 1) + k`;
//! out, entry `e` against slot `k` of its row at `e (h + 1) + k`.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepEq {
    pub label: Vec<Signal<In, Bits<16>>>,
    pub ent_label: Vec<Signal<In, Bits<16>>>,
    pub own_label: Signal<In, Bits<16>>,
    pub eq: Vec<Signal<Out, Bit>>,
    pub own_eq: Vec<Signal<Out, Bit>>,
    _k: usize,
    _h: usize,
    _n: usize,
    /// `2 h^2`: the first entry of the pixel's own column.
    _same: usize,
}

impl FccRepEq {
    /// The window of filter size `k`.
    pub fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let ne = k * h;
        Self {
            label: vec_of(k * n),
            ent_label: vec_of(ne),
            own_label: Default::default(),
            eq: vec_of(ne * n),
            own_eq: vec_of(n),
            _k: k,
            _h: h,
            _n: n,
            _same: 2 * h * h,
        }
    }
}

impl Logic for FccRepEq {
    #[hdl_gen]
    fn update(&mut self) {
        for nn in self._n..(self._n + 1) {
            // Entries: each compared with its row's run slots.
            for km in (self._k - 1)..self._k {
                for r in 0..self._h {
                    for p in 0..self._h {
                        for k in 0..self._n {
                            self.eq[(r * km + p) * nn + k].next =
                                self.ent_label[r * km + p].val() == self.label[p * nn + k].val();
                        }
                    }
                    for p in self._h..(self._k - 1) {
                        for k in 0..self._n {
                            self.eq[(r * km + p) * nn + k].next = self.ent_label[r * km + p].val()
                                == self.label[(p + 1) * nn + k].val();
                        }
                    }
                }
            }
            for q in self._same..(self._same + 1) {
                for hh in self._h..(self._h + 1) {
                    for m in 1..(self._h + 1) {
                        for k in 0..self._n {
                            self.eq[(q + m - 1) * nn + k].next = self.ent_label[q + m - 1].val()
                                == self.label[(hh - m) * nn + k].val();
                        }
                    }
                }
            }
            for hh in self._h..(self._h + 1) {
                for k in 0..self._n {
                    self.own_eq[k].next = self.own_label.val() == self.label[hh * nn + k].val();
                }
            }
        }
    }
}
