//! Pass 1: intra-channel grouping with the ring check (spec §3).

use crate::frame::{dist2, Frame};
use fcc_params::FccParams;

/// What pass 1 leaves for the later passes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Pass1 {
    /// Provisional label of every pixel, raster order; 0 for an empty pixel
    /// or a pixel of a run that started after labels ran out.
    pub labels: Vec<u32>,
    /// Provisional labels allocated: they are `1 ..= provisional`.
    pub provisional: u32,
    /// Ring-check joins, one per row at most: (first run's label, last run's label).
    pub ring_joins: Vec<(u32, u32)>,
    /// Some run started after the labels `1 ..= 2^B - 1` were exhausted.
    pub overflow: bool,
    /// Valid pixels left with label 0 because of overflow.
    pub unlabelled: usize,
}

/// Label the runs of every row.
///
/// Each valid pixel is compared with the previous valid pixel of its row
/// (empty pixels are skipped, they do not break a run): `d2 <= tH^2`
/// continues the run, otherwise a new run starts with the next provisional
/// label. Labels are allocated in raster order over the whole frame. When a
/// row has at least two valid pixels and its first and last valid pixels are
/// within `tH`, their runs are joined (the ring closes at azimuth 0).
pub fn pass1(params: &FccParams, frame: &Frame) -> Pass1 {
    let th_sq = params.th_h_sq();
    let max_label = params.max_label();
    let mut labels = vec![0u32; frame.points.len()];
    let mut next: u32 = 1;
    let mut overflow = false;
    let mut unlabelled = 0usize;
    let mut ring_joins = Vec::new();

    for (row_pts, row_labels) in frame
        .points
        .chunks_exact(frame.cols)
        .zip(labels.chunks_exact_mut(frame.cols))
    {
        let mut prev = None;
        let mut first = None;
        let mut current = 0u32;
        for (p, l) in row_pts.iter().zip(row_labels.iter_mut()) {
            let Some(p) = *p else { continue };
            let continues = prev.is_some_and(|q| dist2(p, q) <= th_sq);
            if !continues {
                if next <= max_label {
                    current = next;
                    next += 1;
                } else {
                    current = 0;
                    overflow = true;
                }
            }
            if current == 0 {
                unlabelled += 1;
            }
            *l = current;
            if first.is_none() {
                first = Some((p, current));
            }
            prev = Some(p);
        }
        if let (Some((fp, fl)), Some(lp)) = (first, prev) {
            let last_label = current;
            // One valid pixel, or one run spanning the row: nothing to join.
            if fl != 0 && last_label != 0 && fl != last_label && dist2(fp, lp) <= th_sq {
                ring_joins.push((fl, last_label));
            }
        }
    }
    Pass1 {
        labels,
        provisional: next - 1,
        ring_joins,
        overflow,
        unlabelled,
    }
}

/// Provisional labels pass 1 would allocate with unlimited labels: the runs
/// of every row, as [`pass1`] splits them. More than
/// [`FccParams::max_label`] means label overflow.
pub fn runs_needed(params: &FccParams, frame: &Frame) -> u64 {
    let th_sq = params.th_h_sq();
    let mut runs = 0u64;
    for row in frame.points.chunks_exact(frame.cols) {
        let mut prev = None;
        for p in row.iter().flatten() {
            let continues = prev.is_some_and(|q| dist2(*p, q) <= th_sq);
            if !continues {
                runs += 1;
            }
            prev = Some(*p);
        }
    }
    runs
}
