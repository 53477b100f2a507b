//! `FccRowRunsProbe`: `FccRowRuns` for frames of the build's rows behind
//! scalar ports, for its own bench: the pixel slot field by field (with
//! its key and addend `THR_LAG` cycles later, as `FccPixThr` gives them),
//! the run parameters and the free list in; `take` and `out` field by
//! field (`o_*`) out. With `use_pool` the labels come from an
//! `FccLabelPool` of the build's label width (as in the core: its head
//! into the decision, `take` back), which the bench feeds with returned
//! labels (`ret`, `ret_label`) and frame starts (`clear`); `pool_ok` and
//! `pool_label` show its head.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_label_pool::FccLabelPool;
use super::fcc_open_room::OPEN_ROOM_BITS;
use super::fcc_row_runs::FccRowRuns;
use super::ColPix;

#[derive(LogicBlock)]
pub struct FccRowRunsProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub ok: Signal<In, Bit>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub first: Signal<In, Bit>,
    pub last: Signal<In, Bit>,
    pub key: Signal<In, Bits<16>>,
    pub ch: Signal<In, Bits<36>>,
    pub cv: Signal<In, Bits<36>>,
    pub last_col: Signal<In, Bits<12>>,
    pub reach: Signal<In, Bits<12>>,
    pub ring_on: Signal<In, Bit>,
    pub ring_f_max: Signal<In, Bits<12>>,
    pub ring_l_min: Signal<In, Bits<12>>,
    pub free_ok: Signal<In, Bit>,
    pub free_label: Signal<In, Bits<16>>,
    pub open_room: Signal<In, Bits<OPEN_ROOM_BITS>>,
    pub use_pool: Signal<In, Bit>,
    pub clear: Signal<In, Bit>,
    pub ret: Signal<In, Bit>,
    pub ret_label: Signal<In, Bits<16>>,
    pub take: Signal<Out, Bit>,
    pub pool_ok: Signal<Out, Bit>,
    pub pool_label: Signal<Out, Bits<16>>,
    pub free_count: Signal<Out, Bits<16>>,
    pub o_valid: Signal<Out, Bit>,
    pub o_ok: Signal<Out, Bit>,
    pub o_lok: Signal<Out, Bit>,
    pub o_x: Signal<Out, Bits<16>>,
    pub o_y: Signal<Out, Bits<16>>,
    pub o_z: Signal<Out, Bits<16>>,
    pub o_row: Signal<Out, Bits<7>>,
    pub o_col: Signal<Out, Bits<12>>,
    pub o_first: Signal<Out, Bit>,
    pub o_last: Signal<Out, Bit>,
    pub o_last_col: Signal<Out, Bit>,
    pub o_key: Signal<Out, Bits<16>>,
    pub o_cv: Signal<Out, Bits<36>>,
    pub o_label: Signal<Out, Bits<16>>,
    pub o_start: Signal<Out, Bit>,
    pub o_refused: Signal<Out, Bit>,
    pub o_ring_first: Signal<Out, Bit>,
    pub o_ring: Signal<Out, Bit>,
    pub o_ring_hold: Signal<Out, Bit>,
    pub o_ring_a: Signal<Out, Bits<16>>,
    pub o_ring_b: Signal<Out, Bits<16>>,
    pub o_hold_drop: Signal<Out, Bits<16>>,
    pub o_hold_add: Signal<Out, Bits<16>>,
    pub o_hold_rep: Signal<Out, Bits<16>>,
    runs: FccRowRuns,
    pool: FccLabelPool,
    slot: Signal<Local, ColPix>,
}

impl FccRowRunsProbe {
    pub fn new(p: &FccParams) -> Self {
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
            key: Default::default(),
            ch: Default::default(),
            cv: Default::default(),
            last_col: Default::default(),
            reach: Default::default(),
            ring_on: Default::default(),
            ring_f_max: Default::default(),
            ring_l_min: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            open_room: Default::default(),
            use_pool: Default::default(),
            clear: Default::default(),
            ret: Default::default(),
            ret_label: Default::default(),
            take: Default::default(),
            pool_ok: Default::default(),
            pool_label: Default::default(),
            free_count: Default::default(),
            o_valid: Default::default(),
            o_ok: Default::default(),
            o_lok: Default::default(),
            o_x: Default::default(),
            o_y: Default::default(),
            o_z: Default::default(),
            o_row: Default::default(),
            o_col: Default::default(),
            o_first: Default::default(),
            o_last: Default::default(),
            o_last_col: Default::default(),
            o_key: Default::default(),
            o_cv: Default::default(),
            o_label: Default::default(),
            o_start: Default::default(),
            o_refused: Default::default(),
            o_ring_first: Default::default(),
            o_ring: Default::default(),
            o_ring_hold: Default::default(),
            o_ring_a: Default::default(),
            o_ring_b: Default::default(),
            o_hold_drop: Default::default(),
            o_hold_add: Default::default(),
            o_hold_rep: Default::default(),
            runs: FccRowRuns::new(p.rows),
            pool: FccLabelPool::new(p),
            slot: Default::default(),
        }
    }
}

impl Logic for FccRowRunsProbe {
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
        self.runs.clk.next = self.clk.val();
        self.runs.rst.next = self.rst.val();
        self.runs.pix.next = self.slot.val();
        self.runs.key.next = self.key.val();
        self.runs.ch.next = self.ch.val();
        self.runs.cv.next = self.cv.val();
        self.runs.last_col.next = self.last_col.val();
        self.runs.reach.next = self.reach.val();
        self.runs.ring_on.next = self.ring_on.val();
        self.runs.ring_f_max.next = self.ring_f_max.val();
        self.runs.ring_l_min.next = self.ring_l_min.val();
        self.runs.free_ok.next = self.free_ok.val();
        self.runs.free_label.next = self.free_label.val();
        if self.use_pool.val() {
            self.runs.free_ok.next = self.pool.free_ok.val();
            self.runs.free_label.next = self.pool.free_label.val();
        }
        self.runs.open_room.next = self.open_room.val();
        self.take.next = self.runs.take.val();
        self.pool.clk.next = self.clk.val();
        self.pool.rst.next = self.rst.val();
        self.pool.clear.next = self.clear.val();
        self.pool.take.next = self.use_pool.val() & self.runs.take.val();
        self.pool.ret.next = self.ret.val();
        self.pool.ret_label.next = self.ret_label.val();
        self.pool_ok.next = self.pool.free_ok.val();
        self.pool_label.next = self.pool.free_label.val();
        self.free_count.next = self.pool.free_count.val();
        self.o_valid.next = self.runs.out.val().valid;
        self.o_ok.next = self.runs.out.val().ok;
        self.o_lok.next = self.runs.out.val().lok;
        self.o_x.next = self.runs.out.val().x;
        self.o_y.next = self.runs.out.val().y;
        self.o_z.next = self.runs.out.val().z;
        self.o_row.next = self.runs.out.val().row;
        self.o_col.next = self.runs.out.val().col;
        self.o_first.next = self.runs.out.val().first;
        self.o_last.next = self.runs.out.val().last;
        self.o_last_col.next = self.runs.out.val().last_col;
        self.o_key.next = self.runs.out.val().key;
        self.o_cv.next = self.runs.out.val().cv;
        self.o_label.next = self.runs.out.val().label;
        self.o_start.next = self.runs.out.val().start;
        self.o_refused.next = self.runs.out.val().refused;
        self.o_ring_first.next = self.runs.out.val().ring_first;
        self.o_ring.next = self.runs.out.val().ring;
        self.o_ring_hold.next = self.runs.out.val().ring_hold;
        self.o_ring_a.next = self.runs.out.val().ring_a;
        self.o_ring_b.next = self.runs.out.val().ring_b;
        self.o_hold_drop.next = self.runs.out.val().hold_drop;
        self.o_hold_add.next = self.runs.out.val().hold_add;
        self.o_hold_rep.next = self.runs.out.val().hold_rep;
    }
}
