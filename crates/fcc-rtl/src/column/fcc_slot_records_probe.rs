//! `FccSlotRecordsProbe`: `FccSlotRecords` behind scalar ports, for its
//! own bench: an op's kind as flags (`merge`, `close`, `frame_end`, `peek`; none: an
//! add), its word field by field (the record's `a_*`, the holds' `h_*`),
//! the record out field by field (`o_*`, its labels' list `out_head` to
//! `out_tail`).

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use super::fcc_slot_issue::SlotOp;
use super::fcc_slot_records::FccSlotRecords;
use super::{AccWord, SlotHolds, SlotWord, FIRST_BITS};

#[derive(LogicBlock, Default)]
pub struct FccSlotRecordsProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub half: Signal<In, Bits<3>>,
    pub last_col: Signal<In, Bits<12>>,
    pub op_valid: Signal<In, Bit>,
    pub merge: Signal<In, Bit>,
    pub close: Signal<In, Bit>,
    pub frame_end: Signal<In, Bit>,
    pub peek: Signal<In, Bit>,
    pub slot: Signal<In, Bits<SLOT_BITS>>,
    pub other: Signal<In, Bits<SLOT_BITS>>,
    pub col: Signal<In, Bits<12>>,
    pub h_open: Signal<In, Bits<8>>,
    pub h_ring: Signal<In, Bit>,
    pub h_first: Signal<In, Bits<FIRST_BITS>>,
    pub h_head: Signal<In, Bits<16>>,
    pub h_tail: Signal<In, Bits<16>>,
    pub a_points: Signal<In, Bits<20>>,
    pub a_min_col: Signal<In, Bits<12>>,
    pub a_max_col: Signal<In, Bits<12>>,
    pub a_lo_has: Signal<In, Bit>,
    pub a_lo_max: Signal<In, Bits<12>>,
    pub a_hi_has: Signal<In, Bit>,
    pub a_hi_min: Signal<In, Bits<12>>,
    pub a_first_row: Signal<In, Bits<7>>,
    pub a_last_row: Signal<In, Bits<7>>,
    pub a_min_x: Signal<In, Bits<16>>,
    pub a_min_y: Signal<In, Bits<16>>,
    pub a_min_z: Signal<In, Bits<16>>,
    pub a_max_x: Signal<In, Bits<16>>,
    pub a_max_y: Signal<In, Bits<16>>,
    pub a_max_z: Signal<In, Bits<16>>,
    pub a_r2_min: Signal<In, Bits<32>>,
    pub a_r2_max: Signal<In, Bits<32>>,
    pub a_sa: Signal<In, Bits<35>>,
    pub a_sb: Signal<In, Bits<35>>,
    pub a_sc: Signal<In, Bits<35>>,
    pub a_sxx: Signal<In, Bits<50>>,
    pub a_syy: Signal<In, Bits<50>>,
    pub a_sab: Signal<In, Bits<51>>,
    pub a_seam: Signal<In, Bit>,
    pub op_take: Signal<Out, Bit>,
    pub out_valid: Signal<Out, Bit>,
    pub out_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub q_valid: Signal<Out, Bit>,
    pub q_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub q_first: Signal<Out, Bits<FIRST_BITS>>,
    pub q_last: Signal<Out, Bits<12>>,
    pub q_col: Signal<Out, Bits<12>>,
    pub out_head: Signal<Out, Bits<16>>,
    pub out_tail: Signal<Out, Bits<16>>,
    pub link_valid: Signal<Out, Bit>,
    pub link_from: Signal<Out, Bits<16>>,
    pub link_to: Signal<Out, Bits<16>>,
    pub idle: Signal<Out, Bit>,
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
    acc: Signal<Local, AccWord>,
    holds: Signal<Local, SlotHolds>,
    word: Signal<Local, SlotWord>,
    out: Signal<Local, AccWord>,
    records: FccSlotRecords,
}

impl Logic for FccSlotRecordsProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.records.clk.next = self.clk.val();
        self.records.rst.next = self.rst.val();
        self.records.half.next = self.half.val();
        self.records.last_col.next = self.last_col.val();
        self.records.op_valid.next = self.op_valid.val();
        self.records.op_kind.next = SlotOp::Add;
        if self.merge.val() {
            self.records.op_kind.next = SlotOp::Merge;
        }
        if self.close.val() {
            self.records.op_kind.next = SlotOp::Close;
        }
        if self.peek.val() {
            self.records.op_kind.next = SlotOp::Peek;
        }
        if self.frame_end.val() {
            self.records.op_kind.next = SlotOp::End;
        }
        self.records.op_slot.next = self.slot.val();
        self.records.op_other.next = self.other.val();
        self.records.op_col.next = self.col.val();
        self.acc.next.points = self.a_points.val();
        self.acc.next.min_col = self.a_min_col.val();
        self.acc.next.max_col = self.a_max_col.val();
        self.acc.next.lo_has = self.a_lo_has.val();
        self.acc.next.lo_max = self.a_lo_max.val();
        self.acc.next.hi_has = self.a_hi_has.val();
        self.acc.next.hi_min = self.a_hi_min.val();
        self.acc.next.first_row = self.a_first_row.val();
        self.acc.next.last_row = self.a_last_row.val();
        self.acc.next.min_x = self.a_min_x.val();
        self.acc.next.min_y = self.a_min_y.val();
        self.acc.next.min_z = self.a_min_z.val();
        self.acc.next.max_x = self.a_max_x.val();
        self.acc.next.max_y = self.a_max_y.val();
        self.acc.next.max_z = self.a_max_z.val();
        self.acc.next.r2_min = self.a_r2_min.val();
        self.acc.next.r2_max = self.a_r2_max.val();
        self.acc.next.sa = self.a_sa.val();
        self.acc.next.sb = self.a_sb.val();
        self.acc.next.sc = self.a_sc.val();
        self.acc.next.sxx = self.a_sxx.val();
        self.acc.next.syy = self.a_syy.val();
        self.acc.next.sab = self.a_sab.val();
        self.acc.next.seam = self.a_seam.val();
        self.holds.next.open = self.h_open.val();
        self.holds.next.ring = self.h_ring.val();
        self.holds.next.first = self.h_first.val();
        self.holds.next.quiet = self.col.val();
        self.holds.next.head = self.h_head.val();
        self.holds.next.tail = self.h_tail.val();
        self.word.next.acc = self.acc.val();
        self.word.next.holds = self.holds.val();
        self.records.op_word.next = self.word.val();
        self.op_take.next = self.records.op_take.val();
        self.out_valid.next = self.records.out_valid.val();
        self.out_slot.next = self.records.out_slot.val();
        self.q_valid.next = self.records.q_valid.val();
        self.q_slot.next = self.records.q_slot.val();
        self.q_first.next = self.records.q_first.val();
        self.q_last.next = self.records.q_last.val();
        self.q_col.next = self.records.q_col.val();
        self.out_head.next = self.records.out_head.val();
        self.out_tail.next = self.records.out_tail.val();
        self.link_valid.next = self.records.link_valid.val();
        self.link_from.next = self.records.link_from.val();
        self.link_to.next = self.records.link_to.val();
        self.idle.next = self.records.idle.val();
        self.out.next = self.records.out_acc.val();
        self.o_points.next = self.out.val().points;
        self.o_min_col.next = self.out.val().min_col;
        self.o_max_col.next = self.out.val().max_col;
        self.o_lo_has.next = self.out.val().lo_has;
        self.o_lo_max.next = self.out.val().lo_max;
        self.o_hi_has.next = self.out.val().hi_has;
        self.o_hi_min.next = self.out.val().hi_min;
        self.o_first_row.next = self.out.val().first_row;
        self.o_last_row.next = self.out.val().last_row;
        self.o_min_x.next = self.out.val().min_x;
        self.o_min_y.next = self.out.val().min_y;
        self.o_min_z.next = self.out.val().min_z;
        self.o_max_x.next = self.out.val().max_x;
        self.o_max_y.next = self.out.val().max_y;
        self.o_max_z.next = self.out.val().max_z;
        self.o_r2_min.next = self.out.val().r2_min;
        self.o_r2_max.next = self.out.val().r2_max;
        self.o_sa.next = self.out.val().sa;
        self.o_sb.next = self.out.val().sb;
        self.o_sc.next = self.out.val().sc;
        self.o_sxx.next = self.out.val().sxx;
        self.o_syy.next = self.out.val().syy;
        self.o_sab.next = self.out.val().sab;
        self.o_seam.next = self.out.val().seam;
    }
}
