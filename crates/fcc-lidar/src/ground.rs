//! Ground removal for range images. FCC clusters everything it is given, so
//! the ground has to go first or it glues every object into one cluster.
//!
//! Methods:
//! - `none`: keep every point;
//! - `plane`: a RANSAC plane fit (normal within `max_tilt_deg` of vertical,
//!   fitted to the lower half of the beams, refined by least squares on its
//!   inliers); a point within `plane_distance_m` of the plane is ground;
//! - `slope` (the default): the plane seeds a walk up every column from the
//!   bottom beam. The first return of a column is ground if it lies within
//!   `seed_tolerance_m` of the plane and below the sensor; every later return is ground if the
//!   rise from the last ground return of its column is at most
//!   `tan(max_slope_deg)` times the run plus `step_m` (range noise), the same
//!   holds from the return that started the column's ground (so the noise
//!   allowance cannot add up, step by step, up a wall next to the sensor),
//!   and it lies within `max_height_m` of the plane (a return
//!   more than `max_gap_m` beyond the last ground return must meet the seed
//!   tolerance again). A ground return with a non-ground return right above
//!   it (closer than `foot_run_m` across the plane, higher by more than
//!   `step_m`) is the foot of an upright
//!   object and is given back to it. The walk
//!   follows road that bends away from the plane and stops at anything that
//!   rises steeply from it, such as the foot of a car or a kerb-side wall.

use crate::error::{LidarError, Result};
use crate::image::RangeImage;

/// Which ground removal to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum GroundMethod {
    None,
    Plane,
    #[default]
    Slope,
}

impl std::str::FromStr for GroundMethod {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s {
            "none" => Ok(GroundMethod::None),
            "plane" => Ok(GroundMethod::Plane),
            "slope" => Ok(GroundMethod::Slope),
            _ => Err(format!(
                "unknown ground method `{s}`: expected none, plane or slope"
            )),
        }
    }
}

impl std::fmt::Display for GroundMethod {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            GroundMethod::None => "none",
            GroundMethod::Plane => "plane",
            GroundMethod::Slope => "slope",
        })
    }
}

/// Settings of ground removal.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GroundParams {
    pub method: GroundMethod,
    /// `plane`: inlier distance, metres (also the RANSAC inlier distance).
    pub plane_distance_m: f64,
    /// Largest tilt of the ground normal from vertical, degrees.
    pub max_tilt_deg: f64,
    /// RANSAC hypotheses.
    pub iterations: usize,
    /// `slope`: steepest rise between consecutive ground returns, degrees.
    pub max_slope_deg: f64,
    /// `slope`: how far the first ground return of a column may lie from the plane, metres.
    pub seed_tolerance_m: f64,
    /// `slope`: how far any ground return may lie from the plane, metres.
    pub max_height_m: f64,
    /// `slope`: beyond this distance from the last ground return of its
    /// column, a return must meet the seed tolerance again, metres.
    pub max_gap_m: f64,
    /// `slope`: rise allowed on top of the slope between consecutive ground
    /// returns, for range noise, metres.
    pub step_m: f64,
    /// `slope`: a ground return with a non-ground return above it closer
    /// than this across the plane is the foot of an object, not ground, metres.
    pub foot_run_m: f64,
}

impl Default for GroundParams {
    fn default() -> Self {
        GroundParams {
            method: GroundMethod::Slope,
            plane_distance_m: 0.2,
            max_tilt_deg: 15.0,
            iterations: 200,
            max_slope_deg: 10.0,
            seed_tolerance_m: 0.3,
            max_height_m: 0.8,
            max_gap_m: 5.0,
            foot_run_m: 0.1,
            step_m: 0.03,
        }
    }
}

impl GroundParams {
    /// Check the numbers.
    pub fn validate(&self) -> Result<()> {
        let pos = |name: &str, v: f64, hi: f64| {
            if v.is_finite() && v > 0.0 && v <= hi {
                Ok(())
            } else {
                Err(LidarError::Config(format!(
                    "ground {name} = {v} must be in (0, {hi}]"
                )))
            }
        };
        pos("plane_distance_m", self.plane_distance_m, 10.0)?;
        pos("max_tilt_deg", self.max_tilt_deg, 80.0)?;
        pos("max_slope_deg", self.max_slope_deg, 80.0)?;
        pos("seed_tolerance_m", self.seed_tolerance_m, 10.0)?;
        pos("max_height_m", self.max_height_m, 50.0)?;
        pos("max_gap_m", self.max_gap_m, 1000.0)?;
        for (name, v) in [("foot_run_m", self.foot_run_m), ("step_m", self.step_m)] {
            if !(v.is_finite() && (0.0..=10.0).contains(&v)) {
                return Err(LidarError::Config(format!(
                    "ground {name} = {v} must be in [0, 10]"
                )));
            }
        }
        if !(1..=100_000).contains(&self.iterations) {
            return Err(LidarError::Config(format!(
                "ground iterations = {} must be in 1..=100000",
                self.iterations
            )));
        }
        Ok(())
    }
}

/// The outcome of ground removal on one image.
#[derive(Debug, Clone, PartialEq)]
pub struct Ground {
    /// Per pixel: true where the pixel holds a ground return.
    pub mask: Vec<bool>,
    /// The fitted plane `a x + b y + c z + d = 0` with `(a, b, c)` a unit
    /// normal pointing up, if one was found.
    pub plane: Option<[f64; 4]>,
}

impl Ground {
    /// Ground pixels.
    pub fn count(&self) -> usize {
        self.mask.iter().filter(|&&g| g).count()
    }
}

/// Find the ground of an image.
pub fn detect_ground(image: &RangeImage, params: &GroundParams) -> Result<Ground> {
    params.validate()?;
    let n = image.pixels();
    if params.method == GroundMethod::None {
        return Ok(Ground {
            mask: vec![false; n],
            plane: None,
        });
    }
    let plane = fit_plane(image, params);
    let Some(pl) = plane else {
        return Ok(Ground {
            mask: vec![false; n],
            plane: None,
        });
    };
    let dist = |p: [f32; 3]| {
        pl[0] * f64::from(p[0]) + pl[1] * f64::from(p[1]) + pl[2] * f64::from(p[2]) + pl[3]
    };
    let mut mask = vec![false; n];
    match params.method {
        GroundMethod::None => {}
        GroundMethod::Plane => {
            for (i, m) in mask.iter_mut().enumerate() {
                if let Some(p) = image.point(i) {
                    *m = dist(p).abs() <= params.plane_distance_m;
                }
            }
        }
        GroundMethod::Slope => {
            let tan_max = params.max_slope_deg.to_radians().tan();
            for c in 0..image.cols {
                // The last ground return, and the seed its stretch started from.
                let mut last: Option<([f32; 3], [f32; 3])> = None;
                for r in (0..image.rows).rev() {
                    let i = r * image.cols + c;
                    let Some(p) = image.point(i) else {
                        continue;
                    };
                    let h = dist(p);
                    // A seed lies near the plane and below the sensor (whose
                    // height above the plane is pl[3]): a return above the
                    // sensor looks up and cannot start the ground of a column.
                    let seeded = h.abs() <= params.seed_tolerance_m && h < pl[3];
                    let next = match last {
                        None => seeded.then_some(p),
                        Some((q, seed)) => {
                            // Rise and run measured along the plane normal and across it.
                            let (rise, run) = rise_run(p, q, pl);
                            if run > params.max_gap_m {
                                // Too far from the last ground return to follow
                                // the slope: start again as at the column's foot.
                                seeded.then_some(p)
                            } else {
                                // The slope holds step by step and from the seed
                                // on: the noise allowance is granted once, not
                                // per step, so beams close together cannot climb
                                // a wall next to the sensor a centimetre at a time.
                                let (rise_s, run_s) = rise_run(p, seed, pl);
                                (h.abs() <= params.max_height_m
                                    && rise.abs() <= tan_max * run + params.step_m
                                    && rise_s.abs() <= tan_max * run_s + params.step_m)
                                    .then_some(seed)
                            }
                        }
                    };
                    if let Some(seed) = next {
                        mask[i] = true;
                        last = Some((p, seed));
                    }
                }
                // The foot of an upright object: a ground return whose next
                // return up the column is not ground and stands right above it.
                let mut below: Option<(usize, [f32; 3])> = None;
                for r in (0..image.rows).rev() {
                    let i = r * image.cols + c;
                    let Some(p) = image.point(i) else {
                        continue;
                    };
                    if let Some((j, q)) = below {
                        if mask[j] && !mask[i] {
                            let (rise, run) = rise_run(p, q, pl);
                            if rise > params.step_m && run <= params.foot_run_m {
                                mask[j] = false;
                            }
                        }
                    }
                    below = Some((i, p));
                }
            }
        }
    }
    Ok(Ground { mask, plane })
}

/// A small deterministic generator for RANSAC (splitmix64).
struct SplitMix(u64);

impl SplitMix {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) % n as u64) as usize
    }
}

/// The step from `q` to `p` measured along the unit plane normal `n` (rise)
/// and across it (run).
fn rise_run(p: [f32; 3], q: [f32; 3], n: [f64; 4]) -> (f64, f64) {
    let d = [
        f64::from(p[0] - q[0]),
        f64::from(p[1] - q[1]),
        f64::from(p[2] - q[2]),
    ];
    let rise = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    let run = ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - rise * rise)
        .max(0.0)
        .sqrt();
    (rise, run)
}

fn plane_through(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Option<[f64; 4]> {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let mut n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len < 1e-9 {
        return None;
    }
    if n[2] < 0.0 {
        n = [-n[0], -n[1], -n[2]];
    }
    let n = [n[0] / len, n[1] / len, n[2] / len];
    Some([n[0], n[1], n[2], -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2])])
}

/// RANSAC over the returns of the lower half of the beams, then a least
/// squares refit `z = a x + b y + c` on the inliers.
fn fit_plane(image: &RangeImage, params: &GroundParams) -> Option<[f64; 4]> {
    let first_row = image.rows / 2;
    let mut cand: Vec<[f64; 3]> = (first_row * image.cols..image.pixels())
        .filter_map(|i| image.point(i))
        .map(|p| [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])])
        .collect();
    if cand.len() < 3 {
        return None;
    }
    // At most 4000 candidates, evenly spread.
    if cand.len() > 4000 {
        let step = cand.len() as f64 / 4000.0;
        cand = (0..4000)
            .map(|k| cand[(k as f64 * step) as usize])
            .collect();
    }
    let min_nz = params.max_tilt_deg.to_radians().cos();
    let mut rng = SplitMix(0x5eed);
    let mut best: Option<([f64; 4], usize)> = None;
    for _ in 0..params.iterations {
        let (a, b, c) = (
            rng.below(cand.len()),
            rng.below(cand.len()),
            rng.below(cand.len()),
        );
        let Some(pl) = plane_through(cand[a], cand[b], cand[c]) else {
            continue;
        };
        if pl[2] < min_nz {
            continue;
        }
        let inliers = cand
            .iter()
            .filter(|p| {
                (pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] + pl[3]).abs()
                    <= params.plane_distance_m
            })
            .count();
        // Prefer more inliers; among equals, the lower plane.
        let better = match best {
            None => true,
            Some((bp, bn)) => inliers > bn || (inliers == bn && pl[3] > bp[3]),
        };
        if better {
            best = Some((pl, inliers));
        }
    }
    let (pl, count) = best?;
    if count < 3 {
        return None;
    }
    // Least squares z = a x + b y + c over the inliers.
    let mut m = nalgebra::Matrix3::<f64>::zeros();
    let mut v = nalgebra::Vector3::<f64>::zeros();
    for p in &cand {
        if (pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] + pl[3]).abs() <= params.plane_distance_m {
            let row = nalgebra::Vector3::new(p[0], p[1], 1.0);
            m += row * row.transpose();
            v += row * p[2];
        }
    }
    let Some(sol) = m.lu().solve(&v) else {
        return Some(pl);
    };
    let n = nalgebra::Vector3::new(-sol[0], -sol[1], 1.0).normalize();
    let refit = [n[0], n[1], n[2], -sol[2] * n[2]];
    if refit.iter().all(|x| x.is_finite()) && refit[2] >= min_nz {
        Some(refit)
    } else {
        Some(pl)
    }
}

/// Agreement of a ground mask with the truth.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct GroundScore {
    pub true_positives: usize,
    pub false_positives: usize,
    pub false_negatives: usize,
    /// Share of pixels called ground that are ground (1 if none called).
    pub precision: f64,
    /// Share of ground pixels called ground (1 if there is none).
    pub recall: f64,
}

impl GroundScore {
    /// The score of these counts, with precision and recall derived from them.
    pub fn from_counts(
        true_positives: usize,
        false_positives: usize,
        false_negatives: usize,
    ) -> Self {
        let ratio = |a: usize, b: usize| {
            if a + b == 0 {
                1.0
            } else {
                a as f64 / (a + b) as f64
            }
        };
        Self {
            true_positives,
            false_positives,
            false_negatives,
            precision: ratio(true_positives, false_positives),
            recall: ratio(true_positives, false_negatives),
        }
    }
}

/// Score a ground mask against the true one (pixels counted only where the
/// image has a point).
pub fn score_ground(image: &RangeImage, got: &[bool], truth: &[bool]) -> Result<GroundScore> {
    for (what, len) in [
        ("ground mask", got.len()),
        ("true ground mask", truth.len()),
    ] {
        if len != image.pixels() {
            return Err(LidarError::Mismatch {
                what: format!("{what} of a {} x {} image", image.rows, image.cols),
                expected: image.pixels(),
                got: len,
            });
        }
    }
    let mut s = GroundScore::default();
    for i in 0..image.pixels() {
        if image.point(i).is_none() {
            continue;
        }
        match (got[i], truth[i]) {
            (true, true) => s.true_positives += 1,
            (true, false) => s.false_positives += 1,
            (false, true) => s.false_negatives += 1,
            (false, false) => {}
        }
    }
    Ok(GroundScore::from_counts(
        s.true_positives,
        s.false_positives,
        s.false_negatives,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tilted plane of returns on the lower half, a wall column on top.
    fn scene() -> (RangeImage, Vec<bool>) {
        let (rows, cols) = (16, 64);
        let mut img = RangeImage::empty(rows, cols);
        let mut truth = vec![false; rows * cols];
        for r in 0..rows {
            for c in 0..cols {
                let az = std::f32::consts::TAU * c as f32 / cols as f32;
                let i = r * cols + c;
                if r >= 8 {
                    // Ground: distance grows towards the upper rows, z = -1.8 + 0.02 x.
                    let d = 3.0 + (rows - 1 - r) as f32 * 1.5;
                    let (x, y) = (d * az.cos(), d * az.sin());
                    img.set(i, Some([x, y, -1.8 + 0.02 * x]));
                    truth[i] = true;
                } else if c < 10 {
                    // A wall 20 m away.
                    img.set(
                        i,
                        Some([
                            20.0 * az.cos(),
                            20.0 * az.sin(),
                            -1.0 + (8 - r) as f32 * 0.3,
                        ]),
                    );
                }
            }
        }
        (img, truth)
    }

    #[test]
    fn every_method_on_a_tilted_plane() {
        let (img, truth) = scene();
        for method in [GroundMethod::Plane, GroundMethod::Slope] {
            let params = GroundParams {
                method,
                ..GroundParams::default()
            };
            let g = detect_ground(&img, &params).unwrap();
            let pl = g.plane.unwrap();
            assert!((pl[3] / pl[2] - 1.8).abs() < 0.01, "{pl:?}");
            let s = score_ground(&img, &g.mask, &truth).unwrap();
            assert_eq!((s.precision, s.recall), (1.0, 1.0), "{method}: {s:?}");
        }
        let none = detect_ground(
            &img,
            &GroundParams {
                method: GroundMethod::None,
                ..GroundParams::default()
            },
        )
        .unwrap();
        assert_eq!(none.count(), 0);
    }

    /// Ground 0.2 m below the sensor and, in a sector, a wall 1 m away: near
    /// the sensor, beams 1 degree apart step up the wall by under 2 cm, less
    /// than the noise allowance `step_m`.
    fn near_wall() -> (RangeImage, Vec<bool>) {
        let (rows, cols) = (32, 256);
        let mut img = RangeImage::empty(rows, cols);
        let mut truth = vec![false; rows * cols];
        for r in 0..rows {
            let e = (15.0 - 30.0 * r as f32 / (rows - 1) as f32).to_radians();
            for c in 0..cols {
                let az = std::f32::consts::TAU * c as f32 / cols as f32;
                let i = r * cols + c;
                let ground_hr = if e < 0.0 {
                    0.2 / -e.tan()
                } else {
                    f32::INFINITY
                };
                let wall = (20..60).contains(&c);
                let hr = if wall { ground_hr.min(1.0) } else { ground_hr };
                if hr.is_finite() && hr < 60.0 {
                    img.set(i, Some([hr * az.cos(), hr * az.sin(), hr * e.tan()]));
                    truth[i] = hr == ground_hr;
                }
            }
        }
        (img, truth)
    }

    #[test]
    fn a_lone_return_above_a_low_sensor_does_not_seed_ground() {
        // The sensor 0.1 m above the ground (as OS-1-64's sample, on a
        // table); one column holds a single return 0.5 m away at +10 degrees,
        // 0.19 m above the plane: within the seed tolerance, but above the
        // sensor.
        let (rows, cols) = (16, 128);
        let mut img = RangeImage::empty(rows, cols);
        for r in rows / 2..rows {
            let e = (-2.0 - 2.0 * (r - rows / 2) as f32).to_radians();
            for c in 1..cols {
                let az = std::f32::consts::TAU * c as f32 / cols as f32;
                let hr = 0.1 / -e.tan();
                img.set(r * cols + c, Some([hr * az.cos(), hr * az.sin(), -0.1]));
            }
        }
        let e = 10f32.to_radians();
        img.set(2 * cols, Some([0.5, 0.0, 0.5 * e.tan()]));
        let g = detect_ground(&img, &GroundParams::default()).unwrap();
        let pl = g.plane.unwrap();
        assert!((pl[3] - 0.1).abs() < 0.01, "{pl:?}");
        assert!(!g.mask[2 * cols], "a return above the sensor seeded ground");
        assert!(
            g.count() > (rows / 2) * (cols - 1) * 9 / 10,
            "{}",
            g.count()
        );
    }

    #[test]
    fn a_wall_next_to_the_sensor_is_not_climbed_as_ground() {
        let (img, truth) = near_wall();
        let g = detect_ground(&img, &GroundParams::default()).unwrap();
        let climbed: Vec<(usize, usize, f32)> = (0..img.pixels())
            .filter(|&i| g.mask[i] && !truth[i])
            .filter_map(|i| img.point(i).map(|p| (i / img.cols, i % img.cols, p[2])))
            // The wall's foot, up to the slope and noise tolerance above the
            // last ground return (under 0.1 m here), may pass as ground.
            .filter(|&(_, _, z)| z > -0.2 + 0.1)
            .collect();
        assert!(
            climbed.is_empty(),
            "{} wall returns above the ground called ground, first (row, col, z) {:?}",
            climbed.len(),
            climbed.first()
        );
        let s = score_ground(&img, &g.mask, &truth).unwrap();
        assert!(s.recall > 0.99, "{s:?}");
    }

    #[test]
    fn empty_image_has_no_ground_and_bad_params_are_refused() {
        let img = RangeImage::empty(4, 4);
        let g = detect_ground(&img, &GroundParams::default()).unwrap();
        assert_eq!((g.count(), g.plane), (0, None));
        let bad = GroundParams {
            max_slope_deg: -1.0,
            ..GroundParams::default()
        };
        assert!(detect_ground(&img, &bad)
            .unwrap_err()
            .to_string()
            .contains("max_slope_deg = -1"));
        assert!("bumpy"
            .parse::<GroundMethod>()
            .unwrap_err()
            .contains("none, plane or slope"));
        assert!(score_ground(&img, &[false; 3], &[false; 16]).is_err());
    }
}
