//! `FccHoldsMerge`: two clusters' holds as one (combinational; the record
//! store's, beside `FccAccMerge`): the open runs add (a flush adds -1),
//! the ring flags OR, the smaller first pixel stays; when no run is left
//! open the merge's column becomes the quiet column, and `quiet` says the
//! cluster is held by nothing but its last column (no run open, no ring).
//! The labels' lists join, `b`'s after `a`'s: when both have one, `link`
//! says `a`'s tail must point to `b`'s head (`FccLabelLists`).

use rust_hdl::prelude::*;

use super::SlotHolds;

#[derive(LogicBlock, Default)]
pub struct FccHoldsMerge {
    pub a: Signal<In, SlotHolds>,
    pub b: Signal<In, SlotHolds>,
    pub col: Signal<In, Bits<12>>,
    pub out: Signal<Out, SlotHolds>,
    pub quiet: Signal<Out, Bit>,
    pub link: Signal<Out, Bit>,
    pub link_from: Signal<Out, Bits<16>>,
    pub link_to: Signal<Out, Bits<16>>,
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
        if !self.a.val().head.any() {
            self.out.next.head = self.b.val().head;
            self.out.next.tail = self.b.val().tail;
        }
        if self.a.val().head.any() & self.b.val().head.any() {
            self.out.next.tail = self.b.val().tail;
        }
        self.link.next = self.a.val().head.any() & self.b.val().head.any();
        self.link_from.next = self.a.val().tail;
        self.link_to.next = self.b.val().head;
    }
}
