//! The Verilator harness of the FCC core.
//!
//! [`model::load`] builds (once, cached) and loads a Verilator model of the
//! generated `fcc_top` for any valid [`FccParams`]; [`Dut`] drives frames
//! through its AXI4-Stream ports with optional input gaps and output
//! back-pressure; [`check::compare`] compares every label with the golden
//! model and reports the first differing pixel.

pub mod axil;
pub mod axil_adapter_bench;
pub mod block;
pub mod board;
pub mod check;
pub mod column;
pub mod core_form;
pub mod drive;
pub mod ffi;
pub mod frames;
pub mod label_update_bench;
pub mod merge_bench;
pub mod model;
pub mod plain;
pub mod point_thr_bench;
pub mod regs_bench;
pub mod run;
pub mod sort_net_bench;
pub mod window_bench;

use std::path::PathBuf;

pub use axil::{AxilM, AxilMaster, AxilPort, AxilS, WriteOrder};
pub use axil_adapter_bench::{load_axil_adapter, AdIn, AdOut, AxilAdapterDut};
pub use board::{
    build_expect, build_expect_for, build_run, virtual_board, virtual_board_with, AxiDmaModel,
    Fault, VBuffer, VirtualBoard,
};
pub use check::{compare, expected};
pub use drive::{frame_beats, Drive, FrameRun, Tlast};
pub use label_update_bench::{load_label_update, LuDut, LuIn, LuOut};
pub use merge_bench::{load_merge_table, MergeDut, MergeIn, MergeOut};
pub use model::{
    cache_root, is_cached, is_cached_dir, load, load_dir, read_generated, Dut, GeneratedDir, Model,
};
pub use plain::{load_plain, PlainDut, PlainModel};
pub use point_thr_bench::{load_point_thr, PointThrDut, PtIn, PtOut};
pub use regs_bench::{load_regs, RegsDut, RegsIn, RegsOut};
pub use run::{check_run, run_and_check_with, run_values};
pub use sort_net_bench::{load_sort_net, pack_centre, SnCentre, SnIn, SnOut, SortNetDut};
pub use window_bench::{load_window, WinEntry, WinIn, WinOut, WindowDut};

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
    /// Run parameters the build cannot run.
    #[error("{0}")]
    BadRun(String),
    #[error("virtual board: {0}")]
    Board(String),
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
    let what = format!("{what} seed {}", drive.seed);
    compare(&p, &gold, &run, &what)?;
    check_status_registers(dut, &run, &what)?;
    Ok(run)
}

/// Read the frame status through the AXI4-Lite registers (with BREADY /
/// RREADY stalls) and compare it with what the status ports said; check and
/// clear the sticky FRAME_DONE bit and that FRAME_COUNT moved on.
pub fn check_status_registers(dut: &mut Dut, run: &FrameRun, what: &str) -> Result<(), SimError> {
    use fcc_rtl::regmap::{bits, offset};
    let mut m = AxilMaster::new(dut.cycle);
    m.stall = 0.3;
    let flags = (u32::from(run.overflow) * bits::FLAGS_OVERFLOW)
        | (u32::from(run.frame_error) * bits::FLAGS_FRAME_ERROR);
    let expect = [
        ("CLUSTERS", offset::CLUSTERS, run.clusters),
        ("PROVISIONAL", offset::PROVISIONAL, run.provisional),
        ("UNLABELLED", offset::UNLABELLED, run.unlabelled),
        ("FRAME_FLAGS", offset::FRAME_FLAGS, flags),
        ("JOINS", offset::JOINS, run.joins),
        ("GEAR_STALLS", offset::GEAR_STALLS, run.gear_stalls),
    ];
    for (name, off, want) in expect {
        let got = m.read(dut, off)?;
        if got != want {
            return Err(SimError::Mismatch(format!(
                "{what}: register {name}: expected {want} != got {got}"
            )));
        }
    }
    let st = m.read(dut, offset::STATUS)?;
    if st & bits::STATUS_FRAME_DONE == 0 {
        return Err(SimError::Mismatch(format!(
            "{what}: STATUS.FRAME_DONE not set after the frame (STATUS {st:#x})"
        )));
    }
    m.write_ok(dut, offset::STATUS, bits::STATUS_FRAME_DONE)?;
    let st = m.read(dut, offset::STATUS)?;
    if st & bits::STATUS_FRAME_DONE != 0 {
        return Err(SimError::Mismatch(format!(
            "{what}: STATUS.FRAME_DONE not cleared by writing 1 (STATUS {st:#x})"
        )));
    }
    let count = m.read(dut, offset::FRAME_COUNT)?;
    if count <= dut.frames_seen {
        return Err(SimError::Mismatch(format!(
            "{what}: FRAME_COUNT {count} did not move on from {}",
            dut.frames_seen
        )));
    }
    dut.frames_seen = count;
    Ok(())
}
