//! `FccSlotCheck`: whether a record read for a close leaves (combinational;
//! docs/column-core.md, item 4). A close at column `col` takes a cluster
//! that nothing holds after `col`: it has points, no run open, no ring
//! flag, it went quiet by `col` and its last column is at least `h`
//! columns back (`last <= lim`, `lim = col - h` worked out a cycle
//! ahead, its bit 12 set when negative; `lim = col` at the frame's last
//! column, after which hold 1 is gone). At the frame end (`frame_end`)
//! every cluster with points leaves. Either way the op names the cluster
//! by its first pixel (`key`, from the closer's wait list): a report gone
//! stale (the cluster merged, or its slot freed and taken by another) does
//! not match the slot's first pixel (`first`), so the record stays.

use rust_hdl::prelude::*;

use super::FIRST_BITS;

#[derive(LogicBlock, Default)]
pub struct FccSlotCheck {
    /// The record has points; its last column.
    pub has: Signal<In, Bit>,
    pub last: Signal<In, Bits<12>>,
    /// The holds' open runs, ring flag and quiet column.
    pub open: Signal<In, Bits<8>>,
    pub ring: Signal<In, Bit>,
    pub quiet: Signal<In, Bits<12>>,
    pub col: Signal<In, Bits<12>>,
    pub lim: Signal<In, Bits<13>>,
    pub frame_end: Signal<In, Bit>,
    /// The slot's first pixel, and the one the op names.
    pub first: Signal<In, Bits<FIRST_BITS>>,
    pub key: Signal<In, Bits<FIRST_BITS>>,
    pub leaves: Signal<Out, Bit>,
}

impl Logic for FccSlotCheck {
    #[hdl_gen]
    fn update(&mut self) {
        self.leaves.next = self.has.val()
            & (self.first.val() == self.key.val())
            & (self.frame_end.val()
                | (!self.open.val().any()
                    & !self.ring.val()
                    & (self.quiet.val() <= self.col.val())
                    & !self.lim.val().get_bit(12)
                    & (self.last.val() <= self.lim.val().get_bits::<12>(0))));
    }
}
