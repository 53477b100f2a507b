//! The targets, and a result row checked against them.

use fcc_params::FccParams;
use serde::{Deserialize, Serialize};

use crate::Resources;

use super::{thousands, ResultRow, PAPER_TABLE_I};

/// What the design has to reach, for one configuration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Targets {
    pub rows: usize,
    pub cols: usize,
    pub fsize: usize,
    pub slice_luts: u64,
    pub ff: u64,
    pub dsp48e1: u64,
    /// RAMB36 equivalents.
    pub bram36: f64,
    /// Pre-route critical path (Yosys `sta`), ns.
    pub critical_path_ns: f64,
    /// Cycles per frame divided by rows x cols.
    pub cycles_per_pixel: f64,
    /// Most general-routing hops on any path ([`crate::routing`]).
    pub routing_hops: u32,
    /// Most loads on any net but the clock.
    pub net_loads: usize,
}

/// The corpus name of the synthetic 64 x 2048 scenes the cycle target is about.
pub const SYNTHETIC_CORPUS: &str = "synthetic";

/// The targets: K = 7 on 64 x 2048, no more logic than the paper, a quarter
/// of its block RAM (90 of 362.5 tiles), a 3.0 ns pre-route path, at most
/// 1.3 cycles per pixel, no path over 5 routing hops and no net but the clock
/// over 64 loads.
pub const TARGETS: Targets = Targets {
    rows: 64,
    cols: 2048,
    fsize: 7,
    slice_luts: PAPER_TABLE_I[2].lut,
    ff: PAPER_TABLE_I[2].ff,
    dsp48e1: PAPER_TABLE_I[2].dsp,
    bram36: 90.0,
    critical_path_ns: 3.0,
    cycles_per_pixel: 1.3,
    routing_hops: crate::routing::HOP_LIMIT,
    net_loads: crate::routing::FANOUT_LIMIT,
};

impl Targets {
    /// Whether these targets are about the configuration `p` (K aside from `fsize`).
    pub fn applies_to(&self, p: &FccParams) -> bool {
        p.rows == self.rows && p.cols == self.cols && p.fsize == self.fsize
    }
}

/// Whether a measured value meets an upper bound, and by how much.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TargetCheck {
    pub metric: String,
    pub target: String,
    /// `None` when not measured.
    pub measured: Option<String>,
    /// `Some(true)` met, `Some(false)` missed, `None` not measured.
    pub met: Option<bool>,
    /// `1,234 over (13.3 %)` or `500 under (5.4 %)`.
    pub margin: String,
    /// What the number is made of.
    pub dominated_by: String,
}

fn margin(measured: f64, target: f64, unit: &str, decimals: usize) -> String {
    let diff = measured - target;
    if diff == 0.0 {
        return "exactly at the target".to_string();
    }
    let pct = if target != 0.0 {
        100.0 * diff.abs() / target
    } else {
        0.0
    };
    let amount = if decimals == 0 {
        thousands(diff.abs().round() as u64)
    } else {
        format!("{:.*}", decimals, diff.abs())
    };
    let word = if diff > 0.0 { "over" } else { "under" };
    format!("{amount}{unit} {word} ({pct:.1} %)")
}

fn check(
    metric: &str,
    target: f64,
    measured: Option<f64>,
    unit: &str,
    decimals: usize,
    dominated_by: String,
) -> TargetCheck {
    let show = |x: f64| {
        if decimals == 0 {
            thousands(x.round() as u64)
        } else {
            format!("{x:.decimals$}")
        }
    };
    TargetCheck {
        metric: metric.to_string(),
        target: format!("<= {}{unit}", show(target)),
        measured: measured.map(|m| format!("{}{unit}", show(m))),
        met: measured.map(|m| m <= target),
        margin: measured
            .map(|m| margin(m, target, unit, decimals))
            .unwrap_or_else(|| "not measured".to_string()),
        dominated_by,
    }
}

/// The two largest blocks for `metric`, with their share of the by-block total.
fn top_blocks(row: &ResultRow, metric: impl Fn(&Resources) -> f64) -> Option<String> {
    let blocks = row.by_block.as_ref()?;
    let total: f64 = blocks.values().map(&metric).sum();
    if total <= 0.0 {
        return None;
    }
    let mut v: Vec<(&String, f64)> = blocks.iter().map(|(n, r)| (n, metric(r))).collect();
    v.sort_by(|a, b| b.1.total_cmp(&a.1).then_with(|| a.0.cmp(b.0)));
    Some(
        v.iter()
            .take(2)
            .filter(|(_, x)| *x > 0.0)
            .map(|(n, x)| format!("{n} {:.0} %", 100.0 * x / total))
            .collect::<Vec<_>>()
            .join(", "),
    )
}

/// The largest cell types whose name starts with one of `prefixes`.
fn top_cells(r: &Resources, prefixes: &[&str]) -> String {
    let mut v: Vec<(&String, &u64)> = r
        .by_type
        .iter()
        .filter(|(t, _)| prefixes.iter().any(|p| t.starts_with(p)))
        .collect();
    v.sort_by(|a, b| b.1.cmp(a.1).then_with(|| a.0.cmp(b.0)));
    v.iter()
        .take(3)
        .map(|(t, n)| format!("{t} x {}", thousands(**n)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Check `row` against `t` (the row's configuration is `t`'s).
pub fn check_targets(row: &ResultRow, t: &Targets) -> Vec<TargetCheck> {
    let r = row.resources.as_ref();
    let dom = |metric: fn(&Resources) -> f64, cells: &[&str]| -> String {
        top_blocks(row, metric)
            .or_else(|| r.map(|r| top_cells(r, cells)))
            .unwrap_or_default()
    };
    let pixels = (t.rows * t.cols) as f64;
    // The target is about the synthetic R x C scenes; real sensors of other
    // sizes are reported in the cycles table.
    let worst_cycles = row
        .cycles
        .iter()
        .filter(|c| c.corpus == SYNTHETIC_CORPUS)
        .map(|c| c.max_cycles_per_frame)
        .reduce(f64::max);
    vec![
        check(
            "Slice LUTs",
            t.slice_luts as f64,
            r.map(|r| r.slice_luts as f64),
            "",
            0,
            dom(
                |r| r.slice_luts as f64,
                &[
                    "LUT", "INV", "RAM16", "RAM32", "RAM64", "RAM128", "RAM256", "SRL",
                ],
            ),
        ),
        check(
            "FF",
            t.ff as f64,
            r.map(|r| r.ff as f64),
            "",
            0,
            dom(|r| r.ff as f64, &["FD"]),
        ),
        check(
            "DSP48E1",
            t.dsp48e1 as f64,
            r.map(|r| r.dsp48e1 as f64),
            "",
            0,
            dom(|r| r.dsp48e1 as f64, &["DSP"]),
        ),
        check(
            "Block RAM (RAMB36 eq.)",
            t.bram36,
            r.map(|r| r.bram36),
            "",
            1,
            dom(|r| r.bram36, &["RAMB"]),
        ),
        check(
            "Pre-route critical path",
            t.critical_path_ns,
            row.timing.as_ref().map(|x| x.critical_path_ns),
            " ns",
            3,
            row.timing
                .as_ref()
                .map(|x| {
                    let through = x
                        .through
                        .iter()
                        .map(|(b, n)| format!("{b} {n}"))
                        .collect::<Vec<_>>()
                        .join(", ");
                    format!(
                        "{} to {}, {} logic levels ({through})",
                        x.start, x.end, x.logic_levels
                    )
                })
                .unwrap_or_default(),
        ),
        check(
            "Routing hops on the longest path",
            t.routing_hops as f64,
            row.routing.as_ref().map(|x| x.worst_hops as f64),
            "",
            0,
            row.routing
                .as_ref()
                .and_then(|x| x.worst_paths.first())
                .map(|p| format!("{} to {}", p.start, p.end))
                .unwrap_or_default(),
        ),
        check(
            "Loads on the highest-fanout net nothing replicates (clock aside)",
            t.net_loads as f64,
            unreplicated_top(row).map(|n| n.loads as f64),
            "",
            0,
            unreplicated_top(row)
                .map(|n| format!("{} (driven by {})", n.net, n.driver))
                .unwrap_or_default(),
        ),
        check(
            "Cycles per frame (worst synthetic scene)",
            t.cycles_per_pixel * pixels,
            worst_cycles,
            "",
            0,
            format!("target is {} x {} x {}", t.cycles_per_pixel, t.rows, t.cols),
        ),
    ]
}

/// The highest-fanout net whose driver carries no `max_fanout` at or below
/// the limit (a report that did not read the attribute: the highest of all).
fn unreplicated_top(row: &ResultRow) -> Option<&crate::routing::NetFanout> {
    let r = row.routing.as_ref()?;
    match r.unreplicated_over_limit {
        Some(_) => r.top_unreplicated.first(),
        None => r.top_fanout.first(),
    }
}
