//! The results table: resources, pre-route timing, cycles and software time
//! per K, beside the paper's figures and the targets.
//!
//! [`measure`] fills a [`Report`] by generating and synthesising each K;
//! cycles (from the Verilator bench) and golden-model times (from
//! `fcc bench --json`) are attached afterwards. [`render_markdown`] is a pure
//! function of the report, so the document is regenerated, never edited.

mod column;
mod measurement;
mod paper;
mod render;
mod report;
mod targets;
#[cfg(test)]
mod tests;

pub use column::{render_column, ColumnTargets, StreamCycles, COLUMN_TARGETS};
pub use measurement::{measure, yosys_config_for, MeasureOptions};
pub use paper::{
    paper_row, PaperRow, PAPER_CLOCK_MHZ, PAPER_CPU_S_PER_FRAME, PAPER_FRAME_MS, PAPER_TABLE_I,
};
pub use render::{render_markdown, summary_header, summary_row, thousands};
pub use report::{
    write_report, BlockCoverage, Coverage, CycleInput, CycleMeasure, GoldenTiming, Quality,
    QualityBand, QualityDbscan, QualityGridPoint, QualityRow, QualityScenes, QualityTiming, Report,
    ResultRow, Throughput,
};
pub use targets::{check_targets, TargetCheck, Targets, SYNTHETIC_CORPUS, TARGETS};
