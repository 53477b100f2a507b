//! Pass 2: inter-channel grouping through the K x K connection filter (spec §4).

use crate::frame::Frame;
use crate::pass1::Pass1;
use crate::threshold::Thresholds;
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
    pass2_with(&mut Pass2Buffers::default(), params, frame, p1, sink)
}

/// The buffers of [`pass2_with`], kept from one frame to the next.
#[derive(Debug, Clone, Default)]
pub(crate) struct Pass2Buffers {
    packed: Vec<[i32; 4]>,
    counted_by: Vec<u32>,
    first_run_pairs: Vec<u32>,
}

/// As [`pass2`], reusing the buffers of `buf` (no allocation once they have
/// grown to the frame size).
pub(crate) fn pass2_with<S: JoinSink>(
    buf: &mut Pass2Buffers,
    params: &FccParams,
    frame: &Frame,
    p1: &Pass1,
    sink: &mut S,
) -> u64 {
    let th = Thresholds::new(params);
    let h = params.half();
    let cols = frame.cols;
    // x, y, z and label side by side; label 0 marks a pixel that never joins.
    let packed = &mut buf.packed;
    packed.clear();
    packed.extend(frame.points.iter().zip(&p1.labels).map(|(p, &l)| match p {
        Some(p) if l != 0 => [i32::from(p[0]), i32::from(p[1]), i32::from(p[2]), l as i32],
        _ => [0; 4],
    }));
    let mut joins = 0u64;
    // The centre label that last counted a pair with each window label. A
    // label's centres are consecutive, except the run the released ring
    // handling relabels with the row's first label (spec §6): the window
    // labels counted with the first run are kept for it.
    let counted_by = &mut buf.counted_by;
    counted_by.clear();
    counted_by.resize(p1.provisional as usize + 1, 0);
    let first_run_pairs = &mut buf.first_run_pairs;
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
                    let point = |v: &[i32; 4]| [v[0] as i16, v[1] as i16, v[2] as i16];
                    if th.joins(point(&pc), point(q)) {
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
