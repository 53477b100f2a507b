//! `FccWindowProbe`: `fcc_window` (with its line buffers) behind scalar
//! ports, for the window's own bench. The pixel goes in field by field; the
//! window entry chosen by `ent_sel` comes out combinationally, so a bench
//! reads all `K*h` entries of a cycle by stepping `ent_sel` before the clock
//! edge. The representative window is not driven (its write port held idle).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_window::FccWindow;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccWindowProbe {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // The pixel (stage W0).
    pub in_valid: Signal<In, Bit>,
    pub in_lok: Signal<In, Bit>,
    pub in_x: Signal<In, Bits<16>>,
    pub in_y: Signal<In, Bits<16>>,
    pub in_z: Signal<In, Bits<16>>,
    pub in_row: Signal<In, Bits<8>>,
    pub in_col: Signal<In, Bits<12>>,
    pub in_rdcol: Signal<In, Bits<12>>,
    // Run size.
    pub last_col: Signal<In, Bits<12>>,
    pub run_k: Signal<In, Bits<4>>,
    // The centre (stage W3) and the entry `ent_sel` of its window.
    pub ent_sel: Signal<In, Bits<8>>,
    pub centre_valid: Signal<Out, Bit>,
    pub centre_x: Signal<Out, Bits<16>>,
    pub centre_col: Signal<Out, Bits<12>>,
    pub ent_ok: Signal<Out, Bit>,
    pub ent_x: Signal<Out, Bits<16>>,
    pub ent_y: Signal<Out, Bits<16>>,
    pub ent_z: Signal<Out, Bits<16>>,
    window: FccWindow,
    entry_index: Vec<Constant<Bits<8>>>,
    zero12: Constant<Bits<12>>,
    zero16: Constant<Bits<16>>,
}

impl FccWindowProbe {
    pub fn new(p: &FccParams) -> Self {
        let n = p.window_positions();
        assert!(n <= 256, "{n} window entries do not fit ent_sel");
        Self {
            clk: Default::default(),
            rst: Default::default(),
            in_valid: Default::default(),
            in_lok: Default::default(),
            in_x: Default::default(),
            in_y: Default::default(),
            in_z: Default::default(),
            in_row: Default::default(),
            in_col: Default::default(),
            in_rdcol: Default::default(),
            last_col: Default::default(),
            run_k: Default::default(),
            ent_sel: Default::default(),
            centre_valid: Default::default(),
            centre_x: Default::default(),
            centre_col: Default::default(),
            ent_ok: Default::default(),
            ent_x: Default::default(),
            ent_y: Default::default(),
            ent_z: Default::default(),
            window: FccWindow::new(p),
            entry_index: (0..n).map(|e| kb(e as u64)).collect(),
            zero12: kb(0),
            zero16: kb(0),
        }
    }
}

impl Logic for FccWindowProbe {
    #[hdl_gen]
    fn update(&mut self) {
        self.window.clk.next = self.clk.val();
        self.window.rst.next = self.rst.val();
        self.window.last_col.next = self.last_col.val();
        self.window.run_k.next = self.run_k.val();
        self.window.inp.next.valid = self.in_valid.val();
        self.window.inp.next.lok = self.in_lok.val();
        self.window.inp.next.x = self.in_x.val();
        self.window.inp.next.y = self.in_y.val();
        self.window.inp.next.z = self.in_z.val();
        self.window.inp.next.label = self.zero16.val();
        self.window.inp.next.row = self.in_row.val();
        self.window.inp.next.col = self.in_col.val();
        self.window.inp.next.rdcol = self.in_rdcol.val();
        self.window.inp.next.last = false;
        self.window.inp.next.ring = false;
        self.window.inp.next.ring_a = self.zero16.val();
        self.window.inp.next.ring_b = self.zero16.val();
        self.window.rep_we.next = false;
        self.window.rep_waddr.next = self.zero12.val();
        self.window.rep_wdata.next = self.zero16.val();
        self.centre_valid.next = self.window.centre.val().valid;
        self.centre_x.next = self.window.centre.val().x;
        self.centre_col.next = self.window.centre.val().col;
        self.ent_ok.next = false;
        self.ent_x.next = self.zero16.val();
        self.ent_y.next = self.zero16.val();
        self.ent_z.next = self.zero16.val();
        for e in 0..self.entry_index.len() {
            if self.ent_sel.val() == self.entry_index[e].val() {
                self.ent_ok.next = self.window.ent_ok[e].val();
                self.ent_x.next = self.window.ent_x[e].val();
                self.ent_y.next = self.window.ent_y[e].val();
                self.ent_z.next = self.window.ent_z[e].val();
            }
        }
    }
}
