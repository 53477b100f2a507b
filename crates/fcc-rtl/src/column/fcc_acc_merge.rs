//! `FccAccMerge`: two records' accumulators as one (combinational; spec
//! §9.3, as the golden `Acc::merge`): counts and sums add, boxes, spans and
//! squared ranges take the smaller minimum and the larger maximum, the
//! seam span's halves keep what either has, `seam` is either's.

use rust_hdl::prelude::*;

use super::AccWord;

#[derive(LogicBlock, Default)]
pub struct FccAccMerge {
    pub a: Signal<In, AccWord>,
    pub b: Signal<In, AccWord>,
    pub out: Signal<Out, AccWord>,
}

impl Logic for FccAccMerge {
    #[hdl_gen]
    fn update(&mut self) {
        self.out.next = self.a.val();
        self.out.next.points = self.a.val().points + self.b.val().points;
        if self.b.val().min_col < self.a.val().min_col {
            self.out.next.min_col = self.b.val().min_col;
        }
        if self.b.val().max_col > self.a.val().max_col {
            self.out.next.max_col = self.b.val().max_col;
        }
        if self.b.val().lo_has
            & (!self.a.val().lo_has | (self.b.val().lo_max > self.a.val().lo_max))
        {
            self.out.next.lo_has = true;
            self.out.next.lo_max = self.b.val().lo_max;
        }
        if self.b.val().hi_has
            & (!self.a.val().hi_has | (self.b.val().hi_min < self.a.val().hi_min))
        {
            self.out.next.hi_has = true;
            self.out.next.hi_min = self.b.val().hi_min;
        }
        if self.b.val().first_row < self.a.val().first_row {
            self.out.next.first_row = self.b.val().first_row;
        }
        if self.b.val().last_row > self.a.val().last_row {
            self.out.next.last_row = self.b.val().last_row;
        }
        if self.b.val().min_x < self.a.val().min_x {
            self.out.next.min_x = self.b.val().min_x;
        }
        if self.b.val().min_y < self.a.val().min_y {
            self.out.next.min_y = self.b.val().min_y;
        }
        if self.b.val().min_z < self.a.val().min_z {
            self.out.next.min_z = self.b.val().min_z;
        }
        if self.b.val().max_x > self.a.val().max_x {
            self.out.next.max_x = self.b.val().max_x;
        }
        if self.b.val().max_y > self.a.val().max_y {
            self.out.next.max_y = self.b.val().max_y;
        }
        if self.b.val().max_z > self.a.val().max_z {
            self.out.next.max_z = self.b.val().max_z;
        }
        if self.b.val().r2_min < self.a.val().r2_min {
            self.out.next.r2_min = self.b.val().r2_min;
        }
        if self.b.val().r2_max > self.a.val().r2_max {
            self.out.next.r2_max = self.b.val().r2_max;
        }
        self.out.next.sa = self.a.val().sa + self.b.val().sa;
        self.out.next.sb = self.a.val().sb + self.b.val().sb;
        self.out.next.sc = self.a.val().sc + self.b.val().sc;
        self.out.next.sxx = self.a.val().sxx + self.b.val().sxx;
        self.out.next.syy = self.a.val().syy + self.b.val().syy;
        self.out.next.sab = self.a.val().sab + self.b.val().sab;
        self.out.next.seam = self.a.val().seam | self.b.val().seam;
    }
}
