//! `fcc_merge_table`: the exact equivalence table.
//!
//! The parent table `T` (block RAM, `2^B` words) is a union-find forest in
//! which every parent is smaller than its child, so a tree's root is the
//! smallest provisional label of its component. A second one-bit table `R`
//! beside it says whether a label is a root, so a read tells at once whether
//! the walk is over. Reads take two cycles (`FccRam`).
//!
//! * Init (after every reset): every label becomes a root, one per cycle.
//! * Union (while pixels stream): a join (a, b) finds the roots of a and b in
//!   two *slots* that own the table's read port on alternate cycles (even and
//!   odd), so both walks advance together, each at one step per two cycles:
//!   the word read for a slot arrives exactly when its turn comes back, and
//!   the next address is the word's parent (one LUT from the RAM's output
//!   register). When both roots are known, the larger is linked under the
//!   smaller, and the next join starts in the same cycle. The root of the
//!   previous join's `a` side is kept: a join with the same `a` (`jsame`)
//!   starts with that side done (its slot takes the kept root one cycle later,
//!   long before the other side can finish). A read issued in the cycle of a link write to
//!   the same word gets the written word forwarded. No path compression: the
//!   joins arrive with representatives that are close to their roots.
//! * Flatten (frame end): for l = 1 .. P in ascending order, a root gets the
//!   next compact number, otherwise `C[l] = C[T[l]]` (`T[l] < l` is already
//!   final; the two labels before l are forwarded from registers). This
//!   numbers components in the raster order of their first pixel, exactly as
//!   the golden model. Each compact label leaves on the `fv`/`fval` stream in
//!   ascending `l`, at most as many in flight as the label updater has room
//!   for, and every label becomes a root again for the next frame.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_ram::FccRam;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccMergeTable {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    // Joins from the sort network.
    pub jv: Signal<In, Bit>,
    pub ja: Signal<In, Bits<16>>,
    pub jb: Signal<In, Bits<16>>,
    pub jsame: Signal<In, Bit>,
    pub jtake: Signal<Out, Bit>,
    // Control.
    pub init_busy: Signal<Out, Bit>,
    /// No join held or in progress.
    pub union_idle: Signal<Out, Bit>,
    pub flat_start: Signal<In, Bit>,
    pub provisional: Signal<In, Bits<17>>,
    // Compact labels in ascending provisional order.
    pub fv: Signal<Out, Bit>,
    pub fval: Signal<Out, Bits<16>>,
    /// Compact labels waiting in the label updater's gearbox (registered).
    pub gear_used: Signal<In, Bits<4>>,
    pub clusters: Signal<Out, Bits<16>>,
    t_ram: FccRam<Bits<16>, 16>,
    r_ram: FccRam<Bit, 16>,
    c_ram: FccRam<Bits<16>, 16>,
    mode: DFF<Bits<2>>,
    ic: DFF<Bits<17>>,
    // Next join (taken from the sort network when empty).
    njv: DFF<Bit>,
    nja: DFF<Bits<16>>,
    njb: DFF<Bits<16>>,
    njs: DFF<Bit>,
    // The join in progress: the two slots.
    busy: DFF<Bit>,
    par: DFF<Bit>,
    x0: DFF<Bits<16>>,
    x1: DFF<Bits<16>>,
    d0: DFF<Bit>,
    d1: DFF<Bit>,
    second: DFF<Bit>,
    ldc: DFF<Bit>,
    pend: DFF<Bits<16>>,
    cr: DFF<Bits<16>>,
    i1v: DFF<Bit>,
    i2v: DFF<Bit>,
    // Forwarding of a link write to a read issued in the same cycle.
    wq_en: DFF<Bit>,
    wq_addr: DFF<Bits<16>>,
    wq_data: DFF<Bits<16>>,
    wq2_data: DFF<Bits<16>>,
    rq: DFF<Bits<16>>,
    rq_en: DFF<Bit>,
    fw: DFF<Bit>,
    // Flatten pipeline.
    fl: DFF<Bits<17>>,
    infl: DFF<Bits<4>>,
    room: DFF<Bit>,
    more: DFF<Bit>,
    f1v: DFF<Bit>,
    f1l: DFF<Bits<16>>,
    f2v: DFF<Bit>,
    f2l: DFF<Bits<16>>,
    lm1: DFF<Bits<16>>,
    lm2: DFF<Bits<16>>,
    f3v: DFF<Bit>,
    f3l: DFF<Bits<16>>,
    f3root: DFF<Bit>,
    f3rv: DFF<Bits<16>>,
    f3d1: DFF<Bit>,
    f3d2: DFF<Bit>,
    f4v: DFF<Bit>,
    f4l: DFF<Bits<16>>,
    f4root: DFF<Bit>,
    f4rv: DFF<Bits<16>>,
    f4d1: DFF<Bit>,
    f4d2: DFF<Bit>,
    ncl: DFF<Bits<16>>,
    lastv: DFF<Bits<16>>,
    lastv2: DFF<Bits<16>>,
    // Combinational.
    root: Signal<Local, Bit>,
    parent: Signal<Local, Bits<16>>,
    cont: Signal<Local, Bit>,
    found: Signal<Local, Bit>,
    sd: Signal<Local, Bit>,
    od: Signal<Local, Bit>,
    link: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    lo: Signal<Local, Bits<16>>,
    hi: Signal<Local, Bits<16>>,
    re: Signal<Local, Bit>,
    t_we: Signal<Local, Bit>,
    t_waddr: Signal<Local, Bits<16>>,
    t_wdata: Signal<Local, Bits<16>>,
    r_wdata: Signal<Local, Bit>,
    raddr: Signal<Local, Bits<16>>,
    issue: Signal<Local, Bit>,
    val: Signal<Local, Bits<16>>,
    m_union: Constant<Bits<2>>,
    m_init: Constant<Bits<2>>,
    m_flat: Constant<Bits<2>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    two16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
    zero4: Constant<Bits<4>>,
    six4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    last_word: Constant<Bits<17>>,
}

impl FccMergeTable {
    pub fn new(p: &FccParams) -> Self {
        let words = 1usize << p.label_bits;
        let b = p.label_bits as usize;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            jv: Default::default(),
            ja: Default::default(),
            jb: Default::default(),
            jsame: Default::default(),
            jtake: Default::default(),
            init_busy: Default::default(),
            union_idle: Default::default(),
            flat_start: Default::default(),
            provisional: Default::default(),
            fv: Default::default(),
            fval: Default::default(),
            gear_used: Default::default(),
            clusters: Default::default(),
            t_ram: FccRam::with_stored_bits(words, b),
            r_ram: FccRam::new(words),
            c_ram: FccRam::with_stored_bits(words, b),
            mode: Default::default(),
            ic: Default::default(),
            njv: Default::default(),
            nja: Default::default(),
            njb: Default::default(),
            njs: Default::default(),
            busy: Default::default(),
            par: Default::default(),
            x0: Default::default(),
            x1: Default::default(),
            d0: Default::default(),
            d1: Default::default(),
            second: Default::default(),
            ldc: Default::default(),
            pend: Default::default(),
            cr: Default::default(),
            i1v: Default::default(),
            i2v: Default::default(),
            wq_en: Default::default(),
            wq_addr: Default::default(),
            wq_data: Default::default(),
            wq2_data: Default::default(),
            rq: Default::default(),
            rq_en: Default::default(),
            fw: Default::default(),
            fl: Default::default(),
            infl: Default::default(),
            room: Default::default(),
            more: Default::default(),
            f1v: Default::default(),
            f1l: Default::default(),
            f2v: Default::default(),
            f2l: Default::default(),
            lm1: Default::default(),
            lm2: Default::default(),
            f3v: Default::default(),
            f3l: Default::default(),
            f3root: Default::default(),
            f3rv: Default::default(),
            f3d1: Default::default(),
            f3d2: Default::default(),
            f4v: Default::default(),
            f4l: Default::default(),
            f4root: Default::default(),
            f4rv: Default::default(),
            f4d1: Default::default(),
            f4d2: Default::default(),
            ncl: Default::default(),
            lastv: Default::default(),
            lastv2: Default::default(),
            root: Default::default(),
            parent: Default::default(),
            cont: Default::default(),
            found: Default::default(),
            sd: Default::default(),
            od: Default::default(),
            link: Default::default(),
            start: Default::default(),
            lo: Default::default(),
            hi: Default::default(),
            re: Default::default(),
            t_we: Default::default(),
            t_waddr: Default::default(),
            t_wdata: Default::default(),
            r_wdata: Default::default(),
            raddr: Default::default(),
            issue: Default::default(),
            val: Default::default(),
            m_union: kb(0),
            m_init: kb(1),
            m_flat: kb(2),
            zero16: kb(0),
            one16: kb(1),
            two16: kb(2),
            zero17: kb(0),
            one17: kb(1),
            zero4: kb(0),
            six4: kb(6),
            one4: kb(1),
            last_word: kb(words as u64 - 1),
        }
    }
}

impl Logic for FccMergeTable {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, mode, ic, njv, nja, njb, njs, busy, par, x0, x1, d0, d1, second, ldc, pend,
            cr, i1v, i2v, wq_en, wq_addr, wq_data, wq2_data, rq, rq_en, fw, fl, infl, room, more,
            f1v, f1l, f2v, f2l, lm1, lm2, f3v, f3l, f3root, f3rv, f3d1, f3d2, f4v, f4l, f4root,
            f4rv, f4d1, f4d2, ncl, lastv, lastv2
        );
        self.t_ram.clk.next = self.clk.val();
        self.r_ram.clk.next = self.clk.val();
        self.c_ram.clk.next = self.clk.val();
        // ---- The word read two cycles ago, with a same-cycle link write forwarded.
        self.root.next = self.r_ram.read_data.val();
        self.parent.next = self.t_ram.read_data.val();
        if self.fw.q.val() {
            // A forwarded word is always a link (a parent, never 0).
            self.root.next = false;
            self.parent.next = self.wq2_data.q.val();
        }
        // The two roots, ordered.
        self.lo.next = self.x0.q.val();
        self.hi.next = self.x1.q.val();
        if self.x1.q.val() < self.x0.q.val() {
            self.lo.next = self.x1.q.val();
            self.hi.next = self.x0.q.val();
        }
        self.par.d.next = !self.par.q.val();
        self.t_we.next = false;
        self.t_waddr.next = self.hi.val();
        self.t_wdata.next = self.lo.val();
        self.r_wdata.next = false;
        self.re.next = false;
        self.start.next = false;
        self.link.next = false;
        self.cont.next = false;
        self.found.next = false;
        self.jtake.next = self.jv.val() & !self.njv.q.val();
        if self.jtake.val() {
            self.njv.d.next = true;
            self.nja.d.next = self.ja.val();
            self.njb.d.next = self.jb.val();
            self.njs.d.next = self.jsame.val();
        }
        // The slot whose turn it is (`par`) and the other one.
        self.sd.next = self.d0.q.val();
        self.od.next = self.d1.q.val();
        if self.par.q.val() {
            self.sd.next = self.d1.q.val();
            self.od.next = self.d0.q.val();
        }
        // The next address when no walk continues: a join's first read, or
        // the second read of the join started in the previous cycle.
        self.pend.d.next = self.nja.q.val();
        if self.njs.q.val() {
            self.pend.d.next = self.njb.q.val();
        }
        if self.jtake.val() {
            self.pend.d.next = self.ja.val();
            if self.jsame.val() {
                self.pend.d.next = self.jb.val();
            }
        }
        self.second.d.next = false;
        self.ldc.d.next = false;
        // ---- Union.
        if self.mode.q.val() == self.m_union.val() {
            self.cont.next = self.i2v.q.val() & !self.root.val();
            self.found.next = self.i2v.q.val() & self.root.val();
            self.link.next = self.busy.q.val() & (self.sd.val() | self.found.val()) & self.od.val();
            if self.cont.val() {
                // The walk goes on in this slot: read the parent now.
                self.re.next = true;
                if self.par.q.val() {
                    self.x1.d.next = self.parent.val();
                } else {
                    self.x0.d.next = self.parent.val();
                }
            }
            if self.found.val() {
                if self.par.q.val() {
                    self.d1.d.next = true;
                } else {
                    self.d0.d.next = true;
                }
            }
            if self.second.q.val() {
                self.re.next = true;
            }
            if self.link.val() {
                self.t_we.next = self.x0.q.val() != self.x1.q.val();
                self.cr.d.next = self.lo.val();
                self.busy.d.next = false;
            }
            // A join that started with the kept root: its slot takes it now.
            if self.ldc.q.val() {
                if self.par.q.val() {
                    self.x1.d.next = self.cr.q.val();
                } else {
                    self.x0.d.next = self.cr.q.val();
                }
            }
            self.start.next = self.njv.q.val() & (!self.busy.q.val() | self.link.val());
            if self.start.val() {
                self.njv.d.next = self.jtake.val();
                self.busy.d.next = true;
                self.re.next = true;
                // This slot reads the first word now; the other slot either
                // holds the cached root of `a` or reads `b` next cycle.
                if self.par.q.val() {
                    self.d1.d.next = false;
                    self.x1.d.next = self.pend.q.val();
                    self.d0.d.next = self.njs.q.val();
                    self.x0.d.next = self.njb.q.val();
                } else {
                    self.d0.d.next = false;
                    self.x0.d.next = self.pend.q.val();
                    self.d1.d.next = self.njs.q.val();
                    self.x1.d.next = self.njb.q.val();
                }
                self.ldc.d.next = self.njs.q.val();
                if !self.njs.q.val() {
                    self.second.d.next = true;
                    self.pend.d.next = self.njb.q.val();
                }
            }
        }
        // ---- Init: every word a root.
        if self.mode.q.val() == self.m_init.val() {
            self.t_we.next = true;
            self.t_waddr.next = self.ic.q.val().get_bits::<16>(0);
            self.r_wdata.next = true;
            self.ic.d.next = self.ic.q.val() + self.one17.val();
            if self.ic.q.val() == self.last_word.val() {
                self.mode.d.next = self.m_union.val();
            }
        }
        // ---- Flatten.
        // Room in the gearbox, one cycle old: labels in flight plus labels
        // waiting grow by at most one per cycle.
        self.room.d.next = (self.infl.q.val() + self.gear_used.val()) <= self.six4.val();
        self.issue.next =
            (self.mode.q.val() == self.m_flat.val()) & self.more.q.val() & self.room.q.val();
        // Labels left to issue after this cycle (fl <= P), from registers.
        self.more.d.next = self.fl.q.val() <= self.provisional.val();
        if self.issue.val() {
            self.more.d.next = self.fl.q.val() < self.provisional.val();
        }
        self.f1v.d.next = self.issue.val();
        self.f1l.d.next = self.fl.q.val().get_bits::<16>(0);
        self.f2v.d.next = self.f1v.q.val();
        self.f2l.d.next = self.f1l.q.val();
        self.lm1.d.next = self.f1l.q.val() - self.one16.val();
        self.lm2.d.next = self.f1l.q.val() - self.two16.val();
        if self.issue.val() {
            self.re.next = true;
            self.fl.d.next = self.fl.q.val() + self.one17.val();
        }
        if self.mode.q.val() == self.m_flat.val() {
            self.pend.d.next = self.fl.q.val().get_bits::<16>(0);
            if self.issue.val() {
                self.pend.d.next = self.fl.q.val().get_bits::<16>(0) + self.one16.val();
            }
        }
        // T[l] arrives: a root, or look up C[T[l]]; T[l] becomes a root again.
        self.c_ram.read_en.next = self.f2v.q.val();
        self.c_ram.read_addr.next = self.parent.val();
        self.f3v.d.next = self.f2v.q.val();
        self.f3l.d.next = self.f2l.q.val();
        self.f3root.d.next = self.root.val();
        self.f3rv.d.next = self.ncl.q.val() + self.one16.val();
        self.f3d1.d.next = self.parent.val() == self.lm1.q.val();
        self.f3d2.d.next = self.parent.val() == self.lm2.q.val();
        if self.f2v.q.val() {
            self.t_we.next = true;
            self.t_waddr.next = self.f2l.q.val();
            self.r_wdata.next = true;
            if self.root.val() {
                self.ncl.d.next = self.ncl.q.val() + self.one16.val();
            }
        }
        self.f4v.d.next = self.f3v.q.val();
        self.f4l.d.next = self.f3l.q.val();
        self.f4root.d.next = self.f3root.q.val();
        self.f4rv.d.next = self.f3rv.q.val();
        self.f4d1.d.next = self.f3d1.q.val();
        self.f4d2.d.next = self.f3d2.q.val();
        // C value known: write C[l] and emit it.
        self.val.next = self.c_ram.read_data.val();
        if self.f4d2.q.val() {
            self.val.next = self.lastv2.q.val();
        }
        if self.f4d1.q.val() {
            self.val.next = self.lastv.q.val();
        }
        if self.f4root.q.val() {
            self.val.next = self.f4rv.q.val();
        }
        self.c_ram.write_en.next = self.f4v.q.val();
        self.c_ram.write_addr.next = self.f4l.q.val();
        self.c_ram.write_data.next = self.val.val();
        self.fv.next = self.f4v.q.val();
        self.fval.next = self.val.val();
        if self.f4v.q.val() {
            self.lastv.d.next = self.val.val();
            self.lastv2.d.next = self.lastv.q.val();
        }
        // Labels between issue and emission.
        if self.issue.val() & !self.f4v.q.val() {
            self.infl.d.next = self.infl.q.val() + self.one4.val();
        }
        if !self.issue.val() & self.f4v.q.val() {
            self.infl.d.next = self.infl.q.val() - self.one4.val();
        }
        if (self.mode.q.val() == self.m_flat.val())
            & !self.more.q.val()
            & (self.infl.q.val() == self.zero4.val())
        {
            self.mode.d.next = self.m_union.val();
        }
        if self.flat_start.val() {
            self.mode.d.next = self.m_flat.val();
            self.fl.d.next = self.one17.val();
            self.pend.d.next = self.one16.val();
            self.ncl.d.next = self.zero16.val();
            self.infl.d.next = self.zero4.val();
            self.more.d.next = self.provisional.val() != self.zero17.val();
        }
        // ---- The table's ports and the forwarding registers.
        self.raddr.next = self.pend.q.val();
        if self.cont.val() {
            self.raddr.next = self.parent.val();
        }
        self.t_ram.read_en.next = self.re.val();
        self.t_ram.read_addr.next = self.raddr.val();
        self.t_ram.write_en.next = self.t_we.val();
        self.t_ram.write_addr.next = self.t_waddr.val();
        self.t_ram.write_data.next = self.t_wdata.val();
        self.r_ram.read_en.next = self.re.val();
        self.r_ram.read_addr.next = self.raddr.val();
        self.r_ram.write_en.next = self.t_we.val();
        self.r_ram.write_addr.next = self.t_waddr.val();
        self.r_ram.write_data.next = self.r_wdata.val();
        self.i1v.d.next = self.re.val() & (self.mode.q.val() == self.m_union.val());
        self.i2v.d.next = self.i1v.q.val();
        self.wq_en.d.next = self.t_we.val();
        self.wq_addr.d.next = self.t_waddr.val();
        self.wq_data.d.next = self.t_wdata.val();
        self.wq2_data.d.next = self.wq_data.q.val();
        self.rq.d.next = self.raddr.val();
        self.rq_en.d.next = self.re.val();
        self.fw.d.next =
            self.wq_en.q.val() & self.rq_en.q.val() & (self.wq_addr.q.val() == self.rq.q.val());
        self.init_busy.next = self.mode.q.val() == self.m_init.val();
        self.union_idle.next = !self.busy.q.val() & !self.njv.q.val();
        self.clusters.next = self.ncl.q.val();
        if self.rst.val() {
            self.mode.d.next = self.m_init.val();
            self.ic.d.next = self.zero17.val();
            self.njv.d.next = false;
            self.busy.d.next = false;
            self.second.d.next = false;
            self.ldc.d.next = false;
            self.room.d.next = false;
            self.i1v.d.next = false;
            self.i2v.d.next = false;
            self.wq_en.d.next = false;
            self.rq_en.d.next = false;
            self.fw.d.next = false;
            self.f1v.d.next = false;
            self.f2v.d.next = false;
            self.f3v.d.next = false;
            self.f4v.d.next = false;
            self.infl.d.next = self.zero4.val();
            // The slot phase has a reset of its own: nothing may rely on a
            // flip-flop's power-up value (4-state simulation, reset-only flows).
            self.par.d.next = false;
        }
    }
}
