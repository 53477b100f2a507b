//! Behaviour of generated and hand-built scenes.

use fcc_scene::{
    beam_elevations_deg, column_azimuth_rad, generate, render, street_layout, Object, ObjectKind,
    Primitive, Scene, SceneConfig, SceneError, GROUND_Z_M,
};
use std::collections::BTreeSet;

/// A configuration without noise, missing returns or dropouts.
fn clean(rows: usize, cols: usize) -> SceneConfig {
    SceneConfig {
        rows,
        cols,
        seed: 1,
        keep_ground: false,
        dropout: 0.0,
        missing: 0.0,
        range_noise_m: 0.0,
    }
}

fn seeded(seed: u64) -> SceneConfig {
    SceneConfig {
        seed,
        ..SceneConfig::default()
    }
}

/// Every `(row, col, point, id)` with a return.
fn points(s: &Scene) -> impl Iterator<Item = (usize, usize, [f64; 3], u32)> + '_ {
    (0..s.rows * s.cols).filter_map(move |i| {
        let (row, col) = (i / s.cols, i % s.cols);
        s.point(row, col)
            .map(|p| (row, col, p.map(f64::from), s.gt[i]))
    })
}

/// Columns holding at least one return of instance `id`.
fn columns_of(s: &Scene, id: u32) -> BTreeSet<usize> {
    points(s)
        .filter(|&(_, _, _, g)| g == id)
        .map(|(_, c, _, _)| c)
        .collect()
}

#[test]
fn same_seed_gives_identical_bits() {
    for seed in [0, 3, u64::MAX] {
        let a = generate(&seeded(seed)).expect("default config is valid");
        let b = generate(&seeded(seed)).expect("default config is valid");
        let bits = |s: &Scene| s.xyz.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert!(bits(&a) == bits(&b), "seed {seed}: xyz differ");
        assert_eq!(a.gt, b.gt, "seed {seed}");
        assert_eq!(a.ground, b.ground, "seed {seed}");
        assert_eq!(a.objects, b.objects, "seed {seed}");
    }
}

#[test]
fn different_seeds_give_different_scenes() {
    let a = generate(&seeded(1)).expect("valid");
    let b = generate(&seeded(2)).expect("valid");
    assert_ne!(a.gt, b.gt);
    assert_ne!(a.objects, b.objects);
    // The same street with a different pixel seed is impossible through `generate`,
    // but the noise streams differ too: compare renders of one layout.
    let objects = street_layout(5);
    let c = render(&objects, &seeded(5)).expect("valid");
    let d = render(&objects, &seeded(6)).expect("valid");
    assert!(c
        .xyz
        .iter()
        .zip(&d.xyz)
        .any(|(x, y)| x.to_bits() != y.to_bits()));
}

#[test]
fn lengths_match_rows_and_cols() {
    for (rows, cols) in [(16, 1), (16, 7), (32, 1024), (64, 2048), (128, 256)] {
        let cfg = SceneConfig {
            rows,
            cols,
            ..seeded(9)
        };
        let s = generate(&cfg).expect("valid config");
        let n = rows * cols;
        assert_eq!((s.rows, s.cols), (rows, cols));
        assert_eq!(s.xyz.len(), 3 * n, "rows={rows} cols={cols}");
        assert_eq!(s.gt.len(), n);
        assert_eq!(s.ground.len(), n);
        for (i, p) in s.xyz.chunks_exact(3).enumerate() {
            let nan = p.iter().filter(|v| v.is_nan()).count();
            assert!(nan == 0 || nan == 3, "pixel {i} partly NaN: {p:?}");
            if nan == 3 {
                assert_eq!(s.gt[i], 0, "empty pixel {i} has an id");
                assert!(!s.ground[i], "empty pixel {i} flagged ground");
            }
        }
    }
}

#[test]
fn ground_is_removed_by_default() {
    for seed in 0..4 {
        let s = generate(&seeded(seed)).expect("valid");
        assert!(s.ground.iter().all(|g| !g), "seed {seed}: ground flagged");
        for (row, col, p, id) in points(&s) {
            assert!(
                id > 0,
                "seed {seed}: unlabelled point at ({row}, {col}) {p:?}"
            );
        }
        let low = points(&s).filter(|&(_, _, p, _)| p[2] < -1.6).count();
        let low_objects = points(&s)
            .filter(|&(_, _, p, id)| p[2] < -1.6 && id > 0)
            .count();
        assert_eq!(
            low, low_objects,
            "seed {seed}: low points that are not objects"
        );
    }
}

#[test]
fn ground_is_kept_and_flagged_on_request() {
    let cfg = SceneConfig {
        keep_ground: true,
        ..seeded(2)
    };
    let s = generate(&cfg).expect("valid");
    let without = generate(&seeded(2)).expect("valid");
    let flagged = s.ground.iter().filter(|g| **g).count();
    assert!(
        flagged > s.rows * s.cols / 4,
        "only {flagged} ground returns"
    );
    assert_eq!(s.num_points(), without.num_points() + flagged);
    let tol = 6.0 * cfg.range_noise_m + 1e-3;
    for i in 0..s.rows * s.cols {
        if s.ground[i] {
            let z = f64::from(s.xyz[3 * i + 2]);
            assert_eq!(s.gt[i], 0, "ground pixel {i} has an id");
            assert!((z - GROUND_Z_M).abs() < tol, "ground pixel {i} at z = {z}");
        } else if !s.xyz[3 * i].is_nan() {
            assert!(s.gt[i] > 0, "non-ground point {i} without an id");
        }
    }
    assert_eq!(
        s.gt, without.gt,
        "ground removal must not change object pixels"
    );
}

#[test]
fn every_listed_object_has_points_and_every_id_is_listed() {
    for seed in 0..4 {
        let s = generate(&seeded(seed)).expect("valid");
        let mut counts = vec![0usize; s.objects.len() + 1];
        for &g in &s.gt {
            assert!((g as usize) < counts.len(), "seed {seed}: unlisted id {g}");
            counts[g as usize] += 1;
        }
        for (i, o) in s.objects.iter().enumerate() {
            assert_eq!(o.id as usize, i + 1, "seed {seed}: ids not dense");
            assert!(o.points > 0, "seed {seed}: object {} has no points", o.id);
            assert_eq!(
                o.points,
                counts[i + 1],
                "seed {seed}: object {} count",
                o.id
            );
        }
    }
}

#[test]
fn instance_points_lie_inside_their_bounding_box() {
    for seed in 0..4 {
        let s = generate(&seeded(seed)).expect("valid");
        for (row, col, p, id) in points(&s) {
            let o = &s.objects[id as usize - 1];
            assert!(
                o.bbox.contains(p, 0.1),
                "seed {seed}: ({row}, {col}) {p:?} of {} {id} outside {:?}",
                o.kind,
                o.bbox
            );
        }
    }
}

#[test]
fn typical_scene_has_20_to_60_objects_of_every_common_kind() {
    let mut kinds = BTreeSet::new();
    for seed in 0..12 {
        let s = generate(&seeded(seed)).expect("valid");
        let n = s.objects.len();
        assert!((20..=60).contains(&n), "seed {seed}: {n} objects");
        kinds.extend(s.objects.iter().map(|o| o.kind));
    }
    assert_eq!(kinds.len(), ObjectKind::ALL.len(), "kinds seen: {kinds:?}");
}

#[test]
fn street_layout_does_not_depend_on_resolution() {
    let layout = street_layout(4);
    assert_eq!(layout, street_layout(4));
    let ids: Vec<u32> = layout.iter().map(|o| o.id).collect();
    assert_eq!(ids, (1..=layout.len() as u32).collect::<Vec<_>>());
    // Every object generate reports at any resolution comes from that street.
    for rows in [16, 64, 128] {
        let cfg = SceneConfig {
            rows,
            cols: 1024,
            ..seeded(4)
        };
        let s = generate(&cfg).expect("valid");
        for o in &s.objects {
            assert!(
                layout.iter().any(|l| l.bbox == o.bbox && l.kind == o.kind),
                "rows={rows}: {o:?} not in the layout"
            );
        }
    }
}

/// xy distance from the sensor to where the ray of azimuth `az` enters a vertical
/// cylinder of radius `r` centred at `(cx, cy)`, if it does.
fn cylinder_entry_xy(az: f64, cx: f64, cy: f64, r: f64) -> Option<f64> {
    let (s, c) = az.sin_cos();
    let along = c * cx + s * cy;
    let across = -s * cx + c * cy;
    let disc = r * r - across * across;
    (along > 0.0 && disc > 0.0).then(|| along - disc.sqrt())
}

#[test]
fn pedestrian_ahead_is_hit_by_the_expected_pixels() {
    let (cx, cy, r, h) = (10.0, 0.0, 0.3, 1.75);
    let cfg = clean(64, 2048);
    let s = render(&[Object::pedestrian(7, cx, cy, r, h)], &cfg).expect("valid");
    // Forward is the boundary between columns 1023 and 1024; the half-angle is
    // asin(0.3 / 10) = 0.030 rad, 9.78 columns of 2 pi / 2048.
    assert_eq!(
        columns_of(&s, 7),
        (1014..=1033).collect::<BTreeSet<_>>(),
        "columns"
    );
    let elev = beam_elevations_deg(cfg.rows);
    let top = GROUND_Z_M + h;
    let mut expected = 0;
    for col in 0..cfg.cols {
        let az = column_azimuth_rad(col, cfg.cols);
        for (row, e) in elev.iter().enumerate() {
            let i = row * cfg.cols + col;
            let z = cylinder_entry_xy(az, cx, cy, r).map(|d| d * e.to_radians().tan());
            let hit = matches!(z, Some(z) if (GROUND_Z_M..=top).contains(&z));
            assert_eq!(s.gt[i] == 7, hit, "({row}, {col}) z at the side {z:?}");
            if hit {
                expected += 1;
                let p = s.point(row, col).expect("hit pixel has a point");
                let rr = (f64::from(p[0]) - cx).hypot(f64::from(p[1]) - cy);
                assert!((rr - r).abs() < 1e-4, "({row}, {col}) {rr} off the surface");
            }
        }
    }
    assert_eq!(s.objects[0].points, expected);
    assert!(expected > 100, "{expected}");
}

#[test]
fn pedestrian_left_is_hit_around_a_quarter_turn() {
    let s = render(
        &[Object::pedestrian(1, 0.0, 10.0, 0.3, 1.75)],
        &clean(64, 2048),
    )
    .expect("valid");
    // Left (+y) is the boundary between columns 511 and 512.
    assert_eq!(columns_of(&s, 1), (502..=521).collect::<BTreeSet<_>>());
}

#[test]
fn pole_behind_is_hit_across_the_column_wrap() {
    let s = render(&[Object::pole(3, -10.0, 0.0, 0.3, 5.0)], &clean(64, 2048)).expect("valid");
    let expected: BTreeSet<usize> = (0..=9).chain(2038..=2047).collect();
    assert_eq!(columns_of(&s, 3), expected);
}

#[test]
fn occluded_object_gets_no_points_and_is_dropped_by_retain_visible() {
    let objects = [
        Object::pedestrian(4, 30.0, 0.0, 0.3, 1.75),
        Object::wall(9, 20.0, 0.0, 0.0, 1.0, 30.0, 10.0),
    ];
    let mut s = render(&objects, &clean(64, 2048)).expect("valid");
    assert_eq!(s.objects[0].points, 0, "pedestrian behind the wall");
    assert!(s.objects[1].points > 0);
    let wall_pixels = s.objects[1].points;
    s.retain_visible();
    assert_eq!(s.objects.len(), 1);
    assert_eq!((s.objects[0].id, s.objects[0].kind), (1, ObjectKind::Wall));
    assert_eq!(s.gt.iter().filter(|&&g| g == 1).count(), wall_pixels);
    assert!(s.gt.iter().all(|&g| g <= 1));
}

#[test]
fn returns_beyond_max_range_are_empty() {
    let objects = [
        Object::pole(1, 115.0, 0.0, 1.0, 10.0),
        Object::pole(2, 0.0, 125.0, 1.0, 10.0),
    ];
    let s = render(&objects, &clean(64, 2048)).expect("valid");
    assert!(s.objects[0].points > 0, "pole at 115 m");
    assert_eq!(s.objects[1].points, 0, "pole at 125 m");
}

#[test]
fn composite_objects_are_one_instance() {
    // Far enough that the +2 degree top beam reaches the crown (2.25 m up).
    let objects = [
        Object::tree(1, 30.0, 5.0, 0.25, 3.0, 1.5),
        Object::cyclist(2, 6.0, -3.0, 0.0),
    ];
    let s = render(&objects, &clean(64, 2048)).expect("valid");
    let of = |id: u32| -> Vec<[f64; 3]> {
        points(&s)
            .filter(|&(_, _, _, g)| g == id)
            .map(|(_, _, p, _)| p)
            .collect()
    };
    // Trunk points lie on its surface, crown points farther from the axis.
    let axis = |p: &[f64; 3]| (p[0] - 30.0).hypot(p[1] - 5.0);
    let tree = of(1);
    assert!(tree.iter().any(|p| axis(p) < 0.26), "trunk points");
    assert!(tree.iter().any(|p| axis(p) > 0.5), "crown points");
    let cyclist = of(2);
    assert!(
        cyclist.iter().any(|p| p[2] - GROUND_Z_M < 0.85),
        "bike points"
    );
    assert!(
        cyclist.iter().any(|p| p[2] - GROUND_Z_M > 1.1),
        "rider points"
    );
}

#[test]
fn missing_one_empties_every_pixel() {
    let cfg = SceneConfig {
        missing: 1.0,
        keep_ground: true,
        ..seeded(1)
    };
    let s = generate(&cfg).expect("valid");
    assert_eq!(s.num_points(), 0);
    assert!(s.objects.is_empty());
}

#[test]
fn dropouts_are_runs_and_grow_with_probability() {
    let base = SceneConfig {
        keep_ground: true,
        dropout: 0.0,
        missing: 0.0,
        range_noise_m: 0.0,
        ..seeded(11)
    };
    let empty = |dropout: f64| -> Vec<bool> {
        let s = render(
            &[],
            &SceneConfig {
                dropout,
                ..base.clone()
            },
        )
        .expect("valid");
        s.xyz.chunks_exact(3).map(|p| p[0].is_nan()).collect()
    };
    let none = empty(0.0);
    let some = empty(0.05);
    let more = empty(0.2);
    let lost = |e: &[bool]| e.iter().zip(&none).filter(|(a, b)| **a && !**b).count();
    assert!(lost(&some) > 0);
    assert!(lost(&more) > lost(&some));
    for i in 0..none.len() {
        assert!(
            !some[i] || more[i],
            "pixel {i} dropped at 0.05 but not at 0.2"
        );
    }
    // On the lowest beam (every pixel a ground return) lost pixels come in runs of at
    // least a quarter segment: 2048 / 64 / 4 = 8 columns, unless runs merge at a wrap.
    let row = &more[63 * 2048..64 * 2048];
    assert!(row.iter().any(|&e| e));
    let mut run = 0;
    let mut runs = Vec::new();
    for &e in row.iter().chain([false].iter()) {
        if e {
            run += 1;
        } else if run > 0 {
            runs.push(run);
            run = 0;
        }
    }
    let wraps = row[0] && row[2047];
    let short = runs.iter().filter(|&&r| r < 8).count();
    assert!(short <= usize::from(wraps) * 2, "runs {runs:?}");
}

#[test]
fn range_noise_has_the_requested_spread() {
    let sigma = 0.05;
    let quiet = SceneConfig {
        keep_ground: true,
        ..clean(64, 2048)
    };
    let noisy = SceneConfig {
        range_noise_m: sigma,
        ..quiet.clone()
    };
    let a = render(&[], &quiet).expect("valid");
    let b = render(&[], &noisy).expect("valid");
    let norm = |p: &[f32]| p.iter().map(|v| f64::from(*v).powi(2)).sum::<f64>().sqrt();
    let diffs: Vec<f64> = a
        .xyz
        .chunks_exact(3)
        .zip(b.xyz.chunks_exact(3))
        .filter(|(p, _)| !p[0].is_nan())
        .map(|(p, q)| norm(q) - norm(p))
        .collect();
    assert!(diffs.len() > 100_000, "{} ground points", diffs.len());
    let n = diffs.len() as f64;
    let mean = diffs.iter().sum::<f64>() / n;
    let sd = (diffs.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / n).sqrt();
    assert!(mean.abs() < 0.002, "mean {mean}");
    assert!((sd - sigma).abs() < 0.05 * sigma, "sd {sd}");
}

#[test]
fn render_rejects_bad_objects_naming_them() {
    let cfg = clean(16, 64);
    let cases: Vec<(Vec<Object>, usize, &str)> = vec![
        (vec![Object::pedestrian(0, 5.0, 0.0, 0.3, 1.7)], 0, "id 0"),
        (
            vec![
                Object::pole(2, 5.0, 0.0, 0.1, 4.0),
                Object::pole(2, 6.0, 0.0, 0.1, 4.0),
            ],
            1,
            "earlier object",
        ),
        (vec![Object::pole(1, 5.0, 0.0, 0.0, 4.0)], 0, "radius"),
        (
            vec![Object::new(1, ObjectKind::Wall, vec![])],
            0,
            "at least one",
        ),
        (
            vec![Object::new(
                1,
                ObjectKind::Tree,
                vec![Primitive::Sphere {
                    center: fcc_scene::nalgebra::Point3::new(f64::NAN, 0.0, 0.0),
                    radius: 1.0,
                }],
            )],
            0,
            "finite",
        ),
    ];
    for (objects, bad, words) in cases {
        match render(&objects, &cfg) {
            Err(e @ SceneError::InvalidObject { index, .. }) => {
                assert_eq!(index, bad, "{e}");
                assert!(e.to_string().contains(words), "{e}");
            }
            other => panic!("expected InvalidObject for {objects:?}, got {other:?}"),
        }
    }
}

#[test]
fn generate_and_render_validate_the_config() {
    let cfg = SceneConfig {
        cols: 0,
        ..SceneConfig::default()
    };
    let err = generate(&cfg).map(|_| ()).unwrap_err();
    assert!(matches!(err, SceneError::OutOfRange { field: "cols", .. }));
    assert!(err.to_string().contains("`cols`"), "{err}");
    let cfg = SceneConfig {
        range_noise_m: 2.0,
        ..SceneConfig::default()
    };
    let err = render(&[], &cfg).map(|_| ()).unwrap_err();
    assert!(err.to_string().contains("`range_noise_m` = 2"), "{err}");
}

#[test]
fn hand_built_primitives_render_like_the_constructors() {
    let ped = Object::pedestrian(1, 6.0, -2.0, 0.3, 1.8);
    let same = Object::new(1, ObjectKind::Pedestrian, ped.parts.clone());
    let cfg = clean(32, 512);
    let a = render(&[ped], &cfg).expect("valid");
    let b = render(&[same], &cfg).expect("valid");
    assert_eq!(a.gt, b.gt);
    assert!(a.objects[0].points > 0);
}

#[test]
fn config_reads_from_json_with_defaults_and_rejects_unknown_fields() {
    let cfg: SceneConfig =
        serde_json::from_str(r#"{"rows": 32, "seed": 5, "keep_ground": true}"#).expect("parses");
    assert_eq!(
        cfg,
        SceneConfig {
            rows: 32,
            seed: 5,
            keep_ground: true,
            ..SceneConfig::default()
        }
    );
    let err = serde_json::from_str::<SceneConfig>(r#"{"row": 32}"#)
        .map(|_| ())
        .unwrap_err();
    assert!(err.to_string().contains("row"), "{err}");
}
