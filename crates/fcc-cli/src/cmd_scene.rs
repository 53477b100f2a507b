//! `fcc scene`: write a synthetic LiDAR scene and its ground truth.

use clap::Args;
use fcc_scene::{generate, SceneConfig};
use std::path::PathBuf;

fn defaults() -> SceneConfig {
    SceneConfig::default()
}

#[derive(Args, Debug)]
pub struct SceneArgs {
    /// Seed: the same seed gives the same scene, bit for bit.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Output frame: .npy (R, C, 3) float32, NaN = empty pixel.
    #[arg(long, short)]
    pub output: PathBuf,
    /// Ground-truth instance ids: .npy (R, C) uint32, 0 = empty or ground.
    #[arg(long)]
    pub gt: Option<PathBuf>,
    /// Beams (image rows), 16..=128.
    #[arg(long, default_value_t = defaults().rows)]
    pub rows: usize,
    /// Azimuth columns.
    #[arg(long, default_value_t = defaults().cols)]
    pub cols: usize,
    /// Keep the ground returns (they are removed by default, as FCC assumes).
    #[arg(long)]
    pub keep_ground: bool,
    /// Probability that a beam drops out for a stretch of columns.
    #[arg(long, default_value_t = defaults().dropout)]
    pub dropout: f64,
    /// Probability that a single return is missing.
    #[arg(long, default_value_t = defaults().missing)]
    pub missing: f64,
    /// Standard deviation of the range noise, metres.
    #[arg(long, default_value_t = defaults().range_noise_m)]
    pub range_noise: f64,
}

impl SceneArgs {
    pub fn config(&self) -> SceneConfig {
        SceneConfig {
            rows: self.rows,
            cols: self.cols,
            seed: self.seed,
            keep_ground: self.keep_ground,
            dropout: self.dropout,
            missing: self.missing,
            range_noise_m: self.range_noise,
        }
    }
}

pub fn run(args: &SceneArgs) -> anyhow::Result<()> {
    let mut outputs = vec![("--output", args.output.as_path())];
    outputs.extend(args.gt.as_deref().map(|g| ("--gt", g)));
    fcc_io::check_outputs([], &outputs)?;
    let scene = generate(&args.config())?;
    fcc_npy::write_xyz_f32(&args.output, scene.rows, scene.cols, &scene.xyz)?;
    eprintln!(
        "wrote {}: {} x {}, {} points",
        args.output.display(),
        scene.rows,
        scene.cols,
        scene.xyz.chunks_exact(3).filter(|p| !p[0].is_nan()).count()
    );
    if let Some(gt) = &args.gt {
        fcc_npy::write_labels(gt, scene.rows, scene.cols, &scene.gt)?;
        eprintln!("wrote {}", gt.display());
    }
    Ok(())
}
