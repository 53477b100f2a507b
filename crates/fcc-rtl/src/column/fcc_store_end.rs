//! `FccStoreEnd`: the record store's frame end (docs/column-core.md, item
//! 4 and item 8, "The record store half"). When the frame end's marker
//! (column `C`) is at the head of the union-find queue's events
//! (`ev_end`), every op before it is in the store (the rows' last runs'
//! finds among them), and once the closer has caught up with the last
//! column (`caught_up`) and no marker or close is under way (`calm`):
//!
//! 1. `Run` to `Peek`: the closer's list is cleared (`clear`) and
//!    `ending` rises: the closer's reports are due at the end column and
//!    its closes are ends;
//! 2. `Peek`: every slot is peeked, `1 ..= max_slot` one a cycle at most
//!    (`peek_*`), so that each slot with a record (ring-held clusters too)
//!    is reported; with the last peek's taking the end column is marked
//!    (`end_mark`, behind the peeks' reports);
//! 3. `Drain`: the closes come as for any column, in the golden order;
//!    once the closer has caught up, nothing is under way and the record
//!    out is idle, the end beat is loaded (`load_end`);
//! 4. `Beat`: the marker is taken (`end_take`), the closer cleared for the
//!    next frame and the record ids restarted (`id_clear`).

use rust_hdl::prelude::*;

use super::fcc_label_sets::SLOT_BITS;
use crate::types::kb;

/// Where the frame end is.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum EndStep {
    Run,
    Peek,
    Drain,
    Beat,
}

#[derive(LogicBlock)]
pub struct FccStoreEnd {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub ev_end: Signal<In, Bit>,
    pub caught_up: Signal<In, Bit>,
    pub calm: Signal<In, Bit>,
    pub out_idle: Signal<In, Bit>,
    pub ending: Signal<Out, Bit>,
    pub clear: Signal<Out, Bit>,
    pub peek_valid: Signal<Out, Bit>,
    pub peek_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub peek_take: Signal<In, Bit>,
    pub end_mark: Signal<Out, Bit>,
    pub load_end: Signal<Out, Bit>,
    pub end_take: Signal<Out, Bit>,
    pub id_clear: Signal<Out, Bit>,
    step: DFF<EndStep>,
    slot: DFF<Bits<SLOT_BITS>>,
    last: Signal<Local, Bit>,
    one: Constant<Bits<SLOT_BITS>>,
    max_slot: Constant<Bits<SLOT_BITS>>,
}

impl Default for FccStoreEnd {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            ev_end: Default::default(),
            caught_up: Default::default(),
            calm: Default::default(),
            out_idle: Default::default(),
            ending: Default::default(),
            clear: Default::default(),
            peek_valid: Default::default(),
            peek_slot: Default::default(),
            peek_take: Default::default(),
            end_mark: Default::default(),
            load_end: Default::default(),
            end_take: Default::default(),
            id_clear: Default::default(),
            step: Default::default(),
            slot: Default::default(),
            last: Default::default(),
            one: kb(1),
            max_slot: kb((1 << SLOT_BITS) - 1),
        }
    }
}

impl Logic for FccStoreEnd {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, step, slot);
        self.ending.next = false;
        self.clear.next = false;
        self.peek_valid.next = false;
        self.peek_slot.next = self.slot.q.val();
        self.end_mark.next = false;
        self.load_end.next = false;
        self.end_take.next = false;
        self.id_clear.next = false;
        self.last.next = self.slot.q.val() == self.max_slot.val();
        match self.step.q.val() {
            EndStep::Run => {
                if self.ev_end.val() & self.caught_up.val() & self.calm.val() {
                    self.clear.next = true;
                    self.slot.d.next = self.one.val();
                    self.step.d.next = EndStep::Peek;
                }
            }
            EndStep::Peek => {
                self.ending.next = true;
                self.peek_valid.next = true;
                if self.peek_take.val() {
                    self.slot.d.next = self.slot.q.val() + self.one.val();
                    if self.last.val() {
                        self.end_mark.next = true;
                        self.step.d.next = EndStep::Drain;
                    }
                }
            }
            EndStep::Drain => {
                self.ending.next = true;
                if self.caught_up.val() & self.calm.val() & self.out_idle.val() {
                    self.load_end.next = true;
                    self.step.d.next = EndStep::Beat;
                }
            }
            EndStep::Beat => {
                self.end_take.next = true;
                self.clear.next = true;
                self.id_clear.next = true;
                self.step.d.next = EndStep::Run;
            }
            _ => {
                self.step.d.next = EndStep::Run;
            }
        }
        if self.rst.val() {
            self.step.d.next = EndStep::Run;
        }
    }
}
