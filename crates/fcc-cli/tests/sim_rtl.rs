//! `fcc sim --rtl DIR`: a frame run on a configuration generated once for
//! larger limits, its size, K and thresholds programmed through the run
//! registers; and the errors of a frame or flags the build cannot run.

use fcc_testkit::{s, text, tmpdir};
use std::path::{Path, PathBuf};
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

/// `fcc gen` of `flags` into `d/name` (constraints and scripts beside it).
fn gen(d: &Path, name: &str, flags: &[&str]) -> PathBuf {
    let out = d.join(name);
    let mut args = vec!["gen", "--no-lint", "--out", s(&out)];
    let (xdc, tcl) = (d.join(format!("{name}-xdc")), d.join(format!("{name}-tcl")));
    args.extend(["--constraints", s(&xdc), "--scripts", s(&tcl)]);
    args.extend(flags);
    let o = fcc(&args);
    assert!(o.status.success(), "{}", text(&o));
    out
}

/// The OS-1-64 capture's first frame as a 64 x 1024 .npy.
fn os1_64(d: &Path) -> PathBuf {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fcc-lidar/tests/data");
    let npy = d.join("os1_64.npy");
    let o = fcc(&[
        "convert",
        "--input",
        s(&data.join("OS-1-64_1024x10_fw20.pcap")),
        "--meta",
        s(&data.join("OS-1-64_sensor_config_reduced.json")),
        "--max-frames",
        "1",
        "--output",
        s(&npy),
    ]);
    assert!(o.status.success(), "{}", text(&o));
    npy
}

/// The example of the documentation: a 64 x 1024 frame at K = 7 on the
/// K_max = 11, 128 x 2048, 16-bit core.
#[test]
fn sim_rtl_runs_a_64x1024_frame_at_k7_on_the_k11_128x2048_core() {
    let d = tmpdir("k11");
    let k11 = gen(
        &d,
        "k11",
        &[
            "--fsize",
            "11",
            "--rows",
            "128",
            "--cols",
            "2048",
            "--label-bits",
            "16",
        ],
    );
    let npy = os1_64(&d);
    let o = fcc(&[
        "sim",
        "--rtl",
        s(&k11),
        "--input",
        s(&npy),
        "--fsize",
        "7",
        "--th-h",
        "0.4",
        "--th-v",
        "0.8",
    ]);
    let t = text(&o);
    assert!(o.status.success(), "{t}");
    assert!(t.contains("PASS: 65536 labels match"), "{t}");
    assert!(
        t.contains(
            "run registers: rows=64 cols=1024 fsize=7 th_h=0.4 th_v=0.8 th_h_slope=0 th_v_slope=0"
        ),
        "{t}"
    );
    assert!(t.contains("rows=128 cols=2048 fsize=11"), "{t}");
    // The slopes are run registers too: range-adaptive thresholds on the
    // core built with slopes 0.
    let o = fcc(&[
        "sim",
        "--rtl",
        s(&k11),
        "--input",
        s(&npy),
        "--fsize",
        "5",
        "--th-h-slope",
        "0.01",
        "--th-v-slope",
        "0.035",
    ]);
    let t = text(&o);
    assert!(o.status.success(), "{t}");
    assert!(t.contains("PASS: 65536 labels match"), "{t}");
    assert!(
        t.contains("fsize=5 th_h=0.5 th_v=1 th_h_slope=0.01 th_v_slope=0.035"),
        "{t}"
    );
}

/// Nothing is built or simulated for a frame the build cannot take: each
/// error names what is wrong, and exits with code 2.
#[test]
fn sim_rtl_refuses_what_the_build_cannot_run() {
    let d = tmpdir("small");
    let small = gen(
        &d,
        "small",
        &["--fsize", "5", "--rows", "16", "--cols", "256"],
    );
    let scene = |extra: &[&str]| {
        let mut a = vec!["sim", "--rtl", s(&small), "--scene-seed", "1"];
        a.extend(extra);
        fcc(&a)
    };
    let cases: [(&[&str], &str); 7] = [
        (
            &["--th-v-slope", "1"],
            "th_v_slope = 1 is out of range: 0 <= th_v_slope < 1 metre per metre",
        ),
        (&["--bridge", "4"], "bridge = 4 is out of range"),
        (
            &["--fsize", "7"],
            "RUN_K = 7 is out of range for this build: odd, 3 ..= 5",
        ),
        (
            &["--rows", "17"],
            "RUN_ROWS = 17 is out of range for this build: 1 ..= 16",
        ),
        (
            &["--cols", "31"],
            "RUN_COLS = 31 is out of range for this build: 32 ..= 256",
        ),
        (&["--th-h", "0.001"], "RUN_TH_H = 0 is out of range"),
        (
            &["--label-bits", "12"],
            "--label-bits is fixed by the build",
        ),
    ];
    for (extra, want) in cases {
        let o = scene(extra);
        let t = text(&o);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {t}");
        assert!(t.contains(want), "{extra:?}: expected `{want}` in: {t}");
    }
    let o = fcc(&[
        "sim",
        "--rtl",
        s(&d.join("nothing-here")),
        "--scene-seed",
        "1",
    ]);
    let t = text(&o);
    assert_eq!(o.status.code(), Some(2), "{t}");
    assert!(t.contains("no generated configuration here"), "{t}");
}
