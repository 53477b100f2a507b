//! `fcc_gearbox`: the queue of compact labels between the merge table's
//! flatten pass and the read-back's head beat.
//!
//! Flatten pushes the compact label of provisional label 1, 2, 3, ... in that
//! order (`push_valid`, `push_label`, no back-pressure: the merge table stops
//! when `used` reaches its limit); the head beat pops one (`pop`) or two
//! (`pop` and `pop_two`) a cycle from the front.
//!
//! A ring of eight slots: a push writes the slot `write_slot` points at, a pop
//! only moves `read_slot` and `second_slot` (so the pop decision drives a few
//! pointer bits, not every slot); `front` and `second` are the slots they
//! point at. The new count is chosen among values computed from
//! `count` alone, so no adder follows the pop decision.

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

/// Entries of the gearbox.
pub const GEAR_SLOTS: usize = 8;

#[derive(LogicBlock)]
pub struct FccGearbox {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Start of a read-back: empty the queue.
    pub clear: Signal<In, Bit>,
    pub push_valid: Signal<In, Bit>,
    pub push_label: Signal<In, Bits<16>>,
    /// Pop the front label; with `pop_two`, the front two.
    pub pop: Signal<In, Bit>,
    pub pop_two: Signal<In, Bit>,
    pub front: Signal<Out, Bits<16>>,
    pub second: Signal<Out, Bits<16>>,
    /// Labels waiting (registered).
    pub used: Signal<Out, Bits<4>>,
    /// At least one, at least two labels wait.
    pub has_one: Signal<Out, Bit>,
    pub has_two: Signal<Out, Bit>,
    slots: Vec<DFF<Bits<16>>>,
    count: DFF<Bits<4>>,
    read_slot: DFF<Bits<3>>,
    /// Always `read_slot + 1`: a register of its own, so that each pointer
    /// selects one 16-bit multiplexer (under 64 loads a bit).
    second_slot: DFF<Bits<3>>,
    write_slot: DFF<Bits<3>>,
    pop_one: Signal<Local, Bit>,
    count_inc: Signal<Local, Bits<4>>,
    count_dec: Signal<Local, Bits<4>>,
    count_dec2: Signal<Local, Bits<4>>,
    count_is: Vec<Constant<Bits<4>>>,
    slot_is: Vec<Constant<Bits<3>>>,
    one: Constant<Bits<4>>,
    two: Constant<Bits<4>>,
    one3: Constant<Bits<3>>,
    two3: Constant<Bits<3>>,
    /// What a slot holds after reset: the output register loads slots while
    /// `m_axis_tvalid` is low, so no slot may ever be X (reset-only flows).
    empty_slot: Constant<Bits<16>>,
}

impl FccGearbox {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            push_valid: Default::default(),
            push_label: Default::default(),
            pop: Default::default(),
            pop_two: Default::default(),
            front: Default::default(),
            second: Default::default(),
            used: Default::default(),
            has_one: Default::default(),
            has_two: Default::default(),
            slots: vec_of(GEAR_SLOTS),
            count: Default::default(),
            read_slot: Default::default(),
            write_slot: Default::default(),
            second_slot: Default::default(),
            pop_one: Default::default(),
            count_inc: Default::default(),
            count_dec: Default::default(),
            count_dec2: Default::default(),
            count_is: (0..2).map(|n| kb(n as u64)).collect(),
            slot_is: (0..GEAR_SLOTS).map(|n| kb(n as u64)).collect(),
            one: kb(1),
            two: kb(2),
            one3: kb(1),
            two3: kb(2),
            empty_slot: kb(0),
        }
    }
}

impl Default for FccGearbox {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccGearbox {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, count, read_slot, second_slot, write_slot);
        for i in 0..8 {
            self.slots[i].clock.next = self.clk.val();
            self.slots[i].d.next = self.slots[i].q.val();
        }
        self.used.next = self.count.q.val();
        self.has_one.next = self.count.q.val() != self.count_is[0].val();
        self.has_two.next = (self.count.q.val() != self.count_is[0].val())
            & (self.count.q.val() != self.count_is[1].val());
        // The front two labels.
        self.front.next = self.slots[0].q.val();
        self.second.next = self.slots[0].q.val();
        for i in 0..8 {
            if self.read_slot.q.val() == self.slot_is[i].val() {
                self.front.next = self.slots[i].q.val();
            }
            if self.second_slot.q.val() == self.slot_is[i].val() {
                self.second.next = self.slots[i].q.val();
            }
        }
        // Push behind the labels held, pop from the front.
        if self.push_valid.val() {
            for i in 0..8 {
                if self.write_slot.q.val() == self.slot_is[i].val() {
                    self.slots[i].d.next = self.push_label.val();
                }
            }
            self.write_slot.d.next = self.write_slot.q.val() + self.one3.val();
        }
        if self.pop.val() {
            self.read_slot.d.next = self.read_slot.q.val() + self.one3.val();
            self.second_slot.d.next = self.second_slot.q.val() + self.one3.val();
        }
        if self.pop_two.val() {
            self.read_slot.d.next = self.read_slot.q.val() + self.two3.val();
            self.second_slot.d.next = self.second_slot.q.val() + self.two3.val();
        }
        self.pop_one.next = self.pop.val() & !self.pop_two.val();
        self.count_inc.next = self.count.q.val() + self.one.val();
        self.count_dec.next = self.count.q.val() - self.one.val();
        self.count_dec2.next = self.count.q.val() - self.two.val();
        if self.push_valid.val() {
            self.count.d.next = self.count_inc.val();
        }
        if self.pop_one.val() {
            if self.push_valid.val() {
                self.count.d.next = self.count.q.val();
            } else {
                self.count.d.next = self.count_dec.val();
            }
        }
        if self.pop_two.val() {
            if self.push_valid.val() {
                self.count.d.next = self.count_dec.val();
            } else {
                self.count.d.next = self.count_dec2.val();
            }
        }
        if self.clear.val() | self.rst.val() {
            self.count.d.next = self.count_is[0].val();
            self.read_slot.d.next = self.slot_is[0].val();
            self.second_slot.d.next = self.slot_is[1].val();
            self.write_slot.d.next = self.slot_is[0].val();
        }
        if self.rst.val() {
            for i in 0..8 {
                self.slots[i].d.next = self.empty_slot.val();
            }
        }
    }
}
