//! `FccRepJoins`: the column core's representative rows and join filter
//! (docs/column-core.md, item 3, "How the next pixel sees the rewrite").
//! Pixels arrive in column order with their run's label (`FccRowRuns`)
//! and their pass-2 hits (`FccColDist`: per window entry, a hit and the
//! label of the entry's run); out come the joins between labels the
//! union-find must make, `(x, m)`, each before the pixel that sends it,
//! and the pixels in order.
//!
//! Each row keeps its last `h + 1` runs' labels and representatives (a
//! label of the run's cluster). A pixel names its own run and its hits'
//! runs, a mask over the window's run slots; its smallest named
//! representative `m` becomes every named run's, and each other distinct
//! value there is a join. The next pixel sees the rewrite: the pixels in
//! flight correct their partial minimums by it (`FccRepOverlap`), and the
//! joins are read off the window as the rewrite is made.
//!
//! Stages (every one holds while `FccRepExtract` replays a pixel's second
//! join or more, from a flip-flop):
//! * A1 (`FccRepFront`): the pixel taken; the window shifts (`FccRowReps`,
//!   its rows from and back to the table, `FccRepRowFeed`), the run it
//!   starts pushed; `FccRepMatch` makes its mask from its labels' matches,
//!   found a cycle before as it came in (`FccRepEq`).
//! * A2 (`FccRepStage`, `FccRepFront`): the mask, and the representatives
//!   of the pixel's rows as the window rewrites them at A1's edge.
//! * M1 .. M3 (`FccRepStage`, `FccRepMin`): the minimum tree, three
//!   stages of groups of `gs` (`gs^3 >= K (h + 1)`), each group corrected
//!   by the rewrite broadcast that cycle where it names a slot of the
//!   group (`FccRepShift` places the broadcast in the pixel's rows; the
//!   overlaps are worked out a cycle ahead, `FccRepAhead`,
//!   `FccRepSeenAhead`, from the shifts between the pixels' A1s kept as
//!   they move, `FccRepGaps`, so the comparisons take registers only).
//! * B = M3: the pixel's `m`; the broadcast (its mask in the window's
//!   positions, `m`) rewrites the window at the edge, and `FccRepExtract`
//!   takes the window's values as they were.

use rust_hdl::prelude::*;

use super::fcc_rep_ahead::FccRepAhead;
use super::fcc_rep_eq::FccRepEq;
use super::fcc_rep_extract::FccRepExtract;
use super::fcc_rep_front::FccRepFront;
use super::fcc_rep_gaps::FccRepGaps;
use super::fcc_rep_match::FccRepMatch;
use super::fcc_rep_min::FccRepMin;
use super::fcc_rep_overlap::FccRepOverlap;
use super::fcc_rep_row_feed::FccRepRowFeed;
use super::fcc_rep_seen_ahead::FccRepSeenAhead;
use super::fcc_rep_shift::FccRepShift;
use super::fcc_rep_stage::FccRepStage;
use super::fcc_row_reps::FccRowReps;
use super::RunPix;
use crate::types::{kb, vec_of};

/// Stages of the minimum tree, M1 to B.
pub const REP_STAGES: usize = 3;

/// The window's shifts a pixel sees between its A1 and its broadcast at B
/// (A2 and the tree's stages): the rows kept above the window.
pub const REP_DEPTH: usize = REP_STAGES + 1;

/// The tree's group size for `np` run slots: the least `gs` with
/// `gs^3 >= np`.
pub fn rep_group(np: usize) -> usize {
    (2..).find(|g| g * g * g >= np).expect("some group size")
}

#[derive(LogicBlock)]
pub struct FccRepJoins {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub inp: Signal<In, RunPix>,
    pub inp_hit: Vec<Signal<In, Bit>>,
    pub inp_label: Vec<Signal<In, Bits<16>>>,
    pub ready: Signal<Out, Bit>,
    /// The frame's last row, `R - 1` (constant while a frame runs).
    pub last_row: Signal<In, Bits<7>>,
    pub out: Signal<Out, RunPix>,
    /// The pixel out last has joins still to come after this cycle's
    /// (its column's marker waits for them).
    pub j_more: Signal<Out, Bit>,
    pub j_valid: Signal<Out, Bit>,
    pub j_a: Signal<Out, Bits<16>>,
    pub j_b: Signal<Out, Bits<16>>,
    /// `j_a` is the run the pixel started, filed under `j_b`'s cluster.
    pub j_under: Signal<Out, Bit>,
    /// The join is the ring check's pair.
    pub j_seam: Signal<Out, Bit>,
    pub miss: Signal<Out, Bit>,
    feed: FccRepRowFeed,
    window: FccRowReps,
    front: FccRepFront,
    eqs: FccRepEq,
    matcher: FccRepMatch,
    st0: FccRepStage,
    st1: FccRepStage,
    st2: FccRepStage,
    st3: FccRepStage,
    min1: FccRepMin,
    min2: FccRepMin,
    min3: FccRepMin,
    seen1: FccRepSeenAhead,
    ov1: FccRepOverlap,
    ahead2: FccRepAhead,
    ahead3: FccRepAhead,
    gaps: FccRepGaps,
    wshift: FccRepShift,
    extract: FccRepExtract,
    bcast: Signal<Local, Bit>,
    m: Signal<Local, Bits<16>>,
    /// M2's pixel is labelled: the next broadcast is real.
    next_b: Signal<Local, Bit>,
    one: Constant<Bit>,
    zero3: Constant<Bits<3>>,
    none: Constant<Bits<16>>,
    /// Run slots of the pixel's rows, `K (h + 1)`, and of a row.
    _np: usize,
    _n: usize,
    /// The first run slot of the window's centre rows, `S (h + 1)`.
    _soff: usize,
    /// The centre row's first run slot among the pixel's rows', `h n`.
    _centre: usize,
    _g1: usize,
    _g2: usize,
}

impl FccRepJoins {
    /// For frames of at most `rows` rows and filter size `k`.
    pub fn new(rows: usize, k: usize) -> Self {
        let h = (k - 1) / 2;
        let n = h + 1;
        let ne = k * h;
        let np = k * n;
        let s = REP_DEPTH;
        let gs = rep_group(np);
        let g1 = np.div_ceil(gs);
        let g2 = g1.div_ceil(gs);
        let g3 = g2.div_ceil(gs);
        assert_eq!(g3, 1, "three stages of {gs} take {np} slots");
        let wp = (k + s) * n;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            inp_hit: vec_of(ne),
            inp_label: vec_of(ne),
            ready: Default::default(),
            last_row: Default::default(),
            out: Default::default(),
            j_more: Default::default(),
            j_valid: Default::default(),
            j_a: Default::default(),
            j_b: Default::default(),
            j_under: Default::default(),
            j_seam: Default::default(),
            miss: Default::default(),
            feed: FccRepRowFeed::new(rows, k, s),
            window: FccRowReps::new(k, s),
            front: FccRepFront::new(ne, n, np, g1 * gs),
            eqs: FccRepEq::new(k),
            matcher: FccRepMatch::new(k),
            st0: FccRepStage::new(np),
            st1: FccRepStage::new(np),
            st2: FccRepStage::new(np),
            st3: FccRepStage::new(np),
            min1: FccRepMin::new(g1, gs),
            min2: FccRepMin::new(g2, gs),
            min3: FccRepMin::new(g3, gs),
            seen1: FccRepSeenAhead::new(n, k, s),
            ov1: FccRepOverlap::new(np, gs),
            ahead2: FccRepAhead::new(n, k, s, gs * gs),
            ahead3: FccRepAhead::new(n, k, s, gs * gs * gs),
            gaps: Default::default(),
            wshift: FccRepShift::new(n, k, k + s, s, s),
            extract: FccRepExtract::new(wp),
            bcast: Default::default(),
            m: Default::default(),
            next_b: Default::default(),
            one: Constant::new(true),
            zero3: kb(0),
            none: kb(0xFFFF),
            _np: np,
            _n: n,
            _soff: s * n,
            _centre: h * n,
            _g1: g1,
            _g2: g2,
        }
    }
}

impl Logic for FccRepJoins {
    #[hdl_gen]
    fn update(&mut self) {
        // The table feeds the window's rows and takes back the one leaving.
        self.feed.clk.next = self.clk.val();
        self.feed.rst.next = self.rst.val();
        self.feed.last_row.next = self.last_row.val();
        self.feed.pop.next = self.front.shift.val();
        for k in 0..self.feed.wb_label.len() {
            self.feed.wb_label[k].next = self.window.wb_label[k].val();
            self.feed.wb_rep[k].next = self.window.wb_rep[k].val();
            self.feed.wb_age[k].next = self.window.wb_age[k].val();
            self.window.load_label[k].next = self.feed.head_label[k].val();
            self.window.load_rep[k].next = self.feed.head_rep[k].val();
            self.window.load_age[k].next = self.feed.head_age[k].val();
        }
        self.window.clk.next = self.clk.val();
        self.window.rst.next = self.rst.val();
        self.window.shift.next = self.front.shift.val();
        self.window.push.next = self.front.push.val();
        self.window.push_label.next = self.inp.val().label;
        self.window.push_rep.next = self.front.push_rep.val();
        // A1: the pixel, its mask, the representatives it names.
        self.front.clk.next = self.clk.val();
        self.front.rst.next = self.rst.val();
        self.front.inp.next = self.inp.val();
        self.front.go.next = self.extract.go.val();
        self.front.head_ok.next = self.feed.head_ok.val();
        self.front.match_miss.next = self.matcher.miss.val();
        for e in 0..self.inp_hit.len() {
            self.front.inp_hit[e].next = self.inp_hit[e].val();
            self.eqs.ent_label[e].next = self.inp_label[e].val();
            self.matcher.ent_hit[e].next = self.front.a1_hit[e].val();
        }
        for q in 0..self.eqs.eq.len() {
            self.front.inp_eq[q].next = self.eqs.eq[q].val();
            self.matcher.eq[q].next = self.front.a1_eq[q].val();
        }
        for k in 0..self.eqs.own_eq.len() {
            self.front.inp_own_eq[k].next = self.eqs.own_eq[k].val();
            self.matcher.own_eq[k].next = self.front.a1_own_eq[k].val();
        }
        self.eqs.own_label.next = self.inp.val().label;
        self.matcher.lok.next = self.front.a1_pix.val().lok;
        self.matcher.start.next = self.front.a1_pix.val().start;
        for soff in self._soff..(self._soff + 1) {
            for j in 0..self._np {
                self.matcher.age[j].next = self.window.age[soff + j].val();
                self.front.rep_next[j].next = self.window.rep_next[soff + j].val();
            }
            for c in self._centre..(self._centre + 1) {
                for k in 0..self._n {
                    self.front.a1_label[k].next = self.window.label[soff + c + k].val();
                    self.front.a1_age[k].next = self.window.age[soff + c + k].val();
                }
            }
            // The input pixel's rows as they will be once it shifts the
            // window in: one place up, the table's head row last.
            for nn in self._n..(self._n + 1) {
                for j in 0..(self._np - self._n) {
                    self.eqs.label[j].next = self.window.label[soff + nn + j].val();
                }
                for top in (self._np - self._n)..(self._np - self._n + 1) {
                    for k in 0..self._n {
                        self.eqs.label[top + k].next = self.feed.head_label[k].val();
                    }
                }
            }
        }
        // The broadcast: B's mask and `m`, as B moves on.
        self.m.next = self.min3.out[0].val();
        self.bcast.next = self.front.adv.val() & self.st3.pix.val().valid & self.st3.pix.val().lok;
        self.wshift.a.next = self.st3.sh.val();
        self.wshift.b.next = self.zero3.val();
        self.window.rw_valid.next = self.bcast.val();
        self.window.rw_rep.next = self.m.val();
        for b in 0..self.window.rw_mask.len() {
            self.window.rw_mask[b].next = self.wshift.out[b].val();
        }
        // A2, M1 .. M3: the pixels, the tree, the corrections.
        self.st0.in_pix.next = self.front.a1_pix.val();
        self.st0.in_sh.next = self.zero3.val();
        // A2's flush names its run's representative (M1 on): a label of its
        // cluster, as A2 sees the window.
        self.st1.in_pix.next = self.st0.pix.val();
        if self.front.a2_drop_hit.val() {
            self.st1.in_pix.next.hold_rep = self.front.a2_drop.val();
        }
        self.st1.in_sh.next = self.st0.sh.val();
        self.st2.in_pix.next = self.st1.pix.val();
        self.st2.in_sh.next = self.st1.sh.val();
        self.st3.in_pix.next = self.st2.pix.val();
        self.st3.in_sh.next = self.st2.sh.val();
        // The corrections, worked out a cycle ahead from M2's pixel (the
        // next broadcaster) and each next receiver.
        self.next_b.next = self.st2.pix.val().valid & self.st2.pix.val().lok;
        self.seen1.clk.next = self.clk.val();
        self.seen1.adv.next = self.front.adv.val();
        self.seen1.b_valid.next = self.next_b.val();
        self.seen1.b_sh.next = self.st2.sh.val();
        self.ahead2.clk.next = self.clk.val();
        self.ahead2.adv.next = self.front.adv.val();
        self.ahead2.b_valid.next = self.next_b.val();
        self.ahead2.d.next = self.gaps.d2.val();
        self.ahead3.clk.next = self.clk.val();
        self.ahead3.adv.next = self.front.adv.val();
        self.ahead3.b_valid.next = self.next_b.val();
        self.ahead3.d.next = self.gaps.d3.val();
        self.gaps.clk.next = self.clk.val();
        self.gaps.adv.next = self.front.adv.val();
        self.gaps.st0_sh.next = self.st0.sh.val();
        self.gaps.st1_sh.next = self.st1.sh.val();
        self.ov1.valid.next = self.one.val();
        for j in 0..self._np {
            self.wshift.inp[j].next = self.st3.mask[j].val();
            self.seen1.b_mask[j].next = self.st2.mask[j].val();
            self.ahead2.b_mask[j].next = self.st2.mask[j].val();
            self.ahead3.b_mask[j].next = self.st2.mask[j].val();
            self.ahead2.r_mask[j].next = self.st0.mask[j].val();
            self.ahead3.r_mask[j].next = self.st1.mask[j].val();
            self.ov1.mask[j].next = self.st0.mask[j].val();
            self.ov1.seen[j].next = self.seen1.seen[j].val();
            self.st0.in_mask[j].next = self.matcher.mask[j].val();
            self.st1.in_mask[j].next = self.st0.mask[j].val();
            self.st2.in_mask[j].next = self.st1.mask[j].val();
            self.st3.in_mask[j].next = self.st2.mask[j].val();
        }
        self.st0.clk.next = self.clk.val();
        self.st1.clk.next = self.clk.val();
        self.st2.clk.next = self.clk.val();
        self.st3.clk.next = self.clk.val();
        self.st0.rst.next = self.rst.val();
        self.st1.rst.next = self.rst.val();
        self.st2.rst.next = self.rst.val();
        self.st3.rst.next = self.rst.val();
        self.st0.adv.next = self.front.adv.val();
        self.st1.adv.next = self.front.adv.val();
        self.st2.adv.next = self.front.adv.val();
        self.st3.adv.next = self.front.adv.val();
        self.st0.shift.next = self.front.shift.val();
        self.st1.shift.next = self.front.shift.val();
        self.st2.shift.next = self.front.shift.val();
        self.st3.shift.next = self.front.shift.val();
        self.min1.clk.next = self.clk.val();
        self.min2.clk.next = self.clk.val();
        self.min3.clk.next = self.clk.val();
        self.min1.go.next = self.extract.go.val();
        self.min2.go.next = self.extract.go.val();
        self.min3.go.next = self.extract.go.val();
        self.min1.m.next = self.m.val();
        self.min2.m.next = self.m.val();
        self.min3.m.next = self.m.val();
        for g in 0..self.min1.ov.len() {
            self.min1.ov[g].next = self.ov1.ov[g].val();
        }
        for g in 0..self.min2.ov.len() {
            self.min2.ov[g].next = self.ahead2.ov[g].val();
        }
        for g in 0..self.min3.ov.len() {
            self.min3.ov[g].next = self.ahead3.ov[g].val();
        }
        for i in 0..self.min1.v.len() {
            self.min1.v[i].next = self.front.v[i].val();
            self.min1.pres[i].next = false;
        }
        for j in 0..self._np {
            self.min1.pres[j].next = self.st0.mask[j].val();
        }
        for i in 0..self.min2.v.len() {
            self.min2.v[i].next = self.none.val();
            self.min2.pres[i].next = false;
        }
        for i in 0..self._g1 {
            self.min2.v[i].next = self.min1.out[i].val();
            self.min2.pres[i].next = true;
        }
        for i in 0..self.min3.v.len() {
            self.min3.v[i].next = self.none.val();
            self.min3.pres[i].next = false;
        }
        for i in 0..self._g2 {
            self.min3.v[i].next = self.min2.out[i].val();
            self.min3.pres[i].next = true;
        }
        // B: the joins, one a cycle, then the pixel.
        self.extract.clk.next = self.clk.val();
        self.extract.rst.next = self.rst.val();
        self.extract.b_pix.next = self.st3.pix.val();
        self.extract.b_m.next = self.m.val();
        for b in 0..self.window.rep.len() {
            self.extract.b_mask[b].next = self.wshift.out[b].val();
            self.extract.b_val[b].next = self.window.rep[b].val();
        }
        self.ready.next = self.front.ready.val();
        self.out.next = self.extract.out.val();
        self.j_valid.next = self.extract.j_valid.val();
        self.j_more.next = self.extract.more.val();
        self.j_a.next = self.extract.j_a.val();
        self.j_b.next = self.extract.j_b.val();
        self.j_under.next = self.extract.j_under.val();
        self.j_seam.next = self.extract.j_seam.val();
        self.miss.next = self.front.miss.val();
    }
}
