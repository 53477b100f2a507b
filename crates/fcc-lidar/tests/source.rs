//! The input source: every kind of input to frames in order, with the
//! capture's summary line, and one error for an input of no known type.

use fcc_lidar::cloud::{write_kitti_bin, PointCloud};
use fcc_lidar::source::{single_frame, Frame, InputKind, Source, SourceOptions, Summary};
use fcc_lidar::LidarError;
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

const OS1_32: &str = "OS-1-32-G_v2.1.1_1024x10.pcap";

fn range_images() -> SourceOptions {
    SourceOptions {
        range_images: true,
        ..SourceOptions::default()
    }
}

/// Every frame and the notes of one input.
fn read(
    path: &Path,
    truth: Option<&Path>,
    opts: &SourceOptions,
) -> Result<(Vec<Frame>, Vec<String>, Summary), LidarError> {
    let (mut frames, mut notes) = (Vec::new(), Vec::new());
    let s = Source::open(path, truth, opts)?.for_each(
        |n| notes.push(n.to_string()),
        |f| {
            frames.push(f);
            Ok::<(), LidarError>(())
        },
    )?;
    Ok((frames, notes, s))
}

#[test]
fn ouster_capture_gives_named_frames_and_its_summary_line() {
    let cap = data(OS1_32);
    let opts = range_images();
    assert_eq!(InputKind::of(&cap, &opts), Some(InputKind::Ouster));
    let (frames, _, s) = read(&cap, None, &opts).unwrap();
    assert!(!frames.is_empty());
    assert_eq!(s.frames_used, frames.len());
    let f = &frames[0];
    assert!(
        f.name.starts_with("OS-1-32-G_v2.1.1_1024x10_f"),
        "{}",
        f.name
    );
    assert_eq!((f.image.rows, f.image.cols), (32, 1024));
    assert_eq!(f.intensity.as_ref().map(Vec::len), Some(32 * 1024));
    assert!(!f.range_image && f.projection.is_none() && f.truth.is_none());
    let line = s.line.unwrap();
    assert!(
        line.contains(&format!("{} frames used of", frames.len())),
        "{line}"
    );
    assert!(s.warnings.is_empty());
    assert_eq!(single_frame(&cap, &opts), frames.len() == 1);
}

#[test]
fn frames_all_skipped_warn_or_fail_with_strict() {
    let cap = data(OS1_32);
    let mut opts = SourceOptions {
        skip_frames: 100,
        max_frames: Some(3),
        ..range_images()
    };
    let (frames, _, s) = read(&cap, None, &opts).unwrap();
    assert!(frames.is_empty());
    assert_eq!(s.warnings.len(), 1);
    assert!(
        s.warnings[0].ends_with("(--skip-frames 100, --max-frames 3)"),
        "{}",
        s.warnings[0]
    );
    assert!(s.warnings[0].contains("no frame used of"));
    opts.strict = true;
    let e = read(&cap, None, &opts).unwrap_err().to_string();
    assert!(
        e.ends_with("(--skip-frames 100, --max-frames 3) (--strict)"),
        "{e}"
    );
}

#[test]
fn velodyne_capture_is_told_by_the_missing_metadata() {
    let cap = data("velodyne/vlp16.pcap");
    let opts = range_images();
    assert_eq!(InputKind::of(&cap, &opts), Some(InputKind::Velodyne));
    let (frames, _, s) = read(&cap, None, &opts).unwrap();
    assert!(!frames.is_empty());
    assert!(frames[0].name.starts_with("vlp16_f"), "{}", frames[0].name);
    assert!(
        s.line.as_deref().unwrap().contains("Velodyne VLP-16, "),
        "{:?}",
        s.line
    );
    // Capped at one rotation: one frame.
    let one = SourceOptions {
        max_frames: Some(1),
        ..range_images()
    };
    assert!(single_frame(&cap, &one));
    assert_eq!(read(&cap, None, &one).unwrap().0.len(), 1);
}

#[test]
fn recording_gives_a_frame_per_message() {
    let rec = data("mcap/organised.mcap");
    let opts = range_images();
    assert_eq!(InputKind::of(&rec, &opts), Some(InputKind::Mcap));
    let (frames, _, s) = read(&rec, None, &opts).unwrap();
    assert!(!frames.is_empty());
    assert_eq!(frames[0].name, "organised_m00000");
    assert!(
        s.line
            .as_deref()
            .unwrap()
            .contains(&format!("{} PointCloud2 messages used", frames.len())),
        "{:?}",
        s.line
    );
    assert!(!single_frame(&rec, &opts));
}

#[test]
fn point_cloud_and_range_image_with_truth() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("scan.bin");
    let cloud = PointCloud {
        points: vec![[10.0, 0.0, -1.0], [10.0, 0.1, -1.0], [0.0, 0.0, 0.0]],
        intensity: Some(vec![0.1, 0.2, 0.3]),
    };
    write_kitti_bin(&bin, &cloud).unwrap();
    let label = dir.path().join("scan.label");
    let raw: Vec<u8> = [(1u32 << 16) | 10, (1 << 16) | 10, 0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    std::fs::write(&label, raw).unwrap();
    let opts = range_images();
    let (frames, notes, s) = read(&bin, Some(&label), &opts).unwrap();
    assert!(notes.is_empty() && s.line.is_none());
    let f = &frames[0];
    assert_eq!(f.name, "scan");
    assert_eq!(f.losses.input_points, 3);
    assert_eq!(f.losses.unprojected, 1);
    assert!(f.projection.is_some());
    assert_eq!(f.truth_points.as_ref().map(Vec::len), Some(3));
    assert!(single_frame(&bin, &opts));

    let npy = dir.path().join("img.npy");
    fcc_npy::write_xyz_f32(&npy, 2, 2, &[1.0; 12]).unwrap();
    let truth = dir.path().join("truth.npy");
    fcc_npy::write_labels(&truth, 2, 3, &[0; 6]).unwrap();
    let e = read(&npy, Some(&truth), &opts).unwrap_err().to_string();
    assert!(e.contains("ground truth is 2 x 3 but"), "{e}");
    let (frames, _, _) = read(&npy, None, &opts).unwrap();
    assert!(frames[0].range_image);
    assert_eq!(frames[0].image.valid_count(), 4);
}

#[test]
fn unknown_inputs_and_truth_for_captures_are_one_clear_error() {
    let txt = Path::new("notes.txt");
    let e = Source::open(txt, None, &range_images())
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "notes.txt: unknown input type (expected .pcap, .pcapng, .mcap, .bin, .pcd, .ply or .npy)"
    );
    // A tool that makes range images does not read them.
    let e = Source::open(Path::new("a.npy"), None, &SourceOptions::default())
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "a.npy: unknown input type (expected .pcap, .pcapng, .mcap, .bin, .pcd or .ply)"
    );
    let cap = data(OS1_32);
    let e = Source::open(&cap, Some(Path::new("t.label")), &range_images())
        .unwrap_err()
        .to_string();
    assert!(
        e.ends_with("ground truth for Ouster captures is not supported"),
        "{e}"
    );
}
