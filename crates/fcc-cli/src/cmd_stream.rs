//! `fcc stream-report`: how soon the golden stream (spec §9) closes its
//! records, and what the reach limits of spec §3 change, on the synthetic
//! corpus and on Ouster captures; and what a column core's slot table
//! absorbs (unions, records and labels freed per column). Writes the
//! tables of docs/streaming.md.

use crate::cmd_lidar::{for_each_frame, percentile, OusterArgs};
use crate::slot_load::{self, SlotLoad};
use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::{same_partition, MergeMode, Record};
use fcc_lidar::eval::synthetic_frames;
use fcc_lidar::ground::detect_ground;
use fcc_lidar::ground::{GroundMethod, GroundParams};
use fcc_lidar::pipeline::{cluster_image, params_for, stream_image, PipelineConfig};
use fcc_lidar::RangeImage;
use fcc_params::FccParams;
use std::fmt::Write as _;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct StreamReportArgs {
    /// Synthetic scenes (seeds 1..=N, ROWS x 2048, ground removed by the generator).
    #[arg(long, default_value_t = 20)]
    pub scenes: u64,
    /// Rows of the synthetic scenes.
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub rows: u32,
    /// Ouster captures as CAPTURE.pcap:META.json (ground removed by `slope`).
    #[arg(long, num_args = 1..)]
    pub capture: Vec<String>,
    /// Frames used per capture.
    #[arg(long, default_value_t = 3)]
    pub capture_frames: usize,
    /// Filter sizes.
    #[arg(long, num_args = 1.., value_delimiter = ',', default_values_t = [3usize, 7, 11])]
    pub fsize: Vec<usize>,
    /// Slots before the runs a pixel names take its representative, in the
    /// second table's representative model (1: the next pixel sees it).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    pub reps_late: u64,
    /// Write the Markdown here (default: standard output).
    #[arg(long)]
    pub output: Option<PathBuf>,
}

/// The reach settings compared: (name, bridge, ring reach).
const SETTINGS: [(&str, Option<u32>, Option<u32>); 4] = [
    ("unlimited", None, None),
    ("bridge 16, ring 16", Some(16), Some(16)),
    ("bridge 4, ring 16", Some(4), Some(16)),
    ("bridge 2, ring 16", Some(2), Some(16)),
];

/// The table's columns.
const COLUMNS: [&str; 16] = [
    "source",
    "K",
    "setting",
    "frames",
    "records",
    "seam-held",
    "p50",
    "p90",
    "p99",
    "max",
    "frames changed",
    "clusters",
    "runs",
    "peak labels",
    "peak open",
    "peak counted",
];

/// The second table's columns: what a column core's slot table absorbs.
const LOAD_COLUMNS: [&str; 19] = [
    "source",
    "K",
    "setting",
    "joined runs per pixel",
    "joined runs at a pixel",
    "row roots: offered per slot",
    "offered beyond one a slot",
    "representatives: joins per slot",
    "joins beyond one a slot",
    "joins in a column",
    "union-find reads per slot",
    "reads in a column",
    "longest walk",
    "merges per slot",
    "merges per frame",
    "merges in a column",
    "records in a column",
    "waiting to close",
    "labels freed in a column",
];

#[derive(Default)]
struct Tally {
    frames: usize,
    records: usize,
    seam_held: usize,
    latency: Vec<u32>,
    /// Frames whose partition differs from the unlimited contract's.
    changed_frames: usize,
    clusters: usize,
    /// Most runs (provisional labels) of one frame, most labels in use at
    /// once in the stream, and most clusters open at once.
    runs: u32,
    peak_labels: u32,
    peak_open: u32,
    /// Most clusters counted open by the open limit's rule (spec §9.1).
    peak_counted: u32,
    /// Most unions of two clusters in a frame, and in one column; most
    /// records closed and labels freed at one column.
    merges: u32,
    col_merges: u32,
    col_closed: u32,
    col_freed: u32,
    /// Most clusters past their last column and not yet closed at once
    /// (before the frame end): what a column core's closer holds.
    waiting: u32,
    /// What the slot table is offered (joined runs, the row-root model).
    load: SlotLoad,
}

/// The most records of a frame of `cols` columns that are past their last
/// column and not yet closed at one column `c` (`last_col < c <=
/// closed_col`), the frame end's closes left out: the clusters a column
/// core's closer holds, each reported once no run of it is open, until its
/// close is sent (docs/column-core.md, item 4), stale reports aside.
fn waiting_to_close<'a>(records: impl Iterator<Item = &'a Record>, cols: usize) -> u32 {
    let mut delta = vec![0i64; cols + 2];
    for r in records.filter(|r| (r.closed_col as usize) < cols) {
        delta[r.last_col as usize + 1] += 1;
        delta[r.closed_col as usize + 1] -= 1;
    }
    let mut now = 0;
    delta
        .iter()
        .map(|d| {
            now += d;
            now
        })
        .max()
        .unwrap_or(0) as u32
}

pub fn run(args: &StreamReportArgs) -> anyhow::Result<()> {
    let mut sources: Vec<(String, Vec<RangeImage>, GroundMethod)> = Vec::new();
    if args.scenes > 0 {
        eprintln!("making {} synthetic scenes", args.scenes);
        let rows = args.rows as usize;
        let frames = synthetic_frames(1..args.scenes + 1, rows, 2048, false)?;
        sources.push((
            format!("synthetic corpus ({} scenes, {rows} x 2048)", args.scenes),
            frames.into_iter().map(|f| f.image).collect(),
            GroundMethod::None,
        ));
    }
    for spec in &args.capture {
        let Some((pcap, meta)) = spec.rsplit_once(':') else {
            bail!("--capture {spec}: give CAPTURE.pcap:META.json");
        };
        let o = OusterArgs {
            meta: Some(PathBuf::from(meta)),
            keep_incomplete: false,
            lidar_frame: false,
            image_origin: fcc_lidar::ouster::ImageOrigin::Sensor,
            skip_frames: 0,
            max_frames: Some(args.capture_frames),
        };
        let mut images = Vec::new();
        for_each_frame(std::path::Path::new(pcap), &o, |f| {
            images.push(f.image);
            Ok(())
        })?;
        if images.is_empty() {
            bail!("{pcap}: no complete frame");
        }
        let name = std::path::Path::new(pcap)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let (r, c) = (images[0].rows, images[0].cols);
        sources.push((
            format!("{name} ({} frames, {r} x {c})", images.len()),
            images,
            GroundMethod::Slope,
        ));
    }
    let mut md = String::new();
    writeln!(md, "| {} |", COLUMNS.join(" | "))?;
    writeln!(md, "|{}", "---|".repeat(COLUMNS.len()))?;
    let mut load = String::new();
    writeln!(load, "| {} |", LOAD_COLUMNS.join(" | "))?;
    writeln!(load, "|{}", "---|".repeat(LOAD_COLUMNS.len()))?;
    for (name, images, ground) in &sources {
        for &k in &args.fsize {
            eprintln!("{name}: K = {k}");
            let cfg_for = |bridge, ring_reach| PipelineConfig {
                params: FccParams {
                    fsize: k,
                    bridge,
                    ring_reach,
                    ..FccParams::default()
                },
                mode: MergeMode::Exact,
                ground: GroundParams {
                    method: *ground,
                    ..GroundParams::default()
                },
                min_points: 0,
            };
            let unlimited: Vec<Vec<u32>> = images
                .iter()
                .map(|im| Ok(cluster_image(im, &cfg_for(None, None))?.labels))
                .collect::<anyhow::Result<_>>()?;
            for (setting, bridge, ring) in SETTINGS {
                let cfg = cfg_for(bridge, ring);
                let mut t = Tally::default();
                for (im, want) in images.iter().zip(&unlimited) {
                    let framed = cluster_image(im, &cfg)?;
                    let streamed = stream_image(im, &cfg, |_| {})?;
                    if !same_partition(&framed.labels, &streamed.result.labels) {
                        bail!("{name}, K = {k}, {setting}: the stream's partition differs from frame mode's (a bug: spec §9.1)");
                    }
                    t.frames += 1;
                    t.clusters += framed.clusters as usize;
                    t.changed_frames += usize::from(!same_partition(want, &framed.labels));
                    t.runs = t.runs.max(streamed.stats.runs);
                    t.peak_labels = t.peak_labels.max(streamed.stats.peak_labels);
                    t.peak_open = t.peak_open.max(streamed.stats.peak_open);
                    t.peak_counted = t.peak_counted.max(streamed.stats.peak_counted);
                    let st = &streamed.stats;
                    t.merges = t.merges.max(st.merges);
                    t.col_merges = t.col_merges.max(st.peak_col_merges);
                    t.col_closed = t.col_closed.max(st.peak_col_closed);
                    t.col_freed = t.col_freed.max(st.peak_col_freed);
                    let kept = im.without(&detect_ground(im, &cfg.ground)?.mask);
                    slot_load::measure(
                        &params_for(im, &cfg.params),
                        &kept.to_frame(),
                        args.reps_late,
                        &mut t.load,
                    )?;
                    t.waiting = t.waiting.max(waiting_to_close(
                        streamed.records.iter().map(|r| &r.record),
                        im.cols,
                    ));
                    for r in &streamed.records {
                        t.records += 1;
                        if (r.record.closed_col as usize) < im.cols {
                            t.latency.push(r.record.closed_col - r.record.last_col);
                        } else {
                            t.seam_held += 1;
                        }
                    }
                }
                t.latency.sort_unstable();
                let q = |p| percentile(&t.latency, p).map_or("-".into(), |v| v.to_string());
                writeln!(
                    md,
                    "| {name} | {k} | {setting} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                    t.frames,
                    t.records,
                    t.seam_held,
                    q(50),
                    q(90),
                    q(99),
                    t.latency.last().map_or("-".into(), |v| v.to_string()),
                    t.changed_frames,
                    t.clusters,
                    t.runs,
                    t.peak_labels,
                    t.peak_open,
                    t.peak_counted,
                )?;
                writeln!(
                    load,
                    "| {name} | {k} | {setting} | {:.2} | {} | {:.3} | {:.4} | {:.3} | {:.4} | {} | {:.3} | {} | {} | {:.3} | {} | {} | {} | {} | {} |",
                    t.load.joined_runs as f64 / t.load.labelled.max(1) as f64,
                    t.load.joined_runs_max,
                    t.load.offered as f64 / t.load.slots.max(1) as f64,
                    t.load.offered_more as f64 / t.load.slots.max(1) as f64,
                    t.load.rep_joins as f64 / t.load.slots.max(1) as f64,
                    t.load.rep_joins_more as f64 / t.load.slots.max(1) as f64,
                    t.load.rep_joins_col,
                    t.load.uf_reads as f64 / t.load.slots.max(1) as f64,
                    t.load.uf_reads_col,
                    t.load.uf_walk_max,
                    t.load.merges as f64 / t.load.slots.max(1) as f64,
                    t.merges,
                    t.col_merges,
                    t.col_closed,
                    t.waiting,
                    t.col_freed,
                )?;
            }
        }
    }
    writeln!(md)?;
    md.push_str(&load);
    match &args.output {
        Some(p) => {
            fcc_io::write_atomic(p, md.as_bytes())
                .with_context(|| format!("{}: cannot write", p.display()))?;
            eprintln!("wrote {}", p.display());
        }
        None => print!("{md}"),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(last_col: u32, closed_col: u32) -> Record {
        Record {
            frame: 0,
            id: 1,
            points: 1,
            first_col: last_col,
            last_col,
            closed_col,
            seam: false,
            first_row: 0,
            last_row: 0,
            min: [0; 3],
            max: [0; 3],
            range2_min: 0,
            range2_max: 0,
            sum: [0; 3],
            sum_xx: 0,
            sum_xy: 0,
            sum_yy: 0,
        }
    }

    #[test]
    fn waiting_counts_records_between_their_last_and_closing_columns() {
        // Waiting over columns 3..=5, 4..=7 and 6..=6; the frame end's
        // close (column 10 of 10) does not count.
        let rs = [record(2, 5), record(3, 7), record(5, 6), record(1, 10)];
        assert_eq!(waiting_to_close(rs.iter(), 10), 2);
        let rs = [record(2, 5), record(3, 7), record(4, 6), record(1, 10)];
        assert_eq!(waiting_to_close(rs.iter(), 10), 3);
        assert_eq!(waiting_to_close([].iter(), 10), 0);
    }
}
