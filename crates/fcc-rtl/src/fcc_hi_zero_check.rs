//! `FccHiZeroCheck`: the range check of a run-parameter write whose range is
//! every 16-bit value (RUN_SLOPE_H, RUN_SLOPE_V: `0 ..= 0xFFFF`), where
//! `FccRangeCheck`'s comparators against the ends would be constant: only
//! bits 31:16 of the bus data are checked, registered as W is taken, and
//! `ok` holds from the next cycle (the write's cycle), as `FccRangeCheck`'s.

use rust_hdl::prelude::*;

use crate::regmap::RunRange;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccHiZeroCheck {
    pub clk: Signal<In, Clock>,
    /// W is taken in this cycle: `bus_hi` is the data to check.
    pub w_take: Signal<In, Bit>,
    /// Bits 31:16 of the bus data.
    pub bus_hi: Signal<In, Bits<16>>,
    /// The held write data is in the range.
    pub ok: Signal<Out, Bit>,
    hi_zero: DFF<Bit>,
    zero16: Constant<Bits<16>>,
}

impl FccHiZeroCheck {
    /// The check of `range`, which must be every 16-bit value.
    pub fn new(range: RunRange) -> Self {
        assert_eq!(
            (range.min, range.max),
            (0, 0xffff),
            "a range other than 0 ..= 0xFFFF needs FccRangeCheck"
        );
        Self {
            clk: Default::default(),
            w_take: Default::default(),
            bus_hi: Default::default(),
            ok: Default::default(),
            hi_zero: Default::default(),
            zero16: kb(0),
        }
    }
}

impl Logic for FccHiZeroCheck {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, hi_zero);
        if self.w_take.val() {
            self.hi_zero.d.next = self.bus_hi.val() == self.zero16.val();
        }
        self.ok.next = self.hi_zero.q.val();
    }
}
