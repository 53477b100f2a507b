//! `fcc_flatten`: the merge table's flatten pass (frame end).
//!
//! For l = 1 .. P in ascending order, a root gets the next compact number,
//! otherwise `C[l] = C[T[l]]` (`T[l] < l` is already final; the two labels
//! before l are forwarded from registers, `value_prev` and `value_prev2`).
//! This numbers components in the raster order of their first pixel, exactly
//! as the golden model. Each compact label leaves on the `out_valid` /
//! `out_label` stream in ascending `l`, at most as many in flight as the label
//! updater's gearbox has room for, and every label becomes a root again (the
//! table write) for the next frame. The compact table `C` is this block's own
//! RAM.
//!
//! Pipeline: `_s1` the read of `T[l]` is issued; `_s2` it is in the RAM;
//! `_s3` `T[l]` has arrived, `C[T[l]]` is read; `_s4` `C[T[l]]` has arrived,
//! `C[l]` is written and emitted. `label_valid_s4` drives the compact
//! table's write enable only; two kept copies of it (same input, same
//! cycle) drive the rest: `out_valid_s4` `out_valid` (the label updater's
//! gearbox), `prev_valid_s4` the forwarding registers and the in-flight
//! count, so no net carries two groups of loads.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use crate::fcc_keep_reg::FccKeepReg;
use crate::fcc_ram::FccRam;
use crate::types::kb;

/// Labels in flight plus labels waiting in the gearbox above which the pass
/// pauses.
const GEAR_ROOM: u64 = 6;

#[derive(LogicBlock)]
pub struct FccFlatten {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The table is in Flatten mode.
    pub active: Signal<In, Bit>,
    /// Start a pass (one cycle; the table enters Flatten mode with it).
    pub start: Signal<In, Bit>,
    /// The pass is over (every label emitted).
    pub done: Signal<Out, Bit>,
    pub provisional: Signal<In, Bits<17>>,
    /// Compact labels waiting in the label updater's gearbox (registered).
    pub gear_used: Signal<In, Bits<4>>,
    // The word read two cycles ago (forwarding applied).
    pub word_root: Signal<In, Bit>,
    pub word_parent: Signal<In, Bits<16>>,
    // Read request: `T[read_addr]`.
    pub read_en: Signal<Out, Bit>,
    pub read_addr: Signal<Out, Bits<16>>,
    // Table write: `write_addr` becomes a root again.
    pub write_en: Signal<Out, Bit>,
    pub write_addr: Signal<Out, Bits<16>>,
    // Compact labels in ascending provisional order.
    pub out_valid: Signal<Out, Bit>,
    pub out_label: Signal<Out, Bits<16>>,
    /// Components numbered so far (all of them once `done`).
    pub clusters: Signal<Out, Bits<16>>,
    compact_ram: FccRam<Bits<16>, 16>,
    /// The next label to issue (1 .. P+1).
    next_label: DFF<Bits<17>>,
    /// Labels between issue and emission.
    in_flight: DFF<Bits<4>>,
    /// Room in the gearbox, one cycle old.
    has_room: DFF<Bit>,
    /// Labels left to issue.
    more_labels: DFF<Bit>,
    label_valid_s1: DFF<Bit>,
    label_s1: DFF<Bits<16>>,
    label_valid_s2: DFF<Bit>,
    label_s2: DFF<Bits<16>>,
    label_minus1_s2: DFF<Bits<16>>,
    label_minus2_s2: DFF<Bits<16>>,
    label_valid_s3: DFF<Bit>,
    label_s3: DFF<Bits<16>>,
    is_root_s3: DFF<Bit>,
    new_number_s3: DFF<Bits<16>>,
    parent_is_prev_s3: DFF<Bit>,
    parent_is_prev2_s3: DFF<Bit>,
    label_valid_s4: DFF<Bit>,
    out_valid_s4: FccKeepReg<Bit>,
    prev_valid_s4: FccKeepReg<Bit>,
    label_s4: DFF<Bits<16>>,
    is_root_s4: DFF<Bit>,
    new_number_s4: DFF<Bits<16>>,
    parent_is_prev_s4: DFF<Bit>,
    parent_is_prev2_s4: DFF<Bit>,
    cluster_count: DFF<Bits<16>>,
    /// The compact labels of the two labels emitted last.
    value_prev: DFF<Bits<16>>,
    value_prev2: DFF<Bits<16>>,
    // Combinational.
    issue: Signal<Local, Bit>,
    value: Signal<Local, Bits<16>>,
    gear_room: Constant<Bits<4>>,
    zero4: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    zero16: Constant<Bits<16>>,
    one16: Constant<Bits<16>>,
    two16: Constant<Bits<16>>,
    zero17: Constant<Bits<17>>,
    one17: Constant<Bits<17>>,
}

impl FccFlatten {
    pub fn new(p: &FccParams) -> Self {
        let words = 1usize << p.label_bits;
        Self {
            clk: Default::default(),
            rst: Default::default(),
            active: Default::default(),
            start: Default::default(),
            done: Default::default(),
            provisional: Default::default(),
            gear_used: Default::default(),
            word_root: Default::default(),
            word_parent: Default::default(),
            read_en: Default::default(),
            read_addr: Default::default(),
            write_en: Default::default(),
            write_addr: Default::default(),
            out_valid: Default::default(),
            out_label: Default::default(),
            clusters: Default::default(),
            compact_ram: FccRam::with_stored_bits(words, p.label_bits as usize),
            next_label: Default::default(),
            in_flight: Default::default(),
            has_room: Default::default(),
            more_labels: Default::default(),
            label_valid_s1: Default::default(),
            label_s1: Default::default(),
            label_valid_s2: Default::default(),
            label_s2: Default::default(),
            label_minus1_s2: Default::default(),
            label_minus2_s2: Default::default(),
            label_valid_s3: Default::default(),
            label_s3: Default::default(),
            is_root_s3: Default::default(),
            new_number_s3: Default::default(),
            parent_is_prev_s3: Default::default(),
            parent_is_prev2_s3: Default::default(),
            label_valid_s4: Default::default(),
            out_valid_s4: Default::default(),
            prev_valid_s4: Default::default(),
            label_s4: Default::default(),
            is_root_s4: Default::default(),
            new_number_s4: Default::default(),
            parent_is_prev_s4: Default::default(),
            parent_is_prev2_s4: Default::default(),
            cluster_count: Default::default(),
            value_prev: Default::default(),
            value_prev2: Default::default(),
            issue: Default::default(),
            value: Default::default(),
            gear_room: kb(GEAR_ROOM),
            zero4: kb(0),
            one4: kb(1),
            zero16: kb(0),
            one16: kb(1),
            two16: kb(2),
            zero17: kb(0),
            one17: kb(1),
        }
    }
}

impl Logic for FccFlatten {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clk,
            next_label,
            in_flight,
            has_room,
            more_labels,
            label_valid_s1,
            label_s1,
            label_valid_s2,
            label_s2,
            label_minus1_s2,
            label_minus2_s2,
            label_valid_s3,
            label_s3,
            is_root_s3,
            new_number_s3,
            parent_is_prev_s3,
            parent_is_prev2_s3,
            label_valid_s4,
            label_s4,
            is_root_s4,
            new_number_s4,
            parent_is_prev_s4,
            parent_is_prev2_s4,
            cluster_count,
            value_prev,
            value_prev2
        );
        self.compact_ram.clk.next = self.clk.val();
        // Issue: labels in flight plus labels waiting grow by at most one per
        // cycle, so a one-cycle-old room check is safe.
        self.has_room.d.next =
            (self.in_flight.q.val() + self.gear_used.val()) <= self.gear_room.val();
        self.issue.next = self.active.val() & self.more_labels.q.val() & self.has_room.q.val();
        // Labels left to issue after this cycle (next_label <= P), from registers.
        self.more_labels.d.next = self.next_label.q.val() <= self.provisional.val();
        if self.issue.val() {
            self.more_labels.d.next = self.next_label.q.val() < self.provisional.val();
            self.next_label.d.next = self.next_label.q.val() + self.one17.val();
        }
        self.read_en.next = self.issue.val();
        self.read_addr.next = self.next_label.q.val().get_bits::<16>(0);
        self.label_valid_s1.d.next = self.issue.val();
        self.label_s1.d.next = self.next_label.q.val().get_bits::<16>(0);
        self.label_valid_s2.d.next = self.label_valid_s1.q.val();
        self.label_s2.d.next = self.label_s1.q.val();
        self.label_minus1_s2.d.next = self.label_s1.q.val() - self.one16.val();
        self.label_minus2_s2.d.next = self.label_s1.q.val() - self.two16.val();
        // T[l] arrives: a root, or look up C[T[l]]; l becomes a root again.
        self.compact_ram.read_en.next = self.label_valid_s2.q.val();
        self.compact_ram.read_addr.next = self.word_parent.val();
        self.label_valid_s3.d.next = self.label_valid_s2.q.val();
        self.label_s3.d.next = self.label_s2.q.val();
        self.is_root_s3.d.next = self.word_root.val();
        self.new_number_s3.d.next = self.cluster_count.q.val() + self.one16.val();
        self.parent_is_prev_s3.d.next = self.word_parent.val() == self.label_minus1_s2.q.val();
        self.parent_is_prev2_s3.d.next = self.word_parent.val() == self.label_minus2_s2.q.val();
        self.write_en.next = self.label_valid_s2.q.val();
        self.write_addr.next = self.label_s2.q.val();
        if self.label_valid_s2.q.val() & self.word_root.val() {
            self.cluster_count.d.next = self.cluster_count.q.val() + self.one16.val();
        }
        self.label_valid_s4.d.next = self.label_valid_s3.q.val();
        self.out_valid_s4.clock.next = self.clk.val();
        self.out_valid_s4.d.next = self.label_valid_s3.q.val() & !self.rst.val();
        self.prev_valid_s4.clock.next = self.clk.val();
        self.prev_valid_s4.d.next = self.label_valid_s3.q.val() & !self.rst.val();
        self.label_s4.d.next = self.label_s3.q.val();
        self.is_root_s4.d.next = self.is_root_s3.q.val();
        self.new_number_s4.d.next = self.new_number_s3.q.val();
        self.parent_is_prev_s4.d.next = self.parent_is_prev_s3.q.val();
        self.parent_is_prev2_s4.d.next = self.parent_is_prev2_s3.q.val();
        // C value known: write C[l] and emit it.
        self.value.next = self.compact_ram.read_data.val();
        if self.parent_is_prev2_s4.q.val() {
            self.value.next = self.value_prev2.q.val();
        }
        if self.parent_is_prev_s4.q.val() {
            self.value.next = self.value_prev.q.val();
        }
        if self.is_root_s4.q.val() {
            self.value.next = self.new_number_s4.q.val();
        }
        self.compact_ram.write_en.next = self.label_valid_s4.q.val();
        self.compact_ram.write_addr.next = self.label_s4.q.val();
        self.compact_ram.write_data.next = self.value.val();
        self.out_valid.next = self.out_valid_s4.q.val();
        self.out_label.next = self.value.val();
        if self.prev_valid_s4.q.val() {
            self.value_prev.d.next = self.value.val();
            self.value_prev2.d.next = self.value_prev.q.val();
        }
        if self.issue.val() & !self.prev_valid_s4.q.val() {
            self.in_flight.d.next = self.in_flight.q.val() + self.one4.val();
        }
        if !self.issue.val() & self.prev_valid_s4.q.val() {
            self.in_flight.d.next = self.in_flight.q.val() - self.one4.val();
        }
        self.done.next = self.active.val()
            & !self.more_labels.q.val()
            & (self.in_flight.q.val() == self.zero4.val());
        if self.start.val() {
            self.next_label.d.next = self.one17.val();
            self.cluster_count.d.next = self.zero16.val();
            self.in_flight.d.next = self.zero4.val();
            self.more_labels.d.next = self.provisional.val() != self.zero17.val();
        }
        self.clusters.next = self.cluster_count.q.val();
        if self.rst.val() {
            self.has_room.d.next = false;
            self.label_valid_s1.d.next = false;
            self.label_valid_s2.d.next = false;
            self.label_valid_s3.d.next = false;
            self.label_valid_s4.d.next = false;
            self.in_flight.d.next = self.zero4.val();
        }
    }
}
