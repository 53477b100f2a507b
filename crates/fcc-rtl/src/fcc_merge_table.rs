//! `fcc_merge_table`: the exact equivalence table.
//!
//! The parent table `T` (block RAM, `2^B` words) is a union-find forest in
//! which every parent is smaller than its child, so a tree's root is the
//! smallest provisional label of its component.
//!
//! * Init (after every reset): `T[l] = l` for every label, one word per cycle.
//! * Union (while pixels stream): each FIFO entry holds a centre label `c` and
//!   up to four partners. `find(c)` is skipped when `c` is the previous entry's
//!   centre (its root is cached). `find` uses path halving (`T[x] = T[T[x]]`),
//!   one table read per cycle; two different roots are linked larger under
//!   smaller. A read of a word written in the previous cycle is forwarded.
//! * Flatten (frame end): for l = 1 .. P in ascending order, `T[l] == l` gets
//!   the next compact number, otherwise `C[l] = C[T[l]]` (`T[l] < l` is
//!   already final). This numbers components in the raster order of their
//!   first pixel, exactly as the golden model. Each compact label leaves on
//!   the `fv`/`fval` stream in ascending `l` (one per cycle, as long as the
//!   label updater has room), and `T[l] = l` is restored for the next frame.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::{kb, JoinEntry};

#[derive(LogicBlock)]
pub struct FccMergeTable {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Join FIFO (first word fall through).
    pub head: Signal<In, JoinEntry>,
    pub empty: Signal<In, Bit>,
    pub pop: Signal<Out, Bit>,
    // Control.
    pub init_busy: Signal<Out, Bit>,
    pub union_idle: Signal<Out, Bit>,
    pub flat_start: Signal<In, Bit>,
    pub provisional: Signal<In, Bits<17>>,
    // Compact labels in ascending provisional order.
    pub fv: Signal<Out, Bit>,
    pub fval: Signal<Out, Bits<16>>,
    pub gear_free: Signal<In, Bits<4>>,
    pub clusters: Signal<Out, Bits<16>>,
    t_ram: FccRam<Bits<16>, 16>,
    c_ram: FccRam<Bits<16>, 16>,
    mode: DFF<Bits<2>>,
    ph: DFF<Bits<3>>,
    ent: DFF<JoinEntry>,
    si: DFF<Bits<2>>,
    x: DFF<Bits<16>>,
    xp: DFF<Bits<16>>,
    ra: DFF<Bits<16>>,
    cache_v: DFF<Bit>,
    cache_c: DFF<Bits<16>>,
    cache_r: DFF<Bits<16>>,
    wq_en: DFF<Bit>,
    wq_addr: DFF<Bits<16>>,
    wq_data: DFF<Bits<16>>,
    rq_addr: DFF<Bits<16>>,
    ic: DFF<Bits<17>>,
    fl: DFF<Bits<17>>,
    f1v: DFF<Bit>,
    f1l: DFF<Bits<16>>,
    f2v: DFF<Bit>,
    f2l: DFF<Bits<16>>,
    f2root: DFF<Bit>,
    f2rv: DFF<Bits<16>>,
    f2p: DFF<Bits<16>>,
    ncl: DFF<Bits<16>>,
    lastv: DFF<Bits<16>>,
    // Combinational.
    d: Signal<Local, Bits<16>>,
    t_raddr: Signal<Local, Bits<16>>,
    t_we: Signal<Local, Bit>,
    t_waddr: Signal<Local, Bits<16>>,
    t_wdata: Signal<Local, Bits<16>>,
    start_next: Signal<Local, Bit>,
    found_b: Signal<Local, Bit>,
    rb: Signal<Local, Bits<16>>,
    lo: Signal<Local, Bits<16>>,
    hi: Signal<Local, Bits<16>>,
    cv_eff: Signal<Local, Bit>,
    cc_eff: Signal<Local, Bits<16>>,
    cr_eff: Signal<Local, Bits<16>>,
    infl: Signal<Local, Bits<4>>,
    root: Signal<Local, Bit>,
    val: Signal<Local, Bits<16>>,
    m_union: Constant<Bits<2>>,
    m_init: Constant<Bits<2>>,
    m_flat: Constant<Bits<2>>,
    p_idle: Constant<Bits<3>>,
    p_ax: Constant<Bits<3>>,
    p_ap: Constant<Bits<3>>,
    p_bx: Constant<Bits<3>>,
    p_bp: Constant<Bits<3>>,
    s0: Constant<Bits<2>>,
    s1: Constant<Bits<2>>,
    s2: Constant<Bits<2>>,
    one2: Constant<Bits<2>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    last_word: Constant<Bits<17>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
}

impl FccMergeTable {
    pub fn new(p: &FccParams) -> Self {
        let words = 1usize << p.label_bits;
        let b = p.label_bits as usize;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            head: Default::default(),
            empty: Default::default(),
            pop: Default::default(),
            init_busy: Default::default(),
            union_idle: Default::default(),
            flat_start: Default::default(),
            provisional: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_free: Default::default(),
            clusters: Default::default(),
            t_ram: FccRam::with_stored_bits(words, b),
            c_ram: FccRam::with_stored_bits(words, b),
            mode: Default::default(),
            ph: Default::default(),
            ent: Default::default(),
            si: Default::default(),
            x: Default::default(),
            xp: Default::default(),
            ra: Default::default(),
            cache_v: Default::default(),
            cache_c: Default::default(),
            cache_r: Default::default(),
            wq_en: Default::default(),
            wq_addr: Default::default(),
            wq_data: Default::default(),
            rq_addr: Default::default(),
            ic: Default::default(),
            fl: Default::default(),
            f1v: Default::default(),
            f1l: Default::default(),
            f2v: Default::default(),
            f2l: Default::default(),
            f2root: Default::default(),
            f2rv: Default::default(),
            f2p: Default::default(),
            ncl: Default::default(),
            lastv: Default::default(),
            d: Default::default(),
            t_raddr: Default::default(),
            t_we: Default::default(),
            t_waddr: Default::default(),
            t_wdata: Default::default(),
            start_next: Default::default(),
            found_b: Default::default(),
            rb: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            cv_eff: Default::default(),
            cc_eff: Default::default(),
            cr_eff: Default::default(),
            infl: Default::default(),
            root: Default::default(),
            val: Default::default(),
            m_union: kb(0),
            m_init: kb(1),
            m_flat: kb(2),
            p_idle: kb(0),
            p_ax: kb(1),
            p_ap: kb(2),
            p_bx: kb(3),
            p_bp: kb(4),
            s0: kb(0),
            s1: kb(1),
            s2: kb(2),
            one2: kb(1),
            zero16: kb(0),
            one16: kb(1),
            zero17: kb(0),
            one17: kb(1),
            last_word: kb(words as u64 - 1),
            zero4: kb(0),
            one4: kb(1),
        }
    }
}

impl Logic for FccMergeTable {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, mode, ph, ent, si, x, xp, ra, cache_v, cache_c, cache_r, wq_en, wq_addr,
            wq_data, rq_addr, ic, fl, f1v, f1l, f2v, f2l, f2root, f2rv, f2p, ncl, lastv
        );
        self.t_ram.clk.next = self.clk.val();
        self.c_ram.clk.next = self.clk.val();
        // Table word read in the previous cycle, with the previous write forwarded.
        self.d.next = self.t_ram.read_data.val();
        if self.wq_en.q.val() & (self.wq_addr.q.val() == self.rq_addr.q.val()) {
            self.d.next = self.wq_data.q.val();
        }
        self.t_raddr.next = self.x.q.val();
        self.t_we.next = false;
        self.t_waddr.next = self.x.q.val();
        self.t_wdata.next = self.d.val();
        self.start_next.next = false;
        self.found_b.next = false;
        self.rb.next = self.x.q.val();
        self.lo.next = self.ra.q.val();
        self.hi.next = self.rb.val();
        self.cv_eff.next = self.cache_v.q.val();
        self.cc_eff.next = self.cache_c.q.val();
        self.cr_eff.next = self.cache_r.q.val();
        self.pop.next = false;
        self.fv.next = false;
        self.val.next = self.f2rv.q.val();
        self.root.next = false;
        self.infl.next = self.zero4.val();
        self.c_ram.read_en.next = false;
        self.c_ram.read_addr.next = self.d.val();
        self.c_ram.write_en.next = false;
        self.c_ram.write_addr.next = self.f2l.q.val();
        self.c_ram.write_data.next = self.val.val();
        // ---- Union engine.
        if self.mode.q.val() == self.m_union.val() {
            if self.ph.q.val() == self.p_idle.val() {
                self.start_next.next = true;
            }
            if self.ph.q.val() == self.p_ax.val() {
                if self.d.val() == self.x.q.val() {
                    self.ra.d.next = self.x.q.val();
                    self.si.d.next = self.s0.val();
                    self.x.d.next = self.ent.q.val().n0;
                    self.t_raddr.next = self.ent.q.val().n0;
                    self.ph.d.next = self.p_bx.val();
                } else {
                    self.t_raddr.next = self.d.val();
                    self.xp.d.next = self.d.val();
                    self.ph.d.next = self.p_ap.val();
                }
            }
            if self.ph.q.val() == self.p_ap.val() {
                if self.d.val() == self.xp.q.val() {
                    self.ra.d.next = self.xp.q.val();
                    self.si.d.next = self.s0.val();
                    self.x.d.next = self.ent.q.val().n0;
                    self.t_raddr.next = self.ent.q.val().n0;
                    self.ph.d.next = self.p_bx.val();
                } else {
                    self.t_we.next = true;
                    self.t_waddr.next = self.x.q.val();
                    self.t_wdata.next = self.d.val();
                    self.x.d.next = self.d.val();
                    self.t_raddr.next = self.d.val();
                    self.ph.d.next = self.p_ax.val();
                }
            }
            if self.ph.q.val() == self.p_bx.val() {
                if self.d.val() == self.x.q.val() {
                    self.found_b.next = true;
                    self.rb.next = self.x.q.val();
                } else {
                    self.t_raddr.next = self.d.val();
                    self.xp.d.next = self.d.val();
                    self.ph.d.next = self.p_bp.val();
                }
            }
            if self.ph.q.val() == self.p_bp.val() {
                if self.d.val() == self.xp.q.val() {
                    self.found_b.next = true;
                    self.rb.next = self.xp.q.val();
                } else {
                    self.t_we.next = true;
                    self.t_waddr.next = self.x.q.val();
                    self.t_wdata.next = self.d.val();
                    self.x.d.next = self.d.val();
                    self.t_raddr.next = self.d.val();
                    self.ph.d.next = self.p_bx.val();
                }
            }
            if self.found_b.val() {
                // Link the larger root under the smaller.
                self.lo.next = self.ra.q.val();
                self.hi.next = self.rb.val();
                if self.rb.val() < self.ra.q.val() {
                    self.lo.next = self.rb.val();
                    self.hi.next = self.ra.q.val();
                }
                if self.rb.val() != self.ra.q.val() {
                    self.t_we.next = true;
                    self.t_waddr.next = self.hi.val();
                    self.t_wdata.next = self.lo.val();
                }
                self.ra.d.next = self.lo.val();
                if (self.si.q.val() == self.s0.val()) & self.ent.q.val().v1 {
                    self.si.d.next = self.s1.val();
                    self.x.d.next = self.ent.q.val().n1;
                    self.t_raddr.next = self.ent.q.val().n1;
                    self.ph.d.next = self.p_bx.val();
                } else if (self.si.q.val() == self.s1.val()) & self.ent.q.val().v2 {
                    self.si.d.next = self.s2.val();
                    self.x.d.next = self.ent.q.val().n2;
                    self.t_raddr.next = self.ent.q.val().n2;
                    self.ph.d.next = self.p_bx.val();
                } else if (self.si.q.val() == self.s2.val()) & self.ent.q.val().v3 {
                    self.si.d.next = self.si.q.val() + self.one2.val();
                    self.x.d.next = self.ent.q.val().n3;
                    self.t_raddr.next = self.ent.q.val().n3;
                    self.ph.d.next = self.p_bx.val();
                } else {
                    self.cv_eff.next = true;
                    self.cc_eff.next = self.ent.q.val().c;
                    self.cr_eff.next = self.lo.val();
                    self.start_next.next = true;
                }
            }
            if self.start_next.val() {
                self.ph.d.next = self.p_idle.val();
                if !self.empty.val() {
                    self.pop.next = true;
                    self.ent.d.next = self.head.val();
                    if self.cv_eff.val() & (self.head.val().c == self.cc_eff.val()) {
                        self.ra.d.next = self.cr_eff.val();
                        self.si.d.next = self.s0.val();
                        self.x.d.next = self.head.val().n0;
                        self.t_raddr.next = self.head.val().n0;
                        self.ph.d.next = self.p_bx.val();
                    } else {
                        self.x.d.next = self.head.val().c;
                        self.t_raddr.next = self.head.val().c;
                        self.ph.d.next = self.p_ax.val();
                    }
                }
            }
            self.cache_v.d.next = self.cv_eff.val();
            self.cache_c.d.next = self.cc_eff.val();
            self.cache_r.d.next = self.cr_eff.val();
        }
        // ---- Init: T[l] = l for every word.
        if self.mode.q.val() == self.m_init.val() {
            self.t_we.next = true;
            self.t_waddr.next = self.ic.q.val().get_bits::<16>(0);
            self.t_wdata.next = self.ic.q.val().get_bits::<16>(0);
            self.ic.d.next = self.ic.q.val() + self.one17.val();
            if self.ic.q.val() == self.last_word.val() {
                self.mode.d.next = self.m_union.val();
            }
        }
        // ---- Flatten.
        if self.f1v.q.val() {
            self.infl.next = self.one4.val();
        }
        if self.f2v.q.val() {
            self.infl.next = self.infl.val() + self.one4.val();
        }
        if self.mode.q.val() == self.m_flat.val() {
            self.f1v.d.next = false;
            self.f2v.d.next = false;
            // Issue T[l].
            if (self.fl.q.val() <= self.provisional.val())
                & (self.gear_free.val() > self.infl.val())
            {
                self.t_raddr.next = self.fl.q.val().get_bits::<16>(0);
                self.f1v.d.next = true;
                self.f1l.d.next = self.fl.q.val().get_bits::<16>(0);
                self.fl.d.next = self.fl.q.val() + self.one17.val();
            }
            // T[l] arrives: root or look up C[T[l]]; restore T[l] = l.
            if self.f1v.q.val() {
                self.root.next = self.d.val() == self.f1l.q.val();
                self.t_we.next = true;
                self.t_waddr.next = self.f1l.q.val();
                self.t_wdata.next = self.f1l.q.val();
                self.c_ram.read_en.next = true;
                self.c_ram.read_addr.next = self.d.val();
                self.f2v.d.next = true;
                self.f2l.d.next = self.f1l.q.val();
                self.f2root.d.next = self.root.val();
                self.f2rv.d.next = self.ncl.q.val() + self.one16.val();
                self.f2p.d.next = self.d.val();
                if self.root.val() {
                    self.ncl.d.next = self.ncl.q.val() + self.one16.val();
                }
            }
            // C value known: write C[l] and emit it.
            if self.f2v.q.val() {
                self.val.next = self.c_ram.read_data.val();
                if self.f2p.q.val() == (self.f2l.q.val() - self.one16.val()) {
                    self.val.next = self.lastv.q.val();
                }
                if self.f2root.q.val() {
                    self.val.next = self.f2rv.q.val();
                }
                self.c_ram.write_en.next = true;
                self.c_ram.write_addr.next = self.f2l.q.val();
                self.c_ram.write_data.next = self.val.val();
                self.fv.next = true;
                self.lastv.d.next = self.val.val();
            }
            if (self.fl.q.val() > self.provisional.val()) & !self.f1v.q.val() & !self.f2v.q.val() {
                self.mode.d.next = self.m_union.val();
            }
        }
        if self.flat_start.val() {
            self.mode.d.next = self.m_flat.val();
            self.fl.d.next = self.one17.val();
            self.ncl.d.next = self.zero16.val();
            self.f1v.d.next = false;
            self.f2v.d.next = false;
            self.cache_v.d.next = false;
        }
        self.t_ram.read_en.next = true;
        self.t_ram.read_addr.next = self.t_raddr.val();
        self.t_ram.write_en.next = self.t_we.val();
        self.t_ram.write_addr.next = self.t_waddr.val();
        self.t_ram.write_data.next = self.t_wdata.val();
        self.wq_en.d.next = self.t_we.val();
        self.wq_addr.d.next = self.t_waddr.val();
        self.wq_data.d.next = self.t_wdata.val();
        self.rq_addr.d.next = self.t_raddr.val();
        self.fval.next = self.val.val();
        self.init_busy.next = self.mode.q.val() == self.m_init.val();
        self.union_idle.next =
            (self.mode.q.val() == self.m_union.val()) & (self.ph.q.val() == self.p_idle.val());
        self.clusters.next = self.ncl.q.val();
        if self.rst.val() {
            self.mode.d.next = self.m_init.val();
            self.ic.d.next = self.zero17.val();
            self.ph.d.next = self.p_idle.val();
            self.cache_v.d.next = false;
            self.f1v.d.next = false;
            self.f2v.d.next = false;
            self.wq_en.d.next = false;
        }
    }
}
