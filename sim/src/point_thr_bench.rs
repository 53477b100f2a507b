//! The per-point threshold unit `fcc_point_thr` alone under Verilator: built
//! (once, cached) from `fcc_rtl::generate_point_thr`, one point and the run
//! parameters in per cycle, its key and addends out `PT_LATENCY` cycles
//! later.

use std::ffi::c_void;
use std::sync::{Arc, OnceLock};

use fcc_params::FccParams;

use crate::block::{load_bench, BenchShim, BlockCache, BlockInstance, BlockModel};
use crate::ffi::c_struct;
use crate::SimError;

const SHIM: BenchShim = BenchShim {
    file: "fcc_point_thr_shim.cpp",
    text: include_str!("../csrc/fcc_point_thr_shim.cpp"),
    symbol: "fcc_point_thr",
};

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct PtIn {
        /// Fixed thresholds' addends, 36-bit two's complement:
        /// `-(tH^2 + 1)` and `-tV^2`.
        pub ch_t: u64,
        pub cv_t: u64,
        /// Squared slopes `S = A^2 >> 8` (24 bits).
        pub sh: u32,
        pub sv: u32,
        /// The point, offset binary.
        pub x: u16,
        pub y: u16,
        pub z: u16,
        /// Clears the key register.
        pub rst: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct PtOut {
        /// `-(T'_H + 1)` and `-T'_V`, 36-bit two's complement.
        pub ch: u64,
        pub cv: u64,
        /// The coarse squared range (square metres).
        pub key: u16,
    }
}

type StepFn = unsafe extern "C" fn(*mut c_void, *const PtIn, *mut PtOut);

/// A loaded Verilator model of `fcc_point_thr`.
pub type PtModel = BlockModel<StepFn>;

/// Load the threshold unit's model (named for the build `p`), building it
/// if needed.
pub fn load_point_thr(p: &FccParams) -> Result<Arc<PtModel>, SimError> {
    static MODELS: BlockCache<StepFn> = OnceLock::new();
    load_bench(&MODELS, fcc_rtl::BenchBlock::PointThr, p, &SHIM, &[])
}

/// One simulated threshold unit.
pub struct PointThrDut {
    dut: BlockInstance<StepFn>,
}

impl PointThrDut {
    pub fn new(model: Arc<PtModel>) -> Self {
        let dut = BlockInstance::new(model);
        PointThrDut { dut }
    }

    /// One cycle with `inp`; the outputs seen before the clock edge.
    pub fn step(&mut self, inp: &PtIn) -> PtOut {
        let mut out = PtOut::default();
        let (step, handle) = self.dut.step_fn();
        // SAFETY: `handle` is live; both pointers refer to `repr(C)` values.
        unsafe { step(handle, inp, &mut out) };
        out
    }
}
