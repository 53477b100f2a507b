//! `fcc` on Velodyne captures and ROS 2 recordings, its per-cluster table,
//! labels with a class, the PLY label and intensity, and
//! `eval --rules semantickitti`: outputs read back.

use fcc_lidar::cloud::{read_ply, write_kitti_bin, PointCloud};
use fcc_lidar::labels::{pack_label, read_label_file, unpack_label};
use fcc_testkit::{assert_one_line_error, lidar_data, s, stderr, tmpdir};
use std::path::{Path, PathBuf};
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

fn fixture(dir: &str, name: &str) -> PathBuf {
    lidar_data().join(dir).join(name)
}

#[test]
fn velodyne_capture_gives_table_labels_with_class_and_ply_with_intensity() {
    let d = tmpdir("vlp16");
    let cap = fixture("velodyne", "vlp16.pcap");
    let (csv, label, ply, png) = (
        d.join("c.csv"),
        d.join("l.label"),
        d.join("p.ply"),
        d.join("p.png"),
    );
    let o = fcc(&[
        "cluster",
        "-i",
        s(&cap),
        "--clusters",
        s(&csv),
        "--label",
        s(&label),
        "--ply",
        s(&ply),
        "--png",
        s(&png),
        "--label-class",
        "30",
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("Velodyne VLP-16, 1 rotations used"),
        "{}",
        stderr(&o)
    );
    assert!(png.exists());
    // The table: the box in front (x 6..8 m) is one cluster whose face is at x = 6 m.
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), fcc_lidar::clusters::CSV_HEADER);
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    assert!(!rows.is_empty());
    let boxes: Vec<&Vec<String>> = rows
        .iter()
        .filter(|r| (r[3].parse::<f64>().unwrap() - 6.0).abs() < 0.05)
        .collect();
    assert_eq!(boxes.len(), 1, "{text}");
    let b = boxes[0];
    assert_eq!(b[0], "vlp16_f00001");
    let f = |k: usize| b[k].parse::<f64>().unwrap();
    assert!(f(6) >= 5.99 && f(9) <= 6.01, "box front face: {b:?}");
    assert!(f(7) >= -1.01 && f(10) <= 1.01 && f(12) >= 5.99, "{b:?}");
    // Labels: clustered points carry class 30 and their cluster id.
    let ply_cloud = read_ply(&ply).unwrap();
    let labels = read_label_file(&label, Some(ply_cloud.len())).unwrap();
    let box_id: u16 = b[1].parse().unwrap();
    let n_box = labels
        .iter()
        .filter(|&&l| unpack_label(l) == (30, box_id))
        .count();
    assert_eq!(n_box.to_string(), b[2]);
    assert!(labels.iter().all(|&l| {
        let (c, i) = unpack_label(l);
        (i == 0 && (c == 0 || c == 49)) || (i != 0 && c == 30)
    }));
    // PLY: a signed label and the intensity the capture carried (box 200).
    let bytes = std::fs::read(&ply).unwrap();
    let head = String::from_utf8_lossy(&bytes[..400]).into_owned();
    assert!(
        head.contains("property float intensity\nproperty int label\n"),
        "{head}"
    );
    let inten = ply_cloud.intensity.unwrap();
    for (k, &l) in labels.iter().enumerate() {
        if unpack_label(l).1 == box_id {
            assert_eq!(inten[k], 200.0, "point {k}");
        }
    }
}

#[test]
fn velodyne_json_table_and_hdl64e_calibration() {
    let d = tmpdir("hdl64e");
    let cap = fixture("velodyne", "hdl64e.pcap");
    let json = d.join("t.json");
    let o = fcc(&[
        "cluster",
        "-i",
        s(&cap),
        "--velodyne-calibration",
        s(&fixture("velodyne", "hdl64e.yaml")),
        "--clusters",
        s(&json),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows: Vec<fcc_lidar::clusters::ClusterRow> =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert!(rows
        .iter()
        .any(|r| (r.centroid_x - 6.0).abs() < 0.05 && r.max_z <= 0.51));
    // Without its calibration: one line naming the capture.
    let o = fcc(&["cluster", "-i", s(&cap)]);
    assert_one_line_error(&o, &cap, "--velodyne-calibration");
    // Junk on the Velodyne path.
    let junk = d.join("junk.pcap");
    std::fs::write(&junk, b"\xd4\xc3\xb2\xa1 and then nothing").unwrap();
    let o = fcc(&["cluster", "-i", s(&junk), "--sensor", "velodyne"]);
    assert_one_line_error(&o, &junk, "");
}

#[test]
fn mcap_recordings_cluster_and_convert() {
    let d = tmpdir("mcap");
    let rec = fixture("mcap", "organised.mcap");
    let out = d.join("img.npy");
    let o = fcc(&["convert", "-i", s(&rec), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    for k in 0..2 {
        let img = fcc_npy::read_xyz(&d.join(format!("img_organised_m{k:05}.npy"))).unwrap();
        assert_eq!((img.rows, img.cols), (16, 180));
    }
    // The unorganised recording, projected onto the same grid, gives the
    // same clustering as the organised one.
    let stats = |args: &[&str]| -> serde_json::Value {
        let o = fcc(args);
        assert!(o.status.success(), "{}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout).into_owned();
        serde_json::from_str(out.lines().next().unwrap()).unwrap()
    };
    let a = stats(&["cluster", "-i", s(&rec), "--stats"]);
    let un = fixture("mcap", "unorganised.mcap");
    let b = stats(&[
        "cluster",
        "-i",
        s(&un),
        "--topic",
        "/velodyne_points",
        "--rows",
        "16",
        "--cols",
        "180",
        "--fov-up",
        "15",
        "--fov-down",
        "-15",
        "--stats",
    ]);
    for k in ["points", "ground_points", "clusters"] {
        assert_eq!(a[k], b[k], "{k}: {a} vs {b}");
    }
    let o = fcc(&["cluster", "-i", s(&un)]);
    assert_one_line_error(&o, &un, "choose one with --topic");
    let junk = d.join("junk.mcap");
    std::fs::write(&junk, b"nothing here").unwrap();
    let o = fcc(&["cluster", "-i", s(&junk)]);
    assert_one_line_error(&o, &junk, "not a MCAP file");
}

/// A scan of two boxes on a road, labelled as SemanticKITTI would: cars
/// 10 with instances 1 and 2, road 40.
fn write_scan(d: &Path) -> (PathBuf, PathBuf) {
    let mut points = Vec::new();
    let mut labels = Vec::new();
    for r in 0..64 {
        let elev = (3.0 - 28.0 * f64::from(r) / 63.0).to_radians();
        for c in 0..2048 {
            let az = -std::f64::consts::PI + (f64::from(c) + 0.5) * std::f64::consts::TAU / 2048.0;
            let dir = [elev.cos() * az.cos(), elev.cos() * az.sin(), elev.sin()];
            // Cars: boxes 4 x 2 x 1.5 m at (10, 0) and (-12, 5), sensor 1.7 m up.
            let mut hit: Option<(f64, u32)> = None;
            for (k, (cx, cy)) in [(10.0, 0.0), (-12.0, 5.0)].into_iter().enumerate() {
                let (lo, hi) = ([cx - 2.0, cy - 1.0, -1.7], [cx + 2.0, cy + 1.0, -0.2]);
                let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
                for a in 0..3 {
                    if dir[a].abs() < 1e-12 {
                        if !(lo[a]..=hi[a]).contains(&0.0) {
                            t0 = f64::INFINITY;
                        }
                        continue;
                    }
                    let (p, q) = (lo[a] / dir[a], hi[a] / dir[a]);
                    t0 = t0.max(p.min(q));
                    t1 = t1.min(p.max(q));
                }
                if t0 <= t1 && hit.is_none_or(|h| t0 < h.0) {
                    hit = Some((t0, pack_label(10, k as u16 + 1)));
                }
            }
            if hit.is_none() && dir[2] < 0.0 {
                let t = -1.7 / dir[2];
                if t < 60.0 {
                    hit = Some((t, pack_label(40, 0)));
                }
            }
            if let Some((t, l)) = hit {
                points.push([
                    (t * dir[0]) as f32,
                    (t * dir[1]) as f32,
                    (t * dir[2]) as f32,
                ]);
                labels.push(l);
            }
        }
    }
    let bin = d.join("000000.bin");
    let label = d.join("000000.label");
    write_kitti_bin(
        &bin,
        &PointCloud {
            points,
            intensity: None,
        },
    )
    .unwrap();
    let bytes: Vec<u8> = labels.iter().flat_map(|l| l.to_le_bytes()).collect();
    std::fs::write(&label, bytes).unwrap();
    (bin, label)
}

#[test]
fn eval_semantickitti_rules_count_stuff_and_every_class() {
    let d = tmpdir("sk");
    let (bin, label) = write_scan(&d);
    let json = d.join("t.json");
    let o = fcc(&[
        "eval",
        "--rules",
        "semantickitti",
        "--input",
        s(&bin),
        "--truth",
        s(&label),
        "--fsizes",
        "7",
        "--modes",
        "exact",
        "--json",
        s(&json),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(
        out.contains("| car PQ | car TP | car FP | car FN |"),
        "{out}"
    );
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let row = &t["rows"][0];
    let c = &row["counts"];
    // Both cars found (class 1 = car); the road (class 9) is predicted as
    // other-ground (class 12, fcc's ground class): one FN and one FP.
    assert_eq!(
        (c["tp"][1].as_u64(), c["fn"][1].as_u64()),
        (Some(2), Some(0)),
        "{out}"
    );
    assert_eq!(
        (c["fn"][9].as_u64(), c["fp"][12].as_u64()),
        (Some(1), Some(1)),
        "{out}"
    );
    // PQ is the mean over the 19 classes: only car scores.
    let car_pq =
        c["iou_sum"][1].as_f64().unwrap() / 2.0 * 2.0 / (2.0 + 0.5 * c["fp"][1].as_f64().unwrap());
    assert!(
        (row["pq"].as_f64().unwrap() - car_pq / 19.0).abs() < 1e-12,
        "{row}"
    );
    assert_eq!(t["min_instance_points"], 50);
    // fcc's rules on the same scan: class-agnostic, the road void.
    let o = fcc(&[
        "eval",
        "--input",
        s(&bin),
        "--truth",
        s(&label),
        "--fsizes",
        "7",
        "--modes",
        "exact",
        "--json",
        s(&json),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let c = &t["rows"][0]["counts"];
    assert_eq!(
        (c["true_positives"].as_u64(), c["false_negatives"].as_u64()),
        (Some(2), Some(0)),
        "{t}"
    );
    // semantickitti rules need .label ground truth.
    let npy = d.join("x.npy");
    fcc_npy::write_xyz_f32(&npy, 2, 2, &[1.0; 12]).unwrap();
    let o = fcc(&[
        "eval",
        "--rules",
        "semantickitti",
        "--input",
        s(&npy),
        "--truth",
        s(&npy),
    ]);
    assert_one_line_error(&o, &npy, "--rules semantickitti scores point clouds");
}

#[test]
fn eval_takes_npy_range_images_with_npy_truth() {
    let d = tmpdir("npy");
    let (scene, gt) = (d.join("scene.npy"), d.join("gt.npy"));
    let o = fcc(&["scene", "--seed", "4", "-o", s(&scene), "--gt", s(&gt)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let json = d.join("t.json");
    let o = fcc(&[
        "eval",
        "--input",
        s(&scene),
        "--truth",
        s(&gt),
        "--fsizes",
        "7",
        "--modes",
        "exact",
        "--min-points",
        "40",
        "--json",
        s(&json),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    // Prepared range images: no ground removal, and a good score on a synthetic scene.
    assert_eq!(t["ground_method"], "none");
    assert!(t["rows"][0]["pq"].as_f64().unwrap() > 0.6, "{t}");
}

#[test]
fn hdl64e_beam_table_leaves_no_empty_rows() {
    let d = tmpdir("beams");
    // A scan at the HDL-64E's nominal elevations, each laser off by up to
    // 0.1 degree as a unit's calibration is.
    let table = fcc_lidar::velodyne::beam_table("hdl64e").unwrap();
    let mut points = Vec::new();
    for (k, e) in table.iter().enumerate() {
        let e = (e + 0.1 * ((k * 7 % 5) as f64 - 2.0) / 2.0).to_radians();
        for c in 0..2000 {
            let az = f64::from(c) / 2000.0 * std::f64::consts::TAU;
            let r = 20.0;
            points.push([
                (r * e.cos() * az.cos()) as f32,
                (r * e.cos() * az.sin()) as f32,
                (r * e.sin()) as f32,
            ]);
        }
    }
    let bin = d.join("scan.bin");
    write_kitti_bin(
        &bin,
        &PointCloud {
            points,
            intensity: None,
        },
    )
    .unwrap();
    let empty_rows = |extra: &[&str]| -> usize {
        let out = d.join("img.npy");
        let mut args = vec!["convert", "-i", s(&bin), "-o", s(&out)];
        args.extend_from_slice(extra);
        let o = fcc(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let img = fcc_npy::read_xyz(&out).unwrap();
        (0..img.rows)
            .filter(|&r| (0..img.cols).all(|c| !img.xyz[3 * (r * img.cols + c)].is_finite()))
            .count()
    };
    assert_eq!(empty_rows(&["--beams", "hdl64e"]), 0);
    assert!(
        empty_rows(&[]) > 0,
        "the uniform field of view leaves empty rows"
    );
}
