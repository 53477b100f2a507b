//! `FccRepReplay`: stage R of the representative rows (docs/column-core.md,
//! item 3). The pixel goes out in its first cycle in R, with its first
//! join (or, with none, at the last column, the ring check's pair). With
//! more to send, it holds every stage before it while it
//! finds the first flag left (`Pick`), takes its value and sends it
//! (`Take`), then clears its equals (`Check`): three cycles a further
//! join, and one to find none left. At the last column it then sends the
//! ring check's pair (`Ring`). So a pixel's joins follow it, all of them
//! before the next pixel; `more` says the pixel out last has joins still
//! to come (it falls with the last, or a cycle after it when `Pick` only
//! then finds none left), and its slot's marker waits for them. A join's
//! `x` of `0xFFFF` is the run the pixel started (`FccRepFront`'s
//! `push_rep`): it goes out as the pixel's label, `under` high (the run
//! filed under its neighbours' cluster, `m`).
//!
//! Every stage before R moves on `go`, high while R does not hold: a
//! register of its own, the complement of R's busy flag, so that the
//! thousands of registers it enables take it straight to their clock
//! enables, with no inverter each, and Vivado replicates it
//! (`FccFanoutReg`). It powers up low, a cycle in which nothing moves.

use rust_hdl::prelude::*;

use super::fcc_rep_first::FccRepFirst;
use super::fcc_rep_take::FccRepTake;
use super::RunPix;
use crate::fcc_fanout_reg::FccFanoutReg;
use crate::types::{kb, vec_of};

/// What R does next while it holds a pixel.
#[derive(Copy, Clone, Debug, PartialEq, LogicState)]
pub enum ReplayStep {
    Idle,
    Pick,
    Take,
    Check,
    Ring,
}

#[derive(LogicBlock)]
pub struct FccRepReplay {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// F's pixel (`FccRepSieve`), taken on `go`.
    pub f_pix: Signal<In, RunPix>,
    pub f_m: Signal<In, Bits<16>>,
    pub f_x: Signal<In, Bits<16>>,
    pub f_any: Signal<In, Bit>,
    pub f_more: Signal<In, Bit>,
    pub f_left: Vec<Signal<In, Bit>>,
    pub f_val: Vec<Signal<In, Bits<16>>>,
    /// The stages before R move this cycle.
    pub go: Signal<Out, Bit>,
    pub out: Signal<Out, RunPix>,
    /// The pixel out last has joins still to come after this cycle's.
    pub more: Signal<Out, Bit>,
    pub j_valid: Signal<Out, Bit>,
    pub j_a: Signal<Out, Bits<16>>,
    pub j_b: Signal<Out, Bits<16>>,
    /// `j_a` is the run the pixel started, filed under `j_b`'s cluster.
    pub under: Signal<Out, Bit>,
    /// The join is the ring check's pair.
    pub seam: Signal<Out, Bit>,
    first: FccRepFirst,
    take: FccRepTake,
    r_pix: DFF<RunPix>,
    r_rem: Vec<DFF<Bit>>,
    r_first: Vec<DFF<Bit>>,
    r_val: Vec<DFF<Bits<16>>>,
    r_m: DFF<Bits<16>>,
    r_x: FccFanoutReg<Bits<16>>,
    r_emit: DFF<Bit>,
    r_step: DFF<ReplayStep>,
    rb: DFF<Bit>,
    /// `rb`'s next value; `go_q` holds its complement.
    rb_n: Signal<Local, Bit>,
    go_q: FccFanoutReg<Bit>,
    /// R's pixel is new: it goes out this cycle.
    r_new: DFF<Bit>,
    /// The flags left with the value just sent cleared.
    rem2: Vec<Signal<Local, Bit>>,
    pix_zero: Constant<RunPix>,
    none: Constant<Bits<16>>,
}

impl FccRepReplay {
    /// `n` window positions.
    pub fn new(n: usize) -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            f_pix: Default::default(),
            f_m: Default::default(),
            f_x: Default::default(),
            f_any: Default::default(),
            f_more: Default::default(),
            f_left: vec_of(n),
            f_val: vec_of(n),
            go: Default::default(),
            out: Default::default(),
            more: Default::default(),
            j_valid: Default::default(),
            j_a: Default::default(),
            j_b: Default::default(),
            under: Default::default(),
            seam: Default::default(),
            first: FccRepFirst::new(n),
            take: FccRepTake::new(n),
            r_pix: Default::default(),
            r_rem: vec_of(n),
            r_first: vec_of(n),
            r_val: vec_of(n),
            r_m: Default::default(),
            r_x: Default::default(),
            r_emit: Default::default(),
            r_step: Default::default(),
            rb: Default::default(),
            rb_n: Default::default(),
            go_q: Default::default(),
            r_new: Default::default(),
            rem2: vec_of(n),
            pix_zero: Constant::new(RunPix::default()),
            none: kb(0xFFFF),
        }
    }
}

impl Logic for FccRepReplay {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clk, r_pix, r_m, r_x, r_emit, r_step, rb, r_new);
        self.go_q.clock.next = self.clk.val();
        self.rb_n.next = self.rb.q.val();
        for b in 0..self.f_left.len() {
            self.r_rem[b].clock.next = self.clk.val();
            self.r_first[b].clock.next = self.clk.val();
            self.r_val[b].clock.next = self.clk.val();
            self.r_rem[b].d.next = self.r_rem[b].q.val();
            self.r_first[b].d.next = self.r_first[b].q.val();
            self.r_val[b].d.next = self.r_val[b].q.val();
            self.first.flag[b].next = self.r_rem[b].q.val();
            self.take.first[b].next = self.r_first[b].q.val();
            self.take.val[b].next = self.r_val[b].q.val();
            self.rem2[b].next = self.r_rem[b].q.val() & (self.r_val[b].q.val() != self.r_x.q.val());
        }
        if self.go_q.q.val() {
            // R takes F's pixel.
            self.r_pix.d.next = self.f_pix.val();
            self.r_new.d.next = self.f_pix.val().valid;
            self.r_m.d.next = self.f_m.val();
            self.r_x.d.next = self.f_x.val();
            self.r_emit.d.next = self.f_pix.val().valid & self.f_any.val();
            for b in 0..self.f_left.len() {
                self.r_rem[b].d.next = self.f_left[b].val();
                self.r_val[b].d.next = self.f_val[b].val();
            }
            self.r_step.d.next = ReplayStep::Idle;
            if self.f_pix.val().valid & self.f_pix.val().ring {
                self.r_step.d.next = ReplayStep::Ring;
                self.rb_n.next = true;
            }
            if self.f_pix.val().valid & self.f_more.val() {
                self.r_step.d.next = ReplayStep::Pick;
                self.rb_n.next = true;
            }
        } else {
            self.r_emit.d.next = false;
            self.r_new.d.next = false;
            match self.r_step.q.val() {
                ReplayStep::Idle => {}
                ReplayStep::Pick => {
                    for b in 0..self.f_left.len() {
                        self.r_first[b].d.next = self.first.first[b].val();
                    }
                    if self.first.any.val() {
                        self.r_step.d.next = ReplayStep::Take;
                    } else if self.r_pix.q.val().ring {
                        self.r_step.d.next = ReplayStep::Ring;
                    } else {
                        self.r_step.d.next = ReplayStep::Idle;
                        self.rb_n.next = false;
                    }
                }
                ReplayStep::Take => {
                    self.r_x.d.next = self.take.x.val();
                    self.r_emit.d.next = true;
                    self.r_step.d.next = ReplayStep::Check;
                    for b in 0..self.f_left.len() {
                        self.r_rem[b].d.next = self.r_rem[b].q.val() & !self.r_first[b].q.val();
                    }
                }
                ReplayStep::Check => {
                    self.r_step.d.next = ReplayStep::Pick;
                    for b in 0..self.f_left.len() {
                        self.r_rem[b].d.next = self.rem2[b].val();
                    }
                }
                ReplayStep::Ring => {
                    if !self.r_emit.q.val() {
                        self.r_step.d.next = ReplayStep::Idle;
                        self.rb_n.next = false;
                    }
                }
            }
        }
        // Out: R's pixel in its first cycle, R's join in any.
        self.go.next = self.go_q.q.val();
        self.more.next =
            self.rb.q.val() & !((self.r_step.q.val() == ReplayStep::Ring) & !self.r_emit.q.val());
        self.j_valid.next = self.r_pix.q.val().valid
            & (self.r_emit.q.val() | ((self.r_step.q.val() == ReplayStep::Ring) & self.rb.q.val()));
        self.j_a.next = self.r_pix.q.val().ring_a;
        self.j_b.next = self.r_pix.q.val().ring_b;
        self.under.next = false;
        self.seam.next = !self.r_emit.q.val();
        if self.r_emit.q.val() {
            self.j_a.next = self.r_x.q.val();
            self.j_b.next = self.r_m.q.val();
            // The run the pixel started, named by `0xFFFF` until its
            // rewrite (`FccRepFront`): its label.
            if self.r_x.q.val() == self.none.val() {
                self.j_a.next = self.r_pix.q.val().label;
                self.under.next = true;
            }
        }
        self.out.next = self.pix_zero.val();
        if self.r_new.q.val() {
            self.out.next = self.r_pix.q.val();
        }
        if self.rst.val() {
            self.r_new.d.next = false;
            self.r_pix.d.next = self.pix_zero.val();
            self.r_emit.d.next = false;
            self.r_step.d.next = ReplayStep::Idle;
            self.rb_n.next = false;
        }
        self.rb.d.next = self.rb_n.val();
        self.go_q.d.next = !self.rb_n.val();
    }
}
