//! `FccInputStageProbe`: `FccInputStage` with its slot (`Pix`, 75 bits)
//! brought out field by field, for the input stage's own bench; every other
//! port passes through under its own name.

use rust_hdl::prelude::*;

use crate::fcc_input_stage::FccInputStage;

#[derive(LogicBlock, Default)]
pub struct FccInputStageProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub rst_next: Signal<In, Bit>,
    pub s_axis_tdata: Signal<In, Bits<49>>,
    pub s_axis_tvalid: Signal<In, Bit>,
    pub s_axis_tlast: Signal<In, Bit>,
    pub s_axis_tready: Signal<Out, Bit>,
    pub run_rows: Signal<In, Bits<8>>,
    pub run_cols: Signal<In, Bits<12>>,
    pub run: Signal<In, Bit>,
    pub restart: Signal<In, Bit>,
    pub run_next: Signal<In, Bit>,
    pub room: Signal<In, Bit>,
    pub col_hold: Signal<In, Bit>,
    pub col_first: Signal<Out, Bit>,
    pub slot_now: Signal<Out, Bit>,
    pub slot_valid: Signal<Out, Bit>,
    pub slot_ok: Signal<Out, Bit>,
    pub slot_x: Signal<Out, Bits<16>>,
    pub slot_y: Signal<Out, Bits<16>>,
    pub slot_z: Signal<Out, Bits<16>>,
    pub slot_row: Signal<Out, Bits<8>>,
    pub slot_col: Signal<Out, Bits<12>>,
    pub slot_first: Signal<Out, Bit>,
    pub slot_last: Signal<Out, Bit>,
    pub slot_col0: Signal<Out, Bit>,
    pub slot_coln: Signal<Out, Bit>,
    pub in_done: Signal<Out, Bit>,
    pub err: Signal<Out, Bit>,
    pub last_col: Signal<Out, Bits<12>>,
    pub idle: Signal<Out, Bit>,
    pub idle_next: Signal<Out, Bit>,
    stage: FccInputStage,
}

impl FccInputStageProbe {
    /// The probe of the column-order stage (`FccInputStage::column_order`).
    pub fn column_order() -> Self {
        Self {
            stage: FccInputStage::column_order(),
            ..Self::default()
        }
    }
}

impl Logic for FccInputStageProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.stage.clk.next = self.clk.val();
        self.stage.rst.next = self.rst.val();
        self.stage.rst_next.next = self.rst_next.val();
        self.stage.s_axis_tdata.next = self.s_axis_tdata.val();
        self.stage.s_axis_tvalid.next = self.s_axis_tvalid.val();
        self.stage.s_axis_tlast.next = self.s_axis_tlast.val();
        self.stage.run_rows.next = self.run_rows.val();
        self.stage.run_cols.next = self.run_cols.val();
        self.stage.run.next = self.run.val();
        self.stage.restart.next = self.restart.val();
        self.stage.run_next.next = self.run_next.val();
        self.stage.room.next = self.room.val();
        self.stage.col_hold.next = self.col_hold.val();
        self.col_first.next = self.stage.col_first.val();
        self.s_axis_tready.next = self.stage.s_axis_tready.val();
        self.slot_now.next = self.stage.slot_now.val();
        self.slot_valid.next = self.stage.slot.val().valid;
        self.slot_ok.next = self.stage.slot.val().ok;
        self.slot_x.next = self.stage.slot.val().x;
        self.slot_y.next = self.stage.slot.val().y;
        self.slot_z.next = self.stage.slot.val().z;
        self.slot_row.next = self.stage.slot.val().row;
        self.slot_col.next = self.stage.slot.val().col;
        self.slot_first.next = self.stage.slot.val().first;
        self.slot_last.next = self.stage.slot.val().last;
        self.slot_col0.next = self.stage.slot.val().col0;
        self.slot_coln.next = self.stage.slot.val().coln;
        self.in_done.next = self.stage.in_done.val();
        self.err.next = self.stage.err.val();
        self.last_col.next = self.stage.last_col.val();
        self.idle.next = self.stage.idle.val();
        self.idle_next.next = self.stage.idle_next.val();
    }
}
