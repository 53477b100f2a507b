//! `FccQuadLane`: one lane of `FccColSlotBuf`, four window entries' labels
//! (`l0` .. `l3`) in an `FccStreamLane` of one 64-bit word, moved by the
//! buffer's one control (`FccStreamCtl`) with its other lanes.

use rust_hdl::prelude::*;

use super::fcc_col_slot_buf::SLOT_BUF_BITS;
use crate::fcc_stream_ctl::LOAD;
use crate::fcc_stream_lane::FccStreamLane;

/// Four entries' labels in one lane word, the first in the low bits.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct LabelQuad {
    pub l0: Bits<16>,
    pub l1: Bits<16>,
    pub l2: Bits<16>,
    pub l3: Bits<16>,
}

#[derive(LogicBlock, Default)]
pub struct FccQuadLane {
    pub clk: Signal<In, Clock>,
    /// The control's signals (`FccStreamLane`'s).
    pub we: Signal<In, Bit>,
    pub waddr: Signal<In, Bits<SLOT_BUF_BITS>>,
    pub re: Signal<In, Bit>,
    pub raddr: Signal<In, Bits<SLOT_BUF_BITS>>,
    pub shift: Signal<In, Bit>,
    pub load: Signal<In, Bits<LOAD>>,
    pub l0: Signal<In, Bits<16>>,
    pub l1: Signal<In, Bits<16>>,
    pub l2: Signal<In, Bits<16>>,
    pub l3: Signal<In, Bits<16>>,
    /// The head's labels.
    pub o0: Signal<Out, Bits<16>>,
    pub o1: Signal<Out, Bits<16>>,
    pub o2: Signal<Out, Bits<16>>,
    pub o3: Signal<Out, Bits<16>>,
    lane: FccStreamLane<LabelQuad, SLOT_BUF_BITS>,
    quad: Signal<Local, LabelQuad>,
}

impl Logic for FccQuadLane {
    #[hdl_gen]
    fn update(&mut self) {
        self.quad.next.l0 = self.l0.val();
        self.quad.next.l1 = self.l1.val();
        self.quad.next.l2 = self.l2.val();
        self.quad.next.l3 = self.l3.val();
        self.lane.clk.next = self.clk.val();
        self.lane.we.next = self.we.val();
        self.lane.waddr.next = self.waddr.val();
        self.lane.din.next = self.quad.val();
        self.lane.re.next = self.re.val();
        self.lane.raddr.next = self.raddr.val();
        self.lane.shift.next = self.shift.val();
        self.lane.load.next = self.load.val();
        self.o0.next = self.lane.dout.val().l0;
        self.o1.next = self.lane.dout.val().l1;
        self.o2.next = self.lane.dout.val().l2;
        self.o3.next = self.lane.dout.val().l3;
    }
}
