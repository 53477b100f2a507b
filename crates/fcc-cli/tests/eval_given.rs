//! `fcc eval --predicted`: another clusterer's labels scored by FCC's rules.
//! FCC's own labels, given back, score exactly as `fcc eval` scores them;
//! a wrong count, a wrong size or a clustering flag is refused.

use fcc_testkit::{s, stderr, tmpdir};
use std::path::PathBuf;
use std::process::Output;

fn fcc(args: &[&str]) -> Output {
    fcc_testkit::run_in(env!("CARGO_BIN_EXE_fcc"), None, args)
}

/// Two small scenes with their truth and FCC's labels at K = 5.
fn corpus(d: &std::path::Path) -> Vec<(PathBuf, PathBuf, PathBuf)> {
    (3..5)
        .map(|seed| {
            let (npy, gt, lab) = (
                d.join(format!("s{seed}.npy")),
                d.join(format!("g{seed}.npy")),
                d.join(format!("l{seed}.npy")),
            );
            let seed = seed.to_string();
            let o = fcc(&[
                "scene",
                "--seed",
                &seed,
                "--rows",
                "32",
                "--cols",
                "512",
                "--output",
                s(&npy),
                "--gt",
                s(&gt),
            ]);
            assert!(o.status.success(), "{}", stderr(&o));
            let o = fcc(&[
                "cluster",
                "--input",
                s(&npy),
                "--fsize",
                "5",
                "--output",
                s(&lab),
            ]);
            assert!(o.status.success(), "{}", stderr(&o));
            (npy, gt, lab)
        })
        .collect()
}

fn json(p: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

#[test]
fn given_fcc_labels_score_as_fcc_eval_scores_them() {
    let d = tmpdir("eval-given");
    let c = corpus(&d);
    let (fcc_json, given_json) = (d.join("fcc.json"), d.join("given.json"));
    let mut args = vec!["eval", "--input", s(&c[0].0), s(&c[1].0)];
    args.extend(["--truth", s(&c[0].1), s(&c[1].1)]);
    let mut own = args.clone();
    own.extend(["--fsize", "5", "--merge", "exact", "--json", s(&fcc_json)]);
    let o = fcc(&own);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut given = args.clone();
    given.extend([
        "--predicted",
        s(&c[0].2),
        s(&c[1].2),
        "--json",
        s(&given_json),
    ]);
    let o = fcc(&given);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(out.contains("| – | given labels | 0."), "{out}");
    let (a, b) = (json(&fcc_json), json(&given_json));
    let (ra, rb) = (&a["rows"][0], &b["rows"][0]);
    assert_eq!(ra["fsize"], 5);
    assert!(
        rb.get("fsize").is_none() && rb.get("mode").is_none(),
        "{rb}"
    );
    assert_eq!(b["given"], true);
    // Integer counts exactly; ratios and IoU sums to rounding (the sums
    // are taken in hash order).
    let mut ra = ra.clone();
    let own = ra.as_object_mut().unwrap();
    own.remove("fsize");
    own.remove("mode");
    same(&ra, rb, "row");
}

fn same(a: &serde_json::Value, b: &serde_json::Value, at: &str) {
    use serde_json::Value;
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.len(), y.len(), "{at}: fcc eval {a} != given {b}");
            for (k, v) in x {
                same(v, &y[k], &format!("{at}.{k}"));
            }
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{at}: fcc eval {a} != given {b}");
            for (i, (v, w)) in x.iter().zip(y).enumerate() {
                same(v, w, &format!("{at}[{i}]"));
            }
        }
        (Value::Number(x), Value::Number(y)) if x.is_f64() || y.is_f64() => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1.0),
                "{at}: fcc eval {x} != given {y}"
            );
        }
        _ => assert_eq!(a, b, "{at}: fcc eval {a} != given {b}"),
    }
}

#[test]
fn given_labels_are_checked() {
    let d = tmpdir("eval-given-bad");
    let c = corpus(&d);
    let base = ["eval", "--input", s(&c[0].0), "--truth", s(&c[0].1)];
    // One label image per input.
    let mut a = base.to_vec();
    a.extend(["--predicted", s(&c[0].2), s(&c[1].2)]);
    let o = fcc(&a);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("--predicted names 2 files for 1 inputs"),
        "{}",
        stderr(&o)
    );
    // The label image must have the input's size.
    let small = d.join("small.npy");
    let o = fcc(&[
        "scene",
        "--rows",
        "16",
        "--cols",
        "64",
        "--output",
        s(&d.join("x.npy")),
        "--gt",
        s(&small),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut a = base.to_vec();
    a.extend(["--predicted", s(&small)]);
    let o = fcc(&a);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("labels are 16 x 64 but"),
        "{}",
        stderr(&o)
    );
    // A missing file says so.
    let mut a = base.to_vec();
    let missing = d.join("missing.npy");
    a.extend(["--predicted", s(&missing)]);
    let o = fcc(&a);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("missing.npy"), "{}", stderr(&o));
    // Clustering flags do not apply to given labels.
    for flag in [
        ["--fsize", "7"],
        ["--preset", "adaptive"],
        ["--ground", "slope"],
    ] {
        let mut a = base.to_vec();
        a.extend(["--predicted", s(&c[0].2)]);
        a.extend(flag);
        let o = fcc(&a);
        assert!(!o.status.success(), "{flag:?} accepted");
        assert!(stderr(&o).contains("cannot be used with"), "{}", stderr(&o));
    }
}
