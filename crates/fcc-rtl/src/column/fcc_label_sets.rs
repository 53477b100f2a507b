//! `FccLabelSets`: the column core's union-find over labels
//! (docs/column-core.md, item 3). Per label a word in block RAM: its parent
//! (itself at a root) and, at a root, the record slot its cluster owns.
//!
//! * A *make* (`mk_*`: a run starts with a label and its cluster a slot)
//!   writes the label's word as a root. It is taken with `mk_ready` (from
//!   flip-flops: low while a join may retire and link, which needs the
//!   write port), and an op naming the label may follow from the next
//!   cycle.
//! * An *op* (`op_*`, taken when `op_take`): a find (the root and slot of
//!   `op_a`: a run's flush) or a join (`op_a` and `op_b`'s sets united,
//!   one root linked under the other, which keeps its slot). With
//!   `op_under` (`op_a` is a run the pixel just started, filed under its
//!   neighbours' cluster, named `op_b` by the representative rows) `op_b`'s
//!   root is kept, so that the cluster's name stays near its root; else the
//!   smaller root (the two clusters' roots, whichever the rows name). Each
//!   gives one event, in order (`ev_*`): a find's root and slot; a join's
//!   root and slot kept and gone, `ev_merged` when they were two sets.
//!
//! The walks and their order are `FccSetWalks`'; the table needs no reset
//! (a label is made before it is named). This block is wiring.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_set_walks::FccSetWalks;
use crate::fcc_ram::FccRam;

/// Bits of a record slot (512 records).
pub const SLOT_BITS: usize = 9;

#[derive(LogicBlock)]
pub struct FccLabelSets {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub mk_valid: Signal<In, Bit>,
    pub mk_label: Signal<In, Bits<16>>,
    pub mk_slot: Signal<In, Bits<SLOT_BITS>>,
    pub mk_ready: Signal<Out, Bit>,
    pub op_valid: Signal<In, Bit>,
    pub op_join: Signal<In, Bit>,
    pub op_under: Signal<In, Bit>,
    pub op_a: Signal<In, Bits<16>>,
    pub op_b: Signal<In, Bits<16>>,
    pub op_take: Signal<Out, Bit>,
    pub ev_valid: Signal<Out, Bit>,
    pub ev_join: Signal<Out, Bit>,
    pub ev_merged: Signal<Out, Bit>,
    pub ev_keep: Signal<Out, Bits<16>>,
    pub ev_keep_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub ev_gone: Signal<Out, Bits<16>>,
    pub ev_gone_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub idle: Signal<Out, Bit>,
    parent: FccRam<Bits<16>, 16>,
    slot: FccRam<Bits<SLOT_BITS>, 16>,
    walks: FccSetWalks,
    /// A make taken this cycle.
    mk_go: Signal<Local, Bit>,
}

impl FccLabelSets {
    pub fn new(p: &FccParams) -> Self {
        let b = super::label_bits(p);
        Self {
            clk: Default::default(),
            rst: Default::default(),
            mk_valid: Default::default(),
            mk_label: Default::default(),
            mk_slot: Default::default(),
            mk_ready: Default::default(),
            op_valid: Default::default(),
            op_join: Default::default(),
            op_under: Default::default(),
            op_a: Default::default(),
            op_b: Default::default(),
            op_take: Default::default(),
            ev_valid: Default::default(),
            ev_join: Default::default(),
            ev_merged: Default::default(),
            ev_keep: Default::default(),
            ev_keep_slot: Default::default(),
            ev_gone: Default::default(),
            ev_gone_slot: Default::default(),
            idle: Default::default(),
            parent: FccRam::with_stored_bits(1 << b, b),
            slot: FccRam::new(1 << b),
            walks: Default::default(),
            mk_go: Default::default(),
        }
    }
}

impl Logic for FccLabelSets {
    #[hdl_gen]
    fn update(&mut self) {
        self.parent.clk.next = self.clk.val();
        self.slot.clk.next = self.clk.val();
        self.walks.clk.next = self.clk.val();
        self.walks.rst.next = self.rst.val();
        self.walks.op_valid.next = self.op_valid.val();
        self.walks.op_join.next = self.op_join.val();
        self.walks.op_under.next = self.op_under.val();
        self.walks.op_a.next = self.op_a.val();
        self.walks.op_b.next = self.op_b.val();
        self.mk_ready.next = self.walks.mk_ready.val();
        self.mk_go.next = self.mk_valid.val() & self.walks.mk_ready.val();
        self.op_take.next = self.walks.op_take.val();
        // Reads: both tables at once.
        self.parent.read_en.next = self.walks.read_en.val();
        self.parent.read_addr.next = self.walks.read_addr.val();
        self.slot.read_en.next = self.walks.read_en.val();
        self.slot.read_addr.next = self.walks.read_addr.val();
        self.walks.word_parent.next = self.parent.read_data.val();
        self.walks.word_slot.next = self.slot.read_data.val();
        // Writes: a make, else a link (never both: a link comes only while
        // `mk_ready` is low, which also chooses the address and word, from
        // flip-flops).
        self.parent.write_en.next = self.mk_go.val() | self.walks.link_en.val();
        self.parent.write_addr.next = self.mk_label.val();
        self.parent.write_data.next = self.mk_label.val();
        if !self.walks.mk_ready.val() {
            self.parent.write_addr.next = self.walks.link_gone.val();
            self.parent.write_data.next = self.walks.link_keep.val();
        }
        self.slot.write_en.next = self.mk_go.val();
        self.slot.write_addr.next = self.mk_label.val();
        self.slot.write_data.next = self.mk_slot.val();
        self.ev_valid.next = self.walks.ev_valid.val();
        self.ev_join.next = self.walks.ev_join.val();
        self.ev_merged.next = self.walks.ev_merged.val();
        self.ev_keep.next = self.walks.ev_keep.val();
        self.ev_keep_slot.next = self.walks.ev_keep_slot.val();
        self.ev_gone.next = self.walks.ev_gone.val();
        self.ev_gone_slot.next = self.walks.ev_gone_slot.val();
        self.idle.next = self.walks.idle.val();
    }
}
