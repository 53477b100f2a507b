//! `fcc synth`: resources and a timing estimate of the generated core.
//!
//! One K: generate the RTL (or take `--rtl-dir`), synthesise it with Yosys
//! (`synth_xilinx -family xc7`, `stat -json`, `sta`) and print a table row.
//! When `vivado` is on PATH (and `--yosys` is not given), run the project's
//! Vivado build script instead and print the routed figures.
//!
//! `--all`: every K the generator supports, written to `docs/results.md` and
//! `docs/results.json` beside the paper's Table I and the targets; golden
//! model times (`fcc bench --json`) and Verilator cycles are attached with
//! `--bench-json` and `--cycles-json`, and `--from-json` re-renders a report
//! without synthesising again.

use std::path::{Path, PathBuf};

use anyhow::Context;
use clap::Args;
use fcc_params::{limits, FccParams, Scan};
use fcc_synth::results::{self, MeasureOptions, Report, ResultRow};
use fcc_synth::vivado;
use fcc_synth::yosys::YosysConfig;

use crate::model_args::HwArgs;

fn defaults() -> FccParams {
    FccParams::default()
}

/// The defaults of `fcc synth`'s paths.
const WORK_DIR: &str = "target/fcc-synth";
const YOSYS: &str = "yosys";
pub const RESULTS_MD: &str = "docs/results.md";
pub const RESULTS_JSON: &str = "docs/results.json";

#[derive(Args, Debug)]
pub struct SynthArgs {
    #[command(flatten)]
    pub hw: HwArgs,
    /// Measure every K in 3..=11 and write the results document.
    #[arg(long, conflicts_with_all = ["fsize", "rtl_dir"])]
    pub all: bool,
    /// Synthesise the Verilog already in this directory instead of generating it
    /// (its fcc_params.json, when present, gives the parameters). For the Vivado
    /// build, the directory's parent must hold the generator's scripts/ and
    /// constraints/ (as the repository root does for rtl_out/).
    #[arg(long)]
    pub rtl_dir: Option<PathBuf>,
    /// Where the generated RTL, the Yosys script, its log and reports go.
    #[arg(long, default_value = WORK_DIR)]
    pub work_dir: PathBuf,
    /// Use Yosys even when Vivado is on PATH.
    #[arg(long)]
    pub yosys: bool,
    /// The Yosys executable.
    #[arg(long, default_value = YOSYS)]
    pub yosys_bin: PathBuf,
    /// Skip the timing estimate (faster).
    #[arg(long)]
    pub no_timing: bool,
    /// Also count cells per block (a second synthesis). With --all it is done
    /// for the targets' K = 7 row in any case, unless --no-by-block.
    #[arg(long, conflicts_with = "no_by_block")]
    pub by_block: bool,
    /// With --all: no by-block synthesis of the targets' K (it about doubles
    /// that K's time; `fcc synth --fsize 7` alone still does it).
    #[arg(long, requires = "all")]
    pub no_by_block: bool,
    /// With --all: the Markdown document.
    #[arg(long, default_value = RESULTS_MD)]
    pub out: PathBuf,
    /// With --all: the JSON beside it.
    #[arg(long, default_value = RESULTS_JSON)]
    pub json: PathBuf,
    /// With --all: attach golden-model times from `fcc bench --json FILE` (same rows and columns).
    #[arg(long)]
    pub bench_json: Option<PathBuf>,
    /// With --all: attach Verilator cycle counts (a JSON array of
    /// {fsize, corpus, frames, cycles_per_frame, max_cycles_per_frame, latency_cycles}).
    #[arg(long)]
    pub cycles_json: Option<PathBuf>,
    /// With --all: attach the per-block coverage summary of `sim/coverage.sh`
    /// (the JSON of `sim/coverage_summary.py --json`, committed as docs/coverage.json).
    #[arg(long)]
    pub coverage_json: Option<PathBuf>,
    /// With --all: attach the clustering-quality summary of
    /// `bench/quality.py` (committed as docs/quality.json).
    #[arg(long)]
    pub quality_json: Option<PathBuf>,
    /// With --all: do not synthesise; read this results JSON, attach
    /// --bench-json / --cycles-json / --coverage-json and write the document
    /// again (what the JSON already holds is kept).
    #[arg(long, requires = "all")]
    pub from_json: Option<PathBuf>,
}

impl Default for SynthArgs {
    /// The flags' defaults, as `fcc synth` alone.
    fn default() -> SynthArgs {
        SynthArgs {
            hw: HwArgs::default(),
            all: false,
            rtl_dir: None,
            work_dir: WORK_DIR.into(),
            yosys: false,
            yosys_bin: YOSYS.into(),
            no_timing: false,
            by_block: false,
            no_by_block: false,
            out: RESULTS_MD.into(),
            json: RESULTS_JSON.into(),
            bench_json: None,
            cycles_json: None,
            coverage_json: None,
            quality_json: None,
            from_json: None,
        }
    }
}

impl SynthArgs {
    fn params(&self, fsize: usize) -> anyhow::Result<FccParams> {
        let p = FccParams {
            fsize,
            ..self.hw.unchecked()
        };
        p.validate_for_hardware()?;
        Ok(p)
    }

    fn yosys_config(&self) -> YosysConfig {
        YosysConfig {
            program: self.yosys_bin.clone(),
            timing: !self.no_timing,
            by_block: self.by_block,
            ..YosysConfig::default()
        }
    }

    /// The command line that regenerates the document, for its header.
    fn command(&self) -> String {
        let mut c = format!("fcc synth --all{}", self.hw.changed_flags());
        if self.no_by_block {
            c.push_str(" --no-by-block");
        }
        if self.bench_json.is_some() {
            c.push_str(" --bench-json BENCH.json");
        }
        if self.cycles_json.is_some() {
            c.push_str(" --cycles-json CYCLES.json");
        }
        if self.coverage_json.is_some() {
            c.push_str(" --coverage-json docs/coverage.json");
        }
        if self.quality_json.is_some() {
            c.push_str(" --quality-json docs/quality.json");
        }
        c
    }

    /// The command for the header of a report re-rendered from `previous`'s
    /// JSON: the command that made it, with the inputs attached now.
    fn command_after(&self, previous: &str) -> String {
        let mut c = previous.to_string();
        // `fcc results` always measures every K: `--all` is implied there.
        let implied_all = previous.starts_with("fcc results");
        for flag in self.command().split(" --").skip(1) {
            let flag = format!(" --{flag}");
            if implied_all && flag.trim() == "--all" {
                continue;
            }
            if !c.contains(&flag) {
                c.push_str(&flag);
            }
        }
        c
    }
}

fn read(path: &Path) -> anyhow::Result<String> {
    std::fs::read_to_string(path).with_context(|| format!("{}: cannot read", path.display()))
}

pub fn run(args: &SynthArgs) -> anyhow::Result<()> {
    if args.all {
        return run_all(args);
    }
    let mut p = args.params(args.hw.unchecked().fsize)?;
    if let Some(dir) = &args.rtl_dir {
        let json = dir.join("fcc_params.json");
        if json.is_file() {
            p = fcc_rtl::ParamsFile::params_from_json(&read(&json)?)
                .with_context(|| format!("{}: not a parameter file", json.display()))?;
            eprintln!("parameters from {}", json.display());
        }
    }
    let vivado_bin = if args.yosys {
        None
    } else {
        vivado::find_on_path("vivado")
    };
    if let Some(vivado_bin) = vivado_bin {
        return run_vivado(args, &p, &vivado_bin);
    }
    let work = args.work_dir.join(format!("k{}", p.fsize));
    // The script `fcc results` uses for this configuration.
    let cfg = results::yosys_config_for(&p, &args.yosys_config(), true);
    let hb = crate::progress::Heartbeat::start(&format!(
        "synthesising K = {} with {}{} (log in {}; about two minutes per pass)",
        p.fsize,
        cfg.program.display(),
        if cfg.by_block {
            ", then again by block as the results document does"
        } else {
            ""
        },
        work.display()
    ));
    let run = match &args.rtl_dir {
        Some(dir) => fcc_synth::estimate_dir(dir, &work.join("yosys"), &cfg)?,
        None => fcc_synth::estimate(&p, &work, &cfg)?,
    };
    hb.done();
    eprintln!("{} in {:.0} s", run.yosys_version, run.seconds);
    if let Some(t) = &run.timing {
        eprintln!(
            "critical path (pre-route, Yosys sta, not Vivado timing): {:.3} ns, {} logic levels, {} -> {}",
            t.critical_path_ns, t.logic_levels, t.start, t.end
        );
        for w in &t.warnings {
            eprintln!("sta warning: {w}");
        }
    }
    if let Some(r) = &run.routing {
        use fcc_synth::routing::{FANOUT_LIMIT, HOP_LIMIT};
        eprintln!(
            "routing hops (netlist, before placement): at most {} ({} endpoints over {HOP_LIMIT}); \
             {} nets over {FANOUT_LIMIT} loads, {} of them without `max_fanout` (nothing replicates them)",
            r.worst_hops,
            r.endpoints_over_limit,
            r.nets_over_limit,
            r.unreplicated_over_limit.unwrap_or(r.nets_over_limit)
        );
        for p in &r.worst_paths {
            eprintln!("  {} hops: {} -> {}", p.hops, p.start, p.end);
        }
        eprintln!("highest fanout (clock aside):");
        for n in &r.top_fanout {
            let mark = n
                .max_fanout
                .map_or(String::new(), |m| format!(", max_fanout {m}"));
            eprintln!(
                "  {:>6} loads  {}  (driven by {}{mark})",
                n.loads, n.net, n.driver
            );
        }
    }
    let row = ResultRow::from_run(&p, Ok(run));
    println!("{}", results::summary_header());
    println!("{}", results::summary_row(&row));
    if let Some(blocks) = &row.by_block {
        println!();
        println!("| block | Slice LUTs | FF | DSP48E1 | BRAM (36 eq.) |");
        println!("|---|--:|--:|--:|--:|");
        for (name, r) in blocks {
            println!(
                "| {name} | {} | {} | {} | {} |",
                results::thousands(r.slice_luts),
                results::thousands(r.ff),
                r.dsp48e1,
                r.bram36
            );
        }
    }
    Ok(())
}

fn run_vivado(args: &SynthArgs, p: &FccParams, vivado_bin: &Path) -> anyhow::Result<()> {
    // The generator writes each configuration's own XDC and build script
    // beside its Verilog (rtl_out/, constraints/, scripts/ of one root).
    let root = match &args.rtl_dir {
        Some(d) => d.parent().map(Path::to_path_buf).unwrap_or_default(),
        None => {
            let root = args.work_dir.join(format!("k{}", p.fsize)).join("layout");
            // The work directory is this command's own: a previous run's
            // configuration there is replaced.
            let opts = fcc_rtl::WriteOptions {
                force: true,
                ..Default::default()
            };
            fcc_rtl::write_all_with(p, &fcc_rtl::Layout::under(&root), &opts)?;
            root
        }
    };
    let out = args.work_dir.join(format!("k{}", p.fsize)).join("vivado");
    eprintln!(
        "running {} -source {} (reports in {}); pass --yosys for the Yosys estimate",
        vivado_bin.display(),
        root.join(vivado::BUILD_SCRIPT).display(),
        out.display()
    );
    let v = vivado::run_build(vivado_bin, &root, &out, p.clock_mhz)?;
    println!("| K | Slice LUTs | FF | DSP48E1 | RAMB36E1 | RAMB18E1 | BRAM (36 eq.) | WNS (ns) @ {} MHz | fmax (MHz) |", p.clock_mhz);
    println!("|--:|--:|--:|--:|--:|--:|--:|--:|--:|");
    println!(
        "| {} | {} | {} | {} | {} | {} | {} | {:.3} | {:.0} |",
        p.fsize,
        results::thousands(v.slice_luts),
        results::thousands(v.ff),
        v.dsp,
        v.ramb36,
        v.ramb18,
        v.bram36,
        v.wns_ns,
        v.fmax_mhz
    );
    Ok(())
}

fn run_all(args: &SynthArgs) -> anyhow::Result<()> {
    let mut report = match &args.from_json {
        Some(path) => Report::from_json(&read(path)?)
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}", path.display()))?,
        None => {
            let base = args.params(defaults().fsize)?;
            let fsizes: Vec<usize> = limits::HW_FSIZE.step_by(2).collect();
            let opts = MeasureOptions {
                fsizes,
                yosys: args.yosys_config(),
                by_block_for_targets: !args.no_by_block,
                work_dir: args.work_dir.clone(),
                command: args.command(),
            };
            let hb = crate::progress::Heartbeat::start("synthesising every K");
            let report = results::measure(&base, &opts, &mut |line| eprintln!("{line}"))?;
            hb.done();
            report
        }
    };
    let scan = args.hw.unchecked().scan;
    let json_in = args.from_json.as_deref().unwrap_or(&args.json);
    match &args.from_json {
        Some(_) => {
            let part = core_part(&mut report, scan, json_in)?;
            part.command = args.command_after(&part.command);
        }
        None => report.command = args.command(),
    }
    let rewrites_its_input = args.from_json.as_deref().is_some_and(|f| {
        f == args.json
            || f.canonicalize()
                .is_ok_and(|a| args.json.canonicalize().is_ok_and(|b| a == b))
    });
    let mut report = if rewrites_its_input {
        report
    } else {
        with_the_other_core(report, &args.json)?
    };
    if let Some(path) = &args.coverage_json {
        let n = report
            .attach_coverage_json(&read(path)?)
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}", path.display()))?;
        eprintln!("coverage of {n} blocks from {}", path.display());
    }
    if let Some(path) = &args.quality_json {
        let n = report
            .attach_quality_json(&read(path)?)
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}", path.display()))?;
        eprintln!("clustering quality, {n} rows, from {}", path.display());
    }
    if let Some(path) = &args.bench_json {
        let n = report
            .attach_golden_bench(&read(path)?)
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}", path.display()))?;
        eprintln!("golden-model times for {n} K from {}", path.display());
    }
    if let Some(path) = &args.cycles_json {
        let n = core_part(&mut report, scan, json_in)?
            .attach_cycles_json(&read(path)?)
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}", path.display()))?;
        eprintln!("{n} cycle measurements from {}", path.display());
    }
    results::write_report(&report, &args.out, &args.json)?;
    eprintln!("wrote {} and {}", args.out.display(), args.json.display());
    Ok(())
}

/// The part of `report` (read from `file`) that belongs to the core of
/// `scan`: a row-major core's report holds the column core's as its column part.
fn core_part<'a>(
    report: &'a mut Report,
    scan: Scan,
    file: &Path,
) -> anyhow::Result<&'a mut Report> {
    if scan == Scan::Column && report.base.scan == Scan::Row {
        return report.column.as_deref_mut().ok_or_else(|| {
            anyhow::anyhow!(
                "{}: holds no column-streaming core's part (measure it first: \
                 fcc synth --all --scan column)",
                file.display()
            )
        });
    }
    if scan != report.base.scan {
        anyhow::bail!(
            "{}: a {} core's report, not the {} core's",
            file.display(),
            report.base.scan.as_str(),
            scan.as_str()
        );
    }
    Ok(report)
}

/// The report to write for `report` (measured, or read from another file),
/// given what `json` holds:
/// each core's `--all` run replaces its own part of the document and keeps
/// the other core's. A column core's report goes into a row-major core's
/// report there as its column part; a row-major core's report takes the
/// column part the file held. A file that is not a report is refused, not
/// overwritten.
fn with_the_other_core(report: Report, json: &Path) -> anyhow::Result<Report> {
    if !json.is_file() {
        return Ok(report);
    }
    let previous = Report::from_json(&read(json)?)
        .map_err(anyhow::Error::msg)
        .with_context(|| {
            format!(
                "{}: not a results report, so it is not replaced (pass another --json)",
                json.display()
            )
        })?;
    Ok(match (report.base.scan, previous.base.scan) {
        (Scan::Column, Scan::Row) => {
            eprintln!(
                "{}: the column-streaming core's part replaced, the row-major core's kept",
                json.display()
            );
            let mut merged = previous;
            merged.set_column(report).map_err(anyhow::Error::msg)?;
            merged
        }
        (Scan::Row, Scan::Row) if report.column.is_none() && previous.column.is_some() => {
            eprintln!(
                "{}: the row-major core's part replaced, the column-streaming core's kept",
                json.display()
            );
            Report {
                column: previous.column,
                ..report
            }
        }
        _ => report,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        synth: SynthArgs,
    }

    fn parse(args: &[&str]) -> Result<SynthArgs, clap::Error> {
        Cli::try_parse_from(std::iter::once("synth").chain(args.iter().copied())).map(|c| c.synth)
    }

    #[test]
    fn defaults_are_the_default_parameters() {
        let a = parse(&[]).unwrap();
        assert_eq!(
            a.params(a.hw.unchecked().fsize).unwrap(),
            FccParams::default()
        );
        // What `fcc results` builds in code is what the bare command parses.
        assert_eq!(format!("{a:?}"), format!("{:?}", SynthArgs::default()));
    }

    #[test]
    fn all_conflicts_with_one_k_and_from_json_needs_all() {
        assert!(parse(&["--all", "--fsize", "5"]).is_err());
        assert!(parse(&["--all", "--rtl-dir", "x"]).is_err());
        assert!(parse(&["--from-json", "r.json"]).is_err());
        assert!(parse(&["--all", "--from-json", "r.json"]).is_ok());
        assert!(parse(&["--no-by-block"]).is_err());
        assert!(parse(&["--all", "--no-by-block", "--by-block"]).is_err());
        let a = parse(&["--all", "--no-by-block"]).unwrap();
        assert_eq!(a.command(), "fcc synth --all --no-by-block");
    }

    #[test]
    fn synth_of_the_target_configuration_runs_the_results_script() {
        // `fcc synth --fsize 7` and `fcc results` must synthesise K = 7 with
        // the same Yosys script, or they report different LUT counts.
        let a = parse(&["--fsize", "7"]).unwrap();
        let p = a.params(7).unwrap();
        let files = [PathBuf::from("fcc_top.v"), PathBuf::from("fcc_intra.v")];
        let blocks = vec!["fcc_intra".to_string()];
        let synth = results::yosys_config_for(&p, &a.yosys_config(), true);
        let all = parse(&["--all"]).unwrap();
        let results_cfg = results::yosys_config_for(&p, &all.yosys_config(), true);
        assert_eq!(
            fcc_synth::yosys::script(&files, &synth, &blocks),
            fcc_synth::yosys::script(&files, &results_cfg, &blocks)
        );
        assert!(synth.by_block, "the results document counts K = 7 by block");
    }

    fn empty_report(scan: Scan, command: &str) -> Report {
        Report {
            base: FccParams {
                scan,
                ..FccParams::default()
            },
            yosys_version: None,
            command: command.into(),
            rows: vec![],
            coverage: None,
            quality: None,
            column: None,
            stream_cycles: vec![],
        }
    }

    #[test]
    fn each_cores_run_replaces_its_part_of_the_document_and_keeps_the_others() {
        let d = tempfile::tempdir().unwrap();
        let json = d.path().join("results.json");
        let md = d.path().join("results.md");
        // No document yet: the measured report alone.
        let col = empty_report(Scan::Column, "fcc synth --all --scan column");
        let first = with_the_other_core(col.clone(), &json).unwrap();
        assert_eq!(first, col);
        // A row-major document takes the column core's as its part ...
        let row = empty_report(Scan::Row, "fcc synth --all");
        results::write_report(&row, &md, &json).unwrap();
        let merged = with_the_other_core(col.clone(), &json).unwrap();
        assert_eq!(merged.command, "fcc synth --all");
        assert_eq!(merged.column.as_deref(), Some(&col));
        // ... and keeps it when the row-major core is measured again.
        results::write_report(&merged, &md, &json).unwrap();
        let again =
            with_the_other_core(empty_report(Scan::Row, "fcc synth --all --rows 32"), &json)
                .unwrap();
        assert_eq!(again.command, "fcc synth --all --rows 32");
        assert_eq!(again.column.as_deref(), Some(&col));
        // The part of each core, and a part that is not there.
        let mut again = again;
        assert_eq!(
            core_part(&mut again, Scan::Column, &json).unwrap().command,
            col.command
        );
        assert_eq!(
            core_part(&mut again, Scan::Row, &json).unwrap().base.scan,
            Scan::Row
        );
        let mut bare = empty_report(Scan::Row, "x");
        let e = core_part(&mut bare, Scan::Column, &json)
            .unwrap_err()
            .to_string();
        assert!(e.contains("fcc synth --all --scan column"), "{e}");
        let mut alone = col.clone();
        let e = core_part(&mut alone, Scan::Row, &json)
            .unwrap_err()
            .to_string();
        assert!(e.contains("a column core's report"), "{e}");
        // A file that is not a report is neither read as one nor replaced.
        std::fs::write(&json, "not json").unwrap();
        let e = format!("{:#}", with_the_other_core(col, &json).unwrap_err());
        assert!(
            e.contains("not a results report, so it is not replaced"),
            "{e}"
        );
        assert_eq!(std::fs::read_to_string(&json).unwrap(), "not json");
    }

    #[test]
    fn hardware_ranges_are_checked() {
        let a = parse(&["--fsize", "13"]).unwrap();
        let e = a.params(a.hw.unchecked().fsize).unwrap_err().to_string();
        assert!(e.contains("fsize = 13"), "{e}");
    }

    #[test]
    fn regenerating_command_names_only_changed_flags() {
        assert_eq!(parse(&["--all"]).unwrap().command(), "fcc synth --all");
        let a = parse(&["--all", "--rows", "32", "--clock-mhz", "250"]).unwrap();
        assert_eq!(a.command(), "fcc synth --all --rows 32 --clock-mhz 250");
        // Flags of fields the defaults leave out are named too.
        let a = parse(&[
            "--all",
            "--scan",
            "column",
            "--bridge",
            "16",
            "--ring-reach",
            "16",
        ])
        .unwrap();
        assert_eq!(
            a.command(),
            "fcc synth --all --bridge 16 --ring-reach 16 --scan column"
        );
        // The column core's label width is its own default; another is a
        // change, and the row-major core's default is one for it.
        assert_eq!(a.hw.unchecked().label_bits, 13);
        let a = parse(&["--all", "--scan", "column", "--label-bits", "15"]).unwrap();
        assert_eq!(a.command(), "fcc synth --all --label-bits 15 --scan column");
        let a = parse(&["--all", "--label-bits", "13"]).unwrap();
        assert_eq!(a.hw.unchecked().label_bits, 13);
        assert_eq!(a.command(), "fcc synth --all --label-bits 13");
        assert_eq!(parse(&["--all"]).unwrap().hw.unchecked().label_bits, 15);
    }

    #[test]
    fn re_rendering_keeps_the_command_that_made_the_report() {
        let a = parse(&[
            "--all",
            "--from-json",
            "r.json",
            "--coverage-json",
            "c.json",
        ])
        .unwrap();
        assert_eq!(
            a.command_after("fcc synth --all --bench-json BENCH.json"),
            "fcc synth --all --bench-json BENCH.json --coverage-json docs/coverage.json"
        );
        assert_eq!(
            a.command_after("fcc results --coverage-json docs/coverage.json"),
            "fcc results --coverage-json docs/coverage.json"
        );
    }
}
