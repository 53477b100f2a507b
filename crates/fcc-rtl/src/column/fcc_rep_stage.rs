//! `FccRepStage`: one stage of the representative rows' pipeline between
//! A1 and B (docs/column-core.md, item 3): the pixel, its mask of run slots
//! (its `K` rows as at its A1) and `sh`, the window's shifts since its A1.
//! It takes the stage before's when `adv`, counting the shift made at the
//! same edge (`shift`); `rst` empties it.

use rust_hdl::prelude::*;

use super::RunPix;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccRepStage {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub adv: Signal<In, Bit>,
    pub shift: Signal<In, Bit>,
    pub in_pix: Signal<In, RunPix>,
    pub in_mask: Vec<Signal<In, Bit>>,
    pub in_sh: Signal<In, Bits<3>>,
    pub pix: Signal<Out, RunPix>,
    pub mask: Vec<Signal<Out, Bit>>,
    pub sh: Signal<Out, Bits<3>>,
    pix_q: DFF<RunPix>,
    mask_q: Vec<FccFanoutReg<Bit>>,
    sh_q: DFF<Bits<3>>,
    pix_zero: Constant<RunPix>,
    one3: Constant<Bits<3>>,
}

impl FccRepStage {
    /// `n` run slots.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            adv: Default::default(),
            shift: Default::default(),
            in_pix: Default::default(),
            in_mask: vec_of(n),
            in_sh: Default::default(),
            pix: Default::default(),
            mask: vec_of(n),
            sh: Default::default(),
            pix_q: Default::default(),
            mask_q: vec_of(n),
            sh_q: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
            one3: kb(1),
        }
    }
}

impl Logic for FccRepStage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, pix_q, sh_q);
        for b in 0..self.mask_q.len() {
            self.mask_q[b].clock.next = self.clk.val();
            self.mask_q[b].d.next = self.mask_q[b].q.val();
            self.mask[b].next = self.mask_q[b].q.val();
        }
        if self.adv.val() {
            self.pix_q.d.next = self.in_pix.val();
            self.sh_q.d.next = self.in_sh.val();
            if self.shift.val() {
                self.sh_q.d.next = self.in_sh.val() + self.one3.val();
            }
            for b in 0..self.mask_q.len() {
                self.mask_q[b].d.next = self.in_mask[b].val();
            }
        }
        if self.rst.val() {
            self.pix_q.d.next = self.pix_zero.val();
        }
        self.pix.next = self.pix_q.q.val();
        self.sh.next = self.sh_q.q.val();
    }
}
