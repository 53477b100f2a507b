//! The Vivado path: run the project's non-project build script and read its
//! reports.
//!
//! Contract with the script the RTL generator writes beside the Verilog
//! (`scripts/fcc_build.tcl` of a generated layout, [`BUILD_SCRIPT`]):
//!
//! ```text
//! vivado -mode batch -nojournal -log OUT/vivado.log \
//!        -source <layout>/scripts/fcc_build.tcl -tclargs -out OUT
//! ```
//!
//! - the script reads `../rtl_out/fcc_top.v` and `../constraints/fcc_top.xdc`
//!   relative to itself, so each generated configuration carries its own;
//! - it synthesises, optimises, places and routes for the board's part (the
//!   ZC706's XC7Z045 for the layouts this crate generates) and writes
//!   [`UTILIZATION_REPORT`] (`report_utilization`) and [`TIMING_REPORT`]
//!   (`report_timing_summary`) under `OUT`;
//! - when the routed design misses the clock (WNS < 0) it writes the reports
//!   and then fails, so [`run_build`] reports a tool failure whose log tail
//!   names the slack.
//!
//! Vivado is not available where this crate was written: the report readers
//! follow the documented text layout of those two commands and are tested on
//! excerpts of it, not on a run.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde::{Deserialize, Serialize};

use crate::yosys::{start, TAIL};
use crate::{io_err, tail_lines, SynthError};

/// The build script, relative to the root of a generated layout.
pub const BUILD_SCRIPT: &str = "scripts/fcc_build.tcl";
/// The routed utilisation report, relative to the script's `-out` directory.
pub const UTILIZATION_REPORT: &str = "build/utilization_route.rpt";
/// The routed timing summary, relative to the script's `-out` directory.
pub const TIMING_REPORT: &str = "build/timing_route.rpt";
/// The XDC the script reads from the RTL directory.
pub const XDC_FILE: &str = "fcc_top.xdc";
/// How to get Vivado, for error messages.
pub const INSTALL: &str = "AMD Vivado, then `source <Vivado>/settings64.sh`";

/// `program` if it is a path to a file, or its first match on PATH.
pub fn find_on_path(program: &str) -> Option<PathBuf> {
    let p = Path::new(program);
    if p.components().count() > 1 {
        return p.is_file().then(|| p.to_path_buf());
    }
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|d| d.join(program))
        .find(|c| c.is_file())
}

/// What Vivado reported after routing.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VivadoResult {
    pub slice_luts: u64,
    pub ff: u64,
    pub dsp: u64,
    /// "Block RAM Tile" (RAMB36 equivalents).
    pub bram36: f64,
    pub ramb36: u64,
    pub ramb18: u64,
    /// Worst negative slack, ns (positive: met).
    pub wns_ns: f64,
    /// The constrained clock period, ns.
    pub period_ns: f64,
    /// `1000 / (period - WNS)`.
    pub fmax_mhz: f64,
}

/// Cells of a `| name | used | ... |` table row, trimmed.
fn row_cells(line: &str) -> Vec<&str> {
    line.trim()
        .trim_matches('|')
        .split('|')
        .map(str::trim)
        .collect()
}

/// The "Used" column of the first row named `name` (a trailing `*` ignored on both sides).
fn used(text: &str, name: &str) -> Result<f64, String> {
    let want = name.trim_end_matches('*');
    text.lines()
        .filter(|l| l.trim_start().starts_with('|'))
        .map(row_cells)
        .find(|c| c.first().map(|n| n.trim_end_matches('*')) == Some(want))
        .and_then(|c| c.get(1).and_then(|v| v.parse::<f64>().ok()))
        .ok_or_else(|| format!("no `{name}` row with a number in the Used column"))
}

/// Read `report_utilization` of a 7-series design.
/// Returns slice LUTs, registers, DSPs, block RAM tiles, RAMB36 and RAMB18.
pub fn parse_utilization(text: &str) -> Result<(u64, u64, u64, f64, u64, u64), String> {
    Ok((
        used(text, "Slice LUTs")? as u64,
        used(text, "Slice Registers")? as u64,
        used(text, "DSPs")? as u64,
        used(text, "Block RAM Tile")?,
        used(text, "RAMB36/FIFO")? as u64,
        used(text, "RAMB18")? as u64,
    ))
}

/// The WNS of `report_timing_summary` ("Design Timing Summary").
pub fn parse_wns(text: &str) -> Result<f64, String> {
    let lines: Vec<&str> = text.lines().collect();
    let i = lines
        .iter()
        .position(|l| l.trim_start().starts_with("WNS(ns)"))
        .ok_or("no `WNS(ns)` header: not the output of report_timing_summary")?;
    let values = lines
        .iter()
        .skip(i + 1)
        .find(|l| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('-')
        })
        .ok_or("no values under the `WNS(ns)` header")?;
    let first = values.split_whitespace().next().unwrap_or("");
    first
        .parse::<f64>()
        .ok()
        .filter(|w| w.is_finite())
        .ok_or_else(|| format!("WNS `{first}` is not a number (is the clock constrained?)"))
}

/// Run the build script of the generated layout rooted at `layout_root`;
/// reports go under `out_dir`.
pub fn run_build(
    vivado: &Path,
    layout_root: &Path,
    out_dir: &Path,
    clock_mhz: f64,
) -> Result<VivadoResult, SynthError> {
    let script = layout_root.join(BUILD_SCRIPT);
    if !script.is_file() {
        return Err(SynthError::Io {
            action: "find the Vivado build script",
            path: script,
            err: std::io::Error::from(std::io::ErrorKind::NotFound),
        });
    }
    std::fs::create_dir_all(out_dir).map_err(io_err("create", out_dir))?;
    let out_dir = out_dir.canonicalize().map_err(io_err("open", out_dir))?;
    let script = script.canonicalize().map_err(io_err("open", &script))?;
    let log = out_dir.join("vivado.log");
    let out = start(
        vivado,
        INSTALL,
        Command::new(vivado)
            .args(["-mode", "batch", "-nojournal", "-log"])
            .arg(&log)
            .arg("-source")
            .arg(&script)
            .args(["-tclargs", "-out"])
            .arg(&out_dir)
            .current_dir(&out_dir),
    )?;
    let log_text = std::fs::read_to_string(&log)
        .unwrap_or_else(|_| String::from_utf8_lossy(&out.stdout).to_string());
    if !out.status.success() {
        return Err(SynthError::ToolFailed {
            tool: vivado.display().to_string(),
            step: BUILD_SCRIPT.to_string(),
            status: out.status.to_string(),
            log,
            tail: tail_lines(&log_text, TAIL),
        });
    }
    let read = |name: &str| -> Result<(PathBuf, String), SynthError> {
        let p = out_dir.join(name);
        if !p.is_file() {
            return Err(SynthError::Parse {
                what: "the Vivado reports".into(),
                path: p,
                reason: format!(
                    "Vivado finished but did not write it; {BUILD_SCRIPT} must take \
                     `-tclargs -out OUT` and write {UTILIZATION_REPORT} and {TIMING_REPORT} under OUT"
                ),
                tail: tail_lines(&log_text, TAIL),
            });
        }
        let t = std::fs::read_to_string(&p).map_err(io_err("read", &p))?;
        Ok((p, t))
    };
    let (upath, utext) = read(UTILIZATION_REPORT)?;
    let (lut, ff, dsp, bram36, ramb36, ramb18) =
        parse_utilization(&utext).map_err(|reason| SynthError::Parse {
            what: "the Vivado utilisation report".into(),
            path: upath,
            reason,
            tail: tail_lines(&log_text, TAIL),
        })?;
    let (tpath, ttext) = read(TIMING_REPORT)?;
    let wns_ns = parse_wns(&ttext).map_err(|reason| SynthError::Parse {
        what: "the Vivado timing summary".into(),
        path: tpath,
        reason,
        tail: tail_lines(&log_text, TAIL),
    })?;
    let period_ns = 1000.0 / clock_mhz;
    Ok(VivadoResult {
        slice_luts: lut,
        ff,
        dsp,
        bram36,
        ramb36,
        ramb18,
        wns_ns,
        period_ns,
        fmax_mhz: 1000.0 / (period_ns - wns_ns),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    // Excerpts in the layout of `report_utilization` for a 7-series part.
    const UTIL: &str = "\
1. Slice Logic
--------------

+----------------------------+------+-------+-----------+-------+
|          Site Type         | Used | Fixed | Available | Util% |
+----------------------------+------+-------+-----------+-------+
| Slice LUTs                 | 9304 |     0 |    218600 |  4.26 |
|   LUT as Logic             | 9000 |     0 |    218600 |  4.12 |
|   LUT as Memory            |  304 |     0 |     70400 |  0.43 |
| Slice Registers            | 10222 |    0 |    437200 |  2.34 |
+----------------------------+------+-------+-----------+-------+

3. Memory
---------

+-------------------+-------+-------+-----------+-------+
|     Site Type     |  Used | Fixed | Available | Util% |
+-------------------+-------+-------+-----------+-------+
| Block RAM Tile    | 362.5 |     0 |       545 | 66.51 |
|   RAMB36/FIFO*    |   362 |     0 |       545 | 66.42 |
|     RAMB36E1 only |   362 |       |           |       |
|   RAMB18          |     1 |     0 |      1090 |  0.09 |
+-------------------+-------+-------+-----------+-------+

4. DSP
------

+----------------+------+-------+-----------+-------+
|    Site Type   | Used | Fixed | Available | Util% |
+----------------+------+-------+-----------+-------+
| DSPs           |   69 |     0 |       900 |  7.67 |
|   DSP48E1 only |   69 |       |           |       |
+----------------+------+-------+-----------+-------+
";

    const TIMING: &str = "\
------------------------------------------------------------------------------------------------
| Design Timing Summary
| ---------------------
------------------------------------------------------------------------------------------------

    WNS(ns)      TNS(ns)  TNS Failing Endpoints  TNS Total Endpoints      WHS(ns)      THS(ns)
    -------      -------  ---------------------  -------------------      -------      -------
      0.412        0.000                      0                23456        0.051        0.000
";

    #[test]
    fn utilisation_rows() {
        assert_eq!(
            parse_utilization(UTIL).unwrap(),
            (9304, 10222, 69, 362.5, 362, 1)
        );
    }

    #[test]
    fn synthesis_only_rows_carry_a_star() {
        let t = UTIL.replace("| Slice LUTs      ", "| Slice LUTs*     ");
        assert_eq!(parse_utilization(&t).unwrap().0, 9304);
    }

    #[test]
    fn missing_row_is_named() {
        let e = parse_utilization("| Slice LUTs | 1 |\n").unwrap_err();
        assert!(e.contains("Slice Registers"), "{e}");
    }

    #[test]
    fn wns_from_the_summary() {
        assert_eq!(parse_wns(TIMING).unwrap(), 0.412);
        let e = parse_wns("WNS(ns)  TNS(ns)\n------- -------\n  inf  0.0\n").unwrap_err();
        assert!(e.contains("is the clock constrained"), "{e}");
        assert!(parse_wns("nothing").is_err());
    }

    #[cfg(unix)]
    #[test]
    fn a_script_that_writes_no_reports_is_named() {
        use std::os::unix::fs::PermissionsExt;
        let root = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(root.path().join("scripts")).unwrap();
        std::fs::write(root.path().join(BUILD_SCRIPT), "# nothing\n").unwrap();
        let fake = root.path().join("vivado");
        std::fs::write(&fake, "#!/bin/sh\necho \"$@\" > args.txt\n").unwrap();
        std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
        let out = root.path().join("out");
        let e = run_build(&fake, root.path(), &out, 200.0).unwrap_err();
        assert!(
            e.to_string().contains("must take `-tclargs -out OUT`"),
            "{e}"
        );
        let args = std::fs::read_to_string(out.join("args.txt")).unwrap();
        assert!(args.starts_with("-mode batch -nojournal -log "), "{args}");
        assert!(
            args.contains("-source ") && args.contains("-tclargs -out "),
            "{args}"
        );
    }

    #[test]
    fn missing_build_script_is_named() {
        let root = tempfile::tempdir().unwrap();
        let e = run_build(
            Path::new("vivado"),
            root.path(),
            &root.path().join("out"),
            200.0,
        )
        .unwrap_err();
        assert!(e.to_string().contains("scripts/fcc_build.tcl"), "{e}");
    }

    #[test]
    fn find_on_path_rejects_missing_programs() {
        assert!(find_on_path("fcc-no-such-vivado").is_none());
        assert!(find_on_path("./no/such/vivado").is_none());
    }
}
