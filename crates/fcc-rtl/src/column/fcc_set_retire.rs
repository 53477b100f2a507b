//! `FccSetRetire`: the retire of `FccSetWalks`' oldest op (docs/column-core.md,
//! item 3). The oldest op (`o_*`: place 0's) retires once its walks are
//! done and its roots chased, but not in the cycle after a link, when a
//! root recorded before the link may still be the one linked, and a join
//! once its roots' order (`o_lt`, registered) is theirs
//! (`o_lt_ok`) (`retire`).
//! A join that may retire keeps the write port from makes, whether it
//! links or not (`mk_ready`, from flip-flops and place 0 only: it reads no
//! root). A join of two roots links one under the other (`link_*`):
//! `a`'s under `b`'s when `o_under` (a run just started, filed under its
//! neighbours' cluster), else the larger under the smaller; the
//! link is kept for the two cycles after it (`l_*`), for the chase. Each
//! retire gives one event (`ev_*`, registered): a find's root and slot, a
//! join's roots and slots kept and gone, `ev_merged` when it linked.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;

#[derive(LogicBlock, Default)]
pub struct FccSetRetire {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub o_valid: Signal<In, Bit>,
    pub o_join: Signal<In, Bit>,
    pub o_under: Signal<In, Bit>,
    /// Root 1 below root 0, and whether that is the roots' order now.
    pub o_lt: Signal<In, Bit>,
    pub o_lt_ok: Signal<In, Bit>,
    pub o_done0: Signal<In, Bit>,
    pub o_done1: Signal<In, Bit>,
    pub o_root0: Signal<In, Bits<16>>,
    pub o_root1: Signal<In, Bits<16>>,
    pub o_slot0: Signal<In, Bits<SLOT_BITS>>,
    pub o_slot1: Signal<In, Bits<SLOT_BITS>>,
    pub retire: Signal<Out, Bit>,
    pub mk_ready: Signal<Out, Bit>,
    // The link write: `parent[link_gone] = link_keep`.
    pub link_en: Signal<Out, Bit>,
    pub link_gone: Signal<Out, Bits<16>>,
    pub link_keep: Signal<Out, Bits<16>>,
    /// A link in either of the two cycles before, its roots and the slot
    /// kept.
    pub l_valid: Signal<Out, Bit>,
    pub l_gone: Signal<Out, Bits<16>>,
    pub l_keep: Signal<Out, Bits<16>>,
    pub l_keep_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_valid: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_keep: Signal<Out, Bits<16>>,
    pub ev_keep_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_gone: Signal<Out, Bits<16>>,
    pub ev_gone_slot: Signal<Out, Bits<SLOT_BITS>>,
    /// The last link, for the two cycles after it (`l1`, `l2`).
    l1: DFF<Bit>,
    l2: DFF<Bit>,
    lg: DFF<Bits<16>>,
    lk: DFF<Bits<16>>,
    lks: DFF<Bits<SLOT_BITS>>,
    evv: DFF<Bit>,
    evj: DFF<Bit>,
    evm: DFF<Bit>,
    evk: DFF<Bits<16>>,
    evks: DFF<Bits<SLOT_BITS>>,
    evg: DFF<Bits<16>>,
    evgs: DFF<Bits<SLOT_BITS>>,
    fire: Signal<Local, Bit>,
    linking: Signal<Local, Bit>,
    /// A join keeps root 1 (`b`'s).
    keep1: Signal<Local, Bit>,
    /// The roots kept and gone.
    keep: Signal<Local, Bits<16>>,
    keep_slot: Signal<Local, Bits<SLOT_BITS>>,
    gone: Signal<Local, Bits<16>>,
    gone_slot: Signal<Local, Bits<SLOT_BITS>>,
}

impl Logic for FccSetRetire {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, l1, l2, lg, lk, lks, evv, evj, evm, evk, evks, evg, evgs);
        self.fire.next = self.o_valid.val()
            & self.o_done0.val()
            & !self.l1.q.val()
            & (!self.o_join.val() | (self.o_done1.val() & self.o_lt_ok.val()));
        self.retire.next = self.fire.val();
        self.mk_ready.next = !(self.o_valid.val()
            & self.o_done0.val()
            & !self.l1.q.val()
            & self.o_join.val()
            & self.o_done1.val()
            & self.o_lt_ok.val());
        self.linking.next =
            self.fire.val() & self.o_join.val() & (self.o_root0.val() != self.o_root1.val());
        self.keep1.next = self.o_join.val() & (self.o_under.val() | self.o_lt.val());
        self.keep.next = self.o_root0.val();
        self.keep_slot.next = self.o_slot0.val();
        self.gone.next = self.o_root1.val();
        self.gone_slot.next = self.o_slot1.val();
        if self.keep1.val() {
            self.keep.next = self.o_root1.val();
            self.keep_slot.next = self.o_slot1.val();
            self.gone.next = self.o_root0.val();
            self.gone_slot.next = self.o_slot0.val();
        }
        self.link_en.next = self.linking.val();
        self.link_gone.next = self.gone.val();
        self.link_keep.next = self.keep.val();
        self.l1.d.next = self.linking.val();
        self.l2.d.next = self.l1.q.val();
        if self.linking.val() {
            self.lg.d.next = self.gone.val();
            self.lk.d.next = self.keep.val();
            self.lks.d.next = self.keep_slot.val();
        }
        self.l_valid.next = self.l1.q.val() | self.l2.q.val();
        self.l_gone.next = self.lg.q.val();
        self.l_keep.next = self.lk.q.val();
        self.l_keep_slot.next = self.lks.q.val();
        self.evv.d.next = self.fire.val();
        self.evj.d.next = self.o_join.val();
        self.evm.d.next = self.linking.val();
        self.evk.d.next = self.keep.val();
        self.evks.d.next = self.keep_slot.val();
        self.evg.d.next = self.gone.val();
        self.evgs.d.next = self.gone_slot.val();
        self.ev_valid.next = self.evv.q.val();
        self.ev_join.next = self.evj.q.val();
        self.ev_merged.next = self.evm.q.val();
        self.ev_keep.next = self.evk.q.val();
        self.ev_keep_slot.next = self.evks.q.val();
        self.ev_gone.next = self.evg.q.val();
        self.ev_gone_slot.next = self.evgs.q.val();
        if self.rst.val() {
            self.l1.d.next = false;
            self.l2.d.next = false;
            self.evv.d.next = false;
        }
    }
}
