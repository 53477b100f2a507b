//! `FccColStore`: the column core's record store half (docs/column-core.md,
//! item 8, "The record store half"), behind the slot table half's events.
//! `FccStoreOps` turns each event into the store's ops (a make's start, a
//! find's accumulator, a join's merge and seam), the closer's closes into
//! closes, and passes column markers to the closer; `FccStoreEnd` runs the
//! frame end (peeks, the end column's closes, the end beat). Behind them:
//! `FccSlotRecords` (the records and holds), `FccCloser` (which close, and
//! in which order), `FccLabelLists` (a closed cluster's labels back to the
//! label pool), `FccRecordOut` (the record beats, `m_axis_*`), and the two
//! pools, labels (`free_*`, for the input half's runs) and record slots
//! (`slot_*`, for the union-find's makes), the slots coming back from
//! merges and closes through `FccSlotReturns`. The frame end's marker
//! carries the frame's flags: `ev_ring` its overflow, `ev_row` bit 0 its
//! input error. This block is wiring.

use fcc_params::FccParams;
use rust_hdl::prelude::*;

use super::fcc_closer::FccCloser;
use super::fcc_label_lists::FccLabelLists;
use super::fcc_label_pool::FccLabelPool;
use super::fcc_label_sets::SLOT_BITS;
use super::fcc_record_out::FccRecordOut;
use super::fcc_slot_records::FccSlotRecords;
use super::fcc_slot_returns::FccSlotReturns;
use super::fcc_store_end::FccStoreEnd;
use super::fcc_store_ops::FccStoreOps;
use super::AccWord;
use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColStore {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// `h` and the frame's last column `C - 1` (run parameters).
    pub half: Signal<In, Bits<3>>,
    pub last_col: Signal<In, Bits<12>>,
    /// The union-find queue's events (`FccColTable`'s `ev_*`; `ev_ring` on a
    /// join: the ring check's).
    pub ev_valid: Signal<In, Bit>,
    pub ev_make: Signal<In, Bit>,
    pub ev_join: Signal<In, Bit>,
    pub ev_mark: Signal<In, Bit>,
    pub ev_ring: Signal<In, Bit>,
    pub ev_merged: Signal<In, Bit>,
    pub ev_label: Signal<In, Bits<16>>,
    pub ev_slot: Signal<In, Bits<SLOT_BITS>>,
    pub ev_other: Signal<In, Bits<SLOT_BITS>>,
    pub ev_col: Signal<In, Bits<12>>,
    pub ev_row: Signal<In, Bits<7>>,
    pub ev_take: Signal<Out, Bit>,
    pub acc_valid: Signal<In, Bit>,
    pub acc: Signal<In, AccWord>,
    pub acc_take: Signal<Out, Bit>,
    /// The label pool's head, taken by `label_take`; labels free.
    pub free_ok: Signal<Out, Bit>,
    pub free_label: Signal<Out, Bits<16>>,
    pub label_take: Signal<In, Bit>,
    pub labels_free: Signal<Out, Bits<16>>,
    /// The slot pool's head, taken by `slot_take`; slots free.
    pub slot_ok: Signal<Out, Bit>,
    pub slot: Signal<Out, Bits<SLOT_BITS>>,
    pub slot_take: Signal<In, Bit>,
    pub slots_free: Signal<Out, Bits<16>>,
    /// The record stream (spec §9.4).
    pub m_axis_tdata: Signal<Out, Bits<64>>,
    pub m_axis_tvalid: Signal<Out, Bit>,
    pub m_axis_tlast: Signal<Out, Bit>,
    pub m_axis_tready: Signal<In, Bit>,
    /// A marker taken (a column's, or the frame end's).
    pub marked: Signal<Out, Bit>,
    /// Nothing under way: every marker taken has passed, its closes'
    /// records are out and their labels and slots back.
    pub calm: Signal<Out, Bit>,
    /// A slot return lost (never, by design).
    pub bad: Signal<Out, Bit>,
    ops: FccStoreOps,
    ends: FccStoreEnd,
    records: FccSlotRecords,
    closer: FccCloser,
    lists: FccLabelLists,
    out: FccRecordOut,
    rets: FccSlotReturns,
    /// The free record slots, their FIFO (512 x 9 bits) in LUT RAM: about
    /// 140 LUTs for a RAMB18, so that the core at its 13-bit labels takes
    /// 24 block RAMs (36k equivalents; docs/column-core.md).
    slots: FccLabelPool,
    labels: FccLabelPool,
    one: Constant<Bits<12>>,
}

impl FccColStore {
    /// The store of the build's labels.
    pub fn new(p: &FccParams) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            half: Default::default(),
            last_col: Default::default(),
            ev_valid: Default::default(),
            ev_make: Default::default(),
            ev_join: Default::default(),
            ev_mark: Default::default(),
            ev_ring: Default::default(),
            ev_merged: Default::default(),
            ev_label: Default::default(),
            ev_slot: Default::default(),
            ev_other: Default::default(),
            ev_col: Default::default(),
            ev_row: Default::default(),
            ev_take: Default::default(),
            acc_valid: Default::default(),
            acc: Default::default(),
            acc_take: Default::default(),
            free_ok: Default::default(),
            free_label: Default::default(),
            label_take: Default::default(),
            labels_free: Default::default(),
            slot_ok: Default::default(),
            slot: Default::default(),
            slot_take: Default::default(),
            slots_free: Default::default(),
            m_axis_tdata: Default::default(),
            m_axis_tvalid: Default::default(),
            m_axis_tlast: Default::default(),
            m_axis_tready: Default::default(),
            marked: Default::default(),
            calm: Default::default(),
            bad: Default::default(),
            ops: Default::default(),
            ends: Default::default(),
            records: Default::default(),
            closer: Default::default(),
            lists: FccLabelLists::new(p),
            out: Default::default(),
            rets: Default::default(),
            slots: FccLabelPool::with_bits(SLOT_BITS).in_lut_ram(),
            labels: FccLabelPool::new(p),
            one: kb(1),
        }
    }
}

impl Logic for FccColStore {
    #[hdl_gen]
    fn update(&mut self) {
        self.ops.clk.next = self.clk.val();
        self.ends.clk.next = self.clk.val();
        self.records.clk.next = self.clk.val();
        self.closer.clk.next = self.clk.val();
        self.lists.clk.next = self.clk.val();
        self.out.clk.next = self.clk.val();
        self.rets.clk.next = self.clk.val();
        self.slots.clk.next = self.clk.val();
        self.labels.clk.next = self.clk.val();
        self.ops.rst.next = self.rst.val();
        self.ends.rst.next = self.rst.val();
        self.records.rst.next = self.rst.val();
        self.closer.rst.next = self.rst.val();
        self.lists.rst.next = self.rst.val();
        self.out.rst.next = self.rst.val();
        self.rets.rst.next = self.rst.val();
        self.slots.rst.next = self.rst.val();
        self.labels.rst.next = self.rst.val();
        self.slots.clear.next = false;
        self.labels.clear.next = false;
        // The ops.
        self.ops.last_col.next = self.last_col.val();
        self.ops.ev_valid.next = self.ev_valid.val();
        self.ops.ev_make.next = self.ev_make.val();
        self.ops.ev_join.next = self.ev_join.val();
        self.ops.ev_mark.next = self.ev_mark.val();
        self.ops.ev_ring.next = self.ev_ring.val();
        self.ops.ev_merged.next = self.ev_merged.val();
        self.ops.ev_label.next = self.ev_label.val();
        self.ops.ev_slot.next = self.ev_slot.val();
        self.ops.ev_other.next = self.ev_other.val();
        self.ops.ev_col.next = self.ev_col.val();
        self.ops.ev_row.next = self.ev_row.val();
        self.ev_take.next = self.ops.ev_take.val();
        self.ops.end_take.next = self.ends.end_take.val();
        self.ops.acc_valid.next = self.acc_valid.val();
        self.ops.acc.next = self.acc.val();
        self.acc_take.next = self.ops.acc_take.val();
        self.ops.close_valid.next = self.closer.close_valid.val();
        self.ops.close_slot.next = self.closer.close_slot.val();
        self.ops.close_key.next = self.closer.close_key.val();
        self.ops.close_col.next = self.closer.close_col.val();
        self.ops.room.next = self.closer.room.val();
        self.ops.walk_room.next = self.lists.walk_room.val();
        self.ops.out_idle.next = self.out.idle.val();
        self.ops.ending.next = self.ends.ending.val();
        self.ops.peek_valid.next = self.ends.peek_valid.val();
        self.ops.peek_slot.next = self.ends.peek_slot.val();
        self.ops.end_mark.next = self.ends.end_mark.val();
        self.ops.end_col.next = self.last_col.val() + self.one.val();
        self.ops.op_take.next = self.records.op_take.val();
        self.ops.out_load.next = self.records.out_valid.val();
        self.ops.id_clear.next = self.ends.id_clear.val();
        self.marked.next = self.ops.marked.val();
        // The frame end.
        self.ends.ev_end.next = self.ops.ev_end.val();
        self.ends.caught_up.next = self.closer.caught_up.val();
        self.ends.calm.next = self.ops.calm.val();
        self.ends.out_idle.next = self.out.idle.val();
        self.ends.peek_take.next = self.ops.peek_take.val();
        // The records.
        self.records.half.next = self.half.val();
        self.records.last_col.next = self.last_col.val();
        self.records.op_valid.next = self.ops.op_valid.val();
        self.records.op_kind.next = self.ops.op_kind.val();
        self.records.op_slot.next = self.ops.op_slot.val();
        self.records.op_other.next = self.ops.op_other.val();
        self.records.op_word.next = self.ops.op_word.val();
        self.records.op_col.next = self.ops.op_col.val();
        // The closer.
        self.closer.clear.next = self.ends.clear.val();
        self.closer.half.next = self.half.val();
        self.closer.last_col.next = self.last_col.val();
        self.closer.ending.next = self.ends.ending.val();
        self.closer.end_col.next = self.last_col.val() + self.one.val();
        self.closer.q_valid.next = self.records.q_valid.val();
        self.closer.q_slot.next = self.records.q_slot.val();
        self.closer.q_first.next = self.records.q_first.val();
        self.closer.q_last.next = self.records.q_last.val();
        self.closer.q_col.next = self.records.q_col.val();
        self.closer.mark_valid.next = self.ops.mark_valid.val();
        self.closer.mark_col.next = self.ops.mark_col.val();
        self.closer.close_take.next = self.ops.close_take.val();
        // The labels' lists.
        self.lists.link_valid.next = self.records.link_valid.val();
        self.lists.link_from.next = self.records.link_from.val();
        self.lists.link_to.next = self.records.link_to.val();
        self.lists.walk_valid.next = self.records.out_valid.val();
        self.lists.walk_head.next = self.records.out_head.val();
        self.lists.walk_tail.next = self.records.out_tail.val();
        // The record out.
        self.out.load.next = self.records.out_valid.val();
        self.out.acc.next = self.records.out_acc.val();
        self.out.id.next = self.ops.rec_id.val();
        self.out.closed_col.next = self.ops.rec_col.val();
        self.out.load_end.next = self.ends.load_end.val();
        self.out.overflow.next = self.ev_ring.val();
        self.out.frame_error.next = self.ev_row.val().get_bit(0);
        self.out.ready.next = self.m_axis_tready.val();
        self.m_axis_tvalid.next = self.out.valid.val();
        self.m_axis_tdata.next = self.out.beat.val();
        self.m_axis_tlast.next = self.out.last.val();
        // The pools.
        self.rets.a_valid.next = self.ops.gone_valid.val();
        self.rets.a_slot.next = self.ops.gone_slot.val();
        self.rets.b_valid.next = self.records.out_valid.val();
        self.rets.b_slot.next = self.records.out_slot.val();
        self.slots.ret.next = self.rets.ret_valid.val();
        self.slots.ret_label.next = bit_cast::<16, SLOT_BITS>(self.rets.ret_slot.val());
        self.slots.take.next = self.slot_take.val();
        self.slot_ok.next = self.slots.free_ok.val();
        self.slot.next = self.slots.free_label.val().get_bits::<SLOT_BITS>(0);
        self.slots_free.next = self.slots.free_count.val();
        self.labels.ret.next = self.lists.ret_valid.val();
        self.labels.ret_label.next = self.lists.ret_label.val();
        self.labels.take.next = self.label_take.val();
        self.free_ok.next = self.labels.free_ok.val();
        self.free_label.next = self.labels.free_label.val();
        self.labels_free.next = self.labels.free_count.val();
        self.calm.next = self.ops.calm.val()
            & self.closer.caught_up.val()
            & self.records.idle.val()
            & self.out.idle.val()
            & self.lists.idle.val()
            & self.rets.empty.val()
            & !self.ends.ending.val();
        self.bad.next = self.rets.bad.val();
    }
}
