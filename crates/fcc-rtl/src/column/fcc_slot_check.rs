//! `FccSlotCheck`: whether a record read for a close leaves (combinational;
//! docs/column-core.md, item 4). A close at column `col` takes a cluster
//! that nothing holds after `col`: it has points, no run open, no ring
//! flag, it went quiet by `col` and its last column is at least `h`
//! columns back (`last <= lim`, `lim = col - h` worked out a cycle
//! ahead, its bit 12 set when negative). At the frame end (`frame_end`)
//! every cluster with points leaves.

use rust_hdl::prelude::*;

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
    pub leaves: Signal<Out, Bit>,
}

impl Logic for FccSlotCheck {
    #[hdl_gen]
    fn update(&mut self) {
        self.leaves.next = self.has.val()
            & (self.frame_end.val()
                | (!self.open.val().any()
                    & !self.ring.val()
                    & (self.quiet.val() <= self.col.val())
                    & !self.lim.val().get_bit(12)
                    & (self.last.val() <= self.lim.val().get_bits::<12>(0))));
    }
}
