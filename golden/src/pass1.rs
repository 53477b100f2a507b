//! Pass 1: intra-channel grouping with the ring check (spec §3, and §6 for
//! the released code's ring handling).

use crate::frame::{Frame, Point};
use crate::threshold::Thresholds;
use fcc_params::FccParams;

/// One labelled run: a label and the columns of its first and last valid
/// pixel. Every valid pixel of its row between the two belongs to it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Run {
    pub label: u32,
    pub first: u32,
    pub last: u32,
}

/// What pass 1 leaves for the later passes.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Pass1 {
    /// Provisional label of every pixel, raster order; 0 for an empty pixel
    /// or a pixel of a run that started after labels ran out.
    pub labels: Vec<u32>,
    /// Provisional labels allocated (and not given back by
    /// [`pass1_released`]): they are `1 ..= provisional`.
    pub provisional: u32,
    /// Ring-check joins, one per row at most: (first run's label, last run's
    /// label). Empty from [`pass1_released`], which relabels instead.
    pub ring_joins: Vec<(u32, u32)>,
    /// Some run started after the labels `1 ..= 2^B - 1` were exhausted.
    pub overflow: bool,
    /// Valid pixels left with label 0 because of overflow.
    pub unlabelled: usize,
    /// Valid pixels in the frame.
    pub points: usize,
    /// The labelled runs of every row, left to right, rows one after another.
    /// A run relabelled by [`pass1_released`] keeps its own entry, with the
    /// label of its row's first run.
    pub runs: Vec<Run>,
    /// `runs[row_runs[i] .. row_runs[i + 1]]` are the runs of row `i`.
    pub row_runs: Vec<usize>,
}

impl Pass1 {
    /// The labelled runs of row `i`, left to right.
    pub fn runs_of_row(&self, i: usize) -> &[Run] {
        &self.runs[self.row_runs[i]..self.row_runs[i + 1]]
    }
}

/// Label the runs of every row.
///
/// Each valid pixel is compared with the previous valid pixel of its row
/// (empty pixels are skipped; they break a run only beyond the bridge limit):
/// `d2 <= tH^2` continues the run, otherwise a new run starts with the next
/// provisional label. Labels are allocated in raster order over the whole
/// frame. When a row has at least two valid pixels, its first and last valid
/// pixels are within `tH` and within the ring reach, their runs are joined
/// (the ring closes at azimuth 0).
pub fn pass1(params: &FccParams, frame: &Frame) -> Pass1 {
    let mut out = Pass1::default();
    label_runs(params, frame, RingHandling::Join, &mut out);
    out
}

/// Pass 1 with the ring handling of the authors' released code (spec §6):
/// when the ring check passes and the row's last run is not its first run,
/// the last run's pixels take the first run's label and the last run's label
/// is given back, so the next run allocated reuses it. Nothing is left in
/// [`Pass1::ring_joins`].
pub fn pass1_released(params: &FccParams, frame: &Frame) -> Pass1 {
    let mut out = Pass1::default();
    label_runs(params, frame, RingHandling::Relabel, &mut out);
    out
}

#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum RingHandling {
    /// Record a join for the merge (spec §3).
    Join,
    /// Relabel the last run with the first run's label (spec §6).
    Relabel,
}

/// Pass 1 into the buffers of `out`, which keep their allocations.
pub(crate) fn label_runs(params: &FccParams, frame: &Frame, ring: RingHandling, out: &mut Pass1) {
    let th = Thresholds::new(params);
    let max_label = params.max_label();
    let cols = frame.cols;
    let Pass1 {
        labels,
        ring_joins,
        runs,
        row_runs,
        ..
    } = out;
    labels.clear();
    labels.resize(frame.points.len(), 0);
    ring_joins.clear();
    runs.clear();
    row_runs.clear();
    row_runs.push(0);
    let mut next: u32 = 1;
    let mut overflow = false;
    let mut unlabelled = 0usize;
    let mut points = 0usize;

    for (row_pts, row_labels) in frame
        .points
        .chunks_exact(cols)
        .zip(labels.chunks_exact_mut(cols))
    {
        let Some(f) = row_pts.iter().position(Option::is_some) else {
            row_runs.push(runs.len());
            continue;
        };
        let mut prev = row_pts[f].expect("f is valid");
        let first_point = prev;
        let mut new_label = |overflow: &mut bool| {
            if next <= max_label {
                next += 1;
                next - 1
            } else {
                *overflow = true;
                0
            }
        };
        // The open run: its label (0 when unlabelled) and columns.
        let mut current = new_label(&mut overflow);
        let (mut start, mut last) = (f, f);
        row_labels[f] = current;
        points += 1;
        let mut close = |current: u32, start: usize, last: usize, unlabelled: &mut usize| {
            if current != 0 {
                runs.push(Run {
                    label: current,
                    first: start as u32,
                    last: last as u32,
                });
            } else {
                *unlabelled += row_pts[start..=last].iter().flatten().count();
            }
        };
        for (c, p) in row_pts.iter().enumerate().skip(f + 1) {
            let Some(p) = *p else { continue };
            points += 1;
            if !params.bridges(c - last - 1) || !th.continues(p, prev) {
                close(current, start, last, &mut unlabelled);
                current = new_label(&mut overflow);
                start = c;
            }
            row_labels[c] = current;
            last = c;
            prev = p;
        }
        close(current, start, last, &mut unlabelled);
        let first_label = row_labels[f];
        // One valid pixel, or one run spanning the row: nothing to join.
        // (The released code also gives back the label of a row that is one
        // run; spec §6 says why this model does not.)
        if first_label != 0
            && current != 0
            && first_label != current
            && params.ring_reaches(f, last)
            && th.continues(first_point, prev)
        {
            match ring {
                RingHandling::Join => ring_joins.push((first_label, current)),
                RingHandling::Relabel => {
                    let last_run = runs.last_mut().expect("the last run is labelled");
                    for l in &mut row_labels[start..=last] {
                        if *l == current {
                            *l = first_label;
                        }
                    }
                    // The last run holds the latest label allocated.
                    next -= 1;
                    last_run.label = first_label;
                }
            }
        }
        row_runs.push(runs.len());
    }
    out.provisional = next - 1;
    out.overflow = overflow;
    out.unlabelled = unlabelled;
    out.points = points;
}

/// Provisional labels pass 1 would allocate with unlimited labels: the runs
/// of every row, as [`pass1`] splits them. More than
/// [`FccParams::max_label`] means label overflow.
pub fn runs_needed(params: &FccParams, frame: &Frame) -> u64 {
    let th = Thresholds::new(params);
    let mut runs = 0u64;
    for row in frame.points.chunks_exact(frame.cols) {
        let mut prev: Option<(usize, Point)> = None;
        for (c, p) in row.iter().enumerate() {
            let Some(p) = *p else { continue };
            let continues =
                prev.is_some_and(|(b, q)| params.bridges(c - b - 1) && th.continues(p, q));
            if !continues {
                runs += 1;
            }
            prev = Some((c, p));
        }
    }
    runs
}
