//! `FccHitsUnpack`: the inverse of `FccHitsPack`, for the probes that take
//! a window's hits in the packed form: the hits as a mask (`hits`, entry
//! `e` in bit `e`) and the labels four to a word (`lw0` .. `lw13`, entry
//! `4w + m` in bits `16m ..`) out as `hit[e]` and `hit_label[e]`, `K x h`
//! entries (combinational).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_hits_pack::PACK_WORDS;
use crate::types::vec_of;

#[derive(LogicBlock)]
pub struct FccHitsUnpack {
    pub hits: Signal<In, Bits<64>>,
    pub lw0: Signal<In, Bits<64>>,
    pub lw1: Signal<In, Bits<64>>,
    pub lw2: Signal<In, Bits<64>>,
    pub lw3: Signal<In, Bits<64>>,
    pub lw4: Signal<In, Bits<64>>,
    pub lw5: Signal<In, Bits<64>>,
    pub lw6: Signal<In, Bits<64>>,
    pub lw7: Signal<In, Bits<64>>,
    pub lw8: Signal<In, Bits<64>>,
    pub lw9: Signal<In, Bits<64>>,
    pub lw10: Signal<In, Bits<64>>,
    pub lw11: Signal<In, Bits<64>>,
    pub lw12: Signal<In, Bits<64>>,
    pub lw13: Signal<In, Bits<64>>,
    pub hit: Vec<Signal<Out, Bit>>,
    pub hit_label: Vec<Signal<Out, Bits<16>>>,
    /// The words by number (a word's field reaches an index only through a
    /// named signal).
    words: Vec<Signal<Local, Bits<64>>>,
    _n: usize,
}

impl FccHitsUnpack {
    /// The unpack of the build's window.
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(
            n <= 4 * PACK_WORDS,
            "{n} window entries do not fit the label words"
        );
        Self {
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
            hit: vec_of(n),
            hit_label: vec_of(n),
            words: vec_of(PACK_WORDS),
            _n: n,
        }
    }
}

impl Logic for FccHitsUnpack {
    #[hdl_gen]
    fn update(&mut self) {
        self.words[0].next = self.lw0.val();
        self.words[1].next = self.lw1.val();
        self.words[2].next = self.lw2.val();
        self.words[3].next = self.lw3.val();
        self.words[4].next = self.lw4.val();
        self.words[5].next = self.lw5.val();
        self.words[6].next = self.lw6.val();
        self.words[7].next = self.lw7.val();
        self.words[8].next = self.lw8.val();
        self.words[9].next = self.lw9.val();
        self.words[10].next = self.lw10.val();
        self.words[11].next = self.lw11.val();
        self.words[12].next = self.lw12.val();
        self.words[13].next = self.lw13.val();
        for e in 0..self._n {
            self.hit[e].next = self.hits.val().get_bit(e);
        }
        for w in 0..(self._n / 4) {
            for m in 0..4 {
                self.hit_label[w * 4 + m].next = self.words[w].val().get_bits::<16>(m * 16);
            }
        }
        for w in (self._n / 4)..(self._n / 4 + 1) {
            for m in 0..(self._n % 4) {
                self.hit_label[w * 4 + m].next = self.words[w].val().get_bits::<16>(m * 16);
            }
        }
    }
}
