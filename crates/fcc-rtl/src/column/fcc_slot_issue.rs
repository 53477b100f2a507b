//! `FccSlotIssue`: the order of `FccSlotRecords`' ops and their stages
//! (docs/column-core.md, item 3). An op is taken one a cycle (a merge:
//! two); it reads its record (a merge: the gone record, then the kept one
//! in the next cycle, two halves), and its halves move through three
//! stages: 1, the block RAM's read; 2, the word shows and is merged; 3,
//! the merged word is written (or, for a close, goes out). A read misses
//! the writes of the cycle it is issued in and the two after it: ops on a
//! slot still in the stages do not wait, `FccSlotPipe` forwards those
//! writes into stage 2 instead (`s2`: stage 2's slot).
//!
//! After a reset no op is taken for `2^SLOT_BITS` cycles (`clearing`):
//! the write port empties every slot (`sweep`), so that the block RAM
//! needs no initial contents and a slot never read stale.

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use crate::fcc_fanout_reg::FccFanoutReg;

/// An op on the record store.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum SlotOp {
    /// A run's accumulator added to its cluster's record.
    Add,
    /// Two clusters' records as one: `other`'s into `slot`'s.
    Merge,
    /// A cluster's record out if nothing holds it after the op's column
    /// (`FccSlotCheck`); its slot empty after.
    Close,
    /// At the frame end: a cluster's record out, whatever holds it.
    End,
    /// At the frame end: the slot reported (`q_*`) if it has a record,
    /// whatever holds it; nothing written.
    Peek,
}

/// What a read is for, as it moves through the stages.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum SlotHalf {
    Add,
    /// A merge's record that goes (read first).
    Gone,
    /// A merge's record that stays (read second, the gone one beside it).
    Keep,
    Close,
    End,
    Peek,
}

#[derive(LogicBlock)]
pub struct FccSlotIssue {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_kind: Signal<In, SlotOp>,
    pub op_slot: Signal<In, Bits<SLOT_BITS>>,
    pub op_other: Signal<In, Bits<SLOT_BITS>>,
    pub op_take: Signal<Out, Bit>,
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<SLOT_BITS>>,
    // The stages' halves: stage 1's (what for) and stage 3's.
    pub h1: Signal<Out, SlotHalf>,
    /// Stage 2's slot (its read shows: `FccSlotPipe` forwards the words
    /// written since the read was issued).
    pub s2: Signal<Out, Bits<SLOT_BITS>>,
    pub v3: Signal<Out, Bit>,
    pub h3: Signal<Out, SlotHalf>,
    pub s3: Signal<Out, Bits<SLOT_BITS>>,
    /// The slots are being emptied, `sweep` this cycle.
    pub clearing: Signal<Out, Bit>,
    pub sweep: Signal<Out, Bits<SLOT_BITS>>,
    /// No op in flight, none held back.
    pub idle: Signal<Out, Bit>,
    take: Signal<Local, Bit>,
    /// A merge's kept record is read this cycle.
    second: DFF<Bit>,
    keep: DFF<Bits<SLOT_BITS>>,
    sv1: DFF<Bit>,
    sh1: DFF<SlotHalf>,
    ss1: DFF<Bits<SLOT_BITS>>,
    sv2: DFF<Bit>,
    sh2: DFF<SlotHalf>,
    ss2: DFF<Bits<SLOT_BITS>>,
    sv3: DFF<Bit>,
    sh3: DFF<SlotHalf>,
    ss3: DFF<Bits<SLOT_BITS>>,
    clear: FccFanoutReg<Bit>,
    next: DFF<Bits<SLOT_BITS>>,
    zero: Constant<Bits<SLOT_BITS>>,
    one: Constant<Bits<SLOT_BITS>>,
    last: Constant<Bits<SLOT_BITS>>,
}

impl Default for FccSlotIssue {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            op_valid: Default::default(),
            op_kind: Default::default(),
            op_slot: Default::default(),
            op_other: Default::default(),
            op_take: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            h1: Default::default(),
            s2: Default::default(),
            v3: Default::default(),
            h3: Default::default(),
            s3: Default::default(),
            clearing: Default::default(),
            sweep: Default::default(),
            idle: Default::default(),
            take: Default::default(),
            second: Default::default(),
            keep: Default::default(),
            sv1: Default::default(),
            sh1: Default::default(),
            ss1: Default::default(),
            sv2: Default::default(),
            sh2: Default::default(),
            ss2: Default::default(),
            sv3: Default::default(),
            sh3: Default::default(),
            ss3: Default::default(),
            clear: Default::default(),
            next: Default::default(),
            zero: Constant::new(0_u64.to_bits()),
            one: Constant::new(1_u64.to_bits()),
            last: Constant::new(((1_u64 << SLOT_BITS) - 1).to_bits()),
        }
    }
}

impl Logic for FccSlotIssue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clk, second, keep, sv1, sh1, ss1, sv2, sh2, ss2, sv3, sh3, ss3, clear, next
        );
        self.take.next =
            self.op_valid.val() & !self.second.q.val() & !self.clear.q.val() & !self.rst.val();
        self.op_take.next = self.take.val();
        self.read_en.next = self.take.val() | self.second.q.val();
        self.read_addr.next = self.op_slot.val();
        self.sh1.d.next = SlotHalf::Add;
        if self.op_kind.val() == SlotOp::Merge {
            self.read_addr.next = self.op_other.val();
            self.sh1.d.next = SlotHalf::Gone;
        }
        if self.op_kind.val() == SlotOp::Close {
            self.sh1.d.next = SlotHalf::Close;
        }
        if self.op_kind.val() == SlotOp::End {
            self.sh1.d.next = SlotHalf::End;
        }
        if self.op_kind.val() == SlotOp::Peek {
            self.sh1.d.next = SlotHalf::Peek;
        }
        if self.second.q.val() {
            self.read_addr.next = self.keep.q.val();
            self.sh1.d.next = SlotHalf::Keep;
        }
        self.sv1.d.next = self.take.val() | self.second.q.val();
        self.ss1.d.next = self.read_addr.val();
        self.second.d.next = self.take.val() & (self.op_kind.val() == SlotOp::Merge);
        self.keep.d.next = self.op_slot.val();
        self.sv2.d.next = self.sv1.q.val();
        self.sh2.d.next = self.sh1.q.val();
        self.ss2.d.next = self.ss1.q.val();
        self.sv3.d.next = self.sv2.q.val();
        self.sh3.d.next = self.sh2.q.val();
        self.ss3.d.next = self.ss2.q.val();
        if self.clear.q.val() {
            self.next.d.next = self.next.q.val() + self.one.val();
            if self.next.q.val() == self.last.val() {
                self.clear.d.next = false;
            }
        }
        if self.rst.val() {
            self.clear.d.next = true;
            self.next.d.next = self.zero.val();
            self.second.d.next = false;
            self.sv1.d.next = false;
            self.sv2.d.next = false;
            self.sv3.d.next = false;
        }
        self.h1.next = self.sh1.q.val();
        self.s2.next = self.ss2.q.val();
        self.v3.next = self.sv3.q.val();
        self.h3.next = self.sh3.q.val();
        self.s3.next = self.ss3.q.val();
        self.clearing.next = self.clear.q.val();
        self.sweep.next = self.next.q.val();
        self.idle.next = !(self.sv1.q.val()
            | self.sv2.q.val()
            | self.sv3.q.val()
            | self.second.q.val()
            | self.clear.q.val());
    }
}
