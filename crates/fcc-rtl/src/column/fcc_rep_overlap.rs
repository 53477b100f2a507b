//! `FccRepOverlap`: which groups of a pixel's run slots the rewrite being
//! broadcast names (combinational; docs/column-core.md, item 3). Group
//! `g` covers slots `g * span .. (g + 1) * span` of the pixel's mask (the
//! slots one output of a minimum tree stage stands for): `ov[g]` when the
//! pixel names one of them and the broadcast, seen in the pixel's rows
//! (`FccRepShift`), names it too.

use rust_hdl::prelude::*;

use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccRepOverlap {
    pub valid: Signal<In, Bit>,
    pub mask: Vec<Signal<In, Bit>>,
    pub seen: Vec<Signal<In, Bit>>,
    pub ov: Vec<Signal<Out, Bit>>,
    /// Both name the slot, padded with zeros to whole groups.
    both: Vec<Signal<Local, Bit>>,
    _span: usize,
}

impl FccRepOverlap {
    /// `n` slots in groups of `span`.
    pub fn new(n: usize, span: usize) -> Self {
        let g = n.div_ceil(span);
        Self {
            valid: Default::default(),
            mask: vec_of(n),
            seen: vec_of(n),
            ov: vec_of(g),
            both: vec_of(g * span),
            _span: span,
        }
    }
}

impl Logic for FccRepOverlap {
    #[hdl_gen]
    fn update(&mut self) {
        for b in 0..self.both.len() {
            self.both[b].next = false;
        }
        for b in 0..self.mask.len() {
            self.both[b].next = self.valid.val() & self.mask[b].val() & self.seen[b].val();
        }
        for span in self._span..(self._span + 1) {
            for g in 0..self.ov.len() {
                self.ov[g].next = false;
                for c in 0..self._span {
                    if self.both[g * span + c].val() {
                        self.ov[g].next = true;
                    }
                }
            }
        }
    }
}
