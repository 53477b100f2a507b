//! `FccRunAccProbe`: `FccRunAcc` for frames of the build's rows behind
//! scalar ports, for its own bench: a pixel goes in field by field (its
//! point offset binary), a flush comes out field by field (`f_label`, the
//! accumulator as `o_*`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_run_acc::FccRunAcc;
use super::RunPix;

#[derive(LogicBlock)]
pub struct FccRunAccProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub lok: Signal<In, Bit>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub label: Signal<In, Bits<16>>,
    pub start: Signal<In, Bit>,
    pub hold_drop: Signal<In, Bits<16>>,
    pub last: Signal<In, Bit>,
    pub ring_hold: Signal<In, Bit>,
    pub half: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub drain_go: Signal<In, Bit>,
    pub ready: Signal<Out, Bit>,
    pub f_valid: Signal<Out, Bit>,
    pub f_label: Signal<Out, Bits<16>>,
    pub f_end: Signal<Out, Bit>,
    pub f_ring: Signal<Out, Bit>,
    pub done: Signal<Out, Bit>,
    pub bad: Signal<Out, Bit>,
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
    acc: FccRunAcc,
    pix: Signal<Local, RunPix>,
    pix_zero: Constant<RunPix>,
}

impl FccRunAccProbe {
    /// The block for frames of at most `p.rows` rows.
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            lok: Default::default(),
            row: Default::default(),
            col: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            label: Default::default(),
            start: Default::default(),
            hold_drop: Default::default(),
            last: Default::default(),
            ring_hold: Default::default(),
            half: Default::default(),
            last_row: Default::default(),
            drain_go: Default::default(),
            ready: Default::default(),
            f_valid: Default::default(),
            f_label: Default::default(),
            f_end: Default::default(),
            f_ring: Default::default(),
            done: Default::default(),
            bad: Default::default(),
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
            acc: FccRunAcc::new(p.rows),
            pix: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
        }
    }
}

impl Logic for FccRunAccProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.pix.next = self.pix_zero.val();
        self.pix.next.valid = self.valid.val();
        self.pix.next.lok = self.lok.val();
        self.pix.next.row = self.row.val();
        self.pix.next.col = self.col.val();
        self.pix.next.x = self.x.val();
        self.pix.next.y = self.y.val();
        self.pix.next.z = self.z.val();
        self.pix.next.label = self.label.val();
        self.pix.next.start = self.start.val();
        self.pix.next.hold_drop = self.hold_drop.val();
        self.pix.next.last = self.last.val();
        self.pix.next.ring_hold = self.ring_hold.val();
        self.acc.clk.next = self.clk.val();
        self.acc.rst.next = self.rst.val();
        self.acc.inp.next = self.pix.val();
        self.acc.half.next = self.half.val();
        self.acc.last_row.next = self.last_row.val();
        self.acc.drain_go.next = self.drain_go.val();
        self.ready.next = self.acc.ready.val();
        self.f_valid.next = self.acc.f_valid.val();
        self.f_label.next = self.acc.f_label.val();
        self.f_end.next = self.acc.f_end.val();
        self.f_ring.next = self.acc.f_ring.val();
        self.done.next = self.acc.done.val();
        self.bad.next = self.acc.bad.val();
        self.o_points.next = self.acc.f_acc.val().points;
        self.o_min_col.next = self.acc.f_acc.val().min_col;
        self.o_max_col.next = self.acc.f_acc.val().max_col;
        self.o_lo_has.next = self.acc.f_acc.val().lo_has;
        self.o_lo_max.next = self.acc.f_acc.val().lo_max;
        self.o_hi_has.next = self.acc.f_acc.val().hi_has;
        self.o_hi_min.next = self.acc.f_acc.val().hi_min;
        self.o_first_row.next = self.acc.f_acc.val().first_row;
        self.o_last_row.next = self.acc.f_acc.val().last_row;
        self.o_min_x.next = self.acc.f_acc.val().min_x;
        self.o_min_y.next = self.acc.f_acc.val().min_y;
        self.o_min_z.next = self.acc.f_acc.val().min_z;
        self.o_max_x.next = self.acc.f_acc.val().max_x;
        self.o_max_y.next = self.acc.f_acc.val().max_y;
        self.o_max_z.next = self.acc.f_acc.val().max_z;
        self.o_r2_min.next = self.acc.f_acc.val().r2_min;
        self.o_r2_max.next = self.acc.f_acc.val().r2_max;
        self.o_sa.next = self.acc.f_acc.val().sa;
        self.o_sb.next = self.acc.f_acc.val().sb;
        self.o_sc.next = self.acc.f_acc.val().sc;
        self.o_sxx.next = self.acc.f_acc.val().sxx;
        self.o_syy.next = self.acc.f_acc.val().syy;
        self.o_sab.next = self.acc.f_acc.val().sab;
        self.o_seam.next = self.acc.f_acc.val().seam;
    }
}
