//! The paper's figures: its clock, frame time, CPU time and Table I.

use serde::{Deserialize, Serialize};

/// The clock of the paper's implementation, MHz.
pub const PAPER_CLOCK_MHZ: f64 = 203.6;
/// The paper's frame time on the FPGA, ms.
pub const PAPER_FRAME_MS: f64 = 1.93;
/// The paper's CPU time per frame (Table III), seconds: fastest and slowest.
pub const PAPER_CPU_S_PER_FRAME: [f64; 2] = [0.91, 6.29];

/// One row of the paper's Table I (Vivado, XC7Z045).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PaperRow {
    pub fsize: usize,
    pub lut: u64,
    pub ff: u64,
    pub dsp: u64,
    /// Block RAM tiles (RAMB36 equivalents).
    pub bram36: f64,
}

/// The paper's Table I.
pub const PAPER_TABLE_I: [PaperRow; 3] = [
    PaperRow {
        fsize: 3,
        lut: 4_810,
        ff: 5_477,
        dsp: 15,
        bram36: 359.5,
    },
    PaperRow {
        fsize: 5,
        lut: 6_591,
        ff: 7_482,
        dsp: 36,
        bram36: 361.5,
    },
    PaperRow {
        fsize: 7,
        lut: 9_304,
        ff: 10_222,
        dsp: 69,
        bram36: 362.5,
    },
];

/// The paper's Table I row for `fsize`, if it has one.
pub fn paper_row(fsize: usize) -> Option<PaperRow> {
    PAPER_TABLE_I.iter().copied().find(|r| r.fsize == fsize)
}
