//! `fcc_beat_assembly`: the head beat of the queue collects its new labels
//! from the gearbox, up to two per cycle, and leaves for the output register
//! when it has them all (the last ones may arrive in the same cycle) and the
//! output register is free. Each slot's label, and the run carried into the
//! next beat, is chosen by one `fcc_slot_mux` (slot j's with the arms of the
//! first j + 1 new labels only, the carried run's with all of them).
//!
//! Output: four 16-bit slots from bit 0, `tkeep` marking the bytes of the
//! slots that hold labels, `tlast` on the frame's last beat.

use rust_hdl::prelude::*;

use crate::fcc_beat_queue::Beat;
use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_pop_decision::FccPopDecision;
use crate::fcc_slot_mux::{FccSlotMux, OutWord, NEW_LABELS};
use crate::types::{kb, vec_of};

#[derive(LogicBlock)]
pub struct FccBeatAssembly {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A copy of `rst` for the collected labels (64 loads).
    pub rst_collected: Signal<In, Bit>,
    /// Start of a read-back: no labels collected, no stalls counted.
    pub clear: Signal<In, Bit>,
    // The head of the decoded-beat queue.
    pub head_valid: Signal<In, Bit>,
    pub head: Signal<In, Beat>,
    /// The head beat leaves (the queue pops it).
    pub head_done: Signal<Out, Bit>,
    // The gearbox's front: its labels and how many wait (a kept copy).
    pub gear_front: Signal<In, Bits<16>>,
    pub gear_second: Signal<In, Bits<16>>,
    pub gear_has_one: Signal<In, Bit>,
    pub gear_has_two: Signal<In, Bit>,
    /// A kept copy of `taken`, for the gearbox's copy of the pop decision
    /// (this block's copy, `decision`, steers the collected labels).
    pub taken_copy: Signal<Out, Bits<3>>,
    // Output stream.
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tkeep: Signal<Out, Bits<8>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    /// The frame's last beat is accepted.
    pub frame_sent: Signal<Out, Bit>,
    /// Cycles in which the head beat waited for compact labels.
    pub gear_stalls: Signal<Out, Bits<24>>,
    decision: FccPopDecision,
    taken_copy_q: FccKeepReg<Bits<3>>,
    slot_mux: Vec<FccSlotMux>,
    run_mux: FccSlotMux,
    /// New labels the head beat has collected, and their values.
    /// Kept, as its copy `taken_copy_q` is: neither is merged into the other.
    taken: FccKeepReg<Bits<3>>,
    collected: Vec<DFF<Bits<16>>>,
    /// The label of the run carried into the head beat.
    carried_run: DFF<Bits<16>>,
    out_valid: DFF<Bit>,
    out_data: DFF<OutWord>,
    out_keep: DFF<Bits<8>>,
    out_last: DFF<Bit>,
    stall_count: DFF<Bits<24>>,
    /// `clear`, one cycle late: zeroes `stall_count` (no beat waits in the
    /// cycle after a start, the queue being empty), keeping the counter off
    /// the start net.
    clear_s1: DFF<Bit>,
    collected_word: Signal<Local, OutWord>,
    out_free: Signal<Local, Bit>,
    done: Signal<Local, Bit>,
    count: Vec<Constant<Bits<3>>>,
    one3: Constant<Bits<3>>,
    two3: Constant<Bits<3>>,
    zero3: Constant<Bits<3>>,
    one24: Constant<Bits<24>>,
    zero24: Constant<Bits<24>>,
    zero16: Constant<Bits<16>>,
}

impl FccBeatAssembly {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rst_collected: Default::default(),
            clear: Default::default(),
            head_valid: Default::default(),
            head: Default::default(),
            head_done: Default::default(),
            gear_front: Default::default(),
            gear_second: Default::default(),
            gear_has_one: Default::default(),
            gear_has_two: Default::default(),
            taken_copy: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tkeep: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tlast: Default::default(),
            m_axis_tready: Default::default(),
            frame_sent: Default::default(),
            gear_stalls: Default::default(),
            decision: Default::default(),
            taken_copy_q: Default::default(),
            slot_mux: (0..NEW_LABELS).map(|j| FccSlotMux::new(j + 1)).collect(),
            run_mux: FccSlotMux::new(NEW_LABELS),
            taken: Default::default(),
            collected: vec_of(NEW_LABELS),
            carried_run: Default::default(),
            out_valid: Default::default(),
            out_data: Default::default(),
            out_keep: Default::default(),
            out_last: Default::default(),
            stall_count: Default::default(),
            clear_s1: Default::default(),
            collected_word: Default::default(),
            out_free: Default::default(),
            done: Default::default(),
            count: (0..NEW_LABELS).map(|n| kb(n as u64)).collect(),
            one3: kb(1),
            two3: kb(2),
            zero3: kb(0),
            one24: kb(1),
            zero24: kb(0),
            zero16: kb(0),
        }
    }
}

impl Default for FccBeatAssembly {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccBeatAssembly {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            taken,
            carried_run,
            out_valid,
            out_data,
            out_keep,
            out_last,
            stall_count,
            clear_s1
        );
        for k in 0..4 {
            self.collected[k].clock.next = self.clk.val();
            self.collected[k].d.next = self.collected[k].q.val();
        }
        self.out_free.next = !self.out_valid.q.val() | self.m_axis_tready.val();
        self.decision.head_valid.next = self.head_valid.val();
        self.decision.need.next = self.head.val().need;
        self.decision.taken.next = self.taken.q.val();
        self.decision.has_one.next = self.gear_has_one.val();
        self.decision.has_two.next = self.gear_has_two.val();
        self.done.next = self.head_valid.val() & self.out_free.val() & self.decision.complete.val();
        self.head_done.next = self.done.val();
        // The slots' labels and the carried run (new labels `taken` and
        // `taken + 1` forwarded from the gearbox).
        self.collected_word.next.l0 = self.collected[0].q.val();
        self.collected_word.next.l1 = self.collected[1].q.val();
        self.collected_word.next.l2 = self.collected[2].q.val();
        self.collected_word.next.l3 = self.collected[3].q.val();
        for i in 0..4 {
            self.slot_mux[i].taken.next = self.taken.q.val();
            self.slot_mux[i].carried.next = self.carried_run.q.val();
            self.slot_mux[i].collected.next = self.collected_word.val();
            self.slot_mux[i].gear_head.next = self.gear_front.val();
            self.slot_mux[i].gear_next.next = self.gear_second.val();
        }
        self.slot_mux[0].source.next = self.head.val().s0;
        self.slot_mux[1].source.next = self.head.val().s1;
        self.slot_mux[2].source.next = self.head.val().s2;
        self.slot_mux[3].source.next = self.head.val().s3;
        self.run_mux.source.next = self.head.val().run;
        self.run_mux.taken.next = self.taken.q.val();
        self.run_mux.carried.next = self.carried_run.q.val();
        self.run_mux.collected.next = self.collected_word.val();
        self.run_mux.gear_head.next = self.gear_front.val();
        self.run_mux.gear_next.next = self.gear_second.val();
        // Collect the popped labels.
        if self.decision.pop.val() {
            for k in 0..4 {
                if self.taken.q.val() == self.count[k].val() {
                    self.collected[k].d.next = self.gear_front.val();
                }
            }
            self.taken.d.next = self.taken.q.val() + self.one3.val();
        }
        if self.decision.pop_two.val() {
            for k in 1..4 {
                if self.taken.q.val() == self.count[k - 1].val() {
                    self.collected[k].d.next = self.gear_second.val();
                }
            }
            self.taken.d.next = self.taken.q.val() + self.two3.val();
        }
        // The output register.
        if self.out_valid.q.val() & self.m_axis_tready.val() {
            self.out_valid.d.next = false;
        }
        // Slots 0 .. 2 load whenever the register is free and a head beat
        // waits (what they hold without `out_valid` is never seen, and is
        // never X: the head and the labels it selects are defined), the rest
        // with the beat: the enable is two nets of under 64 loads each, not
        // one of 90.
        if self.out_free.val() & self.head_valid.val() {
            self.out_data.d.next.l0 = self.slot_mux[0].label.val();
            self.out_data.d.next.l1 = self.slot_mux[1].label.val();
            self.out_data.d.next.l2 = self.slot_mux[2].label.val();
        }
        if self.done.val() {
            self.carried_run.d.next = self.run_mux.label.val();
            self.taken.d.next = self.zero3.val();
            self.out_valid.d.next = true;
            self.out_data.d.next.l3 = self.slot_mux[3].label.val();
            self.out_keep.d.next = self.head.val().keep;
            self.out_last.d.next = self.head.val().last;
        }
        if self.head_valid.val() & !self.done.val() & self.out_free.val() {
            self.stall_count.d.next = self.stall_count.q.val() + self.one24.val();
        }
        self.clear_s1.d.next = self.clear.val();
        if self.clear_s1.q.val() {
            self.stall_count.d.next = self.zero24.val();
        }
        if self.clear.val() {
            self.taken.d.next = self.zero3.val();
        }
        if self.rst.val() {
            self.taken.d.next = self.zero3.val();
            self.out_valid.d.next = false;
            self.carried_run.d.next = self.zero16.val();
        }
        if self.rst_collected.val() {
            for k in 0..4 {
                self.collected[k].d.next = self.zero16.val();
            }
        }
        self.m_axis_tdata.next = self.out_data.q.val().into();
        self.m_axis_tkeep.next = self.out_keep.q.val();
        self.m_axis_tvalid.next = self.out_valid.q.val();
        self.m_axis_tlast.next = self.out_last.q.val();
        self.frame_sent.next =
            self.out_valid.q.val() & self.m_axis_tready.val() & self.out_last.q.val();
        self.gear_stalls.next = self.stall_count.q.val();
        // The copy of `taken` follows its input, read after every
        // assignment above (reset included).
        self.taken_copy_q.clock.next = self.clk.val();
        self.taken_copy_q.d.next = self.taken.d.val();
        self.taken_copy.next = self.taken_copy_q.q.val();
    }
}
