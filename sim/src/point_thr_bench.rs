//! The per-point threshold unit `fcc_point_thr` alone under Verilator: built
//! (once, cached) from `fcc_rtl::generate_point_thr`, one point and the run
//! parameters in per cycle, its key and addends out `PT_LATENCY` cycles
//! later.

use fcc_params::FccParams;

use crate::ffi::c_struct;
use crate::plain::{load_plain, PlainDut, PlainModel};
use crate::SimError;

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

/// A loaded Verilator model of `fcc_point_thr`.
pub type PtModel = PlainModel<PtIn, PtOut>;

/// One simulated threshold unit.
pub type PointThrDut = PlainDut<PtIn, PtOut>;

/// Load the threshold unit's model (named for the build `p`), building it
/// if needed.
pub fn load_point_thr(p: &FccParams) -> Result<PtModel, SimError> {
    load_plain(fcc_rtl::BenchBlock::PointThr, p)
}
