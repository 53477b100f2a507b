//! Ground removal on synthetic street scenes rendered with the ground left
//! in: precision and recall of the ground pixels against the scene's truth.

use fcc_lidar::ground::{detect_ground, score_ground, GroundMethod, GroundParams};
use fcc_lidar::RangeImage;
use fcc_scene::{generate, SceneConfig};

#[test]
fn ground_removal_on_synthetic_scenes() {
    let mut totals = Vec::new();
    for method in [GroundMethod::Plane, GroundMethod::Slope] {
        let (mut tp, mut fp, mut fneg) = (0, 0, 0);
        for seed in 0..4 {
            let scene = generate(&SceneConfig {
                seed,
                keep_ground: true,
                ..SceneConfig::default()
            })
            .unwrap();
            let img = RangeImage::from_xyz(scene.rows, scene.cols, scene.xyz.clone()).unwrap();
            let params = GroundParams {
                method,
                ..GroundParams::default()
            };
            let g = detect_ground(&img, &params).unwrap();
            let pl = g.plane.expect("a plane on a flat street");
            assert!(
                (pl[3] / pl[2] - 1.73).abs() < 0.05,
                "seed {seed}: plane {pl:?}"
            );
            let s = score_ground(&img, &g.mask, &scene.ground).unwrap();
            eprintln!(
                "{method} seed {seed}: precision {:.4} recall {:.4}",
                s.precision, s.recall
            );
            tp += s.true_positives;
            fp += s.false_positives;
            fneg += s.false_negatives;
        }
        let precision = tp as f64 / (tp + fp) as f64;
        let recall = tp as f64 / (tp + fneg) as f64;
        eprintln!("{method}: precision {precision:.4} recall {recall:.4} over 4 scenes");
        totals.push((method, precision, recall));
    }
    // The plane also takes the lowest few centimetres of every object; the
    // slope walk gives object feet back and loses a little ground under cars.
    let want = |m: GroundMethod| match m {
        GroundMethod::Plane => (0.95, 0.995),
        _ => (0.995, 0.98),
    };
    for (method, precision, recall) in totals {
        let (p, r) = want(method);
        assert!(
            precision > p && recall > r,
            "{method}: precision {precision:.4}, recall {recall:.4}"
        );
    }
}
