//! `FccRootWindow`: the row roots of the `K` rows around the pixel at the
//! slot table (rows `i - h ..= i + h`, position `j` holding row `i - h + j`),
//! a shift register beside `FccRootTable`. Each position holds what the
//! table holds for its row: the labels of the row's last `h + 1` runs,
//! newest first, their clusters' slots, and the slot of the row's first
//! run's cluster.
//!
//! `shift` moves the window one row on as the next pixel arrives: position
//! `j` takes position `j + 1`'s entries, the last position the table's row
//! `(i + 1 + h) mod R` (`load_*`, read a cycle before and kept current, so
//! taken as it is). Rows past the frame's last row are the
//! next column's first rows, so the window runs on from column to column;
//! positions outside the frame are never read (`FccColEdge` masks them).
//! A run that the pixel moving into the centre starts is pushed in front
//! of its row's entries as they shift into the centre position (`push`,
//! `push_first` as in `FccRootTable`; only with `shift`). A merge being broadcast (`rw_*`) rewrites every
//! slot at the edge, as in the table, so positions never hold a slot that
//! merged away.

use rust_hdl::prelude::*;

use super::SLOT_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRootWindow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub shift: Signal<In, Bit>,
    pub load_label: Vec<Signal<In, Bits<16>>>,
    pub load_slot: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub load_first: Signal<In, Bits<SLOT_BITS>>,
    pub push: Signal<In, Bit>,
    pub push_first: Signal<In, Bit>,
    pub push_label: Signal<In, Bits<16>>,
    pub push_slot: Signal<In, Bits<SLOT_BITS>>,
    pub rw_valid: Signal<In, Bit>,
    pub rw_from: Signal<In, Bits<SLOT_BITS>>,
    pub rw_into: Signal<In, Bits<SLOT_BITS>>,
    /// Position `j`'s entry `k` at `j * (h + 1) + k`; the centre's first.
    pub label: Vec<Signal<Out, Bits<16>>>,
    pub slot: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    pub centre_first: Signal<Out, Bits<SLOT_BITS>>,
    label_q: Vec<DFF<Bits<16>>>,
    slot_q: Vec<DFF<Bits<SLOT_BITS>>>,
    first_q: Vec<DFF<Bits<SLOT_BITS>>>,
    slot_nx: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    first_nx: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    zero16: Constant<Bits<16>>,
    _k: usize,
    _h: usize,
    _n: usize,
}

impl FccRootWindow {
    /// `k` positions of `h + 1` entries.
    pub fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            shift: Default::default(),
            load_label: vec_of(n),
            load_slot: vec_of(n),
            load_first: Default::default(),
            push: Default::default(),
            push_first: Default::default(),
            push_label: Default::default(),
            push_slot: Default::default(),
            rw_valid: Default::default(),
            rw_from: Default::default(),
            rw_into: Default::default(),
            label: vec_of(k * n),
            slot: vec_of(k * n),
            centre_first: Default::default(),
            label_q: vec_of(k * n),
            slot_q: vec_of(k * n),
            first_q: vec_of(k),
            slot_nx: vec_of(k * n),
            first_nx: vec_of(k),
            zero16: kb(0),
            _k: k,
            _h: h,
            _n: n,
        }
    }
}

impl Logic for FccRootWindow {
    #[hdl_gen]
    fn update(&mut self) {
        for nn in self._n..(self._n + 1) {
            for hh in self._h..(self._h + 1) {
                // Hold, or shift one position on (the last loads).
                for j in 0..self._k {
                    self.first_q[j].clock.next = self.clk.val();
                    self.first_nx[j].next = self.first_q[j].q.val();
                    for k in 0..self._n {
                        self.label_q[j * nn + k].clock.next = self.clk.val();
                        self.slot_q[j * nn + k].clock.next = self.clk.val();
                        self.label_q[j * nn + k].d.next = self.label_q[j * nn + k].q.val();
                        self.slot_nx[j * nn + k].next = self.slot_q[j * nn + k].q.val();
                        self.label[j * nn + k].next = self.label_q[j * nn + k].q.val();
                        self.slot[j * nn + k].next = self.slot_q[j * nn + k].q.val();
                    }
                }
                if self.shift.val() {
                    for j in 0..(self._k - 1) {
                        self.first_nx[j].next = self.first_q[j + 1].q.val();
                        for k in 0..self._n {
                            self.label_q[j * nn + k].d.next =
                                self.label_q[(j + 1) * nn + k].q.val();
                            self.slot_nx[j * nn + k].next = self.slot_q[(j + 1) * nn + k].q.val();
                        }
                    }
                    for j in (self._k - 1)..self._k {
                        self.first_nx[j].next = self.load_first.val();
                        for k in 0..self._n {
                            self.label_q[j * nn + k].d.next = self.load_label[k].val();
                            self.slot_nx[j * nn + k].next = self.load_slot[k].val();
                        }
                    }
                }
                self.centre_first.next = self.first_q[hh].q.val();
                // A run the entering pixel starts goes in front of its row's
                // entries, which shift into the centre.
                if self.push.val() & self.shift.val() {
                    self.label_q[hh * nn].d.next = self.push_label.val();
                    self.slot_nx[hh * nn].next = self.push_slot.val();
                    for k in 1..self._n {
                        self.label_q[hh * nn + k].d.next =
                            self.label_q[(hh + 1) * nn + k - 1].q.val();
                        self.slot_nx[hh * nn + k].next = self.slot_q[(hh + 1) * nn + k - 1].q.val();
                    }
                    if self.push_first.val() {
                        self.first_nx[hh].next = self.push_slot.val();
                    }
                }
                // The merge's rewrite, then the reset.
                for j in 0..self._k {
                    self.first_q[j].d.next = self.first_nx[j].val();
                    if self.rw_valid.val() & (self.first_nx[j].val() == self.rw_from.val()) {
                        self.first_q[j].d.next = self.rw_into.val();
                    }
                    for k in 0..self._n {
                        self.slot_q[j * nn + k].d.next = self.slot_nx[j * nn + k].val();
                        if self.rw_valid.val()
                            & (self.slot_nx[j * nn + k].val() == self.rw_from.val())
                        {
                            self.slot_q[j * nn + k].d.next = self.rw_into.val();
                        }
                        if self.rst.val() {
                            self.label_q[j * nn + k].d.next = self.zero16.val();
                        }
                    }
                }
                // The row loaded is current already (no rewrite on its way in).
                if self.shift.val() {
                    for j in (self._k - 1)..self._k {
                        self.first_q[j].d.next = self.load_first.val();
                        for k in 0..self._n {
                            self.slot_q[j * nn + k].d.next = self.load_slot[k].val();
                        }
                    }
                }
            }
        }
    }
}
