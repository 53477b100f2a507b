//! `FccColWindowProbe`: `FccColWindow` of the build's K and rows behind
//! scalar ports, for its own bench: a labelled pixel in field by field
//! (the fields the window reads, its key and pass-2 addend among them; the
//! rest of the slot is zero), the
//! centre's position and label out, and the entry chosen by `ent_sel`
//! (`e_ok` and the word) combinationally (zero past the last entry).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_col_window::FccColWindow;
use super::RunPix;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColWindowProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub valid: Signal<In, Bit>,
    pub lok: Signal<In, Bit>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub z: Signal<In, Bits<16>>,
    pub key: Signal<In, Bits<16>>,
    pub cv: Signal<In, Bits<36>>,
    pub label: Signal<In, Bits<16>>,
    pub row: Signal<In, Bits<7>>,
    pub col: Signal<In, Bits<12>>,
    pub last_row: Signal<In, Bits<7>>,
    pub run_k: Signal<In, Bits<4>>,
    pub ent_sel: Signal<In, Bits<8>>,
    pub c_valid: Signal<Out, Bit>,
    pub c_row: Signal<Out, Bits<7>>,
    pub c_col: Signal<Out, Bits<12>>,
    pub c_label: Signal<Out, Bits<16>>,
    pub e_ok: Signal<Out, Bit>,
    pub e_x: Signal<Out, Bits<16>>,
    pub e_y: Signal<Out, Bits<16>>,
    pub e_z: Signal<Out, Bits<16>>,
    pub e_key: Signal<Out, Bits<16>>,
    pub e_cv: Signal<Out, Bits<36>>,
    pub e_label: Signal<Out, Bits<16>>,
    col_window: FccColWindow,
    slot: Signal<Local, RunPix>,
    slot_zero: Constant<RunPix>,
    zero16: Constant<Bits<16>>,
    zero36: Constant<Bits<36>>,
    entry_index: Vec<Constant<Bits<8>>>,
}

impl FccColWindowProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(n <= 256, "{n} window entries do not fit ent_sel");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            valid: Default::default(),
            lok: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            key: Default::default(),
            cv: Default::default(),
            label: Default::default(),
            row: Default::default(),
            col: Default::default(),
            last_row: Default::default(),
            run_k: Default::default(),
            ent_sel: Default::default(),
            c_valid: Default::default(),
            c_row: Default::default(),
            c_col: Default::default(),
            c_label: Default::default(),
            e_ok: Default::default(),
            e_x: Default::default(),
            e_y: Default::default(),
            e_z: Default::default(),
            e_key: Default::default(),
            e_cv: Default::default(),
            e_label: Default::default(),
            col_window: FccColWindow::new(p),
            slot: Default::default(),
            slot_zero: Constant::new(RunPix::default()),
            zero16: kb(0),
            zero36: kb(0),
            entry_index: (0..n).map(|e| kb(e as u64)).collect(),
        }
    }
}

impl Logic for FccColWindowProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.slot.next = self.slot_zero.val();
        self.slot.next.valid = self.valid.val();
        self.slot.next.ok = self.lok.val();
        self.slot.next.lok = self.lok.val();
        self.slot.next.x = self.x.val();
        self.slot.next.y = self.y.val();
        self.slot.next.z = self.z.val();
        self.slot.next.key = self.key.val();
        self.slot.next.cv = self.cv.val();
        self.slot.next.label = self.label.val();
        self.slot.next.row = self.row.val();
        self.slot.next.col = self.col.val();
        self.col_window.clk.next = self.clk.val();
        self.col_window.rst.next = self.rst.val();
        self.col_window.inp.next = self.slot.val();
        self.col_window.last_row.next = self.last_row.val();
        self.col_window.run_k.next = self.run_k.val();
        self.c_valid.next = self.col_window.centre.val().valid;
        self.c_row.next = self.col_window.centre.val().row;
        self.c_col.next = self.col_window.centre.val().col;
        self.c_label.next = self.col_window.centre.val().label;
        self.e_ok.next = false;
        self.e_x.next = self.zero16.val();
        self.e_y.next = self.zero16.val();
        self.e_z.next = self.zero16.val();
        self.e_key.next = self.zero16.val();
        self.e_cv.next = self.zero36.val();
        self.e_label.next = self.zero16.val();
        for e in 0..self.entry_index.len() {
            if self.ent_sel.val() == self.entry_index[e].val() {
                self.e_ok.next = self.col_window.ent_ok[e].val();
                self.e_x.next = self.col_window.ent_x[e].val();
                self.e_y.next = self.col_window.ent_y[e].val();
                self.e_z.next = self.col_window.ent_z[e].val();
                self.e_key.next = self.col_window.ent_key[e].val();
                self.e_cv.next = self.col_window.ent_cv[e].val();
                self.e_label.next = self.col_window.ent_label[e].val();
            }
        }
    }
}
