//! `FccCredits`: the front end's credit counter.
//!
//! Every pixel slot taken (`slot`) holds a credit until the sort network
//! either drops it (`drop`: no record needed) or takes its record out of the
//! centre buffer (`take`); both may return one in the same cycle. `room` is
//! registered: high while fewer than [`CREDITS`] credits are out, so the
//! centre buffer can never overflow and `s_axis_tready` is a flip-flop's
//! output. `rst` returns every credit.

use rust_hdl::prelude::*;

use crate::types::kb;

/// Pixel slots that may be between the input and the centre buffer's output:
/// the buffer's size less a margin for the registered `s_axis_tready`.
pub const CREDITS: usize = (1 << crate::fcc_sort_net::CB_BITS) - 16;

#[derive(LogicBlock)]
pub struct FccCredits {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A pixel slot enters the pipeline this cycle.
    pub slot: Signal<In, Bit>,
    /// The sort network returns a credit (each of the two).
    pub drop: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    /// Fewer than `CREDITS` credits were out at the last clock edge.
    pub room: Signal<Out, Bit>,
    credits: DFF<Bits<10>>,
    room_q: DFF<Bit>,
    one10: Constant<Bits<10>>,
    two10: Constant<Bits<10>>,
    zero10: Constant<Bits<10>>,
    limit: Constant<Bits<10>>,
}

impl Default for FccCredits {
    fn default() -> Self {
        Self::with_limit(CREDITS)
    }
}

impl FccCredits {
    /// A counter whose `room` is high while fewer than `limit` credits are
    /// out (below 1024).
    pub fn with_limit(limit: usize) -> Self {
        assert!(limit < 1024, "{limit} credits do not fit the counter");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            slot: Default::default(),
            drop: Default::default(),
            take: Default::default(),
            room: Default::default(),
            credits: Default::default(),
            room_q: Default::default(),
            one10: kb(1),
            two10: kb(2),
            zero10: kb(0),
            limit: kb(limit as u64),
        }
    }
}

impl Logic for FccCredits {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, credits, room_q);
        self.credits.d.next = self.credits.q.val();
        if self.slot.val() {
            self.credits.d.next = self.credits.q.val() + self.one10.val();
            if self.drop.val() ^ self.take.val() {
                self.credits.d.next = self.credits.q.val();
            }
            if self.drop.val() & self.take.val() {
                self.credits.d.next = self.credits.q.val() - self.one10.val();
            }
        } else {
            if self.drop.val() ^ self.take.val() {
                self.credits.d.next = self.credits.q.val() - self.one10.val();
            }
            if self.drop.val() & self.take.val() {
                self.credits.d.next = self.credits.q.val() - self.two10.val();
            }
        }
        self.room_q.d.next = self.credits.q.val() < self.limit.val();
        if self.rst.val() {
            self.credits.d.next = self.zero10.val();
            self.room_q.d.next = true;
        }
        self.room.next = self.room_q.q.val();
    }
}
