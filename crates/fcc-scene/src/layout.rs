//! The random street: where objects go.
//!
//! Objects are placed in a street frame (u along the street, v to its left) and the
//! whole street is then turned by a small random heading into the sensor frame. The
//! sensor rides in a lane at the street-frame origin.

use rand::Rng;
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

use crate::geometry::Object;
use crate::render::{rng_for, STREAM_LAYOUT};

/// Clearance kept between the footprints of neighbouring objects, metres.
const MARGIN_M: f64 = 0.25;

/// Largest |heading| of the street relative to the sensor's +x, radians.
const MAX_HEADING_RAD: f64 = 0.15;

/// Facades and poles run this far along the street in both directions, metres.
const STREET_HALF_LENGTH_M: f64 = 85.0;

/// Placement attempts for one randomly placed object before it is skipped.
const ATTEMPTS: usize = 12;

/// An axis-aligned box in the street frame, z measured up from the ground.
#[derive(Debug, Clone, Copy)]
struct Aabb {
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Aabb {
    /// A box around a footprint rectangle `length x width` yawed by `yaw`.
    fn rect(u: f64, v: f64, yaw: f64, length: f64, width: f64, z: [f64; 2]) -> Self {
        let (s, c) = yaw.sin_cos();
        let eu = length / 2.0 * c.abs() + width / 2.0 * s.abs();
        let ev = length / 2.0 * s.abs() + width / 2.0 * c.abs();
        Aabb {
            lo: [u - eu, v - ev, z[0]],
            hi: [u + eu, v + ev, z[1]],
        }
    }

    /// A box around a footprint disc.
    fn disc(u: f64, v: f64, r: f64, z: [f64; 2]) -> Self {
        Aabb {
            lo: [u - r, v - r, z[0]],
            hi: [u + r, v + r, z[1]],
        }
    }

    /// Whether the boxes come closer than `MARGIN_M` on the ground plane while
    /// overlapping in height.
    fn near(&self, o: &Aabb) -> bool {
        (0..2).all(|k| self.lo[k] < o.hi[k] + MARGIN_M && o.lo[k] < self.hi[k] + MARGIN_M)
            && self.lo[2] < o.hi[2]
            && o.lo[2] < self.hi[2]
    }
}

/// The space the sensor's own vehicle occupies (street frame).
const EGO: Aabb = Aabb {
    lo: [-3.0, -1.3, 0.0],
    hi: [3.0, 1.3, 2.0],
};

/// One object waiting for an id, in the street frame.
#[derive(Debug, Clone, Copy)]
enum Proposal {
    Car {
        u: f64,
        v: f64,
        yaw: f64,
        length: f64,
        width: f64,
        height: f64,
    },
    Pedestrian {
        u: f64,
        v: f64,
        radius: f64,
        height: f64,
    },
    Cyclist {
        u: f64,
        v: f64,
        yaw: f64,
    },
    Pole {
        u: f64,
        v: f64,
        radius: f64,
        height: f64,
    },
    Tree {
        u: f64,
        v: f64,
        trunk_radius: f64,
        trunk_height: f64,
        crown_radius: f64,
    },
    Wall {
        u: f64,
        v: f64,
        length: f64,
        thickness: f64,
        height: f64,
    },
}

impl Proposal {
    /// Boxes that must stay clear of every other object's boxes.
    fn boxes(&self) -> Vec<Aabb> {
        match *self {
            Proposal::Car {
                u,
                v,
                yaw,
                length,
                width,
                height,
            } => vec![Aabb::rect(u, v, yaw, length, width, [0.0, height])],
            Proposal::Pedestrian {
                u,
                v,
                radius,
                height,
            }
            | Proposal::Pole {
                u,
                v,
                radius,
                height,
            } => vec![Aabb::disc(u, v, radius, [0.0, height])],
            Proposal::Cyclist { u, v, yaw } => vec![Aabb::rect(u, v, yaw, 1.75, 0.6, [0.0, 1.75])],
            Proposal::Tree {
                u,
                v,
                trunk_radius,
                trunk_height,
                crown_radius,
            } => {
                let crown_z = trunk_height + 0.5 * crown_radius;
                vec![
                    Aabb::disc(u, v, trunk_radius, [0.0, trunk_height]),
                    Aabb::disc(
                        u,
                        v,
                        crown_radius,
                        [crown_z - crown_radius, crown_z + crown_radius],
                    ),
                ]
            }
            Proposal::Wall {
                u,
                v,
                length,
                thickness,
                height,
            } => vec![Aabb::rect(u, v, 0.0, length, thickness, [0.0, height])],
        }
    }

    /// The object in the sensor frame, the street turned by `heading`.
    fn build(&self, id: u32, heading: f64) -> Object {
        let (s, c) = heading.sin_cos();
        let at = |u: f64, v: f64| (c * u - s * v, s * u + c * v);
        match *self {
            Proposal::Car {
                u,
                v,
                yaw,
                length,
                width,
                height,
            } => {
                let (x, y) = at(u, v);
                Object::car(id, x, y, yaw + heading, length, width, height)
            }
            Proposal::Pedestrian {
                u,
                v,
                radius,
                height,
            } => {
                let (x, y) = at(u, v);
                Object::pedestrian(id, x, y, radius, height)
            }
            Proposal::Cyclist { u, v, yaw } => {
                let (x, y) = at(u, v);
                Object::cyclist(id, x, y, yaw + heading)
            }
            Proposal::Pole {
                u,
                v,
                radius,
                height,
            } => {
                let (x, y) = at(u, v);
                Object::pole(id, x, y, radius, height)
            }
            Proposal::Tree {
                u,
                v,
                trunk_radius,
                trunk_height,
                crown_radius,
            } => {
                let (x, y) = at(u, v);
                Object::tree(id, x, y, trunk_radius, trunk_height, crown_radius)
            }
            Proposal::Wall {
                u,
                v,
                length,
                thickness,
                height,
            } => {
                let (x, y) = at(u, v);
                Object::wall(id, x, y, heading, length, thickness, height)
            }
        }
    }
}

/// Accepts proposals that keep clear of everything placed so far.
#[derive(Default)]
struct Placer {
    boxes: Vec<Aabb>,
    placed: Vec<Proposal>,
}

impl Placer {
    fn try_place(&mut self, p: Proposal) -> bool {
        let new = p.boxes();
        let blocked = new
            .iter()
            .any(|b| b.near(&EGO) || self.boxes.iter().any(|o| b.near(o)));
        if !blocked {
            self.boxes.extend(new);
            self.placed.push(p);
        }
        !blocked
    }

    /// Tries up to `ATTEMPTS` proposals from `propose`, keeping the first that fits.
    fn place_one(&mut self, rng: &mut ChaCha8Rng, propose: impl Fn(&mut ChaCha8Rng) -> Proposal) {
        for _ in 0..ATTEMPTS {
            if self.try_place(propose(rng)) {
                return;
            }
        }
    }
}

/// Heading along the street in either direction, with a little jitter.
fn along(rng: &mut ChaCha8Rng, jitter: f64) -> f64 {
    let base = if rng.gen_bool(0.5) { 0.0 } else { PI };
    base + rng.gen_range(-jitter..=jitter)
}

/// One street side: where the kerb is, how wide the pavement, where the facades start.
#[derive(Debug, Clone, Copy)]
struct Side {
    /// +1 for the left side (+v), -1 for the right.
    sign: f64,
    /// |v| of the kerb.
    kerb: f64,
    /// Pavement width.
    pavement: f64,
    /// |v| of the facade line.
    facade: f64,
}

impl Side {
    /// `v` at `depth` metres beyond the kerb (negative: into the road).
    fn v(&self, depth: f64) -> f64 {
        self.sign * (self.kerb + depth)
    }
}

/// The objects of the street drawn from `seed`, with ids `1..=n` in placement order,
/// in the sensor frame.
///
/// Depends on the seed only, so one seed gives the same street for every sensor
/// resolution. Objects never overlap (footprints keep 0.25 m apart unless one passes
/// above the other, like a tree crown over a car) and keep clear of the sensor's own
/// vehicle.
pub fn street_layout(seed: u64) -> Vec<Object> {
    let mut rng = rng_for(seed, STREAM_LAYOUT);
    let heading = rng.gen_range(-MAX_HEADING_RAD..=MAX_HEADING_RAD);
    let sides = [
        (1.0, rng.gen_range(4.5..11.0)),
        (-1.0, rng.gen_range(1.8..5.5)),
    ]
    .map(|(sign, kerb)| {
        let pavement = rng.gen_range(2.5..5.0);
        let facade = kerb + pavement + rng.gen_range(0.0..3.0);
        Side {
            sign,
            kerb,
            pavement,
            facade,
        }
    });
    let road = (sides[1].v(0.0), sides[0].v(0.0));
    let mut placer = Placer::default();

    // Facades: long boxes behind the pavement, with gaps for side streets and yards.
    for side in sides {
        let mut u = -STREET_HALF_LENGTH_M + rng.gen_range(-5.0..5.0);
        while u < STREET_HALF_LENGTH_M {
            let length = rng.gen_range(10.0..40.0);
            let thickness = rng.gen_range(0.4..1.0);
            let height = rng.gen_range(3.0..14.0);
            if rng.gen_bool(0.85) {
                placer.try_place(Proposal::Wall {
                    u: u + length / 2.0,
                    v: side.sign * (side.facade + thickness / 2.0),
                    length,
                    thickness,
                    height,
                });
            }
            u += length + rng.gen_range(1.5..10.0);
        }
    }

    // Poles along the kerb.
    for side in sides {
        let mut u = -STREET_HALF_LENGTH_M + rng.gen_range(0.0..10.0);
        while u < STREET_HALF_LENGTH_M {
            let radius = rng.gen_range(0.08..0.15);
            let height = rng.gen_range(4.0..6.5);
            let v = side.v(rng.gen_range(0.3..0.6));
            placer.try_place(Proposal::Pole {
                u,
                v,
                radius,
                height,
            });
            u += rng.gen_range(20.0..45.0);
        }
    }

    // Trees on the pavement.
    for side in sides {
        let mut u = -60.0 + rng.gen_range(0.0..10.0);
        while u < 60.0 {
            let trunk_radius = rng.gen_range(0.12..0.3);
            let trunk_height = rng.gen_range(2.5..4.0);
            let crown_radius = rng.gen_range(1.0..2.2);
            let v = side.v(side.pavement * rng.gen_range(0.35..0.75));
            if rng.gen_bool(0.5) {
                placer.try_place(Proposal::Tree {
                    u,
                    v,
                    trunk_radius,
                    trunk_height,
                    crown_radius,
                });
            }
            u += rng.gen_range(10.0..28.0);
        }
    }

    // Parked cars along both kerbs.
    for side in sides {
        if !rng.gen_bool(0.8) {
            continue;
        }
        let mut u = -50.0 + rng.gen_range(0.0..6.0);
        while u < 50.0 {
            let length = rng.gen_range(3.9..4.9);
            let width = rng.gen_range(1.65..1.95);
            let height = rng.gen_range(1.4..1.65);
            let yaw = along(&mut rng, 0.04);
            let v = side.v(-(width / 2.0 + rng.gen_range(0.15..0.4)));
            if rng.gen_bool(0.45) {
                placer.try_place(Proposal::Car {
                    u: u + length / 2.0,
                    v,
                    yaw,
                    length,
                    width,
                    height,
                });
            }
            u += length + rng.gen_range(0.8..6.0);
        }
    }

    // Moving cars in the lanes.
    for _ in 0..rng.gen_range(1..=6) {
        placer.place_one(&mut rng, |rng| {
            let length = rng.gen_range(3.9..4.9);
            let width = rng.gen_range(1.65..1.95);
            Proposal::Car {
                u: rng.gen_range(-60.0..60.0),
                v: rng.gen_range(road.0 + 1.2..road.1 - 1.2),
                yaw: along(rng, 0.06),
                length,
                width,
                height: rng.gen_range(1.4..1.65),
            }
        });
    }

    // Cyclists near the kerbs.
    for _ in 0..rng.gen_range(0..=3) {
        placer.place_one(&mut rng, |rng| {
            let side = sides[usize::from(rng.gen_bool(0.5))];
            Proposal::Cyclist {
                u: rng.gen_range(-45.0..45.0),
                v: side.v(-rng.gen_range(0.6..1.8)),
                yaw: along(rng, 0.12),
            }
        });
    }

    // Pedestrians, mostly on the pavements, a few crossing.
    for _ in 0..rng.gen_range(3..=10) {
        placer.place_one(&mut rng, |rng| {
            let v = if rng.gen_bool(0.15) {
                rng.gen_range(road.0..road.1)
            } else {
                let side = sides[usize::from(rng.gen_bool(0.5))];
                side.v(side.pavement * rng.gen_range(0.1..0.9))
            };
            Proposal::Pedestrian {
                u: rng.gen_range(-40.0..40.0),
                v,
                radius: rng.gen_range(0.25..0.35),
                height: rng.gen_range(1.55..1.9),
            }
        });
    }

    placer
        .placed
        .iter()
        .zip(1u32..)
        .map(|(p, id)| p.build(id, heading))
        .collect()
}
