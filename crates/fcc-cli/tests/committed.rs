//! The committed default configuration is exactly what `fcc gen --fsize 7`
//! writes: the whole tree (`rtl_out/`, `constraints/`, `scripts/`) is
//! generated into a scratch directory and compared, file by file and line
//! by line, with the repository's.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use fcc_testkit::{run_in, s, stderr, tmpdir};

/// The directories `fcc gen --out DIR` writes under DIR.
const TREES: [&str; 3] = ["rtl_out", "constraints", "scripts"];

/// Files in those directories that are written by hand, not by `fcc gen`.
const HAND_WRITTEN: [&str; 1] = ["scripts/yosys_stat.sh"];

const REGENERATE: &str =
    "regenerate with `fcc gen --fsize 7` at the repository root, never by hand, and commit";

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The files under `root`'s generated directories, `/`-separated and
/// relative to `root`.
fn tree(root: &Path) -> BTreeSet<String> {
    fn walk(dir: &Path, rel: &str, out: &mut BTreeSet<String>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries {
            let e = e.unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
            let name = e.file_name().to_string_lossy().into_owned();
            let rel = format!("{rel}/{name}");
            if e.path().is_dir() {
                walk(&e.path(), &rel, out);
            } else {
                out.insert(rel);
            }
        }
    }
    let mut out = BTreeSet::new();
    for t in TREES {
        walk(&root.join(t), t, &mut out);
    }
    out
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Where `committed` and `generated` first differ: the 1-based line and
/// both lines (`None` past the end of a file).
fn first_difference<'a>(
    committed: &'a str,
    generated: &'a str,
) -> Option<(usize, Option<&'a str>, Option<&'a str>)> {
    if committed == generated {
        return None;
    }
    let (mut c, mut g) = (committed.split('\n'), generated.split('\n'));
    let mut n = 0;
    loop {
        n += 1;
        match (c.next(), g.next()) {
            (a, b) if a == b && a.is_some() => continue,
            (a, b) => return Some((n, a, b)),
        }
    }
}

#[test]
fn committed_tree_is_what_fcc_gen_writes() {
    let root = repo_root();
    let d = tmpdir("committed");
    let o = run_in(
        env!("CARGO_BIN_EXE_fcc"),
        None,
        &["gen", "--fsize", "7", "--no-lint", "--out", s(&d)],
    );
    assert!(o.status.success(), "fcc gen failed: {}", stderr(&o));

    let generated = tree(&d);
    let committed = tree(&root);
    for f in HAND_WRITTEN {
        assert!(
            committed.contains(f),
            "{f} is listed as hand-written but is not in the repository"
        );
        assert!(
            !generated.contains(f),
            "{f} is listed as hand-written but fcc gen writes it"
        );
    }
    let mut problems = vec![];
    for f in committed.union(&generated) {
        if HAND_WRITTEN.contains(&f.as_str()) {
            continue;
        }
        match (committed.contains(f), generated.contains(f)) {
            (true, false) => problems.push(format!(
                "{f}: in the repository, but fcc gen --fsize 7 does not write it"
            )),
            (false, true) => problems.push(format!(
                "{f}: written by fcc gen --fsize 7, but not in the repository"
            )),
            _ => {
                let (c, g) = (read(&root.join(f)), read(&d.join(f)));
                if let Some((line, a, b)) = first_difference(&c, &g) {
                    let show =
                        |l: Option<&str>| l.map_or("(end of file)".into(), |l| format!("{l:?}"));
                    problems.push(format!(
                        "{f}:{line}: differs from the generator's output\n    committed: {}\n    generated: {}",
                        show(a),
                        show(b)
                    ));
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&d);
    assert!(
        problems.is_empty(),
        "the committed tree is not what fcc gen writes; {REGENERATE}:\n{}",
        problems.join("\n")
    );
    // Every file fcc gen writes is compared: the Verilog and its companions,
    // the XDC, the build, IP-packaging and block-design Tcl, the register
    // header and the C example.
    for f in [
        "rtl_out/fcc_top.v",
        "constraints/fcc_top.xdc",
        "scripts/fcc_build.tcl",
        "scripts/fcc_package_ip.tcl",
        "scripts/fcc_zc706_bd.tcl",
        "scripts/fcc_regs.h",
        "scripts/fcc_zc706_example.c",
    ] {
        assert!(generated.contains(f), "fcc gen no longer writes {f}");
    }
}

#[test]
fn first_difference_names_the_line() {
    assert_eq!(first_difference("a\nb\n", "a\nb\n"), None);
    assert_eq!(
        first_difference("a\nb\nc\n", "a\nx\nc\n"),
        Some((2, Some("b"), Some("x")))
    );
    assert_eq!(
        first_difference("a\n", "a\nb\n"),
        Some((2, Some(""), Some("b")))
    );
    assert_eq!(first_difference("a", "a\n"), Some((2, None, Some(""))));
}
