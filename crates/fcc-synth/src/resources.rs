//! Xilinx 7-series cell counts, read from Yosys's `stat -json`.
//!
//! Counting follows Vivado's utilisation report, so the numbers sit beside the
//! paper's Table I: "Slice LUTs" are LUTs used as logic plus LUTs used as
//! memory (distributed RAM and shift registers); "Block RAM Tile" counts a
//! RAMB36E1 as one and a RAMB18E1 as a half.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

/// LUT sites taken by each distributed-RAM primitive (7 series).
const LUTRAM_SITES: [(&str, u64); 13] = [
    ("RAM32X1S", 1),
    ("RAM64X1S", 1),
    ("RAM128X1S", 2),
    ("RAM256X1S", 4),
    ("RAM32X1D", 2),
    ("RAM32X1D_1", 2),
    ("RAM64X1D", 2),
    ("RAM64X1D_1", 2),
    ("RAM128X1D", 4),
    ("RAM32M", 4),
    ("RAM64M", 4),
    ("RAM32X2S", 2),
    ("RAM16X1D", 2),
];
/// Shift-register primitives: one LUT each.
const SRL_TYPES: [&str; 4] = ["SRL16", "SRL16E", "SRLC16E", "SRLC32E"];
/// Flip-flops, either clock edge.
const FF_TYPES: [&str; 8] = [
    "FDRE", "FDSE", "FDCE", "FDPE", "FDRE_1", "FDSE_1", "FDCE_1", "FDPE_1",
];
/// Latches (a synchronous design should have none).
const LATCH_TYPES: [&str; 2] = ["LDCE", "LDPE"];
/// LUTs used as logic; `INV` is placed as a LUT1.
const LUT_TYPES: [&str; 7] = ["LUT1", "LUT2", "LUT3", "LUT4", "LUT5", "LUT6", "INV"];

/// Cell counts of one synthesised design.
///
/// Build it with [`Resources::from_cell_counts`] or
/// [`Resources::from_stat_json`]; the totals are derived there, once.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Resources {
    /// Vivado's "Slice LUTs": `lut_logic + lut_memory`.
    pub slice_luts: u64,
    /// LUT1 ..= LUT6 (and INV): LUTs used as logic.
    pub lut_logic: u64,
    /// LUT sites used as memory: distributed RAM (RAM64M = 4, RAM32X1D = 2, ...) plus SRLs.
    pub lut_memory: u64,
    /// Distributed-RAM cells (RAM32M, RAM64M, RAM64X1D, ...), as cells.
    pub lutram_cells: u64,
    /// Shift-register cells (SRL16E, SRLC32E).
    pub srl: u64,
    /// Flip-flops: FDRE, FDSE, FDCE, FDPE.
    pub ff: u64,
    /// Latches: LDCE, LDPE.
    pub latch: u64,
    pub carry4: u64,
    pub muxf7: u64,
    pub muxf8: u64,
    pub dsp48e1: u64,
    /// RAMB36E1 (and FIFO36E1).
    pub ramb36e1: u64,
    /// RAMB18E1 (and FIFO18E1).
    pub ramb18e1: u64,
    /// Block RAM in RAMB36 equivalents: `ramb36e1 + ramb18e1 / 2`.
    pub bram36: f64,
    /// Cells Yosys left as its own generic cells (`$...`); should be 0.
    pub unmapped: u64,
    /// Every cell type and its count.
    pub by_type: BTreeMap<String, u64>,
}

/// One module (or the whole design) in `stat -json`.
#[derive(Debug, Deserialize)]
struct StatModule {
    #[serde(default)]
    num_cells_by_type: BTreeMap<String, u64>,
}

/// The top level of `stat -json`.
#[derive(Debug, Deserialize)]
struct StatJson {
    #[serde(default)]
    modules: BTreeMap<String, StatModule>,
    design: Option<StatModule>,
}

impl Resources {
    /// Classify a map from cell type to count.
    pub fn from_cell_counts(counts: &BTreeMap<String, u64>) -> Resources {
        let by_type: BTreeMap<String, u64> = counts
            .iter()
            .map(|(t, n)| (t.trim_start_matches('\\').to_string(), *n))
            .collect();
        let sum = |types: &[&str]| -> u64 {
            types
                .iter()
                .map(|t| by_type.get(*t).copied().unwrap_or(0))
                .sum()
        };
        let lut_logic = sum(&LUT_TYPES);
        let srl = sum(&SRL_TYPES);
        let (mut lutram_cells, mut lutram_sites) = (0, 0);
        for (t, sites) in LUTRAM_SITES {
            let n = by_type.get(t).copied().unwrap_or(0);
            lutram_cells += n;
            lutram_sites += n * sites;
        }
        let lut_memory = lutram_sites + srl;
        let ramb36e1 = sum(&["RAMB36E1", "FIFO36E1"]);
        let ramb18e1 = sum(&["RAMB18E1", "FIFO18E1"]);
        let unmapped = by_type
            .iter()
            .filter(|(t, _)| t.starts_with('$'))
            .map(|(_, n)| n)
            .sum();
        Resources {
            slice_luts: lut_logic + lut_memory,
            lut_logic,
            lut_memory,
            lutram_cells,
            srl,
            ff: sum(&FF_TYPES),
            latch: sum(&LATCH_TYPES),
            carry4: sum(&["CARRY4"]),
            muxf7: sum(&["MUXF7"]),
            muxf8: sum(&["MUXF8"]),
            dsp48e1: sum(&["DSP48E1"]),
            ramb36e1,
            ramb18e1,
            bram36: ramb36e1 as f64 + 0.5 * ramb18e1 as f64,
            unmapped,
            by_type,
        }
    }

    /// Read the output of `stat -json` after a flattening synthesis.
    ///
    /// Uses the `design` totals when Yosys writes them, otherwise the single
    /// module; several modules without totals means the design was not
    /// flattened, and per-module counts would not add up to the design.
    pub fn from_stat_json(text: &str) -> Result<Resources, String> {
        let stat: StatJson =
            serde_json::from_str(text).map_err(|e| format!("not stat -json output: {e}"))?;
        let module = match (stat.design, stat.modules.len()) {
            (Some(d), _) => d,
            (None, 1) => stat
                .modules
                .into_values()
                .next()
                .ok_or("no modules in stat -json output")?,
            (None, 0) => return Err("no modules in stat -json output".into()),
            (None, _) => {
                return Err(format!(
                    "{} modules and no design totals ({}); synthesise with -flatten",
                    stat.modules.len(),
                    stat.modules.keys().cloned().collect::<Vec<_>>().join(", ")
                ))
            }
        };
        Ok(Resources::from_cell_counts(&module.num_cells_by_type))
    }

    /// Read `stat -json -top TOP` of a synthesis that kept the first-level
    /// blocks as hierarchy: each block's cells (times its instances in the
    /// top), and the top's own cells under the top's name.
    ///
    /// Yosys 0.23 writes the hierarchy of a design kept more than one level
    /// deep into that JSON as text (a line per module: its name and count,
    /// between `modules` and `design`); those lines are left out.
    pub fn blocks_from_stat_json(
        text: &str,
        top: &str,
    ) -> Result<BTreeMap<String, Resources>, String> {
        let json: String = text
            .lines()
            .filter(|l| !is_hierarchy_line(l))
            .flat_map(|l| [l, "\n"])
            .collect();
        let stat: StatJson =
            serde_json::from_str(&json).map_err(|e| format!("not stat -json output: {e}"))?;
        let modules: BTreeMap<String, BTreeMap<String, u64>> = stat
            .modules
            .into_iter()
            .map(|(name, m)| {
                let cells = m
                    .num_cells_by_type
                    .into_iter()
                    .map(|(t, n)| (t.trim_start_matches('\\').to_string(), n))
                    .collect();
                (name.trim_start_matches('\\').to_string(), cells)
            })
            .collect();
        let top_cells = modules
            .get(top)
            .ok_or_else(|| format!("no module `{top}` in stat -json output"))?;
        let own = |cells: &BTreeMap<String, u64>, times: u64| -> BTreeMap<String, u64> {
            cells
                .iter()
                .filter(|(t, _)| !modules.contains_key(*t))
                .map(|(t, n)| (t.clone(), n * times))
                .collect()
        };
        let mut out = BTreeMap::new();
        for (name, cells) in &modules {
            let times = if name == top {
                1
            } else {
                top_cells.get(name).copied().unwrap_or(1)
            };
            out.insert(
                name.clone(),
                Resources::from_cell_counts(&own(cells, times)),
            );
        }
        Ok(out)
    }

    /// The `n` most numerous cell types, largest first.
    pub fn top_types(&self, n: usize) -> Vec<(String, u64)> {
        let mut v: Vec<(String, u64)> = self.by_type.iter().map(|(t, c)| (t.clone(), *c)).collect();
        v.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
        v.truncate(n);
        v
    }
}

/// A line of the hierarchy Yosys 0.23 writes as text into `stat -json -top`
/// (a module's name and its count, no JSON punctuation).
fn is_hierarchy_line(line: &str) -> bool {
    let t = line.trim();
    !t.is_empty() && !t.contains(['"', '{', '}', '[', ']', ',', ':'])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn counts(pairs: &[(&str, u64)]) -> BTreeMap<String, u64> {
        pairs.iter().map(|(t, n)| (t.to_string(), *n)).collect()
    }

    #[test]
    fn luts_as_memory_count_their_sites() {
        let r = Resources::from_cell_counts(&counts(&[
            ("LUT2", 3),
            ("LUT6", 4),
            ("RAM64M", 2),
            ("RAM32X1D", 1),
            ("SRLC32E", 5),
        ]));
        assert_eq!(r.lut_logic, 7);
        assert_eq!(r.lutram_cells, 3);
        assert_eq!(r.srl, 5);
        assert_eq!(r.lut_memory, 2 * 4 + 2 + 5);
        assert_eq!(r.slice_luts, 7 + 15);
    }

    #[test]
    fn ramb18_is_half_a_ramb36() {
        let r = Resources::from_cell_counts(&counts(&[("RAMB36E1", 3), ("RAMB18E1", 3)]));
        assert_eq!(r.bram36, 4.5);
    }

    #[test]
    fn flip_flops_of_both_edges_and_unmapped_cells() {
        let r = Resources::from_cell_counts(&counts(&[
            ("FDRE", 10),
            ("FDSE", 1),
            ("FDCE_1", 2),
            ("$_DFF_P_", 3),
            ("BUFG", 1),
        ]));
        assert_eq!(r.ff, 13);
        assert_eq!(r.unmapped, 3);
        assert_eq!(r.by_type["BUFG"], 1);
    }

    #[test]
    fn several_modules_without_totals_are_refused() {
        let text = r#"{"modules": {"\\a": {"num_cells_by_type": {}}, "\\b": {}}}"#;
        let e = Resources::from_stat_json(text).unwrap_err();
        assert!(e.contains("synthesise with -flatten"), "{e}");
    }

    #[test]
    fn garbage_is_refused_with_the_reason() {
        let e = Resources::from_stat_json("ERROR: something").unwrap_err();
        assert!(e.starts_with("not stat -json output"), "{e}");
    }

    #[test]
    fn the_hierarchy_text_of_yosys_0_23_in_the_json_is_left_out() {
        let text = "{\n   \"modules\": {\n      \"\\\\top\": {\n         \"num_cells_by_type\": {\n\
                    \x20           \"LUT2\": 1,\n            \"core\": 1\n         }\n      },\n\
                    \x20     \"\\\\core\": { \"num_cells_by_type\": { \"FDRE\": 3, \"core__sets\": 1 } },\n\
                    \x20     \"\\\\core__sets\": { \"num_cells_by_type\": { \"LUT6\": 2 } }\n   },\n\
                    \x20      core      1\n         core__sets      1\n\
                    \x20     \"design\": {\n         \"num_cells\": 7\n      }\n}\n";
        assert!(serde_json::from_str::<serde_json::Value>(text).is_err());
        let b = Resources::blocks_from_stat_json(text, "top").unwrap();
        assert_eq!(b["top"].lut_logic, 1);
        assert_eq!(b["core"].ff, 3);
        assert!(!b["core"].by_type.contains_key("core__sets"));
        assert_eq!(b["core__sets"].lut_logic, 2);
    }

    #[test]
    fn blocks_leave_child_instances_out_of_the_top() {
        let text = r#"{"modules": {
            "\\top": {"num_cells_by_type": {"blk": 2, "LUT2": 1}},
            "\\blk": {"num_cells_by_type": {"FDRE": 3, "DSP48E1": 1}}}}"#;
        let b = Resources::blocks_from_stat_json(text, "top").unwrap();
        assert_eq!(b["top"].lut_logic, 1);
        assert!(!b["top"].by_type.contains_key("blk"));
        assert_eq!(b["blk"].ff, 6);
        assert_eq!(b["blk"].dsp48e1, 2);
        let e = Resources::blocks_from_stat_json(text, "other").unwrap_err();
        assert!(e.contains("no module `other`"), "{e}");
    }

    #[test]
    fn top_types_are_sorted_by_count() {
        let r = Resources::from_cell_counts(&counts(&[("FDRE", 5), ("LUT6", 9), ("LUT2", 5)]));
        assert_eq!(
            r.top_types(2),
            vec![("LUT6".to_string(), 9), ("FDRE".to_string(), 5)]
        );
    }
}
