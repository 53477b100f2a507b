//! `FccRecordOut`: the core's record stream (spec §9.4), AXI4-Stream
//! style. `load` (taken while `idle`) keeps a closed cluster's
//! accumulator, id and closing column; `FccRecBeats` registers the
//! record's fields from them (`Prep`, one cycle), then its 11 beats follow
//! (`Send`), beat 0 first, each held while `valid` and not `ready`.
//! `load_end` (taken while `idle`) sends the frame's end beat (`End`): `id`
//! 0, the records sent since the last end beat, the `overflow` and
//! `frame_error` given with it, and `last` (the stream's `tlast`), which no
//! record beat has. Records and end beats leave in the order of their
//! loads; `idle` rises after a load's last beat is taken.

use rust_hdl::prelude::*;

use super::fcc_rec_beats::FccRecBeats;
use super::AccWord;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::kb;
use fcc_pixel::record::{EndField, END_LAYOUT, RECORD_WORDS};

/// Where the output is (see the module doc).
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum OutState {
    Idle,
    Prep,
    Send,
    End,
}

#[derive(LogicBlock)]
pub struct FccRecordOut {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    pub load: Signal<In, Bit>,
    pub acc: Signal<In, AccWord>,
    pub id: Signal<In, Bits<20>>,
    pub closed_col: Signal<In, Bits<13>>,
    pub load_end: Signal<In, Bit>,
    pub overflow: Signal<In, Bit>,
    pub frame_error: Signal<In, Bit>,
    pub idle: Signal<Out, Bit>,
    pub ready: Signal<In, Bit>,
    pub valid: Signal<Out, Bit>,
    pub beat: Signal<Out, Bits<64>>,
    pub last: Signal<Out, Bit>,
    rec: DFF<AccWord>,
    rid: DFF<Bits<20>>,
    rclosed: DFF<Bits<13>>,
    count: FccFanoutReg<Bits<4>>,
    state: DFF<OutState>,
    /// Records sent since the last end beat, counted in place in the end
    /// beat (masked to the field's bits there).
    records: DFF<Bits<64>>,
    /// The end beat's flags, each at its place in the beat.
    ovf_word: DFF<Bits<64>>,
    err_word: DFF<Bits<64>>,
    beats: FccRecBeats,
    /// The end beat's field positions (`END_LAYOUT`).
    records_one: Constant<Bits<64>>,
    records_mask: Constant<Bits<64>>,
    ovf_mask: Constant<Bits<64>>,
    err_mask: Constant<Bits<64>>,
    zero64: Constant<Bits<64>>,
    last_beat: Constant<Bits<4>>,
    one4: Constant<Bits<4>>,
    zero4: Constant<Bits<4>>,
}

impl Default for FccRecordOut {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            load: Default::default(),
            acc: Default::default(),
            id: Default::default(),
            closed_col: Default::default(),
            load_end: Default::default(),
            overflow: Default::default(),
            frame_error: Default::default(),
            idle: Default::default(),
            ready: Default::default(),
            valid: Default::default(),
            beat: Default::default(),
            last: Default::default(),
            rec: Default::default(),
            rid: Default::default(),
            rclosed: Default::default(),
            count: Default::default(),
            state: Default::default(),
            records: Default::default(),
            ovf_word: Default::default(),
            err_word: Default::default(),
            beats: Default::default(),
            records_one: kb(1 << end_lsb(EndField::Records, 20)),
            records_mask: kb(((1 << 20) - 1) << end_lsb(EndField::Records, 20)),
            ovf_mask: kb(1 << end_lsb(EndField::Overflow, 1)),
            err_mask: kb(1 << end_lsb(EndField::FrameError, 1)),
            zero64: kb(0),
            last_beat: kb(RECORD_WORDS as u64 - 1),
            one4: kb(1),
            zero4: kb(0),
        }
    }
}

/// Where `field` of the end beat lies; its width must be the block's.
fn end_lsb(field: EndField, bits: u32) -> u64 {
    let l = END_LAYOUT
        .iter()
        .find(|l| l.field == field)
        .expect("every end-beat field is in END_LAYOUT");
    assert_eq!(l.bits, bits, "end beat field {}: width", l.name);
    u64::from(l.lsb)
}

impl Logic for FccRecordOut {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, rec, rid, rclosed, count, state, records, ovf_word, err_word);
        if self.load.val() & (self.state.q.val() == OutState::Idle) {
            self.rec.d.next = self.acc.val();
            self.rid.d.next = self.id.val();
            self.rclosed.d.next = self.closed_col.val();
            self.count.d.next = self.zero4.val();
            self.state.d.next = OutState::Prep;
        }
        if self.load_end.val() & !self.load.val() & (self.state.q.val() == OutState::Idle) {
            self.ovf_word.d.next = self.zero64.val();
            if self.overflow.val() {
                self.ovf_word.d.next = self.ovf_mask.val();
            }
            self.err_word.d.next = self.zero64.val();
            if self.frame_error.val() {
                self.err_word.d.next = self.err_mask.val();
            }
            self.state.d.next = OutState::End;
        }
        if self.state.q.val() == OutState::Prep {
            self.state.d.next = OutState::Send;
        }
        self.beats.clk.next = self.clk.val();
        self.beats.sel.next = self.count.q.val();
        self.beats.id.next = self.rid.q.val();
        self.beats.closed_col.next = self.rclosed.q.val();
        self.beats.points.next = self.rec.q.val().points;
        self.beats.min_col.next = self.rec.q.val().min_col;
        self.beats.max_col.next = self.rec.q.val().max_col;
        self.beats.lo_has.next = self.rec.q.val().lo_has;
        self.beats.lo_max.next = self.rec.q.val().lo_max;
        self.beats.hi_has.next = self.rec.q.val().hi_has;
        self.beats.hi_min.next = self.rec.q.val().hi_min;
        self.beats.first_row.next = self.rec.q.val().first_row;
        self.beats.last_row.next = self.rec.q.val().last_row;
        self.beats.min_x.next = self.rec.q.val().min_x;
        self.beats.min_y.next = self.rec.q.val().min_y;
        self.beats.min_z.next = self.rec.q.val().min_z;
        self.beats.max_x.next = self.rec.q.val().max_x;
        self.beats.max_y.next = self.rec.q.val().max_y;
        self.beats.max_z.next = self.rec.q.val().max_z;
        self.beats.r2_min.next = self.rec.q.val().r2_min;
        self.beats.r2_max.next = self.rec.q.val().r2_max;
        self.beats.sa.next = self.rec.q.val().sa;
        self.beats.sb.next = self.rec.q.val().sb;
        self.beats.sc.next = self.rec.q.val().sc;
        self.beats.sxx.next = self.rec.q.val().sxx;
        self.beats.syy.next = self.rec.q.val().syy;
        self.beats.sab.next = self.rec.q.val().sab;
        self.beats.seam.next = self.rec.q.val().seam;
        self.valid.next =
            (self.state.q.val() == OutState::Send) | (self.state.q.val() == OutState::End);
        self.beat.next = self.beats.beat.val();
        if self.state.q.val() == OutState::End {
            self.beat.next = ((self.records.q.val() & self.records_mask.val())
                | self.ovf_word.q.val())
                | self.err_word.q.val();
        }
        self.last.next = self.state.q.val() == OutState::End;
        if (self.state.q.val() == OutState::Send) & self.ready.val() {
            self.count.d.next = self.count.q.val() + self.one4.val();
            if self.count.q.val() == self.last_beat.val() {
                self.records.d.next = self.records.q.val() + self.records_one.val();
                self.state.d.next = OutState::Idle;
            }
        }
        if (self.state.q.val() == OutState::End) & self.ready.val() {
            self.records.d.next = self.zero64.val();
            self.state.d.next = OutState::Idle;
        }
        self.idle.next = self.state.q.val() == OutState::Idle;
        if self.rst.val() {
            self.state.d.next = OutState::Idle;
            self.records.d.next = self.zero64.val();
        }
    }
}
