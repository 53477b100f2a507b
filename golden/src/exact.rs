//! The `exact` path of [`cluster`](crate::cluster): pass 1, the ring check,
//! pass 2 run against run, the exact merge and the final numbering (spec §3,
//! §4, §5 and §7), with compact buffers kept from one frame to the next.
//!
//! Pass 1 copies the labelled points of each run, with their columns, into
//! one compact array (runs in raster order, so run `r` holds provisional label
//! `r + 1`) and records each run's bounding box. Pass 2 only looks at pairs of
//! runs at most `h` rows and `h` columns apart; a pair whose boxes are `tV`
//! or more apart cannot join (every pixel pair is at least that far apart)
//! and is skipped without a distance; the others are compared pixel pair by
//! pixel pair, over the compact points only, until the first join.

use crate::frame::{Frame, Point};
use crate::merge::ExactMerge;
use crate::threshold::Thresholds;
use fcc_params::FccParams;

/// A valid point and its column: x, y, z and the column's bits as `i16`
/// (columns are below 2^16), so a run's bounding box is a lane-wise min and
/// max over four lanes.
type Px = [i16; 4];

/// The column of a compact point.
#[inline]
fn col(q: &Px) -> usize {
    usize::from(q[3] as u16)
}

/// The coordinates of a compact point.
#[inline]
fn point(q: &Px) -> Point {
    [q[0], q[1], q[2]]
}

/// A labelled run: its first and last column, its points
/// `px[start..end]` and their bounding box.
#[derive(Debug, Clone, Copy)]
struct RunBox {
    first: u32,
    last: u32,
    start: u32,
    end: u32,
    /// x, y, z lower and upper bounds, and a fourth lane of 0 in both (four
    /// lanes, so the gap between two boxes is computed lane-wise).
    lo: [i32; 4],
    hi: [i32; 4],
    /// The largest inter-channel threshold of its points (`tV^2` with fixed
    /// thresholds): no pair with a point of this run joins beyond it.
    tv_max: i64,
}

/// Buffers of the exact path.
#[derive(Debug, Clone, Default)]
pub(crate) struct Exact {
    px: Vec<Px>,
    /// Where the runs of one row start, as indices into its points.
    starts: Vec<u32>,
    runs: Vec<RunBox>,
    /// `runs[row_runs[i] .. row_runs[i + 1]]` are the runs of row `i`.
    row_runs: Vec<u32>,
    ring_joins: Vec<(u32, u32)>,
    pub(crate) merge: ExactMerge,
    /// Per row above the centre: the first run that may still reach a centre
    /// run of the current row.
    from: Vec<usize>,
    /// Final number of each component root.
    id: Vec<u32>,
}

/// What the exact path reports besides the labels.
pub(crate) struct ExactStats {
    pub points: usize,
    pub provisional: u32,
    pub overflow: bool,
    pub unlabelled: usize,
    pub joins: u64,
    pub merges: u64,
    pub clusters: u32,
}

impl Exact {
    /// Cluster `frame` into `labels` (resized to the frame).
    pub(crate) fn run(
        &mut self,
        params: &FccParams,
        frame: &Frame,
        labels: &mut Vec<u32>,
    ) -> ExactStats {
        let (points, overflow, unlabelled) = self.pass1(params, frame);
        let provisional = self.runs.len() as u32;
        self.merge.reset(provisional);
        for &(a, b) in &self.ring_joins {
            self.merge.union(a, b);
        }
        let joins = self.pass2(params, frame.rows);
        let merges = self.merge.merges;
        let clusters = self.number(frame, labels);
        ExactStats {
            points,
            provisional,
            overflow,
            unlabelled,
            joins,
            merges,
            clusters,
        }
    }

    /// Pass 1 and the ring check (spec §3, §7). Returns (points, overflow,
    /// unlabelled).
    #[inline(never)]
    fn pass1(&mut self, params: &FccParams, frame: &Frame) -> (usize, bool, usize) {
        let th = Thresholds::new(params);
        let max_runs = params.max_label() as usize;
        let Exact {
            px,
            starts,
            runs,
            row_runs,
            ring_joins,
            ..
        } = self;
        px.clear();
        px.reserve(frame.points.len());
        runs.clear();
        row_runs.clear();
        row_runs.push(0);
        ring_joins.clear();
        let (mut overflow, mut unlabelled) = (false, 0usize);
        for row in frame.points.chunks_exact(frame.cols) {
            // Copy the row's valid points (those of unlabelled runs too, but
            // no run refers to them)
            // and where runs start: at every step wider than tH (the first
            // point starts a run whatever its distance to `prev`).
            let base = px.len();
            starts.clear();
            let mut prev = [i16::MIN; 3];
            // One past the previous valid pixel's column.
            let mut after_prev = 0usize;
            for (c, q) in row.iter().enumerate() {
                if let Some(p) = *q {
                    if !params.bridges(c - after_prev) || !th.continues(p, prev) {
                        starts.push((px.len() - base) as u32);
                    }
                    px.push([p[0], p[1], p[2], c as u16 as i16]);
                    prev = p;
                    after_prev = c + 1;
                }
            }
            let row_px = &px[base..];
            let first_run = runs.len();
            let (Some(first_px), Some(last_px)) = (row_px.first(), row_px.last()) else {
                row_runs.push(runs.len() as u32);
                continue;
            };
            let mut close = |start: usize, end: usize| {
                if runs.len() < max_runs {
                    let (mut lo, mut hi) = ([i16::MAX; 4], [i16::MIN; 4]);
                    for q in &row_px[start..end] {
                        for d in 0..4 {
                            lo[d] = lo[d].min(q[d]);
                            hi[d] = hi[d].max(q[d]);
                        }
                    }
                    runs.push(RunBox {
                        first: col(&row_px[start]) as u32,
                        last: col(&row_px[end - 1]) as u32,
                        start: (base + start) as u32,
                        end: (base + end) as u32,
                        lo: [lo[0], lo[1], lo[2], 0].map(i32::from),
                        hi: [hi[0], hi[1], hi[2], 0].map(i32::from),
                        tv_max: if th.v_adaptive() {
                            row_px[start..end]
                                .iter()
                                .map(|q| th.v_of(point(q)))
                                .max()
                                .unwrap_or(th.v_sq())
                        } else {
                            th.v_sq()
                        },
                    });
                } else {
                    overflow = true;
                    unlabelled += end - start;
                }
            };
            let mut start = 0usize;
            for &t in starts.iter().filter(|&&t| t != 0) {
                close(start, t as usize);
                start = t as usize;
            }
            close(start, row_px.len());
            let n = base + row_px.len();
            // Ring check: the row's first and last runs, both labelled and
            // different, are joined when their end points are within tH.
            if runs.len() >= first_run + 2
                && runs[runs.len() - 1].end as usize == n
                && params.ring_reaches(col(first_px), col(last_px))
                && th.continues(point(first_px), point(last_px))
            {
                ring_joins.push((first_run as u32 + 1, runs.len() as u32));
            }
            row_runs.push(runs.len() as u32);
        }
        (px.len(), overflow, unlabelled)
    }

    /// Pass 2 run against run (spec §4): unites the runs with a joining pixel
    /// pair and returns how many pairs of runs (labels) joined.
    #[inline(never)]
    fn pass2(&mut self, params: &FccParams, rows: usize) -> u64 {
        let th = Thresholds::new(params);
        let h = params.half();
        let Exact {
            px,
            runs,
            row_runs,
            merge,
            from,
            ..
        } = self;
        let mut joins = 0u64;
        from.clear();
        from.resize(h, 0);
        for i in 1..rows {
            let hm = h.min(i);
            for (m, f) in (1..=hm).zip(from.iter_mut()) {
                *f = row_runs[i - m] as usize;
            }
            let centre_runs = row_runs[i] as usize..row_runs[i + 1] as usize;
            for r in centre_runs {
                let run = &runs[r];
                let lo = (run.first as usize).saturating_sub(h);
                let hi = run.last as usize + h;
                let mut root = merge.find(r as u32 + 1);
                for (m, start) in (1..=hm).zip(from.iter_mut()) {
                    let end = row_runs[i - m + 1] as usize;
                    let mut k = *start;
                    while k < end && (runs[k].last as usize) < lo {
                        k += 1;
                    }
                    *start = k;
                    for (o, other) in runs[k..end].iter().enumerate() {
                        if other.first as usize > hi {
                            break;
                        }
                        if box_gap_sq(run, other) >= run.tv_max.min(other.tv_max)
                            || !runs_touch(px, run, other, h, &th)
                        {
                            continue;
                        }
                        joins += 1;
                        let other_root = merge.find((k + o) as u32 + 1);
                        if other_root != root {
                            merge.link_roots(root, other_root);
                            root = root.min(other_root);
                        }
                    }
                }
            }
        }
        joins
    }

    /// The final labels (spec §5): components numbered in raster order of
    /// their first run, 0 for empty and unlabelled pixels. Returns N.
    #[inline(never)]
    fn number(&mut self, frame: &Frame, labels: &mut Vec<u32>) -> u32 {
        let Exact {
            px,
            runs,
            row_runs,
            merge,
            id,
            ..
        } = self;
        let rep = merge.flatten();
        id.clear();
        id.resize(rep.len(), 0);
        labels.clear();
        labels.resize(frame.points.len(), 0);
        let mut n = 0u32;
        for (out, bounds) in labels.chunks_exact_mut(frame.cols).zip(row_runs.windows(2)) {
            for (r, run) in runs[bounds[0] as usize..bounds[1] as usize]
                .iter()
                .enumerate()
            {
                let root = rep[bounds[0] as usize + r + 1] as usize;
                if id[root] == 0 {
                    n += 1;
                    id[root] = n;
                }
                let v = id[root];
                for q in &px[run.start as usize..run.end as usize] {
                    out[col(q)] = v;
                }
            }
        }
        n
    }
}

/// Squared gap between the bounding boxes of two runs: a lower bound of the
/// squared distance of any of their pixel pairs.
#[inline]
fn box_gap_sq(a: &RunBox, b: &RunBox) -> i64 {
    // Each gap is below 2^16, so its square fits in a u64 from a u32.
    let sq = |d: usize| {
        let gap = (a.lo[d] - b.hi[d]).max(b.lo[d] - a.hi[d]).max(0) as u32;
        u64::from(gap) * u64::from(gap)
    };
    (sq(0) + sq(1) + sq(2) + sq(3)) as i64
}

/// Whether a point of run `a` and a point of run `b` at most `h` columns
/// apart join (spec §4, with the range-adaptive threshold of §2).
#[inline]
fn runs_touch(px: &[Px], a: &RunBox, b: &RunBox, h: usize, th: &Thresholds) -> bool {
    let centre = &px[a.start as usize..a.end as usize];
    let other = &px[b.start as usize..b.end as usize];
    let (first, last) = (b.first as usize, b.last as usize);
    // Only centre points within h columns of the other run can join;
    // `other[lo..hi]` are the points within h columns of the centre point.
    let from = if col(&centre[0]) + h >= first {
        0
    } else {
        centre.partition_point(|p| col(p) + h < first)
    };
    let Some(c0) = centre.get(from) else {
        return false;
    };
    let mut lo = if col(&other[0]) + h >= col(c0) {
        0
    } else {
        other.partition_point(|q| col(q) + h < col(c0))
    };
    let mut hi = lo;
    for p in &centre[from..] {
        let c = col(p);
        if c > last + h {
            break;
        }
        while col(&other[lo]) + h < c {
            lo += 1;
        }
        while hi < other.len() && col(&other[hi]) <= c + h {
            hi += 1;
        }
        if other[lo..hi].iter().any(|q| th.joins(point(p), point(q))) {
            return true;
        }
    }
    false
}
