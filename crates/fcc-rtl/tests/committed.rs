//! The committed default configuration (`rtl_out/`, `constraints/`,
//! `scripts/`) is exactly what the generator writes today.

use std::path::Path;

use fcc_params::FccParams;
use fcc_rtl::{generate, vivado};

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| {
        panic!(
            "{}: {e}; run `cargo run -- gen` from the repository root",
            path.display()
        )
    })
}

#[test]
fn committed_default_rtl_is_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let p = FccParams::default();
    let g = generate(&p).unwrap();
    let mut expected: Vec<(String, String)> = g
        .files()
        .into_iter()
        .map(|(n, t)| (format!("rtl_out/{n}"), t.to_string()))
        .collect();
    expected.push(("constraints/fcc_top.xdc".into(), vivado::xdc(&p)));
    expected.push((
        "scripts/fcc_build.tcl".into(),
        vivado::tcl(&p, "../rtl_out/fcc_top.v", "../constraints/fcc_top.xdc"),
    ));
    for (name, text) in expected {
        let got = read(&root.join(&name));
        assert!(
            got == text,
            "{name} differs from the generator's output; run `cargo run -- gen` and commit"
        );
    }
}

#[test]
fn relative_paths_for_the_build_script() {
    assert_eq!(
        vivado::relative(Path::new("scripts"), Path::new("rtl_out/fcc_top.v")),
        "../rtl_out/fcc_top.v"
    );
    assert_eq!(
        vivado::relative(Path::new("/a/b"), Path::new("/a/b/c/d.v")),
        "c/d.v"
    );
}
