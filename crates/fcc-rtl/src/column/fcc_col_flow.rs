//! `FccColFlow`: the column core's frame sequence, for its top. A frame's
//! records leave well after its last pixel (the last columns close at the
//! frame end), so frames overlap: the next frame's pixels are taken while
//! the last one's records are still on their way. The run registers must
//! not change under a frame in either state, so:
//! - `quiet`: no frame is in the datapath (every frame whose last pixel
//!   went in has sent its end beat); counted here, +1 as a frame's input
//!   is done (`in_done` rises), -1 as an end beat is taken (`end_sent`);
//! - `load_next`: the input waits for a frame's first pixel and the core is
//!   quiet in the next cycle, the register file's `idle_next` (its active
//!   copies load then, and STATUS.IDLE reads it);
//! - `restart`: the next frame may start once the input stage is done with
//!   this one (`in_done`); while a register write is owed (`dirty`: any
//!   register was written since the last load) it waits for `quiet`, so a
//!   write takes effect at the next frame boundary even when frames come
//!   back to back. One pulse per frame;
//! - `start_hold`: high while the input waits for a frame's first pixel
//!   and a write is owed (or performed now), so that no frame starts until
//!   the registers have loaded (it holds the first pixel as the
//!   column-start check holds a column's);
//! - `reload_next`, `reload`: the registers load with a write owed (`dirty`,
//!   idle and quiet): the datapath is reset in the next cycle (`reload`,
//!   with `reload_next` its flip-flop's input, as the register file's
//!   `core_rst`), since its per-row state and tables follow the frame's
//!   size and K. Nothing is lost: no frame is in it, and no pixel is taken
//!   while `start_hold` is high (the reset's cycle drops the input's ready
//!   itself).

use rust_hdl::prelude::*;

use crate::types::kb;

#[derive(LogicBlock)]
pub struct FccColFlow {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// The input stage has taken the frame's last slot (until `restart`).
    pub in_done: Signal<In, Bit>,
    /// The input waits for a frame's first pixel (now, and in the next cycle).
    pub idle: Signal<In, Bit>,
    pub idle_next: Signal<In, Bit>,
    /// An end beat is taken (`tvalid`, `tready` and `tlast`).
    pub end_sent: Signal<In, Bit>,
    /// A register write is performed.
    pub written: Signal<In, Bit>,
    pub restart: Signal<Out, Bit>,
    pub quiet: Signal<Out, Bit>,
    pub load_next: Signal<Out, Bit>,
    pub start_hold: Signal<Out, Bit>,
    pub reload_next: Signal<Out, Bit>,
    pub reload: Signal<Out, Bit>,
    /// Frames in the datapath after their last pixel (short frames can
    /// queue up behind a long frame end; far fewer than 255).
    open: DFF<Bits<8>>,
    done_q: DFF<Bit>,
    restarted: DFF<Bit>,
    dirty: DFF<Bit>,
    reload_q: DFF<Bit>,
    /// A frame's input is done in this cycle.
    rise: Signal<Local, Bit>,
    zero8: Constant<Bits<8>>,
    one8: Constant<Bits<8>>,
}

impl Default for FccColFlow {
    fn default() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            in_done: Default::default(),
            idle: Default::default(),
            idle_next: Default::default(),
            end_sent: Default::default(),
            written: Default::default(),
            restart: Default::default(),
            quiet: Default::default(),
            load_next: Default::default(),
            start_hold: Default::default(),
            reload_next: Default::default(),
            reload: Default::default(),
            open: Default::default(),
            done_q: Default::default(),
            restarted: Default::default(),
            dirty: Default::default(),
            reload_q: Default::default(),
            rise: Default::default(),
            zero8: kb(0),
            one8: kb(1),
        }
    }
}

impl Logic for FccColFlow {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, open, done_q, restarted, dirty, reload_q);
        self.rise.next = self.in_done.val() & !self.done_q.q.val();
        self.done_q.d.next = self.in_done.val();
        if self.rise.val() & !self.end_sent.val() {
            self.open.d.next = self.open.q.val() + self.one8.val();
        }
        if !self.rise.val() & self.end_sent.val() {
            self.open.d.next = self.open.q.val() - self.one8.val();
        }
        self.quiet.next = self.open.q.val() == self.zero8.val();
        self.load_next.next = self.idle_next.val() & (self.open.d.val() == self.zero8.val());
        self.restart.next = self.in_done.val()
            & !self.restarted.q.val()
            & (!self.dirty.q.val() | (self.open.q.val() == self.zero8.val()));
        self.restarted.d.next = self.restart.val();
        // The registers load while idle and quiet; with a write owed, the
        // datapath is reset after.
        self.reload_next.next = false;
        if self.idle.val() & (self.open.q.val() == self.zero8.val()) {
            self.dirty.d.next = false;
            self.reload_next.next = self.dirty.q.val();
        }
        self.reload_q.d.next = self.reload_next.val();
        self.reload.next = self.reload_q.q.val();
        self.start_hold.next = self.idle.val() & (self.dirty.q.val() | self.written.val());
        if self.written.val() {
            self.dirty.d.next = true;
        }
        if self.rst.val() {
            self.open.d.next = self.zero8.val();
            self.done_q.d.next = false;
            self.restarted.d.next = false;
            self.dirty.d.next = false;
            self.reload_q.d.next = false;
        }
    }
}
