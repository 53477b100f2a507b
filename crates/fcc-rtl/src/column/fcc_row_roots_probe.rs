//! `FccRowRootsProbe`: `FccRowRoots` for frames of the build's rows and K
//! behind scalar ports, for its own bench. A pixel goes in field by field
//! with its window's hits as a mask (`hits`, entry `e` in bit `e`) and the
//! entries' labels four to a word (`lw0` .. `lw13`, entry `4w + m` in bits
//! `16m + 15 .. 16m` of word `w`); the pixel event and the merge come out
//! field by field (`o_*`, `m_*`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_row_roots::FccRowRoots;
use super::{RunPix, SLOT_BITS};
use crate::types::vec_of;

/// Label words: four entries each, for the largest window (K = 11: 55).
pub const LABEL_WORDS: usize = 14;

#[derive(LogicBlock)]
pub struct FccRowRootsProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub ok: Signal<In, Bit>,
    pub lok: Signal<In, Bit>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub label: Signal<In, Bits<16>>,
    pub start: Signal<In, Bit>,
    pub ring_first: Signal<In, Bit>,
    pub ring: Signal<In, Bit>,
    pub ring_a: Signal<In, Bits<16>>,
    pub ring_b: Signal<In, Bits<16>>,
    pub hold_drop: Signal<In, Bits<16>>,
    pub hold_add: Signal<In, Bits<16>>,
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
    pub last_row: Signal<In, Bits<7>>,
    pub new_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ready: Signal<Out, Bit>,
    pub take: Signal<Out, Bit>,
    pub o_valid: Signal<Out, Bit>,
    pub o_lok: Signal<Out, Bit>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_own: Signal<Out, Bits<SLOT_BITS>>,
    pub o_drop_ok: Signal<Out, Bit>,
    pub o_drop: Signal<Out, Bits<SLOT_BITS>>,
    pub o_add_ok: Signal<Out, Bit>,
    pub o_add: Signal<Out, Bits<SLOT_BITS>>,
    pub m_valid: Signal<Out, Bit>,
    pub m_from: Signal<Out, Bits<SLOT_BITS>>,
    pub m_into: Signal<Out, Bits<SLOT_BITS>>,
    pub miss: Signal<Out, Bit>,
    roots: FccRowRoots,
    pix: Signal<Local, RunPix>,
    pix_zero: Constant<RunPix>,
    words: Vec<Signal<Local, Bits<64>>>,
    _ne: usize,
}

impl FccRowRootsProbe {
    pub fn new(p: &FccParams) -> Self {
        let ne = p.window_positions();
        assert!(ne <= 4 * LABEL_WORDS, "{ne} window entries do not fit");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            ok: Default::default(),
            lok: Default::default(),
            row: Default::default(),
            col: Default::default(),
            label: Default::default(),
            start: Default::default(),
            ring_first: Default::default(),
            ring: Default::default(),
            ring_a: Default::default(),
            ring_b: Default::default(),
            hold_drop: Default::default(),
            hold_add: Default::default(),
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
            last_row: Default::default(),
            new_slot: Default::default(),
            ready: Default::default(),
            take: Default::default(),
            o_valid: Default::default(),
            o_lok: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_own: Default::default(),
            o_drop_ok: Default::default(),
            o_drop: Default::default(),
            o_add_ok: Default::default(),
            o_add: Default::default(),
            m_valid: Default::default(),
            m_from: Default::default(),
            m_into: Default::default(),
            miss: Default::default(),
            roots: FccRowRoots::new(p.rows, p.fsize),
            pix: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
            words: vec_of(LABEL_WORDS),
            _ne: ne,
        }
    }
}

impl Logic for FccRowRootsProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.pix.next = self.pix_zero.val();
        self.pix.next.valid = self.valid.val();
        self.pix.next.ok = self.ok.val();
        self.pix.next.lok = self.lok.val();
        self.pix.next.row = self.row.val();
        self.pix.next.col = self.col.val();
        self.pix.next.label = self.label.val();
        self.pix.next.start = self.start.val();
        self.pix.next.ring_first = self.ring_first.val();
        self.pix.next.ring = self.ring.val();
        self.pix.next.ring_a = self.ring_a.val();
        self.pix.next.ring_b = self.ring_b.val();
        self.pix.next.hold_drop = self.hold_drop.val();
        self.pix.next.hold_add = self.hold_add.val();
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
        self.roots.clk.next = self.clk.val();
        self.roots.rst.next = self.rst.val();
        self.roots.inp.next = self.pix.val();
        self.roots.last_row.next = self.last_row.val();
        self.roots.new_slot.next = self.new_slot.val();
        for e in 0..self._ne {
            self.roots.inp_hit[e].next = self.hits.val().get_bit(e);
        }
        for w in 0..(self._ne / 4) {
            for m in 0..4 {
                self.roots.inp_label[w * 4 + m].next = self.words[w].val().get_bits::<16>(m * 16);
            }
        }
        for w in (self._ne / 4)..(self._ne / 4 + 1) {
            for m in 0..(self._ne % 4) {
                self.roots.inp_label[w * 4 + m].next = self.words[w].val().get_bits::<16>(m * 16);
            }
        }
        self.ready.next = self.roots.ready.val();
        self.take.next = self.roots.take.val();
        self.o_valid.next = self.roots.out.val().valid;
        self.o_lok.next = self.roots.out.val().lok;
        self.o_row.next = self.roots.out.val().row;
        self.o_col.next = self.roots.out.val().col;
        self.o_label.next = self.roots.out.val().label;
        self.o_start.next = self.roots.out.val().start;
        self.o_own.next = self.roots.out_own.val();
        self.o_drop_ok.next = self.roots.out_drop_ok.val();
        self.o_drop.next = self.roots.out_drop.val();
        self.o_add_ok.next = self.roots.out_add_ok.val();
        self.o_add.next = self.roots.out_add.val();
        self.m_valid.next = self.roots.m_valid.val();
        self.m_from.next = self.roots.m_from.val();
        self.m_into.next = self.roots.m_into.val();
        self.miss.next = self.roots.miss.val();
    }
}
