//! Generate the RTL of one configuration and estimate it.

use std::path::{Path, PathBuf};

use fcc_params::FccParams;

use crate::yosys::{self, YosysConfig, YosysRun};
use crate::SynthError;

/// Subdirectory of the work directory that receives the generated RTL.
pub const RTL_SUBDIR: &str = "rtl";
/// Subdirectory of the work directory that receives the Yosys files.
pub const YOSYS_SUBDIR: &str = "yosys";

/// Write the RTL of `p` into `dir` and return its Verilog files.
pub fn generate_rtl(p: &FccParams, dir: &Path) -> Result<Vec<PathBuf>, SynthError> {
    let files = fcc_rtl::write_rtl(p, dir)?;
    let verilog: Vec<PathBuf> = files
        .into_iter()
        .filter(|f| f.extension().is_some_and(|e| e == "v"))
        .collect();
    if verilog.is_empty() {
        return Err(SynthError::NoVerilog(dir.to_path_buf()));
    }
    Ok(verilog)
}

/// The XDC of `p` (clock on `clk` at `p.clock_mhz`), as the RTL generator writes it.
pub fn xdc(p: &FccParams) -> String {
    fcc_rtl::vivado::xdc(p)
}

/// Generate the RTL of `p` under `work_dir/rtl` and synthesise it under `work_dir/yosys`.
pub fn estimate(p: &FccParams, work_dir: &Path, cfg: &YosysConfig) -> Result<YosysRun, SynthError> {
    let files = generate_rtl(p, &work_dir.join(RTL_SUBDIR))?;
    yosys::synthesize(&files, cfg, &work_dir.join(YOSYS_SUBDIR))
}

/// Synthesise the Verilog files already in `rtl_dir`, with the Yosys files under `work_dir`.
pub fn estimate_dir(
    rtl_dir: &Path,
    work_dir: &Path,
    cfg: &YosysConfig,
) -> Result<YosysRun, SynthError> {
    let files = yosys::verilog_files_in(rtl_dir)?;
    yosys::synthesize(&files, cfg, work_dir)
}
