//! `fcc_beat_queue`: the decoded beats between the read-back pipeline and the
//! output: a head register and a ring of four entries behind it, five beats
//! in all. A beat enters (`in_valid`, no back-pressure: the read-back
//! pipeline issues no more beats than fit) into the head register when the
//! queue is empty, or when the head leaves in the same cycle and the ring is
//! empty, and into the ring entry `write_entry` points at otherwise. On `pop`
//! the head register loads the ring's front (the entry at `read_entry`, read
//! from registers in parallel with the pop decision), or the entering beat.
//! The head is a register, so the decision that pops it (which reads it)
//! starts from flip-flops and not from a 4:1 multiplexer.

use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
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

/// Entries of the ring behind the head register.
const RING_BEATS: usize = 4;

/// Beats the queue holds (the head and the ring): the beats that can be
/// between the frame-buffer read and the registered pop (`fcc_rb_pipeline`).
pub const QUEUE_BEATS: usize = RING_BEATS + 1;

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
    /// Kept copies of `head_valid` and the head's `need`, for the label
    /// updater's gearbox-side copy of the pop decision (`fcc_pop_decision`).
    pub head_valid_copy: Signal<Out, Bit>,
    pub head_need_copy: Signal<Out, Bits<3>>,
    /// Kept (as its copy below is), so that synthesis merges neither into
    /// the other.
    head_valid_q: FccKeepReg<Bit>,
    /// The head beat; its `need` is read from `head_need_q` (the beat
    /// assembly's) and `head_need_copy_q` (the gearbox's), two kept
    /// registers on the same input, so that `head_q`'s own `need` bits are
    /// left unread (and removed by synthesis).
    head_q: DFF<Beat>,
    head_need_q: FccKeepReg<Bits<3>>,
    head_valid_copy_q: FccKeepReg<Bit>,
    head_need_copy_q: FccKeepReg<Bits<3>>,
    entries: Vec<DFF<Beat>>,
    /// Beats in the ring (0 .. 4); `ring_any_q`: it is not 0.
    ring_count: DFF<Bits<3>>,
    ring_any_q: DFF<Bit>,
    read_entry: DFF<Bits<2>>,
    write_entry: DFF<Bits<2>>,
    /// The ring's front, the entry at `read_entry`.
    ring_front: Signal<Local, Beat>,
    /// The entering beat goes to the head register, or into the ring.
    to_head: Signal<Local, Bit>,
    to_ring: Signal<Local, Bit>,
    /// The ring's front moves to the head register.
    from_ring: Signal<Local, Bit>,
    entry_is: Vec<Constant<Bits<2>>>,
    zero3: Constant<Bits<3>>,
    one3: Constant<Bits<3>>,
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
            head_valid_copy: Default::default(),
            head_need_copy: Default::default(),
            head_valid_q: Default::default(),
            head_q: Default::default(),
            head_need_q: Default::default(),
            head_valid_copy_q: Default::default(),
            head_need_copy_q: Default::default(),
            entries: vec_of(RING_BEATS),
            ring_count: Default::default(),
            ring_any_q: Default::default(),
            read_entry: Default::default(),
            write_entry: Default::default(),
            ring_front: Default::default(),
            to_head: Default::default(),
            to_ring: Default::default(),
            from_ring: Default::default(),
            entry_is: (0..RING_BEATS).map(|n| kb(n as u64)).collect(),
            zero3: kb(0),
            one3: kb(1),
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
        dff_setup!(
            self,
            clk,
            head_valid_q,
            head_q,
            ring_count,
            ring_any_q,
            read_entry,
            write_entry
        );
        for i in 0..4 {
            self.entries[i].clock.next = self.clk.val();
            self.entries[i].d.next = self.entries[i].q.val();
        }
        self.head_valid.next = self.head_valid_q.q.val();
        self.head.next = self.head_q.q.val();
        self.ring_front.next = self.entries[0].q.val();
        for i in 0..4 {
            if self.read_entry.q.val() == self.entry_is[i].val() {
                self.ring_front.next = self.entries[i].q.val();
            }
        }
        // Where the entering beat goes, and whether the ring's front moves up.
        self.to_head.next = self.in_valid.val()
            & !self.ring_any_q.q.val()
            & (!self.head_valid_q.q.val() | self.pop.val());
        self.to_ring.next = self.in_valid.val() & !self.to_head.val();
        self.from_ring.next = self.pop.val() & self.ring_any_q.q.val();
        // The head register.
        if self.pop.val() {
            self.head_valid_q.d.next = false;
        }
        if self.to_head.val() {
            self.head_valid_q.d.next = true;
            self.head_q.d.next = self.in_beat.val();
        }
        if self.from_ring.val() {
            self.head_valid_q.d.next = true;
            self.head_q.d.next = self.ring_front.val();
            self.read_entry.d.next = self.read_entry.q.val() + self.one2.val();
        }
        // The ring. An entering beat is written at `write_entry` whether or
        // not it goes to the head (the entry is free either way), so the
        // entries' enables do not wait for the pop decision.
        if self.in_valid.val() {
            for i in 0..4 {
                if self.write_entry.q.val() == self.entry_is[i].val() {
                    self.entries[i].d.next = self.in_beat.val();
                }
            }
        }
        if self.to_ring.val() {
            self.write_entry.d.next = self.write_entry.q.val() + self.one2.val();
        }
        if self.to_ring.val() & !self.from_ring.val() {
            self.ring_count.d.next = self.ring_count.q.val() + self.one3.val();
            self.ring_any_q.d.next = true;
        }
        if !self.to_ring.val() & self.from_ring.val() {
            self.ring_count.d.next = self.ring_count.q.val() - self.one3.val();
            self.ring_any_q.d.next = self.ring_count.q.val() != self.one3.val();
        }
        if self.clear.val() | self.rst.val() {
            self.head_valid_q.d.next = false;
            self.ring_count.d.next = self.zero3.val();
            self.ring_any_q.d.next = false;
            self.read_entry.d.next = self.entry_is[0].val();
            self.write_entry.d.next = self.entry_is[0].val();
        }
        // The copies follow the head's inputs, read after every assignment
        // above (clear and reset included).
        self.head_valid_copy_q.clock.next = self.clk.val();
        self.head_need_q.clock.next = self.clk.val();
        self.head_need_copy_q.clock.next = self.clk.val();
        self.head_valid_copy_q.d.next = self.head_valid_q.d.val();
        self.head_need_q.d.next = self.head_q.d.val().need;
        self.head_need_copy_q.d.next = self.head_q.d.val().need;
        self.head.next.need = self.head_need_q.q.val();
        self.head_valid_copy.next = self.head_valid_copy_q.q.val();
        self.head_need_copy.next = self.head_need_copy_q.q.val();
    }
}
