//! Deterministic synthetic LiDAR street scenes with ground-truth instances: FCC's own
//! test corpus.
//!
//! A spinning multi-beam sensor (HDL-64E-like) is ray-cast over a random street. Every
//! pixel of the range image gets the first return along its ray, the instance id of
//! what it hit, and a ground flag. Range noise, missing returns and beam dropouts make
//! the image look like a real scan. Everything is drawn from one seed.
//!
//! ```
//! use fcc_scene::{generate, SceneConfig};
//!
//! let cfg = SceneConfig { seed: 7, ..SceneConfig::default() };
//! let scene = generate(&cfg)?;
//! assert_eq!(scene.xyz.len(), 64 * 2048 * 3);
//! assert!(scene.objects.iter().all(|o| o.points > 0));
//! # Ok::<(), fcc_scene::SceneError>(())
//! ```
//!
//! # Geometry and conventions
//!
//! - **Frame.** The sensor sits at the origin, x forward, y left, z up, in metres. It is
//!   mounted [`SENSOR_HEIGHT_M`] (1.73 m) above a flat ground, so the ground plane is
//!   `z = GROUND_Z_M = -1.73`.
//! - **Rows.** Row 0 is the top beam. [`beam_elevations_deg`] gives the elevations: for
//!   64 rows an upper block from +2 down to -8.33 degrees at 1/3 degree and a lower block
//!   from -8.83 down to -24.33 degrees at 1/2 degree, like the HDL-64E; other row counts
//!   resample that profile over the same span.
//! - **Columns.** Column `c` of `cols` looks along azimuth
//!   `pi - 2*pi*(c + 0.5)/cols`, measured from +x toward +y ([`column_azimuth_rad`]).
//!   Column 0 looks backward and the azimuth decreases with the column, clockwise seen
//!   from above, as in KITTI/Velodyne scans: `cols/4` looks left, `cols/2` forward,
//!   `3*cols/4` right.
//!
//! ```text
//!                 +x (forward)   column cols/2
//!                      ^
//!                      |
//!  column cols/4  +y <-o-> -y  column 3*cols/4        o = sensor, 1.73 m above ground
//!                      |
//!                 column 0 / cols-1 (backward)
//! ```
//!
//! - **Range.** Returns nearer than [`MIN_RANGE_M`] (1 m) or farther than
//!   [`MAX_RANGE_M`] (120 m) are not reported. A ray that hits nothing, including every
//!   ray at or above the horizon that misses all objects, gives an empty pixel.
//! - **Pixels.** [`Scene::xyz`] holds `(row, col, xyz)` in row-major order as `f32`; an
//!   empty pixel is `NaN` in all three coordinates, with `gt` 0 and `ground` false.
//!   [`Scene::gt`] is the instance id (0 for empty and ground pixels).
//!   [`Scene::ground`] is true exactly where a kept ground return is.
//!
//! # Objects
//!
//! Every object is one instance made of solid primitives ([`Primitive`]: boxes yawed
//! about the vertical, vertical capped cylinders, spheres):
//!
//! | kind | shape |
//! |---|---|
//! | [`ObjectKind::Car`] | body box from 0.25 m up plus a cabin box, about 4.5 x 1.8 x 1.5 m |
//! | [`ObjectKind::Pedestrian`] | cylinder, radius about 0.3 m, about 1.75 m tall |
//! | [`ObjectKind::Cyclist`] | bike box 1.75 x 0.45 x 0.95 m plus a rider cylinder |
//! | [`ObjectKind::Pole`] | cylinder, radius 0.08 to 0.15 m, 4 to 6.5 m tall |
//! | [`ObjectKind::Tree`] | trunk cylinder plus a sphere crown |
//! | [`ObjectKind::Wall`] | a long box along the street side (building facade) |
//!
//! Rays are cast against the ground plane and every primitive (slab method in the box
//! frame, quadratic plus cap slab for cylinders, quadratic for spheres); the nearest
//! hit wins. Each column only tests the objects whose footprint circle its azimuth
//! interval can touch, nearest first, and stops once the next object cannot beat the
//! current hit.
//!
//! # What is randomised
//!
//! [`generate`] draws, from [`SceneConfig::seed`] alone, a street ([`street_layout`]):
//! its heading (within +-0.15 rad of +x), road, pavement and facade widths on each
//! side; facades with gaps; poles along the kerbs; trees on the pavements; parked cars
//! along the kerbs; moving cars in the lanes; cyclists near the kerbs; pedestrians on
//! the pavements and crossing. Objects do not overlap and keep clear of the sensor's
//! own vehicle. A scene typically has 20 to 60 visible objects. Because the street
//! depends on the seed only, the same seed gives the same street at every resolution.
//!
//! Rendering ([`render`]) then draws, from the same seed on separate random streams:
//! gaussian range noise along each ray ([`SceneConfig::range_noise_m`]); missing single
//! returns ([`SceneConfig::missing`]); and beam dropouts
//! ([`SceneConfig::dropout`]): each beam and each 1/64 of a revolution drops out, with
//! that probability, for a stretch of 1/4 to 1 segment of columns starting in the
//! segment. The noisy range is clamped to at least [`MIN_RANGE_M`].
//!
//! Generation is deterministic: the same configuration gives bit-identical scenes. All
//! randomness comes from `ChaCha8Rng::seed_from_u64(seed)` on fixed streams.

mod config;
mod geometry;
mod layout;
mod render;
mod sensor;

pub use config::{SceneConfig, SceneError, COLS_RANGE, MAX_RANGE_NOISE_M, ROWS_RANGE};
pub use geometry::{BoundingBox, Object, ObjectKind, Primitive};
pub use layout::street_layout;
pub use nalgebra;
pub use render::{render, ObjectInfo, Scene};
pub use sensor::{
    beam_elevations_deg, column_azimuth_rad, column_of_azimuth, GROUND_Z_M, MAX_RANGE_M,
    MIN_RANGE_M, SENSOR_HEIGHT_M,
};

/// Generates the scene of `cfg`: the street of [`street_layout`]`(cfg.seed)`, rendered
/// by [`render`], keeping only objects that received at least one return.
///
/// The kept objects are renumbered `1..=n` in placement order, so
/// `scene.objects[i].id == i + 1`, and every id in [`Scene::gt`] is listed.
pub fn generate(cfg: &SceneConfig) -> Result<Scene, SceneError> {
    cfg.validate()?;
    let objects = street_layout(cfg.seed);
    let mut scene = render(&objects, cfg)?;
    scene.retain_visible();
    Ok(scene)
}
