//! `FccRepGaps`: the shifts between two pixels' A1s, registered
//! (docs/column-core.md, item 3), for `FccRepAhead`: the difference of the
//! two stages' `sh` never changes as they move, so it moves with the
//! pixel instead of being subtracted every cycle. A pixel entering A2 is
//! `st0.sh` shifts behind the pixel entering M1 with it and `st1.sh`
//! behind the one entering M2 (both gain the edge's shift alike).
//!
//! * `d2`: A2's pixel behind M2's (the tree's second stage's correction);
//! * `d3`: M1's pixel behind M2's (the third's).

use rust_hdl::prelude::*;

#[derive(LogicBlock, Default)]
pub struct FccRepGaps {
    pub clk: Signal<In, Clock>,
    pub adv: Signal<In, Bit>,
    pub st0_sh: Signal<In, Bits<3>>,
    pub st1_sh: Signal<In, Bits<3>>,
    pub d2: Signal<Out, Bits<3>>,
    pub d3: Signal<Out, Bits<3>>,
    /// A2's pixel behind M1's and behind M2's; M1's behind M2's.
    a2_1: DFF<Bits<3>>,
    a2_2: DFF<Bits<3>>,
    m1_1: DFF<Bits<3>>,
}

impl Logic for FccRepGaps {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, a2_1, a2_2, m1_1);
        if self.adv.val() {
            self.a2_1.d.next = self.st0_sh.val();
            self.a2_2.d.next = self.st1_sh.val();
            self.m1_1.d.next = self.a2_1.q.val();
        }
        self.d2.next = self.a2_2.q.val();
        self.d3.next = self.m1_1.q.val();
    }
}
