//! `fcc_label_update`: the frame buffer and the label read-back.
//!
//! Provisional labels are non-decreasing in raster order and a new label is
//! taken exactly where a labelled run starts, so the frame buffer does not
//! store labels: it stores a 2-bit code per pixel (0 empty, 1 continues the
//! run, 2 starts a labelled run, 3 starts an unlabelled run), four pixels per
//! word. At read-back the k-th code 2 *is* provisional label k. The merge
//! table's flatten pass emits the compact label of 1, 2, 3, ... in that same
//! order, so the read-back consumes them from a small queue ("gearbox",
//! eight entries, up to four taken per beat) and never looks a label up; it
//! can start as soon as flatten starts and waits only when a beat needs more
//! compact labels than have been flattened.
//!
//! Output: `L` labels per beat in 16-bit slots from bit 0, `tkeep` marking
//! the bytes of the slots that hold labels, `tlast` on the frame's last beat.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::{kb, FbWord};

/// Four 16-bit label slots of one output beat.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct OutWord {
    pub l0: Bits<16>,
    pub l1: Bits<16>,
    pub l2: Bits<16>,
    pub l3: Bits<16>,
}

const GEAR: usize = 8;

#[derive(LogicBlock)]
pub struct FccLabelUpdate {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Frame-buffer writes from the labelled pixel stream.
    pub en: Signal<In, Bit>,
    pub wr_valid: Signal<In, Bit>,
    pub wr_state: Signal<In, Bits<2>>,
    pub wr_last: Signal<In, Bit>,
    // Read-back.
    pub rb_start: Signal<In, Bit>,
    pub fv: Signal<In, Bit>,
    pub fval: Signal<In, Bits<16>>,
    pub gear_free: Signal<Out, Bits<4>>,
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tkeep: Signal<Out, Bits<8>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    pub rb_done: Signal<Out, Bit>,
    /// Cycles in which a beat waited for compact labels.
    pub gear_stalls: Signal<Out, Bits<24>>,
    fb: FccRam<FbWord, 17>,
    ws0: DFF<Bits<2>>,
    ws1: DFF<Bits<2>>,
    ws2: DFF<Bits<2>>,
    wsub: DFF<Bits<2>>,
    waddr: DFF<Bits<17>>,
    active: DFF<Bit>,
    rpix: DFF<Bits<20>>,
    r1v: DFF<Bit>,
    r1_sub: DFF<Bits<2>>,
    r1_n: DFF<Bits<3>>,
    r1_last: DFF<Bit>,
    q: Vec<DFF<Bits<16>>>,
    qn: DFF<Bits<4>>,
    cur_run: DFF<Bits<16>>,
    o_valid: DFF<Bit>,
    o_data: DFF<OutWord>,
    o_keep: DFF<Bits<8>>,
    o_last: DFF<Bit>,
    gstall: DFF<Bits<24>>,
    // Combinational.
    issue: Signal<Local, Bit>,
    rem: Signal<Local, Bits<20>>,
    fire: Signal<Local, Bit>,
    out_free: Signal<Local, Bit>,
    idx: Signal<Local, Bits<2>>,
    st: Vec<Signal<Local, Bits<2>>>,
    lab: Vec<Signal<Local, Bits<16>>>,
    run: Signal<Local, Bits<16>>,
    j: Signal<Local, Bits<3>>,
    need: Signal<Local, Bits<4>>,
    k: Signal<Local, Bits<4>>,
    pos: Signal<Local, Bits<4>>,
    qx: Vec<Signal<Local, Bits<16>>>,
    keep_l: Signal<Local, Bits<8>>,
    // Constants.
    slot_off: Vec<Constant<Bits<2>>>,
    slot_idx: Vec<Constant<Bits<3>>>,
    slot_pos: Vec<Constant<Bits<4>>>,
    keep_n: Vec<Constant<Bits<8>>>,
    total: Constant<Bits<20>>,
    lpb20: Constant<Bits<20>>,
    lpb3: Constant<Bits<3>>,
    gear_cap: Constant<Bits<4>>,
    b2_0: Constant<Bits<2>>,
    b2_1: Constant<Bits<2>>,
    b2_2: Constant<Bits<2>>,
    b2_3: Constant<Bits<2>>,
    b3_0: Constant<Bits<3>>,
    b3_1: Constant<Bits<3>>,
    b3_2: Constant<Bits<3>>,
    b3_3: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    b4_0: Constant<Bits<4>>,
    b4_1: Constant<Bits<4>>,
    b4_2: Constant<Bits<4>>,
    b4_3: Constant<Bits<4>>,
    b4_4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    zero20: Constant<Bits<20>>,
    one24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
    n_of: Vec<Constant<Bits<3>>>,
    _l: usize,
}

fn v<T: Default>(n: usize) -> Vec<T> {
    (0..n).map(|_| T::default()).collect()
}

impl FccLabelUpdate {
    pub fn new(p: &FccParams) -> Self {
        let l = p.labels_per_beat as usize;
        let words = p.pixels().div_ceil(4);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            en: Default::default(),
            wr_valid: Default::default(),
            wr_state: Default::default(),
            wr_last: Default::default(),
            rb_start: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_free: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tkeep: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tlast: Default::default(),
            m_axis_tready: Default::default(),
            rb_done: Default::default(),
            gear_stalls: Default::default(),
            fb: FccRam::new(words.max(2)),
            ws0: Default::default(),
            ws1: Default::default(),
            ws2: Default::default(),
            wsub: Default::default(),
            waddr: Default::default(),
            active: Default::default(),
            rpix: Default::default(),
            r1v: Default::default(),
            r1_sub: Default::default(),
            r1_n: Default::default(),
            r1_last: Default::default(),
            q: v(GEAR),
            qn: Default::default(),
            cur_run: Default::default(),
            o_valid: Default::default(),
            o_data: Default::default(),
            o_keep: Default::default(),
            o_last: Default::default(),
            gstall: Default::default(),
            issue: Default::default(),
            rem: Default::default(),
            fire: Default::default(),
            out_free: Default::default(),
            idx: Default::default(),
            st: v(l),
            lab: v(4),
            run: Default::default(),
            j: Default::default(),
            need: Default::default(),
            k: Default::default(),
            pos: Default::default(),
            qx: v(GEAR + 4),
            keep_l: Default::default(),
            slot_off: (0..l).map(|i| kb(i as u64)).collect(),
            slot_idx: (0..l).map(|i| kb(i as u64)).collect(),
            slot_pos: (0..GEAR).map(|i| kb(i as u64)).collect(),
            keep_n: (0..=4).map(|n| kb((1u64 << (2 * n)) - 1)).collect(),
            total: kb(p.pixels() as u64),
            lpb20: kb(l as u64),
            lpb3: kb(l as u64),
            gear_cap: kb(GEAR as u64),
            b2_0: kb(0),
            b2_1: kb(1),
            b2_2: kb(2),
            b2_3: kb(3),
            b3_0: kb(0),
            b3_1: kb(1),
            b3_2: kb(2),
            b3_3: kb(3),
            one3: kb(1),
            b4_0: kb(0),
            b4_1: kb(1),
            b4_2: kb(2),
            b4_3: kb(3),
            b4_4: kb(4),
            zero16: kb(0),
            zero17: kb(0),
            one17: kb(1),
            zero20: kb(0),
            one24: kb(1),
            zero24: kb(0),
            n_of: (0..=4).map(|n| kb(n as u64)).collect(),
            _l: l,
        }
    }
}

impl Logic for FccLabelUpdate {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, ws0, ws1, ws2, wsub, waddr, active, rpix, r1v, r1_sub, r1_n, r1_last, qn,
            cur_run, o_valid, o_data, o_keep, o_last, gstall
        );
        for i in 0..8 {
            self.q[i].clock.next = self.clk.val();
            self.q[i].d.next = self.q[i].q.val();
        }
        // ---- Frame-buffer writes: four codes per word.
        self.fb.clk.next = self.clk.val();
        self.fb.write_en.next = false;
        self.fb.write_addr.next = self.waddr.q.val();
        self.fb.write_data.next.s0 = self.ws0.q.val();
        self.fb.write_data.next.s1 = self.ws1.q.val();
        self.fb.write_data.next.s2 = self.ws2.q.val();
        self.fb.write_data.next.s3 = self.wr_state.val();
        if self.wsub.q.val() == self.b2_0.val() {
            self.fb.write_data.next.s0 = self.wr_state.val();
        }
        if self.wsub.q.val() == self.b2_1.val() {
            self.fb.write_data.next.s1 = self.wr_state.val();
        }
        if self.wsub.q.val() == self.b2_2.val() {
            self.fb.write_data.next.s2 = self.wr_state.val();
        }
        if self.en.val() & self.wr_valid.val() {
            if self.wsub.q.val() == self.b2_0.val() {
                self.ws0.d.next = self.wr_state.val();
            }
            if self.wsub.q.val() == self.b2_1.val() {
                self.ws1.d.next = self.wr_state.val();
            }
            if self.wsub.q.val() == self.b2_2.val() {
                self.ws2.d.next = self.wr_state.val();
            }
            self.wsub.d.next = self.wsub.q.val() + self.b2_1.val();
            if (self.wsub.q.val() == self.b2_3.val()) | self.wr_last.val() {
                self.fb.write_en.next = true;
                self.waddr.d.next = self.waddr.q.val() + self.one17.val();
            }
            if self.wr_last.val() {
                self.wsub.d.next = self.b2_0.val();
                self.waddr.d.next = self.zero17.val();
            }
        }
        // ---- Read-back, stage 1: codes of this beat and its labels.
        self.out_free.next = !self.o_valid.q.val() | self.m_axis_tready.val();
        self.run.next = self.cur_run.q.val();
        self.j.next = self.b3_0.val();
        for i in 0..4 {
            self.lab[i].next = self.zero16.val();
        }
        for i in 0..self._l {
            self.st[i].next = self.b2_0.val();
        }
        for i in 0..self._l {
            self.idx.next = self.r1_sub.q.val() + self.slot_off[i].val();
            if self.idx.val() == self.b2_0.val() {
                self.st[i].next = self.fb.read_data.val().s0;
            }
            if self.idx.val() == self.b2_1.val() {
                self.st[i].next = self.fb.read_data.val().s1;
            }
            if self.idx.val() == self.b2_2.val() {
                self.st[i].next = self.fb.read_data.val().s2;
            }
            if self.idx.val() == self.b2_3.val() {
                self.st[i].next = self.fb.read_data.val().s3;
            }
            if self.slot_idx[i].val() >= self.r1_n.q.val() {
                self.st[i].next = self.b2_0.val();
            }
            if self.st[i].val() == self.b2_2.val() {
                if self.j.val() == self.b3_0.val() {
                    self.run.next = self.q[0].q.val();
                }
                if self.j.val() == self.b3_1.val() {
                    self.run.next = self.q[1].q.val();
                }
                if self.j.val() == self.b3_2.val() {
                    self.run.next = self.q[2].q.val();
                }
                if self.j.val() == self.b3_3.val() {
                    self.run.next = self.q[3].q.val();
                }
                self.j.next = self.j.val() + self.one3.val();
            }
            if self.st[i].val() == self.b2_3.val() {
                self.run.next = self.zero16.val();
            }
            if self.st[i].val() != self.b2_0.val() {
                self.lab[i].next = self.run.val();
            }
        }
        self.need.next = self.b4_0.val();
        if self.j.val() == self.b3_1.val() {
            self.need.next = self.b4_1.val();
        }
        if self.j.val() == self.b3_2.val() {
            self.need.next = self.b4_2.val();
        }
        if self.j.val() == self.b3_3.val() {
            self.need.next = self.b4_3.val();
        }
        if self.j.val() > self.b3_3.val() {
            self.need.next = self.b4_4.val();
        }
        self.fire.next =
            self.r1v.q.val() & (self.qn.q.val() >= self.need.val()) & self.out_free.val();
        if self.r1v.q.val() & !self.fire.val() & self.out_free.val() {
            self.gstall.d.next = self.gstall.q.val() + self.one24.val();
        }
        self.keep_l.next = self.keep_n[0].val();
        for n in 0..5 {
            if self.r1_n.q.val() == self.n_of[n].val() {
                self.keep_l.next = self.keep_n[n].val();
            }
        }
        if self.o_valid.q.val() & self.m_axis_tready.val() {
            self.o_valid.d.next = false;
        }
        if self.fire.val() {
            self.o_valid.d.next = true;
            self.o_data.d.next.l0 = self.lab[0].val();
            self.o_data.d.next.l1 = self.lab[1].val();
            self.o_data.d.next.l2 = self.lab[2].val();
            self.o_data.d.next.l3 = self.lab[3].val();
            self.o_keep.d.next = self.keep_l.val();
            self.o_last.d.next = self.r1_last.q.val();
            self.cur_run.d.next = self.run.val();
            self.r1v.d.next = false;
        }
        // ---- Read-back, stage 0: issue the frame-buffer read of the next beat.
        self.issue.next = self.active.q.val() & (!self.r1v.q.val() | self.fire.val());
        self.rem.next = self.total.val() - self.rpix.q.val();
        self.fb.read_en.next = self.issue.val();
        self.fb.read_addr.next = self.rpix.q.val().get_bits::<17>(2);
        if self.issue.val() {
            self.r1v.d.next = true;
            self.r1_sub.d.next = self.rpix.q.val().get_bits::<2>(0);
            self.r1_n.d.next = self.lpb3.val();
            self.r1_last.d.next = false;
            if self.rem.val() <= self.lpb20.val() {
                self.r1_n.d.next = self.rem.val().get_bits::<3>(0);
                self.r1_last.d.next = true;
                self.active.d.next = false;
            }
            self.rpix.d.next = self.rpix.q.val() + self.lpb20.val();
        }
        // ---- Gearbox: take `need` on a fired beat, append one flattened label.
        self.k.next = self.b4_0.val();
        if self.fire.val() {
            self.k.next = self.need.val();
        }
        for i in 0..8 {
            self.qx[i].next = self.q[i].q.val();
        }
        for i in 8..12 {
            self.qx[i].next = self.zero16.val();
        }
        for i in 0..8 {
            if self.k.val() == self.b4_0.val() {
                self.q[i].d.next = self.qx[i].val();
            }
            if self.k.val() == self.b4_1.val() {
                self.q[i].d.next = self.qx[i + 1].val();
            }
            if self.k.val() == self.b4_2.val() {
                self.q[i].d.next = self.qx[i + 2].val();
            }
            if self.k.val() == self.b4_3.val() {
                self.q[i].d.next = self.qx[i + 3].val();
            }
            if self.k.val() == self.b4_4.val() {
                self.q[i].d.next = self.qx[i + 4].val();
            }
        }
        self.pos.next = self.qn.q.val() - self.k.val();
        if self.fv.val() {
            for i in 0..8 {
                if self.pos.val() == self.slot_pos[i].val() {
                    self.q[i].d.next = self.fval.val();
                }
            }
            self.qn.d.next = self.pos.val() + self.b4_1.val();
        } else {
            self.qn.d.next = self.pos.val();
        }
        self.gear_free.next = self.gear_cap.val() - self.qn.q.val();
        if self.rb_start.val() {
            self.active.d.next = true;
            self.rpix.d.next = self.zero20.val();
            self.r1v.d.next = false;
            self.cur_run.d.next = self.zero16.val();
            self.qn.d.next = self.b4_0.val();
            self.gstall.d.next = self.zero24.val();
        }
        if self.rst.val() {
            self.active.d.next = false;
            self.r1v.d.next = false;
            self.o_valid.d.next = false;
            self.qn.d.next = self.b4_0.val();
            self.wsub.d.next = self.b2_0.val();
            self.waddr.d.next = self.zero17.val();
        }
        self.m_axis_tdata.next = self.o_data.q.val().into();
        self.m_axis_tkeep.next = self.o_keep.q.val();
        self.m_axis_tvalid.next = self.o_valid.q.val();
        self.m_axis_tlast.next = self.o_last.q.val();
        self.rb_done.next = self.o_valid.q.val() & self.m_axis_tready.val() & self.o_last.q.val();
        self.gear_stalls.next = self.gstall.q.val();
    }
}
