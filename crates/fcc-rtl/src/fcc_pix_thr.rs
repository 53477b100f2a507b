//! `fcc_pix_thr`: the input pixels on their way to `fcc_intra`, with each
//! point's own thresholds (spec §2, range-adaptive). The pixel slot waits
//! `PIX_DELAY` cycles while an `FccPointThr` computes its key and addends,
//! which follow it `PT_LATENCY - PIX_DELAY` cycles later: just in time for
//! `fcc_intra`'s pair thresholds (`FccIntraThr`) to select one per pair
//! before its distance units add it.

use rust_hdl::prelude::*;

use crate::fcc_point_thr::{FccPointThr, PT_LATENCY};
use crate::types::Pix;

/// Cycles a pixel slot waits here.
pub const PIX_DELAY: usize = 6;

/// Cycles from a slot leaving here (`out`) to its thresholds (`key`, `ch`, `cv`).
pub const THR_LAG: usize = PT_LATENCY - PIX_DELAY;

// The delay line below is written out for six stages.
const _: () = assert!(PIX_DELAY == 6);

#[derive(LogicBlock)]
pub struct FccPixThr {
    pub clk: Signal<In, Clock>,
    pub rst: Signal<In, Bit>,
    /// Pixel slots from the input stage.
    pub pix: Signal<In, Pix>,
    /// Squared slopes `S = A^2 >> 8`, from the run parameters.
    pub sh: Signal<In, Bits<24>>,
    pub sv: Signal<In, Bits<24>>,
    /// Fixed thresholds' addends: `-(tH^2 + 1)` and `-tV^2`.
    pub ch_t: Signal<In, Bits<36>>,
    pub cv_t: Signal<In, Bits<36>>,
    /// The slots, `PIX_DELAY` cycles later.
    pub out: Signal<Out, Pix>,
    /// The thresholds of the slot that left `THR_LAG` cycles ago.
    pub key: Signal<Out, Bits<16>>,
    pub ch: Signal<Out, Bits<36>>,
    pub cv: Signal<Out, Bits<36>>,
    thr: FccPointThr,
    pd: Vec<DFF<Pix>>,
    pix_zero: Constant<Pix>,
}

impl FccPixThr {
    pub fn new() -> Self {
        Self {
            clk: Default::default(),
            rst: Default::default(),
            pix: Default::default(),
            sh: Default::default(),
            sv: Default::default(),
            ch_t: Default::default(),
            cv_t: Default::default(),
            out: Default::default(),
            key: Default::default(),
            ch: Default::default(),
            cv: Default::default(),
            thr: FccPointThr::new(),
            pd: (0..PIX_DELAY).map(|_| Default::default()).collect(),
            pix_zero: Constant::new(Pix::default()),
        }
    }
}

impl Default for FccPixThr {
    fn default() -> Self {
        Self::new()
    }
}

impl Logic for FccPixThr {
    #[hdl_gen]
    fn update(&mut self) {
        self.thr.clk.next = self.clk.val();
        self.thr.rst.next = self.rst.val();
        self.thr.x.next = self.pix.val().x;
        self.thr.y.next = self.pix.val().y;
        self.thr.z.next = self.pix.val().z;
        self.thr.sh.next = self.sh.val();
        self.thr.sv.next = self.sv.val();
        self.thr.ch_t.next = self.ch_t.val();
        self.thr.cv_t.next = self.cv_t.val();
        self.key.next = self.thr.key.val();
        self.ch.next = self.thr.ch.val();
        self.cv.next = self.thr.cv.val();
        for i in 0..6 {
            self.pd[i].clock.next = self.clk.val();
        }
        self.pd[0].d.next = self.pix.val();
        for i in 1..6 {
            self.pd[i].d.next = self.pd[i - 1].q.val();
        }
        if self.rst.val() {
            self.pd[0].d.next.valid = false;
            self.pd[1].d.next.valid = false;
            self.pd[2].d.next.valid = false;
            self.pd[3].d.next.valid = false;
            self.pd[4].d.next.valid = false;
            // The whole last stage is reset, so that it stays a flip-flop
            // (a shift-register LUT's output is slow).
            self.pd[5].d.next = self.pix_zero.val();
        }
        self.out.next = self.pd[5].q.val();
    }
}
