//! Real LiDAR data on the command line: cluster Ouster captures, KITTI /
//! SemanticKITTI scans, PCD, PLY and `.npy` range images into labels,
//! coloured PLY and PNG pictures; convert them to `.npy` range images; and
//! measure clustering quality against ground truth.
//!
//! Commands (as wired in `main.rs`): [`ClusterLidarArgs`] / [`run_cluster`],
//! [`ConvertArgs`] / [`run_convert`], [`EvalArgs`] / [`run_eval`].

use crate::model_args::ModelArgs;
use crate::sensor_args::VelodyneArgs;
use anyhow::{bail, Context};
use clap::Args;
use fcc_golden::MergeMode;
use fcc_lidar::cloud::{read_point_cloud, write_ply_with_intensity, PlyFormat};
use fcc_lidar::clusters::{cluster_rows, frame_cluster_records, write_cluster_table, ClusterRow};
use fcc_lidar::eval::{
    evaluate, evaluate_given, score_frame, synthetic_frames, EvalConfig, EvalFrame,
};
use fcc_lidar::ground::{GroundMethod, GroundParams};
use fcc_lidar::labels::{read_label_file, write_label_file, DEFAULT_LABEL_CLASS};
use fcc_lidar::ouster::{CaptureStats, ImageOrigin, OusterFrame};
use fcc_lidar::picture::{cluster_colour, cluster_colours, render_overview, Overview};
use fcc_lidar::pipeline::{
    cluster_image, stream_image, ClosedRecord, PipelineConfig, PipelineResult,
};
use fcc_lidar::projection::{project, BackProjection, ProjectionConfig, VerticalLayout};
use fcc_lidar::sinks::mcap::{McapFrame, McapSink};
use fcc_lidar::source::{for_each_ouster_frame, Frame as Item, InputKind, Source, SourceOptions};
use fcc_lidar::RangeImage;
use fcc_pixel::record::{frame_beats, FrameEnd, RECORD_WORDS};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// How point clouds become range images.
#[derive(Args, Debug, Clone)]
pub struct ProjectionArgs {
    /// Rows of the range image of a point cloud (beams).
    #[arg(long, default_value_t = 64)]
    pub rows: usize,
    /// Columns of the range image of a point cloud.
    #[arg(long, default_value_t = 2048)]
    pub cols: usize,
    /// Top of the vertical field of view, degrees.
    #[arg(long, default_value_t = 3.0, allow_hyphen_values = true)]
    pub fov_up: f64,
    /// Bottom of the vertical field of view, degrees.
    #[arg(long, default_value_t = -25.0, allow_hyphen_values = true)]
    pub fov_down: f64,
    /// Beam elevations: a built-in table (vlp16, vlp32c, hdl32e, hdl64e) or
    /// a text file of elevations in degrees, one per line, top beam first;
    /// replaces the field of view and sets the rows.
    #[arg(long)]
    pub beams: Option<PathBuf>,
}

impl ProjectionArgs {
    fn config(&self) -> anyhow::Result<ProjectionConfig> {
        // A built-in beam table, unless a file of that name exists.
        let table = self
            .beams
            .as_ref()
            .filter(|p| !p.exists())
            .and_then(|p| fcc_lidar::velodyne::beam_table(&p.to_string_lossy()));
        let cfg = match &self.beams {
            Some(_) if table.is_some() => {
                let beams = table.unwrap_or_default();
                ProjectionConfig {
                    rows: beams.len(),
                    cols: self.cols,
                    layout: VerticalLayout::Beams(beams),
                }
            }
            Some(path) => {
                let text = std::fs::read_to_string(path)
                    .with_context(|| format!("{}: cannot read", path.display()))?;
                let beams = text
                    .lines()
                    .map(str::trim)
                    .filter(|l| !l.is_empty() && !l.starts_with('#'))
                    .enumerate()
                    .map(|(i, l)| {
                        l.parse::<f64>().with_context(|| {
                            format!(
                                "{}: line {}: `{l}` is not an angle in degrees",
                                path.display(),
                                i + 1
                            )
                        })
                    })
                    .collect::<anyhow::Result<Vec<f64>>>()?;
                ProjectionConfig {
                    rows: beams.len(),
                    cols: self.cols,
                    layout: VerticalLayout::Beams(beams),
                }
            }
            None => ProjectionConfig {
                rows: self.rows,
                cols: self.cols,
                layout: VerticalLayout::Fov {
                    up_deg: self.fov_up,
                    down_deg: self.fov_down,
                },
            },
        };
        cfg.validate()?;
        Ok(cfg)
    }
}

/// Ground removal before clustering.
#[derive(Args, Debug, Clone)]
pub struct GroundArgs {
    /// Ground removal: `slope` (column walk seeded by a plane fit), `plane`
    /// (RANSAC plane) or `none`. Default: `slope` for captures and point
    /// clouds, `none` for .npy range images (taken as already prepared, as
    /// FCC assumes).
    #[arg(long)]
    pub ground: Option<GroundMethod>,
    /// Steepest rise between consecutive ground returns, degrees (`slope`).
    #[arg(long, allow_negative_numbers = true, default_value_t = GroundParams::default().max_slope_deg)]
    pub ground_max_slope: f64,
    /// Distance from the ground plane still counted as ground, metres (`plane`).
    #[arg(long, allow_negative_numbers = true, default_value_t = GroundParams::default().plane_distance_m)]
    pub ground_distance: f64,
}

impl GroundArgs {
    /// The method asked for, or the default for this kind of input.
    fn method(&self, range_image: bool) -> GroundMethod {
        self.ground.unwrap_or(if range_image {
            GroundMethod::None
        } else {
            GroundMethod::Slope
        })
    }

    pub(crate) fn params(&self, range_image: bool) -> anyhow::Result<GroundParams> {
        let p = GroundParams {
            method: self.method(range_image),
            max_slope_deg: self.ground_max_slope,
            plane_distance_m: self.ground_distance,
            ..GroundParams::default()
        };
        p.validate()?;
        Ok(p)
    }
}

/// Ouster capture options.
#[derive(Args, Debug, Clone)]
pub struct OusterArgs {
    /// Ouster metadata JSON of the capture(s) (default: the .json beside each
    /// capture with the same name).
    #[arg(long)]
    pub meta: Option<PathBuf>,
    /// Also use frames that miss columns (missing columns are empty).
    #[arg(long)]
    pub keep_incomplete: bool,
    /// Points in the lidar frame instead of the sensor frame.
    #[arg(long)]
    pub lidar_frame: bool,
    /// Where Ouster images start: sensor (the sensor's destaggered image,
    /// as Ouster's SDK makes it) or sweep (rotated by the largest
    /// destaggering shift, so that each column is complete a few columns
    /// after the sweep passes it; what `fcc live --image-origin sweep`
    /// streams).
    #[arg(long, default_value = "sensor")]
    pub image_origin: ImageOrigin,
    /// Skip this many frames of each capture.
    #[arg(long, default_value_t = 0)]
    pub skip_frames: usize,
    /// Use at most this many frames of each capture.
    #[arg(long)]
    pub max_frames: Option<usize>,
}

impl OusterArgs {
    /// The input source's options for these capture options, the Velodyne
    /// ones and the rest.
    fn source(
        &self,
        velodyne: Option<&VelodyneArgs>,
        topic: Option<&str>,
        projection: ProjectionConfig,
    ) -> SourceOptions {
        SourceOptions {
            meta: self.meta.clone(),
            keep_incomplete: self.keep_incomplete,
            lidar_frame: self.lidar_frame,
            origin: self.image_origin,
            skip_frames: self.skip_frames,
            max_frames: self.max_frames,
            sensor: velodyne.map(VelodyneArgs::sensor).unwrap_or_default(),
            velodyne: velodyne.map(VelodyneArgs::options).unwrap_or_default(),
            topic: topic.map(str::to_string),
            projection,
            range_images: true,
            strict: false,
        }
    }
}

/// Every frame of one input, in order, to `f`: the source's notes and, at
/// the end, its warnings and summary line on stderr.
fn for_each_input_frame(
    input: &Path,
    truth: Option<&Path>,
    opts: &SourceOptions,
    f: impl FnMut(Item) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let summary = Source::open(input, truth, opts)?.for_each(|n| eprintln!("{n}"), f)?;
    for w in &summary.warnings {
        eprintln!("warning: {w}");
    }
    if let Some(line) = &summary.line {
        eprintln!("{line}");
    }
    Ok(())
}

#[derive(Args, Debug, Clone)]
pub struct ClusterLidarArgs {
    /// Inputs: Ouster captures (.pcap, .pcapng) with their JSON metadata,
    /// Velodyne captures, ROS 2 recordings (.mcap, PointCloud2), point clouds
    /// (.bin KITTI/SemanticKITTI, .pcd, .ply) or range images (.npy of shape
    /// (R, C, 3)). A capture or recording gives one result per frame.
    #[arg(long, short, required = true, num_args = 1..)]
    pub input: Vec<PathBuf>,
    #[command(flatten)]
    pub model: ModelArgs,
    #[command(flatten)]
    pub ground: GroundArgs,
    /// Drop clusters of N points or fewer (the authors' pipeline used 40).
    #[arg(long, default_value_t = 0)]
    pub min_points: usize,
    #[command(flatten)]
    pub projection: ProjectionArgs,
    #[command(flatten)]
    pub ouster: OusterArgs,
    #[command(flatten)]
    pub velodyne: VelodyneArgs,
    /// Topic of .mcap inputs (default: the only sensor_msgs/msg/PointCloud2 topic).
    #[arg(long)]
    pub topic: Option<String>,
    /// Ground truth per input, in input order: SemanticKITTI .label for a
    /// point cloud, a .npy label image (R, C) for a range image. Shown beside
    /// the clustering in the picture and scored in --stats.
    #[arg(long, num_args = 1..)]
    pub truth: Vec<PathBuf>,
    /// Write the picture here (range image by cluster, ground truth, bird's-eye view).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Write the labels as a .npy label image (R, C) uint32; with several
    /// results, `<stem>_<name>.npy` beside it.
    #[arg(long, short, alias = "labels-npy")]
    pub output: Option<PathBuf>,
    /// Write SemanticKITTI .label: per input point for a point cloud, per
    /// point of the PLY (valid pixels in raster order) for a range image.
    #[arg(long)]
    pub label: Option<PathBuf>,
    /// Semantic class of clustered points in --label (SemanticKITTI id;
    /// default 10, car, the commonest thing class).
    #[arg(long, default_value_t = DEFAULT_LABEL_CLASS)]
    pub label_class: u16,
    /// Write the clustered points as a colour PLY with a label property
    /// (and intensity when the input has it).
    #[arg(long)]
    pub ply: Option<PathBuf>,
    /// Write one row per cluster per frame (id, points, centroid, box,
    /// closest and farthest range, first pixel) as .csv or .json.
    #[arg(long)]
    pub clusters: Option<PathBuf>,
    /// Half-width of the bird's-eye view, metres (default: from the data).
    #[arg(long, allow_negative_numbers = true)]
    pub bev_extent: Option<f32>,
    /// Print a JSON summary per frame (one line each) on stdout.
    #[arg(long)]
    pub stats: bool,
    /// Cluster column by column with the golden stream (spec §9): one JSON
    /// line per cluster on stdout as it closes (or the table in --clusters),
    /// the label image numbered by closing order; --stats adds the latency
    /// in columns from each cluster's last column to its record.
    #[arg(long)]
    pub stream: bool,
    /// With --stream: write each frame's record beats as the
    /// column-streaming core sends them (spec §9.4: 11 little-endian 64-bit
    /// words per record, then the frame's end beat, which carries `tlast`),
    /// the golden stream's, for a bench or a board to compare with. Every
    /// cluster is sent, so no --min-points.
    #[arg(long)]
    pub beats: Option<PathBuf>,
    /// Write a ROS 2 recording (MCAP): per frame a sensor_msgs/msg/PointCloud2
    /// with the cluster `label` and a visualization_msgs/msg/MarkerArray of
    /// the clusters' boxes, stamped with the frame's time where the input
    /// has one (Ouster captures, ROS 2 recordings), else 0.1 s apart from 0.
    #[arg(long)]
    pub mcap: Option<PathBuf>,
    /// Frames clustered in parallel (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Make lost points an error: label overflow, coordinates beyond the
    /// Q7.8 range, points outside the field of view, a capture with no frame.
    #[arg(long)]
    pub strict: bool,
}

impl ClusterLidarArgs {
    /// Every file the run reads.
    fn inputs(&self) -> Vec<&Path> {
        let mut v: Vec<&Path> = self
            .input
            .iter()
            .chain(&self.truth)
            .map(PathBuf::as_path)
            .collect();
        v.extend(self.ouster.meta.as_deref());
        v.extend(self.projection.beams.as_deref());
        v.extend(self.velodyne.velodyne_calibration.as_deref());
        v
    }

    /// Every output asked for, with its option, for one result (`name`).
    fn outputs(&self, name: &str, single: bool) -> Vec<(&'static str, PathBuf)> {
        [
            ("--png", &self.png),
            ("--output", &self.output),
            ("--label", &self.label),
            ("--ply", &self.ply),
            ("--beats", &self.beats),
        ]
        .into_iter()
        .filter_map(|(flag, p)| p.as_ref().map(|p| (flag, output_path(p, name, single))))
        .collect()
    }

    /// Refuse outputs that would overwrite an input or each other.
    fn check_outputs(&self, name: &str, single: bool) -> anyhow::Result<()> {
        let mut outs = self.outputs(name, single);
        // One table and one recording for the whole run, named as given.
        outs.extend(self.clusters.as_ref().map(|p| ("--clusters", p.clone())));
        outs.extend(self.mcap.as_ref().map(|p| ("--mcap", p.clone())));
        let outs: Vec<(&str, &Path)> = outs.iter().map(|(f, p)| (*f, p.as_path())).collect();
        fcc_io::check_outputs(self.inputs(), &outs)?;
        Ok(())
    }
}

/// Refuse a `--png` path that does not end in `.png` (only PNG is written).
pub fn check_png_path(png: Option<&Path>) -> anyhow::Result<()> {
    if let Some(p) = png {
        let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
        if !ext.eq_ignore_ascii_case("png") {
            bail!(
                "{}: --png writes PNG pictures only; give a name ending in .png",
                p.display()
            );
        }
    }
    Ok(())
}

fn stem(path: &Path) -> String {
    path.file_stem()
        .unwrap_or_default()
        .to_string_lossy()
        .into_owned()
}

/// `out` for a single result, `out` with `_<name>` before the extension otherwise.
fn output_path(out: &Path, name: &str, single: bool) -> PathBuf {
    if single {
        return out.to_path_buf();
    }
    let ext = out
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    out.with_file_name(format!("{}_{name}{ext}", stem(out)))
}

/// What `process` gives for one result: its `--stats` line, its rows of the
/// cluster table, and with `--mcap` its points, their labels and its rows.
type Processed = (String, Vec<ClusterRow>, Option<McapParts>);

/// Points, their labels and the clusters of one frame, for the MCAP sink.
pub(crate) type McapParts = (Vec<[f32; 3]>, Vec<u32>, Vec<ClusterRow>);

/// Per point of the outputs: coordinates, cluster, ground, intensity.
type PerPoint = (Vec<[f32; 3]>, Vec<u32>, Vec<bool>, Option<Vec<f32>>);

/// The `--stats` line of one frame.
#[derive(Serialize)]
struct FrameStats {
    input: String,
    rows: usize,
    cols: usize,
    points: usize,
    ground_points: usize,
    clusters: u32,
    clusters_before_min_points: u32,
    fsize: usize,
    merge: MergeMode,
    /// Provisional labels allocated by pass 1.
    provisional: u32,
    /// Pass-2 pairs that passed the threshold (frame mode).
    #[serde(skip_serializing_if = "Option::is_none")]
    joins: Option<u64>,
    /// Joins that united two different components (frame mode).
    #[serde(skip_serializing_if = "Option::is_none")]
    merges: Option<u64>,
    overflow: bool,
    /// Valid pixels left unlabelled by label overflow.
    unlabelled: usize,
    /// Provisional labels the frame needs (more than 2^B - 1 on overflow).
    labels_needed: u64,
    /// Points (not ground) beyond the Q7.8 range (about ±128 m), not clustered.
    out_of_range: usize,
    /// Point clouds: input points, points above or below the field of view,
    /// points that lost their pixel to a nearer point, points with no pixel.
    #[serde(skip_serializing_if = "Option::is_none")]
    input_points: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    outside_fov: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pixel_shared: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    unprojected: Option<usize>,
    time_ms: f64,
    /// `--stream`: when the records closed.
    #[serde(skip_serializing_if = "Option::is_none")]
    stream: Option<StreamLatency>,
    /// PQ, SQ, RQ per pixel of the range image (as `fcc eval` scores).
    #[serde(skip_serializing_if = "Option::is_none")]
    quality: Option<fcc_lidar::eval::Scores>,
    /// Point clouds: PQ, SQ, RQ per input point (points that shared a pixel
    /// take their label from the back-projection).
    #[serde(skip_serializing_if = "Option::is_none")]
    quality_per_point: Option<fcc_lidar::eval::Scores>,
}

/// Latency of one streamed frame's records, in columns from a cluster's
/// last column to the column at which it closed (`closed_col - last_col`),
/// over the records that closed before the frame end; the seam-held ones
/// (closed at the frame end, spec §9.2) are counted apart.
#[derive(Serialize, Debug, Clone, Default, PartialEq)]
pub struct StreamLatency {
    pub records: usize,
    pub seam_held: usize,
    pub p50: Option<u32>,
    pub p90: Option<u32>,
    pub p99: Option<u32>,
    pub max: Option<u32>,
    /// Most provisional labels in use at once.
    pub peak_labels: u32,
}

impl StreamLatency {
    /// The figures of `records` of a frame of `cols` columns.
    pub fn of(records: &[fcc_golden::Record], cols: usize, peak_labels: u32) -> StreamLatency {
        let mut lat: Vec<u32> = records
            .iter()
            .filter(|r| (r.closed_col as usize) < cols)
            .map(|r| r.closed_col - r.last_col)
            .collect();
        lat.sort_unstable();
        StreamLatency {
            records: records.len(),
            seam_held: records.len() - lat.len(),
            p50: percentile(&lat, 50),
            p90: percentile(&lat, 90),
            p99: percentile(&lat, 99),
            max: lat.last().copied(),
            peak_labels,
        }
    }
}

/// The `q`-th percentile of sorted values (nearest rank), `None` for none.
pub fn percentile(sorted: &[u32], q: usize) -> Option<u32> {
    if sorted.is_empty() {
        return None;
    }
    let rank = (q * sorted.len()).div_ceil(100).max(1);
    Some(sorted[rank - 1])
}

/// Half-width of the bird's-eye view: the 95th percentile of horizontal
/// range, rounded up to 10 m, within 10..=80 m.
fn auto_extent(image: &RangeImage) -> f32 {
    let mut d: Vec<f32> = (0..image.pixels())
        .filter_map(|i| image.point(i))
        .map(|p| (p[0] * p[0] + p[1] * p[1]).sqrt())
        .collect();
    if d.is_empty() {
        return 40.0;
    }
    let k = (d.len() * 95 / 100).min(d.len() - 1);
    let (_, v, _) = d.select_nth_unstable_by(k, f32::total_cmp);
    ((*v / 10.0).ceil() * 10.0).clamp(10.0, 80.0)
}

/// What a frame lost, one sentence each: label overflow, points beyond the
/// Q7.8 range, points outside the field of view.
fn loss_warnings(item: &Item, out: &PipelineResult) -> Vec<String> {
    let mut w = Vec::new();
    let c = &out.clustering;
    if c.overflow {
        let bits = fcc_params::FccParams::label_bits_for(out.labels_needed);
        w.push(format!(
            "label overflow: {} of {} points left unlabelled; the frame needs {} provisional labels, --label-bits {} has {}; use --label-bits {bits}",
            c.unlabelled,
            c.points,
            out.labels_needed,
            out.params.label_bits,
            out.params.max_label(),
        ));
    }
    if out.open_refused > 0 {
        w.push(format!(
            "open limit: {} runs left unlabelled, started while {} clusters counted open (spec §9.1); raise --open-limit",
            out.open_refused,
            out.params.open_limit.unwrap_or(0),
        ));
    }
    if out.out_of_range > 0 {
        w.push(format!(
            "{} points beyond the Q7.8 coordinate range (about ±128 m) were not clustered",
            out.out_of_range
        ));
    }
    let l = &item.losses;
    if l.outside_fov > 0 {
        w.push(format!(
            "{} of {} points lie outside the vertical field of view and were squeezed into the top or bottom row ({} points lost their pixel to a nearer one); fit --fov-up/--fov-down or give --beams",
            l.outside_fov, l.input_points, l.pixel_shared
        ));
    }
    w
}

/// The caption's note on lost points, empty when none were lost.
fn loss_caption(out: &PipelineResult) -> String {
    let mut s = String::new();
    if out.clustering.overflow || out.open_refused > 0 {
        s.push_str(&format!(
            ", {}: {} POINTS UNLABELLED",
            if out.clustering.overflow {
                "LABEL OVERFLOW"
            } else {
                "OPEN LIMIT"
            },
            out.clustering.unlabelled
        ));
    }
    if out.out_of_range > 0 {
        s.push_str(&format!(", {} POINTS OUT OF RANGE", out.out_of_range));
    }
    s
}

/// The caption's quality against ground truth, empty without it.
fn quality_caption(q: Option<&fcc_lidar::eval::Scores>) -> String {
    q.map(|q| format!(", PQ {:.3} SQ {:.3} RQ {:.3} (PER PIXEL)", q.pq, q.sq, q.rq))
        .unwrap_or_default()
}

/// Hardware that clusters a frame in place of the golden model (`fcc board
/// run`): it gets the frame without its ground and the golden model's
/// result, and returns its own labels, already checked against it.
pub trait Hardware {
    fn cluster(
        &self,
        name: &str,
        kept: &RangeImage,
        gold: &PipelineResult,
    ) -> anyhow::Result<Vec<u32>>;

    /// With `--stream` (the column core): the frame's records, checked
    /// against the golden stream's `records` (in closing order) and its
    /// end beat `end`; the outputs are then the golden stream's.
    fn stream(
        &self,
        name: &str,
        kept: &RangeImage,
        gold: &PipelineResult,
        records: &[ClosedRecord],
        end: FrameEnd,
    ) -> anyhow::Result<()>;
}

fn process(
    args: &ClusterLidarArgs,
    cfg: &PipelineConfig,
    item: &Item,
    single: bool,
    hw: Option<&dyn Hardware>,
) -> anyhow::Result<Processed> {
    args.check_outputs(&item.name, single)?;
    let t = Instant::now();
    let mut end = None;
    let (mut out, streamed): (PipelineResult, Option<(Vec<ClosedRecord>, u32)>) = if args.stream {
        let s = stream_image(&item.image, cfg, |_| {}).with_context(|| item.name.clone())?;
        // Every record is the stream's (--beats refuses --min-points).
        end = Some(s.stats.frame_end());
        (s.result, Some((s.records, s.stats.peak_labels)))
    } else {
        (
            cluster_image(&item.image, cfg).with_context(|| item.name.clone())?,
            None,
        )
    };
    let time_ms = t.elapsed().as_secs_f64() * 1e3;
    if let (Some(hw), Some((records, _)), Some(end)) = (hw, &streamed, end) {
        // The records the outputs are made of are the hardware's (equal to
        // the golden stream's, or `stream` failed).
        let kept = item.image.without(&out.ground.mask);
        hw.stream(&item.name, &kept, &out, records, end)?;
    } else if let Some(hw) = hw {
        // The outputs carry the hardware's labels (equal to the golden
        // model's, or `cluster` failed), through the same min-points filter.
        let kept = item.image.without(&out.ground.mask);
        let labels = hw.cluster(&item.name, &kept, &out)?;
        (out.labels, out.clusters) = if cfg.min_points > 0 {
            fcc_lidar::labels::filter_min_points(&labels, cfg.min_points)
        } else {
            let clusters = labels.iter().copied().max().unwrap_or(0);
            (labels, clusters)
        };
    }
    let warnings = loss_warnings(item, &out);
    if args.strict {
        if let Some(w) = warnings.first() {
            bail!("{}: {w} (--strict)", item.name);
        }
    }
    for w in &warnings {
        eprintln!("warning: {}: {w}", item.name);
    }
    let cloud = item.projection.is_some();
    let mut wrote: Vec<PathBuf> = Vec::new();
    let quality = match &item.truth {
        Some(truth) => Some(score_frame(&out.labels, truth, &EvalConfig::default())?.scores()),
        None => None,
    };
    if let Some(p) = &args.png {
        let title = format!(
            "{}: K={} {}, {} CLUSTERS{}, GROUND {}{}{}",
            item.name,
            out.params.fsize,
            if args.model.merge == MergeMode::Exact {
                "EXACT"
            } else {
                "PAPER"
            },
            out.clusters,
            if args.min_points > 0 {
                format!(" > {} POINTS", args.min_points)
            } else {
                String::new()
            },
            cfg.ground.method,
            quality_caption(quality.as_ref()),
            loss_caption(&out)
        );
        let instances = item
            .truth
            .as_ref()
            .map(|t| {
                t.iter()
                    .filter(|&&l| l != 0)
                    .collect::<std::collections::HashSet<_>>()
                    .len()
            })
            .unwrap_or(0);
        let pic = render_overview(&Overview {
            image: &item.image,
            labels: &out.labels,
            ground: Some(&out.ground.mask),
            truth: item.truth.as_deref(),
            title,
            truth_title: format!("GROUND TRUTH: {instances} INSTANCES"),
            bev_extent_m: args.bev_extent.unwrap_or_else(|| auto_extent(&item.image)),
        })?;
        let path = output_path(p, &item.name, single);
        pic.save_png(&path)?;
        wrote.push(path);
    }
    if let Some(p) = &args.output {
        let path = output_path(p, &item.name, single);
        fcc_npy::write_labels(&path, item.image.rows, item.image.cols, &out.labels)?;
        wrote.push(path);
    }
    if let (Some(p), Some((records, _)), Some(end)) = (&args.beats, &streamed, end) {
        let path = output_path(p, &item.name, single);
        let hw: Vec<_> = records.iter().map(|c| c.record.hw()).collect();
        let mut beats = Vec::with_capacity(hw.len() * RECORD_WORDS + 1);
        frame_beats(&hw, end, &mut beats).map_err(|e| anyhow::anyhow!("{}: {e}", item.name))?;
        let bytes: Vec<u8> = beats.iter().flat_map(|(w, _)| w.to_le_bytes()).collect();
        fcc_io::write_atomic(&path, &bytes)
            .with_context(|| format!("{}: cannot write the record beats", path.display()))?;
        wrote.push(path);
    }
    let (points, labels, ground, intensity) = per_point(item, &out)?;
    // For point clouds, also score every input point, not only the pixel
    // winners (`fcc eval` scores pixels, as `quality` does).
    let quality_per_point = match &item.truth_points {
        Some(truth_points) => {
            Some(score_frame(&labels, truth_points, &EvalConfig::default())?.scores())
        }
        None => None,
    };
    if let Some(p) = &args.label {
        let path = output_path(p, &item.name, single);
        write_label_file(&path, &labels, Some(&ground), args.label_class)?;
        wrote.push(path);
    }
    if let Some(p) = &args.ply {
        // The picture's colours: touching clusters differ.
        let map = cluster_colours(item.image.rows, item.image.cols, &out.labels);
        let colours: Vec<[u8; 3]> = labels
            .iter()
            .zip(&ground)
            .map(|(&l, &g)| {
                if l == 0 && g {
                    [110, 80, 50]
                } else {
                    map.get(&l).copied().unwrap_or_else(|| cluster_colour(l))
                }
            })
            .collect();
        let path = output_path(p, &item.name, single);
        write_ply_with_intensity(
            &path,
            &points,
            Some(&colours),
            Some(&labels),
            intensity.as_deref(),
            PlyFormat::BinaryLittleEndian,
        )?;
        wrote.push(path);
    }
    for path in &wrote {
        eprintln!(
            "wrote {} ({}: {} clusters)",
            path.display(),
            item.name,
            out.clusters
        );
    }
    let stats = FrameStats {
        input: item.name.clone(),
        rows: item.image.rows,
        cols: item.image.cols,
        points: item.image.valid_count(),
        ground_points: out.ground.count(),
        clusters: out.clusters,
        clusters_before_min_points: out.clustering.clusters,
        fsize: out.params.fsize,
        merge: args.model.merge,
        provisional: out.clustering.provisional,
        joins: streamed.is_none().then_some(out.clustering.joins),
        merges: streamed.is_none().then_some(out.clustering.merges),
        overflow: out.clustering.overflow,
        unlabelled: out.clustering.unlabelled,
        labels_needed: out.labels_needed,
        out_of_range: out.out_of_range,
        input_points: cloud.then_some(item.losses.input_points),
        outside_fov: cloud.then_some(item.losses.outside_fov),
        pixel_shared: cloud.then_some(item.losses.pixel_shared),
        unprojected: cloud.then_some(item.losses.unprojected),
        time_ms,
        stream: streamed.as_ref().map(|(records, peak)| {
            let r: Vec<fcc_golden::Record> = records.iter().map(|c| c.record).collect();
            StreamLatency::of(&r, item.image.cols, *peak)
        }),
        quality,
        quality_per_point,
    };
    let rows = if args.clusters.is_some() || args.stream || args.mcap.is_some() {
        table_rows(item, &out, &points, &labels, streamed.map(|(r, _)| r))?
    } else {
        Vec::new()
    };
    let mcap = args
        .mcap
        .is_some()
        .then(|| (points.clone(), labels.clone(), rows.clone()));
    Ok((serde_json::to_string(&stats)?, rows, mcap))
}

/// Per point of the outputs: every input point of a cloud, valid pixels
/// otherwise.
pub(crate) fn per_point(item: &Item, out: &PipelineResult) -> anyhow::Result<PerPoint> {
    Ok(match &item.projection {
        Some((proj, pts)) => {
            let labels = proj.labels_to_points(&out.labels, BackProjection::default())?;
            let g: Vec<u32> = out.ground.mask.iter().map(|&g| u32::from(g)).collect();
            let ground = proj.labels_to_points(&g, BackProjection::default())?;
            (
                pts.clone(),
                labels,
                ground.iter().map(|&g| g == 1).collect(),
                item.intensity.clone(),
            )
        }
        None => {
            let idx = valid_pixels(&item.image);
            (
                idx.iter().filter_map(|&i| item.image.point(i)).collect(),
                idx.iter().map(|&i| out.labels[i]).collect(),
                idx.iter().map(|&i| out.ground.mask[i]).collect(),
                item.intensity
                    .as_ref()
                    .map(|v| idx.iter().map(|&i| v[i]).collect()),
            )
        }
    })
}

/// The pixels of `image` that hold a point, in raster order: the points of
/// the per-point outputs of an image without a projection.
pub(crate) fn valid_pixels(image: &RangeImage) -> Vec<usize> {
    (0..image.pixels())
        .filter(|&i| image.point(i).is_some())
        .collect()
}

/// The rows of the cluster table and of `--stream`'s JSON lines for one
/// result: the stream's records in closing order (`streamed`), or frame
/// mode's computed from the frame's pixels.
fn table_rows(
    item: &Item,
    out: &PipelineResult,
    points: &[[f32; 3]],
    labels: &[u32],
    streamed: Option<Vec<ClosedRecord>>,
) -> anyhow::Result<Vec<ClusterRow>> {
    let mut rows = cluster_rows(&item.name, points, labels, &out.labels, item.image.cols)?;
    // The record of each cluster: the stream's, in closing order, or
    // computed from the frame's pixels.
    let records: Vec<(fcc_golden::Record, Option<fcc_golden::OrientedBox>)> = match streamed {
        Some(records) => records
            .into_iter()
            .map(|c| (c.record, c.oriented_box))
            .collect(),
        None => {
            let kept = item.image.without(&out.ground.mask).to_frame();
            frame_cluster_records(&out.params, &kept, &out.labels, out.clusters)
        }
    };
    let mut by_id: Vec<Option<ClusterRow>> = vec![None; records.len() + 1];
    for row in rows.drain(..) {
        if let Some(slot) = by_id.get_mut(row.cluster as usize) {
            *slot = Some(row);
        }
    }
    for (r, obb) in &records {
        if let Some(mut row) = by_id[r.id as usize].take() {
            row.set_record(r, obb.as_ref());
            rows.push(row);
        }
    }
    Ok(rows)
}

/// One frame through the golden stream exactly as `fcc cluster --stream`
/// takes it: the result and the rows it prints, in closing order; with
/// `hw`, the frame (its ground removed) through the hardware too, its
/// records checked against the golden stream's.
pub(crate) fn stream_rows(
    item: &Item,
    cfg: &PipelineConfig,
    hw: Option<&dyn Hardware>,
) -> anyhow::Result<(PipelineResult, Vec<ClusterRow>)> {
    let s = stream_image(&item.image, cfg, |_| {}).with_context(|| item.name.clone())?;
    if let Some(hw) = hw {
        // The records the rows are made of are the hardware's (equal to the
        // golden stream's, or `stream` failed).
        let kept = item.image.without(&s.result.ground.mask);
        hw.stream(
            &item.name,
            &kept,
            &s.result,
            &s.records,
            s.stats.frame_end(),
        )?;
    }
    let (points, labels, _, _) = per_point(item, &s.result)?;
    let rows = table_rows(item, &s.result, &points, &labels, Some(s.records))?;
    Ok((s.result, rows))
}

/// `--stream`'s output: one JSON line per record, flushed.
pub(crate) fn write_json_lines(
    out: &mut impl std::io::Write,
    rows: &[ClusterRow],
) -> anyhow::Result<()> {
    // One write for the batch: a line-buffered stdout would otherwise look
    // for line ends in every piece the serializer hands it.
    let mut buf = Vec::with_capacity(rows.len() * 640);
    for row in rows {
        serde_json::to_writer(&mut buf, row)?;
        buf.push(b'\n');
    }
    out.write_all(&buf)?;
    out.flush()?;
    Ok(())
}

fn progress_bar(len: Option<u64>, what: &str) -> ProgressBar {
    let pb = match len {
        Some(n) => ProgressBar::new(n),
        None => ProgressBar::new_spinner(),
    };
    let template = if len.is_some() {
        format!("{{bar:40}} {{pos}}/{{len}} {what} {{elapsed}} (eta {{eta}})")
    } else {
        format!("{{spinner}} {{pos}} {what} {{elapsed}}")
    };
    if let Ok(style) = ProgressStyle::with_template(&template) {
        pb.set_style(style);
    }
    pb
}

/// `fcc cluster` on real LiDAR data.
pub fn run_cluster(args: &ClusterLidarArgs) -> anyhow::Result<()> {
    run_cluster_on(args, None)
}

/// `fcc cluster`, with every frame also sent through `hw` (one frame at a
/// time, in order) when given.
pub fn run_cluster_on(args: &ClusterLidarArgs, hw: Option<&dyn Hardware>) -> anyhow::Result<()> {
    if !args.truth.is_empty() && args.truth.len() != args.input.len() {
        bail!(
            "--truth names {} files for {} inputs: give one per input, in order",
            args.truth.len(),
            args.input.len()
        );
    }
    check_png_path(args.png.as_deref())?;
    if args.stream && args.model.merge != MergeMode::Exact {
        bail!("--stream clusters exactly (spec §9): drop --merge paper");
    }
    if args.beats.is_some() && !args.stream {
        bail!("--beats writes the column-streaming core's records: add --stream");
    }
    if args.beats.is_some() && args.min_points > 0 {
        bail!(
            "--beats writes what the core sends, every cluster: drop --min-points {}",
            args.min_points
        );
    }
    let sources = SourceOptions {
        strict: args.strict,
        ..args.ouster.source(
            Some(&args.velodyne),
            args.topic.as_deref(),
            args.projection.config()?,
        )
    };
    // The outputs as given; the names of several results are checked per frame.
    args.check_outputs("", true)?;
    let cfg_for = |range_image: bool| -> anyhow::Result<PipelineConfig> {
        Ok(PipelineConfig {
            params: args.model.params(1, 1)?,
            mode: args.model.merge,
            ground: args.ground.params(range_image)?,
            min_points: args.min_points,
        })
    };
    let cfgs = [cfg_for(false)?, cfg_for(true)?];
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()?;
    let batch = if hw.is_some() {
        1
    } else {
        pool.current_num_threads().max(1) * 2
    };
    // One result overall keeps output names as given.
    let single = args.input.len() == 1 && fcc_lidar::source::single_frame(&args.input[0], &sources);
    let pb = progress_bar(None, "frames");
    let mut lines = Vec::new();
    let mut table = Vec::new();
    let mut mcap = args.mcap.as_deref().map(McapSink::create).transpose()?;
    let mut mcap_frames = 0u64;
    let mut flush = |items: &mut Vec<Item>| -> anyhow::Result<()> {
        let res: Vec<anyhow::Result<Processed>> = match hw {
            None => pool.install(|| {
                items
                    .par_iter()
                    .map(|it| process(args, &cfgs[usize::from(it.range_image)], it, single, None))
                    .collect()
            }),
            Some(hw) => items
                .iter()
                .map(|it| {
                    process(
                        args,
                        &cfgs[usize::from(it.range_image)],
                        it,
                        single,
                        Some(hw),
                    )
                })
                .collect(),
        };
        pb.inc(items.len() as u64);
        let stamps: Vec<Option<u64>> = items.iter().map(|it| it.timestamp_ns).collect();
        items.clear();
        for (r, stamp) in res.into_iter().zip(stamps) {
            let (line, rows, parts) = r?;
            if let (Some(sink), Some((points, labels, clusters))) = (&mut mcap, parts) {
                sink.write(&McapFrame {
                    stamp_ns: stamp.unwrap_or(mcap_frames * 100_000_000),
                    frame_id: "lidar",
                    points: &points,
                    labels: &labels,
                    clusters: &clusters,
                })?;
                mcap_frames += 1;
            }
            lines.push(line);
            table.extend(rows);
        }
        Ok(())
    };
    let mut items = Vec::new();
    for (k, input) in args.input.iter().enumerate() {
        let truth = args.truth.get(k).map(PathBuf::as_path);
        for_each_input_frame(input, truth, &sources, |item| {
            items.push(item);
            if items.len() >= batch {
                flush(&mut items)?;
            }
            Ok(())
        })?;
    }
    flush(&mut items)?;
    pb.finish_and_clear();
    if let (Some(sink), Some(p)) = (mcap, &args.mcap) {
        sink.finish()?;
        eprintln!("wrote {} ({mcap_frames} frames)", p.display());
    }
    if lines.is_empty() {
        bail!("no frame was clustered: nothing written");
    }
    if let Some(p) = &args.clusters {
        write_cluster_table(p, &table)?;
    } else if args.stream {
        write_json_lines(&mut std::io::stdout().lock(), &table)?;
    }
    if args.stats {
        for l in &lines {
            println!("{l}");
        }
    }
    Ok(())
}

/// Decode a capture (metadata from `--meta` or beside it), skip and cap
/// frames as asked, and hand each frame to `f`. Returns the frames used and
/// the decoder's statistics; a capture without a single frame is an error
/// that says what it held instead.
pub(crate) fn for_each_frame(
    input: &Path,
    o: &OusterArgs,
    f: impl FnMut(OusterFrame) -> anyhow::Result<()>,
) -> anyhow::Result<(usize, CaptureStats)> {
    let opts = o.source(None, None, ProjectionConfig::default());
    for_each_ouster_frame(input, &opts, |n| eprintln!("{n}"), f)
}

#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// Inputs: Ouster and Velodyne captures, ROS 2 recordings (.mcap), point
    /// clouds (.bin, .pcd, .ply).
    #[arg(long, short, required = true, num_args = 1..)]
    pub input: Vec<PathBuf>,
    /// Output .npy range image (R, C, 3) float32, NaN = empty; with several
    /// frames, `_<input>_f<frame>` is added before the extension.
    #[arg(long, short)]
    pub output: PathBuf,
    #[command(flatten)]
    pub projection: ProjectionArgs,
    #[command(flatten)]
    pub ouster: OusterArgs,
    #[command(flatten)]
    pub velodyne: VelodyneArgs,
    /// Topic of .mcap inputs (default: the only sensor_msgs/msg/PointCloud2 topic).
    #[arg(long)]
    pub topic: Option<String>,
    /// Make lost points an error: points outside the field of view, a
    /// capture with no frame (as `cluster --strict`).
    #[arg(long)]
    pub strict: bool,
}

/// `fcc convert`: range images as .npy, for `cluster`, `sim` and other tools.
pub fn run_convert(args: &ConvertArgs) -> anyhow::Result<()> {
    let proj = args.projection.config()?;
    let mut inputs: Vec<&Path> = args.input.iter().map(PathBuf::as_path).collect();
    inputs.extend(args.ouster.meta.as_deref());
    inputs.extend(args.projection.beams.as_deref());
    fcc_io::check_outputs(inputs.iter().copied(), &[("--output", &args.output)])?;
    let sources = SourceOptions {
        range_images: false,
        strict: args.strict,
        ..args
            .ouster
            .source(Some(&args.velodyne), args.topic.as_deref(), proj)
    };
    let mut images: Vec<(String, RangeImage)> = Vec::new();
    for input in &args.input {
        let cloud = InputKind::of(input, &sources) == Some(InputKind::Cloud);
        for_each_input_frame(input, None, &sources, |frame| {
            if cloud && frame.losses.outside_fov > 0 {
                let w = format!(
                    "{}: {} of {} points lie outside the vertical field of view and were squeezed into the top or bottom row; fit --fov-up/--fov-down or give --beams",
                    input.display(),
                    frame.losses.outside_fov,
                    frame.losses.input_points
                );
                if args.strict {
                    bail!("{w} (--strict)");
                }
                eprintln!("warning: {w}");
            }
            images.push((frame.name, frame.image));
            Ok(())
        })?;
    }
    if images.is_empty() {
        bail!("no frame to convert: nothing written");
    }
    let single = images.len() == 1;
    for (name, img) in &images {
        let out = output_path(&args.output, name, single);
        fcc_io::check_outputs(inputs.iter().copied(), &[("--output", &out)])?;
        fcc_npy::write_xyz_f32(&out, img.rows, img.cols, &img.xyz)?;
        eprintln!(
            "wrote {}: {} x {}, {} points",
            out.display(),
            img.rows,
            img.cols,
            img.valid_count()
        );
    }
    Ok(())
}

#[derive(Args, Debug)]
pub struct EvalArgs {
    /// Evaluate on this many synthetic scenes (seeds 0..N) when no --input is given.
    #[arg(long, default_value_t = 20)]
    pub synthetic: u64,
    /// Rows of the synthetic scenes.
    #[arg(long, default_value_t = 64)]
    pub scene_rows: usize,
    /// Columns of the synthetic scenes.
    #[arg(long, default_value_t = 2048)]
    pub scene_cols: usize,
    /// Render the synthetic scenes without ground (as after a perfect ground removal).
    #[arg(long)]
    pub no_ground: bool,
    /// Inputs with ground truth instead of synthetic scenes (pair each with
    /// --truth, in order): point clouds (.bin, .pcd, .ply) with SemanticKITTI
    /// .label files, or .npy range images (R, C, 3) with .npy instance
    /// images (R, C).
    #[arg(long, num_args = 1..)]
    pub input: Vec<PathBuf>,
    /// Ground truth for --input: SemanticKITTI .label, or .npy label images.
    #[arg(long, num_args = 1..)]
    pub truth: Vec<PathBuf>,
    /// Score these label images instead of clustering: another clusterer's
    /// labels for the .npy range images of --input, one (R, C) .npy per
    /// input, in order (0 = unclustered), scored by the same rules, range
    /// bands and --min-points filter as FCC's.
    #[arg(long, num_args = 1.., requires = "input", conflicts_with_all = [
        "fsize", "merge", "th_h", "th_v", "label_bits", "th_h_slope", "th_v_slope",
        "preset", "ground", "rules",
    ])]
    pub predicted: Vec<PathBuf>,
    /// Scoring rules: `fcc` (class-agnostic, void-aware; see docs/lidar.md)
    /// or `semantickitti` (evaluate_panoptic.py's PanopticEval: 19 classes,
    /// stuff counted; needs point clouds with .label ground truth).
    #[arg(long, value_enum, default_value_t = Rules::Fcc)]
    pub rules: Rules,
    /// Semantic class of clustered points under `--rules semantickitti`
    /// (SemanticKITTI id, as `cluster --label-class`).
    #[arg(long, default_value_t = DEFAULT_LABEL_CLASS)]
    pub label_class: u16,
    #[command(flatten)]
    pub projection: ProjectionArgs,
    /// Filter sizes K to evaluate: `--fsize 3 5 7` or `--fsize 3,5,7`.
    #[arg(long, alias = "fsizes", num_args = 1.., value_delimiter = ',', allow_negative_numbers = true, default_values_t = [3, 5, 7, 9, 11])]
    pub fsize: Vec<usize>,
    /// Merge modes to evaluate: `--merge exact paper` or `--merge exact,paper`.
    #[arg(long, alias = "modes", num_args = 1.., value_delimiter = ',', default_values = ["exact", "paper"])]
    pub merge: Vec<MergeMode>,
    /// Intra-channel threshold th_H, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = fcc_params::FccParams::default().th_h)]
    pub th_h: f64,
    /// Inter-channel threshold th_V, metres.
    #[arg(long, allow_negative_numbers = true, default_value_t = fcc_params::FccParams::default().th_v)]
    pub th_v: f64,
    /// Provisional label width B.
    #[arg(long, default_value_t = fcc_params::FccParams::default().label_bits)]
    pub label_bits: u32,
    #[command(flatten)]
    pub slopes: crate::model_args::SlopeArgs,
    #[command(flatten)]
    pub ground: GroundArgs,
    /// Drop clusters of N points or fewer before scoring.
    #[arg(long, default_value_t = 0)]
    pub min_points: usize,
    /// Ignore ground-truth instances with fewer points (`fcc` rules, default
    /// 1); under `semantickitti`, unmatched segments with fewer points are
    /// neither FN nor FP (default 50, as evaluate_panoptic.py).
    #[arg(long)]
    pub min_instance_points: Option<usize>,
    /// Write the table as JSON here.
    #[arg(long)]
    pub json: Option<PathBuf>,
    /// Write the table as Markdown here.
    #[arg(long)]
    pub markdown: Option<PathBuf>,
    /// Frames evaluated in parallel (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

/// Scoring rules of `fcc eval`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Rules {
    Fcc,
    Semantickitti,
}

/// `fcc eval`: the quality table.
pub fn run_eval(args: &EvalArgs) -> anyhow::Result<()> {
    let inputs: Vec<&Path> = args
        .input
        .iter()
        .chain(&args.truth)
        .chain(&args.predicted)
        .map(PathBuf::as_path)
        .collect();
    let outputs: Vec<(&str, &Path)> = [("--json", &args.json), ("--markdown", &args.markdown)]
        .into_iter()
        .filter_map(|(f, p)| p.as_deref().map(|p| (f, p)))
        .collect();
    fcc_io::check_outputs(inputs, &outputs)?;
    // .npy range images are taken as prepared (no ground removal by
    // default), as in `fcc cluster`.
    let all_npy = !args.input.is_empty()
        && args
            .input
            .iter()
            .all(|i| InputKind::of(i, &SourceOptions::default()) == Some(InputKind::RangeImage));
    let base = eval_base(args, all_npy)?;
    base.params.validate()?;
    for &k in &args.fsize {
        fcc_params::FccParams {
            fsize: k,
            ..base.params.clone()
        }
        .validate()?;
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()?;
    if args.rules == Rules::Semantickitti {
        return run_eval_semantickitti(args, &pool);
    }
    let frames: Vec<EvalFrame> = if args.input.is_empty() {
        if args.synthetic == 0 {
            bail!("nothing to evaluate: give --synthetic N or --input with --truth");
        }
        eprintln!(
            "rendering {} synthetic scenes of {} x {}",
            args.synthetic, args.scene_rows, args.scene_cols
        );
        pool.install(|| {
            synthetic_frames(
                0..args.synthetic,
                args.scene_rows,
                args.scene_cols,
                !args.no_ground,
            )
        })?
    } else {
        if args.truth.len() != args.input.len() {
            bail!(
                "--truth names {} files for {} inputs: give one per input, in order",
                args.truth.len(),
                args.input.len()
            );
        }
        let sources = SourceOptions {
            projection: args.projection.config()?,
            range_images: true,
            ..SourceOptions::default()
        };
        let mut frames = Vec::new();
        for (i, t) in args.input.iter().zip(&args.truth) {
            for_each_input_frame(i, Some(t), &sources, |item| {
                frames.push(EvalFrame {
                    name: item.name,
                    image: item.image,
                    truth: item.truth.unwrap_or_default(),
                    ground: None,
                });
                Ok(())
            })?;
        }
        frames
    };
    let eval_cfg = EvalConfig {
        min_instance_points: args.min_instance_points.unwrap_or(1),
    };
    let table = if args.predicted.is_empty() {
        let pb = progress_bar(Some(frames.len() as u64), "frames");
        let table = pool.install(|| {
            evaluate(&frames, &base, &args.fsize, &args.merge, &eval_cfg, &|| {
                pb.inc(1)
            })
        })?;
        pb.finish_and_clear();
        table
    } else {
        let predicted = read_predicted(args, &frames)?;
        pool.install(|| evaluate_given(&frames, &predicted, &base, &eval_cfg))?
    };
    write_table(args, &table.to_markdown(), &table)
}

/// The label images of `fcc eval --predicted`, one per frame of the
/// .npy range images of --input.
fn read_predicted(args: &EvalArgs, frames: &[EvalFrame]) -> anyhow::Result<Vec<Vec<u32>>> {
    if args.predicted.len() != args.input.len() {
        bail!(
            "--predicted names {} files for {} inputs: give one per input, in order",
            args.predicted.len(),
            args.input.len()
        );
    }
    if let Some(i) = args
        .input
        .iter()
        .find(|i| InputKind::of(i, &SourceOptions::default()) != Some(InputKind::RangeImage))
    {
        bail!(
            "{}: --predicted scores labels of .npy range images (R, C, 3); this input is not one",
            i.display()
        );
    }
    frames
        .iter()
        .zip(&args.predicted)
        .map(|(f, p)| {
            let l =
                fcc_npy::read_labels(p).with_context(|| format!("{}: cannot read", p.display()))?;
            if (l.rows, l.cols) != (f.image.rows, f.image.cols) {
                bail!(
                    "{}: labels are {} x {} but {} is {} x {}",
                    p.display(),
                    l.rows,
                    l.cols,
                    f.name,
                    f.image.rows,
                    f.image.cols
                );
            }
            Ok(l.labels)
        })
        .collect()
}

/// Print `fcc eval`'s table and write it to --markdown and --json.
fn write_table(args: &EvalArgs, md: &str, table: &impl Serialize) -> anyhow::Result<()> {
    println!("{md}");
    if let Some(p) = &args.markdown {
        fcc_io::write_atomic(p, md.as_bytes())
            .with_context(|| format!("{}: cannot write", p.display()))?;
    }
    if let Some(p) = &args.json {
        fcc_io::write_atomic(p, serde_json::to_string_pretty(table)?.as_bytes())
            .with_context(|| format!("{}: cannot write", p.display()))?;
    }
    Ok(())
}

/// The pipeline settings of `fcc eval`.
fn eval_base(args: &EvalArgs, range_images: bool) -> anyhow::Result<PipelineConfig> {
    Ok(PipelineConfig {
        params: args.slopes.apply(fcc_params::FccParams {
            th_h: args.th_h,
            th_v: args.th_v,
            label_bits: args.label_bits,
            ..fcc_params::FccParams::default()
        }),
        mode: MergeMode::Exact,
        ground: args.ground.params(range_images)?,
        min_points: args.min_points,
    })
}

/// `fcc eval --rules semantickitti`: point clouds with their .label files,
/// scored as SemanticKITTI's evaluate_panoptic.py scores them.
fn run_eval_semantickitti(args: &EvalArgs, pool: &rayon::ThreadPool) -> anyhow::Result<()> {
    use fcc_lidar::semantickitti::{evaluate, ScanTruth, DEFAULT_MIN_POINTS};
    if args.input.is_empty() {
        bail!("--rules semantickitti needs point clouds with SemanticKITTI ground truth: give --input and --truth");
    }
    if args.truth.len() != args.input.len() {
        bail!(
            "--truth names {} files for {} inputs: give one per input, in order",
            args.truth.len(),
            args.input.len()
        );
    }
    let proj = args.projection.config()?;
    let scans = args
        .input
        .iter()
        .zip(&args.truth)
        .map(|(i, t)| -> anyhow::Result<ScanTruth> {
            if InputKind::of(i, &SourceOptions::default()) != Some(InputKind::Cloud) {
                bail!(
                    "{}: --rules semantickitti scores point clouds (.bin, .pcd, .ply) with .label ground truth",
                    i.display()
                );
            }
            let cloud = read_point_cloud(i)?;
            Ok(ScanTruth {
                name: stem(i),
                labels: read_label_file(t, Some(cloud.len()))?,
                projection: project(&cloud.points, &proj)?,
            })
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let base = eval_base(args, false)?;
    let pb = progress_bar(Some(scans.len() as u64), "scans");
    let table = pool.install(|| {
        evaluate(
            &scans,
            &base,
            &args.fsize,
            &args.merge,
            args.label_class,
            args.min_instance_points.unwrap_or(DEFAULT_MIN_POINTS),
            &|| pb.inc(1),
        )
    })?;
    pb.finish_and_clear();
    write_table(args, &table.to_markdown(), &table)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn caption_shows_quality_with_ground_truth_and_lost_points() {
        assert_eq!(quality_caption(None), "");
        let q = fcc_lidar::eval::Scores {
            pq: 0.6512,
            sq: 0.8,
            rq: 0.814,
            over_segmentation: 0.0,
            under_segmentation: 0.0,
            clusters_per_frame: 1.0,
            instances_per_frame: 1.0,
        };
        assert_eq!(
            quality_caption(Some(&q)),
            ", PQ 0.651 SQ 0.800 RQ 0.814 (PER PIXEL)"
        );
        // 300 isolated returns in one row with 8-bit labels: 45 unlabelled.
        let mut img = RangeImage::empty(16, 600);
        for c in (0..600).step_by(2) {
            let a = std::f32::consts::TAU * c as f32 / 600.0;
            img.set(c, Some([10.0 * a.cos(), 10.0 * a.sin(), 0.0]));
        }
        img.set(1, Some([200.0, 0.0, 0.0]));
        let cfg = PipelineConfig {
            params: fcc_params::FccParams {
                label_bits: 8,
                th_h: 0.05,
                ..fcc_params::FccParams::default()
            },
            ground: GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
            ..PipelineConfig::default()
        };
        let out = cluster_image(&img, &cfg).unwrap();
        assert_eq!(
            loss_caption(&out),
            ", LABEL OVERFLOW: 45 POINTS UNLABELLED, 1 POINTS OUT OF RANGE"
        );
    }
}
