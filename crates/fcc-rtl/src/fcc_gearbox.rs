//! `fcc_gearbox`: the queue of compact labels between the merge table's
//! flatten pass and the read-back's head beat.
//!
//! Flatten pushes the compact label of provisional label 1, 2, 3, ... in that
//! order (`push_valid`, `push_label`, no back-pressure: the merge table stops
//! when `used` reaches its limit); the head beat pops one (`pop`) or two
//! (`pop` and `pop_two`) a cycle from the front.
//!
//! A ring of eight slots: a push writes the slot `write_slot` points at, a pop
//! moves the read pointers. `front` and `second` come from registers
//! (`front_label`, `second_label`) that always equal the slots at `read_slot`
//! and `read_slot + 1`, so the beat assembly reads flip-flops, not the ring's
//! 8:1 read multiplexer; the ring is read at `read_slot + 2` and `+ 3` to
//! refill them when one or two labels leave, and a label pushed into one of
//! the four front slots is forwarded into them (a clear leaves them as they
//! are: what they hold is only read while labels wait, and the first label
//! pushed after a clear is forwarded into `front_label`). The new count is chosen among
//! values computed from `count` alone, so no adder follows the pop decision.

use rust_hdl::prelude::*;

use crate::fcc_fanout_reg::FccFanoutReg;
use crate::fcc_keep_reg::FccKeepReg;
use crate::types::{kb, vec_of};

/// Entries of the gearbox.
pub const GEAR_SLOTS: usize = 8;

#[derive(LogicBlock)]
pub struct FccGearbox {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Copies of `rst` for slots 0 .. 3 and 4 .. 7 (64 loads each).
    pub rst_low_slots: Signal<In, Bit>,
    pub rst_high_slots: Signal<In, Bit>,
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
    /// `has_one` and `has_two` again, from a kept copy of the count: the
    /// beat assembly's copy of the pop decision reads these, the label
    /// updater's gearbox-side copy the ones above (`fcc_pop_decision`).
    pub has_one_copy: Signal<Out, Bit>,
    pub has_two_copy: Signal<Out, Bit>,
    slots: Vec<DFF<Bits<16>>>,
    /// Kept, as its copy is: neither is merged into the other.
    count: FccKeepReg<Bits<4>>,
    count_copy: FccKeepReg<Bits<4>>,
    read_slot: DFF<Bits<3>>,
    /// Always `read_slot + 1`: a register of its own, so that each pointer
    /// selects one 16-bit multiplexer (under 64 loads a bit).
    second_slot: DFF<Bits<3>>,
    /// `read_slot + 2` and `read_slot + 3`: the slots that refill the front
    /// registers on a pop.
    third_slot: FccFanoutReg<Bits<3>>,
    fourth_slot: FccFanoutReg<Bits<3>>,
    write_slot: DFF<Bits<3>>,
    /// The slots at `read_slot` and `second_slot`, kept in step with the ring.
    front_label: DFF<Bits<16>>,
    second_label: DFF<Bits<16>>,
    /// The ring read at `third_slot` and `fourth_slot`.
    third_ring: Signal<Local, Bits<16>>,
    fourth_ring: Signal<Local, Bits<16>>,
    /// The slots at `read_slot + k` (k = 0..3) after this cycle's push.
    ahead: Vec<Signal<Local, Bits<16>>>,
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
            rst_low_slots: Default::default(),
            rst_high_slots: Default::default(),
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
            has_one_copy: Default::default(),
            has_two_copy: Default::default(),
            slots: vec_of(GEAR_SLOTS),
            count: Default::default(),
            count_copy: Default::default(),
            read_slot: Default::default(),
            write_slot: Default::default(),
            second_slot: Default::default(),
            third_slot: Default::default(),
            fourth_slot: Default::default(),
            front_label: Default::default(),
            second_label: Default::default(),
            third_ring: Default::default(),
            fourth_ring: Default::default(),
            ahead: vec_of(4),
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
        dff_setup!(
            self,
            clk,
            count,
            read_slot,
            second_slot,
            third_slot,
            fourth_slot,
            write_slot,
            front_label,
            second_label
        );
        for i in 0..8 {
            self.slots[i].clock.next = self.clk.val();
            self.slots[i].d.next = self.slots[i].q.val();
        }
        self.used.next = self.count.q.val();
        self.has_one.next = self.count.q.val() != self.count_is[0].val();
        self.has_two.next = (self.count.q.val() != self.count_is[0].val())
            & (self.count.q.val() != self.count_is[1].val());
        // The front two labels, registered.
        self.front.next = self.front_label.q.val();
        self.second.next = self.second_label.q.val();
        // The ring two and three slots behind the front.
        self.third_ring.next = self.slots[0].q.val();
        self.fourth_ring.next = self.slots[0].q.val();
        for i in 0..8 {
            if self.third_slot.q.val() == self.slot_is[i].val() {
                self.third_ring.next = self.slots[i].q.val();
            }
            if self.fourth_slot.q.val() == self.slot_is[i].val() {
                self.fourth_ring.next = self.slots[i].q.val();
            }
        }
        // The four front slots as they will be after the push.
        self.ahead[0].next = self.front_label.q.val();
        self.ahead[1].next = self.second_label.q.val();
        self.ahead[2].next = self.third_ring.val();
        self.ahead[3].next = self.fourth_ring.val();
        if self.push_valid.val() {
            if self.write_slot.q.val() == self.read_slot.q.val() {
                self.ahead[0].next = self.push_label.val();
            }
            if self.write_slot.q.val() == self.second_slot.q.val() {
                self.ahead[1].next = self.push_label.val();
            }
            if self.write_slot.q.val() == self.third_slot.q.val() {
                self.ahead[2].next = self.push_label.val();
            }
            if self.write_slot.q.val() == self.fourth_slot.q.val() {
                self.ahead[3].next = self.push_label.val();
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
        self.front_label.d.next = self.ahead[0].val();
        self.second_label.d.next = self.ahead[1].val();
        if self.pop.val() {
            self.read_slot.d.next = self.read_slot.q.val() + self.one3.val();
            self.second_slot.d.next = self.second_slot.q.val() + self.one3.val();
            self.third_slot.d.next = self.third_slot.q.val() + self.one3.val();
            self.fourth_slot.d.next = self.fourth_slot.q.val() + self.one3.val();
            self.front_label.d.next = self.ahead[1].val();
            self.second_label.d.next = self.ahead[2].val();
        }
        if self.pop_two.val() {
            self.read_slot.d.next = self.read_slot.q.val() + self.two3.val();
            self.second_slot.d.next = self.second_slot.q.val() + self.two3.val();
            self.third_slot.d.next = self.third_slot.q.val() + self.two3.val();
            self.fourth_slot.d.next = self.fourth_slot.q.val() + self.two3.val();
            self.front_label.d.next = self.ahead[2].val();
            self.second_label.d.next = self.ahead[3].val();
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
            self.third_slot.d.next = self.slot_is[2].val();
            self.fourth_slot.d.next = self.slot_is[3].val();
            self.write_slot.d.next = self.slot_is[0].val();
        }
        if self.rst_low_slots.val() {
            for i in 0..4 {
                self.slots[i].d.next = self.empty_slot.val();
            }
        }
        if self.rst_high_slots.val() {
            for i in 4..8 {
                self.slots[i].d.next = self.empty_slot.val();
            }
        }
        if self.rst.val() {
            self.front_label.d.next = self.empty_slot.val();
            self.second_label.d.next = self.empty_slot.val();
        }
        // The count's copy follows its input, read after every assignment
        // above (clear and reset included).
        self.count_copy.clock.next = self.clk.val();
        self.count_copy.d.next = self.count.d.val();
        self.has_one_copy.next = self.count_copy.q.val() != self.count_is[0].val();
        self.has_two_copy.next = (self.count_copy.q.val() != self.count_is[0].val())
            & (self.count_copy.q.val() != self.count_is[1].val());
    }
}
