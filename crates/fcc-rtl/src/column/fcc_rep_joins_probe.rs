//! `FccRepJoinsProbe`: `FccRepJoins` for frames of the build's rows and K
//! behind scalar ports, for its own bench. A pixel goes in field by field
//! with its window's hits as a mask (`hits`, entry `e` in bit `e`) and the
//! entries' labels four to a word (`lw0` .. `lw13`, entry `4w + m` in bits
//! `16m + 15 .. 16m` of word `w`, as `FccRepJoinsProbe` takes them); the
//! pixel and the join come out field by field (`o_*`, `j_*`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_hits_unpack::FccHitsUnpack;
use super::fcc_rep_joins::FccRepJoins;
use super::RunPix;

#[derive(LogicBlock)]
pub struct FccRepJoinsProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub ok: Signal<In, Bit>,
    pub lok: Signal<In, Bit>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub label: Signal<In, Bits<16>>,
    pub start: Signal<In, Bit>,
    pub ring_first: Signal<In, Bit>,
    pub ring: Signal<In, Bit>,
    pub ring_a: Signal<In, Bits<16>>,
    pub ring_b: Signal<In, Bits<16>>,
    pub hold_drop: Signal<In, Bits<16>>,
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
    pub last_row: Signal<In, Bits<7>>,
    pub ready: Signal<Out, Bit>,
    pub o_valid: Signal<Out, Bit>,
    pub o_lok: Signal<Out, Bit>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_ring_first: Signal<Out, Bit>,
    pub o_hold_drop: Signal<Out, Bits<16>>,
    pub o_hold_rep: Signal<Out, Bits<16>>,
    pub j_valid: Signal<Out, Bit>,
    pub j_more: Signal<Out, Bit>,
    pub j_a: Signal<Out, Bits<16>>,
    pub j_b: Signal<Out, Bits<16>>,
    /// `j_a` is the run the pixel started, filed under `j_b`'s cluster.
    pub j_under: Signal<Out, Bit>,
    pub j_seam: Signal<Out, Bit>,
    pub miss: Signal<Out, Bit>,
    joins: FccRepJoins,
    pix: Signal<Local, RunPix>,
    pix_zero: Constant<RunPix>,
    unpack: FccHitsUnpack,
    _ne: usize,
}

impl FccRepJoinsProbe {
    pub fn new(p: &FccParams) -> Self {
        let ne = p.window_positions();
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            ok: Default::default(),
            lok: Default::default(),
            row: Default::default(),
            col: Default::default(),
            label: Default::default(),
            start: Default::default(),
            ring_first: Default::default(),
            ring: Default::default(),
            ring_a: Default::default(),
            ring_b: Default::default(),
            hold_drop: Default::default(),
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
            last_row: Default::default(),
            ready: Default::default(),
            o_valid: Default::default(),
            o_lok: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_ring_first: Default::default(),
            o_hold_drop: Default::default(),
            o_hold_rep: Default::default(),
            j_valid: Default::default(),
            j_more: Default::default(),
            j_a: Default::default(),
            j_b: Default::default(),
            j_under: Default::default(),
            j_seam: Default::default(),
            miss: Default::default(),
            joins: FccRepJoins::new(p.rows, p.fsize),
            pix: Default::default(),
            pix_zero: Constant::new(RunPix::default()),
            unpack: FccHitsUnpack::new(p),
            _ne: ne,
        }
    }
}

impl Logic for FccRepJoinsProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.pix.next = self.pix_zero.val();
        self.pix.next.valid = self.valid.val();
        self.pix.next.ok = self.ok.val();
        self.pix.next.lok = self.lok.val();
        self.pix.next.row = self.row.val();
        self.pix.next.col = self.col.val();
        self.pix.next.label = self.label.val();
        self.pix.next.start = self.start.val();
        self.pix.next.ring_first = self.ring_first.val();
        self.pix.next.ring = self.ring.val();
        self.pix.next.ring_a = self.ring_a.val();
        self.pix.next.ring_b = self.ring_b.val();
        self.pix.next.hold_drop = self.hold_drop.val();
        self.pix.next.hold_rep = self.hold_drop.val();
        self.joins.clk.next = self.clk.val();
        self.joins.rst.next = self.rst.val();
        self.joins.inp.next = self.pix.val();
        self.joins.last_row.next = self.last_row.val();
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
        for e in 0..self._ne {
            self.joins.inp_hit[e].next = self.unpack.hit[e].val();
            self.joins.inp_label[e].next = self.unpack.hit_label[e].val();
        }
        self.ready.next = self.joins.ready.val();
        self.o_valid.next = self.joins.out.val().valid;
        self.o_lok.next = self.joins.out.val().lok;
        self.o_row.next = self.joins.out.val().row;
        self.o_col.next = self.joins.out.val().col;
        self.o_label.next = self.joins.out.val().label;
        self.o_start.next = self.joins.out.val().start;
        self.o_ring_first.next = self.joins.out.val().ring_first;
        self.o_hold_drop.next = self.joins.out.val().hold_drop;
        self.o_hold_rep.next = self.joins.out.val().hold_rep;
        self.j_valid.next = self.joins.j_valid.val();
        self.j_more.next = self.joins.j_more.val();
        self.j_a.next = self.joins.j_a.val();
        self.j_b.next = self.joins.j_b.val();
        self.j_under.next = self.joins.j_under.val();
        self.j_seam.next = self.joins.j_seam.val();
        self.miss.next = self.joins.miss.val();
    }
}
