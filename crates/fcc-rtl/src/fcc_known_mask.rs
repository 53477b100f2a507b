//! `FccKnownMask`: which upper pixels of the window already matched an
//! earlier centre of the same run (see `fcc_sort_filter`).
//!
//! The window moves one column per valid slot, so the mask of the previous
//! centre shifts by one position along each window row (the rightmost
//! position enters unknown). A centre of the same run adds its own matches;
//! a centre of a new run starts from its matches alone. The mask of a centre
//! is what the earlier centres knew (`same_run` and shifted), delayed by
//! `delay` cycles to meet the rest of the filter.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccKnownMask {
    pub clk: Signal<In, Clock>,
    // The centre (one stage after the window).
    pub valid: Signal<In, Bit>,
    /// A labelled centre: its matches count.
    pub elig: Signal<In, Bit>,
    /// Same label as the last labelled centre.
    pub same_run: Signal<In, Bit>,
    pub hit: Vec<Signal<In, Bit>>,
    /// Positions known before this centre, `delay` cycles later.
    pub known_late: Vec<Signal<Out, Bit>>,
    /// The mask after the last valid centre.
    known: Vec<DFF<Bit>>,
    shifted: Vec<Signal<Local, Bit>>,
    known_before: Vec<Signal<Local, Bit>>,
    /// Delay line: position e's stages at `e * delay ..`.
    known_line: Vec<DFF<Bit>>,
    _k: usize,
    _h: usize,
    _n: usize,
    _delay: usize,
}

impl FccKnownMask {
    /// A window of `h` rows of `k` positions; the output `delay` >= 1
    /// cycles after the inputs.
    pub fn new(k: usize, h: usize, delay: usize) -> Self {
        assert!(k >= 2 && h >= 1 && delay >= 1);
        let n = k * h;
        Self {
            clk: Default::default(),
            valid: Default::default(),
            elig: Default::default(),
            same_run: Default::default(),
            hit: vec_of(n),
            known_late: vec_of(n),
            known: vec_of(n),
            shifted: vec_of(n),
            known_before: vec_of(n),
            known_line: vec_of(n * delay),
            _k: k,
            _h: h,
            _n: n,
            _delay: delay,
        }
    }
}

impl Logic for FccKnownMask {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..(self._n * self._delay) {
            self.known_line[i].clock.next = self.clk.val();
        }
        for kk in self._k..(self._k + 1) {
            for r in 0..self._h {
                for n in 0..(self._k - 1) {
                    self.shifted[r * kk + n].next = self.known[r * kk + n + 1].q.val();
                }
                self.shifted[r * kk + kk - 1].next = false;
            }
        }
        for dk in self._delay..(self._delay + 1) {
            for e in 0..self._n {
                self.known[e].clock.next = self.clk.val();
                self.known[e].d.next = self.known[e].q.val();
                self.known_before[e].next = self.same_run.val() & self.shifted[e].val();
                if self.valid.val() {
                    self.known[e].d.next = self.shifted[e].val();
                    if self.elig.val() {
                        self.known[e].d.next = self.known_before[e].val() | self.hit[e].val();
                    }
                }
                self.known_line[e * dk].d.next = self.known_before[e].val();
                for i in 1..self._delay {
                    self.known_line[e * dk + i].d.next = self.known_line[e * dk + i - 1].q.val();
                }
                self.known_late[e].next = self.known_line[e * dk + dk - 1].q.val();
            }
        }
    }
}
