//! One record per cluster (spec §9.3): the integer part that hardware
//! computes, the direct computation from a labelled frame, and what software
//! derives from the integers (centroid, ranges, heading) and from a
//! cluster's points (the oriented box).

use crate::frame::{dist2, Frame, Point};
use crate::threshold::Thresholds;
use fcc_params::FccParams;
use fcc_pixel::record::HwRecord;
use fcc_pixel::Q_ONE;
use serde::Serialize;

/// One cluster of one frame. Coordinates in Q7.8 units (spec §2); the sums
/// are exact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Record {
    /// Frame number: in the stream, frames since it was made (0, 1, ...).
    pub frame: u64,
    /// Cluster number: raster order of the first pixel in frame mode (spec
    /// §5), the closing order in the stream (spec §9.1).
    pub id: u32,
    /// Labelled pixels of the cluster.
    pub points: u32,
    /// First and last column; for a `seam` cluster with pixels in both
    /// halves of the image, the wrapped span (`last_col < first_col`).
    pub first_col: u32,
    pub last_col: u32,
    /// Column at which the cluster closed (spec §9.2); `C` at the frame end.
    pub closed_col: u32,
    /// A ring check joined two different runs of the cluster.
    pub seam: bool,
    /// Smallest and largest row.
    pub first_row: u32,
    pub last_row: u32,
    /// Axis-aligned box, per coordinate.
    pub min: [i16; 3],
    pub max: [i16; 3],
    /// Smallest and largest squared range `x^2 + y^2 + z^2`.
    pub range2_min: u64,
    pub range2_max: u64,
    /// Sum of x, y and z.
    pub sum: [i64; 3],
    /// Bird's-eye second moments: sum of x^2, x*y and y^2.
    pub sum_xx: i64,
    pub sum_xy: i64,
    pub sum_yy: i64,
}

impl Record {
    /// The part the column-streaming core sends (spec §9.4): every field but
    /// the frame number.
    pub fn hw(&self) -> HwRecord {
        HwRecord {
            id: self.id,
            points: self.points,
            first_col: self.first_col,
            last_col: self.last_col,
            closed_col: self.closed_col,
            seam: self.seam,
            first_row: self.first_row,
            last_row: self.last_row,
            min: self.min,
            max: self.max,
            range2_min: self.range2_min,
            range2_max: self.range2_max,
            sum: self.sum,
            sum_xx: self.sum_xx,
            sum_xy: self.sum_xy,
            sum_yy: self.sum_yy,
        }
    }

    /// Mean point, metres.
    pub fn centroid(&self) -> [f64; 3] {
        let n = f64::from(self.points) * Q_ONE;
        self.sum.map(|s| s as f64 / n)
    }

    /// Distance from the sensor of the closest and the farthest point, metres.
    pub fn range(&self) -> [f64; 2] {
        [self.range2_min, self.range2_max].map(|r2| (r2 as f64).sqrt() / Q_ONE)
    }

    /// Axis-aligned box, metres: `[min, max]`.
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        [self.min, self.max].map(|v| v.map(|q| f64::from(q) / Q_ONE))
    }

    /// Direction of the principal axis of the bird's-eye covariance, radians
    /// in `(-pi/2, pi/2]` from the x axis (0 for a cluster with no spread).
    /// Computed from the exact sums: `n^2 cov = n sum_xy - sum_x sum_y`, etc.
    pub fn heading(&self) -> f64 {
        let n = i128::from(self.points);
        let (sx, sy) = (i128::from(self.sum[0]), i128::from(self.sum[1]));
        let cxx = n * i128::from(self.sum_xx) - sx * sx;
        let cyy = n * i128::from(self.sum_yy) - sy * sy;
        let cxy = n * i128::from(self.sum_xy) - sx * sy;
        if cxy == 0 && cxx >= cyy {
            return 0.0;
        }
        0.5 * (2.0 * cxy as f64).atan2((cxx - cyy) as f64)
    }
}

/// A record being accumulated, pixel by pixel and by merging (spec §9.3):
/// what the stream keeps per open cluster, and the reference of the column
/// core's record accumulators. Start from `Acc::default()` (no pixel).
#[derive(Debug, Clone, Copy)]
pub struct Acc {
    pub points: u32,
    pub min_col: u32,
    pub max_col: u32,
    /// Largest column below `C/2`, smallest at or above it (the wrapped
    /// span of a seam cluster).
    pub lo_max: Option<u32>,
    pub hi_min: Option<u32>,
    pub first_row: u32,
    pub last_row: u32,
    pub min: [i16; 3],
    pub max: [i16; 3],
    pub range2_min: u64,
    pub range2_max: u64,
    pub sum: [i64; 3],
    pub sum_xx: i64,
    pub sum_xy: i64,
    pub sum_yy: i64,
    /// A ring check joined two different runs of the cluster.
    pub seam: bool,
}

impl Default for Acc {
    fn default() -> Self {
        Acc {
            points: 0,
            min_col: u32::MAX,
            max_col: 0,
            lo_max: None,
            hi_min: None,
            first_row: u32::MAX,
            last_row: 0,
            min: [i16::MAX; 3],
            max: [i16::MIN; 3],
            range2_min: u64::MAX,
            range2_max: 0,
            sum: [0; 3],
            sum_xx: 0,
            sum_xy: 0,
            sum_yy: 0,
            seam: false,
        }
    }
}

fn min_some(a: Option<u32>, b: Option<u32>) -> Option<u32> {
    match (a, b) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

impl Acc {
    /// Add the pixel at (`row`, `col`) with point `p`; `half` is `C/2`.
    #[inline]
    pub fn add(&mut self, row: u32, col: u32, p: Point, half: u32) {
        self.min_col = self.min_col.min(col);
        self.max_col = self.max_col.max(col);
        if col < half {
            self.lo_max = self.lo_max.max(Some(col));
        } else {
            self.hi_min = min_some(self.hi_min, Some(col));
        }
        self.add_row_point(row, p);
    }

    /// [`add`](Self::add) for a pixel whose column is no earlier than any
    /// the record holds (the stream's column order): its column is the
    /// largest, so only a first one sets the smallest.
    #[inline]
    pub fn add_in_scan(&mut self, row: u32, col: u32, p: Point, half: u32) {
        debug_assert!(self.points == 0 || col >= self.max_col);
        if self.points == 0 {
            self.min_col = col;
        }
        self.max_col = col;
        if col < half {
            self.lo_max = Some(col);
        } else if self.hi_min.is_none() {
            self.hi_min = Some(col);
        }
        self.add_row_point(row, p);
    }

    /// The row and point of a pixel: everything of [`add`](Self::add) but
    /// the columns.
    #[inline]
    fn add_row_point(&mut self, row: u32, p: Point) {
        self.points += 1;
        self.first_row = self.first_row.min(row);
        self.last_row = self.last_row.max(row);
        // Whole arrays at once: element-wise stores of the adjacent `min`
        // and `max` were compiled into overlapping partial writes that the
        // next read of the record had to wait for.
        let (mn, mx) = (self.min, self.max);
        self.min = [mn[0].min(p[0]), mn[1].min(p[1]), mn[2].min(p[2])];
        self.max = [mx[0].max(p[0]), mx[1].max(p[1]), mx[2].max(p[2])];
        for (s, &v) in self.sum.iter_mut().zip(&p) {
            *s += i64::from(v);
        }
        let r2 = dist2(p, [0; 3]) as u64;
        self.range2_min = self.range2_min.min(r2);
        self.range2_max = self.range2_max.max(r2);
        let (x, y) = (i64::from(p[0]), i64::from(p[1]));
        self.sum_xx += x * x;
        self.sum_xy += x * y;
        self.sum_yy += y * y;
    }

    /// Take in the pixels of `o`.
    pub fn merge(&mut self, o: &Acc) {
        self.points += o.points;
        self.min_col = self.min_col.min(o.min_col);
        self.max_col = self.max_col.max(o.max_col);
        self.lo_max = self.lo_max.max(o.lo_max);
        self.hi_min = min_some(self.hi_min, o.hi_min);
        self.first_row = self.first_row.min(o.first_row);
        self.last_row = self.last_row.max(o.last_row);
        for d in 0..3 {
            self.min[d] = self.min[d].min(o.min[d]);
            self.max[d] = self.max[d].max(o.max[d]);
            self.sum[d] += o.sum[d];
        }
        self.range2_min = self.range2_min.min(o.range2_min);
        self.range2_max = self.range2_max.max(o.range2_max);
        self.sum_xx += o.sum_xx;
        self.sum_xy += o.sum_xy;
        self.sum_yy += o.sum_yy;
        self.seam |= o.seam;
    }

    /// The finished record.
    pub fn record(&self, frame: u64, id: u32, closed_col: u32) -> Record {
        let (first_col, last_col) = match (self.seam, self.hi_min, self.lo_max) {
            (true, Some(hi), Some(lo)) => (hi, lo),
            _ => (self.min_col, self.max_col),
        };
        Record {
            frame,
            id,
            points: self.points,
            first_col,
            last_col,
            closed_col,
            seam: self.seam,
            first_row: self.first_row,
            last_row: self.last_row,
            min: self.min,
            max: self.max,
            range2_min: self.range2_min,
            range2_max: self.range2_max,
            sum: self.sum,
            sum_xx: self.sum_xx,
            sum_xy: self.sum_xy,
            sum_yy: self.sum_yy,
        }
    }
}

/// The columns `(first, last)` of a row's first and last valid pixels when
/// its ring check joins two different runs (spec §3): within `tH`, within
/// the ring reach, with a break (distance or bridge) between them.
/// `labelled` says whether a column's pixel holds a provisional label.
pub(crate) fn ring_join(
    params: &FccParams,
    row: &[Option<Point>],
    labelled: impl Fn(usize) -> bool,
) -> Option<(usize, usize)> {
    let f = row.iter().position(Option::is_some)?;
    let l = row.iter().rposition(Option::is_some)?;
    let (pf, pl) = (row[f]?, row[l]?);
    if f == l
        || !labelled(f)
        || !labelled(l)
        || !params.ring_reaches(f, l)
        || !Thresholds::new(params).continues(pf, pl)
    {
        return None;
    }
    let mut prev = (f, pf);
    for (c, p) in row.iter().enumerate().take(l + 1).skip(f + 1) {
        let Some(p) = *p else { continue };
        if !params.bridges(c - prev.0 - 1) || !Thresholds::new(params).continues(p, prev.1) {
            return Some((f, l));
        }
        prev = (c, p);
    }
    None
}

/// The records of a labelled frame, computed directly from its pixels: one
/// per label `1 ..= clusters` of `labels` (the frame's label image, 0 for
/// none), in label order, all closed at the frame end (`closed_col = C`).
pub fn frame_records(
    params: &FccParams,
    frame: &Frame,
    labels: &[u32],
    clusters: u32,
    frame_no: u64,
) -> Vec<Record> {
    let cols = frame.cols;
    let half = (cols / 2) as u32;
    let mut acc = vec![Acc::default(); clusters as usize + 1];
    for (k, (p, &l)) in frame.points.iter().zip(labels).enumerate() {
        if let (Some(p), true) = (p, l != 0) {
            acc[l as usize].add((k / cols) as u32, (k % cols) as u32, *p, half);
        }
    }
    for (r, row) in frame.points.chunks_exact(cols).enumerate() {
        let row_labels = &labels[r * cols..(r + 1) * cols];
        if let Some((f, _)) = ring_join(params, row, |c| row_labels[c] != 0) {
            acc[row_labels[f] as usize].seam = true;
        }
    }
    acc.iter()
        .enumerate()
        .skip(1)
        .map(|(id, a)| a.record(frame_no, id as u32, cols as u32))
        .collect()
}

/// An oriented box in the bird's-eye plane, metres: the minimum-area
/// rectangle enclosing a cluster's (x, y) points, with its z extent.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OrientedBox {
    /// Centre of the rectangle (x, y).
    pub center: [f64; 2],
    /// Length (along `yaw`) and width, length >= width.
    pub size: [f64; 2],
    /// Direction of the length, radians in `(-pi/2, pi/2]` from the x axis.
    pub yaw: f64,
    /// Lowest and highest z.
    pub z: [f64; 2],
}

/// The minimum-area rectangle enclosing the bird's-eye points (spec §9.3):
/// the convex hull (exact integer arithmetic), then each hull edge as one
/// side; the smallest area wins, the first edge on a tie. `None` for no
/// points.
pub fn oriented_box(points: &[Point]) -> Option<OrientedBox> {
    let (zmin, zmax) = points.iter().fold((i16::MAX, i16::MIN), |(lo, hi), p| {
        (lo.min(p[2]), hi.max(p[2]))
    });
    let hull = monotone_chain(sorted_extremes(points));
    let first = *hull.first()?;
    let m = |v: f64| v / Q_ONE;
    let z = [m(f64::from(zmin)), m(f64::from(zmax))];
    if hull.len() == 1 {
        let c = [m(first[0] as f64), m(first[1] as f64)];
        return Some(OrientedBox {
            center: c,
            size: [0.0, 0.0],
            yaw: 0.0,
            z,
        });
    }
    let mut best: Option<(f64, [f64; 2], [f64; 2], f64)> = None;
    for (k, a) in hull.iter().enumerate() {
        let b = hull[(k + 1) % hull.len()];
        let (dx, dy) = ((b[0] - a[0]) as f64, (b[1] - a[1]) as f64);
        let len = dx.hypot(dy);
        if len == 0.0 {
            continue;
        }
        let (ux, uy) = (dx / len, dy / len);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for q in &hull {
            let (x, y) = ((q[0] - a[0]) as f64, (q[1] - a[1]) as f64);
            let s = [x * ux + y * uy, -x * uy + y * ux];
            for d in 0..2 {
                lo[d] = lo[d].min(s[d]);
                hi[d] = hi[d].max(s[d]);
            }
        }
        let area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if best.is_none_or(|b| area < b.0) {
            let (cu, cv) = ((lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0);
            let centre = [
                a[0] as f64 + cu * ux - cv * uy,
                a[1] as f64 + cu * uy + cv * ux,
            ];
            best = Some((area, [hi[0] - lo[0], hi[1] - lo[1]], centre, uy.atan2(ux)));
        }
    }
    let (_, size, centre, mut yaw) = best?;
    let mut size = size;
    if size[1] > size[0] {
        size.swap(0, 1);
        yaw += std::f64::consts::FRAC_PI_2;
    }
    // Fold the direction into (-pi/2, pi/2]: a box has no front.
    while yaw > std::f64::consts::FRAC_PI_2 {
        yaw -= std::f64::consts::PI;
    }
    while yaw <= -std::f64::consts::FRAC_PI_2 {
        yaw += std::f64::consts::PI;
    }
    Some(OrientedBox {
        center: centre.map(m),
        size: size.map(m),
        yaw,
        z,
    })
}

/// The bird's-eye points sorted and without duplicates, keeping at least
/// every point that can be a vertex of their convex hull: where the x span
/// is small against the count (a cluster's Q7.8 points), only the lowest and
/// highest y of each x, in order, without a sort; otherwise all, sorted.
/// Either way the hull below is the same: a point between two others of its
/// x is never a vertex.
fn sorted_extremes(points: &[Point]) -> Vec<[i64; 2]> {
    let (lo, hi) = points.iter().fold((i16::MAX, i16::MIN), |(lo, hi), q| {
        (lo.min(q[0]), hi.max(q[0]))
    });
    let span = i64::from(hi) - i64::from(lo) + 1;
    if points.len() < 16 || span > 2 * points.len() as i64 {
        // Sorted as one key a point, x then y: offset binary keeps the order.
        let key = |v: i16| u32::from(v as u16 ^ 0x8000);
        let mut k: Vec<u32> = points.iter().map(|q| key(q[0]) << 16 | key(q[1])).collect();
        k.sort_unstable();
        k.dedup();
        let coord = |v: u32| i64::from((v as u16 ^ 0x8000) as i16);
        return k.iter().map(|&v| [coord(v >> 16), coord(v)]).collect();
    }
    let mut ys = vec![(i16::MAX, i16::MIN); span as usize];
    for q in points {
        let y = &mut ys[(q[0] as i32 - lo as i32) as usize];
        *y = (y.0.min(q[1]), y.1.max(q[1]));
    }
    let mut p = Vec::with_capacity(2 * ys.len());
    for (k, &(ymin, ymax)) in ys.iter().enumerate() {
        if ymin > ymax {
            continue;
        }
        let x = i64::from(lo) + k as i64;
        p.push([x, i64::from(ymin)]);
        if ymax != ymin {
            p.push([x, i64::from(ymax)]);
        }
    }
    p
}

/// One chain of the monotone chain: the turns of `points` that stay strictly
/// counter-clockwise, appended to `hull`, without its last point (the next
/// chain's first).
fn chain<'a>(hull: &mut Vec<[i64; 2]>, points: impl Iterator<Item = &'a [i64; 2]>) {
    let cross = |o: [i64; 2], a: [i64; 2], b: [i64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let start = hull.len();
    for &q in points {
        while hull.len() >= start + 2 && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0 {
            hull.pop();
        }
        hull.push(q);
    }
    hull.pop();
}

/// The convex hull of sorted, distinct points (Andrew's monotone chain;
/// integer cross products are exact): its vertices counter-clockwise from
/// the smallest, collinear points dropped.
fn monotone_chain(p: Vec<[i64; 2]>) -> Vec<[i64; 2]> {
    if p.len() <= 2 {
        return p;
    }
    let mut hull: Vec<[i64; 2]> = Vec::with_capacity(2 * p.len());
    chain(&mut hull, p.iter());
    chain(&mut hull, p.iter().rev());
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn hull_of_the_extremes_is_the_hull_of_all_points() {
        // Dense and sparse x spans, vertical runs, duplicates, lines.
        let seed = 0x9e37_79b9_7f4a_7c15;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut next = |m: i64| rng.gen_range(0..m);
        for case in 0..400 {
            let n = 1 + next(300) as usize;
            let (wx, wy) = (1 + next([4, 40, 400, 4000][case % 4]), 1 + next(500));
            let pts: Vec<Point> = (0..n)
                .map(|_| {
                    let y = if case % 7 == 0 { 3 } else { next(wy) };
                    [(next(wx) - wx / 2) as i16, y as i16, 0]
                })
                .collect();
            let mut all: Vec<[i64; 2]> = pts
                .iter()
                .map(|q| [i64::from(q[0]), i64::from(q[1])])
                .collect();
            all.sort_unstable();
            all.dedup();
            let ext = sorted_extremes(&pts);
            assert!(
                ext.windows(2).all(|w| w[0] < w[1]),
                "case {case}: not sorted, seed {seed:#x}"
            );
            assert_eq!(
                monotone_chain(ext),
                monotone_chain(all),
                "case {case}: {n} points, seed {seed:#x}"
            );
        }
    }

    #[test]
    fn oriented_box_of_a_rotated_rectangle() {
        // A 4 m x 2 m rectangle's corners and edge points, rotated by 30 degrees.
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        let mut pts = Vec::new();
        for k in 0..=40 {
            for (u, v) in [
                (k as f64 / 10.0 - 2.0, -1.0),
                (k as f64 / 10.0 - 2.0, 1.0),
                (-2.0, k as f64 / 20.0 - 1.0),
                (2.0, k as f64 / 20.0 - 1.0),
            ] {
                let (x, y) = (10.0 + u * c - v * s, 5.0 + u * s + v * c);
                pts.push([(x * 256.0).round() as i16, (y * 256.0).round() as i16, 0]);
            }
        }
        let b = oriented_box(&pts).unwrap();
        assert!(
            (b.size[0] - 4.0).abs() < 0.01 && (b.size[1] - 2.0).abs() < 0.01,
            "{b:?}"
        );
        assert!((b.yaw - 30f64.to_radians()).abs() < 0.01, "{b:?}");
        assert!((b.center[0] - 10.0).abs() < 0.01 && (b.center[1] - 5.0).abs() < 0.01);
    }

    #[test]
    fn sorted_extremes_sort_as_pairs_over_the_whole_range() {
        // The sort's one key a point against a sort of (x, y) pairs, on
        // spread points (the sorting path) from the whole i16 range, ends
        // and signs included, with duplicates.
        let seed = 0x2545_f491_4f6c_dd1d;
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let ends = [i16::MIN, i16::MIN + 1, -1, 0, 1, i16::MAX - 1, i16::MAX];
        for n in [1usize, 5, 15, 16, 40, 300] {
            for _ in 0..50 {
                let pts: Vec<Point> = (0..n)
                    .map(|_| {
                        let v = |rng: &mut ChaCha8Rng| match rng.gen_range(0..4) {
                            0 => ends[rng.gen_range(0..ends.len())],
                            _ => rng.gen::<i16>(),
                        };
                        let x = v(&mut rng);
                        // Now and then on the diagonal: x and y alike.
                        let y = if rng.gen_range(0..5) == 0 {
                            x
                        } else {
                            v(&mut rng)
                        };
                        [x, y, 0]
                    })
                    .collect();
                let mut want: Vec<[i64; 2]> = pts
                    .iter()
                    .map(|q| [i64::from(q[0]), i64::from(q[1])])
                    .collect();
                want.sort_unstable();
                want.dedup();
                assert_eq!(sorted_extremes(&pts), want, "seed {seed:#x}: {pts:?}");
            }
        }
    }

    #[test]
    fn oriented_box_degenerate() {
        assert!(oriented_box(&[]).is_none());
        let one = oriented_box(&[[256, 512, 10]; 3]).unwrap();
        assert_eq!(one.size, [0.0, 0.0]);
        assert_eq!(one.center, [1.0, 2.0]);
        let line = oriented_box(&[[0, 0, 0], [256, 256, 0], [512, 512, 0]]).unwrap();
        assert!((line.size[0] - 8f64.sqrt()).abs() < 1e-9 && line.size[1].abs() < 1e-9);
        assert!((line.yaw - std::f64::consts::FRAC_PI_4).abs() < 1e-9);
    }

    #[test]
    fn heading_follows_the_long_axis() {
        let mut a = Acc::default();
        for k in 0..10i16 {
            a.add(0, k as u32, [k * 100, k * 100 + (k % 2), 0], 100);
        }
        let h = a.record(0, 1, 0).heading();
        assert!((h - std::f64::consts::FRAC_PI_4).abs() < 0.01, "{h}");
        let mut b = Acc::default();
        b.add(0, 0, [5, 5, 5], 1);
        assert_eq!(b.record(0, 1, 0).heading(), 0.0);
    }
}
