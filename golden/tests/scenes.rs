//! The golden model on synthetic LiDAR scenes equals the reference, for every K.

use fcc_golden::{cluster, reference::reference_labels, Frame, MergeMode};
use fcc_params::FccParams;
use fcc_scene::{generate, SceneConfig};

fn scene(rows: usize, cols: usize, seed: u64, dropout: f64) -> Frame {
    let cfg = SceneConfig {
        rows,
        cols,
        seed,
        dropout,
        ..SceneConfig::default()
    };
    let s = generate(&cfg).unwrap();
    Frame::from_xyz_f32(rows, cols, &s.xyz)
}

fn first_mismatch(want: &[u32], got: &[u32], cols: usize) -> Option<String> {
    let i = want.iter().zip(got).position(|(a, b)| a != b)?;
    Some(format!(
        "row {}, col {}: expected {} != got {}",
        i / cols,
        i % cols,
        want[i],
        got[i]
    ))
}

#[test]
fn synthetic_scenes_match_the_reference_for_every_fsize() {
    for (seed, k) in [
        (1u64, 3usize),
        (2, 5),
        (3, 7),
        (4, 9),
        (5, 11),
        (6, 13),
        (7, 15),
    ] {
        let f = scene(32, 512, seed, 0.05);
        let p = FccParams {
            rows: 32,
            cols: 512,
            fsize: k,
            ..FccParams::default()
        };
        let got = cluster(&p, &f, MergeMode::Exact).unwrap();
        assert!(
            got.clusters > 3 && got.joins > 0,
            "seed {seed}: a dull scene"
        );
        let want = reference_labels(&p, &f);
        if let Some(m) = first_mismatch(&want, &got.labels, 512) {
            panic!("K = {k}, seed {seed}: {m}");
        }
    }
}

#[test]
fn full_size_scene_matches_the_reference() {
    let f = scene(64, 2048, 11, 0.02);
    let p = FccParams::default();
    let got = cluster(&p, &f, MergeMode::Exact).unwrap();
    let want = reference_labels(&p, &f);
    if let Some(m) = first_mismatch(&want, &got.labels, 2048) {
        panic!("seed 11: {m}");
    }
    assert!(!got.overflow);
}

#[test]
fn small_label_budget_overflows_on_a_scene() {
    let f = scene(64, 2048, 12, 0.02);
    let p = FccParams {
        label_bits: 8,
        ..FccParams::default()
    };
    let got = cluster(&p, &f, MergeMode::Exact).unwrap();
    assert!(got.overflow && got.unlabelled > 0 && got.provisional == 255);
    assert_eq!(got.labels, reference_labels(&p, &f));
}
