//! `fcc sim`: run one frame through the Verilator model of the RTL, compare
//! every label with the golden model and report cycles.

use std::path::PathBuf;

use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::Frame;
use fcc_params::FccParams;
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
}

fn probability(name: &str, v: f64) -> anyhow::Result<f64> {
    if (0.0..1.0).contains(&v) {
        Ok(v)
    } else {
        bail!("--{name} = {v} must be in 0 <= p < 1")
    }
}

/// `size_given`: `--rows` or `--cols` was on the command line; they size a
/// synthetic scene only, so an `--input` frame refuses them.
pub fn run(args: &SimArgs, size_given: bool) -> anyhow::Result<()> {
    if let (Some(path), true) = (&args.input, size_given) {
        bail!(
            "{}: --rows and --cols size a --scene-seed scene only; an --input frame brings its own size (drop them, or resample the frame)",
            path.display()
        );
    }
    let frame_of = |rows: usize, cols: usize, xyz: &[f64]| Frame::from_xyz_f64(rows, cols, xyz);
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
                rows: args.hw.rows,
                cols: args.hw.cols,
                seed,
                ..Default::default()
            };
            let scene = fcc_scene::generate(&cfg).context("making the synthetic scene")?;
            (
                Frame::from_xyz_f32(args.hw.rows, args.hw.cols, &scene.xyz),
                format!("synthetic scene seed {seed}"),
            )
        }
        (None, None) => bail!("give a frame with --input FILE.npy or --scene-seed N"),
    };
    let p = FccParams {
        rows: frame.rows,
        cols: frame.cols,
        ..args.hw.unchecked()
    };
    p.validate_for_hardware()
        .context("this frame and these parameters cannot run on the RTL")?;
    let drive = Drive {
        gap: probability("gap", args.gap)?,
        backpressure: probability("backpressure", args.backpressure)?,
        seed: args.seed,
        ..Default::default()
    };
    let step = if fcc_sim::is_cached(&p)? {
        "loading the cached Verilator model".to_string()
    } else {
        format!(
            "building the Verilator model (first run of these parameters, a few minutes; cached in {})",
            fcc_sim::cache_root().display()
        )
    };
    let hb = crate::progress::Heartbeat::start(&step);
    let model = fcc_sim::load(&p).context("preparing the Verilator model")?;
    hb.done();
    let mut dut = Dut::new(model);
    dut.reset(4);
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
    println!("fcc_top: {}", fcc_rtl::param_summary(&p));
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
