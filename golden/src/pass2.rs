//! Pass 2: inter-channel grouping through the K x K connection filter (spec §4).

use crate::frame::{dist2, Frame, Point};
use crate::merge::ExactMerge;
use crate::pass1::Pass1;
use fcc_params::FccParams;

/// Receives the events of pass 2 in scan order. The exact merge only needs
/// [`join`](Self::join); the published merge table also needs to know when
/// the centre's run changes and when a row ends.
pub trait JoinSink {
    /// A valid, labelled centre with provisional label `label` is about to be
    /// filtered. Called for every such centre, in raster order.
    fn centre(&mut self, label: u32);
    /// The centre (label `centre`) is within `tV` of a valid, labelled pixel
    /// above it with label `other`.
    fn join(&mut self, centre: u32, other: u32);
    /// The last column of a row has been filtered.
    fn row_end(&mut self);
}

/// Run the connection filter over every valid centre.
///
/// For centre (i, j) the window holds the pixels (i - m, j + n) with
/// `1 <= m <= h` and `|n| <= h`, h = (K - 1) / 2, that lie inside the image:
/// only rows above, no wrap at the left and right edges. A window pixel
/// joins the centre when both are labelled and `d2 < tV^2` (strict).
/// Window pixels are visited row by row, left to right; a join that repeats
/// the previous join of the same centre is not reported again.
/// Returns the number of distinct label pairs joined: pairs (centre label,
/// window label) with at least one pixel pair that passed the threshold.
pub fn pass2<S: JoinSink>(params: &FccParams, frame: &Frame, p1: &Pass1, sink: &mut S) -> u64 {
    let th_sq = params.th_v_sq();
    let h = params.half();
    let cols = frame.cols;
    // x, y, z and label side by side; label 0 marks a pixel that never joins.
    let packed: Vec<[i32; 4]> = frame
        .points
        .iter()
        .zip(&p1.labels)
        .map(|(p, &l)| match p {
            Some(p) if l != 0 => [i32::from(p[0]), i32::from(p[1]), i32::from(p[2]), l as i32],
            _ => [0; 4],
        })
        .collect();
    let mut joins = 0u64;
    // The centre label that last counted a pair with each window label. A
    // label's centres are consecutive, except the run the released ring
    // handling relabels with the row's first label (spec §6): the window
    // labels counted with the first run are kept for it.
    let mut counted_by = vec![0u32; p1.provisional as usize + 1];
    let mut first_run_pairs: Vec<u32> = Vec::new();
    for i in 0..frame.rows {
        let row = i * cols;
        let (mut first_label, mut past_first_run) = (0u32, false);
        first_run_pairs.clear();
        for j in 0..cols {
            let pc = packed[row + j];
            if pc[3] == 0 {
                continue;
            }
            let lc = pc[3] as u32;
            if first_label == 0 {
                first_label = lc;
            } else if lc != first_label {
                past_first_run = true;
            }
            let seam_run = past_first_run && lc == first_label;
            sink.centre(lc);
            let lo = j.saturating_sub(h);
            let hi = (j + h).min(cols - 1);
            let mut last = 0u32;
            for m in 1..=h.min(i) {
                let up = (i - m) * cols;
                for q in &packed[up + lo..=up + hi] {
                    if q[3] == 0 {
                        continue;
                    }
                    let (dx, dy, dz) = (
                        i64::from(pc[0] - q[0]),
                        i64::from(pc[1] - q[1]),
                        i64::from(pc[2] - q[2]),
                    );
                    if dx * dx + dy * dy + dz * dz < th_sq {
                        let ln = q[3] as u32;
                        if ln != last {
                            last = ln;
                            sink.join(lc, ln);
                            if counted_by[ln as usize] != lc
                                && !(seam_run && first_run_pairs.contains(&ln))
                            {
                                counted_by[ln as usize] = lc;
                                joins += 1;
                                if lc == first_label && !past_first_run {
                                    first_run_pairs.push(ln);
                                }
                            }
                        }
                    }
                }
            }
        }
        sink.row_end();
    }
    joins
}

/// Pass 2 for exact merging, run against run (spec §4 and §5).
///
/// The components only depend on which pairs of runs have at least one
/// joining pixel pair, so each pair of runs whose columns come within `h`
/// of each other, at most `h` rows apart, is visited once, and its pixel
/// pairs are only compared until the first join (most pixel pairs are
/// between runs already joined, so this skips most distances). Unites the
/// same components as [`pass2`] with an [`ExactMerge`] and returns the same
/// count: the pairs of runs (labels) with at least one joining pixel pair.
pub fn pass2_runs(params: &FccParams, frame: &Frame, p1: &Pass1, merge: &mut ExactMerge) -> u64 {
    pass2_runs_with(params, frame, p1, merge, &mut Vec::new())
}

/// [`pass2_runs`] with its scratch space from the caller.
pub(crate) fn pass2_runs_with(
    params: &FccParams,
    frame: &Frame,
    p1: &Pass1,
    merge: &mut ExactMerge,
    from: &mut Vec<usize>,
) -> u64 {
    let th_sq = params.th_v_sq();
    let h = params.half();
    let cols = frame.cols;
    let pts = &frame.points;
    let mut joins = 0u64;
    // For the row m = 1 ..= h above the centre row, `from[m - 1]` is the
    // first run that may still reach a centre run (runs of a row are sorted
    // by column, and so are the centre runs).
    from.clear();
    from.resize(h, 0);
    for i in 1..frame.rows {
        let hm = h.min(i);
        for (m, f) in (1..=hm).zip(from.iter_mut()) {
            *f = p1.row_runs[i - m];
        }
        let centre_row = &pts[i * cols..(i + 1) * cols];
        for run in p1.runs_of_row(i) {
            let (a, b) = (run.first as usize, run.last as usize);
            let lo = a.saturating_sub(h);
            let hi = b + h;
            let mut root = merge.find(run.label);
            for (m, start) in (1..=hm).zip(from.iter_mut()) {
                let u = i - m;
                let end = p1.row_runs[u + 1];
                let mut k = *start;
                while k < end && (p1.runs[k].last as usize) < lo {
                    k += 1;
                }
                *start = k;
                let above_row = &pts[u * cols..(u + 1) * cols];
                for other in &p1.runs[k..end] {
                    if other.first as usize > hi {
                        break;
                    }
                    let (c, d) = (other.first as usize, other.last as usize);
                    if runs_touch(centre_row, (a, b), above_row, (c, d), h, th_sq) {
                        joins += 1;
                        let r = merge.find(other.label);
                        if r != root {
                            merge.link_roots(root, r);
                            root = root.min(r);
                        }
                    }
                }
            }
        }
    }
    joins
}

/// Whether some valid pixel of `centre[a..=b]` and some valid pixel of
/// `above[c..=d]` at most `h` columns apart are closer than `tV`.
#[inline]
fn runs_touch(
    centre: &[Option<Point>],
    (a, b): (usize, usize),
    above: &[Option<Point>],
    (c, d): (usize, usize),
    h: usize,
    th_sq: i64,
) -> bool {
    // Only centre columns within h of the other run can join.
    let first = a.max(c.saturating_sub(h));
    let last = b.min(d + h);
    for (j, p) in centre.iter().enumerate().take(last + 1).skip(first) {
        let Some(p) = *p else { continue };
        let lo = c.max(j.saturating_sub(h));
        let hi = d.min(j + h);
        for q in above[lo..=hi].iter().flatten() {
            if dist2(p, *q) < th_sq {
                return true;
            }
        }
    }
    false
}
