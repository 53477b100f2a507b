//! `fcc_sort_net`: reduces the window positions that matched a centre to a
//! few joins, buffers them, and hands them to the union engine one at a time.
//!
//! Every upper pixel carries a *representative* (`rep`): a provisional label
//! already known to be in its component (its own label at worst; see
//! `fcc_window`). Two pixels with equal representatives are known to be
//! connected. The filter runs at one centre per cycle, without stalls:
//!
//! * S0: the centre's run (`eqc`: same label as the last labelled centre), and
//!   per position `adj`: the position to the left matched too and has the same
//!   representative. The representatives of the matched positions enter a
//!   registered minimum tree (one level per stage, L = ceil(log2 positions)).
//! * S1: the sliding `known` mask: an upper pixel that matched an earlier centre
//!   of the same run (the window moves one column per valid pixel, so the mask
//!   shifts by one position per valid slot; it is cleared when the run changes).
//! * SM = S(L+1): `M`, the smallest representative among the matches. The run's
//!   representative `rep_c` becomes min(rep_c, M) (min(c, M) for a new run) and
//!   is written back to the window as the centre pixel's representative.
//! * SM+1: a match is kept unless it is known, `adj`, has the run's
//!   representative (before this centre), or has representative M while an
//!   earlier position also has M.
//! * SM+3: a centre with kept matches, a ring join or the frame's end is written
//!   to the centre buffer (512 records in block RAM).
//!
//! Exactness: a dropped match (c, n) always has a justification made of joins
//! already queued (or themselves justified) at earlier positions or earlier
//! centres, so the connected components are unchanged. A kept match is sent
//! as the join (rc, rep(n)) with rc = rep_c before this centre (c for a new
//! run): both ends are in the components of c and n, which is what a join of
//! c and n needs.
//!
//! The serializer takes one record at a time from the buffer and emits its
//! joins one every other cycle (emit the selected position, select the next
//! one), then the ring join, and takes the record with its last join. Joins
//! go into a 4096-entry queue (block RAM) in front of the union engine, which
//! absorbs the bursts of joins of dense regions without holding the input. A record taken
//! and a centre that needed no record return their input credit (`take`,
//! `drop`), which `fcc_top` counts to drive `s_axis_tready`.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_any_or::FccAnyOr;
use crate::fcc_fifo::FccFifo;
use crate::fcc_pick::FccPick;
use crate::fcc_prefix_or::FccPrefixOr;
use crate::fcc_ram::FccRam;
use crate::fcc_row_word::{FccRowPack, FccRowUnpack, ROW_BITS};
use crate::fcc_two_or::FccTwoOr;
use crate::types::{clog2, kb, vec_of, Ctr, CtrRec, JoinRec};

/// Centre buffer: 2^CB_BITS records.
pub const CB_BITS: usize = 9;

/// Join queue between the serializer and the union engine: 2^JQ_BITS joins.
pub const JQ_BITS: usize = 12;

/// What the filter carries about a centre from stage to stage.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct FiltCtr {
    pub valid: Bit,
    /// A labelled point: it can join.
    pub elig: Bit,
    /// Same label as the last labelled centre of the frame.
    pub eqc: Bit,
    pub c: Bits<16>,
    pub col: Bits<12>,
    pub last: Bit,
    pub ring: Bit,
    pub ring_a: Bits<16>,
    pub ring_b: Bits<16>,
}

#[derive(LogicBlock)]
pub struct FccSortNet {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Clear the join counter (start of a frame).
    pub clear: Signal<In, Bit>,
    // From the distance tree and the window (stage S0).
    pub centre: Signal<In, Ctr>,
    pub hit: Vec<Signal<In, Bit>>,
    pub rep: Vec<Signal<In, Bits<16>>>,
    // The centre pixel's representative, back to the window.
    pub rep_we: Signal<Out, Bit>,
    pub rep_waddr: Signal<Out, Bits<12>>,
    pub rep_wdata: Signal<Out, Bits<16>>,
    // Joins to the union engine.
    pub jv: Signal<Out, Bit>,
    pub ja: Signal<Out, Bits<16>>,
    pub jb: Signal<Out, Bits<16>>,
    /// `ja` equals the previous join's `ja` of this frame.
    pub jsame: Signal<Out, Bit>,
    pub jtake: Signal<In, Bit>,
    /// The join queue holds nothing (registered; one cycle late).
    pub jq_empty: Signal<Out, Bit>,
    /// The frame's last centre has left the serializer (its joins are out).
    pub last_done: Signal<Out, Bit>,
    /// Input credits returned: a slot that needed no record, a record taken.
    pub drop: Signal<Out, Bit>,
    pub take: Signal<Out, Bit>,
    /// Joins emitted in this frame.
    pub joins: Signal<Out, Bits<24>>,
    // ---- Filter.
    mask_c: DFF<Bits<16>>,
    mask_v: DFF<Bit>,
    c0: Signal<Local, FiltCtr>,
    c1: DFF<FiltCtr>,
    cs: Vec<DFF<FiltCtr>>,
    c_sm: DFF<FiltCtr>,
    c_sm1: DFF<FiltCtr>,
    c_sm2: DFF<FiltCtr>,
    ps_hit: Vec<DFF<Bit>>,
    ps_adj: Vec<DFF<Bit>>,
    ps_rep: Vec<DFF<Bits<16>>>,
    known: Vec<DFF<Bit>>,
    kn: Vec<Signal<Local, Bit>>,
    sh: Vec<Signal<Local, Bit>>,
    knq: Vec<DFF<Bit>>,
    tn: Vec<DFF<Bits<16>>>,
    rep_c: DFF<Bits<16>>,
    rc: Signal<Local, Bits<16>>,
    nr: Signal<Local, Bits<16>>,
    rcq: DFF<Bits<16>>,
    rcq2: DFF<Bits<16>>,
    wr_en: DFF<Bit>,
    wr_addr: DFF<Bits<12>>,
    wr_data: DFF<Bits<16>>,
    eqm: Vec<DFF<Bit>>,
    eqrc: Vec<DFF<Bit>>,
    qp: FccPrefixOr,
    keepq: Vec<DFF<Bit>>,
    kd: Vec<DFF<Bit>>,
    ap: FccAnyOr,
    anyk: Signal<Local, Bit>,
    push_q: DFF<Bit>,
    drop_q: DFF<Bit>,
    rec: DFF<CtrRec>,
    // ---- Centre buffer.
    cb: FccFifo<CtrRec, CB_BITS, { CB_BITS + 1 }>,
    rows: Vec<FccRam<Bits<ROW_BITS>, CB_BITS>>,
    pack: FccRowPack,
    unpack: FccRowUnpack,
    // ---- Serializer.
    ld: DFF<Bit>,
    ph: DFF<Bits<2>>,
    m: Vec<DFF<Bit>>,
    sel: Vec<DFF<Bit>>,
    hkeep: Vec<Signal<Local, Bit>>,
    kp: FccPrefixOr,
    mp: FccPrefixOr,
    /// Any kept position in the head record: a reduction of its own, not
    /// the last output of the prefix network `kp`.
    kany: Signal<Local, Bit>,
    ka: FccAnyOr,
    /// Any position left in `m`, from the register `mq`. Removing the first
    /// set flag leaves some iff at least two were set, so `mq` is loaded with
    /// "at least two" of the flags being reduced (`mt`), and no decision
    /// waits on a reduction of `m`.
    many: Signal<Local, Bit>,
    mq: DFF<Bit>,
    mt: FccTwoOr,
    done: Signal<Local, Bit>,
    rp: DFF<Bit>,
    jq: FccFifo<JoinRec, JQ_BITS, { JQ_BITS + 1 }>,
    jpush: Signal<Local, Bit>,
    jrec: Signal<Local, JoinRec>,
    jfull: DFF<Bit>,
    last_a: DFF<Bits<16>>,
    last_av: DFF<Bit>,
    csame: DFF<Bit>,
    rsame_c: DFF<Bit>,
    rsame_l: DFF<Bit>,
    emitted: DFF<Bit>,
    jfree: Signal<Local, Bit>,
    vals: Vec<Signal<Local, Bits<16>>>,
    pk: FccPick,
    ldone_q: DFF<Bit>,
    joins_q: DFF<Bits<24>>,
    // Constants.
    ctr_zero: Constant<FiltCtr>,
    all16: Constant<Bits<16>>,
    zero16: Constant<Bits<16>>,
    p_sel: Constant<Bits<2>>,
    p_emit: Constant<Bits<2>>,
    p_ring: Constant<Bits<2>>,
    one24: Constant<Bits<24>>,
    jq_high: Constant<Bits<{ JQ_BITS + 1 }>>,
    jq_zero: Constant<Bits<{ JQ_BITS + 1 }>>,
    zero24: Constant<Bits<24>>,
    _k: usize,
    _h: usize,
    _n: usize,
    /// Levels of the minimum tree; leaves = 2^L.
    _l: usize,
    _leaves: usize,
    /// Depth of the representative delay line (S1 .. SM+3).
    _dp: usize,
    /// Depth of the hit and adjacency delay lines (S1 .. SM+1).
    _dh: usize,
    /// Depth of the known-mask delay line (S2 .. SM+1).
    _dk: usize,
    /// K times `_dp` and `_dh`: the stride of a window row in the delay lines.
    _kd: usize,
    _kh: usize,
}

impl FccSortNet {
    pub fn new(p: &FccParams) -> Self {
        let k = p.fsize;
        let h = p.half();
        let n = p.window_positions();
        assert!(n <= 64);
        let l = clog2(n);
        let leaves = 1 << l;
        let dp = l + 4;
        let dh = l + 2;
        let dk = l + 1;
        let row_bits = 17 * k;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            centre: Default::default(),
            hit: vec_of(n),
            rep: vec_of(n),
            rep_we: Default::default(),
            rep_waddr: Default::default(),
            rep_wdata: Default::default(),
            jv: Default::default(),
            ja: Default::default(),
            jb: Default::default(),
            jsame: Default::default(),
            jtake: Default::default(),
            jq_empty: Default::default(),
            last_done: Default::default(),
            drop: Default::default(),
            take: Default::default(),
            joins: Default::default(),
            mask_c: Default::default(),
            mask_v: Default::default(),
            c0: Default::default(),
            c1: Default::default(),
            cs: vec_of(l - 1),
            c_sm: Default::default(),
            c_sm1: Default::default(),
            c_sm2: Default::default(),
            ps_hit: vec_of(n * dh),
            ps_adj: vec_of(n * dh),
            ps_rep: vec_of(n * dp),
            known: vec_of(n),
            kn: vec_of(n),
            sh: vec_of(n),
            knq: vec_of(n * dk),
            tn: vec_of(2 * leaves - 1),
            rep_c: Default::default(),
            rc: Default::default(),
            nr: Default::default(),
            rcq: Default::default(),
            rcq2: Default::default(),
            wr_en: Default::default(),
            wr_addr: Default::default(),
            wr_data: Default::default(),
            eqm: vec_of(n),
            eqrc: vec_of(n),
            qp: FccPrefixOr::new(n),
            keepq: vec_of(n),
            kd: vec_of(n),
            ap: FccAnyOr::new(n),
            anyk: Default::default(),
            push_q: Default::default(),
            drop_q: Default::default(),
            rec: Default::default(),
            cb: FccFifo::default(),
            rows: (0..h)
                .map(|_| FccRam::with_stored_bits(1 << CB_BITS, row_bits))
                .collect(),
            pack: FccRowPack::new(k, h),
            unpack: FccRowUnpack::new(k, h),
            ld: Default::default(),
            ph: Default::default(),
            m: vec_of(n),
            sel: vec_of(n),
            hkeep: vec_of(n),
            kp: FccPrefixOr::new(n),
            mp: FccPrefixOr::new(n),
            kany: Default::default(),
            ka: FccAnyOr::new(n),
            many: Default::default(),
            mq: Default::default(),
            mt: FccTwoOr::new(n),
            done: Default::default(),
            rp: Default::default(),
            jq: FccFifo::default(),
            jpush: Default::default(),
            jrec: Default::default(),
            jfull: Default::default(),
            last_a: Default::default(),
            last_av: Default::default(),
            csame: Default::default(),
            rsame_c: Default::default(),
            rsame_l: Default::default(),
            emitted: Default::default(),
            jfree: Default::default(),
            vals: vec_of(n),
            pk: FccPick::new(n),
            ldone_q: Default::default(),
            joins_q: Default::default(),
            ctr_zero: Constant::new(FiltCtr::default()),
            all16: kb(0xffff),
            zero16: kb(0),
            p_sel: kb(0),
            p_emit: kb(1),
            p_ring: kb(2),
            one24: kb(1),
            jq_high: kb((1 << JQ_BITS) - 8),
            jq_zero: kb(0),
            zero24: kb(0),
            _k: k,
            _h: h,
            _n: n,
            _l: l,
            _leaves: leaves,
            _dp: dp,
            _dk: dk,
            _dh: dh,
            _kd: k * dp,
            _kh: k * dh,
        }
    }
}

impl Logic for FccSortNet {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, mask_c, mask_v, c1, c_sm, c_sm1, c_sm2, rep_c, rcq, rcq2, wr_en, wr_addr,
            wr_data, push_q, drop_q, rec, ld, ph, rp, jfull, last_a, last_av, csame, rsame_c,
            rsame_l, emitted, ldone_q, joins_q, mq
        );
        for i in 0..(self._l - 1) {
            self.cs[i].clock.next = self.clk.val();
        }
        for i in 0..(self._n * self._dp) {
            self.ps_rep[i].clock.next = self.clk.val();
        }
        for i in 0..(self._n * self._dh) {
            self.ps_hit[i].clock.next = self.clk.val();
            self.ps_adj[i].clock.next = self.clk.val();
        }
        for i in 0..(self._n * self._dk) {
            self.knq[i].clock.next = self.clk.val();
        }
        for i in 0..(2 * self._leaves - 1) {
            self.tn[i].clock.next = self.clk.val();
        }
        for e in 0..self._n {
            self.known[e].clock.next = self.clk.val();
            self.eqm[e].clock.next = self.clk.val();
            self.eqrc[e].clock.next = self.clk.val();
            self.keepq[e].clock.next = self.clk.val();
            self.kd[e].clock.next = self.clk.val();
            self.m[e].clock.next = self.clk.val();
            self.sel[e].clock.next = self.clk.val();
            self.known[e].d.next = self.known[e].q.val();
            self.m[e].d.next = self.m[e].q.val();
            self.sel[e].d.next = self.sel[e].q.val();
        }
        // ---- S0: the centre's run and the adjacent duplicates.
        self.c0.next.valid = self.centre.val().valid;
        self.c0.next.elig = self.centre.val().valid & self.centre.val().lok;
        self.c0.next.eqc = self.mask_v.q.val() & (self.centre.val().label == self.mask_c.q.val());
        self.c0.next.c = self.centre.val().label;
        self.c0.next.col = self.centre.val().col;
        self.c0.next.last = self.centre.val().last;
        self.c0.next.ring = self.centre.val().ring;
        self.c0.next.ring_a = self.centre.val().ring_a;
        self.c0.next.ring_b = self.centre.val().ring_b;
        if self.centre.val().valid & self.centre.val().lok {
            self.mask_c.d.next = self.centre.val().label;
            self.mask_v.d.next = true;
        }
        if self.centre.val().valid & self.centre.val().last {
            self.mask_v.d.next = false;
        }
        self.c1.d.next = self.c0.val();
        self.cs[0].d.next = self.c1.q.val();
        for i in 1..(self._l - 1) {
            self.cs[i].d.next = self.cs[i - 1].q.val();
        }
        for l in self._l..(self._l + 1) {
            self.c_sm.d.next = self.cs[l - 2].q.val();
        }
        self.c_sm1.d.next = self.c_sm.q.val();
        self.c_sm2.d.next = self.c_sm1.q.val();
        for kk in self._k..(self._k + 1) {
            for dd in self._dp..(self._dp + 1) {
                for kd in self._kd..(self._kd + 1) {
                    for r in 0..self._h {
                        for n in 0..self._k {
                            self.ps_rep[r * kd + n * dd].d.next = self.rep[r * kk + n].val();
                        }
                    }
                }
                for e in 0..self._n {
                    for i in 1..self._dp {
                        self.ps_rep[e * dd + i].d.next = self.ps_rep[e * dd + i - 1].q.val();
                    }
                }
            }
            for dh in self._dh..(self._dh + 1) {
                for kh in self._kh..(self._kh + 1) {
                    for r in 0..self._h {
                        self.ps_hit[r * kh].d.next = self.hit[r * kk].val();
                        self.ps_adj[r * kh].d.next = false;
                        for n in 1..self._k {
                            self.ps_hit[r * kh + n * dh].d.next = self.hit[r * kk + n].val();
                            self.ps_adj[r * kh + n * dh].d.next = self.hit[r * kk + n - 1].val()
                                & (self.rep[r * kk + n].val() == self.rep[r * kk + n - 1].val());
                        }
                    }
                }
                for e in 0..self._n {
                    for i in 1..self._dh {
                        self.ps_hit[e * dh + i].d.next = self.ps_hit[e * dh + i - 1].q.val();
                        self.ps_adj[e * dh + i].d.next = self.ps_adj[e * dh + i - 1].q.val();
                    }
                }
            }
        }
        // The minimum tree, heap-ordered with node i in tn[i - 1] (root tn[0],
        // children of i are 2i and 2i + 1): leaves are registered in S0, one
        // level per stage.
        for lv in self._leaves..(self._leaves + 1) {
            for e in 0..self._n {
                self.tn[lv + e - 1].d.next = self.all16.val();
                if self.hit[e].val() {
                    self.tn[lv + e - 1].d.next = self.rep[e].val();
                }
            }
            for e in self._n..self._leaves {
                self.tn[lv + e - 1].d.next = self.all16.val();
            }
        }
        for i in 1..self._leaves {
            self.tn[i - 1].d.next = self.tn[2 * i].q.val();
            if self.tn[2 * i - 1].q.val() <= self.tn[2 * i].q.val() {
                self.tn[i - 1].d.next = self.tn[2 * i - 1].q.val();
            }
        }
        // ---- S1: the sliding mask of upper pixels already matched by this run.
        for kk in self._k..(self._k + 1) {
            for r in 0..self._h {
                for n in 0..(self._k - 1) {
                    self.sh[r * kk + n].next = self.known[r * kk + n + 1].q.val();
                }
                self.sh[r * kk + kk - 1].next = false;
            }
        }
        for dh in self._dh..(self._dh + 1) {
            for dk in self._dk..(self._dk + 1) {
                for e in 0..self._n {
                    self.kn[e].next = self.c1.q.val().eqc & self.sh[e].val();
                    if self.c1.q.val().valid {
                        self.known[e].d.next = self.sh[e].val();
                        if self.c1.q.val().elig {
                            self.known[e].d.next = self.kn[e].val() | self.ps_hit[e * dh].q.val();
                        }
                    }
                    self.knq[e * dk].d.next = self.kn[e].val();
                    for i in 1..self._dk {
                        self.knq[e * dk + i].d.next = self.knq[e * dk + i - 1].q.val();
                    }
                }
            }
        }
        // ---- SM: the run's representative; matches with the smallest one.
        for l in self._l..(self._l + 1) {
            self.rc.next = self.c_sm.q.val().c;
            if self.c_sm.q.val().eqc {
                self.rc.next = self.rep_c.q.val();
            }
            self.nr.next = self.rc.val();
            if self.tn[0].q.val() < self.rc.val() {
                self.nr.next = self.tn[0].q.val();
            }
            if self.c_sm.q.val().elig {
                self.rep_c.d.next = self.nr.val();
            }
            self.rcq.d.next = self.rc.val();
            self.wr_en.d.next = self.c_sm.q.val().valid;
            self.wr_addr.d.next = self.c_sm.q.val().col;
            self.wr_data.d.next = self.zero16.val();
            if self.c_sm.q.val().elig {
                self.wr_data.d.next = self.nr.val();
            }
            for dd in self._dp..(self._dp + 1) {
                for dh in self._dh..(self._dh + 1) {
                    for e in 0..self._n {
                        self.eqm[e].d.next = self.ps_hit[e * dh + l].q.val()
                            & (self.ps_rep[e * dd + l].q.val() == self.tn[0].q.val());
                        self.eqrc[e].d.next = self.ps_rep[e * dd + l].q.val() == self.rc.val();
                    }
                }
            }
        }
        self.rep_we.next = self.wr_en.q.val();
        self.rep_waddr.next = self.wr_addr.q.val();
        self.rep_wdata.next = self.wr_data.q.val();
        // ---- SM+1: keep a match unless known, adjacent or a second minimum.
        for e in 0..self._n {
            self.qp.x[e].next = self.eqm[e].q.val();
        }
        for l in self._l..(self._l + 1) {
            for dh in self._dh..(self._dh + 1) {
                for dk in self._dk..(self._dk + 1) {
                    for e in 0..self._n {
                        self.keepq[e].d.next = self.c_sm1.q.val().elig
                            & self.ps_hit[e * dh + l + 1].q.val()
                            & !self.ps_adj[e * dh + l + 1].q.val()
                            & !self.knq[e * dk + dk - 1].q.val()
                            & !self.eqrc[e].q.val()
                            & !(self.eqm[e].q.val() & self.qp.pre[e].val());
                    }
                }
            }
        }
        self.rcq2.d.next = self.rcq.q.val();
        // ---- SM+2: does the centre need a record?
        for e in 0..self._n {
            self.ap.x[e].next = self.keepq[e].q.val();
            self.kd[e].d.next = self.keepq[e].q.val();
        }
        self.anyk.next = self.ap.any.val();
        self.push_q.d.next = self.c_sm2.q.val().valid
            & (self.anyk.val() | self.c_sm2.q.val().ring | self.c_sm2.q.val().last);
        self.drop_q.d.next = self.c_sm2.q.val().valid
            & !(self.anyk.val() | self.c_sm2.q.val().ring | self.c_sm2.q.val().last);
        self.rec.d.next.c = self.rcq2.q.val();
        self.rec.d.next.ring_a = self.c_sm2.q.val().ring_a;
        self.rec.d.next.ring_b = self.c_sm2.q.val().ring_b;
        self.rec.d.next.ring = self.c_sm2.q.val().ring;
        self.rec.d.next.last = self.c_sm2.q.val().last;
        // ---- SM+3: write the record.
        self.cb.clk.next = self.clk.val();
        self.cb.rst.next = self.rst.val();
        self.cb.push.next = self.push_q.q.val();
        self.cb.din.next = self.rec.q.val();
        for kk in self._k..(self._k + 1) {
            for dd in self._dp..(self._dp + 1) {
                for kd in self._kd..(self._kd + 1) {
                    for r in 0..self._h {
                        for n in 0..self._k {
                            self.pack.v[r * kk + n].next =
                                self.ps_rep[r * kd + n * dd + dd - 1].q.val();
                        }
                    }
                }
            }
        }
        for e in 0..self._n {
            self.pack.f[e].next = self.kd[e].q.val();
            self.vals[e].next = self.unpack.v[e].val();
            self.hkeep[e].next = self.unpack.f[e].val();
        }
        for r in 0..self._h {
            self.rows[r].clk.next = self.clk.val();
            self.rows[r].write_en.next = self.cb.ram_we.val();
            self.rows[r].write_addr.next = self.cb.ram_waddr.val();
            self.rows[r].write_data.next = self.pack.word[r].val();
            self.rows[r].read_en.next = self.cb.ram_re.val();
            self.rows[r].read_addr.next = self.cb.ram_raddr.val();
            self.unpack.word[r].next = self.rows[r].read_data.val();
        }
        // ---- Serializer: the head record's joins, one every other cycle.
        // Load: select the first kept position. Emit: send the selected join;
        // take the record if nothing is left. Select: the next kept position.
        // Ring: send the ring join and take the record.
        // Room in the join queue (registered, with a margin for its lateness).
        self.jq.clk.next = self.clk.val();
        self.jq.rst.next = self.rst.val();
        self.jfull.d.next = self.jq.level.val() >= self.jq_high.val();
        self.jfree.next = !self.jfull.q.val();
        self.jpush.next = false;
        self.jrec.next.a = self.cb.dout.val().c;
        self.jrec.next.b = self.pk.o.val();
        self.jrec.next.same = self.csame.q.val() | self.emitted.q.val();
        self.take.next = false;
        self.ldone_q.d.next = false;
        self.cb.take.next = false;
        self.many.next = self.mq.q.val();
        self.kany.next = self.ka.any.val();
        for e in 0..self._n {
            self.kp.x[e].next = self.hkeep[e].val();
            self.ka.x[e].next = self.hkeep[e].val();
            self.mp.x[e].next = self.m[e].q.val();
            self.mt.x[e].next = self.m[e].q.val();
            if !self.ld.q.val() {
                self.mt.x[e].next = self.hkeep[e].val();
            }
            self.pk.sel[e].next = self.sel[e].q.val();
            self.pk.v[e].next = self.vals[e].val();
        }
        self.done.next = false;
        if !self.ld.q.val() & self.cb.valid.val() {
            self.ld.d.next = true;
            self.mq.d.next = self.mt.two.val();
            self.rp.d.next = self.cb.dout.val().ring;
            // Is each join's `a` the previous join's? Decided once per record.
            self.csame.d.next =
                self.last_av.q.val() & (self.cb.dout.val().c == self.last_a.q.val());
            self.rsame_c.d.next = self.cb.dout.val().ring_a == self.cb.dout.val().c;
            self.rsame_l.d.next =
                self.last_av.q.val() & (self.cb.dout.val().ring_a == self.last_a.q.val());
            self.emitted.d.next = false;
            for e in 0..self._n {
                self.sel[e].d.next = self.hkeep[e].val() & !self.kp.pre[e].val();
                self.m[e].d.next = self.hkeep[e].val() & self.kp.pre[e].val();
            }
            self.ph.d.next = self.p_sel.val();
            if self.kany.val() {
                self.ph.d.next = self.p_emit.val();
            } else if self.cb.dout.val().ring {
                self.ph.d.next = self.p_ring.val();
            }
        }
        if self.ld.q.val() & (self.ph.q.val() == self.p_sel.val()) {
            self.mq.d.next = self.mt.two.val();
            for e in 0..self._n {
                self.sel[e].d.next = self.m[e].q.val() & !self.mp.pre[e].val();
                self.m[e].d.next = self.m[e].q.val() & self.mp.pre[e].val();
            }
            if self.many.val() {
                self.ph.d.next = self.p_emit.val();
            } else if self.rp.q.val() {
                self.ph.d.next = self.p_ring.val();
            } else {
                self.done.next = true;
            }
        }
        if self.ld.q.val() & (self.ph.q.val() == self.p_emit.val()) & self.jfree.val() {
            self.jpush.next = true;
            self.emitted.d.next = true;
            self.last_a.d.next = self.cb.dout.val().c;
            self.last_av.d.next = true;
            self.ph.d.next = self.p_sel.val();
            if !self.many.val() {
                if self.rp.q.val() {
                    self.ph.d.next = self.p_ring.val();
                } else {
                    self.done.next = true;
                }
            }
        }
        if self.ld.q.val() & (self.ph.q.val() == self.p_ring.val()) & self.jfree.val() {
            self.jpush.next = true;
            self.jrec.next.a = self.cb.dout.val().ring_a;
            self.jrec.next.b = self.cb.dout.val().ring_b;
            self.jrec.next.same = self.rsame_l.q.val();
            if self.emitted.q.val() {
                self.jrec.next.same = self.rsame_c.q.val();
            }
            self.last_a.d.next = self.cb.dout.val().ring_a;
            self.last_av.d.next = true;
            self.rp.d.next = false;
            self.done.next = true;
        }
        if self.done.val() {
            // The record is done: take it, return its credit.
            self.ld.d.next = false;
            self.cb.take.next = true;
            self.take.next = true;
            self.ldone_q.d.next = self.cb.dout.val().last;
            if self.cb.dout.val().last {
                self.last_av.d.next = false;
            }
        }
        self.jq.push.next = self.jpush.val();
        self.jq.din.next = self.jrec.val();
        self.jq.take.next = self.jtake.val();
        if self.jpush.val() {
            self.joins_q.d.next = self.joins_q.q.val() + self.one24.val();
        }
        // Cleared at the end of a read-back and by reset, so that a frame
        // abandoned by a reset does not count in the next frame's joins.
        if self.clear.val() | self.rst.val() {
            self.joins_q.d.next = self.zero24.val();
        }
        self.jv.next = self.jq.valid.val();
        self.ja.next = self.jq.dout.val().a;
        self.jb.next = self.jq.dout.val().b;
        self.jsame.next = self.jq.dout.val().same;
        self.jq_empty.next = self.jq.level.val() == self.jq_zero.val();
        self.last_done.next = self.ldone_q.q.val();
        self.drop.next = self.drop_q.q.val();
        self.joins.next = self.joins_q.q.val();
        if self.rst.val() {
            self.mask_v.d.next = false;
            self.c1.d.next.valid = false;
            // The representatives compared in SM are reset, so that this
            // stage stays a flip-flop (a shift-register LUT's output is slow).
            for l in self._l..(self._l + 1) {
                for dd in self._dp..(self._dp + 1) {
                    for e in 0..self._n {
                        self.ps_rep[e * dd + l].d.next = self.zero16.val();
                    }
                }
            }
            for i in 0..(self._l - 1) {
                self.cs[i].d.next = self.ctr_zero.val();
            }
            self.c_sm.d.next.valid = false;
            self.c_sm1.d.next.valid = false;
            self.c_sm2.d.next.valid = false;
            self.push_q.d.next = false;
            self.drop_q.d.next = false;
            self.wr_en.d.next = false;
            self.ld.d.next = false;
            self.jfull.d.next = false;
            self.last_av.d.next = false;
            self.ldone_q.d.next = false;
        }
    }
}
