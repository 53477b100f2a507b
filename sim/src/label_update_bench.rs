//! The label updater `fcc_label_update` alone under Verilator: built (once,
//! cached) from `fcc_rtl::generate_label_update`, fed frame-buffer codes and
//! compact labels, its output stream read with back-pressure.

use fcc_params::FccParams;

use crate::ffi::c_struct;
use crate::plain::{load_plain, PlainDut, PlainModel};
use crate::SimError;

c_struct! {
    /// Inputs of one cycle (declared to the shim by the generated `fcc_ffi.h`).
    pub struct LuIn {
        /// Compact label pushed into the gearbox (with `fv`).
        pub fval: u16,
        pub rst: u8,
        /// A labelled pixel's frame-buffer code (`wr_state`), the frame's last pixel.
        pub wr_valid: u8,
        pub wr_state: u8,
        pub wr_last: u8,
        /// Start of the read-back of the frame written.
        pub rb_start: u8,
        pub fv: u8,
        pub m_axis_tready: u8,
    }
}

c_struct! {
    /// Outputs during one cycle.
    pub struct LuOut {
        pub m_axis_tdata: u64,
        pub gear_stalls: u32,
        pub m_axis_tkeep: u8,
        pub m_axis_tvalid: u8,
        pub m_axis_tlast: u8,
        pub rb_done: u8,
        /// Compact labels waiting in the gearbox.
        pub gear_used: u8,
    }
}

/// A loaded Verilator model of `fcc_label_update`.
pub type LuModel = PlainModel<LuIn, LuOut>;

/// One simulated label updater.
pub type LuDut = PlainDut<LuIn, LuOut>;

/// Load the label-updater model of the build `p`, building it if needed.
pub fn load_label_update(p: &FccParams) -> Result<LuModel, SimError> {
    load_plain(fcc_rtl::BenchBlock::LabelUpdate, p)
}
