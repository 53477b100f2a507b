//! Clustering, ground removal, scoring and the synthetic scenes: the
//! parameters are built and validated as `fcc cluster` builds them, and the
//! work is done by `fcc_lidar::pipeline` and the golden model.

use crate::arrays::{array, floats, labels};
use crate::fast::Losses;
use crate::{lidar_err, value_err};
use fcc_golden::{MergeMode, OrientedBox, Record};
use fcc_lidar::clusters::frame_cluster_records;
use fcc_lidar::eval::{score_frame, score_frame_by_range, EvalConfig, RANGE_BANDS};
use fcc_lidar::ground::{detect_ground, GroundMethod, GroundParams};
use fcc_lidar::pipeline::{cluster_image, stream_image, PipelineConfig, PipelineResult};
use fcc_lidar::RangeImage;
use fcc_params::{FccParams, Preset};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::time::Instant;

/// The shape of a range image in messages.
pub const IMAGE_SHAPE: &str = "(R, C, 3)";

/// A range image from an (R, C, 3) float array.
pub fn image_of(xyz: &Bound<'_, PyAny>) -> PyResult<RangeImage> {
    let (v, shape) = floats(xyz, "xyz", &[None, None, Some(3)], IMAGE_SHAPE)?;
    RangeImage::from_xyz(shape[0], shape[1], v).map_err(lidar_err)
}

/// `name` parsed by its type's `FromStr` (the CLI's value names and messages).
pub fn parse<T: std::str::FromStr<Err = String>>(s: &str) -> PyResult<T> {
    s.parse::<T>().map_err(value_err)
}

/// The model parameters as `fcc cluster` makes them from its flags
/// (`ModelArgs::params`): the defaults of `FccParams`, the preset's
/// thresholds and slopes or the ones given (a preset with a threshold or a
/// slope is refused, as the CLI refuses the two flags together), then
/// `FccParams::validate`.
#[allow(clippy::too_many_arguments)]
pub fn model_params(
    fsize: Option<usize>,
    th_h: Option<f64>,
    th_v: Option<f64>,
    label_bits: Option<u32>,
    th_h_slope: Option<f64>,
    th_v_slope: Option<f64>,
    preset: Option<&str>,
    bridge: Option<u32>,
    ring_reach: Option<u32>,
) -> PyResult<FccParams> {
    let d = FccParams::default();
    let base = FccParams {
        fsize: fsize.unwrap_or(d.fsize),
        th_h: th_h.unwrap_or(d.th_h),
        th_v: th_v.unwrap_or(d.th_v),
        label_bits: label_bits.unwrap_or(d.label_bits),
        th_h_slope: th_h_slope.unwrap_or(d.th_h_slope),
        th_v_slope: th_v_slope.unwrap_or(d.th_v_slope),
        bridge,
        ring_reach,
        ..d.clone()
    };
    let p = match preset {
        Some(name) => {
            let given: Vec<&str> = [
                ("th_h", th_h),
                ("th_v", th_v),
                ("th_h_slope", th_h_slope),
                ("th_v_slope", th_v_slope),
            ]
            .iter()
            .filter(|(_, v)| v.is_some())
            .map(|(n, _)| *n)
            .collect();
            if !given.is_empty() {
                return Err(value_err(format!(
                    "preset `{name}` sets the thresholds and slopes: drop {}",
                    given.join(", ")
                )));
            }
            let (th_h, th_v, th_h_slope, th_v_slope) = parse::<Preset>(name)?.thresholds();
            FccParams {
                th_h,
                th_v,
                th_h_slope,
                th_v_slope,
                ..base
            }
        }
        None => base,
    };
    p.validate().map_err(value_err)?;
    Ok(p)
}

/// Ground removal settings as `fcc cluster --ground ... --ground-max-slope
/// ... --ground-distance ...` makes them.
pub fn ground_params(
    method: &str,
    max_slope: Option<f64>,
    distance: Option<f64>,
) -> PyResult<GroundParams> {
    let d = GroundParams::default();
    let p = GroundParams {
        method: parse::<GroundMethod>(method)?,
        max_slope_deg: max_slope.unwrap_or(d.max_slope_deg),
        plane_distance_m: distance.unwrap_or(d.plane_distance_m),
        ..d
    };
    p.validate().map_err(lidar_err)?;
    Ok(p)
}

/// Records with their oriented boxes as a dict of numpy arrays, one entry
/// per record field (`min`, `max`, `sum`, `centroid`, ... are (N, 3)).
pub fn records_dict<'py>(
    py: Python<'py>,
    recs: &[(Record, Option<OrientedBox>)],
) -> PyResult<Bound<'py, PyDict>> {
    let n = recs.len();
    let d = PyDict::new(py);
    macro_rules! column {
        ($name:expr, $f:expr) => {
            d.set_item($name, array(py, recs.iter().map($f).collect(), &[n])?)?
        };
    }
    macro_rules! columns {
        ($name:expr, $k:expr, $f:expr) => {
            d.set_item(
                $name,
                array(py, recs.iter().flat_map($f).collect(), &[n, $k])?,
            )?
        };
    }
    column!("frame", |(r, _)| r.frame);
    column!("id", |(r, _)| r.id);
    column!("points", |(r, _)| r.points);
    column!("first_col", |(r, _)| r.first_col);
    column!("last_col", |(r, _)| r.last_col);
    column!("closed_col", |(r, _)| r.closed_col);
    column!("seam", |(r, _)| r.seam);
    column!("first_row", |(r, _)| r.first_row);
    column!("last_row", |(r, _)| r.last_row);
    columns!("min", 3, |(r, _)| r.min);
    columns!("max", 3, |(r, _)| r.max);
    column!("range2_min", |(r, _)| r.range2_min);
    column!("range2_max", |(r, _)| r.range2_max);
    columns!("sum", 3, |(r, _)| r.sum);
    column!("sum_xx", |(r, _)| r.sum_xx);
    column!("sum_xy", |(r, _)| r.sum_xy);
    column!("sum_yy", |(r, _)| r.sum_yy);
    columns!("centroid", 3, |(r, _)| r.centroid());
    columns!("range", 2, |(r, _)| r.range());
    columns!("bounds_min", 3, |(r, _)| r.bounds()[0]);
    columns!("bounds_max", 3, |(r, _)| r.bounds()[1]);
    column!("heading", |(r, _)| r.heading());
    let nan2 = [f64::NAN; 2];
    columns!("box_center", 2, |(_, b)| b.map_or(nan2, |b| b.center));
    columns!("box_size", 2, |(_, b)| b.map_or(nan2, |b| b.size));
    column!("box_yaw", |(_, b)| b.map_or(f64::NAN, |b| b.yaw));
    columns!("box_z", 2, |(_, b)| b.map_or(nan2, |b| b.z));
    Ok(d)
}

/// The CLI's `--stats` figures of one run, as JSON.
fn stats_json(
    image: &RangeImage,
    out: &PipelineResult,
    streamed: bool,
    peak_labels: Option<u32>,
    time_ms: f64,
) -> String {
    let c = &out.clustering;
    let stats = serde_json::json!({
        "rows": image.rows,
        "cols": image.cols,
        "points": image.valid_count(),
        "ground_points": out.ground.count(),
        "clusters": out.clusters,
        "clusters_before_min_points": c.clusters,
        "fsize": out.params.fsize,
        "label_bits": out.params.label_bits,
        "max_label": out.params.max_label(),
        "provisional": c.provisional,
        "joins": (!streamed).then_some(c.joins),
        "merges": (!streamed).then_some(c.merges),
        "overflow": c.overflow,
        "unlabelled": c.unlabelled,
        "labels_needed": out.labels_needed,
        "label_bits_needed": FccParams::label_bits_for(out.labels_needed),
        "out_of_range": out.out_of_range,
        "peak_labels": peak_labels,
        "time_ms": time_ms,
    });
    stats.to_string()
}

/// What `Pipeline.run` returns: labels, statistics (JSON), records, ground mask.
type RunOutput<'py> = (
    Bound<'py, PyAny>,
    String,
    Option<Bound<'py, PyDict>>,
    Bound<'py, PyAny>,
);

/// Everything that shapes a clustering run, validated once.
#[pyclass(module = "fcc._fcc", frozen)]
pub struct Pipeline {
    cfg: PipelineConfig,
}

impl Pipeline {
    pub fn config(&self) -> &PipelineConfig {
        &self.cfg
    }
}

#[pymethods]
impl Pipeline {
    #[new]
    #[pyo3(signature = (*, fsize=None, th_h=None, th_v=None, merge="exact", label_bits=None,
        th_h_slope=None, th_v_slope=None, preset=None, bridge=None, ring_reach=None,
        ground="none", ground_max_slope=None, ground_distance=None, min_points=0))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        fsize: Option<usize>,
        th_h: Option<f64>,
        th_v: Option<f64>,
        merge: &str,
        label_bits: Option<u32>,
        th_h_slope: Option<f64>,
        th_v_slope: Option<f64>,
        preset: Option<&str>,
        bridge: Option<u32>,
        ring_reach: Option<u32>,
        ground: &str,
        ground_max_slope: Option<f64>,
        ground_distance: Option<f64>,
        min_points: usize,
    ) -> PyResult<Self> {
        let params = model_params(
            fsize, th_h, th_v, label_bits, th_h_slope, th_v_slope, preset, bridge, ring_reach,
        )?;
        Ok(Pipeline {
            cfg: PipelineConfig {
                params,
                mode: parse::<MergeMode>(merge)?,
                ground: ground_params(ground, ground_max_slope, ground_distance)?,
                min_points,
            },
        })
    }

    /// The parameters, as JSON (`FccParams` and the pipeline's settings).
    #[getter]
    fn params_json(&self) -> String {
        serde_json::json!({
            "params": self.cfg.params,
            "merge": self.cfg.mode,
            "ground": self.cfg.ground,
            "min_points": self.cfg.min_points,
        })
        .to_string()
    }

    /// The label image alone (R, C) uint32. Without ground removal the
    /// golden model reads the array in place (see `fast.rs`).
    fn labels<'py>(&self, py: Python<'py>, xyz: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        if self.cfg.ground.method == GroundMethod::None {
            let (labels, losses) = crate::fast::labels(py, xyz, &self.cfg)?;
            losses.warn(py, &self.cfg.params, 2)?;
            return Ok(labels);
        }
        let image = image_of(xyz)?;
        let out = py
            .allow_threads(|| cluster_image(&image, &self.cfg))
            .map_err(lidar_err)?;
        Losses::of(&out).warn(py, &out.params, 2)?;
        Ok(array(py, out.labels, &[image.rows, image.cols])?.into_any())
    }

    /// Labels (R, C), the statistics as JSON, the records (a dict of
    /// arrays, or None) and the ground mask (R, C) bool.
    /// Warnings point `stacklevel` Python frames up (2: the caller's caller).
    #[pyo3(signature = (xyz, records=false, stream=false, stacklevel=2))]
    fn run<'py>(
        &self,
        py: Python<'py>,
        xyz: &Bound<'py, PyAny>,
        records: bool,
        stream: bool,
        stacklevel: i32,
    ) -> PyResult<RunOutput<'py>> {
        if stream && self.cfg.mode != MergeMode::Exact {
            return Err(value_err(
                "stream=True clusters exactly (spec §9): drop merge=\"paper\"",
            ));
        }
        let image = image_of(xyz)?;
        let cfg = &self.cfg;
        type Recs = Vec<(Record, Option<OrientedBox>)>;
        let (out, recs, peak, time_ms) = py
            .allow_threads(
                || -> fcc_lidar::Result<(PipelineResult, Option<Recs>, Option<u32>, f64)> {
                    let t = Instant::now();
                    if stream {
                        let s = stream_image(&image, cfg, |_| {})?;
                        let ms = t.elapsed().as_secs_f64() * 1e3;
                        let recs = s
                            .records
                            .iter()
                            .map(|c| (c.record, c.oriented_box))
                            .collect();
                        Ok((s.result, Some(recs), Some(s.stats.peak_labels), ms))
                    } else {
                        let out = cluster_image(&image, cfg)?;
                        let ms = t.elapsed().as_secs_f64() * 1e3;
                        let recs = records.then(|| {
                            let kept = image.without(&out.ground.mask).to_frame();
                            frame_cluster_records(&out.params, &kept, &out.labels, out.clusters)
                        });
                        Ok((out, recs, None, ms))
                    }
                },
            )
            .map_err(lidar_err)?;
        Losses::of(&out).warn(py, &out.params, stacklevel)?;
        let stats = stats_json(&image, &out, stream, peak, time_ms);
        let recs = match recs.filter(|_| records) {
            Some(r) => Some(records_dict(py, &r)?),
            None => None,
        };
        let shape = [image.rows, image.cols];
        let ground = array(py, out.ground.mask, &shape)?.into_any();
        Ok((
            array(py, out.labels, &shape)?.into_any(),
            stats,
            recs,
            ground,
        ))
    }

    /// Rust-side times of the frame, milliseconds, each the median of
    /// `repeats` runs after one warm-up on this thread: `cluster_with` alone
    /// on the quantised frame (the thread's workspace reused), and
    /// `Frame::from_xyz_f32` (the quantisation `fcc cluster` does before it).
    #[pyo3(signature = (xyz, repeats=20))]
    fn time_core(
        &self,
        py: Python<'_>,
        xyz: &Bound<'_, PyAny>,
        repeats: usize,
    ) -> PyResult<(f64, f64)> {
        let image = image_of(xyz)?;
        let cfg = &self.cfg;
        py.allow_threads(|| -> fcc_lidar::Result<(f64, f64)> {
            let params = fcc_lidar::pipeline::params_for(&image, &cfg.params);
            params.validate()?;
            let ground = detect_ground(&image, &cfg.ground)?;
            let kept = image.without(&ground.mask);
            let median = |mut t: Vec<f64>| {
                t.sort_by(f64::total_cmp);
                t.get(t.len() / 2).copied().unwrap_or(f64::NAN)
            };
            let mut quantise = Vec::with_capacity(repeats);
            let mut frame = kept.to_frame();
            for k in 0..=repeats {
                let t = Instant::now();
                frame = fcc_golden::Frame::from_xyz_f32(kept.rows, kept.cols, &kept.xyz);
                if k > 0 {
                    quantise.push(t.elapsed().as_secs_f64() * 1e3);
                }
            }
            let mut ws = fcc_golden::Workspace::default();
            let mut core = Vec::with_capacity(repeats);
            for k in 0..=repeats {
                let t = Instant::now();
                let c = fcc_golden::cluster_with(&mut ws, &params, &frame, cfg.mode)?;
                let ms = t.elapsed().as_secs_f64() * 1e3;
                ws.recycle(c);
                if k > 0 {
                    core.push(ms);
                }
            }
            Ok((median(core), median(quantise)))
        })
        .map_err(lidar_err)
    }
}

/// The ground mask (R, C) bool of a range image.
#[pyfunction]
#[pyo3(signature = (xyz, method="slope", max_slope=None, distance=None))]
pub fn remove_ground<'py>(
    py: Python<'py>,
    xyz: &Bound<'py, PyAny>,
    method: &str,
    max_slope: Option<f64>,
    distance: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let params = ground_params(method, max_slope, distance)?;
    let image = image_of(xyz)?;
    let g = py
        .allow_threads(|| detect_ground(&image, &params))
        .map_err(lidar_err)?;
    Ok(array(py, g.mask, &[image.rows, image.cols])?.into_any())
}

/// Scores of `labels` against `truth` (same shape, uint32) under fcc's
/// rules, as JSON: the scores and counts, and with `xyz` the scores per
/// range band.
#[pyfunction]
#[pyo3(signature = (labels_, truth, xyz=None, min_instance_points=1))]
pub fn score(
    py: Python<'_>,
    labels_: &Bound<'_, PyAny>,
    truth: &Bound<'_, PyAny>,
    xyz: Option<&Bound<'_, PyAny>>,
    min_instance_points: usize,
) -> PyResult<String> {
    let (pred, shape) = labels(labels_, "labels", &[None, None], "(R, C)")?;
    let shape_text = format!("({}, {}) like labels", shape[0], shape[1]);
    let exact: Vec<Option<usize>> = shape.iter().map(|&n| Some(n)).collect();
    let (truth, _) = labels(truth, "truth", &exact, &shape_text)?;
    let range = match xyz {
        Some(x) => {
            let shape3 = format!("({}, {}, 3) like labels", shape[0], shape[1]);
            let (v, _) = floats(
                x,
                "xyz",
                &[Some(shape[0]), Some(shape[1]), Some(3)],
                &shape3,
            )?;
            let img = RangeImage::from_xyz(shape[0], shape[1], v).map_err(lidar_err)?;
            // Each pixel's distance from the sensor, as `fcc eval` bands it.
            Some(
                (0..img.pixels())
                    .map(|i| img.range(i).unwrap_or(f32::NAN))
                    .collect::<Vec<f32>>(),
            )
        }
        None => None,
    };
    let cfg = EvalConfig {
        min_instance_points,
    };
    py.allow_threads(|| -> fcc_lidar::Result<String> {
        let counts = score_frame(&pred, &truth, &cfg)?;
        let bands = match &range {
            Some(r) => {
                let per = score_frame_by_range(&pred, &truth, r, &RANGE_BANDS, &cfg)?;
                Some(
                    RANGE_BANDS
                        .iter()
                        .zip(per)
                        .map(|(&(lo, hi), c)| {
                            serde_json::json!({"lo": lo, "hi": hi, "scores": c.scores(), "counts": c})
                        })
                        .collect::<Vec<_>>(),
                )
            }
            None => None,
        };
        Ok(serde_json::json!({
            "scores": counts.scores(),
            "counts": counts,
            "bands": bands,
        })
        .to_string())
    })
    .map_err(lidar_err)
}

/// A synthetic street scene of the corpus (`fcc scene`): the (R, C, 3)
/// float32 range image and the (R, C) uint32 ground-truth instances.
#[pyfunction]
#[pyo3(signature = (seed=0, rows=None, cols=None, keep_ground=false, dropout=None, missing=None, range_noise=None))]
#[allow(clippy::too_many_arguments)]
pub fn scene<'py>(
    py: Python<'py>,
    seed: u64,
    rows: Option<usize>,
    cols: Option<usize>,
    keep_ground: bool,
    dropout: Option<f64>,
    missing: Option<f64>,
    range_noise: Option<f64>,
) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyAny>)> {
    let d = fcc_scene::SceneConfig::default();
    let cfg = fcc_scene::SceneConfig {
        rows: rows.unwrap_or(d.rows),
        cols: cols.unwrap_or(d.cols),
        seed,
        keep_ground,
        dropout: dropout.unwrap_or(d.dropout),
        missing: missing.unwrap_or(d.missing),
        range_noise_m: range_noise.unwrap_or(d.range_noise_m),
    };
    let s = py
        .allow_threads(|| fcc_scene::generate(&cfg))
        .map_err(value_err)?;
    let (r, c) = (s.rows, s.cols);
    Ok((
        array(py, s.xyz, &[r, c, 3])?.into_any(),
        array(py, s.gt, &[r, c])?.into_any(),
    ))
}
