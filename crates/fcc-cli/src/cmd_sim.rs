//! `fcc sim`: run one frame through the Verilator model of the RTL, compare
//! every label with the golden model and report cycles.

use std::path::PathBuf;

use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::Frame;
use fcc_params::FccParams;
use fcc_sim::{Drive, Dut};

fn defaults() -> FccParams {
    FccParams::default()
}

/// The frame, the hardware parameters and how to drive the ports.
#[derive(Args, Debug, Clone)]
pub struct SimArgs {
    /// Frame to run: a (rows, cols, 3) float .npy range image in metres (NaN = empty).
    #[arg(long, conflicts_with = "scene_seed")]
    pub input: Option<PathBuf>,
    /// Instead of --input, a synthetic scene with this seed (--rows x --cols).
    #[arg(long)]
    pub scene_seed: Option<u64>,
    /// Rows of the synthetic scene.
    #[arg(long, default_value_t = defaults().rows)]
    pub rows: usize,
    /// Columns of the synthetic scene.
    #[arg(long, default_value_t = defaults().cols)]
    pub cols: usize,
    /// Connection-filter size K (odd, 3..=11).
    #[arg(long, default_value_t = defaults().fsize)]
    pub fsize: usize,
    /// Intra-channel threshold th_H, metres.
    #[arg(long, default_value_t = defaults().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, default_value_t = defaults().th_v)]
    pub th_v: f64,
    /// Provisional label width B (8..=16).
    #[arg(long, default_value_t = defaults().label_bits)]
    pub label_bits: u32,
    /// Labels per output beat: 1, 2 or 4.
    #[arg(long, default_value_t = defaults().labels_per_beat)]
    pub labels_per_beat: u32,
    /// Probability of an idle input cycle between pixels.
    #[arg(long, default_value_t = 0.0)]
    pub gap: f64,
    /// Probability that the output is not ready in a cycle.
    #[arg(long, default_value_t = 0.0)]
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

pub fn run(args: &SimArgs) -> anyhow::Result<()> {
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
                rows: args.rows,
                cols: args.cols,
                seed,
                ..Default::default()
            };
            let scene = fcc_scene::generate(&cfg).context("making the synthetic scene")?;
            (
                Frame::from_xyz_f32(args.rows, args.cols, &scene.xyz),
                format!("synthetic scene seed {seed}"),
            )
        }
        (None, None) => bail!("give a frame with --input FILE.npy or --scene-seed N"),
    };
    let p = FccParams {
        rows: frame.rows,
        cols: frame.cols,
        fsize: args.fsize,
        th_h: args.th_h,
        th_v: args.th_v,
        label_bits: args.label_bits,
        labels_per_beat: args.labels_per_beat,
        ..defaults()
    };
    p.validate_for_hardware()
        .context("this frame and these parameters cannot run on the RTL")?;
    let drive = Drive {
        gap: probability("gap", args.gap)?,
        backpressure: probability("backpressure", args.backpressure)?,
        seed: args.seed,
        ..Default::default()
    };
    eprintln!("building or loading the Verilator model (cached)...");
    let model = fcc_sim::load(&p).context("preparing the Verilator model")?;
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
