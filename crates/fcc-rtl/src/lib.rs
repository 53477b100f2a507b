//! The FCC RTL generator.
//!
//! Each hardware block is a rust-hdl `LogicBlock` in a file of its own name
//! (`fcc_intra`, `fcc_window`, `fcc_dist_tree`, `fcc_sort_net`,
//! `fcc_merge_table`, `fcc_label_update`, `fcc_top`, plus the helpers
//! `fcc_sq_dist`, `fcc_dist_unit`, `fcc_line_buf`, `fcc_fifo`, `fcc_stream_fifo` (with
//! `fcc_stream_ctl`, `fcc_stream_lane`), `fcc_ram`,
//! `fcc_row_word`, `fcc_keep_reg`, `fcc_fanout_reg`, `fcc_fanout_net`,
//! `fcc_prefix_or`, `fcc_any_or`, `fcc_two_or`, `fcc_pick`; inside `fcc_window`:
//! `fcc_win_edge`, `fcc_rep_window` (a lane of `fcc_word_window`, as
//! `fcc_thr_window`'s two lanes are); inside `fcc_sort_net`: `fcc_sort_filter` (with `fcc_filt_centre`, `fcc_min_tree`,
//! `fcc_known_mask`, `fcc_match_delay`), `fcc_centre_buf`, `fcc_serializer`,
//! `fcc_join_queue`; inside `fcc_merge_table`: `fcc_table_init`,
//! `fcc_union_engine`, `fcc_flatten`, `fcc_table_ports`; inside
//! `fcc_label_update`: `fcc_fb_writer`, `fcc_rb_pipeline` (with `fcc_run_number`), `fcc_beat_queue`,
//! `fcc_gearbox`, `fcc_beat_assembly`, `fcc_pop_decision`, `fcc_slot_mux`;
//! inside `fcc_regs`: `fcc_axil_adapter`, `fcc_reg_mux` and the field blocks
//! `fcc_reg_control`, `fcc_reg_w1c`, `fcc_reg_frame_status` (with
//! `fcc_reg_counter`, `fcc_reg_snapshot`), `fcc_reg_run_params` (with
//! `fcc_reg_run`, `fcc_range_check`, `fcc_reg_thresholds` (with
//! `fcc_reg_squared`, `fcc_hi_zero_check`), `fcc_reg_w1c`)).
//! Sizes that vary with the configuration (K, rows, columns, label bits,
//! thresholds, labels per beat) are read from [`FccParams`] when the blocks
//! are built, so one binary generates every configuration.
//!
//! [`generate`] checks the parameters and the design, emits the Verilog and
//! the files that travel with it; [`write_rtl`] writes them to a directory.
//!
//! # Naming and rust-hdl idioms
//!
//! **Blocks.** One `#[derive(LogicBlock)]` struct per file, the file and the
//! Verilog module named after the block (`fcc_union_engine.rs`,
//! `FccUnionEngine`). Ports come first, grouped by interface with a comment;
//! sub-blocks and registers are private. A block that has sub-blocks only
//! wires them in its `update()` (as rust-hdl's `sync_fifo.rs` does), plus at
//! most a small state register that says which sub-block is in charge. A
//! sub-block field's name becomes part of its module's name
//! (`fcc_merge_table__union_engine`) and of every register path in a timing
//! report, so it is named for its role.
//!
//! **Registers and signals** are named for what they hold, in full words
//! (`kept_root`, `next_label`, `word_valid_s1`), never `x0 d0 cr`. rust-hdl
//! already emits a `DFF`'s ports as `name$q` and `name$d`, so there is no
//! `_q` suffix. A value carried down a pipeline takes the number of its stage,
//! in pipeline order, as a suffix (`label_s2`, `label_s3`). A pair of
//! registers that take turns is named for the turn (`walk_even`,
//! `walk_odd`). Internal links with back-pressure use one stream shape:
//! `<link>_valid`, `<link>_ready` (or `<link>_take` where the receiver says
//! it took the item in this cycle), `<link>_data` or named data fields.
//! Ports that `fcc_top` wires keep their established short names.
//!
//! **State machines** are `#[derive(LogicState)]` enums held in a `DFF`
//! (`MergeMode { Init, Union, Flatten }`), decoded once with a `match` into
//! one `Bit` per state that the sub-blocks take as an `active` input, never
//! `Bits<2>` constants.
//!
//! **Constants.** Numbers in `update()` are `Constant<Bits<N>>` fields made
//! with [`types::kb`] (`one16`, `last_word`), not literals: rust-hdl writes a
//! literal as a 32- or 64-bit Verilog constant, which Verilator's width lint
//! rejects, and a named constant says what the number is.
//!
//! **Defaults, then overrides.** Every combinational signal and every `DFF`
//! input a block drives is given its default value at the top of `update()`
//! (`dff_setup!` holds registers; signals get an explicit default), and later
//! `if`s override it; the last assignment wins, so the reset branch comes
//! last. This keeps the emitted `always @(*)` free of latches.
//!
//! **Block RAM.** Reads go through `FccRam` (two-cycle read, read-first);
//! a user that needs the word written in the cycle of its read forwards it
//! itself, from registers (`fcc_table_ports`).
//!
//! **The binder loop.** `#[hdl_gen]` unrolls a `for` loop while it writes
//! the Verilog: the bounds are Rust expressions evaluated at generation, but
//! a vector index (`self.rep[r * kk + n]`) is kept as text and evaluated with
//! only the enclosing loops' variables in scope, so it cannot read a field
//! such as `self._k`, and `update()` cannot hold a `let`. A loop of one
//! iteration binds such a value to a name the index can use:
//! `for kk in self._k..(self._k + 1) { ... self.rep[r * kk + n] ... }` reads
//! "let kk = K". In the Rust simulation it is an ordinary loop that runs
//! once. Blocks name these loop variables after the field they bind (`kk`
//! for `_k`, `dd` for `_dp`, `l` for `_l`).

pub mod bench_blocks;
mod column;
pub mod example;
mod fcc_any_or;
mod fcc_axil_adapter;
mod fcc_beat_assembly;
mod fcc_beat_queue;
mod fcc_centre_buf;
mod fcc_credits;
mod fcc_dist_tree;
mod fcc_dist_unit;
mod fcc_fanout_net;
mod fcc_fanout_reg;
mod fcc_fb_writer;
mod fcc_fifo;
mod fcc_filt_centre;
mod fcc_first_set;
mod fcc_flatten;
mod fcc_frame_phase;
mod fcc_gearbox;
mod fcc_group_or;
mod fcc_hi_zero_check;
mod fcc_input_stage;
mod fcc_input_stage_probe;
mod fcc_intra;
mod fcc_intra_codes;
mod fcc_intra_thr;
mod fcc_join_queue;
mod fcc_keep_reg;
mod fcc_known_mask;
mod fcc_label_update;
mod fcc_line_buf;
mod fcc_match_delay;
mod fcc_merge_table;
mod fcc_min_tree;
mod fcc_pick;
mod fcc_pix_thr;
mod fcc_point_thr;
mod fcc_pop_decision;
mod fcc_prefix_or;
mod fcc_ram;
mod fcc_range_check;
mod fcc_rb_pipeline;
mod fcc_reg_control;
mod fcc_reg_counter;
mod fcc_reg_frame_status;
mod fcc_reg_mux;
mod fcc_reg_run;
mod fcc_reg_run_params;
mod fcc_reg_snapshot;
mod fcc_reg_squared;
mod fcc_reg_stream_limits;
mod fcc_reg_thresholds;
mod fcc_reg_w1c;
mod fcc_regs;
mod fcc_rep_window;
mod fcc_row_word;
mod fcc_run_number;
mod fcc_serializer;
mod fcc_slot_mux;
mod fcc_sort_filter;
mod fcc_sort_net;
mod fcc_sq_dist;
mod fcc_stream_ctl;
mod fcc_stream_fifo;
mod fcc_stream_lane;
mod fcc_table_init;
mod fcc_table_ports;
mod fcc_th_square;
mod fcc_thr_window;
mod fcc_top;
mod fcc_two_or;
mod fcc_union_engine;
mod fcc_win_edge;
mod fcc_window;
mod fcc_window_probe;
mod fcc_word_window;
mod fcc_word_window_probe;
pub mod lint;
pub mod regmap;
pub mod types;
pub mod vivado;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use fcc_params::{FccParams, ParamError, Scan};
use rust_hdl::prelude::*;
use thiserror::Error;

pub use bench_blocks::BenchBlock;
pub use column::fcc_acc_pixel::ACC_PIXEL_LATENCY;
pub use column::fcc_close_order::{CLOSE_ENTRIES, CLOSE_KEY_BITS};
pub use column::fcc_closer::{WAIT_ADDR_BITS, WAIT_ROOM};
pub use column::fcc_col_dist::COL_DIST_LATENCY;
pub use column::fcc_col_front::FRONT_LATENCY;
pub use column::fcc_col_slot_buf::{SLOT_BUF, SLOT_CREDITS};
pub use column::fcc_col_window::COL_WINDOW_LATENCY;
pub use column::fcc_flush_wait::FLUSH_WAIT;
pub use column::fcc_label_lists::{WALK_BITS, WALK_ROOM};
pub use column::fcc_label_pool::POOL_LATENCY;
pub use column::fcc_run_acc::RUN_ACC_LATENCY;
pub use column::fcc_slot_records::SLOT_RECORDS_LATENCY;
pub use column::RunLimits;
pub use fcc_fanout_reg::MAX_FANOUT;
pub use fcc_join_queue::JQ_HIGH_LEVEL;
pub use fcc_pix_thr::THR_LAG;
pub use fcc_regs::FccRegs;
pub use fcc_top::{FccTop, CREDITS};

/// Version of this generator, written into every generated file.
pub const GENERATOR_VERSION: &str = env!("CARGO_PKG_VERSION");

/// The top-level module's name before the configuration suffix (and the
/// name of the files it is written to: `fcc_top.v`, `fcc_top.xdc`).
pub const TOP_NAME: &str = "fcc_top";

/// The top-level Verilog module of `p`: [`TOP_NAME`] and
/// [`FccParams::module_suffix`], e.g. `fcc_top_k7_1b2c3d4e`. Every module of
/// the configuration carries the same suffix, so two configurations can be
/// compiled into one simulation or one Vivado project; the packaged IP has
/// this name too.
pub fn top_module(p: &FccParams) -> String {
    format!("{TOP_NAME}{}", p.module_suffix())
}

/// Everything that can go wrong while generating or checking RTL.
#[derive(Debug, Error)]
pub enum RtlError {
    #[error("parameters cannot be built in hardware: {0}")]
    Params(#[from] ParamError),
    #[error("the rust-hdl design check failed: {0}")]
    Check(String),
    #[error("cannot write {path}: {source}")]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    #[error("cannot run {tool} ({source}); install it (Debian: apt-get install {package}) or put it on PATH")]
    ToolMissing {
        tool: String,
        package: String,
        source: std::io::Error,
    },
    #[error("{0}")]
    Board(String),
    #[error(
        "refusing to overwrite files of another configuration: {}; choose another --out, or pass --force to replace them",
        .0.join(", ")
    )]
    OtherConfiguration(Vec<String>),
    #[error("verilator --lint-only -Wall reported problems in {path}:\n{log}")]
    Lint { path: PathBuf, log: String },
    #[error("{dir}: no generated configuration here (no fcc_params.json in {dir}/rtl_out or in it); make one with `fcc gen --out {dir}`")]
    NotGenerated { dir: PathBuf },
    #[error("{path}: {message}")]
    BadParamsFile { path: PathBuf, message: String },
    #[error("{path}: no module {top}, the top module of its fcc_params.json (written by an older fcc gen, or edited); regenerate it with fcc gen")]
    NoTopModule { path: PathBuf, top: String },
}

/// The generated files of one configuration, as text.
#[derive(Debug, Clone, PartialEq)]
pub struct Generated {
    pub params: FccParams,
    /// `fcc_top.v`: all modules of the core.
    pub verilog: String,
    /// `fcc_params.vh`: the parameters as Verilog defines, for benches.
    pub verilog_header: String,
    /// `fcc_params.h`: the same as C++ constants, for the Verilator shim.
    pub cpp_header: String,
    /// `fcc_params.json`: the canonical parameter set, the generator
    /// version, the hash and the register map (see [`ParamsFile`]).
    pub params_json: String,
    /// `fcc_regs.h`: the register map for C99 software.
    pub regs_header: String,
    /// `fcc_lint.vlt`: the Verilator lint waivers, each with its reason.
    pub lint_waivers: String,
}

impl Generated {
    /// File names and contents, in a fixed order.
    pub fn files(&self) -> Vec<(&'static str, &str)> {
        vec![
            ("fcc_top.v", self.verilog.as_str()),
            ("fcc_params.vh", self.verilog_header.as_str()),
            ("fcc_params.h", self.cpp_header.as_str()),
            ("fcc_params.json", self.params_json.as_str()),
            ("fcc_regs.h", self.regs_header.as_str()),
            ("fcc_lint.vlt", self.lint_waivers.as_str()),
        ]
    }
}

/// One line naming the parameters, for headers and messages.
pub fn param_summary(p: &FccParams) -> String {
    p.fields()
        .iter()
        .map(|(name, value)| format!("{name}={value}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The header every generated file starts with (`prefix` is the comment leader).
pub fn file_header(p: &FccParams, prefix: &str) -> String {
    [
        format!(
            "Generated by fcc-rtl {GENERATOR_VERSION} (rust-hdl 0.46). Do not edit: regenerate."
        ),
        format!("Parameters: {}", param_summary(p)),
        format!("Parameter hash: {}", p.hash()),
    ]
    .iter()
    .map(|l| format!("{prefix} {l}\n"))
    .collect()
}

/// Build the design for `p`, check it and emit Verilog plus its companions.
///
/// The last few configurations generated in this process are kept: a
/// command that checks the model cache, loads the model and sets up the
/// virtual board asks for the same configuration several times, and a large
/// core takes the generator seconds each time.
pub fn generate(p: &FccParams) -> Result<Generated, RtlError> {
    /// How many configurations are kept.
    const KEPT: usize = 4;
    static LAST: std::sync::Mutex<Vec<Generated>> = std::sync::Mutex::new(Vec::new());
    let kept = |g: &Generated| g.params == *p;
    if let Some(g) = LAST
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .iter()
        .find(|g| kept(g))
    {
        return Ok(g.clone());
    }
    let g = generate_uncached(p)?;
    let mut last = LAST.lock().unwrap_or_else(|e| e.into_inner());
    if !last.iter().any(kept) {
        if last.len() == KEPT {
            last.remove(0);
        }
        last.push(g.clone());
    }
    Ok(g)
}

fn generate_uncached(p: &FccParams) -> Result<Generated, RtlError> {
    p.validate_for_hardware()?;
    let raw = match p.scan {
        Scan::Row => top_verilog(FccTop::new(p))?,
        Scan::Column => top_verilog(column::fcc_col_top::FccColTop::new(p))?,
    };
    let body = rename_modules(&constant_selects(&raw), TOP_NAME, &p.module_suffix());
    let mut verilog = file_header(p, "//");
    verilog.push_str(&io_comment());
    verilog.push_str("`default_nettype none\n");
    verilog.push_str(&body);
    if !verilog.ends_with('\n') {
        verilog.push('\n');
    }
    verilog.push_str("`default_nettype wire\n");
    Ok(Generated {
        params: p.clone(),
        verilog,
        verilog_header: verilog_header(p),
        cpp_header: cpp_header(p),
        params_json: params_json(p),
        regs_header: regmap::c_header(p),
        lint_waivers: lint::waivers(p),
    })
}

/// Check the top `top` and emit its Verilog as rust-hdl writes it.
fn top_verilog<B: Block>(mut top: B) -> Result<String, RtlError> {
    top.connect_all();
    check_all(&top).map_err(|e| RtlError::Check(format!("{e:?}")))?;
    Ok(generate_verilog_unchecked(&top))
}

/// Check `block` and emit it alone as the module `name` with the
/// configuration suffix of `p`, for its own bench (the core's copy is inside
/// `fcc_top.v`). `p` has been validated for hardware.
pub(crate) fn generate_block<B: Block>(
    p: &FccParams,
    mut block: B,
    name: &str,
) -> Result<String, RtlError> {
    block.connect_all();
    check_all(&block).map_err(|e| RtlError::Check(format!("{e:?}")))?;
    let raw = generate_verilog_unchecked(&block);
    let mut v = file_header(p, "//");
    v.push_str("`default_nettype none\n");
    v.push_str(&rename_modules(
        &constant_selects(&raw),
        name,
        &p.module_suffix(),
    ));
    v.push_str("\n`default_nettype wire\n");
    Ok(v)
}

/// Name of the register file's module when generated alone (its bench),
/// before the configuration suffix.
pub const REGS_NAME: &str = "fcc_regs";

/// The register file's module when generated alone for `p`:
/// `fcc_regs_k7_1b2c3d4e`.
pub fn regs_module(p: &FccParams) -> String {
    format!("{REGS_NAME}{}", p.module_suffix())
}

/// The Verilog of the register file `FccRegs` alone, as a module
/// [`regs_module`] (for its own bench; the core's copy is inside `fcc_top.v`).
pub fn generate_regs(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(p, FccRegs::new(p), REGS_NAME)
}

/// Name of the register file's bus adapter when generated alone (its
/// bench), before the configuration suffix.
pub const AXIL_ADAPTER_NAME: &str = "fcc_axil_adapter";

/// The register file's AXI4-Lite adapter `FccAxilAdapter` alone, for its
/// bench: one write-enable per writable register of the map of `p`
/// ([`regmap::writable_offsets`], in that order).
pub fn generate_axil_adapter(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(
        p,
        fcc_axil_adapter::FccAxilAdapter::new(&regmap::writable_offsets(p)),
        AXIL_ADAPTER_NAME,
    )
}

/// Name of the merge table's module when generated alone (its bench),
/// before the configuration suffix.
pub const MERGE_TABLE_NAME: &str = "fcc_merge_table";

/// The merge table's module when generated alone for `p`:
/// `fcc_merge_table_k7_1b2c3d4e`.
pub fn merge_table_module(p: &FccParams) -> String {
    format!("{MERGE_TABLE_NAME}{}", p.module_suffix())
}

/// The Verilog of the merge table `FccMergeTable` alone, as a module
/// [`merge_table_module`] with its sub-blocks (for its own bench; the core's copy
/// is inside `fcc_top.v`).
pub fn generate_merge_table(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(p, fcc_merge_table::FccMergeTable::new(p), MERGE_TABLE_NAME)
}

/// Name of the label updater's Verilog module when it is generated alone,
/// before the configuration suffix.
pub const LABEL_UPDATE_NAME: &str = "fcc_label_update";

/// The label updater's module when generated alone for `p`.
pub fn label_update_module(p: &FccParams) -> String {
    format!("{LABEL_UPDATE_NAME}{}", p.module_suffix())
}

/// The label updater `fcc_label_update` alone, for its bench: the frame
/// buffer, the read-back pipeline, the decoded-beat queue, the gearbox and
/// the output register of the build `p`.
pub fn generate_label_update(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(
        p,
        fcc_label_update::FccLabelUpdate::new(p),
        LABEL_UPDATE_NAME,
    )
}

/// Name of the window probe's module (the window's bench), before the
/// configuration suffix.
pub const WINDOW_NAME: &str = "fcc_window_probe";

/// The window probe's module when generated alone for `p`.
pub fn window_module(p: &FccParams) -> String {
    format!("{WINDOW_NAME}{}", p.module_suffix())
}

/// The Verilog of `fcc_window` and its line buffers behind the scalar ports
/// of `FccWindowProbe`, as a module [`window_module`] (for the window's own
/// bench; the core's copy is inside `fcc_top.v`).
pub fn generate_window(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(p, fcc_window_probe::FccWindowProbe::new(p), WINDOW_NAME)
}

/// Name of the per-point threshold unit's module when generated alone (its
/// bench), before the configuration suffix.
pub const POINT_THR_NAME: &str = "fcc_point_thr";

/// The per-point threshold unit `fcc_point_thr` alone, for its bench (the
/// same for every build; the configuration suffix names it).
pub fn generate_point_thr(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(p, fcc_point_thr::FccPointThr::new(), POINT_THR_NAME)
}

/// Name of the sort network's module when generated alone (its bench),
/// before the configuration suffix.
pub const SORT_NET_NAME: &str = "fcc_sort_net";

/// The sort network's module when generated alone for `p`.
pub fn sort_net_module(p: &FccParams) -> String {
    format!("{SORT_NET_NAME}{}", p.module_suffix())
}

/// The Verilog of the sort network `FccSortNet` alone (sort filter, centre
/// buffer, serializer, join queue), as a module [`sort_net_module`] (for its
/// own bench; the core's copy is inside `fcc_top.v`). Its per-position ports
/// keep rust-hdl's names `hit$e` and `rep$e`.
pub fn generate_sort_net(p: &FccParams) -> Result<String, RtlError> {
    p.validate_for_hardware()?;
    generate_block(p, fcc_sort_net::FccSortNet::new(p), SORT_NET_NAME)
}

/// The contents of `fcc_params.json`.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ParamsFile {
    pub generator_version: String,
    /// [`FccParams::hash`] of `params`.
    pub params_hash: String,
    /// [`top_module`] of `params`: the name of the core's Verilog module
    /// and of the packaged IP (absent in files of older generators).
    #[serde(default)]
    pub top_module: String,
    /// The build: limits of the core and power-on defaults of its run registers.
    pub params: FccParams,
    /// The register map ([`regmap::registers`]).
    pub registers: serde_json::Value,
}

impl ParamsFile {
    /// Read `fcc_params.json` text; a plain [`FccParams`] object (files of
    /// older generators) is accepted too.
    pub fn params_from_json(text: &str) -> Result<FccParams, serde_json::Error> {
        match serde_json::from_str::<ParamsFile>(text) {
            Ok(f) => Ok(f.params),
            Err(e) => serde_json::from_str::<FccParams>(text).map_err(|_| e),
        }
    }
}

/// The directory of a configuration written by `fcc gen --out DIR` that
/// holds its `fcc_params.json` and Verilog: `DIR/rtl_out` ([`RTL_DIR`], the
/// layout `fcc gen --out` writes), or `DIR` itself (a Verilog directory
/// given directly, e.g. one written with `fcc gen --rtl`). This is the one
/// place that knows where `fcc gen` puts them.
pub fn generated_rtl_dir(dir: &Path) -> Result<PathBuf, RtlError> {
    [dir.join(RTL_DIR), dir.to_path_buf()]
        .into_iter()
        .find(|d| d.join("fcc_params.json").is_file())
        .ok_or_else(|| RtlError::NotGenerated {
            dir: dir.to_path_buf(),
        })
}

/// The build parameters of the configuration generated into `dir` (see
/// [`generated_rtl_dir`]): the limits of the core and the power-on values of
/// its run registers.
pub fn read_generated_params(dir: &Path) -> Result<FccParams, RtlError> {
    let path = generated_rtl_dir(dir)?.join("fcc_params.json");
    let text = std::fs::read_to_string(&path).map_err(|e| RtlError::BadParamsFile {
        path: path.clone(),
        message: format!("cannot read: {e}"),
    })?;
    let p = ParamsFile::params_from_json(&text).map_err(|e| RtlError::BadParamsFile {
        path: path.clone(),
        message: format!("not a parameter file of fcc gen: {e}"),
    })?;
    p.validate_for_hardware()
        .map_err(|e| RtlError::BadParamsFile {
            path,
            message: e.to_string(),
        })?;
    Ok(p)
}

/// Check that `verilog` (read from `path`) declares the top module of `p`.
pub fn check_top_module(p: &FccParams, verilog: &str, path: &Path) -> Result<(), RtlError> {
    let top = top_module(p);
    let header = format!("module {top}(");
    if verilog.lines().any(|l| l.trim_start().starts_with(&header)) {
        Ok(())
    } else {
        Err(RtlError::NoTopModule {
            path: path.to_path_buf(),
            top,
        })
    }
}

fn params_json(p: &FccParams) -> String {
    let f = ParamsFile {
        generator_version: GENERATOR_VERSION.to_string(),
        params_hash: p.hash(),
        top_module: top_module(p),
        params: p.clone(),
        registers: regmap::json(p),
    };
    format!(
        "{}\n",
        serde_json::to_string_pretty(&f).expect("the parameter file always serialises")
    )
}

/// Write the generated files of `p` into `dir` (created if missing).
pub fn write_rtl(p: &FccParams, dir: &Path) -> Result<Vec<PathBuf>, RtlError> {
    let g = generate(p)?;
    write_files(dir, &g.files())
}

/// Where `write_all` puts things.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// Verilog and its companions.
    pub rtl: PathBuf,
    /// `fcc_top.xdc`.
    pub constraints: PathBuf,
    /// `fcc_build.tcl`, `fcc_package_ip.tcl`, the block design and the C example.
    pub scripts: PathBuf,
}

/// Directory names of a generated layout, under its root.
pub const RTL_DIR: &str = "rtl_out";
pub const CONSTRAINTS_DIR: &str = "constraints";
pub const SCRIPTS_DIR: &str = "scripts";

impl Default for Layout {
    /// The repository layout: `rtl_out/`, `constraints/`, `scripts/`.
    fn default() -> Self {
        Layout {
            rtl: PathBuf::from(RTL_DIR),
            constraints: PathBuf::from(CONSTRAINTS_DIR),
            scripts: PathBuf::from(SCRIPTS_DIR),
        }
    }
}

impl Layout {
    /// The repository-shaped layout under `root`: `root/rtl_out`,
    /// `root/constraints`, `root/scripts`.
    pub fn under(root: &Path) -> Layout {
        Layout {
            rtl: root.join(RTL_DIR),
            constraints: root.join(CONSTRAINTS_DIR),
            scripts: root.join(SCRIPTS_DIR),
        }
    }
}

/// What [`write_all_with`] does besides the default configuration.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct WriteOptions {
    /// The board the block design and the scripts are for.
    pub board: vivado::Board,
    /// Overwrite files generated for another configuration (another
    /// parameter hash or board) or not generated by `fcc gen` at all.
    pub force: bool,
}

/// Write the RTL, the XDC and the Vivado scripts of `p` for the ZC706,
/// refusing to overwrite another configuration's files.
pub fn write_all(p: &FccParams, layout: &Layout) -> Result<Vec<PathBuf>, RtlError> {
    write_all_with(p, layout, &WriteOptions::default())
}

/// Write the RTL, the XDC, the Vivado scripts and the bare-metal C example
/// of `p` for `opts.board`. Every file is made and every existing file
/// checked before the first is written: a configuration the board cannot
/// run, or a directory that holds another configuration, leaves nothing
/// changed.
pub fn write_all_with(
    p: &FccParams,
    layout: &Layout,
    opts: &WriteOptions,
) -> Result<Vec<PathBuf>, RtlError> {
    let g = generate(p)?;
    let extra = vivado::extra_scripts(&g, layout, opts.board)?;
    let xdc = vivado::xdc(p);
    let tcl = vivado::tcl(
        p,
        opts.board,
        &vivado::relative(&layout.scripts, &layout.rtl.join("fcc_top.v")),
        &vivado::relative(&layout.scripts, &layout.constraints.join("fcc_top.xdc")),
    );
    let mut plan: Vec<(PathBuf, &str)> = g
        .files()
        .into_iter()
        .map(|(n, t)| (layout.rtl.join(n), t))
        .collect();
    plan.push((layout.constraints.join("fcc_top.xdc"), &xdc));
    plan.push((layout.scripts.join(vivado::BUILD_SCRIPT), &tcl));
    for (n, t) in &extra {
        plan.push((layout.scripts.join(n), t.as_str()));
    }
    if !opts.force {
        check_overwrite(&plan)?;
    }
    let mut out = vec![];
    for (path, text) in plan {
        let dir = path.parent().unwrap_or(Path::new("."));
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default()
            .to_string();
        out.extend(write_files(dir, &[(&name, text)])?);
    }
    Ok(out)
}

/// Which configuration a generated file belongs to: its parameter hash
/// (`Parameter hash: ...` in the header, `"params_hash"` in the JSON) and,
/// for the board-specific scripts, its board (`Board: ...`).
pub fn file_identity(text: &str) -> Option<(String, Option<String>)> {
    let mut hash = None;
    let mut board = None;
    for line in text.lines().take(12) {
        if let Some(h) = line.split("Parameter hash: ").nth(1) {
            hash = Some(h.trim().to_string());
        } else if let Some(h) = line.split("\"params_hash\": \"").nth(1) {
            hash = Some(h.trim_end_matches([',', '"', ' ']).to_string());
        } else if let Some(b) = line.split("Board: ").nth(1) {
            board = b.split_whitespace().next().map(str::to_string);
        }
    }
    hash.map(|h| (h, board))
}

/// The existing files `plan` would replace that belong to another
/// configuration or were not written by the generator.
fn check_overwrite(plan: &[(PathBuf, &str)]) -> Result<(), RtlError> {
    let mut clashes = vec![];
    for (path, text) in plan {
        let Ok(old) = std::fs::read_to_string(path) else {
            continue;
        };
        let new = file_identity(text);
        // Scripts of generators before the board table were all for the ZC706.
        let old_id = file_identity(&old).map(|(h, b)| {
            let b = match (b, &new) {
                (None, Some((_, Some(_)))) => Some(vivado::Board::Zc706.info().name.to_string()),
                (b, _) => b,
            };
            (h, b)
        });
        match old_id {
            Some(id) if Some(&id) == new.as_ref() => {}
            Some((hash, board)) => clashes.push(format!(
                "{} (parameter hash {hash}{})",
                path.display(),
                board.map(|b| format!(", board {b}")).unwrap_or_default()
            )),
            None => clashes.push(format!("{} (not written by fcc gen)", path.display())),
        }
    }
    if clashes.is_empty() {
        Ok(())
    } else {
        Err(RtlError::OtherConfiguration(clashes))
    }
}

pub(crate) fn write_files(dir: &Path, files: &[(&str, &str)]) -> Result<Vec<PathBuf>, RtlError> {
    std::fs::create_dir_all(dir).map_err(|source| RtlError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut out = vec![];
    for (name, text) in files {
        let path = dir.join(name);
        fcc_io::write_atomic(&path, text.as_bytes()).map_err(|source| RtlError::Io {
            path: path.clone(),
            source,
        })?;
        out.push(path);
    }
    Ok(out)
}

fn io_comment() -> String {
    "//\n\
     // s_axis_tdata (one pixel per beat, raster order, tlast on the last pixel):\n\
     //   [15:0] x, [31:16] y, [47:32] z: Q7.8 two's complement metres\n\
     //   [48] valid: 1 = the pixel holds a point; [63:49] reserved, ignored\n\
     // m_axis_tdata: labels in raster order, 16-bit slots from bit 0,\n\
     //   tkeep marks the bytes of the slots that hold labels, tlast on the last beat.\n\
     //\n"
        .to_string()
}

/// Give rust-hdl's path-named modules the house names, each followed by the
/// configuration's `suffix`: `top` becomes `top_name` (`fcc_top`), a block
/// `top$intra` becomes `fcc_intra`, anything below a block
/// `fcc_<block>__<path>`, and registers of the top `<top_name>__<name>`.
/// Every `module X` declared in `v` is renamed, and every use of `X` with
/// it, so blocks added later are covered without a list.
fn rename_modules(v: &str, top_name: &str, suffix: &str) -> String {
    const BLOCKS: [&str; 7] = [
        "intra",
        "window",
        "dist_tree",
        "sort_net",
        "merge_table",
        "label_update",
        "regs",
    ];
    let mut map = BTreeMap::new();
    for line in v.lines() {
        if let Some(rest) = line.trim_start().strip_prefix("module ") {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == '$')
                .collect();
            let new = if name == "top" {
                top_name.to_string()
            } else if let Some(path) = name.strip_prefix("top$") {
                let first = path.split('$').next().unwrap_or_default();
                let flat = path.replace('$', "__");
                if BLOCKS.contains(&first) {
                    format!("fcc_{flat}")
                } else {
                    format!("{top_name}__{flat}")
                }
            } else {
                format!("fcc_{}", name.replace('$', "__"))
            };
            map.insert(name, format!("{new}{suffix}"));
        }
    }
    let mut out = String::with_capacity(v.len());
    let chars: Vec<char> = v.chars().collect();
    let mut i = 0;
    let is_id = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '$';
    while i < chars.len() {
        let c = chars[i];
        let boundary = i == 0 || !(is_id(chars[i - 1]) || chars[i - 1] == '\'');
        if boundary && (c.is_ascii_alphabetic() || c == '_') {
            let start = i;
            while i < chars.len() && is_id(chars[i]) {
                i += 1;
            }
            let tok: String = chars[start..i].iter().collect();
            match map.get(&tok) {
                Some(new) => out.push_str(new),
                None => out.push_str(&tok),
            }
        } else {
            out.push(c);
            i += 1;
        }
    }
    // Trailing blanks on otherwise empty lines are noise in a committed file.
    out.lines()
        .map(|l| l.trim_end())
        .collect::<Vec<_>>()
        .join("\n")
}

/// rust-hdl writes a constant part-select as `x[(64'h10)+:(16)]` and a
/// constant bit-select as `x[32'h30]`; Verilator's width lint rightly asks
/// for an index of the array's width. Rewrite them as the equivalent plain
/// `x[31:16]` and `x[48]`.
fn constant_selects(v: &str) -> String {
    let part =
        regex::Regex::new(r"\[\((\d+)'([hb])([0-9a-fA-F]+)\)\+:\((\d+)\)\]").expect("valid regex");
    let bit = regex::Regex::new(r"\[(\d+)'([hb])([0-9a-fA-F]+)\]").expect("valid regex");
    let value = |radix: &str, digits: &str| {
        u64::from_str_radix(digits, if radix == "h" { 16 } else { 2 }).unwrap_or(0)
    };
    let v = part.replace_all(v, |c: &regex::Captures| {
        let lo = value(&c[2], &c[3]);
        let w: u64 = c[4].parse().unwrap_or(1);
        format!("[{}:{}]", lo + w - 1, lo)
    });
    bit.replace_all(&v, |c: &regex::Captures| {
        format!("[{}]", value(&c[2], &c[3]))
    })
    .into_owned()
}

fn verilog_header(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`ifndef FCC_PARAMS_VH\n`define FCC_PARAMS_VH\n");
    s.push_str(&format!(
        "// The core's module name: instantiate `FCC_TOP_MODULE.\n`define FCC_TOP_MODULE {}\n",
        top_module(p)
    ));
    for (k, v) in constants(p) {
        s.push_str(&format!("`define FCC_{k} {v}\n"));
    }
    s.push_str("`endif\n");
    s
}

fn cpp_header(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("#pragma once\n#include <cstdint>\nnamespace fcc {\n");
    for (k, v) in constants(p) {
        s.push_str(&format!("constexpr uint64_t {k} = {v}u;\n"));
    }
    s.push_str("}  // namespace fcc\n");
    s
}

/// Integer constants shared by the benches (derived once, from `FccParams`).
fn constants(p: &FccParams) -> Vec<(&'static str, u64)> {
    vec![
        ("ROWS", p.rows as u64),
        ("COLS", p.cols as u64),
        ("PIXELS", p.pixels() as u64),
        ("FSIZE", p.fsize as u64),
        ("HALF", p.half() as u64),
        ("WINDOW_POSITIONS", p.window_positions() as u64),
        ("TH_H_Q", p.th_h_q() as u64),
        ("TH_V_Q", p.th_v_q() as u64),
        ("TH_H_SQ", p.th_h_sq() as u64),
        ("TH_V_SQ", p.th_v_sq() as u64),
        ("LABEL_BITS", u64::from(p.label_bits)),
        ("MAX_LABEL", u64::from(p.max_label())),
        ("LABELS_PER_BEAT", u64::from(p.labels_per_beat)),
        ("INPUT_VALID_BIT", 48),
        ("CENTRE_BUFFER_DEPTH", 1u64 << fcc_sort_net::CB_BITS),
        ("INPUT_CREDITS", CREDITS as u64),
    ]
}
