//! ROS 2 recordings: the MCAP fixtures of `tests/data/mcap` (written by the
//! `mcap` and `mcap-ros2-support` Python packages, see `make_fixtures.py`)
//! and recordings broken on purpose.

use fcc_lidar::rosbag::{read_pointclouds, Cloud2};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/mcap")
        .join(name)
}

fn clouds(path: &Path, topic: Option<&str>) -> fcc_lidar::Result<Vec<Cloud2>> {
    let mut out = Vec::new();
    read_pointclouds(path, topic, |_, c| {
        out.push(c);
        Ok(())
    })?;
    Ok(out)
}

/// The surface intensity of the fixtures' scene a point lies on, if any.
fn on_scene(p: [f32; 3], intensity: f32) -> bool {
    let [x, y, z] = p;
    let tol = 1e-3;
    match intensity as u8 {
        10 => (z + 1.5).abs() < tol,
        50 => (x.abs() - 15.0).abs() < tol || (y.abs() - 12.0).abs() < tol,
        200 => {
            (6.0 - tol..=8.0 + tol).contains(&x)
                && (-1.0 - tol..=1.0 + tol).contains(&y)
                && (-1.5 - tol..=0.5 + tol).contains(&z)
        }
        _ => false,
    }
}

#[test]
fn organised_clouds_become_range_images_top_beam_first() {
    // The only PointCloud2 topic is chosen without --topic; /chatter is skipped.
    let cs = clouds(&data("organised.mcap"), None).unwrap();
    assert_eq!(cs.len(), 2);
    let c = &cs[0];
    assert_eq!((c.height, c.width, c.frame_id.as_str()), (16, 180, "lidar"));
    assert_eq!((c.stamp_sec, c.stamp_nanosec), (100, 500));
    let (img, inten) = c.range_image().unwrap().unwrap();
    let inten = inten.unwrap();
    assert_eq!((img.rows, img.cols), (16, 180));
    // Written bottom beam first: flipped so that row 0 is the +15 degree beam.
    let elev = |row: usize| {
        let p = (0..180).find_map(|col| img.at(row, col)).unwrap();
        f64::from(p[2])
            .atan2(f64::from(p[0]).hypot(f64::from(p[1])))
            .to_degrees()
    };
    assert!((elev(0) - 15.0).abs() < 1e-3, "{}", elev(0));
    assert!((elev(15) + 15.0).abs() < 1e-3, "{}", elev(15));
    let mut n = 0;
    for (i, &v) in inten.iter().enumerate() {
        if let Some(p) = img.point(i) {
            assert!(on_scene(p, v), "pixel {i}: {p:?} intensity {v}");
            n += 1;
        } else {
            assert!(v.is_nan());
        }
    }
    assert_eq!(n, img.valid_count());
    assert!(n > 16 * 180 * 9 / 10, "{n}");
    assert_eq!(cs[1].stamp_sec, 101);
}

#[test]
fn unorganised_float64_cloud_of_the_chosen_topic() {
    let err = clouds(&data("unorganised.mcap"), None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("unorganised.mcap")
            && err.contains("several PointCloud2 topics: choose one with --topic")
            && err.contains("/other_points (1 messages)")
            && !err.contains('\n'),
        "{err}"
    );
    let cs = clouds(&data("unorganised.mcap"), Some("/velodyne_points")).unwrap();
    assert_eq!(cs.len(), 1);
    let c = &cs[0];
    assert_eq!(c.height, 1);
    assert!(c.range_image().unwrap().is_none());
    let (pts, inten) = c.finite_points();
    assert_eq!(pts.len(), c.width);
    let inten = inten.unwrap();
    for (p, &i) in pts.iter().zip(&inten) {
        assert!(on_scene(*p, i), "{p:?} intensity {i}");
    }
    assert_eq!(
        clouds(&data("unorganised.mcap"), Some("/other_points")).unwrap()[0].stamp_sec,
        201
    );
}

#[test]
fn wrong_topics_are_one_line_errors_naming_the_topics() {
    let err = clouds(&data("organised.mcap"), Some("/points"))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("organised.mcap: no topic /points")
            && err.contains("/chatter (std_msgs/msg/String)")
            && err.contains("/lidar/points (sensor_msgs/msg/PointCloud2)"),
        "{err}"
    );
    let err = clouds(&data("organised.mcap"), Some("/chatter"))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("topic /chatter carries std_msgs/msg/String messages"),
        "{err}"
    );
}

#[test]
fn broken_recordings_are_one_line_errors() {
    let dir = tempfile::tempdir().unwrap();
    let junk = dir.path().join("junk.mcap");
    std::fs::write(&junk, b"not an mcap file at all").unwrap();
    let err = clouds(&junk, None).unwrap_err().to_string();
    assert!(
        err.contains("junk.mcap: not a MCAP file") && !err.contains('\n'),
        "{err}"
    );
    // Cut in the middle of its only chunk: nothing decodes.
    let bytes = std::fs::read(data("organised.mcap")).unwrap();
    let cut = dir.path().join("cut.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() / 2]).unwrap();
    let err = clouds(&cut, Some("/lidar/points")).unwrap_err().to_string();
    assert!(err.contains("cut.mcap") && !err.contains('\n'), "{err}");
    let missing = dir.path().join("missing.mcap");
    let err = clouds(&missing, None).unwrap_err().to_string();
    assert!(err.contains("missing.mcap"), "{err}");
}

#[test]
fn every_cut_of_a_recording_is_an_error_or_fewer_clouds_never_a_panic() {
    let bytes = std::fs::read(data("organised.mcap")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("cut.mcap");
    for len in (0..bytes.len()).step_by(97) {
        std::fs::write(&p, &bytes[..len]).unwrap();
        if let Ok(cs) = clouds(&p, Some("/lidar/points")) {
            assert!(cs.len() <= 2, "cut at {len}");
        }
    }
    // Flipped bytes inside the messages.
    for k in (0..bytes.len()).step_by(131) {
        let mut b = bytes.clone();
        b[k] ^= 0x5a;
        std::fs::write(&p, &b).unwrap();
        let _ = clouds(&p, Some("/lidar/points"));
    }
}
