//! Point-cloud readers on generated files, good and broken, and the
//! projection round trip from points to pixels and back.

use fcc_lidar::cloud::{
    read_kitti_bin, read_pcd, read_ply, read_point_cloud, write_kitti_bin, write_ply, PlyFormat,
    PointCloud,
};
use fcc_lidar::projection::{project, BackProjection, ProjectionConfig, VerticalLayout};
use std::path::{Path, PathBuf};

fn sample() -> PointCloud {
    let points: Vec<[f32; 3]> = (0..50)
        .map(|i| [i as f32 * 0.5, -(i as f32), 1.0 + i as f32 * 0.01])
        .collect();
    let intensity = (0..50).map(|i| i as f32 / 50.0).collect();
    PointCloud {
        points,
        intensity: Some(intensity),
    }
}

fn tmp(dir: &tempfile::TempDir, name: &str) -> PathBuf {
    dir.path().join(name)
}

fn err_of(r: fcc_lidar::Result<PointCloud>) -> String {
    r.unwrap_err().to_string()
}

#[test]
fn kitti_bin_round_trip_and_bad_length() {
    let dir = tempfile::tempdir().unwrap();
    let p = tmp(&dir, "000000.bin");
    write_kitti_bin(&p, &sample()).unwrap();
    assert_eq!(read_point_cloud(&p).unwrap(), sample());
    let mut bytes = std::fs::read(&p).unwrap();
    bytes.truncate(bytes.len() - 3);
    std::fs::write(&p, &bytes).unwrap();
    let e = err_of(read_kitti_bin(&p));
    assert!(
        e.contains("000000.bin") && e.contains("not a whole number of 16-byte points"),
        "{e}"
    );
    let e = err_of(read_kitti_bin(Path::new("missing/000001.bin")));
    assert!(e.contains("missing/000001.bin"), "{e}");
}

fn pcd_header(fields: &str, size: &str, ty: &str, count: &str, n: usize, data: &str) -> String {
    format!(
        "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS {fields}\nSIZE {size}\nTYPE {ty}\nCOUNT {count}\nWIDTH {n}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {n}\nDATA {data}\n"
    )
}

#[test]
fn pcd_ascii_binary_and_compressed() {
    let dir = tempfile::tempdir().unwrap();
    let s = sample();
    // ASCII with an extra field before x, and intensity.
    let mut text = pcd_header(
        "rgb x y z intensity",
        "4 4 4 4 4",
        "U F F F F",
        "1 1 1 1 1",
        50,
        "ascii",
    );
    for (p, i) in s.points.iter().zip(s.intensity.as_ref().unwrap()) {
        text.push_str(&format!("7 {} {} {} {}\n", p[0], p[1], p[2], i));
    }
    let a = tmp(&dir, "a.pcd");
    std::fs::write(&a, text).unwrap();
    assert_eq!(read_pcd(&a).unwrap(), s);
    // Binary, double precision, no intensity.
    let mut bin = pcd_header("x y z", "8 8 8", "F F F", "1 1 1", 50, "binary").into_bytes();
    for p in &s.points {
        for v in p {
            bin.extend_from_slice(&f64::from(*v).to_le_bytes());
        }
    }
    let b = tmp(&dir, "b.pcd");
    std::fs::write(&b, &bin).unwrap();
    let got = read_pcd(&b).unwrap();
    assert_eq!(got.points, s.points);
    assert!(got.intensity.is_none());
    // binary_compressed, written by the PCD crate itself.
    let c = tmp(&dir, "c.pcd");
    let schema = pcd_rs::Schema::from_iter([
        ("x", pcd_rs::ValueKind::F32, 1),
        ("y", pcd_rs::ValueKind::F32, 1),
        ("z", pcd_rs::ValueKind::F32, 1),
    ]);
    let mut w: pcd_rs::DynWriter<_> = pcd_rs::WriterInit {
        width: 50,
        height: 1,
        viewpoint: Default::default(),
        data_kind: pcd_rs::DataKind::BinaryCompressed,
        schema: Some(schema),
        version: None,
    }
    .create(&c)
    .unwrap();
    for p in &s.points {
        w.push(&pcd_rs::DynRecord(vec![
            pcd_rs::Field::F32(vec![p[0]]),
            pcd_rs::Field::F32(vec![p[1]]),
            pcd_rs::Field::F32(vec![p[2]]),
        ]))
        .unwrap();
    }
    w.finish().unwrap();
    assert_eq!(read_point_cloud(&c).unwrap().points, s.points);
}

#[test]
fn broken_pcd_files_name_file_and_problem() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("garbage.pcd", b"\x00\x01\x02 hello".to_vec(), "garbage.pcd"),
        (
            "noz.pcd",
            (pcd_header("x y", "4 4", "F F", "1 1", 1, "ascii") + "1 2\n").into_bytes(),
            "fields x, y and z are required",
        ),
        (
            "short.pcd",
            {
                let mut b =
                    pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 1000, "binary").into_bytes();
                b.extend_from_slice(&[0u8; 120]);
                b
            },
            "1000 points of 12 bytes need more than the 120 bytes",
        ),
        (
            "text.pcd",
            (pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 2, "ascii") + "1 2 3\n1 two 3\n")
                .into_bytes(),
            "text.pcd",
        ),
        (
            "fewer.pcd",
            (pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 3, "ascii") + "1 2 3\n4 5 6\n")
                .into_bytes(),
            "fewer.pcd",
        ),
        (
            "huge.pcd",
            {
                let mut b = pcd_header("x y z", "4 4 4", "F F F", "1 1 1", 10, "binary_compressed")
                    .into_bytes();
                b.extend_from_slice(&u32::MAX.to_le_bytes());
                b.extend_from_slice(&120u32.to_le_bytes());
                b
            },
            "compressed block claims",
        ),
    ];
    for (name, bytes, want) in cases {
        let p = tmp(&dir, name);
        std::fs::write(&p, bytes).unwrap();
        let e = err_of(read_pcd(&p));
        eprintln!("{e}");
        assert!(e.contains(name) && e.contains(want), "{name}: {e}");
    }
}

#[test]
fn ply_round_trips_in_every_encoding() {
    let dir = tempfile::tempdir().unwrap();
    let s = sample();
    let colours: Vec<[u8; 3]> = (0..50).map(|i| [i as u8, 2, 3]).collect();
    let labels: Vec<u32> = (0..50).collect();
    for f in [
        PlyFormat::Ascii,
        PlyFormat::BinaryLittleEndian,
        PlyFormat::BinaryBigEndian,
    ] {
        let p = tmp(&dir, "cloud.ply");
        write_ply(&p, &s.points, Some(&colours), Some(&labels), f).unwrap();
        let got = read_ply(&p).unwrap();
        assert_eq!(got.points, s.points, "{f:?}");
        assert!(got.intensity.is_none());
    }
}

#[test]
fn ply_with_faces_lists_and_intensity() {
    let dir = tempfile::tempdir().unwrap();
    let header = "ply\nformat binary_little_endian 1.0\ncomment made by hand\nelement camera 1\nproperty list uchar int ids\nelement vertex 2\nproperty double z\nproperty float x\nproperty float y\nproperty uchar intensity\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    let mut b = header.as_bytes().to_vec();
    b.push(2);
    b.extend_from_slice(&5i32.to_le_bytes());
    b.extend_from_slice(&6i32.to_le_bytes());
    for (z, x, y, i) in [(3.0f64, 1.0f32, 2.0f32, 200u8), (-1.0, 4.0, 5.0, 10)] {
        b.extend_from_slice(&z.to_le_bytes());
        b.extend_from_slice(&x.to_le_bytes());
        b.extend_from_slice(&y.to_le_bytes());
        b.push(i);
    }
    b.push(3);
    for k in 0..3i32 {
        b.extend_from_slice(&k.to_le_bytes());
    }
    let p = tmp(&dir, "hand.ply");
    std::fs::write(&p, b).unwrap();
    let got = read_ply(&p).unwrap();
    assert_eq!(got.points, vec![[1.0, 2.0, 3.0], [4.0, 5.0, -1.0]]);
    assert_eq!(got.intensity, Some(vec![200.0, 10.0]));
}

#[test]
fn broken_ply_files_name_file_and_problem() {
    let dir = tempfile::tempdir().unwrap();
    let head = |fmt: &str, n: usize| {
        format!("ply\nformat {fmt} 1.0\nelement vertex {n}\nproperty float x\nproperty float y\nproperty float z\nend_header\n")
    };
    let cases: Vec<(&str, Vec<u8>, &str)> = vec![
        ("notply.ply", b"solid cube\n".to_vec(), "not a PLY file: the first line is not `ply`"),
        ("noend.ply", b"ply\nformat ascii 1.0\nelement vertex 1\n".to_vec(), "no end_header"),
        ("fmt.ply", head("binary_middle_endian", 1).into_bytes(), "unknown format `binary_middle_endian`"),
        (
            "noz.ply",
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n".to_vec(),
            "needs properties x, y and z",
        ),
        ("count.ply", b"ply\nformat ascii 1.0\nelement vertex many\nend_header\n".to_vec(), "count `many`"),
        ("cut.ply", [head("binary_little_endian", 100).as_bytes(), &[0u8; 20]].concat(), "100 vertices cannot fit"),
        ("word.ply", (head("ascii", 2) + "1 2 3\n4 five 6\n").into_bytes(), "element `vertex` 1, property `y`"),
        ("type.ply", b"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n".to_vec(), "unknown type"),
    ];
    for (name, bytes, want) in cases {
        let p = tmp(&dir, name);
        std::fs::write(&p, bytes).unwrap();
        let e = err_of(read_ply(&p));
        eprintln!("{e}");
        assert!(e.contains(name) && e.contains(want), "{name}: {e}");
    }
    // A binary vertex list cut inside the last vertex.
    let p = tmp(&dir, "tail.ply");
    let mut b = head("binary_little_endian", 2).into_bytes();
    b.extend_from_slice(&[0u8; 12 + 8]);
    // 20 bytes hold 1.67 vertices: enough for the size check of 2 x 12? No: 24 > 20.
    std::fs::write(&p, &b).unwrap();
    assert!(err_of(read_ply(&p)).contains("2 vertices cannot fit"));
}

/// A scan from a 64-beam sensor, written as KITTI .bin, projected with its
/// beam table and back: every point keeps its pixel's label, and points
/// that lost their pixel (two returns per direction) take their
/// neighbour's.
#[test]
fn projection_round_trip_through_a_kitti_file() {
    let beams: Vec<f64> = (0..64).map(|k| 2.0 - 27.0 * k as f64 / 63.0).collect();
    let cfg = ProjectionConfig {
        rows: 64,
        cols: 512,
        layout: VerticalLayout::Beams(beams.clone()),
    };
    let mut points = Vec::new();
    let mut truth = Vec::new();
    for (k, e) in beams.iter().enumerate() {
        for c in 0..512 {
            let yaw = std::f64::consts::PI * (1.0 - (c as f64 + 0.5) / 256.0);
            // A box ahead of the sensor at 8 m, a wall at 20 m elsewhere.
            let (r, label) = if (200..300).contains(&c) && k > 20 {
                (8.0, 1)
            } else {
                (20.0, 2)
            };
            let (e, y) = (e.to_radians(), yaw);
            points.push([
                (r * e.cos() * y.cos()) as f32,
                (r * e.cos() * y.sin()) as f32,
                (r * e.sin()) as f32,
            ]);
            truth.push(label);
            if c % 3 == 0 {
                // A second return 5 cm further: loses the pixel.
                let r2 = r + 0.05;
                points.push([
                    (r2 * e.cos() * y.cos()) as f32,
                    (r2 * e.cos() * y.sin()) as f32,
                    (r2 * e.sin()) as f32,
                ]);
                truth.push(label);
            }
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let p = tmp(&dir, "scan.bin");
    write_kitti_bin(
        &p,
        &PointCloud {
            points,
            intensity: None,
        },
    )
    .unwrap();
    let cloud = read_point_cloud(&p).unwrap();
    let proj = project(&cloud.points, &cfg).unwrap();
    assert_eq!(proj.kept_points(), 64 * 512);
    assert_eq!(proj.image.valid_count(), 64 * 512);
    let pixel_truth = proj.to_pixels(&truth, 0).unwrap();
    let back = proj
        .labels_to_points(&pixel_truth, BackProjection::default())
        .unwrap();
    assert_eq!(back, truth);
    // The default projection keeps the nearest point per pixel too.
    let d = project(&cloud.points, &ProjectionConfig::default()).unwrap();
    assert!(d.kept_points() > 20_000, "{}", d.kept_points());
}
