//! End to end: real Ouster frames and a synthetic scene through ground
//! removal, clustering and the overview picture. Set `FCC_LIDAR_PICTURES`
//! to a directory to keep the pictures for a look.

use fcc_golden::MergeMode;
use fcc_lidar::ouster::{read_capture, DecodeOptions, OusterMetadata};
use fcc_lidar::picture::{render_overview, Overview};
use fcc_lidar::pipeline::{cluster_image, PipelineConfig};
use fcc_lidar::RangeImage;
use fcc_scene::{generate, SceneConfig};
use std::path::{Path, PathBuf};

fn out_dir(tmp: &tempfile::TempDir) -> PathBuf {
    std::env::var_os("FCC_LIDAR_PICTURES").map_or_else(|| tmp.path().to_path_buf(), PathBuf::from)
}

#[test]
fn ouster_frames_cluster_into_sensible_pictures() {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let tmp = tempfile::tempdir().unwrap();
    for (pcap, json) in [
        (
            "OS-2-128-U1_v2.3.0_1024x10.pcap",
            "OS-2-128-U1_v2.3.0_1024x10.json",
        ),
        (
            "OS-1-64_1024x10_fw20.pcap",
            "OS-1-64_sensor_config_reduced.json",
        ),
        (
            "OS-0-128-U1_v2.3.0_1024x10.pcap",
            "OS-0-128-U1_v2.3.0_1024x10.json",
        ),
        (
            "OS-1-32-G_v2.1.1_1024x10.pcap",
            "OS-1-32-G_v2.1.1_1024x10.json",
        ),
    ] {
        let m = OusterMetadata::from_file(&data.join(json)).unwrap();
        let frame = &read_capture(&data.join(pcap), &m, DecodeOptions::default())
            .unwrap()
            .frames[0];
        let cfg = PipelineConfig {
            min_points: 40,
            ..PipelineConfig::default()
        };
        let out = cluster_image(&frame.image, &cfg).unwrap();
        let ground_share = out.ground.count() as f64 / frame.image.valid_count() as f64;
        eprintln!(
            "{pcap}: {} points, ground {:.0} %, {} clusters ({} before min-points), plane {:?}",
            frame.image.valid_count(),
            100.0 * ground_share,
            out.clusters,
            out.clustering.clusters,
            out.ground.plane
        );
        assert!(out.ground.plane.is_some(), "{pcap}: no ground plane");
        assert!(
            out.clusters >= 3 && out.clusters < 300,
            "{pcap}: {} clusters",
            out.clusters
        );
        let pic = render_overview(&Overview {
            image: &frame.image,
            labels: &out.labels,
            ground: Some(&out.ground.mask),
            truth: None,
            title: format!("{pcap}: K=7 EXACT, {} CLUSTERS > 40 POINTS", out.clusters),
            truth_title: String::new(),
            bev_extent_m: 30.0,
        })
        .unwrap();
        pic.save_png(&out_dir(&tmp).join(pcap.replace(".pcap", ".png")))
            .unwrap();
    }
}

#[test]
fn synthetic_scene_picture_with_ground_truth() {
    let scene = generate(&SceneConfig {
        seed: 3,
        keep_ground: true,
        ..SceneConfig::default()
    })
    .unwrap();
    let img = RangeImage::from_xyz(scene.rows, scene.cols, scene.xyz.clone()).unwrap();
    let out = cluster_image(
        &img,
        &PipelineConfig {
            mode: MergeMode::Exact,
            ..PipelineConfig::default()
        },
    )
    .unwrap();
    let tmp = tempfile::tempdir().unwrap();
    let pic = render_overview(&Overview {
        image: &img,
        labels: &out.labels,
        ground: Some(&out.ground.mask),
        truth: Some(&scene.gt),
        title: format!("SYNTHETIC SEED 3: K=7 EXACT, {} CLUSTERS", out.clusters),
        truth_title: format!("GROUND TRUTH: {} INSTANCES", scene.objects.len()),
        bev_extent_m: 40.0,
    })
    .unwrap();
    assert_eq!(pic.width, 2048);
    pic.save_png(&out_dir(&tmp).join("synthetic_seed3.png"))
        .unwrap();
}
