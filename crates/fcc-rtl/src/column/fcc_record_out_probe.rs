//! `FccRecordOutProbe`: `FccRecordOut` with the accumulator field by field,
//! for its bench.

use rust_hdl::prelude::*;

use super::fcc_record_out::FccRecordOut;
use super::AccWord;

#[derive(LogicBlock, Default)]
pub struct FccRecordOutProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub load: Signal<In, Bit>,
    pub id: Signal<In, Bits<20>>,
    pub closed_col: Signal<In, Bits<13>>,
    pub points: Signal<In, Bits<20>>,
    pub min_col: Signal<In, Bits<12>>,
    pub max_col: Signal<In, Bits<12>>,
    pub lo_has: Signal<In, Bit>,
    pub lo_max: Signal<In, Bits<12>>,
    pub hi_has: Signal<In, Bit>,
    pub hi_min: Signal<In, Bits<12>>,
    pub first_row: Signal<In, Bits<7>>,
    pub last_row: Signal<In, Bits<7>>,
    pub min_x: Signal<In, Bits<16>>,
    pub min_y: Signal<In, Bits<16>>,
    pub min_z: Signal<In, Bits<16>>,
    pub max_x: Signal<In, Bits<16>>,
    pub max_y: Signal<In, Bits<16>>,
    pub max_z: Signal<In, Bits<16>>,
    pub r2_min: Signal<In, Bits<32>>,
    pub r2_max: Signal<In, Bits<32>>,
    pub sa: Signal<In, Bits<35>>,
    pub sb: Signal<In, Bits<35>>,
    pub sc: Signal<In, Bits<35>>,
    pub sxx: Signal<In, Bits<50>>,
    pub syy: Signal<In, Bits<50>>,
    pub sab: Signal<In, Bits<51>>,
    pub seam: Signal<In, Bit>,
    pub load_end: Signal<In, Bit>,
    pub overflow: Signal<In, Bit>,
    pub frame_error: Signal<In, Bit>,
    pub ready: Signal<In, Bit>,
    pub idle: Signal<Out, Bit>,
    pub valid: Signal<Out, Bit>,
    pub beat: Signal<Out, Bits<64>>,
    pub last: Signal<Out, Bit>,
    out: FccRecordOut,
    word: Signal<Local, AccWord>,
}

impl Logic for FccRecordOutProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.word.next.points = self.points.val();
        self.word.next.min_col = self.min_col.val();
        self.word.next.max_col = self.max_col.val();
        self.word.next.lo_has = self.lo_has.val();
        self.word.next.lo_max = self.lo_max.val();
        self.word.next.hi_has = self.hi_has.val();
        self.word.next.hi_min = self.hi_min.val();
        self.word.next.first_row = self.first_row.val();
        self.word.next.last_row = self.last_row.val();
        self.word.next.min_x = self.min_x.val();
        self.word.next.min_y = self.min_y.val();
        self.word.next.min_z = self.min_z.val();
        self.word.next.max_x = self.max_x.val();
        self.word.next.max_y = self.max_y.val();
        self.word.next.max_z = self.max_z.val();
        self.word.next.r2_min = self.r2_min.val();
        self.word.next.r2_max = self.r2_max.val();
        self.word.next.sa = self.sa.val();
        self.word.next.sb = self.sb.val();
        self.word.next.sc = self.sc.val();
        self.word.next.sxx = self.sxx.val();
        self.word.next.syy = self.syy.val();
        self.word.next.sab = self.sab.val();
        self.word.next.seam = self.seam.val();
        self.out.clk.next = self.clk.val();
        self.out.rst.next = self.rst.val();
        self.out.load.next = self.load.val();
        self.out.acc.next = self.word.val();
        self.out.id.next = self.id.val();
        self.out.closed_col.next = self.closed_col.val();
        self.out.load_end.next = self.load_end.val();
        self.out.overflow.next = self.overflow.val();
        self.out.frame_error.next = self.frame_error.val();
        self.out.ready.next = self.ready.val();
        self.idle.next = self.out.idle.val();
        self.valid.next = self.out.valid.val();
        self.beat.next = self.out.beat.val();
        self.last.next = self.out.last.val();
    }
}
