//! `FccColFrontProbe`: `FccColFront` of the build behind scalar ports, for
//! its own bench: the pixel slot field by field and the run parameters in;
//! `take`, the centre field by field (`o_*`), its hits as a mask (`hits`,
//! entry `e` in bit `e`) and the entries' labels four to a word (`lw0` ..
//! `lw13`, entry `4w + m` in bits `16m ..`), as `FccRepJoinsProbe` takes
//! them, out.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_front::FccColFront;
use super::fcc_hits_pack::FccHitsPack;
use super::fcc_open_room::OPEN_ROOM_BITS;
use super::fcc_quad_lane::LabelQuad;
use crate::types::Pix;

#[derive(LogicBlock)]
pub struct FccColFrontProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub ok: Signal<In, Bit>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<8>>,
    pub col: Signal<In, Bits<12>>,
    pub first: Signal<In, Bit>,
    pub last: Signal<In, Bit>,
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    pub last_col: Signal<In, Bits<12>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub run_k: Signal<In, Bits<4>>,
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub open_room: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub take: Signal<Out, Bit>,
    pub o_valid: Signal<Out, Bit>,
    pub o_ok: Signal<Out, Bit>,
    pub o_lok: Signal<Out, Bit>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_first: Signal<Out, Bit>,
    pub o_last: Signal<Out, Bit>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_refused: Signal<Out, Bit>,
    pub o_ring_first: Signal<Out, Bit>,
    pub o_ring: Signal<Out, Bit>,
    pub o_ring_a: Signal<Out, Bits<16>>,
    pub o_ring_b: Signal<Out, Bits<16>>,
    pub o_hold_drop: Signal<Out, Bits<16>>,
    pub o_hold_add: Signal<Out, Bits<16>>,
    pub hits: Signal<Out, Bits<64>>,
    pub lw0: Signal<Out, LabelQuad>,
    pub lw1: Signal<Out, LabelQuad>,
    pub lw2: Signal<Out, LabelQuad>,
    pub lw3: Signal<Out, LabelQuad>,
    pub lw4: Signal<Out, LabelQuad>,
    pub lw5: Signal<Out, LabelQuad>,
    pub lw6: Signal<Out, LabelQuad>,
    pub lw7: Signal<Out, LabelQuad>,
    pub lw8: Signal<Out, LabelQuad>,
    pub lw9: Signal<Out, LabelQuad>,
    pub lw10: Signal<Out, LabelQuad>,
    pub lw11: Signal<Out, LabelQuad>,
    pub lw12: Signal<Out, LabelQuad>,
    pub lw13: Signal<Out, LabelQuad>,
    front: FccColFront,
    pack: FccHitsPack,
    slot: Signal<Local, Pix>,
    _n: usize,
}

impl FccColFrontProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            ok: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            row: Default::default(),
            col: Default::default(),
            first: Default::default(),
            last: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            last_col: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            open_room: Default::default(),
            take: Default::default(),
            o_valid: Default::default(),
            o_ok: Default::default(),
            o_lok: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_first: Default::default(),
            o_last: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_refused: Default::default(),
            o_ring_first: Default::default(),
            o_ring: Default::default(),
            o_ring_a: Default::default(),
            o_ring_b: Default::default(),
            o_hold_drop: Default::default(),
            o_hold_add: Default::default(),
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
            front: FccColFront::new(p),
            pack: FccHitsPack::new(p),
            slot: Default::default(),
            _n: n,
        }
    }
}

impl Logic for FccColFrontProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.slot.next.valid = self.valid.val();
        self.slot.next.ok = self.ok.val();
        self.slot.next.x = self.x.val();
        self.slot.next.y = self.y.val();
        self.slot.next.z = self.z.val();
        self.slot.next.row = self.row.val();
        self.slot.next.col = self.col.val();
        self.slot.next.first = self.first.val();
        self.slot.next.last = self.last.val();
        self.slot.next.col0 = false;
        self.slot.next.coln = false;
        self.front.clk.next = self.clk.val();
        self.front.pix.next = self.slot.val();
        self.front.rst.next = self.rst.val();
        self.front.sh.next = self.sh.val();
        self.front.sv.next = self.sv.val();
        self.front.ch_t.next = self.ch_t.val();
        self.front.cv_t.next = self.cv_t.val();
        self.front.last_col.next = self.last_col.val();
        self.front.reach.next = self.reach.val();
        self.front.ring_on.next = self.ring_on.val();
        self.front.ring_f_max.next = self.ring_f_max.val();
        self.front.ring_l_min.next = self.ring_l_min.val();
        self.front.last_row.next = self.last_row.val();
        self.front.run_k.next = self.run_k.val();
        self.front.free_ok.next = self.free_ok.val();
        self.front.free_label.next = self.free_label.val();
        self.front.open_room.next = self.open_room.val();
        self.take.next = self.front.take.val();
        self.o_valid.next = self.front.centre.val().valid;
        self.o_ok.next = self.front.centre.val().ok;
        self.o_lok.next = self.front.centre.val().lok;
        self.o_row.next = self.front.centre.val().row;
        self.o_col.next = self.front.centre.val().col;
        self.o_first.next = self.front.centre.val().first;
        self.o_last.next = self.front.centre.val().last;
        self.o_label.next = self.front.centre.val().label;
        self.o_start.next = self.front.centre.val().start;
        self.o_refused.next = self.front.centre.val().refused;
        self.o_ring_first.next = self.front.centre.val().ring_first;
        self.o_ring.next = self.front.centre.val().ring;
        self.o_ring_a.next = self.front.centre.val().ring_a;
        self.o_ring_b.next = self.front.centre.val().ring_b;
        self.o_hold_drop.next = self.front.centre.val().hold_drop;
        self.o_hold_add.next = self.front.centre.val().hold_add;
        for e in 0..self._n {
            self.pack.hit[e].next = self.front.hit[e].val();
            self.pack.hit_label[e].next = self.front.hit_label[e].val();
        }
        self.hits.next = self.pack.hits.val();
        self.lw0.next = self.pack.lw0.val();
        self.lw1.next = self.pack.lw1.val();
        self.lw2.next = self.pack.lw2.val();
        self.lw3.next = self.pack.lw3.val();
        self.lw4.next = self.pack.lw4.val();
        self.lw5.next = self.pack.lw5.val();
        self.lw6.next = self.pack.lw6.val();
        self.lw7.next = self.pack.lw7.val();
        self.lw8.next = self.pack.lw8.val();
        self.lw9.next = self.pack.lw9.val();
        self.lw10.next = self.pack.lw10.val();
        self.lw11.next = self.pack.lw11.val();
        self.lw12.next = self.pack.lw12.val();
        self.lw13.next = self.pack.lw13.val();
    }
}
