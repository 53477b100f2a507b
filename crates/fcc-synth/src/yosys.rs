//! Run Yosys: `synth_xilinx` for the 7 series, `stat -json` and the flat
//! netlist, then `sta` with the Xilinx cell models in a second session.
//!
//! One Yosys process runs the synthesis script ([`script`]), written into a
//! work directory together with its log (`yosys.log`), the cell counts
//! (`stat.json`) and the netlist (`netlist.json`); a second process runs the
//! timing script ([`sta_script`], log `sta_yosys.log`, report `sta.log`) on
//! that netlist alone. Both can be repeated by hand:
//! `cd WORK && yosys -s synth.ys && yosys -s sta.ys`.
//!
//! Choices, and why:
//! - `-flatten`: `sta` only times paths inside one module, and cell counts of
//!   a flat netlist are the design's totals.
//! - `-noiopad -noclkbuf`: the core sits inside the device behind AXI DMA, so
//!   its ports get no IBUF/OBUF and its clock comes from an existing BUFG.
//!   This matches Vivado's out-of-context synthesis, and the paper's Table I,
//!   which counts the core and not the pins.
//! - Optional by-block counts come from a second synthesis of the same
//!   input in the same process, with the first-level blocks (`fcc_intra`,
//!   `fcc_window`, ...: modules whose name has no `__`) kept as hierarchy and
//!   everything inside them flattened. Nothing is optimised across block
//!   boundaries there, so its totals differ a little from the flat run; it is
//!   used only to say which block dominates.
//! - `autoname` before writing the netlist: names the cells Yosys created
//!   after the nets they drive, so the critical path and the fanout tables
//!   name registers of the RTL rather than `$abc$123` numbers. It changes no
//!   cell.
//! - A fresh session for `sta`: reading the cell models with `-specify` into
//!   the session that synthesised the design gives wrong paths on newer Yosys
//!   versions; the second session reads only the netlist and the models.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::routing::{self, Routing};
use crate::{io_err, tail_lines, Resources, SynthError, Timing};

/// How to install Yosys, for error messages.
pub const INSTALL: &str = "Debian/Ubuntu: `apt-get install yosys`";
/// Lines of the log shown in an error.
pub(crate) const TAIL: usize = 25;
/// Prefix of the lines the script logs before each step, to name a failing step.
const STEP_MARK: &str = "fcc-step:";
/// Files in the work directory.
pub const SCRIPT_FILE: &str = "synth.ys";
pub const LOG_FILE: &str = "yosys.log";
pub const STAT_FILE: &str = "stat.json";
pub const STA_FILE: &str = "sta.log";
pub const BLOCKS_FILE: &str = "stat_blocks.json";
/// The flat netlist after synthesis (Yosys JSON), read by the timing session
/// and by [`crate::routing`].
pub const NETLIST_FILE: &str = "netlist.json";
pub const STA_SCRIPT_FILE: &str = "sta.ys";
pub const STA_LOG_FILE: &str = "sta_yosys.log";

/// How to run Yosys.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct YosysConfig {
    /// The Yosys executable (looked up on PATH unless it is a path).
    pub program: PathBuf,
    /// Top module: [`fcc_rtl::top_module`] of the configuration (set by
    /// [`crate::results::yosys_config_for`]; the default, the bare
    /// [`fcc_rtl::TOP_NAME`], suits hand-written test designs).
    pub top: String,
    /// `synth_xilinx -family`.
    pub family: String,
    /// Run `sta` (in a second Yosys session) and measure fanout and routing
    /// hops after synthesis.
    pub timing: bool,
    /// Also count cells per first-level block (a second synthesis, about twice the time).
    pub by_block: bool,
}

impl Default for YosysConfig {
    fn default() -> Self {
        YosysConfig {
            program: PathBuf::from("yosys"),
            top: fcc_rtl::TOP_NAME.to_string(),
            family: "xc7".to_string(),
            timing: true,
            by_block: false,
        }
    }
}

/// What one run measured.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct YosysRun {
    pub resources: Resources,
    /// `None` when the run was made without timing.
    pub timing: Option<Timing>,
    /// Fanout and routing hops of the netlist; `None` without timing.
    #[serde(default)]
    pub routing: Option<Routing>,
    /// Cells per first-level block, and the top's own cells under the top's name;
    /// `None` unless asked for.
    pub by_block: Option<std::collections::BTreeMap<String, Resources>>,
    /// `yosys -V`.
    pub yosys_version: String,
    /// Wall-clock seconds of the Yosys process.
    pub seconds: f64,
    /// Where the script, log and reports are.
    pub work_dir: PathBuf,
}

/// Quote a path for a Yosys script when it holds blanks.
fn quote(p: &Path) -> String {
    let s = p.display().to_string();
    if s.contains(char::is_whitespace) {
        format!("\"{s}\"")
    } else {
        s
    }
}

/// The Yosys script for `files` (absolute paths; outputs go to the current
/// directory). `blocks` are the modules kept as hierarchy in the by-block run.
pub fn script(files: &[PathBuf], cfg: &YosysConfig, blocks: &[String]) -> String {
    let mut s = String::new();
    s.push_str("# Resource and timing estimate, written by fcc-synth.\n");
    s.push_str("# Run again from this directory with: yosys -s synth.ys\n");
    s.push_str(&format!("log {STEP_MARK} read\n"));
    for f in files {
        s.push_str(&format!("read_verilog {}\n", quote(f)));
    }
    let by_block = cfg.by_block && !blocks.is_empty();
    if by_block {
        s.push_str("design -save input\n");
    }
    s.push_str(&format!("log {STEP_MARK} synth\n"));
    s.push_str(&format!(
        "synth_xilinx -family {} -top {} -flatten -noiopad -noclkbuf\n",
        cfg.family, cfg.top
    ));
    s.push_str(&format!("log {STEP_MARK} stat\n"));
    s.push_str(&format!("tee -q -o {STAT_FILE} stat -json\n"));
    if cfg.timing {
        s.push_str(&format!("log {STEP_MARK} netlist\n"));
        s.push_str("autoname\n");
        s.push_str(&format!("write_json {NETLIST_FILE}\n"));
    }
    if by_block {
        s.push_str(&format!("log {STEP_MARK} by-block synth\n"));
        s.push_str("design -load input\n");
        s.push_str(&format!("hierarchy -top {}\n", cfg.top));
        s.push_str(&format!(
            "setattr -mod -set keep_hierarchy 1 {}\n",
            blocks.join(" ")
        ));
        s.push_str(&format!(
            "synth_xilinx -family {} -top {} -flatten -noiopad -noclkbuf\n",
            cfg.family, cfg.top
        ));
        s.push_str(&format!("log {STEP_MARK} by-block stat\n"));
        s.push_str(&format!(
            "tee -q -o {BLOCKS_FILE} stat -json -top {}\n",
            cfg.top
        ));
    }
    s
}

/// The timing script, run in a fresh Yosys session on the netlist the
/// synthesis script wrote: reading the cell models into the synthesis session
/// itself gives wrong paths on newer Yosys versions.
pub fn sta_script(top: &str) -> String {
    let mut s = String::new();
    s.push_str("# Pre-route timing estimate of the synthesised netlist, written by fcc-synth.\n");
    s.push_str(&format!(
        "# Run again from this directory with: yosys -s {STA_SCRIPT_FILE}\n"
    ));
    s.push_str(&format!("log {STEP_MARK} read netlist\n"));
    s.push_str(&format!("read_json {NETLIST_FILE}\n"));
    s.push_str(&format!("log {STEP_MARK} cell models\n"));
    s.push_str("read_verilog -lib -specify +/xilinx/cells_sim.v\n");
    s.push_str(&format!("hierarchy -top {top}\n"));
    s.push_str(&format!("log {STEP_MARK} sta\n"));
    s.push_str(&format!("tee -q -o {STA_FILE} sta\n"));
    s
}

/// The blocks in `files`, other than `top`:
/// - modules named without `__` (the row-major core's blocks, each its own module);
/// - the top's `core` instance, its sub-blocks and theirs (`<top>__core`,
///   `<top>__core__sets`, `<top>__core__sets__joins`: the column core, whose
///   blocks are all inside one instance). Deeper modules stay inside their block.
pub fn block_modules(files: &[PathBuf], top: &str) -> Result<Vec<String>, SynthError> {
    let mut blocks = vec![];
    for f in files {
        let text = std::fs::read_to_string(f).map_err(io_err("read", f))?;
        for line in text.lines() {
            if let Some(rest) = line.trim_start().strip_prefix("module ") {
                let name: String = rest
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '$')
                    .collect();
                if !name.is_empty() && name != top && is_block(&block_name(&name, top)) {
                    blocks.push(name);
                }
            }
        }
    }
    blocks.sort();
    blocks.dedup();
    Ok(blocks)
}

/// Whether a module (named without the configuration suffix) is a block of [`block_modules`].
fn is_block(name: &str) -> bool {
    match name.strip_prefix(&format!("{}__{CORE_INSTANCE}", fcc_rtl::TOP_NAME)) {
        Some("") => true,
        Some(below) => below.starts_with("__") && below.matches("__").count() <= 2,
        None => !name.contains("__"),
    }
}

/// The instance of the top that holds a core's blocks when they are not modules of their own.
const CORE_INSTANCE: &str = "core";

/// A block's name without the configuration suffix its top `top` carries
/// (`fcc_intra_k7_1b2c3d4e` -> `fcc_intra`), so reports name blocks the same
/// for every configuration.
pub fn block_name(module: &str, top: &str) -> String {
    let suffix = top.strip_prefix(fcc_rtl::TOP_NAME).unwrap_or("");
    if suffix.is_empty() {
        return module.to_string();
    }
    module.strip_suffix(suffix).unwrap_or(module).to_string()
}

/// How a report names a block of [`block_modules`]: [`block_name`], with a
/// block inside the top's instances written as its instance path
/// (`fcc_top__core__sets__joins` -> `core.sets.joins`).
pub fn block_label(module: &str, top: &str) -> String {
    let name = block_name(module, top);
    match name.strip_prefix(&format!("{}__", fcc_rtl::TOP_NAME)) {
        Some(path) => path.replace("__", "."),
        None => name,
    }
}

/// Start `program` with `args`, mapping a failure to start to [`SynthError::ToolMissing`].
pub(crate) fn start(
    program: &Path,
    install: &'static str,
    cmd: &mut Command,
) -> Result<std::process::Output, SynthError> {
    cmd.output().map_err(|e| SynthError::ToolMissing {
        tool: program.display().to_string(),
        install,
        reason: if e.kind() == std::io::ErrorKind::NotFound {
            "not found".to_string()
        } else {
            e.to_string()
        },
    })
}

/// `yosys -V`, e.g. `Yosys 0.23 (git sha1 7ce5011c24b)`.
pub fn version(program: &Path) -> Result<String, SynthError> {
    let out = start(program, INSTALL, Command::new(program).arg("-V"))?;
    let text = String::from_utf8_lossy(&out.stdout).trim().to_string();
    if !out.status.success() || text.is_empty() {
        return Err(SynthError::ToolFailed {
            tool: program.display().to_string(),
            step: "-V".into(),
            status: out.status.to_string(),
            log: PathBuf::from("(stderr)"),
            tail: tail_lines(&String::from_utf8_lossy(&out.stderr), TAIL),
        });
    }
    Ok(text)
}

/// The Verilog files (`*.v`) of a directory, sorted by name.
pub fn verilog_files_in(dir: &Path) -> Result<Vec<PathBuf>, SynthError> {
    let mut files = vec![];
    for entry in std::fs::read_dir(dir).map_err(io_err("read the directory", dir))? {
        let path = entry.map_err(io_err("read the directory", dir))?.path();
        if path.is_file() && path.extension().is_some_and(|e| e == "v") {
            files.push(path);
        }
    }
    if files.is_empty() {
        return Err(SynthError::NoVerilog(dir.to_path_buf()));
    }
    files.sort();
    Ok(files)
}

/// The step the script was in when the log ends.
fn failed_step(log: &str) -> String {
    log.lines()
        .rev()
        .find_map(|l| l.trim().strip_prefix(STEP_MARK))
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|| "start".to_string())
}

/// Synthesise `files` with top `cfg.top` in `work_dir` (created if missing).
pub fn synthesize(
    files: &[PathBuf],
    cfg: &YosysConfig,
    work_dir: &Path,
) -> Result<YosysRun, SynthError> {
    let yosys_version = version(&cfg.program)?;
    std::fs::create_dir_all(work_dir).map_err(io_err("create", work_dir))?;
    let work_dir = work_dir.canonicalize().map_err(io_err("open", work_dir))?;
    let files = files
        .iter()
        .map(|f| f.canonicalize().map_err(io_err("read", f)))
        .collect::<Result<Vec<_>, _>>()?;
    let script_path = work_dir.join(SCRIPT_FILE);
    let blocks = if cfg.by_block {
        block_modules(&files, &cfg.top)?
    } else {
        vec![]
    };
    std::fs::write(&script_path, script(&files, cfg, &blocks))
        .map_err(io_err("write", &script_path))?;
    let log_path = work_dir.join(LOG_FILE);
    for stale in [STAT_FILE, STA_FILE, BLOCKS_FILE, NETLIST_FILE] {
        let p = work_dir.join(stale);
        if p.exists() {
            std::fs::remove_file(&p).map_err(io_err("remove", &p))?;
        }
    }
    let t0 = Instant::now();
    let out = start(
        &cfg.program,
        INSTALL,
        Command::new(&cfg.program)
            .args(["-q", "-l", LOG_FILE, "-s", SCRIPT_FILE])
            .current_dir(&work_dir),
    )?;
    let seconds = t0.elapsed().as_secs_f64();
    let log = std::fs::read_to_string(&log_path).unwrap_or_default();
    let log_tail = || {
        if log.is_empty() {
            let mut s = String::from_utf8_lossy(&out.stdout).to_string();
            s.push_str(&String::from_utf8_lossy(&out.stderr));
            tail_lines(&s, TAIL)
        } else {
            tail_lines(&log, TAIL)
        }
    };
    if !out.status.success() {
        return Err(SynthError::ToolFailed {
            tool: cfg.program.display().to_string(),
            step: failed_step(&log),
            status: out.status.to_string(),
            log: log_path.clone(),
            tail: log_tail(),
        });
    }
    let stat_path = work_dir.join(STAT_FILE);
    let stat = std::fs::read_to_string(&stat_path).map_err(io_err("read", &stat_path))?;
    let resources = Resources::from_stat_json(&stat).map_err(|reason| SynthError::Parse {
        what: "the cell counts of `stat -json`".into(),
        path: stat_path.clone(),
        reason,
        tail: log_tail(),
    })?;
    let timing = if cfg.timing {
        run_sta(cfg, &work_dir)?;
        let sta_path = work_dir.join(STA_FILE);
        let sta = std::fs::read_to_string(&sta_path).map_err(io_err("read", &sta_path))?;
        Some(
            Timing::from_sta_log(&sta).map_err(|reason| SynthError::Parse {
                what: "the critical path of `sta`".into(),
                path: sta_path.clone(),
                reason,
                tail: tail_lines(&sta, TAIL),
            })?,
        )
    } else {
        None
    };
    let routing = if cfg.timing {
        let path = work_dir.join(NETLIST_FILE);
        let text = std::fs::read_to_string(&path).map_err(io_err("read", &path))?;
        Some(
            routing::analyse(&text, &cfg.top).map_err(|reason| SynthError::Parse {
                what: "the synthesised netlist".into(),
                path: path.clone(),
                reason,
                tail: log_tail(),
            })?,
        )
    } else {
        None
    };
    let by_block = if cfg.by_block && !blocks.is_empty() {
        let path = work_dir.join(BLOCKS_FILE);
        let text = std::fs::read_to_string(&path).map_err(io_err("read", &path))?;
        Some(
            Resources::blocks_from_stat_json(&text, &cfg.top)
                .map_err(|reason| SynthError::Parse {
                    what: "the by-block cell counts of `stat -json -top`".into(),
                    path: path.clone(),
                    reason,
                    tail: log_tail(),
                })?
                .into_iter()
                .map(|(name, r)| (block_label(&name, &cfg.top), r))
                .collect(),
        )
    } else {
        None
    };
    Ok(YosysRun {
        resources,
        timing,
        routing,
        by_block,
        yosys_version,
        seconds,
        work_dir,
    })
}

/// Run [`sta_script`] in a fresh Yosys process in `work_dir`.
fn run_sta(cfg: &YosysConfig, work_dir: &Path) -> Result<(), SynthError> {
    let script_path = work_dir.join(STA_SCRIPT_FILE);
    std::fs::write(&script_path, sta_script(&cfg.top)).map_err(io_err("write", &script_path))?;
    let out = start(
        &cfg.program,
        INSTALL,
        Command::new(&cfg.program)
            .args(["-q", "-l", STA_LOG_FILE, "-s", STA_SCRIPT_FILE])
            .current_dir(work_dir),
    )?;
    if !out.status.success() {
        let log_path = work_dir.join(STA_LOG_FILE);
        let log = std::fs::read_to_string(&log_path).unwrap_or_default();
        return Err(SynthError::ToolFailed {
            tool: cfg.program.display().to_string(),
            step: failed_step(&log),
            status: out.status.to_string(),
            log: log_path,
            tail: tail_lines(&log, TAIL),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn script_reads_every_file_and_times_after_synthesis() {
        let s = script(
            &[PathBuf::from("/a/x.v"), PathBuf::from("/b c/y.v")],
            &YosysConfig::default(),
            &[],
        );
        assert!(s.contains("read_verilog /a/x.v\n"));
        assert!(s.contains("read_verilog \"/b c/y.v\"\n"));
        assert!(s.contains("synth_xilinx -family xc7 -top fcc_top -flatten -noiopad -noclkbuf\n"));
        let stat = s.find("stat -json").unwrap();
        let netlist = s.find("write_json netlist.json").unwrap();
        assert!(stat < netlist);
        // Timing runs in its own session, on the netlist.
        assert!(!s.contains("-specify") && !s.contains(" sta\n"), "{s}");
        let t = sta_script("fcc_top");
        let read = t.find("read_json netlist.json").unwrap();
        let models = t
            .find("read_verilog -lib -specify +/xilinx/cells_sim.v")
            .unwrap();
        let sta = t.find("tee -q -o sta.log sta").unwrap();
        assert!(read < models && models < sta, "{t}");
        assert!(t.contains("hierarchy -top fcc_top\n"));
    }

    #[test]
    fn script_without_timing_has_no_sta() {
        let cfg = YosysConfig {
            timing: false,
            ..Default::default()
        };
        let s = script(&[PathBuf::from("/a.v")], &cfg, &[]);
        assert!(
            !s.contains(" sta\n") && !s.contains("-specify") && !s.contains("write_json"),
            "{s}"
        );
    }

    #[test]
    fn by_block_run_keeps_the_blocks_and_reloads_the_input() {
        let cfg = YosysConfig {
            by_block: true,
            ..Default::default()
        };
        let s = script(
            &[PathBuf::from("/a.v")],
            &cfg,
            &["fcc_intra".to_string(), "fcc_window".to_string()],
        );
        assert!(s.contains("design -save input\n"));
        let reload = s.find("design -load input").unwrap();
        assert!(s.find("write_json netlist.json").unwrap() < reload);
        assert!(s.contains("setattr -mod -set keep_hierarchy 1 fcc_intra fcc_window\n"));
        assert!(s.contains("stat -json -top fcc_top\n"));
    }

    #[test]
    fn blocks_are_modules_without_double_underscore() {
        let d = tempfile::tempdir().unwrap();
        let f = d.path().join("x.v");
        std::fs::write(
            &f,
            "module fcc_top(a);\nendmodule\nmodule fcc_intra(a);\nendmodule\n\
             module fcc_intra__ring(a);\nendmodule\n  module fcc_window (a);\nendmodule\n",
        )
        .unwrap();
        assert_eq!(
            block_modules(&[f], "fcc_top").unwrap(),
            vec!["fcc_intra".to_string(), "fcc_window".to_string()]
        );
    }

    #[test]
    fn the_column_cores_blocks_are_two_levels_below_its_core_instance() {
        let d = tempfile::tempdir().unwrap();
        let f = d.path().join("x.v");
        let top = "fcc_top_k7_1b2c3d4e";
        let text: String = [
            "fcc_top",
            "fcc_regs",
            "fcc_regs__bus",
            "fcc_top__flow",
            "fcc_top__core",
            "fcc_top__core__sets",
            "fcc_top__core__sets__joins",
            "fcc_top__core__sets__joins__min1",
            "fcc_top__corex",
        ]
        .iter()
        .map(|m| format!("module {m}_k7_1b2c3d4e(a);\nendmodule\n"))
        .collect();
        std::fs::write(&f, text).unwrap();
        let mut labels: Vec<String> = block_modules(&[f], top)
            .unwrap()
            .iter()
            .map(|m| block_label(m, top))
            .collect();
        labels.sort();
        assert_eq!(
            labels,
            vec!["core", "core.sets", "core.sets.joins", "fcc_regs"],
            "the blocks and how a report names them"
        );
        assert_eq!(block_label(top, top), "fcc_top");
    }

    #[test]
    fn block_names_lose_the_configuration_suffix_of_the_top() {
        let top = "fcc_top_k7_1b2c3d4e";
        assert_eq!(block_name("fcc_intra_k7_1b2c3d4e", top), "fcc_intra");
        assert_eq!(block_name(top, top), "fcc_top");
        assert_eq!(block_name("other", top), "other");
        assert_eq!(block_name("fcc_intra", "fcc_top"), "fcc_intra");
    }

    #[test]
    fn failing_step_is_the_last_marker() {
        let log = "fcc-step: read\nstuff\nfcc-step: synth\nERROR: boom\n";
        assert_eq!(failed_step(log), "synth");
        assert_eq!(failed_step("ERROR: no log"), "start");
    }

    #[test]
    fn missing_yosys_says_how_to_install() {
        let e = version(Path::new("fcc-no-such-yosys")).unwrap_err();
        let msg = e.to_string();
        assert!(matches!(e, SynthError::ToolMissing { .. }), "{msg}");
        assert!(msg.contains("apt-get install yosys"), "{msg}");
        assert!(msg.contains("fcc-no-such-yosys"), "{msg}");
    }

    #[test]
    fn empty_directory_has_no_verilog() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(d.path().join("fcc_params.vh"), "").unwrap();
        let e = verilog_files_in(d.path()).unwrap_err();
        assert!(matches!(e, SynthError::NoVerilog(_)), "{e}");
    }
}
