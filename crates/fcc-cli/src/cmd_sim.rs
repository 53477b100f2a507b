//! `fcc sim`: run one frame through the Verilator model of the RTL, compare
//! every label with the golden model and report cycles.
//!
//! Without `--rtl` the core is generated for the frame's own size and the
//! flags; with `--rtl DIR` it is the configuration `fcc gen --out DIR` wrote
//! (its Verilog as it is there, its limits from its `fcc_params.json`), and
//! the frame's run parameters (its rows and columns, `--fsize`, `--th-h`,
//! `--th-v`; flags not given keep the build's power-on values) are written
//! into the run registers before the frame.
//!
//! With `--scan column` (or a column build in `--rtl DIR`) the frame goes in
//! column order and every record and the end beat are checked against the
//! golden stream; it reports the cycles per pixel and each record's
//! latency after its closing column.

use std::path::PathBuf;

use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::Frame;
use fcc_params::{FccParams, Scan};
use fcc_sim::column::{ColDrive, ColFrame};
use fcc_sim::{Drive, Dut};

use crate::model_args::HwArgs;

/// The frame, the hardware parameters and how to drive the ports.
#[derive(Args, Debug, Clone)]
pub struct SimArgs {
    /// Frame to run: a (rows, cols, 3) float .npy range image in metres (NaN = empty).
    #[arg(long, conflicts_with = "scene_seed")]
    pub input: Option<PathBuf>,
    /// Instead of --input, a synthetic scene with this seed (--rows x --cols).
    #[arg(long)]
    pub scene_seed: Option<u64>,
    /// K, thresholds, label width, labels per beat; --rows and --cols size the
    /// synthetic scene (an --input frame brings its own).
    #[command(flatten)]
    pub hw: HwArgs,
    /// Probability of an idle input cycle between pixels.
    #[arg(long, allow_negative_numbers = true, default_value_t = 0.0)]
    pub gap: f64,
    /// Probability that the output is not ready in a cycle.
    #[arg(long, allow_negative_numbers = true, default_value_t = 0.0)]
    pub backpressure: f64,
    /// Seed of the gap and back-pressure patterns.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Write the hardware's labels as a (rows, cols) .npy.
    #[arg(long)]
    pub output: Option<PathBuf>,
    /// Run on the configuration generated into DIR by `fcc gen --out DIR`
    /// (built once for its limits), programming the frame's size, K and
    /// thresholds through its registers.
    #[arg(long, value_name = "DIR")]
    pub rtl: Option<PathBuf>,
}

fn probability(name: &str, v: f64) -> anyhow::Result<f64> {
    if (0.0..1.0).contains(&v) {
        Ok(v)
    } else {
        bail!("--{name} = {v} must be in 0 <= p < 1")
    }
}

/// `--rows` and `--cols` size a synthetic scene only, so an `--input` frame
/// refuses them.
pub fn run(args: &SimArgs) -> anyhow::Result<()> {
    let hw = &args.hw;
    let size_given = hw.rows.is_some() || hw.cols.is_some();
    if let (Some(path), true) = (&args.input, size_given) {
        bail!(
            "{}: --rows and --cols size a --scene-seed scene only; an --input frame brings its own size (drop them, or resample the frame)",
            path.display()
        );
    }
    let build = match &args.rtl {
        Some(dir) => {
            let g = fcc_sim::read_generated(dir)?;
            for (given, flag) in [
                (hw.label_bits.is_some(), "--label-bits"),
                (hw.labels_per_beat.is_some(), "--labels-per-beat"),
                (hw.clock_mhz.is_some(), "--clock-mhz"),
            ] {
                if given {
                    bail!(
                        "{flag} is fixed by the build in {} ({}); drop it, or generate another configuration",
                        dir.display(),
                        fcc_rtl::param_summary(&g.params)
                    );
                }
            }
            Some(g.params)
        }
        None => None,
    };
    let frame_of = |rows: usize, cols: usize, xyz: &[f64]| Frame::from_xyz_f64(rows, cols, xyz);
    // A synthetic scene on a generated configuration defaults to its limits.
    let (scene_rows, scene_cols) = match &build {
        Some(b) => (hw.rows.unwrap_or(b.rows), hw.cols.unwrap_or(b.cols)),
        None => (hw.unchecked().rows, hw.unchecked().cols),
    };
    let (frame, source) = match (&args.input, args.scene_seed) {
        (Some(path), _) => {
            let img =
                fcc_npy::read_xyz(path).with_context(|| format!("reading {}", path.display()))?;
            (
                frame_of(img.rows, img.cols, &img.xyz),
                path.display().to_string(),
            )
        }
        (None, Some(seed)) => {
            let cfg = fcc_scene::SceneConfig {
                rows: scene_rows,
                cols: scene_cols,
                seed,
                ..Default::default()
            };
            let scene = fcc_scene::generate(&cfg).context("making the synthetic scene")?;
            (
                Frame::from_xyz_f32(scene_rows, scene_cols, &scene.xyz),
                format!("synthetic scene seed {seed}"),
            )
        }
        (None, None) => bail!("give a frame with --input FILE.npy or --scene-seed N"),
    };
    let drive = Drive {
        gap: probability("gap", args.gap)?,
        backpressure: probability("backpressure", args.backpressure)?,
        seed: args.seed,
        ..Default::default()
    };
    // `p`: what the frame runs with (the golden model's parameters).
    let (p, mut dut) = match (&args.rtl, &build) {
        (Some(dir), Some(b)) => {
            // The run parameters given, over the build's power-on values.
            let p = FccParams {
                rows: frame.rows,
                cols: frame.cols,
                ..hw.over(b)
            };
            p.validate_rtl_contract()
                .context("these run parameters cannot run on the RTL")?;
            fcc_sim::check_run(b, &p).with_context(|| {
                format!(
                    "this frame and these parameters cannot run on the build in {}",
                    dir.display()
                )
            })?;
            let model = load_generated(dir)?;
            let mut dut = Dut::new(model);
            dut.reset(4);
            dut.program_run(&p)
                .context("programming the run registers")?;
            (p, dut)
        }
        _ => {
            let p = FccParams {
                rows: frame.rows,
                cols: frame.cols,
                ..args.hw.unchecked()
            };
            p.validate_for_hardware()
                .context("this frame and these parameters cannot run on the RTL")?;
            let model = load_params(&p)?;
            let mut dut = Dut::new(model);
            dut.reset(4);
            (p, dut)
        }
    };
    if p.scan == Scan::Column {
        if let Some(out) = &args.output {
            bail!(
                "{}: --output writes a label image; the column core (--scan column) sends one record per cluster, which `fcc sim` checks and counts",
                out.display()
            );
        }
        return sim_columns(&mut dut, &p, &frame, &source, &drive);
    }
    let gold = fcc_sim::expected(&p, &frame)?;
    let run = dut.run_frame(&frame, &drive)?;
    if let Some(out) = &args.output {
        fcc_npy::write_labels(out, p.rows, p.cols, &run.labels)
            .with_context(|| format!("writing {}", out.display()))?;
    }
    fcc_sim::compare(
        &p,
        &gold,
        &run,
        &format!("{source}, drive seed {}", args.seed),
    )?;
    let rc = p.pixels() as f64;
    println!(
        "PASS: {} labels match the golden model ({source})",
        p.pixels()
    );
    match (&args.rtl, &build) {
        (Some(dir), Some(b)) => {
            println!(
                "{}: {} ({})",
                fcc_rtl::top_module(b),
                fcc_rtl::param_summary(b),
                dir.display()
            );
            println!(
                "run registers: rows={} cols={} fsize={} th_h={} th_v={} th_h_slope={} th_v_slope={}",
                p.rows, p.cols, p.fsize, p.th_h, p.th_v, p.th_h_slope, p.th_v_slope
            );
        }
        _ => println!(
            "{}: {}",
            fcc_rtl::top_module(&p),
            fcc_rtl::param_summary(&p)
        ),
    }
    println!(
        "clusters {}, provisional labels {}, unique joins {}",
        run.clusters, run.provisional, run.joins
    );
    println!(
        "cycles per frame {} ({:.3} x R x C), latency after the last pixel {} cycles",
        run.cycles,
        run.cycles as f64 / rc,
        run.latency
    );
    println!(
        "input stalls {} cycles ({:.2}%), read-back waits {} cycles",
        run.input_stalls,
        100.0 * run.input_stalls as f64 / rc,
        run.gear_stalls
    );
    Ok(())
}

/// The column core: the frame in column order, every record and the end
/// beat checked against the golden stream; cycles and record latency.
fn sim_columns(
    dut: &mut Dut,
    p: &FccParams,
    frame: &Frame,
    source: &str,
    drive: &Drive,
) -> anyhow::Result<()> {
    let f = ColFrame::new(p, frame, fcc_sim::Tlast::Normal, source)?;
    let cdrive = ColDrive {
        gap: drive.gap,
        backpressure: drive.backpressure,
        seed: drive.seed,
        ..Default::default()
    };
    let run = dut
        .run_columns(std::slice::from_ref(&f), &cdrive)
        .with_context(|| format!("{source}, drive seed {}", drive.seed))?;
    println!(
        "PASS: {} records and the end beat match the golden stream ({source})",
        run.records
    );
    println!(
        "{}: {}",
        fcc_rtl::top_module(dut.params()),
        fcc_rtl::param_summary(p)
    );
    let (_, provisional, held) = run.status.first().copied().unwrap_or_default();
    println!(
        "records {}, most provisional labels in use at once {provisional}, column starts held {held} cycles",
        run.records
    );
    println!(
        "input {} cycles ({:.3} x R x C), last end beat after {} cycles",
        run.in_cycles,
        run.cycles_per_pixel(std::slice::from_ref(&f), p),
        run.cycles
    );
    let q = |v: &[u64], x: f64| fcc_sim::column::quantile(v, x);
    println!(
        "record latency after its closing column's last pixel ({} records): median {}, 99% {}, max {} cycles (R = {})",
        run.latency.len(),
        q(&run.latency, 0.5),
        q(&run.latency, 0.99),
        q(&run.latency, 1.0),
        p.rows
    );
    println!(
        "records closed at the frame end ({}): after its last pixel, max {} cycles",
        run.end_latency.len(),
        q(&run.end_latency, 1.0)
    );
    Ok(())
}

/// The Verilator model of the configuration `fcc gen --out DIR` wrote into
/// `dir` (its own Verilog), with progress.
pub fn load_generated(dir: &std::path::Path) -> anyhow::Result<std::sync::Arc<fcc_sim::Model>> {
    let cached = fcc_sim::is_cached_dir(dir)?;
    load_with_progress(cached, || fcc_sim::load_dir(dir))
}

/// The Verilator model of the core generated from `p`, with progress.
pub fn load_params(p: &FccParams) -> anyhow::Result<std::sync::Arc<fcc_sim::Model>> {
    let cached = fcc_sim::is_cached(p)?;
    load_with_progress(cached, || fcc_sim::load(p))
}

/// Load a Verilator model, saying whether it is being built (minutes) or
/// loaded from the cache.
fn load_with_progress(
    cached: bool,
    load: impl FnOnce() -> Result<std::sync::Arc<fcc_sim::Model>, fcc_sim::SimError>,
) -> anyhow::Result<std::sync::Arc<fcc_sim::Model>> {
    let step = if cached {
        "loading the cached Verilator model".to_string()
    } else {
        format!(
            "building the Verilator model (first run of this configuration, a few minutes; cached in {})",
            fcc_sim::cache_root().display()
        )
    };
    let hb = crate::progress::Heartbeat::start(&step);
    let model = load().context("preparing the Verilator model")?;
    hb.done();
    Ok(model)
}
