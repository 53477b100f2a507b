//! `fcc bench`: golden-model time per frame for each K on synthetic scenes,
//! single-threaded and as a parallel batch, and what `paper` merging loses.

use anyhow::Context;
use clap::Args;
use fcc_golden::{cluster, split_components, Frame, MergeMode};
use fcc_params::FccParams;
use fcc_scene::{generate, SceneConfig};
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Filter sizes to measure.
    #[arg(long, num_args = 1.., value_delimiter = ',', allow_negative_numbers = true, default_values_t = [3usize, 5, 7, 9, 11])]
    pub fsize: Vec<usize>,
    /// Synthetic scenes (seeds 0..frames).
    #[arg(long, default_value_t = 8)]
    pub frames: u64,
    /// Times each frame is clustered per K; the median is reported.
    #[arg(long, default_value_t = 5)]
    pub repeat: usize,
    /// Beams (rows) of the synthetic sensor.
    #[arg(long, default_value_t = FccParams::default().rows)]
    pub rows: usize,
    /// Columns of the synthetic sensor.
    #[arg(long, default_value_t = FccParams::default().cols)]
    pub cols: usize,
    /// Beam-dropout probability of the synthetic scenes.
    #[arg(long, allow_negative_numbers = true, default_value_t = SceneConfig::default().dropout)]
    pub dropout: f64,
    /// Missing-return probability of the synthetic scenes.
    #[arg(long, allow_negative_numbers = true, default_value_t = SceneConfig::default().missing)]
    pub missing: f64,
    /// Write the table as JSON here as well.
    #[arg(long)]
    pub json: Option<std::path::PathBuf>,
}

#[derive(Serialize)]
struct Row {
    fsize: usize,
    exact_ms: f64,
    paper_ms: f64,
    batch_frames_per_s: f64,
    threads: usize,
    points: f64,
    provisional: f64,
    joins: f64,
    clusters_exact: u64,
    clusters_paper: u64,
    split_by_paper: u64,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Median single-thread milliseconds of clustering each frame `repeat` times.
fn time_ms(p: &FccParams, frames: &[Frame], mode: MergeMode, repeat: usize) -> anyhow::Result<f64> {
    let mut per_frame = Vec::new();
    for f in frames {
        let mut t = Vec::new();
        for _ in 0..repeat.max(1) {
            let s = Instant::now();
            std::hint::black_box(cluster(p, f, mode)?);
            t.push(s.elapsed().as_secs_f64() * 1e3);
        }
        per_frame.push(median(t));
    }
    Ok(per_frame.iter().sum::<f64>() / per_frame.len() as f64)
}

pub fn run(args: &BenchArgs) -> anyhow::Result<()> {
    anyhow::ensure!(args.frames > 0, "--frames must be at least 1");
    eprintln!(
        "generating {} synthetic {} x {} scenes ...",
        args.frames, args.rows, args.cols
    );
    let frames = (0..args.frames)
        .into_par_iter()
        .map(|seed| {
            let cfg = SceneConfig {
                rows: args.rows,
                cols: args.cols,
                seed,
                dropout: args.dropout,
                missing: args.missing,
                ..SceneConfig::default()
            };
            let s = generate(&cfg).with_context(|| format!("scene seed {seed}"))?;
            Ok(Frame::from_xyz_f32(s.rows, s.cols, &s.xyz))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let threads = rayon::current_num_threads();
    let mut rows = Vec::new();
    for &k in &args.fsize {
        let p = FccParams {
            rows: args.rows,
            cols: args.cols,
            fsize: k,
            ..FccParams::default()
        };
        p.validate()?;
        eprintln!("K = {k} ...");
        let exact_ms = time_ms(&p, &frames, MergeMode::Exact, args.repeat)?;
        let paper_ms = time_ms(&p, &frames, MergeMode::Paper, args.repeat)?;
        let batch = std::iter::repeat_n(&frames, args.repeat.max(1))
            .flatten()
            .collect::<Vec<_>>();
        let s = Instant::now();
        batch
            .par_iter()
            .try_for_each(|f| cluster(&p, f, MergeMode::Exact).map(|_| ()))?;
        let batch_frames_per_s = batch.len() as f64 / s.elapsed().as_secs_f64();
        let (mut pts, mut prov, mut joins) = (0.0, 0.0, 0.0);
        let (mut ce, mut cp, mut split) = (0u64, 0u64, 0u64);
        for f in &frames {
            let e = cluster(&p, f, MergeMode::Exact)?;
            let q = cluster(&p, f, MergeMode::Paper)?;
            pts += e.points as f64;
            prov += f64::from(e.provisional);
            joins += e.joins as f64;
            ce += u64::from(e.clusters);
            cp += u64::from(q.clusters);
            split += split_components(&e.labels, &q.labels) as u64;
        }
        let n = frames.len() as f64;
        rows.push(Row {
            fsize: k,
            exact_ms,
            paper_ms,
            batch_frames_per_s,
            threads,
            points: pts / n,
            provisional: prov / n,
            joins: joins / n,
            clusters_exact: ce,
            clusters_paper: cp,
            split_by_paper: split,
        });
    }
    println!(
        "golden model, {} x {}, {} synthetic scenes (dropout {}, missing {}), median of {} runs",
        args.rows, args.cols, args.frames, args.dropout, args.missing, args.repeat
    );
    println!("| K | exact ms/frame (1 thread) | paper ms/frame | batch frames/s ({threads} threads) | points | provisional | joins | clusters exact | clusters paper | exact clusters split by paper |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for r in &rows {
        println!(
            "| {} | {:.2} | {:.2} | {:.0} | {:.0} | {:.0} | {:.0} | {} | {} | {} ({:.1} %) |",
            r.fsize,
            r.exact_ms,
            r.paper_ms,
            r.batch_frames_per_s,
            r.points,
            r.provisional,
            r.joins,
            r.clusters_exact,
            r.clusters_paper,
            r.split_by_paper,
            100.0 * r.split_by_paper as f64 / r.clusters_exact.max(1) as f64
        );
    }
    if let Some(path) = &args.json {
        fcc_io::write_atomic(path, serde_json::to_string_pretty(&rows)?.as_bytes())
            .with_context(|| format!("{}: cannot write", path.display()))?;
    }
    Ok(())
}
