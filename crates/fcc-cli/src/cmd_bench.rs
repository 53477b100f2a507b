//! `fcc bench`: golden-model time per frame for each K on synthetic scenes,
//! single-threaded and as a parallel batch, for `exact` and `paper` merging,
//! and what `paper` merging loses.
//!
//! The speed-up of the batch is measured against the same batch run on one
//! thread, not against the one-thread median: that median clusters one frame
//! several times in a row, with its data in the core's caches and its branches
//! learnt, and times short stretches that a busy machine seldom interrupts,
//! while a batch goes through all the frames and counts every interruption.
//! Batches have a fixed size and the one-thread and pooled runs alternate, so
//! a slow stretch of a shared machine does not land on one side only.

use anyhow::Context;
use clap::Args;
use fcc_golden::{cluster, cluster_with, split_components, Frame, MergeMode, Workspace};
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
    /// Times each frame is clustered per K, and batch runs per K on one
    /// thread and on the pool; medians are reported.
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
    /// Intra-channel threshold th_H, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = FccParams::default().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = FccParams::default().th_v)]
    pub th_v: f64,
    #[command(flatten)]
    pub slopes: crate::model_args::SlopeArgs,
    /// Threads of the batch run (default: one per core).
    #[arg(long)]
    pub jobs: Option<usize>,
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
    paper_batch_frames_per_s: f64,
    /// The batch on one thread: the rate the speed-up is measured against.
    one_thread_batch_frames_per_s: f64,
    paper_one_thread_batch_frames_per_s: f64,
    /// Median over alternating runs of the same batch of the pool's rate over
    /// the one-thread rate.
    speedup: f64,
    paper_speedup: f64,
    threads: usize,
    points: f64,
    provisional: f64,
    joins: f64,
    paper_provisional: f64,
    paper_joins: f64,
    clusters_exact: u64,
    clusters_paper: u64,
    split_by_paper: u64,
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Median single-thread milliseconds of clustering each frame `repeat` times,
/// averaged over the frames. One workspace, as a tool looping over frames has.
fn time_ms(p: &FccParams, frames: &[Frame], mode: MergeMode, repeat: usize) -> anyhow::Result<f64> {
    let mut ws = Workspace::default();
    let mut per_frame = Vec::new();
    for f in frames {
        let mut t = Vec::new();
        for _ in 0..repeat.max(1) {
            let s = Instant::now();
            let out = std::hint::black_box(cluster_with(&mut ws, p, f, mode)?);
            t.push(s.elapsed().as_secs_f64() * 1e3);
            ws.recycle(out);
        }
        per_frame.push(median(t));
    }
    Ok(per_frame.iter().sum::<f64>() / per_frame.len() as f64)
}

/// Frames per second of one fixed-size batch: `rounds` passes over the
/// frames, each thread taking the next frame as it finishes one (frames
/// differ in cost, so a fixed split would leave one thread waiting). Each
/// thread keeps one workspace, as a tool going through a dataset does.
fn batch_run(
    pool: &rayon::ThreadPool,
    p: &FccParams,
    frames: &[Frame],
    mode: MergeMode,
    rounds: usize,
) -> anyhow::Result<f64> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let items = frames.len() * rounds;
    let next = AtomicUsize::new(0);
    let s = Instant::now();
    let per_thread = pool.broadcast(|_| -> Result<usize, fcc_golden::GoldenError> {
        let mut ws = Workspace::default();
        let mut n = 0;
        loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            if i >= items {
                return Ok(n);
            }
            let out = cluster_with(&mut ws, p, &frames[i % frames.len()], mode)?;
            ws.recycle(std::hint::black_box(out));
            n += 1;
        }
    });
    let secs = s.elapsed().as_secs_f64();
    let mut total = 0;
    for n in per_thread {
        total += n?;
    }
    Ok(total as f64 / secs)
}

/// A one-thread batch should last at least this long.
const BATCH_RUN_SECS: f64 = 0.1;

struct BatchRates {
    /// Median frames per second of the batch on one thread.
    one: f64,
    /// Median frames per second of the batch on the pool.
    pool: f64,
    /// Median over the pairs of the pool's rate over the one-thread rate.
    speedup: f64,
}

/// The batch on one thread and on the pool, `repeat` times each in
/// alternation after one warm-up of each, every run the same size (enough
/// rounds for [`BATCH_RUN_SECS`] on one thread). Pairing the runs keeps a
/// slow stretch of a shared machine from landing on one side only.
fn batch_rates(
    pool: &rayon::ThreadPool,
    one: &rayon::ThreadPool,
    p: &FccParams,
    frames: &[Frame],
    mode: MergeMode,
    repeat: usize,
) -> anyhow::Result<BatchRates> {
    let round_secs = frames.len() as f64 / batch_run(one, p, frames, mode, 1)?;
    let rounds = ((BATCH_RUN_SECS / round_secs).ceil() as usize).max(1);
    batch_run(pool, p, frames, mode, rounds)?;
    let (mut ones, mut pools, mut ratios) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..repeat.max(1) {
        let o = batch_run(one, p, frames, mode, rounds)?;
        let q = batch_run(pool, p, frames, mode, rounds)?;
        ones.push(o);
        pools.push(q);
        ratios.push(q / o);
    }
    Ok(BatchRates {
        one: median(ones),
        pool: median(pools),
        speedup: median(ratios),
    })
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
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()
        .context("cannot start the batch threads")?;
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .context("cannot start the batch thread")?;
    let threads = pool.current_num_threads();
    let mut rows = Vec::new();
    for &k in &args.fsize {
        let p = args.slopes.apply(FccParams {
            rows: args.rows,
            cols: args.cols,
            fsize: k,
            th_h: args.th_h,
            th_v: args.th_v,
            ..FccParams::default()
        });
        p.validate()?;
        eprintln!("K = {k} ...");
        let exact_ms = time_ms(&p, &frames, MergeMode::Exact, args.repeat)?;
        let paper_ms = time_ms(&p, &frames, MergeMode::Paper, args.repeat)?;
        let exact = batch_rates(&pool, &one, &p, &frames, MergeMode::Exact, args.repeat)?;
        let paper = batch_rates(&pool, &one, &p, &frames, MergeMode::Paper, args.repeat)?;
        let (mut pts, mut prov, mut joins) = (0.0, 0.0, 0.0);
        let (mut paper_prov, mut paper_joins) = (0.0, 0.0);
        let (mut ce, mut cp, mut split) = (0u64, 0u64, 0u64);
        for f in &frames {
            let e = cluster(&p, f, MergeMode::Exact)?;
            let q = cluster(&p, f, MergeMode::Paper)?;
            pts += e.points as f64;
            prov += f64::from(e.provisional);
            joins += e.joins as f64;
            paper_prov += f64::from(q.provisional);
            paper_joins += q.joins as f64;
            ce += u64::from(e.clusters);
            cp += u64::from(q.clusters);
            split += split_components(&e.labels, &q.labels) as u64;
        }
        let n = frames.len() as f64;
        rows.push(Row {
            fsize: k,
            exact_ms,
            paper_ms,
            batch_frames_per_s: exact.pool,
            paper_batch_frames_per_s: paper.pool,
            one_thread_batch_frames_per_s: exact.one,
            paper_one_thread_batch_frames_per_s: paper.one,
            speedup: exact.speedup,
            paper_speedup: paper.speedup,
            threads,
            points: pts / n,
            provisional: prov / n,
            joins: joins / n,
            paper_provisional: paper_prov / n,
            paper_joins: paper_joins / n,
            clusters_exact: ce,
            clusters_paper: cp,
            split_by_paper: split,
        });
    }
    let p = args.slopes.apply(FccParams {
        th_h: args.th_h,
        th_v: args.th_v,
        ..FccParams::default()
    });
    println!(
        "golden model, {} x {}, {} synthetic scenes (dropout {}, missing {}), th_H = {} m, th_V = {} m, slopes {} / {} m per m, median of {} runs",
        args.rows, args.cols, args.frames, args.dropout, args.missing, p.th_h, p.th_v, p.th_h_slope, p.th_v_slope, args.repeat
    );
    println!(
        "| K | merge | ms/frame (1 thread) | batch frames/s (1 thread) | batch frames/s ({threads} threads) | speed-up | points | provisional | joins | clusters | exact clusters split |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for r in &rows {
        println!(
            "| {} | exact | {:.3} | {:.0} | {:.0} | {:.2} x | {:.0} | {:.0} | {:.0} | {} | – |",
            r.fsize,
            r.exact_ms,
            r.one_thread_batch_frames_per_s,
            r.batch_frames_per_s,
            r.speedup,
            r.points,
            r.provisional,
            r.joins,
            r.clusters_exact,
        );
        println!(
            "| {} | paper | {:.3} | {:.0} | {:.0} | {:.2} x | {:.0} | {:.0} | {:.0} | {} | {} ({:.1} %) |",
            r.fsize,
            r.paper_ms,
            r.paper_one_thread_batch_frames_per_s,
            r.paper_batch_frames_per_s,
            r.paper_speedup,
            r.points,
            r.paper_provisional,
            r.paper_joins,
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
