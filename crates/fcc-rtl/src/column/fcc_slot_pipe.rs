//! `FccSlotPipe`: the records' data path in `FccSlotRecords`. In stage 2
//! the word read is merged with the stage's other word (`FccAccMerge` for
//! the record, `FccHoldsMerge` for the holds, at the op's column),
//! registered for stage 3's write; a close's word is checked
//! (`FccSlotCheck`), and stage 3 says whether it leaves (`leaves`, the
//! record out) and whether a merged word is quiet (`quiet`). The other
//! word is known a cycle ahead: an add's, taken with the op; a merge's
//! gone word, in stage 2 while its kept half is in stage 1; the empty word
//! (the merges' identity) for a close. So the merges start from registers,
//! and so does the check: the close's column less `h` (the column itself
//! at the last column, `last_col`, after which hold 1 is gone) is worked
//! out in stage 1, and the first pixel it names (its word's) is registered.

use rust_hdl::prelude::*;

use super::fcc_acc_merge::FccAccMerge;
use super::fcc_holds_merge::FccHoldsMerge;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_slot_check::FccSlotCheck;
use super::fcc_slot_issue::SlotHalf;
use super::{AccWord, SlotHolds, SlotWord, FIRST_BITS};

#[derive(LogicBlock)]
pub struct FccSlotPipe {
    pub clk: Signal<In, Clock>,
    /// An op is taken this cycle, with its word and column.
    pub take: Signal<In, Bit>,
    pub op_word: Signal<In, SlotWord>,
    pub op_col: Signal<In, Bits<12>>,
    pub half: Signal<In, Bits<3>>,
    /// The frame's last column, `C - 1`: a close there drops hold 1.
    pub last_col: Signal<In, Bits<12>>,
    pub h1: Signal<In, SlotHalf>,
    /// Stage 2: the word read.
    pub word: Signal<In, SlotWord>,
    /// Stage 3: the merged word, whether a close's record leaves, whether
    /// the merged word is quiet.
    pub merged: Signal<Out, SlotWord>,
    pub leaves: Signal<Out, Bit>,
    pub quiet: Signal<Out, Bit>,
    /// Stage 3: the merged lists' link (if the word is written).
    pub link: Signal<Out, Bit>,
    pub link_from: Signal<Out, Bits<16>>,
    pub link_to: Signal<Out, Bits<16>>,
    /// Stage 2's and stage 3's slots, stage 3's half (`FccSlotIssue`).
    pub s2: Signal<In, Bits<SLOT_BITS>>,
    pub v3: Signal<In, Bit>,
    pub h3: Signal<In, SlotHalf>,
    pub s3: Signal<In, Bits<SLOT_BITS>>,
    /// Stage 3's write into the block RAM (its slot is `s3`).
    pub wen: Signal<Out, Bit>,
    pub wdata: Signal<Out, SlotWord>,
    kept: Signal<Local, Bit>,
    /// Stage 2's word, forwarded.
    fw: Signal<Local, SlotWord>,
    /// The writes of the last two cycles.
    w4v: DFF<Bit>,
    w4a: DFF<Bits<SLOT_BITS>>,
    w4d: DFF<SlotWord>,
    w5v: DFF<Bit>,
    w5a: DFF<Bits<SLOT_BITS>>,
    w5d: DFF<SlotWord>,
    mw: Signal<Local, SlotWord>,
    wa: Signal<Local, AccWord>,
    wh: Signal<Local, SlotHolds>,
    /// Stage 1's word's holds (a close's key).
    ah: Signal<Local, SlotHolds>,
    a1: DFF<SlotWord>,
    c1: DFF<Bits<12>>,
    b2: DFF<SlotWord>,
    c2: DFF<Bits<12>>,
    l2: DFF<Bits<13>>,
    f2: DFF<Bits<FIRST_BITS>>,
    k2: DFF<Bit>,
    e2: DFF<Bit>,
    m3: DFF<SlotWord>,
    l3: DFF<Bit>,
    q3: DFF<Bit>,
    lk3: DFF<Bit>,
    lf3: DFF<Bits<16>>,
    lt3: DFF<Bits<16>>,
    acc: FccAccMerge,
    holds: FccHoldsMerge,
    check: FccSlotCheck,
    empty: Constant<SlotWord>,
}

impl Default for FccSlotPipe {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            take: Default::default(),
            s2: Default::default(),
            v3: Default::default(),
            h3: Default::default(),
            s3: Default::default(),
            wen: Default::default(),
            wdata: Default::default(),
            kept: Default::default(),
            fw: Default::default(),
            w4v: Default::default(),
            w4a: Default::default(),
            w4d: Default::default(),
            w5v: Default::default(),
            w5a: Default::default(),
            w5d: Default::default(),
            op_word: Default::default(),
            op_col: Default::default(),
            half: Default::default(),
            last_col: Default::default(),
            h1: Default::default(),
            word: Default::default(),
            merged: Default::default(),
            leaves: Default::default(),
            quiet: Default::default(),
            link: Default::default(),
            link_from: Default::default(),
            link_to: Default::default(),
            mw: Default::default(),
            wa: Default::default(),
            wh: Default::default(),
            ah: Default::default(),
            a1: Default::default(),
            c1: Default::default(),
            b2: Default::default(),
            c2: Default::default(),
            l2: Default::default(),
            f2: Default::default(),
            k2: Default::default(),
            e2: Default::default(),
            m3: Default::default(),
            l3: Default::default(),
            q3: Default::default(),
            lk3: Default::default(),
            lf3: Default::default(),
            lt3: Default::default(),
            acc: Default::default(),
            holds: Default::default(),
            check: Default::default(),
            empty: Constant::new(SlotWord::empty()),
        }
    }
}

impl Logic for FccSlotPipe {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, a1, c1, b2, c2, l2, f2, k2, e2, m3, l3, q3, lk3, lf3, lt3, w4v, w4a, w4d,
            w5v, w5a, w5d
        );
        // Stage 3's write: a kept word (an add's, a merge's kept half), or
        // the empty word (a merge's gone half, a record that leaves).
        self.kept.next = (self.h3.val() == SlotHalf::Add) | (self.h3.val() == SlotHalf::Keep);
        self.wen.next =
            self.v3.val() & (self.kept.val() | (self.h3.val() == SlotHalf::Gone) | self.l3.q.val());
        self.wdata.next = self.empty.val();
        if self.kept.val() {
            self.wdata.next = self.m3.q.val();
        }
        self.w4v.d.next = self.wen.val();
        self.w4a.d.next = self.s3.val();
        self.w4d.d.next = self.wdata.val();
        self.w5v.d.next = self.w4v.q.val();
        self.w5a.d.next = self.w4a.q.val();
        self.w5d.d.next = self.w4d.q.val();
        // Stage 2's word: the read, or the latest write to its slot since
        // the read was issued (this cycle's and the last two's: the read
        // missed them).
        self.fw.next = self.word.val();
        if self.w5v.q.val() & (self.w5a.q.val() == self.s2.val()) {
            self.fw.next = self.w5d.q.val();
        }
        if self.w4v.q.val() & (self.w4a.q.val() == self.s2.val()) {
            self.fw.next = self.w4d.q.val();
        }
        if self.wen.val() & (self.s3.val() == self.s2.val()) {
            self.fw.next = self.wdata.val();
        }
        // Stage 1: the op's word and column; the other word of stage 2.
        self.a1.d.next = self.op_word.val();
        if self.take.val() {
            self.c1.d.next = self.op_col.val();
        }
        self.c2.d.next = self.c1.q.val();
        self.l2.d.next = bit_cast::<13, 12>(self.c1.q.val()) - bit_cast::<13, 3>(self.half.val());
        // Spec §9.2: no later column holds a cluster after the last one.
        if self.c1.q.val() == self.last_col.val() {
            self.l2.d.next = bit_cast::<13, 12>(self.c1.q.val());
        }
        self.ah.next = self.a1.q.val().holds;
        self.f2.d.next = self.ah.val().first;
        self.k2.d.next = (self.h1.val() == SlotHalf::Close) | (self.h1.val() == SlotHalf::End);
        self.e2.d.next = self.h1.val() == SlotHalf::End;
        self.b2.d.next = self.empty.val();
        if self.h1.val() == SlotHalf::Add {
            self.b2.d.next = self.a1.q.val();
        }
        if self.h1.val() == SlotHalf::Keep {
            self.b2.d.next = self.fw.val();
        }
        // Stage 2: the merges and the check.
        self.wa.next = self.fw.val().acc;
        self.wh.next = self.fw.val().holds;
        self.acc.a.next = self.wa.val();
        self.acc.b.next = self.b2.q.val().acc;
        self.holds.a.next = self.wh.val();
        self.holds.b.next = self.b2.q.val().holds;
        self.holds.col.next = self.c2.q.val();
        self.mw.next.acc = self.acc.out.val();
        self.mw.next.holds = self.holds.out.val();
        self.m3.d.next = self.mw.val();
        self.q3.d.next = self.holds.quiet.val();
        self.lk3.d.next = self.holds.link.val();
        self.lf3.d.next = self.holds.link_from.val();
        self.lt3.d.next = self.holds.link_to.val();
        self.check.has.next = self.wa.val().points.any();
        self.check.last.next = self.wa.val().max_col;
        self.check.open.next = self.wh.val().open;
        self.check.ring.next = self.wh.val().ring;
        self.check.quiet.next = self.wh.val().quiet;
        self.check.col.next = self.c2.q.val();
        self.check.lim.next = self.l2.q.val();
        self.check.frame_end.next = self.e2.q.val();
        self.check.first.next = self.wh.val().first;
        self.check.key.next = self.f2.q.val();
        self.l3.d.next = self.k2.q.val() & self.check.leaves.val();
        // Stage 3.
        self.merged.next = self.m3.q.val();
        self.leaves.next = self.l3.q.val();
        self.quiet.next = self.q3.q.val();
        self.link.next = self.lk3.q.val();
        self.link_from.next = self.lf3.q.val();
        self.link_to.next = self.lt3.q.val();
    }
}
