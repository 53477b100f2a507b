//! `FccSetReads`: the reads `FccSetWalks`' ops still have to issue, the
//! first word of each side of an op, oldest first, and the choice of this
//! cycle's read when the port is free (`busy` low: no walk goes on).
//!
//! An op taken (`take`: its sequence number `seq`, labels `a` and `b`, a
//! join or not) reads side 0 (`a`) at once if the port is free and no
//! read waits; its other reads wait (side 0 otherwise, a join's side 1
//! always). With reads waiting, the head (`valid`, `head`, from
//! flip-flops) goes at a free cycle, which the caller works out (no
//! output here reads an input: a combinational path through the block
//! would close a loop in the emitted Verilog's ordering). Entries are a shift
//! register, so the read address chooses among flip-flops, and each
//! entry's next value is worked out for `busy` high and low, so that the
//! late `busy` only chooses between them. [`READS`] entries: two an op in
//! flight, so it is never full.

use rust_hdl::prelude::*;

use super::fcc_set_op::SEQ_BITS;
use super::fcc_set_walks::SET_OPS;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::vec_of;

/// Reads waiting at most: two an op in flight.
pub const READS: usize = 2 * SET_OPS;

/// One read to issue: its op's sequence number, its side, the label.
#[derive(Clone, Copy, Debug, PartialEq, Default, LogicStruct)]
pub struct SetRead {
    pub seq: Bits<SEQ_BITS>,
    pub side: Bit,
    pub addr: Bits<16>,
}

#[derive(LogicBlock)]
pub struct FccSetReads {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub busy: Signal<In, Bit>,
    pub take: Signal<In, Bit>,
    pub is_join: Signal<In, Bit>,
    pub seq: Signal<In, Bits<SEQ_BITS>>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    pub valid: Signal<Out, Bit>,
    pub head: Signal<Out, SetRead>,
    v: Vec<FccFanoutReg<Bit>>,
    e: Vec<DFF<SetRead>>,
    ra: Signal<Local, SetRead>,
    rb: Signal<Local, SetRead>,
    /// Entry `i` next: with nothing issued from the list (`stay_*`), with
    /// the head issued (`pop_*`); with the new op's first read issued
    /// (the list empty): its side 1 alone, in entry 0 (`sent_*`).
    stay_v: Vec<Signal<Local, Bit>>,
    stay_e: Vec<Signal<Local, SetRead>>,
    pop_v: Vec<Signal<Local, Bit>>,
    pop_e: Vec<Signal<Local, SetRead>>,
    _n: usize,
}

impl Default for FccSetReads {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            busy: Default::default(),
            take: Default::default(),
            is_join: Default::default(),
            seq: Default::default(),
            a: Default::default(),
            b: Default::default(),
            valid: Default::default(),
            head: Default::default(),
            v: vec_of(READS),
            e: vec_of(READS),
            ra: Default::default(),
            rb: Default::default(),
            stay_v: vec_of(READS),
            stay_e: vec_of(READS),
            pop_v: vec_of(READS),
            pop_e: vec_of(READS),
            _n: READS,
        }
    }
}

impl Logic for FccSetReads {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..(self._n) {
            self.v[i].clock.next = self.clk.val();
            self.e[i].clock.next = self.clk.val();
        }
        self.ra.next.seq = self.seq.val();
        self.ra.next.side = false;
        self.ra.next.addr = self.a.val();
        self.rb.next.seq = self.seq.val();
        self.rb.next.side = true;
        self.rb.next.addr = self.b.val();
        self.valid.next = self.v[0].q.val();
        self.head.next = self.e[0].q.val();
        // Nothing issued from the list: a taken op's two reads after the
        // entries in use (those come first).
        for i in 0..(self._n) {
            self.stay_v[i].next = self.v[i].q.val();
            self.stay_e[i].next = self.e[i].q.val();
        }
        for i in 0..1 {
            if !self.v[i].q.val() {
                self.stay_v[i].next = self.take.val();
                self.stay_e[i].next = self.ra.val();
            }
        }
        for i in 1..2 {
            if self.v[i - 1].q.val() & !self.v[i].q.val() {
                self.stay_v[i].next = self.take.val();
                self.stay_e[i].next = self.ra.val();
            }
            if !self.v[i - 1].q.val() {
                self.stay_v[i].next = self.take.val() & self.is_join.val();
                self.stay_e[i].next = self.rb.val();
            }
        }
        for i in 2..(self._n) {
            if self.v[i - 1].q.val() & !self.v[i].q.val() {
                self.stay_v[i].next = self.take.val();
                self.stay_e[i].next = self.ra.val();
            }
            if self.v[i - 2].q.val() & !self.v[i - 1].q.val() {
                self.stay_v[i].next = self.take.val() & self.is_join.val();
                self.stay_e[i].next = self.rb.val();
            }
        }
        // The head issued: the entries move up, the op's reads after them.
        for i in 0..(self._n - 1) {
            self.pop_v[i].next = self.v[i + 1].q.val();
            self.pop_e[i].next = self.e[i + 1].q.val();
            if self.v[i].q.val() & !self.v[i + 1].q.val() {
                self.pop_v[i].next = self.take.val();
                self.pop_e[i].next = self.ra.val();
            }
        }
        for i in (self._n - 1)..(self._n) {
            self.pop_v[i].next = false;
            self.pop_e[i].next = self.e[i].q.val();
        }
        for i in 1..(self._n) {
            if self.v[i - 1].q.val() & !self.v[i].q.val() {
                self.pop_v[i].next = self.take.val() & self.is_join.val();
                self.pop_e[i].next = self.rb.val();
            }
        }
        // The late choice.
        for i in 0..(self._n) {
            self.v[i].d.next = self.stay_v[i].val();
            self.e[i].d.next = self.stay_e[i].val();
            if !self.busy.val() & self.v[0].q.val() {
                self.v[i].d.next = self.pop_v[i].val();
                self.e[i].d.next = self.pop_e[i].val();
            }
        }
        // The new op's first read issued now (the list empty): its side 1
        // alone waits.
        for i in 0..1 {
            if !self.busy.val() & !self.v[0].q.val() {
                self.v[i].d.next = self.take.val() & self.is_join.val();
                self.e[i].d.next = self.rb.val();
            }
        }
        for i in 1..(self._n) {
            if !self.busy.val() & !self.v[0].q.val() {
                self.v[i].d.next = false;
            }
        }
        if self.rst.val() {
            for i in 0..(self._n) {
                self.v[i].d.next = false;
            }
        }
    }
}
