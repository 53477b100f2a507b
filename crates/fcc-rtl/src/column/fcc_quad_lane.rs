//! `FccQuadLane`: one lane of `FccColSlotBuf`, four window entries' labels
//! (`l0` .. `l3`) through an `FccStreamFifo` of one 64-bit word, pushed
//! and taken with the buffer's other lanes.

use rust_hdl::prelude::*;

use super::fcc_col_slot_buf::SLOT_BUF_BITS;
use crate::fcc_stream_fifo::FccStreamFifo;

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
    pub rst: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    pub l0: Signal<In, Bits<16>>,
    pub l1: Signal<In, Bits<16>>,
    pub l2: Signal<In, Bits<16>>,
    pub l3: Signal<In, Bits<16>>,
    /// The head's labels.
    pub o0: Signal<Out, Bits<16>>,
    pub o1: Signal<Out, Bits<16>>,
    pub o2: Signal<Out, Bits<16>>,
    pub o3: Signal<Out, Bits<16>>,
    fifo: FccStreamFifo<LabelQuad, SLOT_BUF_BITS, { SLOT_BUF_BITS + 1 }>,
    quad: Signal<Local, LabelQuad>,
}

impl Logic for FccQuadLane {
    #[hdl_gen]
    fn update(&mut self) {
        self.quad.next.l0 = self.l0.val();
        self.quad.next.l1 = self.l1.val();
        self.quad.next.l2 = self.l2.val();
        self.quad.next.l3 = self.l3.val();
        self.fifo.clk.next = self.clk.val();
        self.fifo.rst.next = self.rst.val();
        self.fifo.push.next = self.push.val();
        self.fifo.din.next = self.quad.val();
        self.fifo.take.next = self.take.val();
        self.o0.next = self.fifo.dout.val().l0;
        self.o1.next = self.fifo.dout.val().l1;
        self.o2.next = self.fifo.dout.val().l2;
        self.o3.next = self.fifo.dout.val().l3;
    }
}
