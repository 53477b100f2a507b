//! The `fcc` binary end to end: scene -> cluster -> labels, and its errors.

use fcc_golden::{reference::reference_labels, Frame};
use fcc_params::FccParams;
use fcc_testkit::{assert_one_line_error, s, same_partition, stderr, tmpdir};
use std::path::PathBuf;
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

#[test]
fn scene_then_cluster_matches_the_reference() {
    let d = tmpdir("scene");
    let (frame, gt, labels) = (d.join("f.npy"), d.join("gt.npy"), d.join("l.npy"));
    let o = fcc(&[
        "scene",
        "--seed",
        "3",
        "--rows",
        "32",
        "--cols",
        "512",
        "--output",
        s(&frame),
        "--gt",
        s(&gt),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = fcc(&[
        "cluster",
        "--input",
        s(&frame),
        "--output",
        s(&labels),
        "--fsize",
        "5",
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    for key in [
        "points",
        "provisional",
        "clusters",
        "joins",
        "overflow",
        "time_ms",
    ] {
        assert!(stats.get(key).is_some(), "--stats lacks {key}: {stats}");
    }
    let img = fcc_npy::read_xyz(&frame).unwrap();
    let got = fcc_npy::read_labels(&labels).unwrap();
    assert_eq!((got.rows, got.cols), (32, 512));
    let p = FccParams {
        rows: 32,
        cols: 512,
        fsize: 5,
        ..FccParams::default()
    };
    let want = reference_labels(&p, &Frame::from_xyz_f64(32, 512, &img.xyz));
    assert!(same_partition(&want, &got.labels));
    assert_eq!(
        want, got.labels,
        "numbering follows raster order of first pixel"
    );
    assert!(stats["clusters"].as_u64().unwrap() > 5);
    let truth = fcc_npy::read_labels(&gt).unwrap();
    assert!(truth.labels.iter().any(|&l| l > 0));
}

#[test]
fn batch_writes_one_label_file_per_input() {
    let d = tmpdir("batch");
    let mut inputs = Vec::new();
    for seed in 0..3 {
        let f = d.join(format!("s{seed}.npy"));
        let o = fcc(&[
            "scene",
            "--seed",
            &seed.to_string(),
            "--rows",
            "16",
            "--cols",
            "256",
            "--output",
            s(&f),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        inputs.push(f);
    }
    let out = d.join("labels.npy");
    let mut args = vec![
        "cluster",
        "--jobs",
        "2",
        "--stats",
        "--output",
        s(&out),
        "--input",
    ];
    args.extend(inputs.iter().map(|p| s(p)));
    let o = fcc(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(String::from_utf8_lossy(&o.stdout).lines().count(), 3);
    for seed in 0..3 {
        assert!(d.join(format!("labels_s{seed}.npy")).exists());
    }
}

#[test]
fn bad_inputs_end_with_one_line_and_exit_code_2() {
    let d = tmpdir("bad");
    let not_npy = d.join("not.npy");
    std::fs::write(&not_npy, "x,y,z\n1,2,3\n").unwrap();
    let o = fcc(&[
        "cluster",
        "--input",
        s(&not_npy),
        "--output",
        s(&d.join("o.npy")),
    ]);
    assert_one_line_error(&o, &not_npy, "not a .npy file");

    let labels = d.join("labels.npy");
    fcc_npy::write_labels(&labels, 2, 2, &[0, 1, 2, 3]).unwrap();
    let o = fcc(&["cluster", "--input", s(&labels)]);
    assert_one_line_error(&o, &labels, "is not (rows, cols, 3)");

    let frame = d.join("frame.npy");
    fcc_npy::write_xyz_f32(&frame, 2, 2, &[1.0; 12]).unwrap();
    let mut bytes = std::fs::read(&frame).unwrap();
    bytes.truncate(bytes.len() - 5);
    let cut = d.join("cut.npy");
    std::fs::write(&cut, bytes).unwrap();
    let o = fcc(&["cluster", "--input", s(&cut)]);
    assert_one_line_error(&o, &cut, "truncated");

    let missing = d.join("missing.npy");
    let o = fcc(&["cluster", "--input", s(&missing)]);
    assert_one_line_error(&o, &missing, "cannot read");
}

#[test]
fn bad_parameters_name_the_field() {
    let d = tmpdir("params");
    let frame = d.join("frame.npy");
    fcc_npy::write_xyz_f32(&frame, 2, 2, &[1.0; 12]).unwrap();
    let o = fcc(&["cluster", "--input", s(&frame), "--fsize", "4"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o).trim(),
        "error: fsize = 4 is out of range: an odd number in 3 ..= 15"
    );
    let o = fcc(&["cluster", "--input", s(&frame), "--th-v", "0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("th_v = 0 is out of range"),
        "{}",
        stderr(&o)
    );
    let o = fcc(&["cluster", "--input", s(&frame), "--merge", "fast"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("expected `exact` or `paper`"),
        "{}",
        stderr(&o)
    );
    let o = fcc(&["scene", "--rows", "4", "--output", s(&d.join("s.npy"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("rows"), "{}", stderr(&o));
}

#[test]
fn paper_merge_is_selectable() {
    let d = tmpdir("paper");
    let frame = d.join("f.npy");
    let o = fcc(&[
        "scene",
        "--seed",
        "5",
        "--rows",
        "16",
        "--cols",
        "256",
        "--output",
        s(&frame),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = fcc(&[
        "cluster",
        "--input",
        s(&frame),
        "--merge",
        "paper",
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(stats["merge"], "paper");
}

/// A real capture from the repository's test data.
fn ouster_capture() -> PathBuf {
    fcc_testkit::lidar_data().join("OS-2-128-U1_v2.3.0_1024x10.pcap")
}

#[test]
fn ouster_capture_gives_labels_and_a_picture() {
    let d = tmpdir("ouster");
    let (png, labels) = (d.join("os2.png"), d.join("os2.npy"));
    let o = fcc(&[
        "cluster",
        "--input",
        s(&ouster_capture()),
        "--min-points",
        "40",
        "--png",
        s(&png),
        "--output",
        s(&labels),
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(
        (stats["rows"].as_u64(), stats["cols"].as_u64()),
        (Some(128), Some(1024))
    );
    let clusters = stats["clusters"].as_u64().unwrap();
    assert!(
        (20..400).contains(&clusters),
        "{clusters} clusters of > 40 points"
    );
    assert!(
        stats["ground_points"].as_u64().unwrap() > 1000,
        "ground removed by default"
    );
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let l = fcc_npy::read_labels(&labels).unwrap();
    assert_eq!(l.labels.iter().max().copied(), Some(clusters as u32));
}

#[test]
fn convert_then_cluster_a_capture_as_npy() {
    let d = tmpdir("convert");
    let npy = d.join("os2.npy");
    let o = fcc(&[
        "convert",
        "--input",
        s(&ouster_capture()),
        "--output",
        s(&npy),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let img = fcc_npy::read_xyz(&npy).unwrap();
    assert_eq!((img.rows, img.cols), (128, 1024));
}

#[test]
fn eval_prints_the_quality_table() {
    let o = fcc(&[
        "eval",
        "--synthetic",
        "2",
        "--scene-rows",
        "32",
        "--scene-cols",
        "512",
        "--fsizes",
        "3,7",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(out.contains("| K | merge | PQ |"), "{out}");
    // Two rows per K and merge mode: the quality table's and the range
    // bands'.
    let (table, bands) = out.split_once("PQ by range band").expect("the band table");
    for part in [table, bands] {
        assert_eq!(
            part.lines()
                .filter(|l| l.starts_with("| 3 |") || l.starts_with("| 7 |"))
                .count(),
            4,
            "{out}"
        );
    }
}

#[test]
fn gen_writes_the_rtl_and_rejects_what_hardware_cannot_do() {
    let d = tmpdir("gen");
    let (rtl, xdc, tcl) = (d.join("rtl"), d.join("xdc"), d.join("tcl"));
    let o = fcc(&[
        "gen",
        "--fsize",
        "3",
        "--rows",
        "16",
        "--cols",
        "256",
        "--clock-mhz",
        "203.6",
        "--no-lint",
        "--rtl",
        s(&rtl),
        "--constraints",
        s(&xdc),
        "--scripts",
        s(&tcl),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v = std::fs::read_to_string(rtl.join("fcc_top.v")).unwrap();
    assert!(
        v.contains("fsize=3") && v.contains("module fcc_top_k3_"),
        "header and top"
    );
    assert!(std::fs::read_to_string(xdc.join("fcc_top.xdc"))
        .unwrap()
        .contains("4.912"));
    assert!(tcl.join("fcc_build.tcl").exists());
    let o = fcc(&["gen", "--fsize", "13", "--out", s(&rtl), "--no-lint"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("fsize = 13 is out of range: an odd number in 3 ..= 11"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn gen_smallest_takes_every_size_at_its_hardware_minimum() {
    use fcc_params::limits;
    let d = tmpdir("gen-smallest");
    let o = fcc(&["gen", "--smallest", "--out", s(&d), "--no-lint"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let json: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(d.join("rtl_out").join("fcc_params.json")).unwrap(),
    )
    .unwrap();
    let p: fcc_params::FccParams = serde_json::from_value(json["params"].clone()).unwrap();
    assert_eq!(
        (p.fsize, p.rows, p.cols, p.label_bits),
        (
            *limits::HW_FSIZE.start(),
            *limits::HW_ROWS.start(),
            *limits::HW_COLS.start(),
            *limits::HW_LABEL_BITS.start()
        )
    );
    let o = fcc(&[
        "gen",
        "--smallest",
        "--fsize",
        "5",
        "--out",
        s(&d),
        "--no-lint",
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--fsize"), "{}", stderr(&o));
}

#[test]
fn bench_prints_exact_and_paper_rows_and_its_json() {
    let d = tmpdir("bench");
    let json = d.join("bench.json");
    let o = fcc(&[
        "bench",
        "--fsize",
        "3,5",
        "--frames",
        "1",
        "--repeat",
        "1",
        "--rows",
        "16",
        "--cols",
        "128",
        "--jobs",
        "2",
        "--json",
        s(&json),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8_lossy(&o.stdout);
    for k in ["3", "5"] {
        for merge in ["exact", "paper"] {
            assert!(
                out.lines()
                    .any(|l| l.starts_with(&format!("| {k} | {merge} |"))),
                "no K = {k} {merge} row in\n{out}"
            );
        }
    }
    assert!(out.contains("batch frames/s (1 thread)"), "{out}");
    assert!(out.contains("batch frames/s (2 threads)"), "{out}");
    let rows: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(rows.as_array().unwrap().len(), 2);
    for field in [
        "exact_ms",
        "paper_ms",
        "batch_frames_per_s",
        "paper_batch_frames_per_s",
        "one_thread_batch_frames_per_s",
        "speedup",
        "paper_speedup",
        "threads",
    ] {
        assert!(rows[0][field].is_number(), "{field} missing: {rows}");
    }
    assert_eq!(rows[0]["threads"], 2);
}
