//! The window `fcc_window` and its line buffers alone under Verilator: built
//! (once, cached) from `fcc_rtl::generate_window`, driven one pixel per cycle
//! through the scalar ports of `fcc_window_probe`, every window entry read
//! back in every cycle.

use std::ffi::c_void;
use std::sync::{Arc, OnceLock};

use fcc_params::FccParams;

use crate::block::{load_bench, BenchShim, BlockCache, BlockInstance, BlockModel};
use crate::ffi::c_struct;
use crate::SimError;

const SHIM: BenchShim = BenchShim {
    file: "fcc_window_shim.cpp",
    text: include_str!("../csrc/fcc_window_shim.cpp"),
    symbol: "fcc_window",
};

c_struct! {
    /// Inputs of one cycle: the W0 pixel and the run size.
    pub struct WinIn {
        pub in_x: u16,
        pub in_y: u16,
        pub in_z: u16,
        pub in_col: u16,
        pub in_rdcol: u16,
        pub last_col: u16,
        pub in_row: u8,
        pub in_valid: u8,
        pub in_lok: u8,
        pub run_k: u8,
        pub rst: u8,
    }
}

c_struct! {
    /// The W3 centre during one cycle (its entries come apart, see [`WindowDut::step`]).
    pub struct WinOut {
        pub centre_x: u16,
        pub centre_col: u16,
        pub centre_valid: u8,
    }
}

type StepFn = unsafe extern "C" fn(*mut c_void, *const WinIn, *mut WinOut, *mut u64, u32);

/// A loaded Verilator model of `fcc_window_probe`.
pub type WindowModel = BlockModel<StepFn>;

/// Load the window model of the build `p`, building it if needed.
pub fn load_window(p: &FccParams) -> Result<Arc<WindowModel>, SimError> {
    static MODELS: BlockCache<StepFn> = OnceLock::new();
    load_bench(&MODELS, fcc_rtl::BenchBlock::Window, p, &SHIM, &[])
}

/// One window entry as the probe reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct WinEntry {
    pub ok: bool,
    pub x: u16,
    pub y: u16,
    pub z: u16,
}

/// One simulated window.
pub struct WindowDut {
    dut: BlockInstance<StepFn>,
    entries: Vec<u64>,
}

impl WindowDut {
    /// An instance of `model`, the window model of the build `p`.
    pub fn new(model: Arc<WindowModel>, p: &FccParams) -> Self {
        let dut = BlockInstance::new(model);
        let entries = vec![0; p.window_positions()];
        WindowDut { dut, entries }
    }

    /// One cycle with `inp`: the centre and its `K*h` entries (row-major
    /// from the top row) seen before the clock edge.
    pub fn step(&mut self, inp: &WinIn) -> (WinOut, Vec<WinEntry>) {
        let mut out = WinOut::default();
        let (step, handle) = self.dut.step_fn();
        // SAFETY: `handle` is live; `entries` holds the model's entry count.
        unsafe {
            step(
                handle,
                inp,
                &mut out,
                self.entries.as_mut_ptr(),
                self.entries.len() as u32,
            )
        };
        let ents = self
            .entries
            .iter()
            .map(|&w| WinEntry {
                ok: (w >> 48) & 1 == 1,
                x: w as u16,
                y: (w >> 16) as u16,
                z: (w >> 32) as u16,
            })
            .collect();
        (out, ents)
    }
}
