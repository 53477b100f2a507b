//! The record beats (spec §9.4): the spec's table is the layout of
//! `fcc_pixel::record`, and a record of the largest frame the hardware takes
//! (`fcc_params::limits`) has its beats.

use fcc_params::limits;
use fcc_pixel::record::{HwRecord, END_LAYOUT, RECORD_LAYOUT, RECORD_WORDS};

/// The cells of the table rows (not the header) of docs/spec.md between
/// `from` and the next of `to` or a new chapter.
fn spec_table(from: &str, to: &str) -> Vec<Vec<String>> {
    let spec = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/spec.md"))
        .expect("docs/spec.md");
    let start = spec.find(from).unwrap_or_else(|| panic!("spec: {from}"));
    let section = &spec[start + from.len()..];
    let end = [to, "\n## "]
        .iter()
        .filter_map(|m| section.find(m))
        .min()
        .unwrap_or(section.len());
    section[..end]
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("|--"))
        .skip(1)
        .map(|l| {
            let c: Vec<&str> = l.split('|').map(str::trim).collect();
            c[1..c.len() - 1]
                .iter()
                .map(|x| x.trim_matches('`').to_string())
                .collect()
        })
        .collect()
}

/// The rows of the spec's §9.4 table: beat, lsb, bits, signed, field.
fn spec_rows() -> Vec<(usize, u32, u32, bool, String)> {
    spec_table("### 9.4 Record beats", "**Frame end.**")
        .into_iter()
        .map(|c| {
            (
                c[0].parse().unwrap(),
                c[1].parse().unwrap(),
                c[2].parse().unwrap(),
                match c[3].as_str() {
                    "yes" => true,
                    "no" => false,
                    other => panic!("spec §9.4: signed is {other:?} in {c:?}"),
                },
                c[4].clone(),
            )
        })
        .collect()
}

#[test]
fn the_spec_table_is_the_layout() {
    let rows = spec_rows();
    let layout: Vec<_> = RECORD_LAYOUT
        .iter()
        .map(|l| (l.word, l.lsb, l.bits, l.signed, l.name.to_string()))
        .collect();
    for (k, (want, got)) in layout.iter().zip(&rows).enumerate() {
        assert_eq!(
            got, want,
            "spec §9.4 row {k}: expected (layout) {want:?}, got (spec) {got:?}"
        );
    }
    assert_eq!(rows.len(), layout.len(), "spec §9.4 rows");
    let beats = 1 + RECORD_LAYOUT.iter().map(|l| l.word).max().unwrap();
    assert_eq!(beats, RECORD_WORDS);
    let spec =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/spec.md")).unwrap();
    assert!(spec.contains(&format!("**{RECORD_WORDS} beats of 64 bits**")));
}

#[test]
fn a_record_of_the_largest_frame_has_its_beats() {
    let (rows, cols) = (*limits::HW_ROWS.end() as u32, *limits::HW_COLS.end() as u32);
    let n = i64::from(rows * cols);
    let (lo, hi) = (i64::from(i16::MIN), i64::from(i16::MAX));
    for (sum, sq, cross) in [
        (lo * n, lo * lo * n, lo * lo * n),
        (hi * n, hi * hi * n, lo * hi * n),
    ] {
        let r = HwRecord {
            id: rows * cols,
            points: rows * cols,
            first_col: cols - 1,
            last_col: cols - 1,
            closed_col: cols,
            seam: true,
            first_row: rows - 1,
            last_row: rows - 1,
            min: [i16::MIN; 3],
            max: [i16::MAX; 3],
            range2_min: 3 << 30,
            range2_max: 3 << 30,
            sum: [sum; 3],
            sum_xx: sq,
            sum_xy: cross,
            sum_yy: sq,
        };
        let words = r.pack().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(HwRecord::unpack(&words), Ok(r));
    }
}

/// The rows of the spec's end-beat table (§9.4, "Frame end"): lsb, bits,
/// field.
fn spec_end_rows() -> Vec<(u32, u32, String)> {
    spec_table("**Frame end.**", "\n### ")
        .into_iter()
        .map(|c| (c[0].parse().unwrap(), c[1].parse().unwrap(), c[2].clone()))
        .collect()
}

#[test]
fn the_spec_end_beat_table_is_the_layout() {
    let rows = spec_end_rows();
    let layout: Vec<_> = END_LAYOUT
        .iter()
        .map(|l| (l.lsb, l.bits, l.name.to_string()))
        .collect();
    assert_eq!(
        rows, layout,
        "spec §9.4's end beat: got (spec), expected (layout)"
    );
}
