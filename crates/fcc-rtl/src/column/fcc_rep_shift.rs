//! `FccRepShift`: a pixel's mask of run slots seen from `d = a - b` window
//! shifts later (combinational; docs/column-core.md, item 3). Masks are
//! rows of `h + 1` bits; output row `r` is input row `r + d - lead` (zero
//! outside the input), for `d` in `0 ..= S`:
//!
//! * with `lead = S`, a pixel's mask (its `K` rows, as at its A1) in the
//!   window's `K + S` positions, `d` the shifts since its A1;
//! * with `lead = 0`, the same mask in a later pixel's `K` rows, `d` the
//!   shifts between the two pixels' A1s.

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepShift {
    pub inp: Vec<Signal<In, Bit>>,
    pub a: Signal<In, Bits<3>>,
    pub b: Signal<In, Bits<3>>,
    pub out: Vec<Signal<Out, Bit>>,
    /// The input with `lead` zero rows before it and `S` after.
    ext: Vec<Signal<Local, Bit>>,
    d: Signal<Local, Bits<3>>,
    shift_no: Vec<Constant<Bits<3>>>,
    _n: usize,
    _lead: usize,
    _ds: usize,
}

impl FccRepShift {
    /// Rows of `n` bits: `rin` in, `rout` out, `lead` zero rows before the
    /// input, shifts `0 ..= s`.
    pub fn new(n: usize, rin: usize, rout: usize, lead: usize, s: usize) -> Self {
        assert!(s < 8, "{s} shifts do not fit 3 bits");
        let ext = (rout + s).max(lead + rin);
        Self {
            inp: vec_of(rin * n),
            a: Default::default(),
            b: Default::default(),
            d: Default::default(),
            out: vec_of(rout * n),
            ext: vec_of(ext * n),
            shift_no: (0..=s).map(|d| kb(d as u64)).collect(),
            _n: n,
            _lead: lead,
            _ds: s + 1,
        }
    }
}

impl Logic for FccRepShift {
    #[hdl_gen]
    fn update(&mut self) {
        self.d.next = self.a.val() - self.b.val();
        for b in 0..self.ext.len() {
            self.ext[b].next = false;
        }
        for lead in self._lead..(self._lead + 1) {
            for nn in self._n..(self._n + 1) {
                for b in 0..self.inp.len() {
                    self.ext[lead * nn + b].next = self.inp[b].val();
                }
                for b in 0..self.out.len() {
                    self.out[b].next = false;
                    for sh in 0..self._ds {
                        if (self.d.val() == self.shift_no[sh].val()) & self.ext[b + sh * nn].val() {
                            self.out[b].next = true;
                        }
                    }
                }
            }
        }
    }
}
