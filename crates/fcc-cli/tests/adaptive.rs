//! Range-adaptive thresholds on the command line (spec §2): `--preset
//! adaptive` is its slopes, the preset and explicit thresholds exclude each
//! other, slopes out of range are refused, and slopes 0 are the fixed
//! contract (the core takes slopes as run registers: the board test).

use fcc_testkit::{s, stderr, tmpdir};
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

fn labels(p: &std::path::Path) -> Vec<u32> {
    fcc_npy::read_labels(p).unwrap().labels
}

#[test]
fn preset_adaptive_is_its_slopes_and_joins_far_objects() {
    let d = tmpdir("adaptive");
    let (npy, gt) = (d.join("f.npy"), d.join("gt.npy"));
    let o = fcc(&["scene", "--seed", "5", "--output", s(&npy), "--gt", s(&gt)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (a, b, c, z) = (
        d.join("a.npy"),
        d.join("b.npy"),
        d.join("c.npy"),
        d.join("z.npy"),
    );
    let run = |out: &std::path::Path, extra: &[&str]| {
        let mut args = vec!["cluster", "--input", s(&npy), "--output", s(out)];
        args.extend_from_slice(extra);
        let o = fcc(&args);
        assert!(o.status.success(), "{extra:?}: {}", stderr(&o));
    };
    let (th_h, th_v, ah, av) = fcc_params::ADAPTIVE;
    let (th_h, th_v, ah, av) = (
        th_h.to_string(),
        th_v.to_string(),
        ah.to_string(),
        av.to_string(),
    );
    run(&a, &["--preset", "adaptive"]);
    run(
        &b,
        &[
            "--th-h",
            &th_h,
            "--th-v",
            &th_v,
            "--th-h-slope",
            &ah,
            "--th-v-slope",
            &av,
        ],
    );
    run(&c, &[]);
    run(&z, &["--preset", "paper"]);
    assert_eq!(labels(&a), labels(&b));
    assert_eq!(labels(&c), labels(&z));
    run(&z, &["--th-h-slope", "0", "--th-v-slope", "0"]);
    assert_eq!(labels(&c), labels(&z));
    let count = |l: Vec<u32>| *l.iter().max().unwrap();
    assert!(
        count(labels(&a)) < count(labels(&c)),
        "the slopes join nothing"
    );
}

#[test]
fn slopes_out_of_range_and_presets_mixed_with_thresholds_are_refused() {
    let d = tmpdir("adaptive-refusals");
    let npy = d.join("f.npy");
    let o = fcc(&[
        "scene",
        "--seed",
        "1",
        "--rows",
        "16",
        "--cols",
        "256",
        "--output",
        s(&npy),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for (args, why) in [
        (
            vec!["cluster", "--input", s(&npy), "--th-v-slope", "1.5"],
            "th_v_slope = 1.5 is out of range: 0 <= th_v_slope < 1 metre per metre",
        ),
        (
            vec![
                "cluster",
                "--input",
                s(&npy),
                "--preset",
                "adaptive",
                "--th-v",
                "0.8",
            ],
            "cannot be used with",
        ),
    ] {
        let o = fcc(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(why), "{args:?}: {}", stderr(&o));
    }
}

#[test]
fn eval_reports_pq_by_range_band_and_takes_the_preset() {
    let o = fcc(&[
        "eval",
        "--synthetic",
        "2",
        "--scene-rows",
        "32",
        "--scene-cols",
        "512",
        "--fsize",
        "7",
        "--merge",
        "exact",
        "--preset",
        "adaptive",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("slopes 0.02 / 0.05 m per m"), "{out}");
    assert!(
        out.contains("| K | merge | 0-20 m | 20-40 m | 40-80 m |"),
        "{out}"
    );
    assert!(
        out.lines()
            .any(|l| l.starts_with("| 7 | exact | 0.") && l.matches('(').count() == 3),
        "{out}"
    );
}

#[test]
fn bench_takes_the_preset_and_says_what_it_timed() {
    let o = fcc(&[
        "bench", "--fsize", "3", "--frames", "1", "--repeat", "1", "--rows", "16", "--cols", "128",
        "--preset", "adaptive",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("th_H = 0.5 m, th_V = 1 m, slopes 0.02 / 0.05 m per m"),
        "{out}"
    );
    let o = fcc(&["bench", "--preset", "adaptive", "--th-v", "2"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("cannot be used with"), "{}", stderr(&o));
}
