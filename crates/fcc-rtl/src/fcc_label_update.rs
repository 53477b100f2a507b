//! `fcc_label_update`: the frame buffer and the label read-back.
//!
//! Provisional labels are non-decreasing in raster order and a new label is
//! taken exactly where a labelled run starts, so the frame buffer does not
//! store labels: it stores a 2-bit code per pixel (0 empty, 1 continues the
//! run, 2 starts a labelled run, 3 starts an unlabelled run), four pixels per
//! word. At read-back the k-th code 2 *is* provisional label k. The merge
//! table's flatten pass emits the compact label of 1, 2, 3, ... in that same
//! order into an eight-entry queue (the gearbox), so the read-back never
//! looks a label up; it starts as soon as flatten starts.
//!
//! Read-back pipeline: R0 issues the frame-buffer read of a beat (at most
//! four beats between R0 and the output), R2 has the word, R3 has it decoded
//! (per slot: zero, the run carried from the previous beat, or the k-th new
//! label of this beat; how many new labels the beat needs), then a four-entry
//! queue of decoded beats. The head beat collects its new labels from the
//! gearbox, up to two per cycle, and leaves when it has them all (the last
//! ones may arrive in the same cycle) and the output register is free.
//!
//! Output: `L` labels per beat in 16-bit slots from bit 0, `tkeep` marking
//! the bytes of the slots that hold labels, `tlast` on the frame's last beat.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::{kb, vec_of, FbWord};

/// Four 16-bit label slots of one output beat.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct OutWord {
    pub l0: Bits<16>,
    pub l1: Bits<16>,
    pub l2: Bits<16>,
    pub l3: Bits<16>,
}

/// A decoded beat. A slot source is 0 (label 0), 1 (the run carried in from
/// the previous beat) or 2 + k (the beat's k-th new label).
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct Beat {
    pub s0: Bits<3>,
    pub s1: Bits<3>,
    pub s2: Bits<3>,
    pub s3: Bits<3>,
    /// Source of the run carried into the next beat.
    pub run: Bits<3>,
    /// New labels this beat takes from the gearbox.
    pub need: Bits<3>,
    pub keep: Bits<8>,
    pub last: Bit,
}

const GEAR: usize = 8;
const SKID: usize = 4;

#[derive(LogicBlock)]
pub struct FccLabelUpdate {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Frame-buffer writes from the labelled pixel stream.
    pub wr_valid: Signal<In, Bit>,
    pub wr_state: Signal<In, Bits<2>>,
    pub wr_last: Signal<In, Bit>,
    // Read-back.
    pub rb_start: Signal<In, Bit>,
    pub fv: Signal<In, Bit>,
    pub fval: Signal<In, Bits<16>>,
    /// Compact labels waiting in the gearbox (registered).
    pub gear_used: Signal<Out, Bits<4>>,
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tkeep: Signal<Out, Bits<8>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    pub rb_done: Signal<Out, Bit>,
    /// Cycles in which the head beat waited for compact labels.
    pub gear_stalls: Signal<Out, Bits<24>>,
    fb: FccRam<FbWord, 17>,
    ws0: DFF<Bits<2>>,
    ws1: DFF<Bits<2>>,
    ws2: DFF<Bits<2>>,
    wsub: DFF<Bits<2>>,
    waddr: DFF<Bits<17>>,
    /// Pixels written in this frame so far, and at its last pixel the
    /// frame's beats less one and labels in its last beat.
    wcnt: DFF<Bits<20>>,
    beats_m1: DFF<Bits<20>>,
    last_n: DFF<Bits<3>>,
    // R0 .. R3.
    active: DFF<Bit>,
    rpix: DFF<Bits<20>>,
    /// Beats still to issue after the next one; `lastb`: the next is the last.
    beats: DFF<Bits<20>>,
    lastb: DFF<Bit>,
    outst: DFF<Bits<3>>,
    r1v: DFF<Bit>,
    r1_sub: DFF<Bits<2>>,
    r1_n: DFF<Bits<3>>,
    r1_last: DFF<Bit>,
    r2v: DFF<Bit>,
    r2_sub: DFF<Bits<2>>,
    r2_n: DFF<Bits<3>>,
    r2_last: DFF<Bit>,
    d3v: DFF<Bit>,
    d3: DFF<Beat>,
    // Decoded beats; sk[0] is the head.
    sk: Vec<DFF<Beat>>,
    skn: DFF<Bits<3>>,
    // The head beat's new labels, and the run carried between beats.
    u: DFF<Bits<3>>,
    labs: Vec<DFF<Bits<16>>>,
    cur_run: DFF<Bits<16>>,
    // Gearbox: compact labels in ascending order; g[0] is the next one.
    g: Vec<DFF<Bits<16>>>,
    gn: DFF<Bits<4>>,
    o_valid: DFF<Bit>,
    o_data: DFF<OutWord>,
    o_keep: DFF<Bits<8>>,
    o_last: DFF<Bit>,
    gstall: DFF<Bits<24>>,
    // Combinational.
    issue: Signal<Local, Bit>,
    st: Vec<Signal<Local, Bits<2>>>,
    src: Vec<Signal<Local, Bits<3>>>,
    slot: Vec<Signal<Local, Bits<3>>>,
    nnew: Vec<Signal<Local, Bits<3>>>,
    idx: Signal<Local, Bits<2>>,
    hv: Signal<Local, Bit>,
    ghv: Signal<Local, Bit>,
    pop: Signal<Local, Bit>,
    pop2: Signal<Local, Bit>,
    pop1: Signal<Local, Bit>,
    /// The head beat needs 0, 1, 2, at least 2 more labels.
    lz: Signal<Local, Bit>,
    l1: Signal<Local, Bit>,
    l2: Signal<Local, Bit>,
    lge2: Signal<Local, Bit>,
    /// At least two labels wait in the gearbox.
    gge2: Signal<Local, Bit>,
    gn_p1: Signal<Local, Bits<4>>,
    gn_m1: Signal<Local, Bits<4>>,
    gn_m2: Signal<Local, Bits<4>>,
    fire: Signal<Local, Bit>,
    ofree: Signal<Local, Bit>,
    lab: Vec<Signal<Local, Bits<16>>>,
    nsrc: Vec<Signal<Local, Bits<3>>>,
    runv: Signal<Local, Bits<16>>,
    wrem: Signal<Local, Bits<2>>,
    // Constants.
    slot_off: Vec<Constant<Bits<2>>>,
    slot_idx: Vec<Constant<Bits<3>>>,
    keep_n: Vec<Constant<Bits<8>>>,
    n_of: Vec<Constant<Bits<3>>>,
    g_of: Vec<Constant<Bits<4>>>,
    k_of: Vec<Constant<Bits<3>>>,
    /// log2 of the labels per beat; labels per beat less one.
    lpb_log: Constant<Bits<2>>,
    lpb_m1: Constant<Bits<2>>,
    one20: Constant<Bits<20>>,
    lpb20: Constant<Bits<20>>,
    lpb3: Constant<Bits<3>>,
    b2_0: Constant<Bits<2>>,
    b2_1: Constant<Bits<2>>,
    b2_2: Constant<Bits<2>>,
    b2_3: Constant<Bits<2>>,
    s_zero: Constant<Bits<3>>,
    s_cur: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
    two3: Constant<Bits<3>>,
    two4: Constant<Bits<4>>,
    zero3: Constant<Bits<3>>,
    four3: Constant<Bits<3>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    zero20: Constant<Bits<20>>,
    one24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
    _l: usize,
}

impl FccLabelUpdate {
    pub fn new(p: &FccParams) -> Self {
        let l = p.labels_per_beat as usize;
        let words = p.pixels().div_ceil(4);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            wr_valid: Default::default(),
            wr_state: Default::default(),
            wr_last: Default::default(),
            rb_start: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_used: Default::default(),
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
            wcnt: Default::default(),
            beats_m1: Default::default(),
            last_n: Default::default(),
            active: Default::default(),
            rpix: Default::default(),
            beats: Default::default(),
            lastb: Default::default(),
            outst: Default::default(),
            r1v: Default::default(),
            r1_sub: Default::default(),
            r1_n: Default::default(),
            r1_last: Default::default(),
            r2v: Default::default(),
            r2_sub: Default::default(),
            r2_n: Default::default(),
            r2_last: Default::default(),
            d3v: Default::default(),
            d3: Default::default(),
            sk: vec_of(SKID),
            skn: Default::default(),
            u: Default::default(),
            labs: vec_of(4),
            cur_run: Default::default(),
            g: vec_of(GEAR),
            gn: Default::default(),
            o_valid: Default::default(),
            o_data: Default::default(),
            o_keep: Default::default(),
            o_last: Default::default(),
            gstall: Default::default(),
            issue: Default::default(),
            st: vec_of(4),
            src: vec_of(5),
            slot: vec_of(4),
            nnew: vec_of(5),
            idx: Default::default(),
            hv: Default::default(),
            ghv: Default::default(),
            pop: Default::default(),
            pop2: Default::default(),
            pop1: Default::default(),
            lz: Default::default(),
            l1: Default::default(),
            l2: Default::default(),
            lge2: Default::default(),
            gge2: Default::default(),
            gn_p1: Default::default(),
            gn_m1: Default::default(),
            gn_m2: Default::default(),
            fire: Default::default(),
            ofree: Default::default(),
            lab: vec_of(4),
            nsrc: vec_of(4),
            runv: Default::default(),
            wrem: Default::default(),
            slot_off: (0..l).map(|i| kb(i as u64)).collect(),
            slot_idx: (0..l).map(|i| kb(i as u64)).collect(),
            keep_n: (0..=4).map(|n| kb((1u64 << (2 * n)) - 1)).collect(),
            n_of: (0..=4).map(|n| kb(n as u64)).collect(),
            g_of: (0..GEAR + 2).map(|n| kb(n as u64)).collect(),
            k_of: (0..4).map(|k| kb(2 + k as u64)).collect(),
            lpb_log: kb(u64::from(l.trailing_zeros())),
            lpb_m1: kb(l as u64 - 1),
            one20: kb(1),
            lpb20: kb(l as u64),
            lpb3: kb(l as u64),
            b2_0: kb(0),
            b2_1: kb(1),
            b2_2: kb(2),
            b2_3: kb(3),
            s_zero: kb(0),
            s_cur: kb(1),
            one3: kb(1),
            two3: kb(2),
            two4: kb(2),
            zero3: kb(0),
            four3: kb(4),
            zero4: kb(0),
            one4: kb(1),
            zero16: kb(0),
            zero17: kb(0),
            one17: kb(1),
            zero20: kb(0),
            one24: kb(1),
            zero24: kb(0),
            _l: l,
        }
    }
}

impl Logic for FccLabelUpdate {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, ws0, ws1, ws2, wsub, waddr, wcnt, beats_m1, last_n, active, rpix, beats,
            lastb, outst, r1v, r1_sub, r1_n, r1_last, r2v, r2_sub, r2_n, r2_last, d3v, d3, skn, u,
            cur_run, gn, o_valid, o_data, o_keep, o_last, gstall
        );
        for i in 0..4 {
            self.sk[i].clock.next = self.clk.val();
            self.sk[i].d.next = self.sk[i].q.val();
            self.labs[i].clock.next = self.clk.val();
            self.labs[i].d.next = self.labs[i].q.val();
        }
        for i in 0..8 {
            self.g[i].clock.next = self.clk.val();
            self.g[i].d.next = self.g[i].q.val();
        }
        // ---- Frame-buffer writes: four codes per word.
        self.wrem.next = self.wcnt.q.val().get_bits::<2>(0) & self.lpb_m1.val();
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
        if self.wr_valid.val() {
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
            self.wcnt.d.next = self.wcnt.q.val() + self.one20.val();
            if self.wr_last.val() {
                self.wsub.d.next = self.b2_0.val();
                self.waddr.d.next = self.zero17.val();
                // `wcnt` is the frame's pixels less one (L is a power of two).
                self.wcnt.d.next = self.zero20.val();
                self.beats_m1.d.next = self.wcnt.q.val() >> self.lpb_log.val();
                self.last_n.d.next = self.n_of[1].val();
                if self.wrem.val() == self.b2_1.val() {
                    self.last_n.d.next = self.n_of[2].val();
                }
                if self.wrem.val() == self.b2_2.val() {
                    self.last_n.d.next = self.n_of[3].val();
                }
                if self.wrem.val() == self.b2_3.val() {
                    self.last_n.d.next = self.n_of[4].val();
                }
            }
        }
        // ---- The head beat: collect its new labels, then leave.
        self.ofree.next = !self.o_valid.q.val() | self.m_axis_tready.val();
        self.hv.next = self.skn.q.val() != self.zero3.val();
        self.ghv.next = self.gn.q.val() != self.zero4.val();
        // Up to two new labels a cycle from the gearbox's head. How many the
        // head beat still needs (`need - u`) is decoded by equalities on the
        // two 3-bit registers, one LUT level, rather than by a subtraction.
        self.lz.next = self.sk[0].q.val().need == self.u.q.val();
        self.l1.next = false;
        self.l2.next = false;
        self.lge2.next = false;
        for k in 0..4 {
            if (self.u.q.val() == self.n_of[k].val())
                & (self.sk[0].q.val().need == self.n_of[k + 1].val())
            {
                self.l1.next = true;
            }
        }
        for k in 0..3 {
            if (self.u.q.val() == self.n_of[k].val())
                & (self.sk[0].q.val().need == self.n_of[k + 2].val())
            {
                self.l2.next = true;
                self.lge2.next = true;
            }
        }
        for k in 0..2 {
            if (self.u.q.val() == self.n_of[k].val())
                & (self.sk[0].q.val().need == self.n_of[k + 3].val())
            {
                self.lge2.next = true;
            }
        }
        if (self.u.q.val() == self.n_of[0].val()) & (self.sk[0].q.val().need == self.n_of[4].val())
        {
            self.lge2.next = true;
        }
        self.gge2.next =
            (self.gn.q.val() != self.zero4.val()) & (self.gn.q.val() != self.one4.val());
        self.pop2.next = self.hv.val() & self.lge2.val() & self.gge2.val();
        self.pop.next = self.hv.val() & !self.lz.val() & self.ghv.val();
        self.fire.next = self.hv.val()
            & self.ofree.val()
            & (self.lz.val()
                | (self.l1.val() & self.ghv.val())
                | (self.l2.val() & self.gge2.val()));
        // Slot sources of the head beat, then the carried run. A source equal
        // to a label being popped now (k == u, u + 1) reads the gearbox's head.
        self.nsrc[0].next = self.sk[0].q.val().s0;
        self.nsrc[1].next = self.sk[0].q.val().s1;
        self.nsrc[2].next = self.sk[0].q.val().s2;
        self.nsrc[3].next = self.sk[0].q.val().s3;
        for i in 0..4 {
            self.lab[i].next = self.zero16.val();
            if self.nsrc[i].val() == self.s_cur.val() {
                self.lab[i].next = self.cur_run.q.val();
            }
            for k in 0..4 {
                if self.nsrc[i].val() == self.k_of[k].val() {
                    self.lab[i].next = self.labs[k].q.val();
                    if self.u.q.val() == self.n_of[k].val() {
                        self.lab[i].next = self.g[0].q.val();
                    }
                }
            }
            for k in 1..4 {
                if (self.nsrc[i].val() == self.k_of[k].val())
                    & (self.u.q.val() == self.n_of[k - 1].val())
                {
                    self.lab[i].next = self.g[1].q.val();
                }
            }
        }
        self.runv.next = self.zero16.val();
        if self.sk[0].q.val().run == self.s_cur.val() {
            self.runv.next = self.cur_run.q.val();
        }
        for k in 0..4 {
            if self.sk[0].q.val().run == self.k_of[k].val() {
                self.runv.next = self.labs[k].q.val();
                if self.u.q.val() == self.n_of[k].val() {
                    self.runv.next = self.g[0].q.val();
                }
            }
        }
        for k in 1..4 {
            if (self.sk[0].q.val().run == self.k_of[k].val())
                & (self.u.q.val() == self.n_of[k - 1].val())
            {
                self.runv.next = self.g[1].q.val();
            }
        }
        if self.fire.val() {
            self.cur_run.d.next = self.runv.val();
        }
        if self.pop.val() {
            for k in 0..4 {
                if self.u.q.val() == self.n_of[k].val() {
                    self.labs[k].d.next = self.g[0].q.val();
                }
            }
            self.u.d.next = self.u.q.val() + self.one3.val();
        }
        if self.pop2.val() {
            for k in 1..4 {
                if self.u.q.val() == self.n_of[k - 1].val() {
                    self.labs[k].d.next = self.g[1].q.val();
                }
            }
            self.u.d.next = self.u.q.val() + self.two3.val();
        }
        if self.o_valid.q.val() & self.m_axis_tready.val() {
            self.o_valid.d.next = false;
        }
        if self.fire.val() {
            self.u.d.next = self.zero3.val();
            self.o_valid.d.next = true;
            self.o_data.d.next.l0 = self.lab[0].val();
            self.o_data.d.next.l1 = self.lab[1].val();
            self.o_data.d.next.l2 = self.lab[2].val();
            self.o_data.d.next.l3 = self.lab[3].val();
            self.o_keep.d.next = self.sk[0].q.val().keep;
            self.o_last.d.next = self.sk[0].q.val().last;
        }
        if self.hv.val() & !self.fire.val() & self.ofree.val() {
            self.gstall.d.next = self.gstall.q.val() + self.one24.val();
        }
        // ---- Gearbox: append the flattened label, drop the popped ones. The
        // new tail (`gn - popped`) and count are chosen among values computed
        // from `gn` alone, so no adder follows the pop decision.
        for i in 0..7 {
            if self.pop.val() {
                self.g[i].d.next = self.g[i + 1].q.val();
            }
        }
        for i in 0..6 {
            if self.pop2.val() {
                self.g[i].d.next = self.g[i + 2].q.val();
            }
        }
        self.pop1.next = self.pop.val() & !self.pop2.val();
        for i in 0..8 {
            if self.fv.val()
                & ((!self.pop.val() & (self.gn.q.val() == self.g_of[i].val()))
                    | (self.pop1.val() & (self.gn.q.val() == self.g_of[i + 1].val()))
                    | (self.pop2.val() & (self.gn.q.val() == self.g_of[i + 2].val())))
            {
                self.g[i].d.next = self.fval.val();
            }
        }
        self.gn_p1.next = self.gn.q.val() + self.one4.val();
        self.gn_m1.next = self.gn.q.val() - self.one4.val();
        self.gn_m2.next = self.gn.q.val() - self.two4.val();
        if self.fv.val() {
            self.gn.d.next = self.gn_p1.val();
        }
        if self.pop1.val() {
            if self.fv.val() {
                self.gn.d.next = self.gn.q.val();
            } else {
                self.gn.d.next = self.gn_m1.val();
            }
        }
        if self.pop2.val() {
            if self.fv.val() {
                self.gn.d.next = self.gn_m1.val();
            } else {
                self.gn.d.next = self.gn_m2.val();
            }
        }
        self.gear_used.next = self.gn.q.val();
        // ---- R0: issue the frame-buffer read of the next beat.
        self.issue.next =
            self.active.q.val() & ((self.outst.q.val() < self.four3.val()) | self.fire.val());
        self.fb.read_en.next = self.issue.val();
        self.fb.read_addr.next = self.rpix.q.val().get_bits::<17>(2);
        self.r1v.d.next = self.issue.val();
        if self.issue.val() {
            self.r1_sub.d.next = self.rpix.q.val().get_bits::<2>(0);
            self.r1_n.d.next = self.lpb3.val();
            self.r1_last.d.next = false;
            if self.lastb.q.val() {
                self.r1_n.d.next = self.last_n.q.val();
                self.r1_last.d.next = true;
                self.active.d.next = false;
            }
            self.rpix.d.next = self.rpix.q.val() + self.lpb20.val();
            self.beats.d.next = self.beats.q.val() - self.one20.val();
            self.lastb.d.next = self.beats.q.val() == self.one20.val();
        }
        if self.issue.val() & !self.fire.val() {
            self.outst.d.next = self.outst.q.val() + self.one3.val();
        }
        if !self.issue.val() & self.fire.val() {
            self.outst.d.next = self.outst.q.val() - self.one3.val();
        }
        self.r2v.d.next = self.r1v.q.val();
        self.r2_sub.d.next = self.r1_sub.q.val();
        self.r2_n.d.next = self.r1_n.q.val();
        self.r2_last.d.next = self.r1_last.q.val();
        // ---- R2: decode the word into slot sources.
        for i in 0..4 {
            self.st[i].next = self.b2_0.val();
        }
        for i in 0..self._l {
            self.idx.next = self.r2_sub.q.val() + self.slot_off[i].val();
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
            if self.slot_idx[i].val() >= self.r2_n.q.val() {
                self.st[i].next = self.b2_0.val();
            }
        }
        self.src[0].next = self.s_cur.val();
        self.nnew[0].next = self.zero3.val();
        for i in 0..4 {
            self.src[i + 1].next = self.src[i].val();
            self.nnew[i + 1].next = self.nnew[i].val();
            if self.st[i].val() == self.b2_2.val() {
                self.src[i + 1].next = self.nnew[i].val() + self.k_of[0].val();
                self.nnew[i + 1].next = self.nnew[i].val() + self.one3.val();
            }
            if self.st[i].val() == self.b2_3.val() {
                self.src[i + 1].next = self.s_zero.val();
            }
            self.slot[i].next = self.src[i + 1].val();
            if self.st[i].val() == self.b2_0.val() {
                self.slot[i].next = self.s_zero.val();
            }
        }
        self.d3v.d.next = self.r2v.q.val();
        self.d3.d.next.s0 = self.slot[0].val();
        self.d3.d.next.s1 = self.slot[1].val();
        self.d3.d.next.s2 = self.slot[2].val();
        self.d3.d.next.s3 = self.slot[3].val();
        self.d3.d.next.run = self.src[4].val();
        self.d3.d.next.need = self.nnew[4].val();
        self.d3.d.next.keep = self.keep_n[0].val();
        for n in 0..5 {
            if self.r2_n.q.val() == self.n_of[n].val() {
                self.d3.d.next.keep = self.keep_n[n].val();
            }
        }
        self.d3.d.next.last = self.r2_last.q.val();
        // ---- The queue of decoded beats (a shift register; sk[0] the head).
        for i in 0..3 {
            if self.fire.val() {
                self.sk[i].d.next = self.sk[i + 1].q.val();
            }
        }
        for i in 0..4 {
            if self.fire.val() {
                if self.d3v.q.val() & (self.skn.q.val() == self.n_of[i + 1].val()) {
                    self.sk[i].d.next = self.d3.q.val();
                }
            } else if self.d3v.q.val() & (self.skn.q.val() == self.n_of[i].val()) {
                self.sk[i].d.next = self.d3.q.val();
            }
        }
        if self.d3v.q.val() & !self.fire.val() {
            self.skn.d.next = self.skn.q.val() + self.one3.val();
        }
        if !self.d3v.q.val() & self.fire.val() {
            self.skn.d.next = self.skn.q.val() - self.one3.val();
        }
        if self.rb_start.val() {
            self.active.d.next = true;
            self.rpix.d.next = self.zero20.val();
            self.beats.d.next = self.beats_m1.q.val();
            self.lastb.d.next = self.beats_m1.q.val() == self.zero20.val();
            self.outst.d.next = self.zero3.val();
            self.r1v.d.next = false;
            self.r2v.d.next = false;
            self.d3v.d.next = false;
            self.skn.d.next = self.zero3.val();
            self.u.d.next = self.zero3.val();
            self.cur_run.d.next = self.zero16.val();
            self.gn.d.next = self.zero4.val();
            self.gstall.d.next = self.zero24.val();
        }
        if self.rst.val() {
            self.active.d.next = false;
            self.outst.d.next = self.zero3.val();
            self.r1v.d.next = false;
            self.r2v.d.next = false;
            self.d3v.d.next = false;
            self.skn.d.next = self.zero3.val();
            self.u.d.next = self.zero3.val();
            self.o_valid.d.next = false;
            self.gn.d.next = self.zero4.val();
            self.wsub.d.next = self.b2_0.val();
            self.waddr.d.next = self.zero17.val();
            self.wcnt.d.next = self.zero20.val();
        }
        self.m_axis_tdata.next = self.o_data.q.val().into();
        self.m_axis_tkeep.next = self.o_keep.q.val();
        self.m_axis_tvalid.next = self.o_valid.q.val();
        self.m_axis_tlast.next = self.o_last.q.val();
        self.rb_done.next = self.o_valid.q.val() & self.m_axis_tready.val() & self.o_last.q.val();
        self.gear_stalls.next = self.gstall.q.val();
    }
}
