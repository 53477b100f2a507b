//! Ray casting a list of objects into a range image.

use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;
use serde::{Deserialize, Serialize};
use std::collections::{HashMap, HashSet};
use std::f64::consts::TAU;

use crate::config::{SceneConfig, SceneError};
use crate::geometry::{BoundingBox, Object, ObjectKind, Shape};
use crate::sensor::{
    beam_elevations_deg, column_azimuth_rad, GROUND_Z_M, MAX_RANGE_M, MIN_RANGE_M,
};

/// ChaCha stream for the street layout.
pub(crate) const STREAM_LAYOUT: u64 = 0;
/// ChaCha stream for beam dropouts.
const STREAM_DROPOUT: u64 = 1;
/// ChaCha stream for per-return noise and missing returns.
const STREAM_PIXEL: u64 = 2;

/// Beam dropout segments per revolution.
const DROPOUT_SEGMENTS: usize = 64;

/// A random generator for one purpose, derived from the scene seed.
pub(crate) fn rng_for(seed: u64, stream: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(stream);
    rng
}

/// What a rendered scene reports about one instance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ObjectInfo {
    /// Instance id, as written to [`Scene::gt`].
    pub id: u32,
    /// What the object is.
    pub kind: ObjectKind,
    /// Oriented box around the whole object.
    pub bbox: BoundingBox,
    /// Number of pixels holding a return from this object.
    pub points: usize,
}

/// A rendered range image with per-pixel ground truth.
///
/// Pixel `(row, col)` is at index `row * cols + col`; row 0 is the top beam and the
/// column convention is that of [`column_azimuth_rad`].
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Beams.
    pub rows: usize,
    /// Azimuth columns.
    pub cols: usize,
    /// `rows * cols * 3` coordinates in metres in the sensor frame, `(row, col, xyz)`
    /// order; all three are `f32::NAN` for an empty pixel.
    pub xyz: Vec<f32>,
    /// `rows * cols` instance ids; 0 for an empty pixel or a ground return.
    pub gt: Vec<u32>,
    /// `rows * cols` flags, true where the pixel holds a ground return. Always false
    /// when ground returns are not kept.
    pub ground: Vec<bool>,
    /// The instances: in the order given to [`render`], in id order from [`crate::generate`].
    pub objects: Vec<ObjectInfo>,
}

impl Scene {
    /// Index of pixel `(row, col)` in [`Scene::gt`] and [`Scene::ground`].
    pub fn index(&self, row: usize, col: usize) -> usize {
        row * self.cols + col
    }

    /// The point at `(row, col)`, or `None` for an empty pixel or out-of-range indices.
    pub fn point(&self, row: usize, col: usize) -> Option<[f32; 3]> {
        if row >= self.rows || col >= self.cols {
            return None;
        }
        let i = 3 * self.index(row, col);
        let p = [self.xyz[i], self.xyz[i + 1], self.xyz[i + 2]];
        (!p[0].is_nan()).then_some(p)
    }

    /// Number of non-empty pixels.
    pub fn num_points(&self) -> usize {
        self.xyz.chunks_exact(3).filter(|p| !p[0].is_nan()).count()
    }

    /// Drops objects without a single return and renumbers the rest `1..=n` in their
    /// current order, rewriting [`Scene::gt`] to match.
    pub fn retain_visible(&mut self) {
        self.objects.retain(|o| o.points > 0);
        let mut map = HashMap::with_capacity(self.objects.len());
        for (new, o) in (1u32..).zip(self.objects.iter_mut()) {
            map.insert(o.id, new);
            o.id = new;
        }
        for g in self.gt.iter_mut().filter(|g| **g != 0) {
            *g = map.get(g).copied().unwrap_or(0);
        }
    }
}

/// An object ready for ray casting.
struct Compiled {
    shapes: Vec<Shape>,
    /// Lower bound on the range of any hit: footprint distance minus radius.
    near: f64,
    /// Position in the caller's slice.
    index: usize,
}

/// Per column, the indices of the objects whose footprint the column's azimuth
/// interval may touch, nearest first.
fn cull_by_column(objects: &[Object], cols: usize) -> (Vec<Compiled>, Vec<Vec<u32>>) {
    let mut order: Vec<(f64, usize, (f64, f64, f64))> = objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let (cx, cy, r) = o.footprint_circle();
            ((cx.hypot(cy) - r).max(0.0), i, (cx, cy, r))
        })
        .collect();
    order.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));

    let mut columns = vec![Vec::new(); cols];
    let mut compiled = Vec::with_capacity(objects.len());
    let per_rad = cols as f64 / TAU;
    for (k, &(near, i, (cx, cy, r))) in order.iter().enumerate() {
        compiled.push(Compiled {
            shapes: objects[i].parts.iter().map(Shape::new).collect(),
            near,
            index: i,
        });
        let k = k as u32;
        let d = cx.hypot(cy);
        if d <= r * 1.0001 + 1e-9 {
            columns.iter_mut().for_each(|c| c.push(k));
            continue;
        }
        // Columns whose azimuth lies in [az - half, az + half], plus one of slack on
        // each side; the column index grows as the azimuth falls.
        let az = cy.atan2(cx);
        let half = (r / d).asin();
        let first = ((std::f64::consts::PI - (az + half)) * per_rad - 0.5).floor() as i64 - 1;
        let last = ((std::f64::consts::PI - (az - half)) * per_rad - 0.5).ceil() as i64 + 1;
        if last - first + 1 >= cols as i64 {
            columns.iter_mut().for_each(|c| c.push(k));
        } else {
            for c in first..=last {
                columns[c.rem_euclid(cols as i64) as usize].push(k);
            }
        }
    }
    (compiled, columns)
}

/// Which pixels lose their return to a beam dropout.
fn dropout_mask(cfg: &SceneConfig) -> Vec<bool> {
    let mut rng = rng_for(cfg.seed, STREAM_DROPOUT);
    let mut mask = vec![false; cfg.pixels()];
    let seg = (cfg.cols / DROPOUT_SEGMENTS).max(1);
    let shortest = (seg / 4).max(1);
    for row in 0..cfg.rows {
        for s in 0..cfg.cols.div_ceil(seg) {
            // Always draw all three so the stream does not depend on the probability:
            // raising `dropout` only adds dropouts.
            let u: f64 = rng.gen();
            let start = s * seg + rng.gen_range(0..seg);
            let len = rng.gen_range(shortest..=seg);
            if u < cfg.dropout {
                for c in start..start + len {
                    mask[row * cfg.cols + c % cfg.cols] = true;
                }
            }
        }
    }
    mask
}

/// What a ray hit first.
#[derive(Clone, Copy, PartialEq)]
enum Hit {
    Nothing,
    Ground,
    Object(usize),
}

/// Ray-casts `objects` with the sensor of `cfg`, then applies range noise, missing
/// returns and beam dropouts drawn from `cfg.seed`.
///
/// Objects keep their ids; `Scene::objects` lists all of them in the given order,
/// including any that received no return. Ids must be non-zero and unique, and every
/// object needs at least one finite, non-degenerate primitive.
pub fn render(objects: &[Object], cfg: &SceneConfig) -> Result<Scene, SceneError> {
    cfg.validate()?;
    let mut seen = HashSet::with_capacity(objects.len());
    for (index, o) in objects.iter().enumerate() {
        let reason = o.problem().or_else(|| {
            (!seen.insert(o.id)).then(|| format!("id {} is used by an earlier object", o.id))
        });
        if let Some(reason) = reason {
            return Err(SceneError::InvalidObject {
                index,
                id: o.id,
                reason,
            });
        }
    }

    let (rows, cols) = (cfg.rows, cfg.cols);
    let (compiled, columns) = cull_by_column(objects, cols);
    let elev: Vec<(f64, f64)> = beam_elevations_deg(rows)
        .into_iter()
        .map(|e| e.to_radians().sin_cos())
        .collect();
    let azim: Vec<(f64, f64)> = (0..cols)
        .map(|c| column_azimuth_rad(c, cols).sin_cos())
        .collect();
    let dropped = dropout_mask(cfg);
    let mut rng = rng_for(cfg.seed, STREAM_PIXEL);

    let n = rows * cols;
    let mut xyz = vec![f32::NAN; 3 * n];
    let mut gt = vec![0u32; n];
    let mut ground = vec![false; n];
    let mut points = vec![0usize; objects.len()];

    for (row, &(se, ce)) in elev.iter().enumerate() {
        for (col, &(sa, ca)) in azim.iter().enumerate() {
            let i = row * cols + col;
            // Drawn for every pixel so each pixel's noise is fixed by the seed alone.
            let noise: f64 = rng.sample(StandardNormal);
            let u_missing: f64 = rng.gen();

            let d = Vector3::new(ce * ca, ce * sa, se);
            let mut best = MAX_RANGE_M;
            let mut hit = Hit::Nothing;
            if se < 0.0 {
                let t = GROUND_Z_M / se;
                if t <= best {
                    best = t;
                    hit = Hit::Ground;
                }
            }
            for &k in &columns[col] {
                let obj = &compiled[k as usize];
                if obj.near >= best {
                    break;
                }
                for shape in &obj.shapes {
                    if let Some(t) = shape.hit(&d) {
                        if t < best {
                            best = t;
                            hit = Hit::Object(obj.index);
                        }
                    }
                }
            }

            let keep = match hit {
                Hit::Nothing => false,
                Hit::Ground => cfg.keep_ground,
                Hit::Object(_) => true,
            };
            if !keep || best < MIN_RANGE_M || dropped[i] || u_missing < cfg.missing {
                continue;
            }
            let range = (best + cfg.range_noise_m * noise).max(MIN_RANGE_M);
            let p = d * range;
            xyz[3 * i] = p.x as f32;
            xyz[3 * i + 1] = p.y as f32;
            xyz[3 * i + 2] = p.z as f32;
            match hit {
                Hit::Object(o) => {
                    gt[i] = objects[o].id;
                    points[o] += 1;
                }
                _ => ground[i] = true,
            }
        }
    }

    let objects = objects
        .iter()
        .zip(points)
        .map(|(o, points)| ObjectInfo {
            id: o.id,
            kind: o.kind,
            bbox: o.bbox,
            points,
        })
        .collect();
    Ok(Scene {
        rows,
        cols,
        xyz,
        gt,
        ground,
        objects,
    })
}
