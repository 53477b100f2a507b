//! Test frames: directed corner cases and seeded random scenes, all built from
//! a simple spinning-LiDAR geometry (row = elevation, column = azimuth), so
//! neighbouring pixels at the same range are close in space.

use fcc_golden::{quantize_point, Frame, Point};
use fcc_params::FccParams;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The point seen at pixel (r, c) at `range` metres.
pub fn point_at(p: &FccParams, r: usize, c: usize, range: f64) -> Option<Point> {
    let az = 2.0 * std::f64::consts::PI * c as f64 / p.cols as f64;
    let el = (r as f64 - p.rows as f64 / 2.0).to_radians() * 0.4;
    quantize_point(
        range * el.cos() * az.cos(),
        range * el.cos() * az.sin(),
        range * el.sin(),
    )
}

/// No points at all.
pub fn empty(p: &FccParams) -> Frame {
    Frame::empty(p.rows, p.cols)
}

/// A single point.
pub fn one_point(p: &FccParams, r: usize, c: usize) -> Frame {
    let mut f = empty(p);
    f.set(r, c, point_at(p, r, c, 10.0));
    f
}

/// One row full of points: a wall at 8 m with a step to 12 m and a few holes.
pub fn one_row(p: &FccParams, r: usize) -> Frame {
    let mut f = empty(p);
    for c in 0..p.cols {
        if c % 17 == 5 {
            continue;
        }
        let range = if (p.cols / 3..p.cols / 2).contains(&c) {
            12.0
        } else {
            8.0
        };
        f.set(r, c, point_at(p, r, c, range));
    }
    f
}

/// Every row is a full circle at 6 m except a far segment in the middle, so
/// the first and last runs of each row meet only through the ring check.
pub fn ring(p: &FccParams) -> Frame {
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..p.cols {
            let far = (p.cols * 2 / 5..p.cols * 3 / 5).contains(&c);
            f.set(r, c, point_at(p, r, c, if far { 30.0 } else { 6.0 }));
        }
    }
    f
}

/// Every pixel valid, alternating near and far along each row and between
/// rows: every pixel is a run of its own, and each joins diagonal neighbours.
pub fn checkerboard(p: &FccParams) -> Frame {
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..p.cols {
            let range = if (r + c) % 2 == 0 { 10.0 } else { 25.0 };
            f.set(r, c, point_at(p, r, c, range));
        }
    }
    f
}

/// Columns alternately near and far in the first `width` columns, the rest
/// empty: every pixel there is a run of its own and matches the same-range
/// pixels of the rows above, so from K = 5 on a centre keeps several joins.
pub fn stripes(p: &FccParams, width: usize) -> Frame {
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..width.min(p.cols) {
            let range = if c % 2 == 0 { 5.0 } else { 20.0 };
            f.set(r, c, point_at(p, r, c, range));
        }
    }
    f
}

/// Vertical teeth (separate runs in every row) that only meet in the bottom
/// row: every tooth's labels merge late, through long parent chains.
pub fn comb(p: &FccParams) -> Frame {
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..p.cols {
            let tooth = c % 8 < 3;
            if tooth || r == p.rows - 1 {
                f.set(r, c, point_at(p, r, c, 9.0));
            }
        }
    }
    f
}

/// Nested U shapes: each U's two arms are separate runs until its bottom, and
/// inner Us end higher, so components merge in an order opposite to their labels.
pub fn u_shapes(p: &FccParams) -> Frame {
    let mut f = empty(p);
    let n = (p.rows / 3).clamp(1, 8);
    for k in 0..n {
        let left = 4 + 6 * k;
        let right = p.cols.saturating_sub(5 + 6 * k);
        let bottom = p.rows - 1 - 2 * k;
        if right <= left + 2 {
            break;
        }
        for r in 0..=bottom {
            for c in [left, left + 1, right - 1, right] {
                f.set(r, c, point_at(p, r, c, 15.0 + k as f64));
            }
        }
        for c in left..=right {
            f.set(bottom, c, point_at(p, bottom, c, 15.0 + k as f64));
        }
    }
    f
}

/// A staircase of short segments, each touching the previous one only in the
/// row above through the window's far corner: a long chain of joins.
pub fn staircase(p: &FccParams) -> Frame {
    let mut f = empty(p);
    let h = p.half();
    for r in 0..p.rows {
        let c0 = (r * (2 * h + 1) + 3) % p.cols;
        for c in c0..(c0 + 2).min(p.cols) {
            f.set(r, c, point_at(p, r, c, 7.0));
        }
    }
    f
}

/// Far more runs than labels when `label_bits` is small: every other pixel
/// alternates between two depths.
pub fn label_overflow(p: &FccParams) -> Frame {
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..p.cols {
            if c % 3 != 2 {
                let range = if c % 3 == 0 { 5.0 } else { 40.0 };
                f.set(r, c, point_at(p, r, c, range));
            }
        }
    }
    f
}

/// Points far apart in every coordinate (differences near the Q7.8 limits).
pub fn extremes(p: &FccParams) -> Frame {
    let mut f = empty(p);
    let vals: [i16; 6] = [i16::MIN, i16::MAX, 0, -1, 1, 12345];
    for r in 0..p.rows {
        for c in 0..p.cols {
            let i = r * 7 + c * 3;
            if i % 5 != 0 {
                f.set(
                    r,
                    c,
                    Some([vals[i % 6], vals[(i / 6) % 6], vals[(i / 36) % 6]]),
                );
            }
        }
    }
    f
}

/// Distances exactly at the thresholds, in Q7.8 units. Along a row, steps
/// of exactly tH continue a run and tH + 1 start a new one; between rows, a
/// vertical offset of tV - 1 joins and exactly tV does not (strict); the
/// row's last pixel sits exactly tH (even rows) or tH + 1 (odd rows) from
/// its first, so only even rows close their ring.
pub fn thresholds(p: &FccParams) -> Frame {
    let th = p.th_h_q();
    let tv = p.th_v_q();
    let mut f = empty(p);
    let block = 40.min(p.cols - 1);
    for r in 0..p.rows {
        let rr = (r % 16) as i64;
        let y = (rr / 2) * (2 * tv - 1) + (rr % 2) * (tv - 1);
        let mut x = 0i64;
        for c in 0..block {
            if c > 0 {
                x += if c % 3 == 0 { th + 1 } else { th };
            }
            f.set(r, c, Some([x as i16, y as i16, 0]));
        }
        let z = if r % 2 == 0 { th } else { th + 1 };
        f.set(r, p.cols - 1, Some([0, y as i16, z as i16]));
    }
    f
}

/// A seeded random scene: boxes of points at random ranges, holes, noise.
pub fn random(p: &FccParams, seed: u64) -> Frame {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut depth = vec![f64::NAN; p.pixels()];
    let objects = rng.gen_range(3..16);
    for _ in 0..objects {
        let r0 = rng.gen_range(0..p.rows);
        let r1 = (r0 + rng.gen_range(1..p.rows.max(2))).min(p.rows);
        let c0 = rng.gen_range(0..p.cols);
        let c1 = (c0 + rng.gen_range(1..(p.cols / 3).max(2))).min(p.cols);
        let range = rng.gen_range(2.0..60.0);
        let tilt = rng.gen_range(-0.05..0.05);
        for r in r0..r1 {
            for c in c0..c1 {
                depth[r * p.cols + c] = range + tilt * (c - c0) as f64;
            }
        }
    }
    let holes = rng.gen_range(0.0..0.3);
    let noise = rng.gen_range(0.0..0.1);
    let mut f = empty(p);
    for r in 0..p.rows {
        for c in 0..p.cols {
            let d = depth[r * p.cols + c];
            let pt = if rng.gen::<f64>() < noise {
                point_at(p, r, c, rng.gen_range(1.0..80.0))
            } else if d.is_finite() && rng.gen::<f64>() >= holes {
                point_at(p, r, c, d + rng.gen_range(-0.03..0.03))
            } else {
                None
            };
            f.set(r, c, pt);
        }
    }
    f
}

/// All directed frames, by name.
pub fn directed(p: &FccParams) -> Vec<(&'static str, Frame)> {
    vec![
        ("empty", empty(p)),
        ("one_point", one_point(p, p.rows / 2, p.cols / 2)),
        ("one_point_corner", one_point(p, p.rows - 1, p.cols - 1)),
        ("one_row", one_row(p, p.rows / 3)),
        ("ring", ring(p)),
        ("checkerboard", checkerboard(p)),
        ("comb", comb(p)),
        ("u_shapes", u_shapes(p)),
        ("staircase", staircase(p)),
        ("label_overflow", label_overflow(p)),
        ("extremes", extremes(p)),
        ("thresholds", thresholds(p)),
    ]
}
