//! The quality table on a small synthetic corpus.

use fcc_golden::MergeMode;
use fcc_lidar::eval::{evaluate, synthetic_frames, EvalConfig};
use fcc_lidar::ground::{GroundMethod, GroundParams};
use fcc_lidar::pipeline::PipelineConfig;
use std::sync::atomic::{AtomicUsize, Ordering};

#[test]
fn quality_table_on_synthetic_scenes() {
    let frames = synthetic_frames(0..3, 64, 1024, true).unwrap();
    let done = AtomicUsize::new(0);
    let table = evaluate(
        &frames,
        &PipelineConfig::default(),
        &[3, 7, 11],
        &[MergeMode::Exact, MergeMode::Paper],
        &EvalConfig::default(),
        &|| {
            done.fetch_add(1, Ordering::Relaxed);
        },
    )
    .unwrap();
    eprintln!("{}", table.to_markdown());
    assert_eq!(done.load(Ordering::Relaxed), 3);
    assert_eq!(table.rows.len(), 6);
    let g = table.ground.unwrap();
    assert!(g.precision > 0.99 && g.recall > 0.98, "{g:?}");
    for r in &table.rows {
        let s = &r.scores;
        assert!(
            s.pq > 0.4 && s.pq <= 1.0,
            "K={:?} {:?}: {s:?}",
            r.fsize,
            r.mode
        );
        assert!(
            s.under_segmentation < 0.2 && s.over_segmentation < 0.3,
            "K={:?} {:?}: {s:?}",
            r.fsize,
            r.mode
        );
    }
    // The paper's merge table can only split what exact merging joins.
    for k in [3, 7, 11] {
        let row = |m| {
            table
                .rows
                .iter()
                .find(|r| r.fsize == Some(k) && r.mode == Some(m))
                .unwrap()
        };
        let (e, p) = (row(MergeMode::Exact), row(MergeMode::Paper));
        assert!(
            p.scores.clusters_per_frame >= e.scores.clusters_per_frame,
            "K={k}"
        );
    }
    let json = serde_json::to_value(&table).unwrap();
    assert_eq!(json["rows"][0]["fsize"], 3);
    assert!(json["rows"][0]["pq"].is_number());
    assert_eq!(json["rows"][1]["mode"], "paper");
}

#[test]
fn ground_left_in_glues_objects_together() {
    let frames = synthetic_frames(0..2, 64, 1024, true).unwrap();
    let base = PipelineConfig::default();
    let none = PipelineConfig {
        ground: GroundParams {
            method: GroundMethod::None,
            ..GroundParams::default()
        },
        ..PipelineConfig::default()
    };
    let run = |cfg: &PipelineConfig| {
        evaluate(
            &frames,
            cfg,
            &[7],
            &[MergeMode::Exact],
            &EvalConfig::default(),
            &|| {},
        )
        .unwrap()
    };
    let (with, without) = (run(&base), run(&none));
    eprintln!(
        "with ground removal {:?}\nwithout {:?}",
        with.rows[0].scores, without.rows[0].scores
    );
    assert!(with.rows[0].scores.pq > without.rows[0].scores.pq + 0.1);
    assert!(without.rows[0].scores.under_segmentation > 0.3);
}
