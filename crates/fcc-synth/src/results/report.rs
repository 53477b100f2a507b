//! The results document as data: one row per K, the cycles, golden-model
//! times and coverage attached to it, and its JSON.

use std::collections::BTreeMap;
use std::path::Path;

use fcc_params::{FccParams, Scan};
use serde::{Deserialize, Serialize};

use crate::routing::Routing;
use crate::yosys::YosysRun;
use crate::{io_err, Resources, SynthError, Timing};

use super::{render_markdown, StreamCycles, PAPER_CLOCK_MHZ};

/// Frame time and rate at one clock.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Throughput {
    pub clock_mhz: f64,
    pub frame_ms: f64,
    pub frames_per_s: f64,
}

impl Throughput {
    pub fn new(cycles_per_frame: f64, clock_mhz: f64) -> Throughput {
        let frame_ms = cycles_per_frame / (clock_mhz * 1e3);
        Throughput {
            clock_mhz,
            frame_ms,
            frames_per_s: 1e3 / frame_ms,
        }
    }
}

/// Cycles measured by the Verilator bench on one corpus.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CycleMeasure {
    /// The frames, e.g. `synthetic` or `ouster`.
    pub corpus: String,
    pub frames: u64,
    /// Mean cycles from the first input pixel to the last output beat.
    pub cycles_per_frame: f64,
    /// Largest cycles per frame over the corpus.
    pub max_cycles_per_frame: f64,
    /// Mean cycles from the last input pixel to the last output beat.
    pub latency_cycles: f64,
    /// `max_cycles_per_frame / (rows x cols)`.
    pub max_cycles_per_pixel: f64,
    /// At the paper's clock, from the mean.
    pub at_paper_clock: Throughput,
    /// At the clock the XDC asks for, from the mean.
    pub at_xdc_clock: Throughput,
}

impl CycleMeasure {
    /// Derive the rates of one corpus measurement for the configuration `p`.
    pub fn new(
        corpus: &str,
        frames: u64,
        cycles_per_frame: f64,
        max_cycles_per_frame: f64,
        latency_cycles: f64,
        p: &FccParams,
    ) -> CycleMeasure {
        CycleMeasure {
            corpus: corpus.to_string(),
            frames,
            cycles_per_frame,
            max_cycles_per_frame,
            latency_cycles,
            max_cycles_per_pixel: max_cycles_per_frame / p.pixels() as f64,
            at_paper_clock: Throughput::new(cycles_per_frame, PAPER_CLOCK_MHZ),
            at_xdc_clock: Throughput::new(cycles_per_frame, p.clock_mhz),
        }
    }
}

/// One line of the cycle counts the Verilator bench writes, as read by
/// [`Report::attach_cycles_json`]: a JSON array of these.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CycleInput {
    pub fsize: usize,
    pub corpus: String,
    pub frames: u64,
    /// Pixels per frame when the corpus is not the row's R x C (real sensors).
    #[serde(default)]
    pub pixels: Option<usize>,
    pub cycles_per_frame: f64,
    pub max_cycles_per_frame: f64,
    pub latency_cycles: f64,
}

/// Golden-model time per frame, from `fcc bench --json`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GoldenTiming {
    /// Median ms per frame, one thread, exact merging, release build.
    pub exact_ms: f64,
    /// Frames per second clustering a batch on all threads, exact merging.
    pub batch_frames_per_s: f64,
    /// Threads of the batch run.
    #[serde(default)]
    pub threads: Option<usize>,
    /// Median ms per frame, one thread, `paper` merging.
    #[serde(default)]
    pub paper_ms: Option<f64>,
    /// Frames per second of the batch, `paper` merging.
    #[serde(default)]
    pub paper_batch_frames_per_s: Option<f64>,
    /// The batch rate over the same batch's rate on one thread, exact
    /// merging (absent from older bench files).
    #[serde(default)]
    pub speedup: Option<f64>,
}

/// Everything measured for one K.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ResultRow {
    pub fsize: usize,
    /// Hash of the parameters the RTL was generated from.
    pub params_hash: String,
    pub resources: Option<Resources>,
    pub timing: Option<Timing>,
    /// Fanout and routing hops of the netlist.
    #[serde(default)]
    pub routing: Option<Routing>,
    /// Cells per first-level block (when asked for).
    #[serde(default)]
    pub by_block: Option<BTreeMap<String, Resources>>,
    /// Why synthesis gave no numbers, if it did not.
    #[serde(default)]
    pub synth_error: Option<String>,
    /// Wall-clock seconds of Yosys.
    #[serde(default)]
    pub synth_seconds: Option<f64>,
    /// Verilator cycles, one entry per corpus; empty until measured.
    #[serde(default)]
    pub cycles: Vec<CycleMeasure>,
    /// Golden-model time; `None` until measured.
    #[serde(default)]
    pub golden: Option<GoldenTiming>,
}

impl ResultRow {
    /// A row from the outcome of one synthesis of `p`.
    pub fn from_run(p: &FccParams, run: Result<YosysRun, String>) -> ResultRow {
        let mut row = ResultRow {
            fsize: p.fsize,
            params_hash: p.hash(),
            resources: None,
            timing: None,
            routing: None,
            by_block: None,
            synth_error: None,
            synth_seconds: None,
            cycles: vec![],
            golden: None,
        };
        match run {
            Ok(r) => {
                row.resources = Some(r.resources);
                row.timing = r.timing;
                row.routing = r.routing;
                row.by_block = r.by_block;
                row.synth_seconds = Some(r.seconds);
            }
            Err(e) => row.synth_error = Some(e),
        }
        row
    }
}

/// The whole results document.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Report {
    /// The configuration every row shares (its `fsize` is that of the targets' row or the first row).
    pub base: FccParams,
    /// `yosys -V` of the runs.
    pub yosys_version: Option<String>,
    /// The command that regenerates the report.
    pub command: String,
    pub rows: Vec<ResultRow>,
    /// Verilator line and toggle coverage per block (`sim/coverage.sh`);
    /// `None` until attached.
    #[serde(default)]
    pub coverage: Option<Coverage>,
    /// Clustering quality of the golden model beside DBSCAN
    /// (`bench/quality.py`); `None` until attached.
    #[serde(default)]
    pub quality: Option<Quality>,
    /// The column-streaming core's report (`fcc synth --all --scan column`),
    /// rendered as a section beside these rows; `None` until measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub column: Option<Box<Report>>,
    /// A column core's report: its cycles and record latency (`fcc cycles
    /// --scan column --json`); empty until attached.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stream_cycles: Vec<StreamCycles>,
}

/// The summary `bench/quality.py --json` writes (docs/quality.json).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Quality {
    pub scenes: QualityScenes,
    pub dbscan: QualityDbscan,
    pub timing_ms_per_frame: QualityTiming,
    pub rows: Vec<QualityRow>,
}

/// The scenes of the quality table: seeds `[first, last]` of `fcc scene`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityScenes {
    pub rows: usize,
    pub cols: usize,
    pub tune_seeds: [u64; 2],
    pub held_out_seeds: [u64; 2],
    pub ground: String,
}

/// DBSCAN's library and the setting chosen on the tuning scenes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityDbscan {
    pub library: String,
    pub eps: f64,
    pub min_samples: u32,
    pub grid: Vec<QualityGridPoint>,
}

/// One DBSCAN setting tried on the tuning scenes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityGridPoint {
    pub eps: f64,
    pub min_samples: u32,
    pub pq: f64,
}

/// Time per frame, milliseconds (golden model on one thread at K = 7).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityTiming {
    pub fcc_paper_k7_ms: f64,
    pub fcc_adaptive_k7_ms: f64,
    pub dbscan_ms: f64,
}

/// One clusterer on one split (`held_out` or `all`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityRow {
    /// `fcc` or `dbscan`.
    pub clusterer: String,
    #[serde(default)]
    pub preset: Option<String>,
    #[serde(default)]
    pub fsize: Option<usize>,
    pub split: String,
    pub pq: f64,
    pub sq: f64,
    pub rq: f64,
    pub over_segmentation: f64,
    pub under_segmentation: f64,
    pub bands: Vec<QualityBand>,
}

/// PQ of one range band, metres `[lo, hi)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct QualityBand {
    pub lo: f64,
    pub hi: f64,
    pub pq: f64,
    pub instances: u64,
}

/// Line and toggle coverage of one block of `fcc_top`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BlockCoverage {
    pub block: String,
    pub line_hit: u64,
    pub line_total: u64,
    pub toggle_hit: u64,
    pub toggle_total: u64,
}

/// The coverage summary `sim/coverage_summary.py --json` writes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Coverage {
    /// The command that measured it.
    pub command: String,
    /// The commit whose generator built the models (absent in older files).
    #[serde(default)]
    pub rtl: Option<String>,
    /// Simulated model instances the counts come from.
    pub instances: u64,
    pub blocks: Vec<BlockCoverage>,
}

/// One line of the golden model bench's JSON (other fields are ignored).
#[derive(Debug, Deserialize)]
struct BenchLine {
    fsize: usize,
    exact_ms: f64,
    batch_frames_per_s: f64,
    #[serde(default)]
    threads: Option<usize>,
    #[serde(default)]
    paper_ms: Option<f64>,
    #[serde(default)]
    paper_batch_frames_per_s: Option<f64>,
    #[serde(default)]
    speedup: Option<f64>,
}

impl Report {
    /// Read a report written by [`write_report`].
    pub fn from_json(text: &str) -> Result<Report, String> {
        serde_json::from_str(text).map_err(|e| format!("not a results JSON file: {e}"))
    }

    /// Attach the coverage summary of `sim/coverage.sh` (replacing any earlier one).
    /// Returns how many blocks it has.
    pub fn attach_coverage_json(&mut self, text: &str) -> Result<usize, String> {
        let c: Coverage = serde_json::from_str(text)
            .map_err(|e| format!("not the JSON of `sim/coverage_summary.py --json`: {e}"))?;
        if c.blocks.is_empty() {
            return Err("the coverage summary lists no block".into());
        }
        for b in &c.blocks {
            if b.line_hit > b.line_total || b.toggle_hit > b.toggle_total {
                return Err(format!(
                    "block {}: more points reached than there are",
                    b.block
                ));
            }
        }
        let n = c.blocks.len();
        self.coverage = Some(c);
        Ok(n)
    }

    /// Attach the quality summary of `bench/quality.py` (replacing any
    /// earlier one). Returns how many rows it has.
    pub fn attach_quality_json(&mut self, text: &str) -> Result<usize, String> {
        let q: Quality = serde_json::from_str(text)
            .map_err(|e| format!("not the JSON of `bench/quality.py --json`: {e}"))?;
        if !q.rows.iter().any(|r| r.split == "held_out") {
            return Err("the quality summary has no held-out row".into());
        }
        if let Some(r) = q
            .rows
            .iter()
            .find(|r| r.clusterer == "fcc" && r.fsize.is_none())
        {
            return Err(format!(
                "an FCC row ({:?}) without its filter size",
                r.preset
            ));
        }
        let n = q.rows.len();
        self.quality = Some(q);
        Ok(n)
    }

    /// Attach the golden-model times of `fcc bench --json` to the rows of the same K.
    /// Returns how many rows got a time.
    pub fn attach_golden_bench(&mut self, bench_json: &str) -> Result<usize, String> {
        let lines: Vec<BenchLine> = serde_json::from_str(bench_json)
            .map_err(|e| format!("not the JSON of `fcc bench --json`: {e}"))?;
        let mut n = 0;
        for l in lines {
            if let Some(row) = self.rows.iter_mut().find(|r| r.fsize == l.fsize) {
                row.golden = Some(GoldenTiming {
                    exact_ms: l.exact_ms,
                    batch_frames_per_s: l.batch_frames_per_s,
                    threads: l.threads,
                    paper_ms: l.paper_ms,
                    paper_batch_frames_per_s: l.paper_batch_frames_per_s,
                    speedup: l.speedup,
                });
                n += 1;
            }
        }
        Ok(n)
    }

    /// Attach one corpus's cycles to the row of `fsize`, replacing an earlier
    /// measurement of the same corpus. False when there is no such row.
    pub fn attach_cycles(&mut self, fsize: usize, m: CycleMeasure) -> bool {
        match self.rows.iter_mut().find(|r| r.fsize == fsize) {
            Some(row) => {
                row.cycles.retain(|c| c.corpus != m.corpus);
                row.cycles.push(m);
                true
            }
            None => false,
        }
    }

    /// Attach the cycle counts of a JSON array of [`CycleInput`]. Returns how
    /// many rows got one; a line whose K has no row is an error.
    pub fn attach_cycles_json(&mut self, text: &str) -> Result<usize, String> {
        if self.base.scan == Scan::Column {
            return self.attach_stream_cycles_json(text);
        }
        let lines: Vec<CycleInput> = serde_json::from_str(text).map_err(|e| {
            format!("not a JSON array of {{fsize, corpus, frames, cycles_per_frame, max_cycles_per_frame, latency_cycles}}: {e}")
        })?;
        for l in &lines {
            let mut p = self.params_for(l.fsize);
            if let Some(px) = l.pixels {
                // Only the pixel count and the clock enter the rates.
                (p.rows, p.cols) = (1, px);
            }
            let m = CycleMeasure::new(
                &l.corpus,
                l.frames,
                l.cycles_per_frame,
                l.max_cycles_per_frame,
                l.latency_cycles,
                &p,
            );
            if !self.attach_cycles(l.fsize, m) {
                return Err(format!(
                    "cycles for K = {}, but the report has no such row",
                    l.fsize
                ));
            }
        }
        Ok(lines.len())
    }

    /// A column core's report: attach the JSON array of [`StreamCycles`]
    /// `fcc cycles --scan column --json` writes, replacing what the report
    /// held for the same K and corpus.
    fn attach_stream_cycles_json(&mut self, text: &str) -> Result<usize, String> {
        let lines: Vec<StreamCycles> = serde_json::from_str(text).map_err(|e| {
            format!("not the JSON of `fcc cycles --scan column` (an array of {{fsize, corpus, frames, rows, pixels, cycles_per_pixel, ...}}): {e}")
        })?;
        for l in &lines {
            if !self.rows.iter().any(|r| r.fsize == l.fsize) {
                return Err(format!(
                    "cycles for K = {}, but the report has no such row",
                    l.fsize
                ));
            }
            self.stream_cycles
                .retain(|m| (m.fsize, &m.corpus) != (l.fsize, &l.corpus));
            self.stream_cycles.push(l.clone());
        }
        self.stream_cycles
            .sort_by(|a, b| (a.fsize, &a.corpus).cmp(&(b.fsize, &b.corpus)));
        Ok(lines.len())
    }

    /// Put the column core's report `col` into this row-major core's report
    /// (replacing the one it held). Either report's other core is refused.
    pub fn set_column(&mut self, col: Report) -> Result<(), String> {
        if self.base.scan != Scan::Row || col.base.scan != Scan::Column {
            return Err(format!(
                "a {} core's report cannot take a {} core's as its column part",
                self.base.scan.as_str(),
                col.base.scan.as_str()
            ));
        }
        self.column = Some(Box::new(col));
        Ok(())
    }

    /// The parameters of the row of `fsize`.
    pub fn params_for(&self, fsize: usize) -> FccParams {
        FccParams {
            fsize,
            ..self.base.clone()
        }
    }
}

/// Write the report as Markdown and as JSON.
pub fn write_report(report: &Report, markdown: &Path, json: &Path) -> Result<(), SynthError> {
    for path in [markdown, json] {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir).map_err(io_err("create", dir))?;
        }
    }
    fcc_io::write_atomic(markdown, render_markdown(report).as_bytes())
        .map_err(io_err("write", markdown))?;
    let text =
        serde_json::to_string_pretty(report).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"));
    fcc_io::write_atomic(json, format!("{text}\n").as_bytes()).map_err(io_err("write", json))?;
    Ok(())
}
