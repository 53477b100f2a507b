//! The Verilator harness of the FCC core.
//!
//! [`model::load`] builds (once, cached) and loads a Verilator model of the
//! generated `fcc_top` for any valid [`FccParams`]; [`Dut`] drives frames
//! through its AXI4-Stream ports with optional input gaps and output
//! back-pressure; [`check::compare`] compares every label with the golden
//! model and reports the first differing pixel.

pub mod check;
pub mod drive;
pub mod frames;
pub mod model;

use std::path::PathBuf;

pub use check::{compare, expected};
pub use drive::{frame_beats, Drive, FrameRun, Tlast};
pub use model::{cache_root, is_cached, load, Dut, Model};

/// Everything that can go wrong in a simulation.
#[derive(Debug, thiserror::Error)]
pub enum SimError {
    #[error(transparent)]
    Rtl(#[from] fcc_rtl::RtlError),
    #[error(transparent)]
    Golden(#[from] fcc_golden::GoldenError),
    #[error("cannot run {tool}: {message}; install Verilator 5 and a C++ compiler (Debian: apt-get install verilator g++)")]
    Tool { tool: String, message: String },
    #[error("building the Verilator model failed in {step}:\n{log}")]
    Build { step: String, log: String },
    #[error("cannot load the Verilator model {path}: {source}")]
    Load {
        path: PathBuf,
        source: libloading::Error,
    },
    #[error("I/O error on {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("no frame completion after {cycles} cycles ({accepted} beats accepted, {emitted} labels out)")]
    Timeout {
        cycles: u64,
        accepted: usize,
        emitted: usize,
    },
    #[error("AXI4-Stream protocol: {0}")]
    Protocol(String),
    #[error("{0}")]
    Mismatch(String),
}

/// Run one frame on a fresh reset of `dut` and compare it with the golden model.
pub fn run_and_check(
    dut: &mut Dut,
    frame: &fcc_golden::Frame,
    drive: &Drive,
    what: &str,
) -> Result<FrameRun, SimError> {
    let p = dut.params().clone();
    let gold = expected(&p, frame)?;
    let run = dut.run_frame(frame, drive)?;
    compare(&p, &gold, &run, &format!("{what} seed {}", drive.seed))?;
    Ok(run)
}
