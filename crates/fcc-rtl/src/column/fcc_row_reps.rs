//! `FccRowReps`: the representative rows of the `K` rows around the
//! pixel, and the `S` rows above them not yet written back, in flip-flops
//! (docs/column-core.md, item 3, "How the next pixel sees the rewrite").
//! Position `j` holds row `i - h - S + j`; the centre is position
//! `S + h`. Each position holds its row's last `h + 1` runs in `h + 1` run
//! slots: each run's label, representative and age (0 the newest, `h` the
//! oldest, all different). A run pushed takes the oldest run's slot and
//! the others age by one, so no run moves: a pixel in flight names run
//! slots by position (a mask), and the positions stay true until the
//! window shifts (the masks shift with it).
//!
//! * `shift` moves the window one row on: position `j` takes position
//!   `j + 1`'s, the last position the row `load_*` (the table's), and
//!   position 0's row leaves as `wb_*` (to be written back to the table,
//!   this cycle's rewrite applied).
//! * `push` (with `shift` only): the pixel moving into the centre starts a
//!   run, with its label (`push_label`) and representative (`push_rep`:
//!   its label, or `0xFFFF` until the pixel's minimum rewrites it when it
//!   names other runs).
//! * `rw_valid`: the representatives at the positions of `rw_mask`
//!   (position `j`'s run slot `k` at `j * (h + 1) + k`, as the window is
//!   this cycle) become `rw_rep`, at the edge, before the shift moves them;
//!   `rep_next` shows them with the rewrite.
//!
//! `rst` empties every row (labels 0, which no hit names; ages by slot).
//! After that, a hit names a run pushed during the frame, found newest
//! first before anything left from an earlier frame.

use rust_hdl::prelude::*;

use super::REP_AGE_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRowReps {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub shift: Signal<In, Bit>,
    pub load_label: Vec<Signal<In, Bits<16>>>,
    pub load_rep: Vec<Signal<In, Bits<16>>>,
    pub load_age: Vec<Signal<In, Bits<REP_AGE_BITS>>>,
    pub push: Signal<In, Bit>,
    pub push_label: Signal<In, Bits<16>>,
    pub push_rep: Signal<In, Bits<16>>,
    pub rw_valid: Signal<In, Bit>,
    pub rw_mask: Vec<Signal<In, Bit>>,
    pub rw_rep: Signal<In, Bits<16>>,
    /// Position `j`'s run slot `k` at `j * (h + 1) + k`.
    pub label: Vec<Signal<Out, Bits<16>>>,
    pub rep: Vec<Signal<Out, Bits<16>>>,
    pub rep_next: Vec<Signal<Out, Bits<16>>>,
    pub age: Vec<Signal<Out, Bits<REP_AGE_BITS>>>,
    /// Position 0's row, leaving when `shift`.
    pub wb_label: Vec<Signal<Out, Bits<16>>>,
    pub wb_rep: Vec<Signal<Out, Bits<16>>>,
    pub wb_age: Vec<Signal<Out, Bits<REP_AGE_BITS>>>,
    label_q: Vec<DFF<Bits<16>>>,
    rep_q: Vec<DFF<Bits<16>>>,
    age_q: Vec<DFF<Bits<REP_AGE_BITS>>>,
    /// The representatives with this cycle's rewrite.
    rep_rw: Vec<Signal<Local, Bits<16>>>,
    oldest: Constant<Bits<REP_AGE_BITS>>,
    zero_age: Constant<Bits<REP_AGE_BITS>>,
    zero16: Constant<Bits<16>>,
    one_age: Constant<Bits<REP_AGE_BITS>>,
    /// Run slot numbers, `0 ..= h` (a row's ages after a reset).
    slot_no: Vec<Constant<Bits<REP_AGE_BITS>>>,
    /// Positions, `K + S`.
    _p: usize,
    /// The centre position, `S + h`.
    _c: usize,
    /// Run slots a row, `h + 1`.
    _n: usize,
}

impl FccRowReps {
    /// Filter size `k`, `s` rows kept above the window.
    pub fn new(k: usize, s: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let p = k + s;
        assert!(n <= 1 << REP_AGE_BITS, "K = {k}: {n} run slots a row");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            shift: Default::default(),
            load_label: vec_of(n),
            load_rep: vec_of(n),
            load_age: vec_of(n),
            push: Default::default(),
            push_label: Default::default(),
            push_rep: Default::default(),
            rw_valid: Default::default(),
            rw_mask: vec_of(p * n),
            rw_rep: Default::default(),
            label: vec_of(p * n),
            rep: vec_of(p * n),
            rep_next: vec_of(p * n),
            age: vec_of(p * n),
            wb_label: vec_of(n),
            wb_rep: vec_of(n),
            wb_age: vec_of(n),
            label_q: vec_of(p * n),
            rep_q: vec_of(p * n),
            age_q: vec_of(p * n),
            rep_rw: vec_of(p * n),
            oldest: kb((n - 1) as u64),
            zero_age: kb(0),
            zero16: kb(0),
            one_age: kb(1),
            slot_no: (0..n).map(|k| kb(k as u64)).collect(),
            _p: p,
            _c: s + h,
            _n: n,
        }
    }
}

impl Logic for FccRowReps {
    #[hdl_gen]
    fn update(&mut self) {
        for nn in self._n..(self._n + 1) {
            for j in 0..self._p {
                for k in 0..self._n {
                    self.label_q[j * nn + k].clock.next = self.clk.val();
                    self.rep_q[j * nn + k].clock.next = self.clk.val();
                    self.age_q[j * nn + k].clock.next = self.clk.val();
                    self.label[j * nn + k].next = self.label_q[j * nn + k].q.val();
                    self.rep[j * nn + k].next = self.rep_q[j * nn + k].q.val();
                    self.age[j * nn + k].next = self.age_q[j * nn + k].q.val();
                    self.rep_rw[j * nn + k].next = self.rep_q[j * nn + k].q.val();
                    if self.rw_valid.val() & self.rw_mask[j * nn + k].val() {
                        self.rep_rw[j * nn + k].next = self.rw_rep.val();
                    }
                    self.rep_next[j * nn + k].next = self.rep_rw[j * nn + k].val();
                    self.label_q[j * nn + k].d.next = self.label_q[j * nn + k].q.val();
                    self.rep_q[j * nn + k].d.next = self.rep_rw[j * nn + k].val();
                    self.age_q[j * nn + k].d.next = self.age_q[j * nn + k].q.val();
                }
            }
            for k in 0..self._n {
                self.wb_label[k].next = self.label_q[k].q.val();
                self.wb_rep[k].next = self.rep_rw[k].val();
                self.wb_age[k].next = self.age_q[k].q.val();
            }
            if self.shift.val() {
                for j in 0..(self._p - 1) {
                    for k in 0..self._n {
                        self.label_q[j * nn + k].d.next = self.label_q[(j + 1) * nn + k].q.val();
                        self.rep_q[j * nn + k].d.next = self.rep_rw[(j + 1) * nn + k].val();
                        self.age_q[j * nn + k].d.next = self.age_q[(j + 1) * nn + k].q.val();
                    }
                }
                for j in (self._p - 1)..self._p {
                    for k in 0..self._n {
                        self.label_q[j * nn + k].d.next = self.load_label[k].val();
                        self.rep_q[j * nn + k].d.next = self.load_rep[k].val();
                        self.age_q[j * nn + k].d.next = self.load_age[k].val();
                    }
                }
            }
            // A push: the entering row's oldest slot takes the run, the
            // others age by one.
            for c in self._c..(self._c + 1) {
                if self.push.val() & self.shift.val() {
                    for k in 0..self._n {
                        self.age_q[c * nn + k].d.next =
                            self.age_q[(c + 1) * nn + k].q.val() + self.one_age.val();
                        if self.age_q[(c + 1) * nn + k].q.val() == self.oldest.val() {
                            self.label_q[c * nn + k].d.next = self.push_label.val();
                            self.rep_q[c * nn + k].d.next = self.push_rep.val();
                            self.age_q[c * nn + k].d.next = self.zero_age.val();
                        }
                    }
                }
            }
            if self.rst.val() {
                for j in 0..self._p {
                    for k in 0..self._n {
                        self.label_q[j * nn + k].d.next = self.zero16.val();
                        self.rep_q[j * nn + k].d.next = self.zero16.val();
                        self.age_q[j * nn + k].d.next = self.slot_no[k].val();
                    }
                }
            }
        }
    }
}
