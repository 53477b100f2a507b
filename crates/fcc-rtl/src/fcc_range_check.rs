//! `FccRangeCheck`: the range check of a run-parameter write (RW with a
//! range, `regmap::run_range`). The bus data is compared as W is taken, one
//! registered comparator per flag: `hi_zero` for bits 31:16 (every range ends
//! below 2^16) and `ge` / `le` for bits 15:0 against each end of the range;
//! `ok` combines them (and, for a register that takes only odd values, bit 0
//! of the held data, `lsb`) in the write's cycle, so no chain of range
//! comparators follows the held data and none lies between it and the
//! registers the write sets.

use rust_hdl::prelude::*;

use crate::regmap::RunRange;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccRangeCheck {
    pub clk: Signal<In, Clock>,
    /// W is taken in this cycle: `bus_wdata` is the data to check.
    pub w_take: Signal<In, Bit>,
    pub bus_wdata: Signal<In, Bits<32>>,
    /// Bit 0 of the held write data.
    pub lsb: Signal<In, Bit>,
    /// The held write data is in the range.
    pub ok: Signal<Out, Bit>,
    hi_zero: DFF<Bit>,
    ge: DFF<Bit>,
    le: DFF<Bit>,
    /// The lower bound; none when it is 0 (every value is at least 0).
    min: Vec<Constant<Bits<16>>>,
    max: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    /// Any value is accepted whatever its bit 0 (not an odd-only register).
    any_lsb: Constant<Bit>,
}

impl FccRangeCheck {
    /// The check of `range`; `odd`: only odd values are accepted.
    pub fn new(range: RunRange, odd: bool) -> Self {
        assert!(
            range.min <= range.max && range.max < 1 << 16,
            "run range {range:?} is empty or ends at or above 2^16"
        );
        Self {
            clk: Default::default(),
            w_take: Default::default(),
            bus_wdata: Default::default(),
            lsb: Default::default(),
            ok: Default::default(),
            hi_zero: Default::default(),
            ge: Default::default(),
            le: Default::default(),
            min: (range.min > 0)
                .then(|| kb(u64::from(range.min)))
                .into_iter()
                .collect(),
            max: kb(u64::from(range.max)),
            zero16: kb(0),
            any_lsb: Constant::new(!odd),
        }
    }
}

impl Logic for FccRangeCheck {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, hi_zero, ge, le);
        if self.w_take.val() {
            self.hi_zero.d.next = self.bus_wdata.val().get_bits::<16>(16) == self.zero16.val();
            self.ge.d.next = true;
            for m in 0..self.min.len() {
                self.ge.d.next = self.bus_wdata.val().get_bits::<16>(0) >= self.min[m].val();
            }
            self.le.d.next = self.bus_wdata.val().get_bits::<16>(0) <= self.max.val();
        }
        self.ok.next = self.hi_zero.q.val()
            & self.ge.q.val()
            & self.le.q.val()
            & (self.lsb.val() | self.any_lsb.val());
    }
}
