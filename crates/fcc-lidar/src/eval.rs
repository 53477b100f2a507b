//! Quality of a clustering against ground-truth instances.
//!
//! Ground truth is an instance id per pixel (or point); 0 means "no
//! instance" (ground, stuff, unlabelled) and is treated as void. Metrics:
//!
//! - **Panoptic quality** for instances, class-agnostic: a cluster `p` and
//!   an instance `g` match when `IoU(p, g) > 0.5`, with
//!   `IoU = |p ∩ g| / (|p| + |g| - |p ∩ g| - |p ∩ void|)` (a cluster's void
//!   pixels do not count against it). Matches are unique at that threshold.
//!   TP = matches, FN = unmatched instances, FP = unmatched clusters whose
//!   pixels are not mostly (> 50 %) void. `SQ` = mean IoU of the matches,
//!   `RQ = TP / (TP + FP/2 + FN/2)`, `PQ = SQ · RQ`.
//! - **Over-segmentation error** (point-weighted): the share of instance
//!   points outside the cluster that holds most of their instance
//!   (points left in no cluster count as outside).
//! - **Under-segmentation error** (point-weighted): the share of clustered,
//!   non-void points outside the instance that holds most of their cluster.
//! - **Clusters** and **instances** per frame.
//!
//! Over a set of frames the counts are summed before the ratios are taken
//! (dataset-level PQ, as in the panoptic benchmarks).

use crate::error::{LidarError, Result};
use crate::ground::{detect_ground, score_ground, GroundMethod, GroundScore};
use crate::image::RangeImage;
use crate::labels::filter_min_points;
use crate::pipeline::{params_for, PipelineConfig};
use fcc_golden::{cluster, MergeMode};
use rayon::prelude::*;
use std::collections::HashMap;

/// Settings of the quality measures.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EvalConfig {
    /// Instances with fewer points are ignored (their points become void).
    pub min_instance_points: usize,
}

impl Default for EvalConfig {
    fn default() -> Self {
        EvalConfig {
            min_instance_points: 1,
        }
    }
}

/// Summable counts of one or more frames.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct Counts {
    pub true_positives: usize,
    pub false_positives: usize,
    pub false_negatives: usize,
    /// Sum of the IoU of the matches.
    pub iou_sum: f64,
    /// Instance points outside their instance's main cluster.
    pub over_points: usize,
    /// Points of counted instances.
    pub instance_points: usize,
    /// Clustered non-void points outside their cluster's main instance.
    pub under_points: usize,
    /// Clustered non-void points.
    pub clustered_points: usize,
    pub clusters: usize,
    pub instances: usize,
    pub frames: usize,
}

impl Counts {
    pub fn add(&mut self, o: &Counts) {
        self.true_positives += o.true_positives;
        self.false_positives += o.false_positives;
        self.false_negatives += o.false_negatives;
        self.iou_sum += o.iou_sum;
        self.over_points += o.over_points;
        self.instance_points += o.instance_points;
        self.under_points += o.under_points;
        self.clustered_points += o.clustered_points;
        self.clusters += o.clusters;
        self.instances += o.instances;
        self.frames += o.frames;
    }

    /// The ratios of these counts.
    pub fn scores(&self) -> Scores {
        let tp = self.true_positives as f64;
        let sq = if self.true_positives == 0 {
            0.0
        } else {
            self.iou_sum / tp
        };
        let denom = tp + 0.5 * (self.false_positives + self.false_negatives) as f64;
        // Nothing to find and nothing found is a perfect score.
        let rq = if denom == 0.0 { 1.0 } else { tp / denom };
        let sq = if denom == 0.0 { 1.0 } else { sq };
        let ratio = |a: usize, b: usize| if b == 0 { 0.0 } else { a as f64 / b as f64 };
        let per_frame = |v: usize| {
            if self.frames == 0 {
                0.0
            } else {
                v as f64 / self.frames as f64
            }
        };
        Scores {
            pq: sq * rq,
            sq,
            rq,
            over_segmentation: ratio(self.over_points, self.instance_points),
            under_segmentation: ratio(self.under_points, self.clustered_points),
            clusters_per_frame: per_frame(self.clusters),
            instances_per_frame: per_frame(self.instances),
        }
    }
}

/// Quality ratios.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Scores {
    pub pq: f64,
    pub sq: f64,
    pub rq: f64,
    pub over_segmentation: f64,
    pub under_segmentation: f64,
    pub clusters_per_frame: f64,
    pub instances_per_frame: f64,
}

/// Compare one clustering with its ground truth (same length, 0 = none).
pub fn score_frame(pred: &[u32], truth: &[u32], cfg: &EvalConfig) -> Result<Counts> {
    if pred.len() != truth.len() {
        return Err(LidarError::Mismatch {
            what: "cluster labels for the ground truth".into(),
            expected: truth.len(),
            got: pred.len(),
        });
    }
    let mut gsize: HashMap<u32, usize> = HashMap::new();
    for &g in truth.iter().filter(|&&g| g != 0) {
        *gsize.entry(g).or_insert(0) += 1;
    }
    gsize.retain(|_, n| *n >= cfg.min_instance_points);
    let gt = |g: u32| {
        if g != 0 && gsize.contains_key(&g) {
            g
        } else {
            0
        }
    };
    let mut psize: HashMap<u32, usize> = HashMap::new();
    let mut pvoid: HashMap<u32, usize> = HashMap::new();
    let mut inter: HashMap<(u32, u32), usize> = HashMap::new();
    for (&p, &g) in pred.iter().zip(truth) {
        let g = gt(g);
        if p != 0 {
            *psize.entry(p).or_insert(0) += 1;
            if g == 0 {
                *pvoid.entry(p).or_insert(0) += 1;
            }
        }
        if p != 0 && g != 0 {
            *inter.entry((p, g)).or_insert(0) += 1;
        }
    }
    let mut c = Counts {
        clusters: psize.len(),
        instances: gsize.len(),
        frames: 1,
        ..Counts::default()
    };
    let mut matched_p: HashMap<u32, bool> = HashMap::new();
    let mut matched_g: HashMap<u32, bool> = HashMap::new();
    let mut best_of_g: HashMap<u32, usize> = HashMap::new();
    let mut best_of_p: HashMap<u32, usize> = HashMap::new();
    for (&(p, g), &n) in &inter {
        let union = psize[&p] + gsize[&g] - n - pvoid.get(&p).copied().unwrap_or(0);
        let iou = n as f64 / union as f64;
        if iou > 0.5 {
            c.true_positives += 1;
            c.iou_sum += iou;
            matched_p.insert(p, true);
            matched_g.insert(g, true);
        }
        let e = best_of_g.entry(g).or_insert(0);
        *e = (*e).max(n);
        let e = best_of_p.entry(p).or_insert(0);
        *e = (*e).max(n);
    }
    for (&p, &n) in &psize {
        let void = pvoid.get(&p).copied().unwrap_or(0);
        if !matched_p.contains_key(&p) && 2 * void <= n {
            c.false_positives += 1;
        }
        let solid = n - void;
        c.clustered_points += solid;
        c.under_points += solid - best_of_p.get(&p).copied().unwrap_or(0);
    }
    for (&g, &n) in &gsize {
        if !matched_g.contains_key(&g) {
            c.false_negatives += 1;
        }
        c.instance_points += n;
        c.over_points += n - best_of_g.get(&g).copied().unwrap_or(0);
    }
    Ok(c)
}

/// The range bands of `fcc eval`'s banded scores, metres: [lo, hi).
pub const RANGE_BANDS: [(f64, f64); 3] = [(0.0, 20.0), (20.0, 40.0), (40.0, 80.0)];

/// [`score_frame`] per range band: an instance belongs to the band of the
/// mean range of its pixels, a cluster likewise; each band is scored over
/// the instances and clusters of that band only (the others become void
/// and unclustered). `range` is each pixel's distance from the sensor
/// (NaN for empty pixels, which belong to no object).
pub fn score_frame_by_range(
    pred: &[u32],
    truth: &[u32],
    range: &[f32],
    bands: &[(f64, f64)],
    cfg: &EvalConfig,
) -> Result<Vec<Counts>> {
    if range.len() != truth.len() {
        return Err(LidarError::Mismatch {
            what: "pixel ranges for the ground truth".into(),
            expected: truth.len(),
            got: range.len(),
        });
    }
    let mean_range = |labels: &[u32]| {
        let mut sum: HashMap<u32, (f64, usize)> = HashMap::new();
        for (&l, &r) in labels.iter().zip(range) {
            if l != 0 && r.is_finite() {
                let e = sum.entry(l).or_insert((0.0, 0));
                e.0 += f64::from(r);
                e.1 += 1;
            }
        }
        sum.into_iter()
            .map(|(l, (s, n))| (l, s / n as f64))
            .collect::<HashMap<u32, f64>>()
    };
    let (pr, gr) = (mean_range(pred), mean_range(truth));
    let keep = |labels: &[u32], r: &HashMap<u32, f64>, (lo, hi): (f64, f64)| -> Vec<u32> {
        labels
            .iter()
            .map(|&l| match r.get(&l) {
                Some(&m) if m >= lo && m < hi => l,
                _ => 0,
            })
            .collect()
    };
    bands
        .iter()
        .map(|&band| score_frame(&keep(pred, &pr, band), &keep(truth, &gr, band), cfg))
        .collect()
}

/// One frame with ground truth.
#[derive(Debug, Clone)]
pub struct EvalFrame {
    pub name: String,
    pub image: RangeImage,
    /// Instance id per pixel, 0 = none.
    pub truth: Vec<u32>,
    /// True ground per pixel, when known (scores the ground removal).
    pub ground: Option<Vec<bool>>,
}

/// One line of the quality table.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EvalRow {
    /// The filter size and merge mode of FCC's row; `None` for a row of
    /// given labels ([`evaluate_given`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fsize: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode: Option<MergeMode>,
    #[serde(flatten)]
    pub scores: Scores,
    pub counts: Counts,
    /// The scores per range band ([`RANGE_BANDS`]).
    pub bands: Vec<BandScores>,
}

/// The scores of one range band, metres `[lo, hi)`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BandScores {
    pub lo: f64,
    pub hi: f64,
    #[serde(flatten)]
    pub scores: Scores,
    pub counts: Counts,
}

/// Quality per filter size and merge mode over a set of frames.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EvalTable {
    pub frames: usize,
    pub th_h: f64,
    pub th_v: f64,
    /// Range-adaptive slopes (spec §2), metres per metre.
    pub th_h_slope: f64,
    pub th_v_slope: f64,
    pub min_points: usize,
    pub ground_method: GroundMethod,
    /// Ground removal against the true ground, when every frame has it.
    pub ground: Option<GroundScore>,
    /// The rows score given labels ([`evaluate_given`]): the thresholds
    /// in the header are not what made them.
    pub given: bool,
    pub rows: Vec<EvalRow>,
}

/// The synthetic corpus: scenes of seeds `seeds`, with the ground left in
/// when `keep_ground`.
pub fn synthetic_frames(
    seeds: std::ops::Range<u64>,
    rows: usize,
    cols: usize,
    keep_ground: bool,
) -> Result<Vec<EvalFrame>> {
    seeds
        .into_par_iter()
        .map(|seed| {
            let cfg = fcc_scene::SceneConfig {
                seed,
                rows,
                cols,
                keep_ground,
                ..fcc_scene::SceneConfig::default()
            };
            let scene = fcc_scene::generate(&cfg).map_err(|e| LidarError::Config(e.to_string()))?;
            Ok(EvalFrame {
                name: format!("synthetic seed {seed}"),
                image: RangeImage::from_xyz(scene.rows, scene.cols, scene.xyz)?,
                truth: scene.gt,
                ground: keep_ground.then_some(scene.ground),
            })
        })
        .collect()
}

/// Run every (filter size, merge mode) over every frame: ground removal
/// once per frame, then clustering, the min-points filter and the scores.
/// Frames run in parallel on rayon's pool; `progress` is called once per
/// frame finished.
pub fn evaluate(
    frames: &[EvalFrame],
    base: &PipelineConfig,
    fsizes: &[usize],
    modes: &[MergeMode],
    cfg: &EvalConfig,
    progress: &(dyn Fn() + Sync),
) -> Result<EvalTable> {
    if fsizes.is_empty() || modes.is_empty() {
        return Err(LidarError::Config(
            "evaluation needs at least one filter size and one merge mode".into(),
        ));
    }
    check_truth(frames)?;
    type PerFrame = (Vec<FrameCounts>, Option<GroundScore>);
    let per_frame: Vec<PerFrame> = frames
        .par_iter()
        .map(|f| -> Result<PerFrame> {
            let ground = detect_ground(&f.image, &base.ground)?;
            let gscore = match &f.ground {
                Some(t) => Some(score_ground(&f.image, &ground.mask, t)?),
                None => None,
            };
            let frame = f.image.without(&ground.mask).to_frame();
            let range = pixel_ranges(&f.image);
            let mut out = Vec::with_capacity(fsizes.len() * modes.len());
            for &k in fsizes {
                for &mode in modes {
                    let params = params_for(
                        &f.image,
                        &fcc_params::FccParams {
                            fsize: k,
                            ..base.params.clone()
                        },
                    );
                    let c = cluster(&params, &frame, mode)?;
                    out.push(score_labels(c.labels, f, &range, base.min_points, cfg)?);
                }
            }
            progress();
            Ok((out, gscore))
        })
        .collect::<Result<_>>()?;
    let mut rows = Vec::new();
    for (ki, &k) in fsizes.iter().enumerate() {
        for (mi, &mode) in modes.iter().enumerate() {
            let i = ki * modes.len() + mi;
            rows.push(sum_row(
                Some(k),
                Some(mode),
                per_frame.iter().map(|(c, _)| &c[i]),
            ));
        }
    }
    let ground = if !frames.is_empty() && per_frame.iter().all(|(_, g)| g.is_some()) {
        let (mut tp, mut fp, mut fn_) = (0, 0, 0);
        for g in per_frame.iter().filter_map(|(_, g)| g.as_ref()) {
            tp += g.true_positives;
            fp += g.false_positives;
            fn_ += g.false_negatives;
        }
        Some(GroundScore::from_counts(tp, fp, fn_))
    } else {
        None
    };
    Ok(EvalTable::new(frames.len(), base, ground, false, rows))
}

/// Scores of one frame: the whole frame and per range band.
type FrameCounts = (Counts, Vec<Counts>);

/// Every frame's ground truth must cover its image.
fn check_truth(frames: &[EvalFrame]) -> Result<()> {
    for f in frames {
        if f.truth.len() != f.image.pixels() {
            return Err(LidarError::Mismatch {
                what: format!("ground-truth labels of {}", f.name),
                expected: f.image.pixels(),
                got: f.truth.len(),
            });
        }
    }
    Ok(())
}

/// Each pixel's distance from the sensor, NaN where empty.
fn pixel_ranges(image: &RangeImage) -> Vec<f32> {
    (0..image.pixels())
        .map(|i| {
            image.point(i).map_or(f32::NAN, |p| {
                (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
            })
        })
        .collect()
}

/// One frame's labels scored, after the min-points filter.
fn score_labels(
    labels: Vec<u32>,
    f: &EvalFrame,
    range: &[f32],
    min_points: usize,
    cfg: &EvalConfig,
) -> Result<FrameCounts> {
    let labels = if min_points > 0 {
        filter_min_points(&labels, min_points).0
    } else {
        labels
    };
    Ok((
        score_frame(&labels, &f.truth, cfg)?,
        score_frame_by_range(&labels, &f.truth, range, &RANGE_BANDS, cfg)?,
    ))
}

/// A table row: the counts of every frame summed, then the ratios.
fn sum_row<'a>(
    fsize: Option<usize>,
    mode: Option<MergeMode>,
    frames: impl Iterator<Item = &'a FrameCounts>,
) -> EvalRow {
    let mut counts = Counts::default();
    let mut bands = vec![Counts::default(); RANGE_BANDS.len()];
    for (all, by_band) in frames {
        counts.add(all);
        for (b, x) in bands.iter_mut().zip(by_band) {
            b.add(x);
        }
    }
    EvalRow {
        fsize,
        mode,
        scores: counts.scores(),
        counts,
        bands: RANGE_BANDS
            .iter()
            .zip(bands)
            .map(|(&(lo, hi), counts)| BandScores {
                lo,
                hi,
                scores: counts.scores(),
                counts,
            })
            .collect(),
    }
}

/// Score labels made elsewhere (another clusterer's, one per frame, in
/// order) with the same rules, bands and min-points filter: a table of one
/// row without a filter size or merge mode. Nothing is clustered and no
/// ground is removed; `base` gives the min-points filter and the table's
/// header.
pub fn evaluate_given(
    frames: &[EvalFrame],
    predicted: &[Vec<u32>],
    base: &PipelineConfig,
    cfg: &EvalConfig,
) -> Result<EvalTable> {
    check_truth(frames)?;
    if predicted.len() != frames.len() {
        return Err(LidarError::Mismatch {
            what: "label images for the frames".into(),
            expected: frames.len(),
            got: predicted.len(),
        });
    }
    for (f, p) in frames.iter().zip(predicted) {
        if p.len() != f.image.pixels() {
            return Err(LidarError::Mismatch {
                what: format!("given labels of {}", f.name),
                expected: f.image.pixels(),
                got: p.len(),
            });
        }
    }
    let per_frame: Vec<FrameCounts> = frames
        .par_iter()
        .zip(predicted)
        .map(|(f, p)| score_labels(p.clone(), f, &pixel_ranges(&f.image), base.min_points, cfg))
        .collect::<Result<_>>()?;
    let rows = vec![sum_row(None, None, per_frame.iter())];
    Ok(EvalTable::new(frames.len(), base, None, true, rows))
}

impl EvalTable {
    /// The table of `frames` frames under `base`'s settings.
    fn new(
        frames: usize,
        base: &PipelineConfig,
        ground: Option<GroundScore>,
        given: bool,
        rows: Vec<EvalRow>,
    ) -> EvalTable {
        EvalTable {
            frames,
            th_h: base.params.th_h,
            th_v: base.params.th_v,
            th_h_slope: base.params.th_h_slope,
            th_v_slope: base.params.th_v_slope,
            min_points: base.min_points,
            ground_method: base.ground.method,
            ground,
            given,
            rows,
        }
    }

    /// The table in Markdown.
    pub fn to_markdown(&self) -> String {
        let k = |r: &EvalRow| r.fsize.map_or("–".to_string(), |k| k.to_string());
        let mode = |r: &EvalRow| match r.mode {
            Some(MergeMode::Exact) => "exact",
            Some(MergeMode::Paper) => "paper",
            None => "given labels",
        };
        let mut s = if self.given {
            format!(
                "{} frames, given labels, min points {}",
                self.frames, self.min_points
            )
        } else {
            format!(
                "{} frames, th_H = {} m, th_V = {} m, min points {}, ground removal `{}`",
                self.frames, self.th_h, self.th_v, self.min_points, self.ground_method
            )
        };
        if !self.given && (self.th_h_slope != 0.0 || self.th_v_slope != 0.0) {
            s.push_str(&format!(
                ", slopes {} / {} m per m",
                self.th_h_slope, self.th_v_slope
            ));
        }
        if let Some(g) = &self.ground {
            s.push_str(&format!(
                " (ground precision {:.4}, recall {:.4})",
                g.precision, g.recall
            ));
        }
        s.push_str("\n\n| K | merge | PQ | SQ | RQ | TP | FP | FN | over-seg | under-seg | clusters/frame | instances/frame |\n");
        s.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        for r in &self.rows {
            let (sc, c) = (&r.scores, &r.counts);
            s.push_str(&format!(
                "| {} | {} | {:.3} | {:.3} | {:.3} | {} | {} | {} | {:.4} | {:.4} | {:.1} | {:.1} |\n",
                k(r),
                mode(r),
                sc.pq,
                sc.sq,
                sc.rq,
                c.true_positives,
                c.false_positives,
                c.false_negatives,
                sc.over_segmentation,
                sc.under_segmentation,
                sc.clusters_per_frame,
                sc.instances_per_frame
            ));
        }
        s.push_str("\nPQ by range band (instances and clusters by their mean range; instances per band in brackets):\n\n| K | merge |");
        for (lo, hi) in RANGE_BANDS {
            s.push_str(&format!(" {lo}-{hi} m |"));
        }
        s.push_str(&format!(
            "\n|---|---|{}\n",
            "---|".repeat(RANGE_BANDS.len())
        ));
        for r in &self.rows {
            s.push_str(&format!("| {} | {} |", k(r), mode(r)));
            for b in &r.bands {
                s.push_str(&format!(" {:.3} ({}) |", b.scores.pq, b.counts.instances));
            }
            s.push('\n');
        }
        s
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn banded_scores_put_each_object_in_the_band_of_its_mean_range() {
        // Pixels 0-3 near (10 m): instance 1 found as cluster 7; pixels 4-7
        // far (50 m): instance 2 split into clusters 8 and 9.
        let range = [10.0, 10.0, 11.0, 11.0, 50.0, 50.0, 51.0, 51.0];
        let truth = [1, 1, 1, 1, 2, 2, 2, 2];
        let pred = [7, 7, 7, 7, 8, 8, 9, 9];
        let c = score_frame_by_range(&pred, &truth, &range, &RANGE_BANDS, &EvalConfig::default())
            .unwrap();
        assert_eq!(c.len(), 3);
        assert_eq!(
            (
                c[0].true_positives,
                c[0].false_positives,
                c[0].false_negatives
            ),
            (1, 0, 0)
        );
        assert_eq!(c[1].instances + c[1].clusters, 0);
        assert_eq!((c[2].true_positives, c[2].false_negatives), (0, 1));
        assert_eq!(c[2].clusters, 2);
        assert!(score_frame_by_range(
            &pred,
            &truth,
            &range[..3],
            &RANGE_BANDS,
            &EvalConfig::default()
        )
        .is_err());
    }

    use super::*;

    #[test]
    fn perfect_clustering_scores_one() {
        let truth = [0, 1, 1, 1, 2, 2, 0];
        let pred = [0, 5, 5, 5, 9, 9, 0];
        let s = score_frame(&pred, &truth, &EvalConfig::default())
            .unwrap()
            .scores();
        assert_eq!((s.pq, s.sq, s.rq), (1.0, 1.0, 1.0));
        assert_eq!((s.over_segmentation, s.under_segmentation), (0.0, 0.0));
    }

    #[test]
    fn hand_worked_split_merge_and_void() {
        // Instance 1: 4 points split 3 + 1. Instances 2 and 3 (2 points each)
        // merged into cluster 7. Cluster 8 lies on void only (ignored);
        // cluster 9 is half void, half instance 4 (4 points, 1 in cluster 9).
        let truth = [1, 1, 1, 1, 2, 2, 3, 3, 0, 0, 0, 4, 4, 4, 4];
        let pred = [5, 5, 5, 6, 7, 7, 7, 7, 8, 8, 9, 9, 0, 0, 0];
        let c = score_frame(&pred, &truth, &EvalConfig::default()).unwrap();
        // Matches: (5, 1) IoU 3/4. (7, 2) IoU 2/4 = 0.5 is not > 0.5.
        assert_eq!((c.true_positives, c.iou_sum), (1, 0.75));
        // Unmatched clusters not mostly void: 6, 7, and 9 (1 of 2 void: not > 50 %).
        assert_eq!(c.false_positives, 3);
        assert_eq!(c.false_negatives, 3);
        // Over: instance 1 loses 1, 2 and 3 lose 0, 4 loses 3 of 4.
        assert_eq!((c.over_points, c.instance_points), (4, 12));
        // Under: cluster 7 holds 4 solid points, 2 outside its main instance.
        assert_eq!((c.under_points, c.clustered_points), (2, 4 + 3 + 1 + 1));
        let s = c.scores();
        assert!((s.rq - 1.0 / (1.0 + 3.0)).abs() < 1e-12);
        assert!((s.pq - 0.75 * 0.25).abs() < 1e-12);
        assert_eq!((c.clusters, c.instances), (5, 4));
    }

    #[test]
    fn small_instances_can_be_ignored_and_lengths_checked() {
        let truth = [1, 2, 2, 2];
        let pred = [0, 3, 3, 3];
        let c = score_frame(
            &pred,
            &truth,
            &EvalConfig {
                min_instance_points: 2,
            },
        )
        .unwrap();
        assert_eq!(
            (c.true_positives, c.false_negatives, c.instances),
            (1, 0, 1)
        );
        assert!(score_frame(&pred[..2], &truth, &EvalConfig::default()).is_err());
        let empty = Counts::default().scores();
        assert_eq!(empty.pq, 1.0);
    }
}
