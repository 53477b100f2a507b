//! Scene objects, their solid primitives, and ray intersection.
//!
//! Every primitive is a closed solid in the sensor frame (x forward, y left, z up,
//! metres). Rays start at the sensor (the origin), so the intersection routines take a
//! unit direction only and return the range of the first entry into the solid. A solid
//! that contains the sensor is never hit.

use nalgebra::{Point3, Rotation3, Vector3};
use serde::{Deserialize, Serialize};
use std::fmt;

use crate::sensor::GROUND_Z_M;

/// What an instance is. One instance may be built from several primitives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum ObjectKind {
    /// Two stacked oriented boxes: the body and the cabin.
    Car,
    /// A vertical cylinder.
    Pedestrian,
    /// An oriented box for the bike and a cylinder for the rider.
    Cyclist,
    /// A thin tall cylinder (street light, sign post).
    Pole,
    /// A trunk cylinder and a sphere crown.
    Tree,
    /// A long box along the street side (building facade, fence).
    Wall,
}

impl ObjectKind {
    /// Every kind, in declaration order.
    pub const ALL: [ObjectKind; 6] = [
        ObjectKind::Car,
        ObjectKind::Pedestrian,
        ObjectKind::Cyclist,
        ObjectKind::Pole,
        ObjectKind::Tree,
        ObjectKind::Wall,
    ];

    /// Lower-case name, as used in reports.
    pub fn name(self) -> &'static str {
        match self {
            ObjectKind::Car => "car",
            ObjectKind::Pedestrian => "pedestrian",
            ObjectKind::Cyclist => "cyclist",
            ObjectKind::Pole => "pole",
            ObjectKind::Tree => "tree",
            ObjectKind::Wall => "wall",
        }
    }
}

impl fmt::Display for ObjectKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An oriented bounding box: a box yawed about the vertical axis, KITTI-label style.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct BoundingBox {
    /// Centre of the box in the sensor frame, metres.
    pub center: [f64; 3],
    /// Extent along the object's own x (length), y (width) and z (height), metres.
    pub size: [f64; 3],
    /// Rotation about +z from the sensor's +x to the object's +x, radians.
    pub yaw: f64,
}

impl BoundingBox {
    /// Whether `p` lies inside the box grown by `margin` metres on every side.
    pub fn contains(&self, p: [f64; 3], margin: f64) -> bool {
        let (s, c) = self.yaw.sin_cos();
        let dx = p[0] - self.center[0];
        let dy = p[1] - self.center[1];
        let local = [c * dx + s * dy, -s * dx + c * dy, p[2] - self.center[2]];
        local
            .iter()
            .zip(self.size)
            .all(|(l, sz)| l.abs() <= sz / 2.0 + margin)
    }
}

/// One solid piece of an object, in the sensor frame (metres, radians).
#[derive(Debug, Clone, PartialEq)]
pub enum Primitive {
    /// A box yawed about the vertical axis through its centre.
    Box {
        /// Centre of the box.
        center: Point3<f64>,
        /// Half of the length, width and height, along the box's own axes.
        half_extents: Vector3<f64>,
        /// Rotation about +z from the sensor's +x to the box's +x.
        yaw: f64,
    },
    /// A vertical cylinder with flat caps.
    Cylinder {
        /// Centre of the bottom cap.
        base: Point3<f64>,
        /// Radius.
        radius: f64,
        /// Height from the bottom cap to the top cap.
        height: f64,
    },
    /// A sphere.
    Sphere {
        /// Centre.
        center: Point3<f64>,
        /// Radius.
        radius: f64,
    },
}

impl Primitive {
    /// Why the primitive is not a proper solid, if it is not.
    fn problem(&self) -> Option<String> {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        match self {
            Primitive::Box {
                center,
                half_extents,
                yaw,
            } => {
                if !finite(center.coords.as_slice()) || !yaw.is_finite() {
                    Some("box centre and yaw must be finite".into())
                } else if !half_extents.iter().all(|h| h.is_finite() && *h > 0.0) {
                    Some(format!(
                        "box half extents must be finite and > 0, got {:?}",
                        half_extents.as_slice()
                    ))
                } else {
                    None
                }
            }
            Primitive::Cylinder {
                base,
                radius,
                height,
            } => {
                if !finite(base.coords.as_slice()) {
                    Some("cylinder base must be finite".into())
                } else if !(radius.is_finite() && *radius > 0.0) {
                    Some(format!(
                        "cylinder radius must be finite and > 0, got {radius}"
                    ))
                } else if !(height.is_finite() && *height > 0.0) {
                    Some(format!(
                        "cylinder height must be finite and > 0, got {height}"
                    ))
                } else {
                    None
                }
            }
            Primitive::Sphere { center, radius } => {
                if !finite(center.coords.as_slice()) {
                    Some("sphere centre must be finite".into())
                } else if !(radius.is_finite() && *radius > 0.0) {
                    Some(format!(
                        "sphere radius must be finite and > 0, got {radius}"
                    ))
                } else {
                    None
                }
            }
        }
    }

    /// Axis-aligned bounds `(min, max)` in the sensor frame.
    fn aabb(&self) -> ([f64; 3], [f64; 3]) {
        match self {
            Primitive::Box {
                center,
                half_extents: h,
                yaw,
            } => {
                let (s, c) = yaw.sin_cos();
                let ex = h.x * c.abs() + h.y * s.abs();
                let ey = h.x * s.abs() + h.y * c.abs();
                (
                    [center.x - ex, center.y - ey, center.z - h.z],
                    [center.x + ex, center.y + ey, center.z + h.z],
                )
            }
            Primitive::Cylinder {
                base,
                radius: r,
                height,
            } => (
                [base.x - r, base.y - r, base.z],
                [base.x + r, base.y + r, base.z + height],
            ),
            Primitive::Sphere { center, radius: r } => (
                [center.x - r, center.y - r, center.z - r],
                [center.x + r, center.y + r, center.z + r],
            ),
        }
    }

    /// A circle `(cx, cy, r)` containing the primitive's footprint on the xy plane.
    fn footprint_circle(&self) -> (f64, f64, f64) {
        match self {
            Primitive::Box {
                center,
                half_extents: h,
                ..
            } => (center.x, center.y, h.x.hypot(h.y)),
            Primitive::Cylinder { base, radius, .. } => (base.x, base.y, *radius),
            Primitive::Sphere { center, radius } => (center.x, center.y, *radius),
        }
    }
}

/// A scene object: one ground-truth instance made of one or more primitives.
#[derive(Debug, Clone, PartialEq)]
pub struct Object {
    /// Instance id written to [`crate::Scene::gt`]; must be non-zero and unique in a scene.
    pub id: u32,
    /// What the object is.
    pub kind: ObjectKind,
    /// Oriented box around the object, reported in [`crate::ObjectInfo`].
    pub bbox: BoundingBox,
    /// The solids that make up the object; a ray hitting any of them hits the object.
    pub parts: Vec<Primitive>,
}

/// `z` of a point `h` metres above the ground.
fn above_ground(h: f64) -> f64 {
    GROUND_Z_M + h
}

/// A yawed box standing on the ground, or lifted by `z0` metres.
fn ground_box(x: f64, y: f64, z0: f64, size: [f64; 3], yaw: f64) -> Primitive {
    Primitive::Box {
        center: Point3::new(x, y, above_ground(z0 + size[2] / 2.0)),
        half_extents: Vector3::new(size[0] / 2.0, size[1] / 2.0, size[2] / 2.0),
        yaw,
    }
}

/// A vertical cylinder whose bottom cap is `z0` metres above the ground.
fn ground_cylinder(x: f64, y: f64, z0: f64, radius: f64, height: f64) -> Primitive {
    Primitive::Cylinder {
        base: Point3::new(x, y, above_ground(z0)),
        radius,
        height,
    }
}

impl Object {
    /// An object from arbitrary parts; its bounding box is the axis-aligned box around
    /// the parts (yaw 0). An object with no parts gets a zero-size box at the origin.
    pub fn new(id: u32, kind: ObjectKind, parts: Vec<Primitive>) -> Self {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for p in &parts {
            let (a, b) = p.aabb();
            for k in 0..3 {
                lo[k] = lo[k].min(a[k]);
                hi[k] = hi[k].max(b[k]);
            }
        }
        let bbox = if parts.is_empty() {
            BoundingBox {
                center: [0.0; 3],
                size: [0.0; 3],
                yaw: 0.0,
            }
        } else {
            BoundingBox {
                center: [0, 1, 2].map(|k| (lo[k] + hi[k]) / 2.0),
                size: [0, 1, 2].map(|k| hi[k] - lo[k]),
                yaw: 0.0,
            }
        };
        Object {
            id,
            kind,
            bbox,
            parts,
        }
    }

    /// A car standing on the ground at `(x, y)`, heading `yaw`: a body box from 0.25 m
    /// above the ground to 60 % of `height`, and a narrower, shorter cabin box on top.
    pub fn car(id: u32, x: f64, y: f64, yaw: f64, length: f64, width: f64, height: f64) -> Self {
        let clearance = 0.25_f64.min(height / 4.0);
        let belt = 0.6 * height;
        let (s, c) = yaw.sin_cos();
        let back = -0.05 * length;
        let parts = vec![
            ground_box(x, y, clearance, [length, width, belt - clearance], yaw),
            ground_box(
                x + c * back,
                y + s * back,
                belt,
                [0.55 * length, 0.9 * width, height - belt],
                yaw,
            ),
        ];
        Object {
            id,
            kind: ObjectKind::Car,
            bbox: BoundingBox {
                center: [x, y, above_ground(height / 2.0)],
                size: [length, width, height],
                yaw,
            },
            parts,
        }
    }

    /// A pedestrian: a vertical cylinder standing on the ground at `(x, y)`.
    pub fn pedestrian(id: u32, x: f64, y: f64, radius: f64, height: f64) -> Self {
        Self::upright(id, ObjectKind::Pedestrian, x, y, radius, height)
    }

    /// A pole: a thin vertical cylinder standing on the ground at `(x, y)`.
    pub fn pole(id: u32, x: f64, y: f64, radius: f64, height: f64) -> Self {
        Self::upright(id, ObjectKind::Pole, x, y, radius, height)
    }

    fn upright(id: u32, kind: ObjectKind, x: f64, y: f64, radius: f64, height: f64) -> Self {
        Object {
            id,
            kind,
            bbox: BoundingBox {
                center: [x, y, above_ground(height / 2.0)],
                size: [2.0 * radius, 2.0 * radius, height],
                yaw: 0.0,
            },
            parts: vec![ground_cylinder(x, y, 0.0, radius, height)],
        }
    }

    /// A cyclist at `(x, y)` heading `yaw`: a 1.75 m x 0.45 m bike box up to 1.0 m and a
    /// rider cylinder (radius 0.25 m) from 0.9 m to 1.75 m, slightly behind the centre.
    pub fn cyclist(id: u32, x: f64, y: f64, yaw: f64) -> Self {
        let (s, c) = yaw.sin_cos();
        let back = -0.15;
        let parts = vec![
            ground_box(x, y, 0.05, [1.75, 0.45, 0.95], yaw),
            ground_cylinder(x + c * back, y + s * back, 0.9, 0.25, 0.85),
        ];
        Object {
            id,
            kind: ObjectKind::Cyclist,
            bbox: BoundingBox {
                center: [x, y, above_ground(1.75 / 2.0)],
                size: [1.75, 0.6, 1.75],
                yaw,
            },
            parts,
        }
    }

    /// A tree at `(x, y)`: a trunk cylinder `trunk_height` tall and a sphere crown whose
    /// centre sits half a crown radius above the top of the trunk.
    pub fn tree(
        id: u32,
        x: f64,
        y: f64,
        trunk_radius: f64,
        trunk_height: f64,
        crown_radius: f64,
    ) -> Self {
        let crown_z = trunk_height + 0.5 * crown_radius;
        let top = crown_z + crown_radius;
        let width = 2.0 * crown_radius.max(trunk_radius);
        Object {
            id,
            kind: ObjectKind::Tree,
            bbox: BoundingBox {
                center: [x, y, above_ground(top / 2.0)],
                size: [width, width, top],
                yaw: 0.0,
            },
            parts: vec![
                ground_cylinder(x, y, 0.0, trunk_radius, trunk_height),
                Primitive::Sphere {
                    center: Point3::new(x, y, above_ground(crown_z)),
                    radius: crown_radius,
                },
            ],
        }
    }

    /// A wall: a box `length` long along `yaw`, standing on the ground centred at `(x, y)`.
    pub fn wall(
        id: u32,
        x: f64,
        y: f64,
        yaw: f64,
        length: f64,
        thickness: f64,
        height: f64,
    ) -> Self {
        Object {
            id,
            kind: ObjectKind::Wall,
            bbox: BoundingBox {
                center: [x, y, above_ground(height / 2.0)],
                size: [length, thickness, height],
                yaw,
            },
            parts: vec![ground_box(x, y, 0.0, [length, thickness, height], yaw)],
        }
    }

    /// Why the object cannot be rendered, if it cannot.
    pub(crate) fn problem(&self) -> Option<String> {
        if self.id == 0 {
            return Some("id 0 is reserved for empty pixels and the ground".into());
        }
        if self.parts.is_empty() {
            return Some("an object needs at least one primitive".into());
        }
        self.parts.iter().find_map(Primitive::problem)
    }

    /// A circle `(cx, cy, r)` containing the object's footprint on the xy plane.
    pub(crate) fn footprint_circle(&self) -> (f64, f64, f64) {
        let circles: Vec<_> = self.parts.iter().map(Primitive::footprint_circle).collect();
        let (mut x0, mut y0) = (f64::INFINITY, f64::INFINITY);
        let (mut x1, mut y1) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        for &(x, y, r) in &circles {
            x0 = x0.min(x - r);
            y0 = y0.min(y - r);
            x1 = x1.max(x + r);
            y1 = y1.max(y + r);
        }
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        let r = circles
            .iter()
            .map(|&(x, y, r)| (x - cx).hypot(y - cy) + r)
            .fold(0.0, f64::max);
        (cx, cy, r)
    }
}

/// Rays hitting closer than this (metres) are treated as starting inside the solid.
const T_EPS: f64 = 1e-9;

/// Directions with a component smaller than this are parallel to that axis.
const DIR_EPS: f64 = 1e-12;

/// A primitive prepared for fast intersection with rays from the origin.
#[derive(Debug, Clone)]
pub(crate) enum Shape {
    Box {
        /// Rotation from the sensor frame into the box frame.
        to_local: Rotation3<f64>,
        /// The ray origin (the sensor) in the box frame.
        origin: Vector3<f64>,
        half: Vector3<f64>,
    },
    Cylinder {
        cx: f64,
        cy: f64,
        /// `cx^2 + cy^2 - r^2`.
        c: f64,
        z0: f64,
        z1: f64,
    },
    Sphere {
        center: Vector3<f64>,
        /// `|center|^2 - r^2`.
        c: f64,
    },
}

/// Intersection of two parameter intervals, returning the entry if it lies ahead.
fn entry(lo: f64, hi: f64) -> Option<f64> {
    (lo <= hi && lo > T_EPS).then_some(lo)
}

/// The parameter interval where `o + t d` lies in the slab `[-h, h]` along one axis.
fn slab(o: f64, d: f64, h: f64) -> Option<(f64, f64)> {
    if d.abs() < DIR_EPS {
        (o.abs() <= h).then_some((f64::NEG_INFINITY, f64::INFINITY))
    } else {
        let a = (-h - o) / d;
        let b = (h - o) / d;
        Some(if a <= b { (a, b) } else { (b, a) })
    }
}

impl Shape {
    pub(crate) fn new(p: &Primitive) -> Self {
        match p {
            Primitive::Box {
                center,
                half_extents,
                yaw,
            } => {
                let to_local = Rotation3::from_axis_angle(&Vector3::z_axis(), -yaw);
                Shape::Box {
                    to_local,
                    origin: to_local * -center.coords,
                    half: *half_extents,
                }
            }
            Primitive::Cylinder {
                base,
                radius,
                height,
            } => Shape::Cylinder {
                cx: base.x,
                cy: base.y,
                c: base.x * base.x + base.y * base.y - radius * radius,
                z0: base.z,
                z1: base.z + height,
            },
            Primitive::Sphere { center, radius } => Shape::Sphere {
                center: center.coords,
                c: center.coords.norm_squared() - radius * radius,
            },
        }
    }

    /// Range to the first entry of the ray from the origin along unit `d` into the solid.
    pub(crate) fn hit(&self, d: &Vector3<f64>) -> Option<f64> {
        match self {
            Shape::Box {
                to_local,
                origin,
                half,
            } => {
                // Slab method in the box frame.
                let dl = to_local * d;
                let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
                for k in 0..3 {
                    let (a, b) = slab(origin[k], dl[k], half[k])?;
                    lo = lo.max(a);
                    hi = hi.min(b);
                    if lo > hi {
                        return None;
                    }
                }
                entry(lo, hi)
            }
            Shape::Cylinder { cx, cy, c, z0, z1 } => {
                // Side: |t d_xy - c_xy|^2 = r^2, i.e. a t^2 - 2 b t + c = 0.
                let a = d.x * d.x + d.y * d.y;
                let (s0, s1) = if a < DIR_EPS * DIR_EPS {
                    if *c > 0.0 {
                        return None;
                    }
                    (f64::NEG_INFINITY, f64::INFINITY)
                } else {
                    let b = d.x * cx + d.y * cy;
                    let disc = b * b - a * c;
                    if disc < 0.0 {
                        return None;
                    }
                    let sq = disc.sqrt();
                    ((b - sq) / a, (b + sq) / a)
                };
                // Caps: z0 <= t d_z <= z1.
                let (c0, c1) = if d.z.abs() < DIR_EPS {
                    if *z0 > 0.0 || *z1 < 0.0 {
                        return None;
                    }
                    (f64::NEG_INFINITY, f64::INFINITY)
                } else {
                    let (a, b) = (z0 / d.z, z1 / d.z);
                    if a <= b {
                        (a, b)
                    } else {
                        (b, a)
                    }
                };
                entry(s0.max(c0), s1.min(c1))
            }
            Shape::Sphere { center, c } => {
                let b = d.dot(center);
                let disc = b * b - c;
                if disc < 0.0 {
                    return None;
                }
                let sq = disc.sqrt();
                entry(b - sq, b + sq)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(x: f64, y: f64, z: f64) -> Vector3<f64> {
        Vector3::new(x, y, z).normalize()
    }

    fn close(a: Option<f64>, b: f64) -> bool {
        a.is_some_and(|a| (a - b).abs() < 1e-9)
    }

    #[test]
    fn box_axis_aligned_front_face() {
        let b = Shape::new(&Primitive::Box {
            center: Point3::new(10.0, 0.0, 0.0),
            half_extents: Vector3::new(1.0, 2.0, 3.0),
            yaw: 0.0,
        });
        assert!(close(b.hit(&dir(1.0, 0.0, 0.0)), 9.0));
        assert!(b.hit(&dir(-1.0, 0.0, 0.0)).is_none(), "behind the sensor");
        assert!(b.hit(&dir(0.0, 1.0, 0.0)).is_none());
        // Just inside and just outside the y extent at the front face.
        assert!(b.hit(&dir(9.0, 1.99, 0.0)).is_some());
        assert!(b.hit(&dir(9.0, 2.01, 0.0)).is_none());
    }

    #[test]
    fn box_yawed_45_degrees_presents_its_corner() {
        // A 2 m cube yawed 45 degrees: the nearest point along +x is a vertical edge.
        let b = Shape::new(&Primitive::Box {
            center: Point3::new(10.0, 0.0, 0.0),
            half_extents: Vector3::new(1.0, 1.0, 1.0),
            yaw: std::f64::consts::FRAC_PI_4,
        });
        assert!(close(b.hit(&dir(1.0, 0.0, 0.0)), 10.0 - 2f64.sqrt()));
        // Unrotated it would be hit at y = 1.2 / 10; rotated the footprint reaches sqrt 2.
        assert!(b.hit(&dir(10.0, 1.3, 0.0)).is_some());
    }

    #[test]
    fn box_containing_the_sensor_is_not_hit() {
        let b = Shape::new(&Primitive::Box {
            center: Point3::new(0.0, 0.0, 0.0),
            half_extents: Vector3::new(1.0, 1.0, 1.0),
            yaw: 0.3,
        });
        assert!(b.hit(&dir(1.0, 0.2, 0.1)).is_none());
    }

    #[test]
    fn cylinder_side_and_caps() {
        let c = Shape::new(&Primitive::Cylinder {
            base: Point3::new(10.0, 0.0, -1.0),
            radius: 0.5,
            height: 2.0,
        });
        assert!(close(c.hit(&dir(1.0, 0.0, 0.0)), 9.5));
        assert!(c.hit(&dir(10.0, 0.51, 0.0)).is_none(), "passes beside");
        // A floating cylinder from z 0.5 to 1.5: the ray passes under the front edge and
        // enters through the bottom cap.
        let c = Shape::new(&Primitive::Cylinder {
            base: Point3::new(10.0, 0.0, 0.5),
            radius: 0.5,
            height: 1.0,
        });
        let d = dir(10.0, 0.0, 0.5);
        let t = c.hit(&d).expect("enters the bottom cap");
        assert!((t * d.z - 0.5).abs() < 1e-9, "enters at z = 0.5");
        assert!(c.hit(&dir(10.0, 0.0, 2.0)).is_none(), "passes over the top");
        assert!(c.hit(&dir(10.0, 0.0, 0.0)).is_none(), "passes under");
    }

    #[test]
    fn sphere_front_and_miss() {
        let s = Shape::new(&Primitive::Sphere {
            center: Point3::new(0.0, 5.0, 0.0),
            radius: 1.0,
        });
        assert!(close(s.hit(&dir(0.0, 1.0, 0.0)), 4.0));
        assert!(s.hit(&dir(0.0, -1.0, 0.0)).is_none());
        assert!(s.hit(&dir(1.0, 1.0, 0.0)).is_none());
    }

    #[test]
    fn bounding_box_contains_respects_yaw() {
        let b = BoundingBox {
            center: [10.0, 0.0, 0.0],
            size: [4.0, 2.0, 2.0],
            yaw: std::f64::consts::FRAC_PI_2,
        };
        assert!(b.contains([10.0, 1.9, 0.0], 0.0), "length now along y");
        assert!(!b.contains([11.9, 0.0, 0.0], 0.0), "width now along x");
        assert!(b.contains([11.9, 0.0, 0.0], 1.0));
    }

    #[test]
    fn object_footprint_circle_covers_all_parts() {
        let t = Object::tree(1, 5.0, 5.0, 0.2, 3.0, 2.0);
        let (cx, cy, r) = t.footprint_circle();
        assert!((cx - 5.0).abs() < 1e-12 && (cy - 5.0).abs() < 1e-12);
        assert!((r - 2.0).abs() < 1e-12);
        let car = Object::car(2, 0.0, 10.0, 0.0, 4.0, 2.0, 1.5);
        let (_, _, r) = car.footprint_circle();
        assert!(r >= 5f64.sqrt() - 1e-12);
    }
}
