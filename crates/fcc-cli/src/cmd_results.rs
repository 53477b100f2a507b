//! `fcc results`: every hardware and software number of `docs/results.md` in
//! one run: golden-model time per K (`fcc bench`), Verilator cycles per K on
//! the synthetic corpus and the Ouster frames (`fcc cycles`), and Yosys
//! resources and pre-route timing per K (`fcc synth --all`), for the
//! row-major core and then for the column-streaming core (`--scan column`
//! at the recommended streaming limits).

use crate::cmd_bench::{self, BenchArgs};
use crate::cmd_cycles::{self, CyclesArgs};
use crate::cmd_synth::{self, SynthArgs};
use anyhow::Context;
use clap::Args;
use fcc_params::{FccParams, Scan};
use fcc_scene::SceneConfig;
use fcc_synth::results::{self, Report};
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct ResultsArgs {
    /// Synthetic 64 x 2048 scenes for the golden-model times and the cycle counts.
    #[arg(long, default_value_t = 4)]
    pub frames: u64,
    /// The Markdown document.
    #[arg(long, default_value = cmd_synth::RESULTS_MD)]
    pub out: PathBuf,
    /// The JSON beside it.
    #[arg(long, default_value = cmd_synth::RESULTS_JSON)]
    pub json: PathBuf,
    /// The coverage summary of `sim/coverage.sh`, attached when the file exists.
    #[arg(long, default_value = "docs/coverage.json")]
    pub coverage_json: PathBuf,
    /// The clustering-quality summary of `bench/quality.py`, attached when the file exists.
    #[arg(long, default_value = "docs/quality.json")]
    pub quality_json: PathBuf,
    /// Intermediate files (bench and cycle JSON, Yosys work).
    #[arg(long, default_value = "target/fcc-results")]
    pub work_dir: PathBuf,
}

pub fn run(args: &ResultsArgs) -> anyhow::Result<()> {
    std::fs::create_dir_all(&args.work_dir)
        .with_context(|| format!("{}: cannot create", args.work_dir.display()))?;
    let fsizes = vec![3usize, 5, 7, 9, 11];
    let bench_json = args.work_dir.join("bench.json");
    let cycles_json = args.work_dir.join("cycles.json");
    let base = FccParams::default();
    eprintln!("1/5 golden model times (fcc bench)");
    cmd_bench::run(&BenchArgs {
        fsize: fsizes.clone(),
        frames: args.frames,
        repeat: 5,
        rows: base.rows,
        cols: base.cols,
        dropout: SceneConfig::default().dropout,
        missing: SceneConfig::default().missing,
        th_h: base.th_h,
        th_v: base.th_v,
        slopes: Default::default(),
        jobs: None,
        json: Some(bench_json.clone()),
    })?;
    // `fcc cycles` of one core, its defaults otherwise.
    let cycles = |scan: Scan, json: &PathBuf| {
        cmd_cycles::run(&CyclesArgs {
            fsize: fsizes.clone(),
            frames: args.frames,
            ouster_dir: None,
            json: Some(json.clone()),
            scan,
            label_bits: Scan::Column.default_label_bits(),
            bridge: fcc_params::RECOMMENDED_BRIDGE,
            ring_reach: fcc_params::RECOMMENDED_RING_REACH,
        })
    };
    eprintln!("2/5 Verilator cycles (fcc cycles)");
    cycles(Scan::Row, &cycles_json)?;
    eprintln!("3/5 Yosys resources and timing (fcc synth --all)");
    let attach = |file: &PathBuf, table: &str, how: &str| {
        if file.is_file() {
            Some(file.clone())
        } else {
            eprintln!(
                "{}: not found, the {table} table stays empty ({how} writes it)",
                file.display()
            );
            None
        }
    };
    cmd_synth::run(&SynthArgs {
        all: true,
        bench_json: Some(bench_json),
        cycles_json: Some(cycles_json),
        coverage_json: attach(&args.coverage_json, "coverage", "bash sim/coverage.sh"),
        quality_json: attach(&args.quality_json, "quality", "bench/quality.py"),
        out: args.out.clone(),
        json: args.json.clone(),
        work_dir: args.work_dir.join("synth"),
        ..SynthArgs::default()
    })?;
    let column_cycles_json = args.work_dir.join("cycles-column.json");
    eprintln!("4/5 the column-streaming core's Verilator cycles (fcc cycles --scan column)");
    cycles(Scan::Column, &column_cycles_json)?;
    eprintln!(
        "5/5 the column-streaming core's resources and timing (fcc synth --all --scan column)"
    );
    let mut column = SynthArgs {
        all: true,
        cycles_json: Some(column_cycles_json),
        out: args.out.clone(),
        json: args.json.clone(),
        work_dir: args.work_dir.join("synth-column"),
        ..SynthArgs::default()
    };
    column.hw.scan = Some(Scan::Column);
    column.hw.limits.bridge = Some(fcc_params::RECOMMENDED_BRIDGE);
    column.hw.limits.ring_reach = Some(fcc_params::RECOMMENDED_RING_REACH);
    // Its part goes into the document the row-major run wrote.
    cmd_synth::run(&column)?;
    // Name the command that regenerates the whole document.
    let text = std::fs::read_to_string(&args.json)
        .with_context(|| format!("{}: cannot read", args.json.display()))?;
    let mut report = Report::from_json(&text).map_err(anyhow::Error::msg)?;
    report.command = "fcc results".to_string();
    results::write_report(&report, &args.out, &args.json)?;
    eprintln!("wrote {} and {}", args.out.display(), args.json.display());
    Ok(())
}
