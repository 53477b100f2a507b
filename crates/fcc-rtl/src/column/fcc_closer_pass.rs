//! `FccCloserPass`: the closer's passes over its wait list (`FccCloser`,
//! docs/column-core.md, item 4), one column at a time.
//!
//! * `Idle`: while a column up to the last one done (`done_col`) is still
//!   to pass (`pass_col`), a pass starts if an entry is due by it
//!   (`min_due <= pass_col`); otherwise `pass_col` moves on to the first
//!   column an entry is due, or past the column done.
//! * `Pass`: the entries in the list as it starts (`left`) are taken from
//!   its head one by one into `r1`: an entry due by `pass_col` goes into
//!   the sorted entries, another goes back at the tail (`FccCloserList`,
//!   which also puts back what the sorted entries drop when full, for the
//!   next pass of the same column). `r1` moves on once the list's write
//!   register is free.
//! * `Send`: the sorted entries' head is offered as a close at `pass_col`
//!   until they are empty.

use rust_hdl::prelude::*;

use super::fcc_close_order::CLOSE_KEY_BITS;
use super::fcc_closer::{WaitEntry, WAIT_BITS};
use super::fcc_label_sets::SLOT_BITS;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::kb;

/// The closer's state.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum CloserState {
    Idle,
    Pass,
    Send,
}

#[derive(LogicBlock)]
pub struct FccCloserPass {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// A report is written into the list this cycle.
    pub rd_valid: Signal<In, Bit>,
    pub done_col: Signal<In, Bits<12>>,
    pub marked: Signal<In, Bit>,
    /// The list: its entries, their smallest due column, its write
    /// register taken; its head, taken.
    pub used: Signal<In, Bits<WAIT_BITS>>,
    pub min_due: Signal<In, Bits<13>>,
    pub b_valid: Signal<In, Bit>,
    pub w_valid: Signal<In, Bit>,
    pub w_out: Signal<In, WaitEntry>,
    pub w_take: Signal<Out, Bit>,
    /// To the list: a pass starts; `r1` moves on (due if `p_r1n`).
    pub p_start: Signal<Out, Bit>,
    pub p_moves: Signal<Out, Bit>,
    pub p_r1n: Signal<Out, Bit>,
    pub p_r1: Signal<Out, WaitEntry>,
    /// The sorted entries: one in, the head and its pop.
    pub o_push: Signal<Out, Bit>,
    pub o_key: Signal<Out, Bits<CLOSE_KEY_BITS>>,
    pub o_slot: Signal<Out, Bits<SLOT_BITS>>,
    pub o_head_valid: Signal<In, Bit>,
    pub o_pop: Signal<Out, Bit>,
    /// The close offered (the head's slot and key beside it), taken; its
    /// column is the one being passed (the list's writes read it too).
    pub close_valid: Signal<Out, Bit>,
    pub close_col: Signal<Out, Bits<13>>,
    pub close_take: Signal<In, Bit>,
    /// Every column done is passed and its closes sent.
    pub caught_up: Signal<Out, Bit>,
    behind: Signal<Local, Bit>,
    start: Signal<Local, Bit>,
    moves: Signal<Local, Bit>,
    take: Signal<Local, Bit>,
    next_col: Signal<Local, Bits<13>>,
    /// `r1`, read field by field.
    e1: Signal<Local, WaitEntry>,
    state: DFF<CloserState>,
    pass_col: DFF<Bits<13>>,
    left: DFF<Bits<WAIT_BITS>>,
    // The entry taken, and whether it is due by `pass_col`.
    r1v: DFF<Bit>,
    r1: FccFanoutReg<WaitEntry>,
    r1n: DFF<Bit>,
    one: Constant<Bits<WAIT_BITS>>,
    col_one: Constant<Bits<13>>,
    col_zero: Constant<Bits<13>>,
}

impl Default for FccCloserPass {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            rd_valid: Default::default(),
            done_col: Default::default(),
            marked: Default::default(),
            used: Default::default(),
            min_due: Default::default(),
            b_valid: Default::default(),
            w_valid: Default::default(),
            w_out: Default::default(),
            w_take: Default::default(),
            p_start: Default::default(),
            p_moves: Default::default(),
            p_r1n: Default::default(),
            p_r1: Default::default(),
            o_push: Default::default(),
            o_key: Default::default(),
            o_slot: Default::default(),
            o_head_valid: Default::default(),
            o_pop: Default::default(),
            close_valid: Default::default(),
            close_col: Default::default(),
            close_take: Default::default(),
            caught_up: Default::default(),
            behind: Default::default(),
            start: Default::default(),
            moves: Default::default(),
            take: Default::default(),
            next_col: Default::default(),
            e1: Default::default(),
            state: Default::default(),
            pass_col: Default::default(),
            left: Default::default(),
            r1v: Default::default(),
            r1: Default::default(),
            r1n: Default::default(),
            one: kb(1),
            col_one: kb(1),
            col_zero: kb(0),
        }
    }
}

impl Logic for FccCloserPass {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, state, pass_col, left, r1v, r1, r1n);
        self.e1.next = self.r1.q.val();
        // Idle: the next pass, or the next column worth one.
        self.behind.next =
            self.marked.val() & (self.pass_col.q.val() <= bit_cast::<13, 12>(self.done_col.val()));
        self.start.next = (self.state.q.val() == CloserState::Idle)
            & self.behind.val()
            & (self.min_due.val() <= self.pass_col.q.val());
        self.next_col.next = bit_cast::<13, 12>(self.done_col.val()) + self.col_one.val();
        if self.min_due.val() < self.next_col.val() {
            self.next_col.next = self.min_due.val();
        }
        if (self.state.q.val() == CloserState::Idle) & self.behind.val() & !self.start.val() {
            self.pass_col.d.next = self.next_col.val();
        }
        if self.start.val() {
            self.state.d.next = CloserState::Pass;
            self.left.d.next = self.used.val();
        }
        // Pass: `r1` moves on once the list's `b` is free (written this
        // cycle, or empty); the head is taken into `r1` as it does.
        self.moves.next = self.r1v.q.val() & (!self.b_valid.val() | !self.rd_valid.val());
        self.take.next = (self.state.q.val() == CloserState::Pass)
            & self.w_valid.val()
            & self.left.q.val().any()
            & (!self.r1v.q.val() | self.moves.val());
        if self.moves.val() {
            self.r1v.d.next = false;
        }
        if self.take.val() {
            self.r1v.d.next = true;
            self.r1.d.next = self.w_out.val();
            self.r1n.d.next = self.w_out.val().due <= self.pass_col.q.val();
            self.left.d.next = self.left.q.val() - self.one.val();
        }
        if (self.state.q.val() == CloserState::Pass)
            & !self.left.q.val().any()
            & !self.r1v.q.val()
            & !self.b_valid.val()
        {
            self.state.d.next = CloserState::Send;
        }
        self.w_take.next = self.take.val();
        self.p_start.next = self.start.val();
        self.p_moves.next = self.moves.val();
        self.p_r1n.next = self.r1n.q.val();
        self.p_r1.next = self.e1.val();
        self.o_push.next = self.moves.val() & self.r1n.q.val();
        self.o_key.next = self.e1.val().key;
        self.o_slot.next = self.e1.val().slot;
        // Send: the head, at `pass_col`, until none is left.
        self.close_valid.next = (self.state.q.val() == CloserState::Send) & self.o_head_valid.val();
        self.close_col.next = self.pass_col.q.val();
        self.o_pop.next = self.close_valid.val() & self.close_take.val();
        if (self.state.q.val() == CloserState::Send) & !self.o_head_valid.val() {
            self.state.d.next = CloserState::Idle;
        }
        self.caught_up.next = (self.state.q.val() == CloserState::Idle) & !self.behind.val();
        if self.rst.val() {
            self.state.d.next = CloserState::Idle;
            self.pass_col.d.next = self.col_zero.val();
            self.r1v.d.next = false;
        }
    }
}
