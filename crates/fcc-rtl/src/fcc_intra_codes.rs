//! `FccIntraCodes`: the last two stages of the intra-channel processor.
//!
//! It takes the label decision of stage N7 (the pixel, whether it continues
//! the run, its raw label, the row's first and current run labels, whether
//! the row has a point yet, and the ring's distance result) and produces
//! the labelled pixel two stages later:
//! * N8: whether each raw label fits in `B` bits (labels are allocated in
//!   order, so "raw label > 2^B - 1" is exactly "labels ran out"), the ring's
//!   comparisons, and the window's read column `(col + h) mod C`, which
//!   follows the frame's columns (`last_col`);
//! * N9: the output codes: the label (0 when unlabelled), the frame-buffer
//!   code (`state`: 0 empty, 1 continues a run, 2 starts a labelled run, 3
//!   starts an unlabelled run) and the row's ring join; `out` and `state`
//!   are registered.
//!
//! It also counts the frame's unlabelled points (`unlabelled`).

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::types::{kb, Pix, WinPix};

#[derive(LogicBlock)]
pub struct FccIntraCodes {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The frame's last column, C - 1 (stable while a frame runs).
    pub last_col: Signal<In, Bits<12>>,
    // N7's decision.
    pub pix: Signal<In, Pix>,
    pub cont: Signal<In, Bit>,
    pub lab: Signal<In, Bits<20>>,
    pub fl: Signal<In, Bits<20>>,
    pub cur: Signal<In, Bits<20>>,
    pub any: Signal<In, Bit>,
    pub ring_hit: Signal<In, Bit>,
    pub out: Signal<Out, WinPix>,
    pub state: Signal<Out, Bits<2>>,
    /// Unlabelled points of the frame in progress.
    pub unlabelled: Signal<Out, Bits<20>>,
    // N8 registers.
    p8: DFF<Pix>,
    cont8: DFF<Bit>,
    lab8: DFF<Bits<20>>,
    fl8: DFF<Bits<20>>,
    cur8: DFF<Bits<20>>,
    any8: DFF<Bit>,
    ringle8: DFF<Bit>,
    // N9 registers.
    p9: DFF<Pix>,
    cont9: DFF<Bit>,
    lab9: DFF<Bits<16>>,
    labok9: DFF<Bit>,
    ring9: DFF<Bit>,
    flok9: DFF<Bit>,
    curok9: DFF<Bit>,
    ne9: DFF<Bit>,
    fl9: DFF<Bits<16>>,
    cur9: DFF<Bits<16>>,
    rdcol9: DFF<Bits<12>>,
    /// `C - h`: the first column whose read address wraps.
    wrap_col: DFF<Bits<12>>,
    out_q: DFF<WinPix>,
    state_q: DFF<Bits<2>>,
    unl: DFF<Bits<20>>,
    lok: Signal<Local, Bit>,
    zero16: Constant<Bits<16>>,
    zero20: Constant<Bits<20>>,
    one20: Constant<Bits<20>>,
    max20: Constant<Bits<20>>,
    half: Constant<Bits<12>>,
    half_m1: Constant<Bits<12>>,
    st_empty: Constant<Bits<2>>,
    st_cont: Constant<Bits<2>>,
    st_new: Constant<Bits<2>>,
    st_unl: Constant<Bits<2>>,
}

impl FccIntraCodes {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            last_col: Default::default(),
            pix: Default::default(),
            cont: Default::default(),
            lab: Default::default(),
            fl: Default::default(),
            cur: Default::default(),
            any: Default::default(),
            ring_hit: Default::default(),
            out: Default::default(),
            state: Default::default(),
            unlabelled: Default::default(),
            p8: Default::default(),
            cont8: Default::default(),
            lab8: Default::default(),
            fl8: Default::default(),
            cur8: Default::default(),
            any8: Default::default(),
            ringle8: Default::default(),
            p9: Default::default(),
            cont9: Default::default(),
            lab9: Default::default(),
            labok9: Default::default(),
            ring9: Default::default(),
            flok9: Default::default(),
            curok9: Default::default(),
            ne9: Default::default(),
            fl9: Default::default(),
            cur9: Default::default(),
            rdcol9: Default::default(),
            wrap_col: Default::default(),
            out_q: Default::default(),
            state_q: Default::default(),
            unl: Default::default(),
            lok: Default::default(),
            zero16: kb(0),
            zero20: kb(0),
            one20: kb(1),
            max20: kb(u64::from(p.max_label())),
            half: kb(p.half() as u64),
            half_m1: kb(p.half() as u64 - 1),
            st_empty: kb(0),
            st_cont: kb(1),
            st_new: kb(2),
            st_unl: kb(3),
        }
    }
}

impl Logic for FccIntraCodes {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, p8, cont8, lab8, fl8, cur8, any8, ringle8, p9, cont9, lab9, labok9, ring9,
            flok9, curok9, ne9, fl9, cur9, rdcol9, wrap_col, out_q, state_q, unl
        );
        self.p8.d.next = self.pix.val();
        self.cont8.d.next = self.cont.val();
        self.lab8.d.next = self.lab.val();
        self.fl8.d.next = self.fl.val();
        self.cur8.d.next = self.cur.val();
        self.any8.d.next = self.any.val();
        self.ringle8.d.next = self.ring_hit.val();
        // ---- N8: does each label fit, and the ring's comparisons.
        self.p9.d.next = self.p8.q.val();
        self.cont9.d.next = self.cont8.q.val();
        self.lab9.d.next = self.lab8.q.val().get_bits::<16>(0);
        self.labok9.d.next = self.lab8.q.val() <= self.max20.val();
        self.ring9.d.next =
            self.p8.q.val().valid & self.p8.q.val().coln & self.any8.q.val() & self.ringle8.q.val();
        self.flok9.d.next = self.fl8.q.val() <= self.max20.val();
        self.curok9.d.next = self.cur8.q.val() <= self.max20.val();
        self.ne9.d.next = self.fl8.q.val() != self.cur8.q.val();
        self.fl9.d.next = self.fl8.q.val().get_bits::<16>(0);
        self.cur9.d.next = self.cur8.q.val().get_bits::<16>(0);
        self.rdcol9.d.next = self.p8.q.val().col + self.half.val();
        if self.p8.q.val().col >= self.wrap_col.q.val() {
            self.rdcol9.d.next = self.p8.q.val().col - self.wrap_col.q.val();
        }
        self.wrap_col.d.next = self.last_col.val() - self.half_m1.val();
        // ---- N9: output codes.
        self.lok.next = self.p9.q.val().valid & self.p9.q.val().ok & self.labok9.q.val();
        self.out_q.d.next.valid = self.p9.q.val().valid;
        self.out_q.d.next.lok = self.lok.val();
        self.out_q.d.next.x = self.p9.q.val().x;
        self.out_q.d.next.y = self.p9.q.val().y;
        self.out_q.d.next.z = self.p9.q.val().z;
        self.out_q.d.next.label = self.zero16.val();
        if self.lok.val() {
            self.out_q.d.next.label = self.lab9.q.val();
        }
        self.state_q.d.next = self.st_empty.val();
        if self.p9.q.val().valid & self.p9.q.val().ok {
            if self.cont9.q.val() {
                self.state_q.d.next = self.st_cont.val();
            } else if self.labok9.q.val() {
                self.state_q.d.next = self.st_new.val();
            } else {
                self.state_q.d.next = self.st_unl.val();
            }
        }
        self.out_q.d.next.row = self.p9.q.val().row;
        self.out_q.d.next.col = self.p9.q.val().col;
        self.out_q.d.next.rdcol = self.rdcol9.q.val();
        self.out_q.d.next.last = self.p9.q.val().last;
        self.out_q.d.next.ring =
            self.ring9.q.val() & self.flok9.q.val() & self.curok9.q.val() & self.ne9.q.val();
        self.out_q.d.next.ring_a = self.fl9.q.val();
        self.out_q.d.next.ring_b = self.cur9.q.val();
        // The frame's first point (column 0: no previous point, no
        // continuation) always gets label 1, so it is never unlabelled: the
        // count restarts there and counts from the next point on.
        if self.p9.q.val().valid {
            if self.p9.q.val().first {
                self.unl.d.next = self.zero20.val();
            }
            if self.p9.q.val().ok & !self.labok9.q.val() {
                self.unl.d.next = self.unl.q.val() + self.one20.val();
            }
        }
        if self.rst.val() {
            self.p8.d.next.valid = false;
            self.p9.d.next.valid = false;
            self.out_q.d.next.valid = false;
        }
        self.out.next = self.out_q.q.val();
        self.state.next = self.state_q.q.val();
        self.unlabelled.next = self.unl.q.val();
    }
}
