//! `fcc board run`: send frames through the core on a board (Linux, UIO and
//! u-dma-buf) or on the virtual board (the Verilator model of the core with
//! a model of the AXI DMA and memory), with the driver of `fcc-driver`;
//! compare every label with the golden model; write the outputs of
//! `fcc cluster`.

use std::cell::RefCell;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{bail, Context};
use clap::{Args, Subcommand};
use fcc_driver::{Driver, Pixels, RunConfig};
use fcc_golden::MergeMode;
use fcc_lidar::pipeline::{ClosedRecord, PipelineResult};
use fcc_lidar::RangeImage;
use fcc_params::{FccParams, Scan};
use fcc_pixel::record::{FrameEnd, HwRecord, Item};
use fcc_sim::VirtualBoard;

use crate::cmd_lidar::{run_cluster_on, ClusterLidarArgs, Hardware};
use crate::model_args::ModelArgs;

#[derive(Subcommand, Debug)]
pub enum BoardCommand {
    /// Send every frame of the inputs through the core, check every label
    /// against the golden model, print time, clusters and status per frame,
    /// and write the outputs `fcc cluster` writes.
    Run(BoardRunArgs),
}

#[derive(Args, Debug)]
pub struct BoardRunArgs {
    /// The virtual board: one core in Verilator (built on first use, then
    /// cached) behind a model of the AXI DMA and memory; the same driver as
    /// on a board. The core is the K_max = 11, 128 x 2048, 16-bit-label
    /// build, or the one in --rtl DIR; every frame runs at its own size, K
    /// and thresholds, set through the run registers.
    #[arg(long = "virtual", conflicts_with = "uio")]
    pub virtual_board: bool,
    /// With --virtual: the configuration `fcc gen --out DIR` wrote, instead
    /// of the K_max = 11, 128 x 2048 build.
    #[arg(long, value_name = "DIR", requires = "virtual_board")]
    pub rtl: Option<PathBuf>,
    /// With --virtual (without --rtl): the core of the virtual board, `row`
    /// (labels of whole frames) or `column` (the column-streaming core:
    /// pixels in column order, one record per cluster as it closes, checked
    /// against the golden stream and written as `fcc cluster --stream`
    /// writes them). With --rtl or --params the build says which.
    #[arg(
        long,
        value_name = "ORDER",
        requires = "virtual_board",
        conflicts_with = "rtl"
    )]
    pub scan: Option<Scan>,
    /// On a board under Linux: the UIO device of the core's registers and
    /// interrupt (its device-tree node name, or uioN).
    #[arg(long, value_name = "NAME", requires = "params")]
    pub uio: Option<String>,
    /// With --uio: the UIO device of the AXI DMA's registers.
    #[arg(long, value_name = "NAME", default_value = "dma")]
    pub uio_dma: String,
    /// With --uio: the u-dma-buf buffer for the frames (two frames of the
    /// build's size).
    #[arg(long, value_name = "NAME", default_value = "udmabuf0")]
    pub udmabuf: String,
    /// With --uio: the fcc_params.json of the bitstream's core (`fcc gen`
    /// writes it beside the Verilog); its hash must match the core's.
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// With --uio: the board the bitstream's block design was made for
    /// (`fcc gen --board`): its DMA's address width (40 bits on the
    /// ZCU104, 32 on the Zynq-7000 boards).
    #[arg(long, default_value = "zc706", value_parser = crate::cmd_gen::parse_board, requires = "uio")]
    pub board: fcc_rtl::vivado::Board,
    #[command(flatten)]
    pub cluster: ClusterLidarArgs,
}

pub fn run(cmd: &BoardCommand) -> anyhow::Result<()> {
    match cmd {
        BoardCommand::Run(a) => run_board(a),
    }
}

/// The core of `fcc board run --virtual` without --rtl: one build for every
/// sensor (K_max = 11, 128 rows, 2048 columns, 16-bit labels, 4 labels per
/// beat), the same as the run-time-size regression's; of the column core
/// with `scan` column.
pub fn virtual_build(scan: Scan) -> FccParams {
    FccParams {
        rows: 128,
        cols: 2048,
        fsize: 11,
        label_bits: 16,
        labels_per_beat: fcc_driver::LABELS_PER_BEAT,
        scan,
        ..FccParams::default()
    }
}

/// What the golden model runs with beside the core of `build`: the row
/// core keeps the unlimited frame contract; the column core streams, its
/// open limit at most what its record slots hold (511, and that when none
/// is given: the golden stream's "no limit" is more than the core has).
fn check_model_for(args: &BoardRunArgs, build: &FccParams) -> anyhow::Result<ClusterLidarArgs> {
    let mut cluster = args.cluster.clone();
    let m = &mut cluster.model.limits;
    match build.scan {
        Scan::Row => {
            if m.bridge.is_some() || m.ring_reach.is_some() || m.open_limit.is_some() {
                bail!("the row-major core keeps the unlimited contract: drop --bridge, --ring-reach and --open-limit (the column core takes them: --scan column; the golden stream: fcc cluster --stream)");
            }
            if cluster.stream {
                bail!("the row-major core returns labels of whole frames: drop --stream, or run the column core (--scan column)");
            }
        }
        Scan::Column => {
            column_model(&mut cluster.model, cluster.min_points)?;
            cluster.stream = true;
        }
    }
    Ok(cluster)
}

/// The golden stream beside the column core: its open limit at most what
/// the core's record slots hold (511, and that when none is given: the
/// golden stream's "no limit" is more than the core has); no
/// `--min-points` (the core sends a record for every cluster).
fn column_model(model: &mut ModelArgs, min_points: usize) -> anyhow::Result<()> {
    let most = fcc_rtl::regmap::OPEN_LIMIT_MAX;
    match model.limits.open_limit {
        Some(n) if n > most => bail!(
            "--open-limit {n}: the column core holds at most {most} open clusters (its record slots); give 1 ..= {most}"
        ),
        Some(_) => {}
        None => model.limits.open_limit = Some(most),
    }
    if min_points > 0 {
        bail!("the column core sends a record for every cluster: drop --min-points {min_points}");
    }
    Ok(())
}

/// The column-streaming core of the virtual board (`fcc live --virtual`),
/// with the model options `model` adjusted to it (as `fcc board run
/// --virtual --scan column` does: the open limit, the build's label bits).
pub fn virtual_column_core(
    model: &ModelArgs,
    min_points: usize,
) -> anyhow::Result<(VirtualCore, ModelArgs)> {
    let build = virtual_build(Scan::Column);
    let mut model = model.clone();
    column_model(&mut model, min_points)?;
    build_label_bits(&mut model, &build, "the virtual board's build")?;
    model.params(1, 1)?;
    let loaded = crate::cmd_sim::load_params(&build)?;
    Ok((VirtualCore(open_virtual(build, loaded)?), model))
}

/// The virtual board with the core `build` (its Verilator model `model`),
/// opened by the driver, a core left busy reset.
fn open_virtual(build: FccParams, model: std::sync::Arc<fcc_sim::Model>) -> anyhow::Result<Runner> {
    let (board, expect) = fcc_sim::virtual_board_with(&build, model)?;
    let mut d = Driver::open(board, &expect).map_err(|e| anyhow::anyhow!("{e}"))?;
    recover_if_busy(&mut d, "virtual board")?;
    Ok(Runner::new(Target::Virtual(Box::new(d), build)))
}

/// A core on the virtual board for another command: [`Hardware`], and the
/// summary of the frames it ran.
pub struct VirtualCore(Runner);

impl VirtualCore {
    pub fn hardware(&self) -> &dyn Hardware {
        &self.0
    }

    /// `PASS: N frames through the core, ...` (every frame that came back
    /// was checked, or the command failed).
    pub fn summary(&self) -> String {
        self.0.summary()
    }
}

/// The build's label bits B for the golden model: `--label-bits` must be B
/// when given; when not, it is B. The rest as [`check_model_for`].
fn label_bits_of(
    args: &BoardRunArgs,
    build: &FccParams,
    where_: &str,
) -> anyhow::Result<ClusterLidarArgs> {
    let mut cluster = check_model_for(args, build)?;
    build_label_bits(&mut cluster.model, build, where_)?;
    Ok(cluster)
}

/// `--label-bits` of `model` must be the build's B when given; it is B.
fn build_label_bits(model: &mut ModelArgs, build: &FccParams, where_: &str) -> anyhow::Result<()> {
    if let Some(b) = model.label_bits.filter(|&b| b != build.label_bits) {
        bail!(
            "--label-bits {b} differs from the core's B = {} ({where_}): drop it or give --label-bits {}",
            build.label_bits,
            build.label_bits
        );
    }
    model.label_bits = Some(build.label_bits);
    Ok(())
}

fn run_board(args: &BoardRunArgs) -> anyhow::Result<()> {
    if args.cluster.model.merge != MergeMode::Exact {
        bail!("the core computes exact connected components: drop --merge paper");
    }
    // The model options are checked before any board is opened (and
    // against the build once it is known).
    args.cluster.model.params(1, 1)?;
    if args.rtl.is_none() && args.uio.is_none() {
        check_model_for(args, &virtual_build(args.scan.unwrap_or_default()))?;
    }
    let t = Instant::now();
    let (report, scan) = if args.virtual_board {
        let (build, model, where_) = match &args.rtl {
            Some(dir) => {
                let g = fcc_sim::read_generated(dir)?;
                let model = crate::cmd_sim::load_generated(dir)?;
                (g.params, model, dir.display().to_string())
            }
            None => {
                let b = virtual_build(args.scan.unwrap_or_default());
                let model = crate::cmd_sim::load_params(&b)?;
                (b, model, "the virtual board's build".to_string())
            }
        };
        let cluster = label_bits_of(args, &build, &where_)?;
        eprintln!(
            "virtual board: one {} core for K_max {}, up to {} x {}, B = {} ({where_}); each frame runs at its own size, K and thresholds{}, set through the run registers",
            match build.scan {
                Scan::Row => "row-major",
                Scan::Column => "column-streaming",
            },
            build.fsize,
            build.rows,
            build.cols,
            build.label_bits,
            match build.scan {
                Scan::Row => "",
                Scan::Column => " (and stream limits)",
            }
        );
        let hw = open_virtual(build, model)?;
        run_cluster_on(&cluster, Some(&hw))?;
        (hw.summary(), hw.build().scan)
    } else if let Some(core) = &args.uio {
        let params = args.params.as_ref().context("--uio needs --params")?;
        let (target, cluster) = open_linux(args, core, params)?;
        let hw = Runner::new(target);
        run_cluster_on(&cluster, Some(&hw))?;
        (hw.summary(), hw.build().scan)
    } else {
        bail!(
            "say where the core is: --virtual, or --uio NAME --params fcc_params.json on a board"
        );
    };
    // With the column core, stdout carries the records (JSON lines).
    if scan == Scan::Column {
        eprintln!("{report} ({:.1} s)", t.elapsed().as_secs_f64());
    } else {
        println!("{report} ({:.1} s)", t.elapsed().as_secs_f64());
    }
    Ok(())
}

/// The build of a bitstream from its `fcc_params.json`.
#[cfg(target_os = "linux")]
fn read_build(path: &std::path::Path) -> anyhow::Result<FccParams> {
    #[derive(serde::Deserialize)]
    struct File {
        params: FccParams,
    }
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    let f: File = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: not an fcc_params.json written by `fcc gen` (no \"params\")",
            path.display()
        )
    })?;
    f.params
        .validate_for_hardware()
        .with_context(|| path.display().to_string())?;
    Ok(f.params)
}

#[cfg(target_os = "linux")]
fn open_linux(
    args: &BoardRunArgs,
    core: &str,
    params: &std::path::Path,
) -> anyhow::Result<(Target, ClusterLidarArgs)> {
    let p = read_build(params)?;
    let cluster = label_bits_of(args, &p, &params.display().to_string())?;
    let expect = fcc_sim::build_expect_for(&p, args.board)?;
    let hal = fcc_driver::linux::LinuxHal::open(core, &args.uio_dma, &args.udmabuf)?;
    let mut d = Driver::open(hal, &expect).map_err(|e| anyhow::anyhow!("{e}"))?;
    recover_if_busy(&mut d, core)?;
    Ok((Target::Linux(Box::new(d), p), cluster))
}

#[cfg(not(target_os = "linux"))]
fn open_linux(
    _: &BoardRunArgs,
    _: &dyn Fn(&str) -> bool,
    _: &str,
    _: &std::path::Path,
) -> anyhow::Result<(Target, ClusterLidarArgs)> {
    bail!("--uio needs Linux (UIO and u-dma-buf); use --virtual here")
}

/// A core left mid-frame by an earlier run is reset before the first frame.
fn recover_if_busy<H: fcc_driver::Hal>(d: &mut Driver<H>, what: &str) -> anyhow::Result<()> {
    if let Some((st, mm, s2)) = d.core_busy().map_err(|e| anyhow::anyhow!("{e}"))? {
        eprintln!(
            "{what}: the core or the DMA was busy (STATUS {st:#x}, MM2S DMASR {mm:#010x}, S2MM DMASR {s2:#010x}), left by an earlier run: resetting both"
        );
        d.recover().map_err(|e| anyhow::anyhow!("{e}"))?;
    }
    Ok(())
}

/// What `fcc board run` asks of a driver, whatever its platform.
trait Core {
    fn labels(
        &mut self,
        run: &RunConfig,
        px: Pixels<'_>,
        labels: &mut [u32],
    ) -> Result<fcc_driver::FrameReport, String>;
    fn records(
        &mut self,
        run: &RunConfig,
        px: Pixels<'_>,
        out: &mut Vec<HwRecord>,
    ) -> Result<fcc_driver::RecordReport, String>;
}

impl<H: fcc_driver::Hal> Core for Driver<H>
where
    H::Error: std::fmt::Display,
{
    fn labels(
        &mut self,
        run: &RunConfig,
        px: Pixels<'_>,
        labels: &mut [u32],
    ) -> Result<fcc_driver::FrameReport, String> {
        self.run_frame(run, px, labels).map_err(|e| e.to_string())
    }
    fn records(
        &mut self,
        run: &RunConfig,
        px: Pixels<'_>,
        out: &mut Vec<HwRecord>,
    ) -> Result<fcc_driver::RecordReport, String> {
        self.run_records(run, px, out).map_err(|e| e.to_string())
    }
}

impl Target {
    /// The driver, the build's clock and whether the core is simulated;
    /// on the virtual board, says that the frame `name` of `p` goes in.
    fn core(&mut self, name: &str, p: &FccParams) -> (&mut dyn Core, f64, bool) {
        match self {
            Target::Virtual(d, build) => {
                eprintln!(
                    "{name}: {} x {}, K {} through the virtual board ...",
                    p.rows, p.cols, p.fsize
                );
                (d.as_mut(), build.clock_mhz, true)
            }
            #[cfg(target_os = "linux")]
            Target::Linux(d, build) => (d.as_mut(), build.clock_mhz, false),
        }
    }
}

enum Target {
    /// The virtual board and the build of its core.
    Virtual(Box<Driver<VirtualBoard>>, FccParams),
    /// A board under Linux and the build of its core.
    #[cfg(target_os = "linux")]
    Linux(Box<Driver<fcc_driver::linux::LinuxHal>>, FccParams),
}

struct Runner {
    target: RefCell<Target>,
    frames: RefCell<(usize, f64)>,
}

impl Runner {
    fn new(target: Target) -> Runner {
        Runner {
            target: RefCell::new(target),
            frames: RefCell::new((0, 0.0)),
        }
    }

    fn summary(&self) -> String {
        let (n, ms) = *self.frames.borrow();
        let what = match self.build().scan {
            Scan::Row => "every label equal to the golden model's",
            Scan::Column => "every record equal to the golden stream's",
        };
        format!(
            "PASS: {n} frame{} through the core, {what}, {ms:.3} ms of core time",
            if n == 1 { "" } else { "s" }
        )
    }

    /// The build of the core.
    fn build(&self) -> FccParams {
        match &*self.target.borrow() {
            Target::Virtual(_, b) => b.clone(),
            #[cfg(target_os = "linux")]
            Target::Linux(_, b) => b.clone(),
        }
    }

    /// One more frame of `ms` core time.
    fn count(&self, ms: f64) {
        let mut f = self.frames.borrow_mut();
        f.0 += 1;
        f.1 += ms;
    }
}

/// The run parameters of a frame under `p` (rows, cols, K, Q7.8 thresholds).
fn run_config(p: &FccParams) -> RunConfig {
    fcc_sim::build_run(p)
}

impl Hardware for Runner {
    fn stream(
        &self,
        name: &str,
        kept: &RangeImage,
        gold: &PipelineResult,
        records: &[ClosedRecord],
        end: FrameEnd,
    ) -> anyhow::Result<()> {
        if self.build().scan != Scan::Column {
            bail!("{name}: the row-major core returns labels, not records");
        }
        // The frame's run values with the column core's stream limits.
        let p = FccParams {
            scan: Scan::Column,
            ..gold.params.clone()
        };
        self.stream_frame(name, kept, &p, records, end)
    }

    fn cluster(
        &self,
        name: &str,
        kept: &RangeImage,
        gold: &PipelineResult,
    ) -> anyhow::Result<Vec<u32>> {
        let mut labels = vec![0u32; kept.pixels()];
        let mut target = self.target.borrow_mut();
        // What the frame runs with: its rows and columns, K and thresholds
        // (the golden model's parameters, whose B is the build's).
        let p = gold.params.clone();
        let run = run_config(&p);
        let wall = Instant::now();
        let (d, clock_mhz, simulated) = target.core(name, &p);
        let report = d
            .labels(&run, Pixels::XyzF32(&kept.xyz), &mut labels)
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        compare(name, &p, &gold.clustering, &labels, &report.status)?;
        let s = &report.status;
        let ms = report.time_ns as f64 / 1e6;
        self.count(ms);
        println!(
            "{name}: {} x {}, K {}: {:.3} ms{} at {clock_mhz} MHz, {} clusters, {} provisional labels, {} joins, frame {}{}; labels equal to the golden model's",
            p.rows,
            p.cols,
            p.fsize,
            ms,
            if simulated {
                format!(" (simulated; {:.1} s wall)", wall.elapsed().as_secs_f64())
            } else {
                String::new()
            },
            s.clusters,
            s.provisional,
            s.joins,
            s.frame_count,
            if s.overflow {
                format!(", LABEL OVERFLOW: {} points unlabelled", s.unlabelled)
            } else {
                String::new()
            },
        );
        Ok(labels)
    }
}

impl Runner {
    /// The column core: `kept` in, its records out, each checked against
    /// the golden stream's `gold` and its end beat `end`.
    fn stream_frame(
        &self,
        name: &str,
        kept: &RangeImage,
        p: &FccParams,
        gold: &[ClosedRecord],
        end: FrameEnd,
    ) -> anyhow::Result<()> {
        let mut target = self.target.borrow_mut();
        let run = run_config(p);
        let mut got = Vec::with_capacity(gold.len());
        let wall = Instant::now();
        let (d, clock_mhz, simulated) = target.core(name, p);
        let report = d
            .records(&run, Pixels::XyzF32(&kept.xyz), &mut got)
            .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
        compare_records(name, p, gold, end, &got, &report)?;
        let ms = report.time_ns as f64 / 1e6;
        self.count(ms);
        let s = &report.status;
        eprintln!(
            "{name}: {} x {}, K {}: {:.3} ms{} at {clock_mhz} MHz ({:.2} cycles a pixel), {} records, at most {} labels in use, frame {}{}; records equal to the golden stream's",
            p.rows,
            p.cols,
            p.fsize,
            ms,
            if simulated {
                format!(" (simulated; {:.1} s wall)", wall.elapsed().as_secs_f64())
            } else {
                String::new()
            },
            report.time_ns as f64 * clock_mhz / 1e3 / p.pixels() as f64,
            report.end.records,
            s.provisional,
            s.frame_count,
            if report.end.overflow {
                ", OVERFLOW: a run was refused a label (labels or the open limit)"
            } else {
                ""
            },
        );
        Ok(())
    }
}

/// The core's records and end beat against the golden stream's, and the
/// status against the end beat; the first differing record on a mismatch.
fn compare_records(
    name: &str,
    p: &FccParams,
    gold: &[ClosedRecord],
    end: FrameEnd,
    got: &[HwRecord],
    report: &fcc_driver::RecordReport,
) -> anyhow::Result<()> {
    let want: Vec<Item> = gold
        .iter()
        .map(|r| Item::Record(r.record.hw()))
        .chain([Item::End(end)])
        .collect();
    let got: Vec<Item> = got
        .iter()
        .copied()
        .map(Item::Record)
        .chain([Item::End(report.end)])
        .collect();
    if let Some(d) = fcc_sim::column::first_difference(&want, &got) {
        bail!(
            "{name}: the core's records differ from the golden stream's ({}): first at {d}",
            fcc_rtl::param_summary(p),
        );
    }
    let s = &report.status;
    let pairs = [
        (
            "clusters",
            u64::from(end.records.min(0xffff)),
            u64::from(s.clusters),
        ),
        ("overflow", u64::from(end.overflow), u64::from(s.overflow)),
    ];
    for (what, e, g) in pairs {
        if e != g {
            bail!("{name}: status {what}: expected {e} != got {g}");
        }
    }
    Ok(())
}

/// Every label and the status against the golden model; the first
/// differing pixel on a mismatch.
fn compare(
    name: &str,
    p: &FccParams,
    gold: &fcc_golden::Clustering,
    got: &[u32],
    s: &fcc_driver::FrameStatus,
) -> anyhow::Result<()> {
    if let Some(i) = (0..gold.labels.len()).find(|&i| got.get(i) != Some(&gold.labels[i])) {
        let bad = gold.labels.iter().zip(got).filter(|(a, b)| a != b).count();
        bail!(
            "{name}: the core's labels differ from the golden model's ({}): first mismatch at row {} col {}: expected {} != got {} ({bad} pixels differ)",
            fcc_rtl::param_summary(p),
            i / p.cols,
            i % p.cols,
            gold.labels[i],
            got.get(i).map_or("nothing".to_string(), |v| v.to_string())
        );
    }
    let pairs = [
        ("clusters", u64::from(gold.clusters), u64::from(s.clusters)),
        (
            "provisional labels",
            u64::from(gold.provisional),
            u64::from(s.provisional),
        ),
        ("overflow", u64::from(gold.overflow), u64::from(s.overflow)),
        (
            "unlabelled points",
            gold.unlabelled as u64,
            u64::from(s.unlabelled),
        ),
    ];
    for (what, e, g) in pairs {
        if e != g {
            bail!("{name}: status {what}: expected {e} != got {g}");
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use fcc_golden::{cluster, Frame};

    #[test]
    fn mismatch_names_first_pixel_expected_and_got_and_status_differences() {
        let p = FccParams {
            rows: 2,
            cols: 3,
            fsize: 3,
            ..FccParams::default()
        };
        let xyz = [
            10.0,
            0.0,
            0.0,
            10.0,
            0.25,
            0.0,
            f64::NAN,
            0.0,
            0.0, //
            10.0,
            0.0,
            -0.5,
            f64::NAN,
            0.0,
            0.0,
            20.0,
            0.0,
            0.0,
        ];
        let gold = cluster(&p, &Frame::from_xyz_f64(2, 3, &xyz), MergeMode::Exact).unwrap();
        let status = fcc_driver::FrameStatus {
            clusters: gold.clusters,
            provisional: gold.provisional,
            ..Default::default()
        };
        compare("f", &p, &gold, &gold.labels, &status).unwrap();
        let mut got = gold.labels.clone();
        got[5] += 1;
        let e = compare("f", &p, &gold, &got, &status)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("row 1 col 2: expected 2 != got 3 (1 pixels differ)"),
            "{e}"
        );
        let bad = fcc_driver::FrameStatus {
            clusters: 9,
            ..status
        };
        let e = compare("f", &p, &gold, &gold.labels, &bad)
            .unwrap_err()
            .to_string();
        assert!(e.contains("status clusters: expected 2 != got 9"), "{e}");
    }
}
