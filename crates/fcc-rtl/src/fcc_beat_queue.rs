//! `fcc_beat_queue`: the decoded beats between the read-back pipeline and the
//! output, a ring of four entries. A beat enters behind the others
//! (`in_valid`, no back-pressure: the read-back pipeline issues no more beats
//! than fit) into the entry `write_entry` points at; the head, the entry at
//! `read_entry`, leaves on `pop`, which only moves `read_entry` (so the pop
//! decision drives a few pointer bits, not every entry).

use rust_hdl::prelude::*;

use crate::types::{kb, vec_of};

/// A decoded beat. A slot source is 0 (label 0), 1 (the run carried in from
/// the previous beat) or 2 + k (the beat's k-th new label), as
/// `fcc_slot_mux` reads it.
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

/// Entries of the queue: the beats that can be between the frame-buffer
/// read and the output.
pub const QUEUE_BEATS: usize = 4;

#[derive(LogicBlock)]
pub struct FccBeatQueue {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Start of a read-back: empty the queue.
    pub clear: Signal<In, Bit>,
    pub in_valid: Signal<In, Bit>,
    pub in_beat: Signal<In, Beat>,
    pub pop: Signal<In, Bit>,
    pub head_valid: Signal<Out, Bit>,
    pub head: Signal<Out, Beat>,
    entries: Vec<DFF<Beat>>,
    count: DFF<Bits<3>>,
    read_entry: DFF<Bits<2>>,
    write_entry: DFF<Bits<2>>,
    count_is: Vec<Constant<Bits<3>>>,
    entry_is: Vec<Constant<Bits<2>>>,
    one: Constant<Bits<3>>,
    one2: Constant<Bits<2>>,
}

impl FccBeatQueue {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            clear: Default::default(),
            in_valid: Default::default(),
            in_beat: Default::default(),
            pop: Default::default(),
            head_valid: Default::default(),
            head: Default::default(),
            entries: vec_of(QUEUE_BEATS),
            count: Default::default(),
            read_entry: Default::default(),
            write_entry: Default::default(),
            count_is: (0..1).map(|n| kb(n as u64)).collect(),
            entry_is: (0..QUEUE_BEATS).map(|n| kb(n as u64)).collect(),
            one: kb(1),
            one2: kb(1),
        }
    }
}

impl Default for FccBeatQueue {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccBeatQueue {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, count, read_entry, write_entry);
        for i in 0..4 {
            self.entries[i].clock.next = self.clk.val();
            self.entries[i].d.next = self.entries[i].q.val();
        }
        self.head_valid.next = self.count.q.val() != self.count_is[0].val();
        self.head.next = self.entries[0].q.val();
        for i in 0..4 {
            if self.read_entry.q.val() == self.entry_is[i].val() {
                self.head.next = self.entries[i].q.val();
            }
        }
        if self.in_valid.val() {
            for i in 0..4 {
                if self.write_entry.q.val() == self.entry_is[i].val() {
                    self.entries[i].d.next = self.in_beat.val();
                }
            }
            self.write_entry.d.next = self.write_entry.q.val() + self.one2.val();
        }
        if self.pop.val() {
            self.read_entry.d.next = self.read_entry.q.val() + self.one2.val();
        }
        if self.in_valid.val() & !self.pop.val() {
            self.count.d.next = self.count.q.val() + self.one.val();
        }
        if !self.in_valid.val() & self.pop.val() {
            self.count.d.next = self.count.q.val() - self.one.val();
        }
        if self.clear.val() | self.rst.val() {
            self.count.d.next = self.count_is[0].val();
            self.read_entry.d.next = self.entry_is[0].val();
            self.write_entry.d.next = self.entry_is[0].val();
        }
    }
}
