//! `FccRootMatch`: the clusters (record slots) of everything a pixel at the
//! slot table names by label, looked up in `FccRootWindow`'s rows
//! (combinational). A label is looked for among its row's last `h + 1`
//! runs, the newest first (a label reused since an older run of the row
//! closed names the newer run); a window row spans `h + 1` columns, so a
//! run the window holds is always among them.
//!
//! * Entry `e` of `FccColWindow`'s order (line `r`, position `p`: rows
//!   `i - h + p`, `p < h`, and `i - h + p + 1` after; then row `i - m` of the
//!   pixel's column at `2h^2 + m - 1`): `ent_ok` (a hit whose run was found)
//!   and `ent_slot`.
//! * The pixel's own run (`own_slot`: `new_slot` for a run that starts), the
//!   runs its row stops and starts holding (`drop_*`, `add_*`, spec §9.2)
//!   and the ring check's (`ring_a`: the row's first run; `ring_b`), all in
//!   the centre row, where a starting run is looked up first.
//!
//! Every slot out is the one after the merge being broadcast (`rw_*`), which
//! the window rewrites only at the edge. `miss` says some label named was not
//! found (a broken invariant: the bench checks it never is).

use rust_hdl::prelude::*;

use super::SLOT_BITS;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRootMatch {
    // The window's rows.
    pub label: Vec<Signal<In, Bits<16>>>,
    pub slot: Vec<Signal<In, Bits<SLOT_BITS>>>,
    pub centre_first: Signal<In, Bits<SLOT_BITS>>,
    // The pixel.
    pub lok: Signal<In, Bit>,
    pub own_label: Signal<In, Bits<16>>,
    pub start: Signal<In, Bit>,
    pub new_slot: Signal<In, Bits<SLOT_BITS>>,
    pub drop_label: Signal<In, Bits<16>>,
    pub add_label: Signal<In, Bits<16>>,
    pub ring: Signal<In, Bit>,
    pub ring_b_label: Signal<In, Bits<16>>,
    pub ent_hit: Vec<Signal<In, Bit>>,
    pub ent_label: Vec<Signal<In, Bits<16>>>,
    pub rw_valid: Signal<In, Bit>,
    pub rw_from: Signal<In, Bits<SLOT_BITS>>,
    pub rw_into: Signal<In, Bits<SLOT_BITS>>,
    // The slots.
    pub ent_ok: Vec<Signal<Out, Bit>>,
    pub ent_slot: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    pub own_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub drop_ok: Signal<Out, Bit>,
    pub drop_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub add_ok: Signal<Out, Bit>,
    pub add_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ring_a_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ring_b_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub miss: Signal<Out, Bit>,
    ent_found: Vec<Signal<Local, Bit>>,
    ent_raw: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    /// The centre row's lookups: own, drop, add, ring_b.
    c_found: Vec<Signal<Local, Bit>>,
    c_raw: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    c_label: Vec<Signal<Local, Bits<16>>>,
    c_out: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    zero16: Constant<Bits<16>>,
    zero_slot: Constant<Bits<SLOT_BITS>>,
    _k: usize,
    _h: usize,
    _n: usize,
    /// `2 h^2`: the first entry of the pixel's own column.
    _same: usize,
}

impl FccRootMatch {
    /// The window of filter size `k`.
    pub fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let ne = k * h;
        Self {
            label: vec_of(k * n),
            slot: vec_of(k * n),
            centre_first: Default::default(),
            lok: Default::default(),
            own_label: Default::default(),
            start: Default::default(),
            new_slot: Default::default(),
            drop_label: Default::default(),
            add_label: Default::default(),
            ring: Default::default(),
            ring_b_label: Default::default(),
            ent_hit: vec_of(ne),
            ent_label: vec_of(ne),
            rw_valid: Default::default(),
            rw_from: Default::default(),
            rw_into: Default::default(),
            ent_ok: vec_of(ne),
            ent_slot: vec_of(ne),
            own_slot: Default::default(),
            drop_ok: Default::default(),
            drop_slot: Default::default(),
            add_ok: Default::default(),
            add_slot: Default::default(),
            ring_a_slot: Default::default(),
            ring_b_slot: Default::default(),
            miss: Default::default(),
            ent_found: vec_of(ne),
            ent_raw: vec_of(ne),
            c_found: vec_of(4),
            c_raw: vec_of(4),
            c_label: vec_of(4),
            c_out: vec_of(4),
            zero16: kb(0),
            zero_slot: kb(0),
            _k: k,
            _h: h,
            _n: n,
            _same: 2 * h * h,
        }
    }
}

impl Logic for FccRootMatch {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self.ent_hit.len() {
            self.ent_found[e].next = false;
            self.ent_raw[e].next = self.zero_slot.val();
        }
        for nn in self._n..(self._n + 1) {
            for km in (self._k - 1)..self._k {
                for hh in self._h..(self._h + 1) {
                    // Lines: each position's row, oldest first, so the newest
                    // (entry 0) wins.
                    for r in 0..self._h {
                        for p in 0..self._h {
                            for k in 0..self._n {
                                if self.ent_label[r * km + p].val()
                                    == self.label[p * nn + nn - 1 - k].val()
                                {
                                    self.ent_found[r * km + p].next = true;
                                    self.ent_raw[r * km + p].next =
                                        self.slot[p * nn + nn - 1 - k].val();
                                }
                            }
                        }
                        for p in self._h..(self._k - 1) {
                            for k in 0..self._n {
                                if self.ent_label[r * km + p].val()
                                    == self.label[(p + 1) * nn + nn - 1 - k].val()
                                {
                                    self.ent_found[r * km + p].next = true;
                                    self.ent_raw[r * km + p].next =
                                        self.slot[(p + 1) * nn + nn - 1 - k].val();
                                }
                            }
                        }
                    }
                    // The pixel's own column: row i - m.
                    for q in self._same..(self._same + 1) {
                        for m in 1..(self._h + 1) {
                            for k in 0..self._n {
                                if self.ent_label[q + m - 1].val()
                                    == self.label[(hh - m) * nn + nn - 1 - k].val()
                                {
                                    self.ent_found[q + m - 1].next = true;
                                    self.ent_raw[q + m - 1].next =
                                        self.slot[(hh - m) * nn + nn - 1 - k].val();
                                }
                            }
                        }
                    }
                    // The centre row: own, drop, add, ring_b; a starting run first.
                    self.c_label[0].next = self.own_label.val();
                    self.c_label[1].next = self.drop_label.val();
                    self.c_label[2].next = self.add_label.val();
                    self.c_label[3].next = self.ring_b_label.val();
                    for c in 0..4 {
                        self.c_found[c].next = false;
                        self.c_raw[c].next = self.zero_slot.val();
                        for k in 0..self._n {
                            if self.c_label[c].val() == self.label[hh * nn + nn - 1 - k].val() {
                                self.c_found[c].next = true;
                                self.c_raw[c].next = self.slot[hh * nn + nn - 1 - k].val();
                            }
                        }
                        if self.start.val() & (self.c_label[c].val() == self.own_label.val()) {
                            self.c_found[c].next = true;
                            self.c_raw[c].next = self.new_slot.val();
                        }
                        self.c_out[c].next = self.c_raw[c].val();
                        if self.rw_valid.val() & (self.c_raw[c].val() == self.rw_from.val()) {
                            self.c_out[c].next = self.rw_into.val();
                        }
                    }
                }
            }
        }
        self.own_slot.next = self.c_out[0].val();
        self.drop_ok.next = self.drop_label.val() != self.zero16.val();
        self.drop_slot.next = self.c_out[1].val();
        self.add_ok.next = self.add_label.val() != self.zero16.val();
        self.add_slot.next = self.c_out[2].val();
        self.ring_b_slot.next = self.c_out[3].val();
        self.ring_a_slot.next = self.centre_first.val();
        if self.rw_valid.val() & (self.centre_first.val() == self.rw_from.val()) {
            self.ring_a_slot.next = self.rw_into.val();
        }
        self.miss.next = (self.lok.val() & !self.c_found[0].val())
            | ((self.drop_label.val() != self.zero16.val()) & !self.c_found[1].val())
            | ((self.add_label.val() != self.zero16.val()) & !self.c_found[2].val())
            | (self.ring.val() & !self.c_found[3].val());
        for e in 0..self.ent_hit.len() {
            self.ent_ok[e].next = self.lok.val() & self.ent_hit[e].val() & self.ent_found[e].val();
            self.ent_slot[e].next = self.ent_raw[e].val();
            if self.rw_valid.val() & (self.ent_raw[e].val() == self.rw_from.val()) {
                self.ent_slot[e].next = self.rw_into.val();
            }
            if self.lok.val() & self.ent_hit[e].val() & !self.ent_found[e].val() {
                self.miss.next = true;
            }
        }
    }
}
