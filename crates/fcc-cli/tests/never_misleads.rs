//! The command line never misleads: no lost input, no silent loss of points,
//! one option vocabulary, one error format. Each test names the edge case.

use fcc_testkit::{lidar_data, s, stderr, tmpdir};
use std::path::{Path, PathBuf};
use std::process::Output;

fn fcc_in(dir: Option<&Path>, args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), dir, args)
}

fn fcc(args: &[&str]) -> Output {
    fcc_in(None, args)
}

fn stats(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("--stats is not one JSON line ({e}): {}", stderr(o)))
}

fn capture(name: &str) -> PathBuf {
    lidar_data().join(name)
}

const OS1_32: &str = "OS-1-32-G_v2.1.1_1024x10.pcap";

/// A small synthetic frame written with `fcc scene`.
fn scene(d: &Path, name: &str) -> PathBuf {
    let f = d.join(name);
    let o = fcc(&[
        "scene",
        "--seed",
        "3",
        "--rows",
        "32",
        "--cols",
        "512",
        "--output",
        s(&f),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    f
}

fn assert_error(o: &Output, needle: &str) {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(2), "exit code; stderr: {e}");
    let last = e.lines().last().unwrap_or_default();
    assert!(
        last.starts_with("error: "),
        "the last line is the error: {e}"
    );
    assert_eq!(e.matches("error:").count(), 1, "one error line: {e}");
    assert!(e.contains(needle), "expected `{needle}` in: {e}");
}

#[test]
fn output_naming_the_input_is_refused_and_the_input_kept() {
    let d = tmpdir("same");
    let f = scene(&d, "a.npy");
    let before = std::fs::read(&f).unwrap();
    let o = fcc(&["cluster", "--input", s(&f), "--output", s(&f)]);
    assert_error(&o, "refusing to overwrite an input");
    // Spelled differently, and through the other outputs.
    std::fs::create_dir_all(d.join("sub")).unwrap();
    let dotted = d.join("sub").join("..").join("a.npy");
    let o = fcc(&["cluster", "--input", s(&f), "--output", s(&dotted)]);
    assert_error(&o, "refusing to overwrite an input");
    let o = fcc(&["cluster", "--input", s(&f), "--label", s(&f)]);
    assert_error(&o, "refusing to overwrite an input");
    let o = fcc(&["cluster", "--input", s(&f), "--ply", s(&f)]);
    assert_error(&o, "refusing to overwrite an input");
    assert_eq!(std::fs::read(&f).unwrap(), before, "the input was changed");
    // Two outputs on one path.
    let out = d.join("out.npy");
    let o = fcc(&[
        "cluster",
        "--input",
        s(&f),
        "--output",
        s(&out),
        "--label",
        s(&out),
    ]);
    assert_error(&o, "given as two outputs");
    // Other commands.
    let o = fcc(&["scene", "--output", s(&out), "--gt", s(&out)]);
    assert_error(&o, "given as two outputs");
    let json = d.join("t.json");
    std::fs::write(&json, "keep").unwrap();
    let o = fcc(&[
        "eval",
        "--synthetic",
        "1",
        "--json",
        s(&json),
        "--markdown",
        s(&json),
    ]);
    assert_error(&o, "given as two outputs");
    assert_eq!(std::fs::read_to_string(&json).unwrap(), "keep");
}

#[test]
fn failed_write_leaves_no_partial_file_and_says_the_os_error_once() {
    let d = tmpdir("failed-write");
    let f = scene(&d, "a.npy");
    for flag in ["--output", "--png", "--ply", "--label"] {
        let out = d.join("no-such-dir").join("out.png");
        let o = fcc(&["cluster", "--input", s(&f), flag, s(&out)]);
        assert_error(&o, "No such file or directory");
        let e = stderr(&o);
        assert_eq!(
            e.matches("No such file or directory").count(),
            1,
            "{flag}: {e}"
        );
        assert_eq!(e.lines().count(), 1, "{flag}: {e}");
    }
    let names: Vec<_> = std::fs::read_dir(&d)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["a.npy"], "a temporary file was left behind");
}

#[test]
fn cluster_says_what_it_wrote() {
    let d = tmpdir("wrote");
    let f = scene(&d, "a.npy");
    let (l, png) = (d.join("l.npy"), d.join("p.png"));
    let o = fcc(&[
        "cluster",
        "--input",
        s(&f),
        "--output",
        s(&l),
        "--png",
        s(&png),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for p in [&l, &png] {
        assert!(
            stderr(&o).contains(&format!("wrote {}", p.display())),
            "{}",
            stderr(&o)
        );
    }
}

#[test]
fn label_overflow_on_os1_32_warns_and_strict_makes_it_an_error() {
    let cap = capture(OS1_32);
    let o = fcc(&[
        "cluster",
        "--input",
        s(&cap),
        "--label-bits",
        "8",
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let st = stats(&o);
    assert_eq!(st["overflow"], true);
    let needed = st["labels_needed"].as_u64().unwrap();
    assert!(needed > 255, "{st}");
    let bits = 64 - needed.leading_zeros();
    let e = stderr(&o);
    assert!(
        e.contains("warning: ") && e.contains("label overflow"),
        "{e}"
    );
    assert!(e.contains(&format!("use --label-bits {bits}")), "{e}");
    assert!(
        e.contains(&format!("{} of", st["unlabelled"])),
        "the warning says how many points are lost: {e}"
    );
    let o = fcc(&[
        "cluster",
        "--input",
        s(&cap),
        "--label-bits",
        "8",
        "--strict",
    ]);
    assert_error(&o, "label overflow");
    // The width the warning names is enough.
    let o = fcc(&[
        "cluster",
        "--input",
        s(&cap),
        "--label-bits",
        &bits.to_string(),
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stats(&o)["overflow"], false);
    assert!(!stderr(&o).contains("label overflow"), "{}", stderr(&o));
}

#[test]
fn points_beyond_the_q7_8_range_are_counted_and_reported() {
    let d = tmpdir("range");
    let f = d.join("far.npy");
    let mut xyz = vec![f32::NAN; 16 * 256 * 3];
    xyz[..3].copy_from_slice(&[10.0, 0.0, 0.0]);
    xyz[3..6].copy_from_slice(&[10.0, 0.1, 0.0]);
    xyz[6..9].copy_from_slice(&[200.0, 0.0, 0.0]);
    fcc_npy::write_xyz_f32(&f, 16, 256, &xyz).unwrap();
    let o = fcc(&["cluster", "--input", s(&f), "--stats"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let st = stats(&o);
    assert_eq!(st["out_of_range"], 1, "{st}");
    assert!(
        stderr(&o).contains("1 points beyond the Q7.8"),
        "{}",
        stderr(&o)
    );
    let o = fcc(&["cluster", "--input", s(&f), "--strict"]);
    assert_error(&o, "Q7.8");
}

#[test]
fn point_cloud_outside_the_field_of_view_is_reported() {
    let d = tmpdir("fov");
    let ply = d.join("c.ply");
    // A ring at +10 degrees and one at +40 degrees; the default field of
    // view is +3 .. -25 degrees.
    let mut pts = Vec::new();
    for k in 0..360 {
        let a = (k as f32).to_radians();
        for el in [10f32, 40.0] {
            let e = el.to_radians();
            pts.push([
                10.0 * e.cos() * a.cos(),
                10.0 * e.cos() * a.sin(),
                10.0 * e.sin(),
            ]);
        }
    }
    fcc_lidar::cloud::write_ply(&ply, &pts, None, None, fcc_lidar::cloud::PlyFormat::Ascii)
        .unwrap();
    let o = fcc(&["cluster", "--input", s(&ply), "--stats"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let st = stats(&o);
    assert_eq!(st["input_points"], 720, "{st}");
    assert_eq!(st["outside_fov"], 720, "{st}");
    assert!(st["pixel_shared"].as_u64().unwrap() > 0, "{st}");
    assert!(
        stderr(&o).contains("outside the vertical field of view"),
        "{}",
        stderr(&o)
    );
    let o = fcc(&[
        "cluster",
        "--input",
        s(&ply),
        "--fov-up",
        "45",
        "--fov-down",
        "5",
        "--stats",
        "--strict",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stats(&o)["outside_fov"], 0);
}

#[test]
fn skip_frames_past_the_end_exits_non_zero() {
    let d = tmpdir("skip");
    let out = d.join("l.npy");
    let o = fcc(&[
        "cluster",
        "--input",
        s(&capture(OS1_32)),
        "--skip-frames",
        "100",
        "--output",
        s(&out),
    ]);
    assert_error(&o, "no frame was clustered");
    assert!(stderr(&o).contains("--skip-frames 100"), "{}", stderr(&o));
    assert!(!out.exists());
    let o = fcc(&[
        "convert",
        "--input",
        s(&capture(OS1_32)),
        "--skip-frames",
        "100",
        "--output",
        s(&out),
    ]);
    assert_error(&o, "no frame to convert");
}

#[test]
fn missing_capture_is_reported_missing() {
    let d = tmpdir("missing");
    let cap = d.join("gone.pcap");
    let o = fcc(&["cluster", "--input", s(&cap)]);
    let e = stderr(&o);
    assert!(
        e.contains("No such file") || e.contains("no such capture file"),
        "{e}"
    );
    assert_error(&o, "gone.pcap");
    assert!(!stderr(&o).contains("metadata"), "{}", stderr(&o));
}

#[test]
fn list_options_take_the_form_the_help_shows() {
    let help = String::from_utf8_lossy(&fcc(&["eval", "--help"]).stdout).into_owned();
    assert!(help.contains("--fsize <FSIZE>..."), "{help}");
    assert!(help.contains("[default: 3 5 7 9 11]"), "{help}");
    for list in [&["3", "7"][..], &["3,7"][..]] {
        let mut args = vec![
            "eval",
            "--synthetic",
            "1",
            "--scene-rows",
            "32",
            "--scene-cols",
            "512",
        ];
        args.push("--fsize");
        args.extend(list);
        args.extend(["--merge", "exact"]);
        let o = fcc(&args);
        assert!(o.status.success(), "{list:?}: {}", stderr(&o));
        let out = String::from_utf8_lossy(&o.stdout);
        // The quality table (the range-band table after it repeats the rows).
        let table = out.split("PQ by range band").next().unwrap_or_default();
        let rows = table
            .lines()
            .filter(|l| l.starts_with("| 3 |") || l.starts_with("| 7 |"));
        assert_eq!(rows.count(), 2, "{list:?}: {out}");
    }
}

#[test]
fn negative_values_get_a_range_error_not_a_parse_error() {
    let d = tmpdir("negative");
    let f = scene(&d, "a.npy");
    let o = fcc(&["cluster", "--input", s(&f), "--th-h", "-0.5"]);
    assert_error(&o, "th_h = -0.5 is out of range");
    let o = fcc(&["eval", "--synthetic", "1", "--th-v", "-1"]);
    assert_error(&o, "th_v = -1 is out of range");
    let o = fcc(&[
        "gen",
        "--fsize",
        "7",
        "--th-h",
        "-0.5",
        "--out",
        s(&d.join("rtl")),
    ]);
    assert_error(&o, "th_h = -0.5 is out of range");
}

#[test]
fn cycles_runs_outside_the_repository_root() {
    // Before the Verilator runs, the samples are read and K is checked: an
    // invalid K shows the captures were found from another directory.
    let d = tmpdir("cycles");
    let o = fcc_in(Some(&d), &["cycles", "--fsize", "4", "--frames", "1"]);
    assert_error(&o, "fsize = 4");
    assert!(!stderr(&o).contains("Ouster"), "{}", stderr(&o));
}

#[test]
fn sim_refuses_rows_and_cols_with_an_input_frame() {
    let d = tmpdir("sim");
    let f = scene(&d, "a.npy");
    let o = fcc(&["sim", "--input", s(&f), "--rows", "64"]);
    assert_error(&o, "--rows and --cols size a --scene-seed scene only");
    let o = fcc(&["sim", "--input", s(&f), "--cols", "512"]);
    assert_error(&o, "--rows and --cols");
}

#[test]
fn gen_refuses_a_clock_the_ps_cannot_give() {
    let d = tmpdir("gen-clock");
    let out = d.join("rtl");
    let o = fcc(&[
        "gen",
        "--fsize",
        "3",
        "--rows",
        "16",
        "--cols",
        "256",
        "--clock-mhz",
        "300",
        "--rtl",
        s(&out),
        "--constraints",
        s(&d.join("xdc")),
        "--scripts",
        s(&d.join("tcl")),
        "--no-lint",
    ]);
    assert_error(&o, "--clock-mhz 300 is above 240 MHz");
    assert!(!out.exists(), "nothing is generated");
}

#[test]
fn png_output_with_another_extension_is_refused() {
    let d = tmpdir("jpg");
    let f = scene(&d, "a.npy");
    let jpg = d.join("out.jpg");
    let o = fcc(&["cluster", "--input", s(&f), "--png", s(&jpg)]);
    assert_error(&o, "--png writes PNG pictures only");
    assert!(!jpg.exists());
}

#[test]
fn readme_set_up_is_the_script_ci_runs_and_puts_fcc_on_path() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let read =
        |f: &str| std::fs::read_to_string(root.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
    let (readme, ci, setup) = (read("README.md"), read(".ci/run"), read("setup.sh"));
    // One set-up command for a user and for CI: the same script.
    assert!(
        readme.lines().any(|l| l.trim() == "./setup.sh"),
        "README's set-up command is `./setup.sh`"
    );
    assert!(
        ci.lines().any(|l| l.trim_start().starts_with("./setup.sh")),
        ".ci/run sets up with ./setup.sh"
    );
    let packages: Vec<&str> = setup
        .lines()
        .find_map(|l| l.trim().strip_prefix("APT_PACKAGES=("))
        .and_then(|l| l.strip_suffix(')'))
        .expect("setup.sh lists its APT_PACKAGES=(...) on one line")
        .split_whitespace()
        .collect();
    for pkg in [
        "verilator",
        "yosys",
        "z3",
        "iverilog",
        "g++",
        "tcl",
        "python3-venv",
    ] {
        assert!(
            packages.contains(&pkg),
            "setup.sh does not install {pkg} (it installs {packages:?})"
        );
    }
    assert!(setup.contains("-r sim/cocotb/requirements.txt"));
    // Without --no-install (CI's flag) it puts fcc on PATH.
    assert!(setup.contains("cargo install --locked --path crates/fcc-cli"));
    for doc in [
        "README.md",
        "docs/rtl.md",
        "docs/vivado.md",
        "docs/lidar.md",
        "docs/results-method.md",
    ] {
        let text = std::fs::read_to_string(root.join(doc)).unwrap();
        for (i, l) in text.lines().enumerate() {
            assert!(
                !l.trim_start().starts_with("cargo run"),
                "{doc}:{}: examples call `fcc` (README says how to put it on PATH): {l}",
                i + 1
            );
        }
    }
}

#[test]
fn point_cloud_quality_is_named_per_pixel_and_per_point() {
    use fcc_lidar::cloud::{write_kitti_bin, PointCloud};
    use fcc_lidar::labels::{pack_label, THING_CLASSES};
    let d = tmpdir("pq");
    // Two boxes of points 10 m ahead and behind, two points per pixel in
    // places, labelled as two instances of a thing class.
    let mut points = Vec::new();
    let mut labels = Vec::new();
    for (inst, x) in [(1u16, 10.0f32), (2, -10.0)] {
        for k in 0..60 {
            for h in 0..8 {
                let y = -1.0 + k as f32 * 0.035;
                let z = -1.0 + h as f32 * 0.12;
                points.push([x, y, z]);
                labels.push(pack_label(THING_CLASSES[0], inst));
            }
        }
    }
    let (bin, label) = (d.join("s.bin"), d.join("s.label"));
    write_kitti_bin(
        &bin,
        &PointCloud {
            points,
            intensity: None,
        },
    )
    .unwrap();
    let raw: Vec<u8> = labels.iter().flat_map(|l| l.to_le_bytes()).collect();
    std::fs::write(&label, raw).unwrap();
    let o = fcc(&[
        "cluster",
        "--input",
        s(&bin),
        "--truth",
        s(&label),
        "--ground",
        "none",
        "--stats",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let st = stats(&o);
    for key in ["quality", "quality_per_point"] {
        assert!(
            st[key]["pq"].as_f64().is_some(),
            "--stats lacks {key}: {st}"
        );
    }
    let help = String::from_utf8_lossy(&fcc(&["cluster", "--help"]).stdout).into_owned();
    assert!(help.contains("--strict"), "{help}");
}

/// Every file of a generated tree, with its contents.
fn tree(root: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = vec![];
    let mut dirs = vec![root.to_path_buf()];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                dirs.push(p);
            } else {
                out.push((p.clone(), std::fs::read(&p).unwrap()));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn gen_out_puts_rtl_constraints_and_scripts_under_it_and_leaves_the_current_directory_alone() {
    // A directory holding a K = 7 configuration in the repository layout, as
    // the repository root does.
    let d = tmpdir("gen-trap");
    let small = ["--rows", "16", "--cols", "256", "--no-lint"];
    let mut k7 = vec!["gen", "--fsize", "7"];
    k7.extend(small);
    let o = fcc_in(Some(&d), &k7);
    assert!(o.status.success(), "{}", stderr(&o));
    let before = tree(&d);
    assert!(before
        .iter()
        .any(|(p, _)| p.ends_with("scripts/fcc_build.tcl")));

    // K = 5 with --out: everything under the new directory, nothing else.
    let mut k5 = vec!["gen", "--fsize", "5", "--out", "k5"];
    k5.extend(small);
    let o = fcc_in(Some(&d), &k5);
    assert!(o.status.success(), "{}", stderr(&o));
    for f in [
        "k5/rtl_out/fcc_top.v",
        "k5/rtl_out/fcc_params.json",
        "k5/constraints/fcc_top.xdc",
        "k5/scripts/fcc_build.tcl",
        "k5/scripts/fcc_zc706_bd.tcl",
        "k5/scripts/fcc_regs.h",
        "k5/scripts/fcc_zc706_example.c",
    ] {
        assert!(d.join(f).is_file(), "{f} missing");
    }
    let build = std::fs::read_to_string(d.join("k5/scripts/fcc_build.tcl")).unwrap();
    assert!(build.contains("fsize=5") && build.contains("../rtl_out/fcc_top.v"));
    let after: Vec<_> = tree(&d)
        .into_iter()
        .filter(|(p, _)| !p.starts_with(d.join("k5")))
        .collect();
    assert!(after == before, "fcc gen --out changed files outside --out");
}

#[test]
fn gen_refuses_to_overwrite_another_configuration_unless_forced() {
    let d = tmpdir("gen-other");
    let small = ["--rows", "16", "--cols", "256", "--no-lint"];
    let mut k7 = vec!["gen", "--fsize", "7"];
    k7.extend(small);
    let o = fcc_in(Some(&d), &k7);
    assert!(o.status.success(), "{}", stderr(&o));
    let before = tree(&d);
    // The same configuration again: regenerated in place.
    let o = fcc_in(Some(&d), &k7);
    assert!(o.status.success(), "{}", stderr(&o));
    // Another one in the same place: refused, nothing changed.
    let mut k5 = vec!["gen", "--fsize", "5"];
    k5.extend(small);
    let o = fcc_in(Some(&d), &k5);
    assert_error(&o, "refusing to overwrite files of another configuration");
    assert!(
        stderr(&o).contains("rtl_out/fcc_params.json"),
        "{}",
        stderr(&o)
    );
    assert!(stderr(&o).contains("--force"), "{}", stderr(&o));
    assert!(tree(&d) == before, "a refused fcc gen changed files");
    // --force replaces them.
    k5.push("--force");
    let o = fcc_in(Some(&d), &k5);
    assert!(o.status.success(), "{}", stderr(&o));
    let json = std::fs::read_to_string(d.join("rtl_out/fcc_params.json")).unwrap();
    assert!(json.contains("\"fsize\": 5"), "{json}");
}

#[test]
fn gen_board_refuses_a_clock_the_boards_dma_cannot_meet() {
    let d = tmpdir("gen-board");
    let o = fcc(&[
        "gen",
        "--board",
        "pynq-z2",
        "--rows",
        "16",
        "--cols",
        "256",
        "--no-lint",
        "--out",
        s(&d.join("pynq")),
    ]);
    assert_error(&o, "--clock-mhz 200 is above 150 MHz");
    assert!(!d.join("pynq").exists(), "nothing is generated");
    let o = fcc(&["gen", "--board", "zc707", "--out", s(&d.join("x"))]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("unknown board 'zc707'"),
        "{}",
        stderr(&o)
    );
}
