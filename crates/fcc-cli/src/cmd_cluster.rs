//! `fcc cluster`: range images in, label images out.

use crate::model_args::ModelArgs;
use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::{cluster, Clustering, Frame};
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(Args, Debug)]
pub struct ClusterArgs {
    /// Input frame(s): .npy of shape (R, C, 3), float32 or float64, NaN = empty pixel.
    #[arg(long, short, required = true, num_args = 1..)]
    pub input: Vec<PathBuf>,
    /// Output: a .npy label image (R, C) uint32 for one input; a directory for several
    /// (each written as <input stem>.labels.npy).
    #[arg(long, short)]
    pub output: Option<PathBuf>,
    #[command(flatten)]
    pub model: ModelArgs,
    /// Print a JSON summary per frame (one line each) on stdout.
    #[arg(long)]
    pub stats: bool,
    /// Frames clustered in parallel (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

/// The `--stats` line of one frame.
#[derive(Serialize)]
struct Stats<'a> {
    input: String,
    fsize: usize,
    merge: fcc_golden::MergeMode,
    #[serde(flatten)]
    result: &'a Clustering,
    time_ms: f64,
}

fn output_for(args: &ClusterArgs, input: &Path) -> Option<PathBuf> {
    let out = args.output.as_ref()?;
    if args.input.len() == 1 {
        return Some(out.clone());
    }
    let stem = input.file_stem().unwrap_or_default().to_string_lossy();
    Some(out.join(format!("{stem}.labels.npy")))
}

fn one(args: &ClusterArgs, input: &Path) -> anyhow::Result<String> {
    let img = fcc_npy::read_xyz(input)?;
    let params = args.model.params(img.rows, img.cols)?;
    let frame = Frame::from_xyz_f64(img.rows, img.cols, &img.xyz);
    let t = Instant::now();
    let result = cluster(&params, &frame, args.model.merge)
        .with_context(|| format!("{}", input.display()))?;
    let time_ms = t.elapsed().as_secs_f64() * 1e3;
    if let Some(out) = output_for(args, input) {
        fcc_npy::write_labels(&out, result.rows, result.cols, &result.labels)?;
    }
    let stats = Stats {
        input: input.display().to_string(),
        fsize: params.fsize,
        merge: args.model.merge,
        result: &result,
        time_ms,
    };
    Ok(serde_json::to_string(&stats)?)
}

pub fn run(args: &ClusterArgs) -> anyhow::Result<()> {
    if args.input.len() > 1 {
        if let Some(dir) = &args.output {
            if dir.exists() && !dir.is_dir() {
                bail!(
                    "{}: several inputs need --output to be a directory",
                    dir.display()
                );
            }
            std::fs::create_dir_all(dir)
                .with_context(|| format!("{}: cannot create directory", dir.display()))?;
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()?;
    let lines: Vec<anyhow::Result<String>> =
        pool.install(|| args.input.par_iter().map(|i| one(args, i)).collect());
    for line in lines {
        let line = line?;
        if args.stats {
            println!("{line}");
        }
    }
    Ok(())
}
