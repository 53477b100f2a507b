//! What the committed files are derived from: the build script's relative
//! paths and the register table of docs/rtl.md. (That the committed
//! `rtl_out/`, `constraints/` and `scripts/` are what `fcc gen --fsize 7`
//! writes is checked by the `committed` test of fcc-cli, on the binary.)

use std::path::Path;

use fcc_params::FccParams;
use fcc_rtl::vivado;

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
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

/// The register table in docs/rtl.md is the one the generator derives from
/// the register map (between the two marker comments).
#[test]
fn rtl_doc_register_table_matches_the_map() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = read(&root.join("docs/rtl.md"));
    let begin =
        "<!-- register map: begin (generated from fcc_rtl::regmap, checked by a test) -->\n";
    let end = "<!-- register map: end -->";
    let start = doc
        .find(begin)
        .unwrap_or_else(|| panic!("docs/rtl.md lacks the marker {begin:?}"))
        + begin.len();
    let stop = doc[start..]
        .find(end)
        .unwrap_or_else(|| panic!("docs/rtl.md lacks the marker {end:?}"))
        + start;
    let want = fcc_rtl::regmap::markdown_table(&FccParams::default());
    assert!(
        doc[start..stop] == want,
        "docs/rtl.md register table differs from the register map; replace it with:\n{want}"
    );
}
