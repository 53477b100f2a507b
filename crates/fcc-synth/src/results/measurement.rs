//! Generating and synthesising every K into a [`Report`].

use std::path::PathBuf;

use fcc_params::FccParams;

use crate::flow;
use crate::yosys::YosysConfig;
use crate::SynthError;

use super::{summary_header, summary_row, Report, ResultRow, TARGETS};

/// What [`measure`] does.
#[derive(Debug, Clone)]
pub struct MeasureOptions {
    /// The K to synthesise.
    pub fsizes: Vec<usize>,
    pub yosys: YosysConfig,
    /// Also count cells per block for the row the targets are about.
    pub by_block_for_targets: bool,
    /// Where each K's RTL and Yosys files go (`k<K>/rtl`, `k<K>/yosys`).
    pub work_dir: PathBuf,
    /// Written into the report as the command that regenerates it.
    pub command: String,
}

/// Generate and synthesise every K of `opts` with the rest of `base`.
///
/// A K that cannot be built or synthesised becomes a row with its error; a
/// missing Yosys stops the whole run. `progress` receives one line per step.
pub fn measure(
    base: &FccParams,
    opts: &MeasureOptions,
    progress: &mut dyn FnMut(&str),
) -> Result<Report, SynthError> {
    let mut report = Report {
        base: FccParams {
            fsize: opts.fsizes.first().copied().unwrap_or(base.fsize),
            ..base.clone()
        },
        yosys_version: None,
        command: opts.command.clone(),
        rows: vec![],
        coverage: None,
        quality: None,
        column: None,
        stream_cycles: vec![],
    };
    if opts.fsizes.contains(&TARGETS.fsize) {
        report.base.fsize = TARGETS.fsize;
    }
    for &k in &opts.fsizes {
        let p = FccParams {
            fsize: k,
            ..base.clone()
        };
        let cfg = yosys_config_for(&p, &opts.yosys, opts.by_block_for_targets);
        let dir = opts.work_dir.join(format!("k{k}"));
        progress(&format!(
            "K = {k}: generating and synthesising in {}{}",
            dir.display(),
            if cfg.by_block {
                " (with by-block counts)"
            } else {
                ""
            }
        ));
        let run = match flow::estimate(&p, &dir, &cfg) {
            Ok(r) => {
                report.yosys_version.get_or_insert(r.yosys_version.clone());
                Ok(r)
            }
            Err(e @ SynthError::ToolMissing { .. }) => return Err(e),
            Err(e) => Err(e.to_string()),
        };
        let row = ResultRow::from_run(&p, run);
        progress(&format!(
            "{}{}",
            summary_header_if(report.rows.is_empty()),
            summary_row(&row)
        ));
        report.rows.push(row);
    }
    Ok(report)
}

fn summary_header_if(first: bool) -> String {
    if first {
        format!("{}\n", summary_header())
    } else {
        String::new()
    }
}

/// The Yosys configuration used for `p`: `base`, with the by-block pass for
/// the target configuration when `by_block_for_targets`. `fcc synth` and the
/// results document both use it, so one configuration is synthesised by one
/// script and gives one set of numbers.
pub fn yosys_config_for(
    p: &FccParams,
    base: &YosysConfig,
    by_block_for_targets: bool,
) -> YosysConfig {
    YosysConfig {
        top: fcc_rtl::top_module(p),
        by_block: base.by_block || (by_block_for_targets && TARGETS.applies_to(p)),
        ..base.clone()
    }
}
