//! SemanticKITTI's own panoptic rules (`evaluate_panoptic.py` of the
//! semantic-kitti-api, its `PanopticEval`), for numbers that equal what
//! that script prints on fcc's `.label` predictions.
//!
//! Per point, the raw labels (class in the lower 16 bits, instance in the
//! upper) are mapped to the 19 training classes by the dataset's
//! `learning_map`; points whose true class maps to 0 ("unlabeled") are
//! dropped, for prediction and truth alike. For each of the 19 classes, a
//! segment is the set of points of that class with the same raw label (so
//! each stuff class is one segment). A predicted and a true segment match
//! when their IoU exceeds 0.5 (`IoU = |p ∩ g| / (|p| + |g| - |p ∩ g|)`, no
//! void discount); unmatched true segments of at least `min_points` points
//! are FN, unmatched predicted segments of at least `min_points` points are
//! FP. Per class, `SQ = IoU sum / TP`, `RQ = TP / (TP + FP/2 + FN/2)` (0
//! when a class never occurs), `PQ = SQ · RQ`; the reported PQ, SQ, RQ are
//! the means over the 19 classes, and PQ things / stuff the means over
//! classes 1..=8 and 9..=19. Counts are summed over the scans before the
//! ratios are taken.
//!
//! fcc's rules (the default, [`crate::eval`]) differ: class-agnostic (every
//! cluster may match any thing instance), stuff and ground are void, a
//! cluster's void points do not count against its IoU, a mostly void
//! cluster is no false positive, and `--min-instance-points` drops small
//! true instances before matching instead of only from the FN count.

use crate::error::{LidarError, Result};
use crate::ground::detect_ground;
use crate::image::RangeImage;
use crate::labels::{filter_min_points, semantic_labels};
use crate::pipeline::{params_for, PipelineConfig};
use crate::projection::{BackProjection, Projection};
use fcc_golden::{cluster, MergeMode};
use rayon::prelude::*;
use std::collections::HashMap;

/// Training classes, "unlabeled" (0) included.
pub const CLASSES: usize = 20;
/// Classes 1..=8 are things (car, bicycle, motorcycle, truck,
/// other-vehicle, person, bicyclist, motorcyclist), 9..=19 stuff.
pub const LAST_THING: usize = 8;
/// `evaluate_panoptic.py`'s default `--min_inst_points`.
pub const DEFAULT_MIN_POINTS: usize = 50;

/// Names of the training classes, 0..=19.
pub const CLASS_NAMES: [&str; CLASSES] = [
    "unlabeled",
    "car",
    "bicycle",
    "motorcycle",
    "truck",
    "other-vehicle",
    "person",
    "bicyclist",
    "motorcyclist",
    "road",
    "parking",
    "sidewalk",
    "other-ground",
    "building",
    "fence",
    "vegetation",
    "trunk",
    "terrain",
    "pole",
    "traffic-sign",
];

/// The dataset's `learning_map`: raw SemanticKITTI class to training
/// class (0 for classes it does not list).
pub fn learning_map(raw: u16) -> usize {
    match raw {
        10 | 252 => 1,
        11 => 2,
        15 => 3,
        18 | 258 => 4,
        13 | 16 | 20 | 256 | 257 | 259 => 5,
        30 | 254 => 6,
        31 | 253 => 7,
        32 | 255 => 8,
        40 | 60 => 9,
        44 => 10,
        48 => 11,
        49 => 12,
        50 => 13,
        51 => 14,
        70 => 15,
        71 => 16,
        72 => 17,
        80 => 18,
        81 => 19,
        _ => 0,
    }
}

/// Per-class counts, summable over scans.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PanopticCounts {
    pub tp: [usize; CLASSES],
    pub fp: [usize; CLASSES],
    #[serde(rename = "fn")]
    pub fn_: [usize; CLASSES],
    pub iou_sum: [f64; CLASSES],
    pub scans: usize,
}

impl Default for PanopticCounts {
    fn default() -> Self {
        PanopticCounts {
            tp: [0; CLASSES],
            fp: [0; CLASSES],
            fn_: [0; CLASSES],
            iou_sum: [0.0; CLASSES],
            scans: 0,
        }
    }
}

/// The means `evaluate_panoptic.py` prints.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PanopticScores {
    pub pq: f64,
    pub sq: f64,
    pub rq: f64,
    pub pq_things: f64,
    pub pq_stuff: f64,
}

impl PanopticCounts {
    pub fn add(&mut self, o: &PanopticCounts) {
        for c in 0..CLASSES {
            self.tp[c] += o.tp[c];
            self.fp[c] += o.fp[c];
            self.fn_[c] += o.fn_[c];
            self.iou_sum[c] += o.iou_sum[c];
        }
        self.scans += o.scans;
    }

    /// (PQ, SQ, RQ) of one class.
    pub fn class_scores(&self, c: usize) -> (f64, f64, f64) {
        let eps = 1e-15;
        let tp = self.tp[c] as f64;
        let sq = self.iou_sum[c] / tp.max(eps);
        let rq = tp / (tp + 0.5 * (self.fp[c] + self.fn_[c]) as f64).max(eps);
        (sq * rq, sq, rq)
    }

    /// The class means.
    pub fn scores(&self) -> PanopticScores {
        let mean = |range: std::ops::RangeInclusive<usize>, k: usize| {
            let n = range.clone().count() as f64;
            range
                .map(|c| {
                    let s = self.class_scores(c);
                    [s.0, s.1, s.2][k]
                })
                .sum::<f64>()
                / n
        };
        PanopticScores {
            pq: mean(1..=CLASSES - 1, 0),
            sq: mean(1..=CLASSES - 1, 1),
            rq: mean(1..=CLASSES - 1, 2),
            pq_things: mean(1..=LAST_THING, 0),
            pq_stuff: mean(LAST_THING + 1..=CLASSES - 1, 0),
        }
    }
}

/// Score one scan: predicted and true raw labels, one per point.
pub fn score_scan(pred: &[u32], truth: &[u32], min_points: usize) -> Result<PanopticCounts> {
    if pred.len() != truth.len() {
        return Err(LidarError::Mismatch {
            what: "predicted labels for the SemanticKITTI ground truth".into(),
            expected: truth.len(),
            got: pred.len(),
        });
    }
    // Segment sizes per (class, raw label), and intersections.
    let mut psize: HashMap<(usize, u32), usize> = HashMap::new();
    let mut gsize: HashMap<(usize, u32), usize> = HashMap::new();
    let mut inter: HashMap<(usize, u32, u32), usize> = HashMap::new();
    for (&p, &g) in pred.iter().zip(truth) {
        let gc = learning_map((g & 0xffff) as u16);
        if gc == 0 {
            continue;
        }
        let pc = learning_map((p & 0xffff) as u16);
        *gsize.entry((gc, g)).or_insert(0) += 1;
        if pc != 0 {
            *psize.entry((pc, p)).or_insert(0) += 1;
        }
        if pc == gc {
            *inter.entry((gc, p, g)).or_insert(0) += 1;
        }
    }
    let mut c = PanopticCounts {
        scans: 1,
        ..PanopticCounts::default()
    };
    let mut matched_p: std::collections::HashSet<(usize, u32)> = Default::default();
    let mut matched_g: std::collections::HashSet<(usize, u32)> = Default::default();
    for (&(cl, p, g), &n) in &inter {
        let union = psize[&(cl, p)] + gsize[&(cl, g)] - n;
        let iou = n as f64 / union as f64;
        if iou > 0.5 {
            c.tp[cl] += 1;
            c.iou_sum[cl] += iou;
            matched_p.insert((cl, p));
            matched_g.insert((cl, g));
        }
    }
    for (k, &n) in &gsize {
        if n >= min_points && !matched_g.contains(k) {
            c.fn_[k.0] += 1;
        }
    }
    for (k, &n) in &psize {
        if n >= min_points && !matched_p.contains(k) {
            c.fp[k.0] += 1;
        }
    }
    Ok(c)
}

/// One scan with its SemanticKITTI labels.
#[derive(Debug, Clone)]
pub struct ScanTruth {
    pub name: String,
    /// The scan's range image and how its points map to pixels.
    pub projection: Projection,
    /// Raw SemanticKITTI label per point.
    pub labels: Vec<u32>,
}

/// One line of the table.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PanopticRow {
    pub fsize: usize,
    pub mode: MergeMode,
    #[serde(flatten)]
    pub scores: PanopticScores,
    pub counts: PanopticCounts,
}

/// SemanticKITTI panoptic quality per filter size and merge mode.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PanopticTable {
    pub scans: usize,
    pub th_h: f64,
    pub th_v: f64,
    pub min_points: usize,
    /// `evaluate_panoptic.py`'s `--min_inst_points`.
    pub min_instance_points: usize,
    /// Raw class written for clustered points.
    pub label_class: u16,
    pub rows: Vec<PanopticRow>,
}

/// Cluster every scan at every (filter size, merge mode), write each point
/// the `.label` fcc would write (clusters as `label_class`, ground as
/// other-ground, the rest unlabeled) and score it with the official rules.
#[allow(clippy::too_many_arguments)]
pub fn evaluate(
    scans: &[ScanTruth],
    base: &PipelineConfig,
    fsizes: &[usize],
    modes: &[MergeMode],
    label_class: u16,
    min_instance_points: usize,
    progress: &(dyn Fn() + Sync),
) -> Result<PanopticTable> {
    if fsizes.is_empty() || modes.is_empty() {
        return Err(LidarError::Config(
            "evaluation needs at least one filter size and one merge mode".into(),
        ));
    }
    let per_scan: Vec<Vec<PanopticCounts>> = scans
        .par_iter()
        .map(|s| -> Result<Vec<PanopticCounts>> {
            let image: &RangeImage = &s.projection.image;
            let ground = detect_ground(image, &base.ground)?;
            let g: Vec<u32> = ground.mask.iter().map(|&m| u32::from(m)).collect();
            let ground_points: Vec<bool> = s
                .projection
                .labels_to_points(&g, BackProjection::default())?
                .iter()
                .map(|&v| v == 1)
                .collect();
            let frame = image.without(&ground.mask).to_frame();
            let mut out = Vec::with_capacity(fsizes.len() * modes.len());
            for &k in fsizes {
                for &mode in modes {
                    let params = params_for(
                        image,
                        &fcc_params::FccParams {
                            fsize: k,
                            ..base.params.clone()
                        },
                    );
                    let c = cluster(&params, &frame, mode)?;
                    let labels = if base.min_points > 0 {
                        filter_min_points(&c.labels, base.min_points).0
                    } else {
                        c.labels
                    };
                    let inst = s
                        .projection
                        .labels_to_points(&labels, BackProjection::default())?;
                    let pred = semantic_labels(&inst, Some(&ground_points), label_class)?;
                    out.push(score_scan(&pred, &s.labels, min_instance_points)?);
                }
            }
            progress();
            Ok(out)
        })
        .collect::<Result<_>>()?;
    let mut rows = Vec::new();
    for (ki, &k) in fsizes.iter().enumerate() {
        for (mi, &mode) in modes.iter().enumerate() {
            let mut counts = PanopticCounts::default();
            for c in &per_scan {
                counts.add(&c[ki * modes.len() + mi]);
            }
            rows.push(PanopticRow {
                fsize: k,
                mode,
                scores: counts.scores(),
                counts,
            });
        }
    }
    Ok(PanopticTable {
        scans: scans.len(),
        th_h: base.params.th_h,
        th_v: base.params.th_v,
        min_points: base.min_points,
        min_instance_points,
        label_class,
        rows,
    })
}

impl PanopticTable {
    /// The table in Markdown: the class means and the counts of the class
    /// fcc's clusters are written as.
    pub fn to_markdown(&self) -> String {
        let cl = learning_map(self.label_class);
        let name = CLASS_NAMES[cl];
        let mut s = format!(
            "{} scans, SemanticKITTI rules (evaluate_panoptic.py, min_inst_points {}), th_H = {} m, th_V = {} m, min points {}, clusters written as class {} ({name})\n\n",
            self.scans, self.min_instance_points, self.th_h, self.th_v, self.min_points, self.label_class
        );
        s.push_str(&format!(
            "| K | merge | PQ | SQ | RQ | PQ things | PQ stuff | {name} PQ | {name} TP | {name} FP | {name} FN |\n"
        ));
        s.push_str("|---|---|---|---|---|---|---|---|---|---|---|\n");
        for r in &self.rows {
            let (sc, c) = (&r.scores, &r.counts);
            s.push_str(&format!(
                "| {} | {} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {:.4} | {} | {} | {} |\n",
                r.fsize,
                match r.mode {
                    MergeMode::Exact => "exact",
                    MergeMode::Paper => "paper",
                },
                sc.pq,
                sc.sq,
                sc.rq,
                sc.pq_things,
                sc.pq_stuff,
                c.class_scores(cl).0,
                c.tp[cl],
                c.fp[cl],
                c.fn_[cl]
            ));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::labels::pack_label;

    #[test]
    fn learning_map_folds_moving_and_rare_classes() {
        assert_eq!(learning_map(252), learning_map(10));
        assert_eq!(learning_map(60), learning_map(40));
        assert_eq!(learning_map(52), 0);
        assert_eq!(learning_map(99), 0);
        assert_eq!(learning_map(1), 0);
        assert_eq!(CLASS_NAMES[learning_map(49)], "other-ground");
    }

    /// The worked example that ships with `PanopticEval` (after Kirillov et
    /// al.), with its classes put on SemanticKITTI ids: grass = road (40),
    /// sky = building (50), person (30), dog = car (10). Its printed
    /// per-class numbers carry over; the means differ only by the 15
    /// classes that never occur here.
    #[test]
    fn panoptic_eval_worked_example() {
        let (road, building, person, car) = (40, 50, 30, 10);
        let mut pred = Vec::new();
        let mut truth = Vec::new();
        let mut push = |n: usize, p: u32, g: u32| {
            pred.extend(std::iter::repeat_n(p, n));
            truth.extend(std::iter::repeat_n(g, n));
        };
        push(50, 0, 0);
        push(40, pack_label(road, 0), pack_label(road, 0));
        push(10, pack_label(building, 0), pack_label(road, 0));
        push(40, pack_label(building, 0), pack_label(building, 0));
        push(10, pack_label(road, 0), pack_label(building, 0));
        push(50, pack_label(person, 35), pack_label(car, 22));
        push(150, pack_label(person, 8), pack_label(person, 33));
        push(50, pack_label(person, 8), pack_label(person, 42));
        push(100, pack_label(person, 95), pack_label(person, 11));
        let c = score_scan(&pred, &truth, 1).unwrap();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        let (pq, sq, rq) = c.class_scores(learning_map(road));
        assert!(close(pq, 2.0 / 3.0) && close(sq, 2.0 / 3.0) && close(rq, 1.0));
        let (pq, sq, rq) = c.class_scores(learning_map(person));
        assert!(close(pq, 0.5833333333333333) && close(sq, 0.875) && close(rq, 2.0 / 3.0));
        assert_eq!(c.class_scores(learning_map(car)), (0.0, 0.0, 0.0));
        // The example's PQ 0.479166 is the mean over its 4 classes.
        let s = c.scores();
        assert!(close(s.pq * 19.0 / 4.0, 0.47916666666666663), "{}", s.pq);
        assert!(close(s.sq * 19.0 / 4.0, 0.5520833333333333));
        assert!(close(s.rq * 19.0 / 4.0, 0.6666666666666666));
    }

    #[test]
    fn min_points_applies_to_fn_and_fp_but_not_tp() {
        let car = |i| pack_label(10, i);
        // A 3-point true car found exactly, a 2-point true car missed, a
        // 2-point false car.
        let truth = [
            car(1),
            car(1),
            car(1),
            car(2),
            car(2),
            pack_label(40, 0),
            pack_label(40, 0),
        ];
        let pred = [car(7), car(7), car(7), 0, 0, car(9), car(9)];
        let c = score_scan(&pred, &truth, 3).unwrap();
        assert_eq!((c.tp[1], c.fn_[1], c.fp[1]), (1, 0, 0));
        let c = score_scan(&pred, &truth, 2).unwrap();
        assert_eq!((c.tp[1], c.fn_[1], c.fp[1]), (1, 1, 1));
        // The road is a stuff segment never predicted: FN of class road.
        assert_eq!(c.fn_[9], 1);
        assert!(score_scan(&pred[..3], &truth, 1).is_err());
    }
}
