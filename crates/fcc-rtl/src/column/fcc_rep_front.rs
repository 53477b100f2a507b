//! `FccRepFront`: the representative rows' input and A1 (docs/column-core.md,
//! item 3). A pixel is taken while nothing holds the pipeline and the
//! table has the row that enters the window with it (`ready`); taking it
//! shifts the window (`shift`) and pushes the run it starts (`push`). A1
//! holds the pixel, its hits and their labels' matches (`FccRepEq`) for
//! `FccRepMatch`; A2 the representatives of A1's rows as the window has
//! them after this cycle's rewrite (`rep_next`), for the minimum tree
//! (`v`, padded with `0xFFFF`; A2's mask says which are present), and
//! the representative of the run A2's row stops holding (`a2_drop`, when
//! `a2_drop_hit`): its slot among the centre row's, `a1_label`, matched
//! at A1, after the push, among the two newest (`a1_age` 0 and 1: the
//! row's latest run, the one before it when the pixel starts one), the
//! newer first, since a label given out again may still name an old run
//! further back. `miss` is sticky until reset (a cycle after
//! the match). A run pushed by a pixel that names others (a hit) takes
//! `0xFFFF` as its representative (`push_rep`) until the pixel's minimum
//! rewrites it: above every label, it leaves the minimum to the others'
//! representatives (a new run takes its neighbours' cluster's name rather
//! than renaming it, which would only make more joins), and a pixel in
//! flight that names it takes the rewrite's `m` in its correction, as the
//! rewrite never raises a value.

use rust_hdl::prelude::*;

use super::{RunPix, REP_AGE_BITS};
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepFront {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub inp: Signal<In, RunPix>,
    pub inp_hit: Vec<Signal<In, Bit>>,
    /// The entries' and the pixel's own label matches (`FccRepEq`).
    pub inp_eq: Vec<Signal<In, Bit>>,
    pub inp_own_eq: Vec<Signal<In, Bit>>,
    /// The centre row's run slots' labels while the pixel is at A1.
    pub a1_label: Vec<Signal<In, Bits<16>>>,
    pub a1_age: Vec<Signal<In, Bits<REP_AGE_BITS>>>,
    /// The pipeline moves this cycle: nothing replays (`FccRepReplay`'s
    /// replicated register).
    pub go: Signal<In, Bit>,
    pub head_ok: Signal<In, Bit>,
    /// The window's representatives at A1's rows with this cycle's
    /// rewrite, and A1's match's `miss`.
    pub rep_next: Vec<Signal<In, Bits<16>>>,
    pub match_miss: Signal<In, Bit>,
    pub ready: Signal<Out, Bit>,
    pub adv: Signal<Out, Bit>,
    pub shift: Signal<Out, Bit>,
    pub push: Signal<Out, Bit>,
    pub push_rep: Signal<Out, Bits<16>>,
    pub a1_pix: Signal<Out, RunPix>,
    pub a1_hit: Vec<Signal<Out, Bit>>,
    pub a1_eq: Vec<Signal<Out, Bit>>,
    pub a1_own_eq: Vec<Signal<Out, Bit>>,
    pub v: Vec<Signal<Out, Bits<16>>>,
    pub a2_drop_hit: Signal<Out, Bit>,
    pub a2_drop: Signal<Out, Bits<16>>,
    pub miss: Signal<Out, Bit>,
    pix_q: DFF<RunPix>,
    hit_q: Vec<DFF<Bit>>,
    eq_q: Vec<DFF<Bit>>,
    own_eq_q: Vec<DFF<Bit>>,
    /// The dropped run's slot among the centre row's, at A2; at A1, the
    /// newest two slots' matches.
    drop2_q: Vec<DFF<Bit>>,
    hit: Vec<Signal<Local, Bit>>,
    m0: Vec<Signal<Local, Bit>>,
    m1: Vec<Signal<Local, Bit>>,
    any0: Signal<Local, Bit>,
    /// The input pixel names a run by a hit.
    named: Signal<Local, Bit>,
    rep_q: Vec<DFF<Bits<16>>>,
    /// A1's match missed last cycle (registered before `miss_q` takes it:
    /// the match is a long path).
    miss_p: DFF<Bit>,
    miss_q: DFF<Bit>,
    take: Signal<Local, Bit>,
    /// The centre row's first run slot among `v`'s, `h n`.
    _centre: usize,
    pix_zero: Constant<RunPix>,
    none: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    age0: Constant<Bits<REP_AGE_BITS>>,
    age1: Constant<Bits<REP_AGE_BITS>>,
}

impl FccRepFront {
    /// `ne` window entries, `n` run slots a row, `np` run slots, `nv`
    /// values for the tree.
    pub fn new(ne: usize, n: usize, np: usize, nv: usize) -> Self {
        assert!(nv >= np);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            inp: Default::default(),
            inp_hit: vec_of(ne),
            inp_eq: vec_of(ne * n),
            inp_own_eq: vec_of(n),
            a1_label: vec_of(n),
            a1_age: vec_of(n),
            go: Default::default(),
            head_ok: Default::default(),
            rep_next: vec_of(np),
            match_miss: Default::default(),
            ready: Default::default(),
            adv: Default::default(),
            shift: Default::default(),
            push: Default::default(),
            push_rep: Default::default(),
            a1_pix: Default::default(),
            a1_hit: vec_of(ne),
            a1_eq: vec_of(ne * n),
            a1_own_eq: vec_of(n),
            v: vec_of(nv),
            a2_drop_hit: Default::default(),
            a2_drop: Default::default(),
            miss: Default::default(),
            pix_q: Default::default(),
            hit_q: vec_of(ne),
            eq_q: vec_of(ne * n),
            own_eq_q: vec_of(n),
            drop2_q: vec_of(n),
            hit: vec_of(n),
            m0: vec_of(n),
            m1: vec_of(n),
            any0: Default::default(),
            named: Default::default(),
            rep_q: vec_of(np),
            miss_p: Default::default(),
            miss_q: Default::default(),
            take: Default::default(),
            _centre: (np / n - 1) / 2 * n,
            pix_zero: Constant::new(RunPix::default()),
            none: kb(0xFFFF),
            zero16: kb(0),
            age0: kb(0),
            age1: kb(1),
        }
    }
}

impl Logic for FccRepFront {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, pix_q, miss_p, miss_q);
        self.adv.next = self.go.val();
        self.ready.next = self.go.val() & self.head_ok.val();
        self.take.next = self.inp.val().valid & self.go.val() & self.head_ok.val();
        self.shift.next = self.take.val();
        self.push.next = self.take.val() & self.inp.val().start;
        self.named.next = false;
        for e in 0..self.inp_hit.len() {
            if self.inp_hit[e].val() {
                self.named.next = true;
            }
        }
        self.push_rep.next = self.inp.val().label;
        if self.named.val() & self.inp.val().lok {
            self.push_rep.next = self.none.val();
        }
        if self.go.val() {
            self.pix_q.d.next = self.pix_zero.val();
            if self.take.val() {
                self.pix_q.d.next = self.inp.val();
            }
        }
        for e in 0..self.hit_q.len() {
            self.hit_q[e].clock.next = self.clk.val();
            self.hit_q[e].d.next = self.hit_q[e].q.val();
            if self.go.val() {
                self.hit_q[e].d.next = self.inp_hit[e].val();
            }
            self.a1_hit[e].next = self.hit_q[e].q.val();
        }
        for q in 0..self.eq_q.len() {
            self.eq_q[q].clock.next = self.clk.val();
            self.eq_q[q].d.next = self.eq_q[q].q.val();
            if self.go.val() {
                self.eq_q[q].d.next = self.inp_eq[q].val();
            }
            self.a1_eq[q].next = self.eq_q[q].q.val();
        }
        for k in 0..self.own_eq_q.len() {
            self.own_eq_q[k].clock.next = self.clk.val();
            self.own_eq_q[k].d.next = self.own_eq_q[k].q.val();
            if self.go.val() {
                self.own_eq_q[k].d.next = self.inp_own_eq[k].val();
            }
            self.a1_own_eq[k].next = self.own_eq_q[k].q.val();
        }
        // The dropped run's slot, to A2, where its representative is read:
        // the newest slot of its label, of the two newest.
        self.a2_drop_hit.next = false;
        self.a2_drop.next = self.none.val();
        self.any0.next = false;
        for k in 0..self.drop2_q.len() {
            self.hit[k].next = self.pix_q.q.val().valid
                & (self.pix_q.q.val().hold_drop != self.zero16.val())
                & (self.pix_q.q.val().hold_drop == self.a1_label[k].val());
            self.m0[k].next = self.hit[k].val() & (self.a1_age[k].val() == self.age0.val());
            self.m1[k].next = self.hit[k].val() & (self.a1_age[k].val() == self.age1.val());
            if self.m0[k].val() {
                self.any0.next = true;
            }
        }
        for k in 0..self.drop2_q.len() {
            self.drop2_q[k].clock.next = self.clk.val();
            self.drop2_q[k].d.next = self.drop2_q[k].q.val();
            if self.go.val() {
                self.drop2_q[k].d.next = self.m0[k].val() | (self.m1[k].val() & !self.any0.val());
            }
        }
        for c in self._centre..(self._centre + 1) {
            for k in 0..self.drop2_q.len() {
                if self.drop2_q[k].q.val() {
                    self.a2_drop_hit.next = true;
                    self.a2_drop.next = self.rep_q[c + k].q.val();
                }
            }
        }
        self.a1_pix.next = self.pix_q.q.val();
        for j in 0..self.v.len() {
            self.v[j].next = self.none.val();
        }
        for j in 0..self.rep_q.len() {
            self.rep_q[j].clock.next = self.clk.val();
            self.rep_q[j].d.next = self.rep_q[j].q.val();
            if self.go.val() {
                self.rep_q[j].d.next = self.rep_next[j].val();
            }
            self.v[j].next = self.rep_q[j].q.val();
        }
        self.miss_p.d.next = self.pix_q.q.val().valid & self.match_miss.val();
        if self.miss_p.q.val() {
            self.miss_q.d.next = true;
        }
        if self.rst.val() {
            self.pix_q.d.next = self.pix_zero.val();
            self.miss_p.d.next = false;
            self.miss_q.d.next = false;
        }
        self.miss.next = self.miss_q.q.val();
    }
}
