//! The documents quote no resource count of their own: the numbers live in
//! docs/results.md and docs/results.json, written by `fcc results`.

use std::path::Path;

fn doc(name: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs")
        .join(name);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn rtl_doc_has_no_hand_typed_resource_table() {
    let text = doc("rtl.md");
    let lines: Vec<&str> = text.lines().collect();
    for (i, line) in lines.iter().enumerate() {
        // A table header: a row followed by the `|---|` separator.
        let header = line.trim_start().starts_with('|')
            && lines.get(i + 1).is_some_and(|l| {
                l.trim_start().starts_with("|-") || l.trim_start().starts_with("| -")
            });
        let names_a_resource = ["LUT", "FDRE", "RAMB36E1", "DSP48E1"]
            .iter()
            .any(|r| line.contains(r));
        assert!(
            !(header && names_a_resource),
            "docs/rtl.md line {}: a resource table typed by hand (`{line}`); quote docs/results.md instead",
            i + 1
        );
    }
}
