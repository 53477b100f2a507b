//! `FccHoldsMerge`: two clusters' holds as one (combinational; the record
//! store's, beside `FccAccMerge`): the open runs add (a flush adds -1),
//! the ring flags OR, the smaller first pixel stays; when no run is left
//! open the merge's column becomes the quiet column, and `quiet` says the
//! cluster is held by nothing but its last column (no run open, no ring).

use rust_hdl::prelude::*;

use super::SlotHolds;

#[derive(LogicBlock, Default)]
pub struct FccHoldsMerge {
    pub a: Signal<In, SlotHolds>,
    pub b: Signal<In, SlotHolds>,
    pub col: Signal<In, Bits<12>>,
    pub out: Signal<Out, SlotHolds>,
    pub quiet: Signal<Out, Bit>,
    open: Signal<Local, Bits<8>>,
}

impl Logic for FccHoldsMerge {
    #[hdl_gen]
    fn update(&mut self) {
        self.open.next = self.a.val().open + self.b.val().open;
        self.out.next = self.a.val();
        self.out.next.open = self.open.val();
        self.out.next.ring = self.a.val().ring | self.b.val().ring;
        if self.b.val().first < self.a.val().first {
            self.out.next.first = self.b.val().first;
        }
        if !self.open.val().any() {
            self.out.next.quiet = self.col.val();
        }
        self.quiet.next = !self.open.val().any() & !(self.a.val().ring | self.b.val().ring);
    }
}
