//! `FccAccProbe`: `FccAccPixel` and `FccAccMerge` over four accumulator
//! registers behind scalar ports, for their bench. Per cycle one of: `add`
//! (slot `s` takes in the pixel given `ACC_PIXEL_LATENCY` cycles before),
//! `merge` (slot `s` takes in slot `t`,
//! which is emptied), `clear` (slot `s` is emptied); `rst` empties all.
//! Slot `rsel` comes out field by field (`o_*`), combinationally.

use rust_hdl::prelude::*;

use super::fcc_acc_merge::FccAccMerge;
use super::fcc_acc_pixel::FccAccPixel;
use super::AccWord;
use crate::types::{kb, vec_of};

/// Accumulator registers of the probe.
const SLOTS: usize = 4;

#[derive(LogicBlock)]
pub struct FccAccProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub add: Signal<In, Bit>,
    pub merge: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub s: Signal<In, Bits<2>>,
    pub t: Signal<In, Bits<2>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub half: Signal<In, Bits<12>>,
    pub rsel: Signal<In, Bits<2>>,
    pub o_points: Signal<Out, Bits<20>>,
    pub o_min_col: Signal<Out, Bits<12>>,
    pub o_max_col: Signal<Out, Bits<12>>,
    pub o_lo_has: Signal<Out, Bit>,
    pub o_lo_max: Signal<Out, Bits<12>>,
    pub o_hi_has: Signal<Out, Bit>,
    pub o_hi_min: Signal<Out, Bits<12>>,
    pub o_first_row: Signal<Out, Bits<7>>,
    pub o_last_row: Signal<Out, Bits<7>>,
    pub o_min_x: Signal<Out, Bits<16>>,
    pub o_min_y: Signal<Out, Bits<16>>,
    pub o_min_z: Signal<Out, Bits<16>>,
    pub o_max_x: Signal<Out, Bits<16>>,
    pub o_max_y: Signal<Out, Bits<16>>,
    pub o_max_z: Signal<Out, Bits<16>>,
    pub o_r2_min: Signal<Out, Bits<32>>,
    pub o_r2_max: Signal<Out, Bits<32>>,
    pub o_sa: Signal<Out, Bits<35>>,
    pub o_sb: Signal<Out, Bits<35>>,
    pub o_sc: Signal<Out, Bits<35>>,
    pub o_sxx: Signal<Out, Bits<50>>,
    pub o_syy: Signal<Out, Bits<50>>,
    pub o_sab: Signal<Out, Bits<51>>,
    pub o_seam: Signal<Out, Bit>,
    pixel: FccAccPixel,
    merger: FccAccMerge,
    slot: Vec<DFF<AccWord>>,
    sel_s: Signal<Local, AccWord>,
    sel_t: Signal<Local, AccWord>,
    rd: Signal<Local, AccWord>,
    empty: Constant<AccWord>,
    index: Vec<Constant<Bits<2>>>,
}

impl Default for FccAccProbe {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            add: Default::default(),
            merge: Default::default(),
            clear: Default::default(),
            s: Default::default(),
            t: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            row: Default::default(),
            col: Default::default(),
            half: Default::default(),
            rsel: Default::default(),
            o_points: Default::default(),
            o_min_col: Default::default(),
            o_max_col: Default::default(),
            o_lo_has: Default::default(),
            o_lo_max: Default::default(),
            o_hi_has: Default::default(),
            o_hi_min: Default::default(),
            o_first_row: Default::default(),
            o_last_row: Default::default(),
            o_min_x: Default::default(),
            o_min_y: Default::default(),
            o_min_z: Default::default(),
            o_max_x: Default::default(),
            o_max_y: Default::default(),
            o_max_z: Default::default(),
            o_r2_min: Default::default(),
            o_r2_max: Default::default(),
            o_sa: Default::default(),
            o_sb: Default::default(),
            o_sc: Default::default(),
            o_sxx: Default::default(),
            o_syy: Default::default(),
            o_sab: Default::default(),
            o_seam: Default::default(),
            pixel: Default::default(),
            merger: Default::default(),
            slot: vec_of(SLOTS),
            sel_s: Default::default(),
            sel_t: Default::default(),
            rd: Default::default(),
            empty: Constant::new(AccWord::empty()),
            index: (0..SLOTS).map(|i| kb(i as u64)).collect(),
        }
    }
}

impl Logic for FccAccProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.pixel.clk.next = self.clk.val();
        self.pixel.rst.next = self.rst.val();
        self.pixel.x.next = self.x.val();
        self.pixel.y.next = self.y.val();
        self.pixel.z.next = self.z.val();
        self.pixel.row.next = self.row.val();
        self.pixel.col.next = self.col.val();
        self.pixel.half.next = self.half.val();
        self.sel_s.next = self.empty.val();
        self.sel_t.next = self.empty.val();
        self.rd.next = self.empty.val();
        for i in 0..4 {
            if self.s.val() == self.index[i].val() {
                self.sel_s.next = self.slot[i].q.val();
            }
            if self.t.val() == self.index[i].val() {
                self.sel_t.next = self.slot[i].q.val();
            }
            if self.rsel.val() == self.index[i].val() {
                self.rd.next = self.slot[i].q.val();
            }
        }
        self.merger.a.next = self.sel_s.val();
        self.merger.b.next = self.sel_t.val();
        if self.add.val() {
            self.merger.b.next = self.pixel.acc.val();
        }
        for i in 0..4 {
            self.slot[i].clock.next = self.clk.val();
            self.slot[i].d.next = self.slot[i].q.val();
            if self.merge.val() & (self.t.val() == self.index[i].val()) {
                self.slot[i].d.next = self.empty.val();
            }
            if self.s.val() == self.index[i].val() {
                if self.add.val() | self.merge.val() {
                    self.slot[i].d.next = self.merger.out.val();
                }
                if self.clear.val() {
                    self.slot[i].d.next = self.empty.val();
                }
            }
            if self.rst.val() {
                self.slot[i].d.next = self.empty.val();
            }
        }
        self.o_points.next = self.rd.val().points;
        self.o_min_col.next = self.rd.val().min_col;
        self.o_max_col.next = self.rd.val().max_col;
        self.o_lo_has.next = self.rd.val().lo_has;
        self.o_lo_max.next = self.rd.val().lo_max;
        self.o_hi_has.next = self.rd.val().hi_has;
        self.o_hi_min.next = self.rd.val().hi_min;
        self.o_first_row.next = self.rd.val().first_row;
        self.o_last_row.next = self.rd.val().last_row;
        self.o_min_x.next = self.rd.val().min_x;
        self.o_min_y.next = self.rd.val().min_y;
        self.o_min_z.next = self.rd.val().min_z;
        self.o_max_x.next = self.rd.val().max_x;
        self.o_max_y.next = self.rd.val().max_y;
        self.o_max_z.next = self.rd.val().max_z;
        self.o_r2_min.next = self.rd.val().r2_min;
        self.o_r2_max.next = self.rd.val().r2_max;
        self.o_sa.next = self.rd.val().sa;
        self.o_sb.next = self.rd.val().sb;
        self.o_sc.next = self.rd.val().sc;
        self.o_sxx.next = self.rd.val().sxx;
        self.o_syy.next = self.rd.val().syy;
        self.o_sab.next = self.rd.val().sab;
        self.o_seam.next = self.rd.val().seam;
    }
}
