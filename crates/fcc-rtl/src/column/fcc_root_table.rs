//! `FccRootTable`: the row roots of the column core (docs/column-core.md),
//! one entry per row of the build: the labels of the row's last `h + 1`
//! labelled runs, newest first, the record slot of each one's cluster, and
//! the slot of the row's first run's cluster (the ring check's, spec §3).
//!
//! Everything is in flip-flops so that a merge rewrites every slot at once:
//! while `rw_valid`, each slot equal to `rw_from` becomes `rw_into` at the
//! clock edge, whatever else the edge writes (a pushed slot included). A
//! `push` puts a run that starts in row `push_row` in front of the row's
//! entries (the oldest drops out); `push_first` also makes it the row's
//! first run. `rd_row` reads one row's entries (combinational, before the
//! edge's rewrite): `FccRootWindow` loads the row that enters its window.
//! Label 0 is no run (a reset clears every entry).

use rust_hdl::prelude::*;

use super::SLOT_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRootTable {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // A run starts: its row, label and cluster's slot.
    pub push: Signal<In, Bit>,
    pub push_first: Signal<In, Bit>,
    pub push_row: Signal<In, Bits<7>>,
    pub push_label: Signal<In, Bits<16>>,
    pub push_slot: Signal<In, Bits<SLOT_BITS>>,
    // The merge being broadcast.
    pub rw_valid: Signal<In, Bit>,
    pub rw_from: Signal<In, Bits<SLOT_BITS>>,
    pub rw_into: Signal<In, Bits<SLOT_BITS>>,
    // One row's entries.
    pub rd_row: Signal<In, Bits<7>>,
    pub rd_label: Vec<Signal<Out, Bits<16>>>,
    pub rd_slot: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    pub rd_first: Signal<Out, Bits<SLOT_BITS>>,
    /// Row `r`'s entry `k` at `r * (h + 1) + k`.
    label: Vec<DFF<Bits<16>>>,
    slot: Vec<DFF<Bits<SLOT_BITS>>>,
    first: Vec<DFF<Bits<SLOT_BITS>>>,
    /// Each slot before the rewrite.
    slot_nx: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    first_nx: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    /// The read: row selected, masked entries, their running OR.
    sel: Vec<Signal<Local, Bit>>,
    m_label: Vec<Signal<Local, Bits<16>>>,
    m_slot: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    m_first: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    a_label: Vec<Signal<Local, Bits<16>>>,
    a_slot: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    a_first: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    row_id: Vec<Constant<Bits<7>>>,
    zero16: Constant<Bits<16>>,
    zero_slot: Constant<Bits<SLOT_BITS>>,
    _n: usize,
}

impl FccRootTable {
    /// `rows` rows of `n` (`h + 1`) entries.
    pub fn new(rows: usize, n: usize) -> Self {
        assert!(rows <= 128 && n >= 2);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            push: Default::default(),
            push_first: Default::default(),
            push_row: Default::default(),
            push_label: Default::default(),
            push_slot: Default::default(),
            rw_valid: Default::default(),
            rw_from: Default::default(),
            rw_into: Default::default(),
            rd_row: Default::default(),
            rd_label: vec_of(n),
            rd_slot: vec_of(n),
            rd_first: Default::default(),
            label: vec_of(rows * n),
            slot: vec_of(rows * n),
            first: vec_of(rows),
            slot_nx: vec_of(rows * n),
            first_nx: vec_of(rows),
            sel: vec_of(rows),
            m_label: vec_of(rows * n),
            m_slot: vec_of(rows * n),
            m_first: vec_of(rows),
            a_label: vec_of(rows * n),
            a_slot: vec_of(rows * n),
            a_first: vec_of(rows),
            row_id: (0..rows).map(|r| kb(r as u64)).collect(),
            zero16: kb(0),
            zero_slot: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccRootTable {
    #[hdl_gen]
    fn update(&mut self) {
        for nn in self._n..(self._n + 1) {
            for r in 0..self.row_id.len() {
                self.first[r].clock.next = self.clk.val();
                self.first_nx[r].next = self.first[r].q.val();
                if self.push.val()
                    & self.push_first.val()
                    & (self.push_row.val() == self.row_id[r].val())
                {
                    self.first_nx[r].next = self.push_slot.val();
                }
                self.first[r].d.next = self.first_nx[r].val();
                if self.rw_valid.val() & (self.first_nx[r].val() == self.rw_from.val()) {
                    self.first[r].d.next = self.rw_into.val();
                }
                for k in 0..self._n {
                    self.label[r * nn + k].clock.next = self.clk.val();
                    self.slot[r * nn + k].clock.next = self.clk.val();
                    self.label[r * nn + k].d.next = self.label[r * nn + k].q.val();
                    self.slot_nx[r * nn + k].next = self.slot[r * nn + k].q.val();
                }
                if self.push.val() & (self.push_row.val() == self.row_id[r].val()) {
                    self.label[r * nn].d.next = self.push_label.val();
                    self.slot_nx[r * nn].next = self.push_slot.val();
                    for k in 1..self._n {
                        self.label[r * nn + k].d.next = self.label[r * nn + k - 1].q.val();
                        self.slot_nx[r * nn + k].next = self.slot[r * nn + k - 1].q.val();
                    }
                }
                for k in 0..self._n {
                    self.slot[r * nn + k].d.next = self.slot_nx[r * nn + k].val();
                    if self.rw_valid.val() & (self.slot_nx[r * nn + k].val() == self.rw_from.val())
                    {
                        self.slot[r * nn + k].d.next = self.rw_into.val();
                    }
                    if self.rst.val() {
                        self.label[r * nn + k].d.next = self.zero16.val();
                    }
                }
            }
        }
        // The read: one row selected, an OR of the masked rows (a tree, not
        // a chain of multiplexers).
        for nn in self._n..(self._n + 1) {
            for r in 0..self.row_id.len() {
                self.sel[r].next = self.rd_row.val() == self.row_id[r].val();
                self.m_first[r].next = self.zero_slot.val();
                if self.sel[r].val() {
                    self.m_first[r].next = self.first[r].q.val();
                }
                for k in 0..self._n {
                    self.m_label[r * nn + k].next = self.zero16.val();
                    self.m_slot[r * nn + k].next = self.zero_slot.val();
                    if self.sel[r].val() {
                        self.m_label[r * nn + k].next = self.label[r * nn + k].q.val();
                        self.m_slot[r * nn + k].next = self.slot[r * nn + k].q.val();
                    }
                }
            }
            self.a_first[0].next = self.m_first[0].val();
            for k in 0..self._n {
                self.a_label[k].next = self.m_label[k].val();
                self.a_slot[k].next = self.m_slot[k].val();
            }
            for r in 1..self.row_id.len() {
                self.a_first[r].next = self.a_first[r - 1].val() | self.m_first[r].val();
                for k in 0..self._n {
                    self.a_label[r * nn + k].next =
                        self.a_label[(r - 1) * nn + k].val() | self.m_label[r * nn + k].val();
                    self.a_slot[r * nn + k].next =
                        self.a_slot[(r - 1) * nn + k].val() | self.m_slot[r * nn + k].val();
                }
            }
            for last in (self.row_id.len() - 1)..self.row_id.len() {
                self.rd_first.next = self.a_first[last].val();
                for k in 0..self._n {
                    self.rd_label[k].next = self.a_label[last * nn + k].val();
                    self.rd_slot[k].next = self.a_slot[last * nn + k].val();
                }
            }
        }
    }
}
