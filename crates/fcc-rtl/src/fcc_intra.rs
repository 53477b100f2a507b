//! `fcc_intra`: the intra-channel processor.
//!
//! Each pixel is compared with the previous *valid* pixel of its row (empty
//! pixels neither break nor start a run). A squared distance `<= tH^2`
//! continues the current run, otherwise the next provisional label is taken
//! (1, 2, ... in raster order over the frame; when `2^B - 1` are used, a new
//! run gets label 0 and the overflow flag is set). At the row's last pixel the
//! ring check joins the row's first and last runs when their end points are
//! within `tH`.
//!
//! Timing: the pixel enters through `pix`, the squared distances take three
//! enabled cycles, the label is decided in the fourth and `out` is registered,
//! so a pixel appears on `out` four enabled cycles after it was on `pix`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_sq_dist::FccSqDist;
use crate::types::{kb, Lab, Pix};

#[derive(LogicBlock)]
pub struct FccIntra {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Pipeline advance (the whole front end moves together).
    pub en: Signal<In, Bit>,
    pub pix: Signal<In, Pix>,
    pub out: Signal<Out, Lab>,
    // Status of the frame in progress.
    pub provisional: Signal<Out, Bits<17>>,
    pub overflow: Signal<Out, Bit>,
    pub unlabelled: Signal<Out, Bits<20>>,
    // Previous valid pixel of the row and the row's first valid pixel.
    prev_x: DFF<Bits<16>>,
    prev_y: DFF<Bits<16>>,
    prev_z: DFF<Bits<16>>,
    has_prev: DFF<Bit>,
    first_x: DFF<Bits<16>>,
    first_y: DFF<Bits<16>>,
    first_z: DFF<Bits<16>>,
    near: FccSqDist,
    ring: FccSqDist,
    // Delay line aligned with the distance units.
    p1: DFF<Pix>,
    p2: DFF<Pix>,
    p3: DFF<Pix>,
    fv1: DFF<Bit>,
    fv2: DFF<Bit>,
    fv3: DFF<Bit>,
    hp1: DFF<Bit>,
    hp2: DFF<Bit>,
    hp3: DFF<Bit>,
    // Labelling state.
    next_label: DFF<Bits<17>>,
    cur_label: DFF<Bits<16>>,
    first_label: DFF<Bits<16>>,
    row_any: DFF<Bit>,
    count: DFF<Bits<17>>,
    ovf: DFF<Bit>,
    unl: DFF<Bits<20>>,
    out_q: DFF<Lab>,
    // Combinational helpers.
    hp_eff: Signal<Local, Bit>,
    fv0: Signal<Local, Bit>,
    cont: Signal<Local, Bit>,
    nl: Signal<Local, Bits<17>>,
    cnt0: Signal<Local, Bits<17>>,
    unl0: Signal<Local, Bits<20>>,
    ovf0: Signal<Local, Bit>,
    lab: Signal<Local, Bits<16>>,
    st: Signal<Local, Bits<2>>,
    cur_next: Signal<Local, Bits<16>>,
    fl_eff: Signal<Local, Bits<16>>,
    any_eff: Signal<Local, Bit>,
    ring_ok: Signal<Local, Bit>,
    // Constants.
    zero12: Constant<Bits<12>>,
    last_col: Constant<Bits<12>>,
    zero16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    max_label: Constant<Bits<17>>,
    zero20: Constant<Bits<20>>,
    one20: Constant<Bits<20>>,
    th_h_sq: Constant<Bits<32>>,
    st_empty: Constant<Bits<2>>,
    st_cont: Constant<Bits<2>>,
    st_new: Constant<Bits<2>>,
    st_unl: Constant<Bits<2>>,
}

impl FccIntra {
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            en: Default::default(),
            pix: Default::default(),
            out: Default::default(),
            provisional: Default::default(),
            overflow: Default::default(),
            unlabelled: Default::default(),
            prev_x: Default::default(),
            prev_y: Default::default(),
            prev_z: Default::default(),
            has_prev: Default::default(),
            first_x: Default::default(),
            first_y: Default::default(),
            first_z: Default::default(),
            near: Default::default(),
            ring: Default::default(),
            p1: Default::default(),
            p2: Default::default(),
            p3: Default::default(),
            fv1: Default::default(),
            fv2: Default::default(),
            fv3: Default::default(),
            hp1: Default::default(),
            hp2: Default::default(),
            hp3: Default::default(),
            next_label: Default::default(),
            cur_label: Default::default(),
            first_label: Default::default(),
            row_any: Default::default(),
            count: Default::default(),
            ovf: Default::default(),
            unl: Default::default(),
            out_q: Default::default(),
            hp_eff: Default::default(),
            fv0: Default::default(),
            cont: Default::default(),
            nl: Default::default(),
            cnt0: Default::default(),
            unl0: Default::default(),
            ovf0: Default::default(),
            lab: Default::default(),
            st: Default::default(),
            cur_next: Default::default(),
            fl_eff: Default::default(),
            any_eff: Default::default(),
            ring_ok: Default::default(),
            zero12: kb(0),
            last_col: kb(p.cols as u64 - 1),
            zero16: kb(0),
            zero17: kb(0),
            one17: kb(1),
            max_label: kb(u64::from(p.max_label())),
            zero20: kb(0),
            one20: kb(1),
            th_h_sq: kb(p.th_h_sq() as u64),
            st_empty: kb(0),
            st_cont: kb(1),
            st_new: kb(2),
            st_unl: kb(3),
        }
    }
}

impl Logic for FccIntra {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            prev_x,
            prev_y,
            prev_z,
            has_prev,
            first_x,
            first_y,
            first_z,
            p1,
            p2,
            p3,
            fv1,
            fv2,
            fv3,
            hp1,
            hp2,
            hp3,
            next_label,
            cur_label,
            first_label,
            row_any,
            count,
            ovf,
            unl,
            out_q
        );
        // ---- Stage 0: the incoming pixel against the row's previous valid pixel.
        self.hp_eff.next = (self.pix.val().col != self.zero12.val()) & self.has_prev.q.val();
        self.fv0.next = self.pix.val().valid & self.pix.val().ok & !self.hp_eff.val();
        self.near.clk.next = self.clk.val();
        self.near.en.next = self.en.val();
        self.near.ax.next = self.pix.val().x;
        self.near.ay.next = self.pix.val().y;
        self.near.az.next = self.pix.val().z;
        self.near.bx.next = self.prev_x.q.val();
        self.near.by.next = self.prev_y.q.val();
        self.near.bz.next = self.prev_z.q.val();
        // Ring: the row's first valid point against its last valid point.
        self.ring.clk.next = self.clk.val();
        self.ring.en.next = self.en.val();
        self.ring.ax.next = self.first_x.q.val();
        self.ring.ay.next = self.first_y.q.val();
        self.ring.az.next = self.first_z.q.val();
        if self.fv0.val() {
            self.ring.ax.next = self.pix.val().x;
            self.ring.ay.next = self.pix.val().y;
            self.ring.az.next = self.pix.val().z;
        }
        self.ring.bx.next = self.prev_x.q.val();
        self.ring.by.next = self.prev_y.q.val();
        self.ring.bz.next = self.prev_z.q.val();
        if self.pix.val().ok {
            self.ring.bx.next = self.pix.val().x;
            self.ring.by.next = self.pix.val().y;
            self.ring.bz.next = self.pix.val().z;
        }
        if self.en.val() {
            self.p1.d.next = self.pix.val();
            self.p2.d.next = self.p1.q.val();
            self.p3.d.next = self.p2.q.val();
            self.fv1.d.next = self.fv0.val();
            self.fv2.d.next = self.fv1.q.val();
            self.fv3.d.next = self.fv2.q.val();
            self.hp1.d.next = self.hp_eff.val();
            self.hp2.d.next = self.hp1.q.val();
            self.hp3.d.next = self.hp2.q.val();
            if self.pix.val().valid {
                self.has_prev.d.next = self.pix.val().ok | self.hp_eff.val();
                if self.pix.val().ok {
                    self.prev_x.d.next = self.pix.val().x;
                    self.prev_y.d.next = self.pix.val().y;
                    self.prev_z.d.next = self.pix.val().z;
                }
                if self.fv0.val() {
                    self.first_x.d.next = self.pix.val().x;
                    self.first_y.d.next = self.pix.val().y;
                    self.first_z.d.next = self.pix.val().z;
                }
            }
        }
        // ---- Stage 3: decide the label.
        self.cont.next = self.hp3.q.val() & (self.near.d2.val() <= self.th_h_sq.val());
        self.nl.next = self.next_label.q.val();
        self.cnt0.next = self.count.q.val();
        self.unl0.next = self.unl.q.val();
        self.ovf0.next = self.ovf.q.val();
        if self.p3.q.val().first {
            self.nl.next = self.one17.val();
            self.cnt0.next = self.zero17.val();
            self.unl0.next = self.zero20.val();
            self.ovf0.next = false;
        }
        self.lab.next = self.zero16.val();
        self.st.next = self.st_empty.val();
        self.cur_next.next = self.cur_label.q.val();
        self.next_label.d.next = self.nl.val();
        self.count.d.next = self.cnt0.val();
        self.unl.d.next = self.unl0.val();
        self.ovf.d.next = self.ovf0.val();
        if self.p3.q.val().valid & self.p3.q.val().ok {
            if self.cont.val() {
                self.lab.next = self.cur_label.q.val();
                self.st.next = self.st_cont.val();
            } else if self.nl.val() <= self.max_label.val() {
                self.lab.next = self.nl.val().get_bits::<16>(0);
                self.st.next = self.st_new.val();
                self.next_label.d.next = self.nl.val() + self.one17.val();
                self.count.d.next = self.cnt0.val() + self.one17.val();
            } else {
                self.st.next = self.st_unl.val();
                self.ovf.d.next = true;
            }
            if self.lab.val() == self.zero16.val() {
                self.unl.d.next = self.unl0.val() + self.one20.val();
            }
            self.cur_next.next = self.lab.val();
        }
        self.fl_eff.next = self.first_label.q.val();
        if self.fv3.q.val() {
            self.fl_eff.next = self.lab.val();
        }
        self.any_eff.next = ((self.p3.q.val().col != self.zero12.val()) & self.row_any.q.val())
            | (self.p3.q.val().valid & self.p3.q.val().ok);
        self.ring_ok.next = self.p3.q.val().valid
            & (self.p3.q.val().col == self.last_col.val())
            & self.any_eff.val()
            & (self.fl_eff.val() != self.zero16.val())
            & (self.cur_next.val() != self.zero16.val())
            & (self.fl_eff.val() != self.cur_next.val())
            & (self.ring.d2.val() <= self.th_h_sq.val());
        if !(self.en.val() & self.p3.q.val().valid) {
            self.next_label.d.next = self.next_label.q.val();
            self.count.d.next = self.count.q.val();
            self.unl.d.next = self.unl.q.val();
            self.ovf.d.next = self.ovf.q.val();
        }
        if self.en.val() & self.p3.q.val().valid {
            self.cur_label.d.next = self.cur_next.val();
            self.first_label.d.next = self.fl_eff.val();
            self.row_any.d.next = self.any_eff.val();
        }
        if self.en.val() {
            self.out_q.d.next.valid = self.p3.q.val().valid;
            self.out_q.d.next.ok = self.p3.q.val().ok;
            self.out_q.d.next.x = self.p3.q.val().x;
            self.out_q.d.next.y = self.p3.q.val().y;
            self.out_q.d.next.z = self.p3.q.val().z;
            self.out_q.d.next.label = self.lab.val();
            self.out_q.d.next.state = self.st.val();
            self.out_q.d.next.row = self.p3.q.val().row;
            self.out_q.d.next.col = self.p3.q.val().col;
            self.out_q.d.next.last = self.p3.q.val().last;
            self.out_q.d.next.ring = self.ring_ok.val();
            self.out_q.d.next.ring_a = self.fl_eff.val();
            self.out_q.d.next.ring_b = self.cur_next.val();
        }
        if self.rst.val() {
            self.p1.d.next.valid = false;
            self.p2.d.next.valid = false;
            self.p3.d.next.valid = false;
            self.out_q.d.next.valid = false;
            self.has_prev.d.next = false;
        }
        self.out.next = self.out_q.q.val();
        self.provisional.next = self.count.q.val();
        self.overflow.next = self.ovf.q.val();
        self.unlabelled.next = self.unl.q.val();
    }
}
