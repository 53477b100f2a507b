//! `FccHitsPack`: a window's hits and their labels (`hit[e]`,
//! `hit_label[e]`, `K x h` entries) as the column core's probes bring them
//! out: the hits as a mask (`hits`, entry `e` in bit `e`) and the labels
//! four to a word (`lw0` .. `lw13`, entry `4w + m` in bits `16m ..`, zeros
//! past the last entry), the form `FccRepJoinsProbe` takes them in.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_quad_lane::LabelQuad;
use crate::types::{kb, vec_of};

/// Label words: 56 entries, K = 11's 55.
pub const PACK_WORDS: usize = 14;

#[derive(LogicBlock)]
pub struct FccHitsPack {
    pub hit: Vec<Signal<In, Bit>>,
    pub hit_label: Vec<Signal<In, Bits<16>>>,
    pub hits: Signal<Out, Bits<64>>,
    pub lw0: Signal<Out, LabelQuad>,
    pub lw1: Signal<Out, LabelQuad>,
    pub lw2: Signal<Out, LabelQuad>,
    pub lw3: Signal<Out, LabelQuad>,
    pub lw4: Signal<Out, LabelQuad>,
    pub lw5: Signal<Out, LabelQuad>,
    pub lw6: Signal<Out, LabelQuad>,
    pub lw7: Signal<Out, LabelQuad>,
    pub lw8: Signal<Out, LabelQuad>,
    pub lw9: Signal<Out, LabelQuad>,
    pub lw10: Signal<Out, LabelQuad>,
    pub lw11: Signal<Out, LabelQuad>,
    pub lw12: Signal<Out, LabelQuad>,
    pub lw13: Signal<Out, LabelQuad>,
    /// The mask so far: entries below `e` at `acc[e]`.
    acc: Vec<Signal<Local, Bits<64>>>,
    onehot: Vec<Constant<Bits<64>>>,
    /// The entries' labels, zeros past the last.
    lab: Vec<Signal<Local, Bits<16>>>,
    zero16: Constant<Bits<16>>,
    zero64: Constant<Bits<64>>,
    _n: usize,
}

impl FccHitsPack {
    /// The pack of the build's window.
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(
            n <= 4 * PACK_WORDS,
            "{n} window entries do not fit the label words"
        );
        Self {
            hit: vec_of(n),
            hit_label: vec_of(n),
            hits: Default::default(),
            lw0: Default::default(),
            lw1: Default::default(),
            lw2: Default::default(),
            lw3: Default::default(),
            lw4: Default::default(),
            lw5: Default::default(),
            lw6: Default::default(),
            lw7: Default::default(),
            lw8: Default::default(),
            lw9: Default::default(),
            lw10: Default::default(),
            lw11: Default::default(),
            lw12: Default::default(),
            lw13: Default::default(),
            acc: vec_of(n + 1),
            onehot: (0..n).map(|e| kb(1u64 << e)).collect(),
            lab: vec_of(4 * PACK_WORDS),
            zero16: kb(0),
            zero64: kb(0),
            _n: n,
        }
    }
}

impl Logic for FccHitsPack {
    #[hdl_gen]
    fn update(&mut self) {
        self.acc[0].next = self.zero64.val();
        for e in 0..self._n {
            self.acc[e + 1].next = self.acc[e].val();
            if self.hit[e].val() {
                self.acc[e + 1].next = self.acc[e].val() | self.onehot[e].val();
            }
            self.lab[e].next = self.hit_label[e].val();
        }
        for e in (self._n)..(self._n + 1) {
            self.hits.next = self.acc[e].val();
        }
        for e in (self._n)..(4 * PACK_WORDS) {
            self.lab[e].next = self.zero16.val();
        }
        self.lw0.next.l0 = self.lab[0].val();
        self.lw0.next.l1 = self.lab[1].val();
        self.lw0.next.l2 = self.lab[2].val();
        self.lw0.next.l3 = self.lab[3].val();
        self.lw1.next.l0 = self.lab[4].val();
        self.lw1.next.l1 = self.lab[5].val();
        self.lw1.next.l2 = self.lab[6].val();
        self.lw1.next.l3 = self.lab[7].val();
        self.lw2.next.l0 = self.lab[8].val();
        self.lw2.next.l1 = self.lab[9].val();
        self.lw2.next.l2 = self.lab[10].val();
        self.lw2.next.l3 = self.lab[11].val();
        self.lw3.next.l0 = self.lab[12].val();
        self.lw3.next.l1 = self.lab[13].val();
        self.lw3.next.l2 = self.lab[14].val();
        self.lw3.next.l3 = self.lab[15].val();
        self.lw4.next.l0 = self.lab[16].val();
        self.lw4.next.l1 = self.lab[17].val();
        self.lw4.next.l2 = self.lab[18].val();
        self.lw4.next.l3 = self.lab[19].val();
        self.lw5.next.l0 = self.lab[20].val();
        self.lw5.next.l1 = self.lab[21].val();
        self.lw5.next.l2 = self.lab[22].val();
        self.lw5.next.l3 = self.lab[23].val();
        self.lw6.next.l0 = self.lab[24].val();
        self.lw6.next.l1 = self.lab[25].val();
        self.lw6.next.l2 = self.lab[26].val();
        self.lw6.next.l3 = self.lab[27].val();
        self.lw7.next.l0 = self.lab[28].val();
        self.lw7.next.l1 = self.lab[29].val();
        self.lw7.next.l2 = self.lab[30].val();
        self.lw7.next.l3 = self.lab[31].val();
        self.lw8.next.l0 = self.lab[32].val();
        self.lw8.next.l1 = self.lab[33].val();
        self.lw8.next.l2 = self.lab[34].val();
        self.lw8.next.l3 = self.lab[35].val();
        self.lw9.next.l0 = self.lab[36].val();
        self.lw9.next.l1 = self.lab[37].val();
        self.lw9.next.l2 = self.lab[38].val();
        self.lw9.next.l3 = self.lab[39].val();
        self.lw10.next.l0 = self.lab[40].val();
        self.lw10.next.l1 = self.lab[41].val();
        self.lw10.next.l2 = self.lab[42].val();
        self.lw10.next.l3 = self.lab[43].val();
        self.lw11.next.l0 = self.lab[44].val();
        self.lw11.next.l1 = self.lab[45].val();
        self.lw11.next.l2 = self.lab[46].val();
        self.lw11.next.l3 = self.lab[47].val();
        self.lw12.next.l0 = self.lab[48].val();
        self.lw12.next.l1 = self.lab[49].val();
        self.lw12.next.l2 = self.lab[50].val();
        self.lw12.next.l3 = self.lab[51].val();
        self.lw13.next.l0 = self.lab[52].val();
        self.lw13.next.l1 = self.lab[53].val();
        self.lw13.next.l2 = self.lab[54].val();
        self.lw13.next.l3 = self.lab[55].val();
    }
}
