//! The MCAP sink read back by a third-party decoder (`mcap-ros2-support`,
//! pinned in tests/requirements.txt): the schemas, the CDR of every field,
//! the stamps, the labels of the points and the boxes of the clusters. With
//! the decoder missing the test fails under `CI=true` and says it did not
//! run otherwise.

use fcc_lidar::clusters::ClusterRow;
use fcc_lidar::sinks::mcap::{McapFrame, McapSink, CLUSTERS_TOPIC, POINTS_TOPIC};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn python() -> PathBuf {
    std::env::var_os("FCC_MCAP_PYTHON")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../../.venv/bin/python"))
}

/// Why the decoder cannot run, if it cannot.
fn missing(python: &Path) -> Option<String> {
    let ok = Command::new(python)
        .args(["-c", "import mcap_ros2.decoder"])
        .output()
        .is_ok_and(|o| o.status.success());
    (!ok).then(|| {
        format!(
            "{} cannot import mcap_ros2: run ./setup.sh (or pip install -r crates/fcc-lidar/tests/requirements.txt), or set FCC_MCAP_PYTHON",
            python.display()
        )
    })
}

fn row(cluster: u32, cx: f64, yaw: f64) -> ClusterRow {
    ClusterRow {
        frame: "t_f00001".into(),
        cluster,
        points: 2,
        min_z: -0.5,
        max_z: 1.5,
        box_cx: cx,
        box_cy: -2.0,
        box_length: 3.0,
        box_width: 1.25,
        box_yaw: yaw,
        ..ClusterRow::default()
    }
}

#[test]
fn a_third_party_decoder_reads_the_points_labels_and_boxes() {
    let py = python();
    if let Some(why) = missing(&py) {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("the MCAP decoder cannot run under CI: {why}");
        }
        eprintln!("NOT RUN: {why}");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.mcap");
    let points = [[1.0f32, 2.0, 3.0], [-4.5, 0.25, 1e-3], [7.0, 8.0, -9.0]];
    let labels = [1u32, 0, 2];
    let rows = [row(1, 5.0, 0.5), row(2, -1.5, -1.0)];
    let stamps = [1_700_000_000_123_456_789u64, 1_700_000_000_223_456_789];
    let mut sink = McapSink::create(&path).unwrap();
    for (k, &stamp_ns) in stamps.iter().enumerate() {
        sink.write(&McapFrame {
            stamp_ns,
            frame_id: "lidar",
            points: &points[..2 + k],
            labels: &labels[..2 + k],
            clusters: &rows[..1 + k],
        })
        .unwrap();
    }
    sink.finish().unwrap();
    let script =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/mcap/read_with_mcap_ros2.py");
    let out = Command::new(&py).arg(&script).arg(&path).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let msgs: Vec<Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(msgs.len(), 4);
    for (k, &stamp) in stamps.iter().enumerate() {
        let (cloud, boxes) = (&msgs[2 * k], &msgs[2 * k + 1]);
        let sec_ns = serde_json::json!([stamp / 1_000_000_000, stamp % 1_000_000_000]);
        assert_eq!(cloud["topic"], POINTS_TOPIC);
        assert_eq!(cloud["schema"], "sensor_msgs/msg/PointCloud2");
        assert_eq!(cloud["log_time"], stamp);
        assert_eq!(cloud["stamp"], sec_ns);
        assert_eq!(cloud["frame_id"], "lidar");
        assert_eq!(
            cloud["fields"],
            serde_json::json!([
                ["x", 0, 7, 1],
                ["y", 4, 7, 1],
                ["z", 8, 7, 1],
                ["label", 12, 6, 1]
            ])
        );
        assert_eq!(cloud["width"], 2 + k);
        assert_eq!(cloud["labels"], serde_json::json!(labels[..2 + k]));
        for (p, q) in cloud["points"].as_array().unwrap().iter().zip(&points) {
            for d in 0..3 {
                assert_eq!(p[d].as_f64().unwrap() as f32, q[d]);
            }
        }
        assert_eq!(boxes["topic"], CLUSTERS_TOPIC);
        assert_eq!(boxes["schema"], "visualization_msgs/msg/MarkerArray");
        let m = boxes["markers"].as_array().unwrap();
        assert_eq!(m.len(), 2 + k);
        assert_eq!(
            (m[0]["action"].as_i64(), m[0]["id"].as_i64()),
            (Some(3), Some(0))
        );
        for (marker, r) in m[1..].iter().zip(&rows) {
            assert_eq!(marker["id"], r.cluster);
            assert_eq!(marker["type"], 1);
            assert_eq!(marker["action"], 0);
            assert_eq!(marker["stamp"], sec_ns);
            assert_eq!(marker["text"], r.cluster.to_string());
            assert_eq!(
                marker["position"],
                serde_json::json!([r.box_cx, r.box_cy, 0.5])
            );
            assert_eq!(marker["scale"], serde_json::json!([3.0, 1.25, 2.0]));
            let q = marker["orientation"].as_array().unwrap();
            let yaw = 2.0 * q[2].as_f64().unwrap().atan2(q[3].as_f64().unwrap());
            assert!((yaw - r.box_yaw).abs() < 1e-12, "{yaw} vs {}", r.box_yaw);
        }
    }
}

#[test]
fn labels_must_match_the_points() {
    let dir = tempfile::tempdir().unwrap();
    let mut sink = McapSink::create(&dir.path().join("bad.mcap")).unwrap();
    let err = sink
        .write(&McapFrame {
            stamp_ns: 0,
            frame_id: "lidar",
            points: &[[0.0; 3]; 2],
            labels: &[1],
            clusters: &[],
        })
        .unwrap_err()
        .to_string();
    assert!(err.contains("expected 2, got 1"), "{err}");
}
