//! Run parameters: one core, built for its limits, programmed per frame
//! through the run registers (RUN_K, RUN_TH_H, RUN_TH_V, RUN_ROWS, RUN_COLS,
//! RUN_SLOPE_H, RUN_SLOPE_V).

use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_rtl::regmap::{self, offset};

use crate::axil::AxilMaster;
use crate::check::{compare, expected};
use crate::drive::{Drive, FrameRun};
use crate::model::Dut;
use crate::SimError;

/// The run registers and the values that program `run` (thresholds as
/// Q7.8 integers and slopes as UQ0.16, the golden model's quantisation);
/// for the column core also its stream limits.
pub fn run_values(run: &FccParams) -> Vec<(&'static str, u32, u32)> {
    let mut v = vec![
        ("RUN_K", offset::RUN_K, run.fsize as u32),
        ("RUN_TH_H", offset::RUN_TH_H, run.th_h_q() as u32),
        ("RUN_TH_V", offset::RUN_TH_V, run.th_v_q() as u32),
        ("RUN_ROWS", offset::RUN_ROWS, run.rows as u32),
        ("RUN_COLS", offset::RUN_COLS, run.cols as u32),
        (
            "RUN_SLOPE_H",
            offset::RUN_SLOPE_H,
            run.th_h_slope_q() as u32,
        ),
        (
            "RUN_SLOPE_V",
            offset::RUN_SLOPE_V,
            run.th_v_slope_q() as u32,
        ),
    ];
    if run.scan == fcc_params::Scan::Column {
        v.extend(regmap::stream_limit_values(run));
    }
    v
}

/// Whether the core built for `build` can run a frame with `run`: the
/// rules its run registers enforce (`regmap::run_value_ok`), and the build's
/// label width and labels per beat. The error names the value and the range.
pub fn check_run(build: &FccParams, run: &FccParams) -> Result<(), SimError> {
    run.validate()
        .map_err(|e| SimError::BadRun(e.to_string()))?;
    if run.label_bits != build.label_bits || run.labels_per_beat != build.labels_per_beat {
        return Err(SimError::BadRun(format!(
            "label_bits {} and labels_per_beat {} are the build's ({} and {})",
            run.label_bits, run.labels_per_beat, build.label_bits, build.labels_per_beat
        )));
    }
    if run.scan != build.scan {
        return Err(SimError::BadRun(format!(
            "scan {} is the build's ({})",
            run.scan.as_str(),
            build.scan.as_str()
        )));
    }
    for (name, off, v) in run_values(run) {
        if !regmap::run_value_ok(build, off, v) {
            let r = regmap::run_range(build, off).expect("a run register");
            let odd = if off == offset::RUN_K { "odd, " } else { "" };
            return Err(SimError::BadRun(format!(
                "{name} = {v} is out of range for this build: {odd}{} ..= {}",
                r.min, r.max
            )));
        }
    }
    Ok(())
}

impl Dut {
    /// Write the run registers for `run` (between frames), then check that
    /// none was refused and that each reads back.
    pub fn program_run(&mut self, run: &FccParams) -> Result<(), SimError> {
        let mut m = AxilMaster::new(self.cycle);
        for (_, off, v) in run_values(run) {
            m.write_ok(self, off, v)?;
        }
        let err = m.read(self, offset::ERROR)?;
        if err != 0 {
            return Err(SimError::Mismatch(format!(
                "ERROR = {err:#x} after programming rows {} cols {} fsize {} th_h {} th_v {} th_h_slope {} th_v_slope {}",
                run.rows, run.cols, run.fsize, run.th_h, run.th_v, run.th_h_slope, run.th_v_slope
            )));
        }
        for (name, off, v) in run_values(run) {
            let got = m.read(self, off)?;
            if got != v {
                return Err(SimError::Mismatch(format!(
                    "{name} reads back {got} after writing {v}"
                )));
            }
        }
        Ok(())
    }
}

/// Program `run` into the core, run `frame` (of `run`'s size) and compare it
/// with the golden model called with `run`; the status registers too.
pub fn run_and_check_with(
    dut: &mut Dut,
    run: &FccParams,
    frame: &Frame,
    drive: &Drive,
    what: &str,
) -> Result<FrameRun, SimError> {
    dut.program_run(run)?;
    let gold = expected(run, frame)?;
    let out = dut.run_frame(frame, drive)?;
    let what = format!("{what} seed {}", drive.seed);
    compare(run, &gold, &out, &what)?;
    crate::check_status_registers(dut, &out, &what)?;
    Ok(out)
}
