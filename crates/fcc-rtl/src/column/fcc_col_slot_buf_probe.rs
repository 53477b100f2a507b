//! `FccColSlotBufProbe`: `FccColSlotBuf` of the build behind scalar ports,
//! for its own bench: the credit taken (`slot`), a slot pushed (`push`
//! with a few of the centre's fields, the hits as a mask, the labels four
//! to a word `lw0` .. `lw13`) and `take` in; `room`, the head (`valid`,
//! `o_*`, `o_hits`, `o0` .. `o13`) out.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_slot_buf::FccColSlotBuf;
use super::fcc_hits_pack::FccHitsPack;
use super::fcc_hits_unpack::FccHitsUnpack;
use super::fcc_quad_lane::LabelQuad;
use super::RunPix;

#[derive(LogicBlock)]
pub struct FccColSlotBufProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub slot: Signal<In, Bit>,
    pub push: Signal<In, Bit>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub label: Signal<In, Bits<16>>,
    pub start: Signal<In, Bit>,
    pub hits: Signal<In, Bits<64>>,
    pub lw0: Signal<In, Bits<64>>,
    pub lw1: Signal<In, Bits<64>>,
    pub lw2: Signal<In, Bits<64>>,
    pub lw3: Signal<In, Bits<64>>,
    pub lw4: Signal<In, Bits<64>>,
    pub lw5: Signal<In, Bits<64>>,
    pub lw6: Signal<In, Bits<64>>,
    pub lw7: Signal<In, Bits<64>>,
    pub lw8: Signal<In, Bits<64>>,
    pub lw9: Signal<In, Bits<64>>,
    pub lw10: Signal<In, Bits<64>>,
    pub lw11: Signal<In, Bits<64>>,
    pub lw12: Signal<In, Bits<64>>,
    pub lw13: Signal<In, Bits<64>>,
    pub take: Signal<In, Bit>,
    pub room: Signal<Out, Bit>,
    pub valid: Signal<Out, Bit>,
    pub o_valid: Signal<Out, Bit>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_hits: Signal<Out, Bits<64>>,
    pub o0: Signal<Out, LabelQuad>,
    pub o1: Signal<Out, LabelQuad>,
    pub o2: Signal<Out, LabelQuad>,
    pub o3: Signal<Out, LabelQuad>,
    pub o4: Signal<Out, LabelQuad>,
    pub o5: Signal<Out, LabelQuad>,
    pub o6: Signal<Out, LabelQuad>,
    pub o7: Signal<Out, LabelQuad>,
    pub o8: Signal<Out, LabelQuad>,
    pub o9: Signal<Out, LabelQuad>,
    pub o10: Signal<Out, LabelQuad>,
    pub o11: Signal<Out, LabelQuad>,
    pub o12: Signal<Out, LabelQuad>,
    pub o13: Signal<Out, LabelQuad>,
    slots: FccColSlotBuf,
    pack: FccHitsPack,
    pix: Signal<Local, RunPix>,
    pix_zero: Constant<RunPix>,
    unpack: FccHitsUnpack,
    _n: usize,
}

impl FccColSlotBufProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            slot: Default::default(),
            push: Default::default(),
            row: Default::default(),
            col: Default::default(),
            label: Default::default(),
            start: Default::default(),
            hits: Default::default(),
            lw0: Default::default(),
            lw1: Default::default(),
            lw2: Default::default(),
            lw3: Default::default(),
            lw4: Default::default(),
            lw5: Default::default(),
            lw6: Default::default(),
            lw7: Default::default(),
            lw8: Default::default(),
            lw9: Default::default(),
            lw10: Default::default(),
            lw11: Default::default(),
            lw12: Default::default(),
            lw13: Default::default(),
            take: Default::default(),
            room: Default::default(),
            valid: Default::default(),
            o_valid: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_hits: Default::default(),
            o0: Default::default(),
            o1: Default::default(),
            o2: Default::default(),
            o3: Default::default(),
            o4: Default::default(),
            o5: Default::default(),
            o6: Default::default(),
            o7: Default::default(),
            o8: Default::default(),
            o9: Default::default(),
            o10: Default::default(),
            o11: Default::default(),
            o12: Default::default(),
            o13: Default::default(),
            slots: FccColSlotBuf::new(p),
            pack: FccHitsPack::new(p),
            pix: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
            unpack: FccHitsUnpack::new(p),
            _n: n,
        }
    }
}

impl Logic for FccColSlotBufProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.pix.next = self.pix_zero.val();
        self.pix.next.valid = self.push.val();
        self.pix.next.row = self.row.val();
        self.pix.next.col = self.col.val();
        self.pix.next.label = self.label.val();
        self.pix.next.start = self.start.val();
        self.slots.clk.next = self.clk.val();
        self.slots.rst.next = self.rst.val();
        self.slots.slot.next = self.slot.val();
        self.slots.take.next = self.take.val();
        self.slots.in_centre.next = self.pix.val();
        self.unpack.hits.next = self.hits.val();
        self.unpack.lw0.next = self.lw0.val();
        self.unpack.lw1.next = self.lw1.val();
        self.unpack.lw2.next = self.lw2.val();
        self.unpack.lw3.next = self.lw3.val();
        self.unpack.lw4.next = self.lw4.val();
        self.unpack.lw5.next = self.lw5.val();
        self.unpack.lw6.next = self.lw6.val();
        self.unpack.lw7.next = self.lw7.val();
        self.unpack.lw8.next = self.lw8.val();
        self.unpack.lw9.next = self.lw9.val();
        self.unpack.lw10.next = self.lw10.val();
        self.unpack.lw11.next = self.lw11.val();
        self.unpack.lw12.next = self.lw12.val();
        self.unpack.lw13.next = self.lw13.val();
        for e in 0..self._n {
            self.slots.in_hit[e].next = self.unpack.hit[e].val();
            self.slots.in_label[e].next = self.unpack.hit_label[e].val();
        }
        self.room.next = self.slots.room.val();
        self.valid.next = self.slots.valid.val();
        self.o_valid.next = self.slots.centre.val().valid;
        self.o_row.next = self.slots.centre.val().row;
        self.o_col.next = self.slots.centre.val().col;
        self.o_label.next = self.slots.centre.val().label;
        self.o_start.next = self.slots.centre.val().start;
        for e in 0..self._n {
            self.pack.hit[e].next = self.slots.hit[e].val();
            self.pack.hit_label[e].next = self.slots.hit_label[e].val();
        }
        self.o_hits.next = self.pack.hits.val();
        self.o0.next = self.pack.lw0.val();
        self.o1.next = self.pack.lw1.val();
        self.o2.next = self.pack.lw2.val();
        self.o3.next = self.pack.lw3.val();
        self.o4.next = self.pack.lw4.val();
        self.o5.next = self.pack.lw5.val();
        self.o6.next = self.pack.lw6.val();
        self.o7.next = self.pack.lw7.val();
        self.o8.next = self.pack.lw8.val();
        self.o9.next = self.pack.lw9.val();
        self.o10.next = self.pack.lw10.val();
        self.o11.next = self.pack.lw11.val();
        self.o12.next = self.pack.lw12.val();
        self.o13.next = self.pack.lw13.val();
    }
}
