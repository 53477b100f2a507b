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
//! * The pixel's own run, the runs its row stops and starts holding (spec
//!   §9.2) and the ring check's pair (the row's first run; its last), all in
//!   the centre row (a run the pixel starts is already there).
//!
//! Out come the slots as the window holds them, in `slot_index` order
//! (`FccSlotBank` with `late` applies the merge broadcast meanwhile; the
//! hold slots are 0 where the row's hold does not change). `miss` says some
//! label named was not found (a broken invariant: the bench checks it never
//! is).

use rust_hdl::prelude::*;

use super::{slot_index, SLOT_BITS};
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
    pub drop_label: Signal<In, Bits<16>>,
    pub add_label: Signal<In, Bits<16>>,
    pub ring: Signal<In, Bit>,
    pub ring_b_label: Signal<In, Bits<16>>,
    pub ent_hit: Vec<Signal<In, Bit>>,
    pub ent_label: Vec<Signal<In, Bits<16>>>,
    // The slots.
    pub ent_ok: Vec<Signal<Out, Bit>>,
    pub found: Vec<Signal<Out, Bits<SLOT_BITS>>>,
    pub miss: Signal<Out, Bit>,
    ent_found: Vec<Signal<Local, Bit>>,
    /// The centre row's lookups: own, drop, add, ring_b.
    c_found: Vec<Signal<Local, Bit>>,
    c_raw: Vec<Signal<Local, Bits<SLOT_BITS>>>,
    c_label: Vec<Signal<Local, Bits<16>>>,
    zero16: Constant<Bits<16>>,
    zero_slot: Constant<Bits<SLOT_BITS>>,
    _k: usize,
    _h: usize,
    _n: usize,
    /// `2 h^2`: the first entry of the pixel's own column.
    _same: usize,
    _own: usize,
    _ring_a: usize,
    _drop: usize,
    _add: usize,
}

impl FccRootMatch {
    /// The window of filter size `k`.
    pub fn new(k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let ne = k * h;
        let ix = slot_index(ne);
        Self {
            label: vec_of(k * n),
            slot: vec_of(k * n),
            centre_first: Default::default(),
            lok: Default::default(),
            own_label: Default::default(),
            drop_label: Default::default(),
            add_label: Default::default(),
            ring: Default::default(),
            ring_b_label: Default::default(),
            ent_hit: vec_of(ne),
            ent_label: vec_of(ne),
            ent_ok: vec_of(ne),
            found: vec_of(ix.count),
            miss: Default::default(),
            ent_found: vec_of(ne),
            c_found: vec_of(4),
            c_raw: vec_of(4),
            c_label: vec_of(4),
            zero16: kb(0),
            zero_slot: kb(0),
            _k: k,
            _h: h,
            _n: n,
            _same: 2 * h * h,
            _own: ix.own,
            _ring_a: ix.ring_a,
            _drop: ix.drop,
            _add: ix.add,
        }
    }
}

impl Logic for FccRootMatch {
    #[hdl_gen]
    fn update(&mut self) {
        for e in 0..self.ent_hit.len() {
            self.ent_found[e].next = false;
            self.found[e].next = self.zero_slot.val();
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
                                    self.found[r * km + p].next =
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
                                    self.found[r * km + p].next =
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
                                    self.found[q + m - 1].next =
                                        self.slot[(hh - m) * nn + nn - 1 - k].val();
                                }
                            }
                        }
                    }
                    // The centre row: own, drop, add, ring_b.
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
                    }
                }
            }
        }
        // Own, ring_a, ring_b, drop, add: the slot_index order.
        for own in self._own..(self._own + 1) {
            self.found[own].next = self.c_raw[0].val();
        }
        for ra in self._ring_a..(self._ring_a + 1) {
            self.found[ra].next = self.centre_first.val();
            self.found[ra + 1].next = self.c_raw[3].val();
        }
        for dr in self._drop..(self._drop + 1) {
            self.found[dr].next = self.zero_slot.val();
            if self.drop_label.val() != self.zero16.val() {
                self.found[dr].next = self.c_raw[1].val();
            }
        }
        for ad in self._add..(self._add + 1) {
            self.found[ad].next = self.zero_slot.val();
            if self.add_label.val() != self.zero16.val() {
                self.found[ad].next = self.c_raw[2].val();
            }
        }
        self.miss.next = (self.lok.val() & !self.c_found[0].val())
            | ((self.drop_label.val() != self.zero16.val()) & !self.c_found[1].val())
            | ((self.add_label.val() != self.zero16.val()) & !self.c_found[2].val())
            | (self.ring.val() & !self.c_found[3].val());
        for e in 0..self.ent_hit.len() {
            self.ent_ok[e].next = self.lok.val() & self.ent_hit[e].val() & self.ent_found[e].val();
            if self.lok.val() & self.ent_hit[e].val() & !self.ent_found[e].val() {
                self.miss.next = true;
            }
        }
    }
}
