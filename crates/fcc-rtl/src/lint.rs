//! Verilator lint of the generated Verilog (`verilator --lint-only -Wall`).

use std::path::Path;
use std::process::Command;

use fcc_params::FccParams;

use crate::{file_header, top_module, RtlError};

/// The waiver file written beside the Verilog. Every waiver says why.
pub fn waivers(p: &FccParams) -> String {
    if p.scan == fcc_params::Scan::Column {
        return col_top_waivers(p);
    }
    let mut s = top_waivers(p);
    s.push_str(
        "// The frame's columns C (<= 4096) are used modulo 4096 (as C - 1 and\n\
         // C - 2, both below 4096), so bit 12 of the run value is not read.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'regs$run_cols'[12]*\"\n\
         // FccFifo offers its fill level and its RAM's ports (for side RAMs) to\n\
         // every user. The centre buffer needs no level (the input credits bound\n\
         // it) and the join queue has no side RAMs.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'records$level'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'queue$ram_*\"\n\
         // The input stage serves both cores: the raster order's column-start\n\
         // flag is constant low and its top holds no column.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'in_stage$col_first'*\"\n\
         // rust-hdl declares a state enum's names (`SerPhase`) as localparams in\n\
         // every module that holds the enum, the state register's DFF included,\n\
         // which does not read them, and that DFF initialises its output with a\n\
         // 64-bit zero.\n\
         lint_off -rule UNUSEDPARAM -file \"*fcc_top.v\" -match \"*'SerPhase$*\"\n\
         lint_off -rule WIDTH -file \"*fcc_top.v\" -match \"*expects 2 bits on the Assign RHS, but Assign RHS's CONST '64'h0'*\"\n",
    );
    s.push_str(&axil_waivers("fcc_top.v"));
    s.push_str(&enum_register_waivers("fcc_top.v"));
    s.push_str(&slot_mux_waivers("fcc_top.v"));
    s.push_str(&rep_window_waivers(p, "fcc_top.v"));
    s
}

/// The waiver of the representative window in `file`: at K = 3 it has one
/// buffer, written by the sort network, and no cascade.
fn rep_window_waivers(p: &FccParams, file: &str) -> String {
    if p.half() > 1 {
        return String::new();
    }
    format!(
        "// At K = 3 the representative window has one buffer (written by the sort\n\
         // network) and no cascade, whose writes the pixel's column addresses.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'cascade_col'*\"\n"
    )
}

/// The waivers of the label updater's slot multiplexers and pop decisions,
/// in `file`.
fn slot_mux_waivers(file: &str) -> String {
    format!(
        "// Slot j of a beat holds one of the beat's first j + 1 new labels, so\n\
         // slot j's FccSlotMux reads only those of the collected labels and\n\
         // slot 0's never the gearbox's second label.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'collected_k$*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'gear_next'*\"\n\
         // The gearbox's copy of the pop decision steers the gearbox only;\n\
         // whether the head beat is complete is the beat assembly's copy's.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'gear_decision$complete'*\"\n"
    )
}

/// The waivers of a bench block `name` that holds a `LogicState` enum
/// register and needs nothing else.
pub fn enum_block_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&enum_register_waivers(&format!("{name}.v")));
    s
}

/// The waivers of a register that holds a `LogicState` enum, in `file`:
/// rust-hdl declares the enum's values as `Enum$Value` parameters in every
/// module that sees the type (the register's own module reads none of them)
/// and sets the register's simulation start value with a 64-bit zero.
fn enum_register_waivers(file: &str) -> String {
    format!(
        "// rust-hdl declares every LogicState enum's values in each module that\n\
         // holds the type, used or not, and starts an enum register at 64'h0.\n\
         lint_off -rule UNUSEDPARAM -file \"*{file}\" -match \"*Parameter is not used: '*$*'*\"\n\
         lint_off -rule WIDTH -file \"*{file}\" -match \"*Assign RHS's CONST '64'h0' generates 64 bits*\"\n"
    )
}

/// The waivers of the register file's ports, in `file`.
fn axil_waivers(file: &str) -> String {
    format!(
        "// The register file ignores write strobes (every write is a full word,\n\
         // see the register map) and decodes word addresses (bits 1:0 unused).\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'s_axil_wstrb'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'s_axil_awaddr'[1:0]*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{file}\" -match \"*'s_axil_araddr'[1:0]*\"\n"
    )
}

/// The waivers of `fcc_regs.v`, the register file generated alone for its bench.
pub fn regs_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_regs.v holds the register file and its read multiplexer.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_regs.v\"\n",
    );
    s.push_str(&axil_waivers("fcc_regs.v"));
    s
}

/// The waivers of `fcc_axil_adapter.v`, the register file's bus adapter
/// generated alone for its bench.
pub fn axil_adapter_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_axil_adapter.v holds the adapter and its registers; the module\n\
         // name carries the configuration suffix.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_axil_adapter.v\"\n",
    );
    s.push_str(&axil_waivers("fcc_axil_adapter.v"));
    s
}

/// The waivers of `fcc_label_update.v`, the label updater generated alone
/// for its bench.
pub fn label_update_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_label_update.v holds the label updater and its sub-blocks.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_label_update.v\"\n",
    );
    s.push_str(&slot_mux_waivers("fcc_label_update.v"));
    s
}

/// The waivers of a bench block `name` that needs none beyond its file's
/// name.
pub fn block_waivers(p: &FccParams, name: &str) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(&format!(
        "// The module carries the configuration suffix; the file does not.\n\
         lint_off -rule DECLFILENAME -file \"*{name}.v\"\n"
    ));
    s
}

/// The waivers of the representative rows' probe `name`: its enum
/// register's (as [`enum_block_waivers`]); its hit mask and label words are
/// sized for K = 11; the probe reads the pixel's
/// position and label only; the rows above the window are not read.
pub fn rep_joins_waivers(p: &FccParams, name: &str) -> String {
    let mut s = enum_block_waivers(p, name);
    s.push_str(&format!(
        "// Sized for K = 11: a smaller window leaves upper bits and words unread.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'words$*\"\n\
         // The probe reads the pixel's position, label and flags only.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'joins$out'*\"\n\
         // The rows above the window only take rewrites on their way out\n\
         // (`wb_*`): their labels, ages and rewritten values are not read.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'window$label$*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'window$age$*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'window$rep_next$*\"\n"
    ));
    s
}

/// The waivers of the column window's probe `name`: it brings out the
/// centre's position and label only; the window passes the rest of the
/// slot through unchanged (a delay line the probe feeds with zeros).
pub fn col_window_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// The probe reads the centre's position and label; the rest of the\n\
         // slot is a delay line fed with zeros.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'col_window$centre'*\"\n\
         // The word window's centre positions (the pixel's own row, never a\n\
         // pair) only feed its cascade.\n"
    ));
    let (k, h) = (p.fsize, p.half());
    for r in 0..h {
        for lane in ["lane", "lok_lane"] {
            s.push_str(&format!(
                "lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'{lane}$ent${}'*\"\n",
                r * k + h
            ));
        }
    }
    s
}

/// The waivers of the column distance tests' probe `name`: it keeps the
/// centre's label only; the rest of the slot is a delay line it feeds with
/// zeros.
pub fn col_dist_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// The probe keeps the centre's label and valid bit; the rest of the\n\
         // slot is a delay line fed with zeros.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'col_dist$centre'*\"\n"
    ));
    s
}

/// The waivers of the column core front's probe `name`: the window's
/// centre positions (as [`col_window_waivers`]), the label words and mask
/// sized for K = 11, and the centre's fields the probe does not bring out.
pub fn col_front_waivers(p: &FccParams, name: &str) -> String {
    let mut s = col_window_waivers(p, name);
    s.push_str(&format!(
        "// The probe brings out the centre's position, run and flags only.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'front$centre'*\"\n\
         // The input stage's slot: the column core reads rows below 128 and\n\
         // marks columns by their number, not by the row-major flags.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'thr$out'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'row8'*\"\n"
    ));
    s
}

/// The waivers of the column slot buffer's probe `name`: its lanes move in
/// step, so the first lane's `valid` and `level` stand for all; the credit
/// counter's `drop` (the row-major core's) is tied low; the probe feeds a
/// few of the centre's fields.
pub fn col_slot_buf_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// The lanes move in step: the centre's lane's valid and level stand\n\
         // for all (the credits, not the level, bound the buffer).\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits$valid'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'fifo$valid'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*$level'*\"\n\
         // Sized for K = 11: a smaller window leaves upper bits, words and a\n\
         // last lane's labels unread.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits$dout'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'words$*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'labels$*\"\n\
         // The probe feeds and reads a few of the centre's fields.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'slots$centre'*\"\n"
    ));
    s
}

/// The waivers of the column core input half's probe `name`: the front's
/// (the window's centre positions, the stage's slot fields the column
/// core does not read) and the slot buffer's lanes, and the centre's
/// fields the probe does not bring out.
pub fn col_in_waivers(p: &FccParams, name: &str) -> String {
    let mut s = col_window_waivers(p, name);
    s.push_str(&format!(
        "// The probe brings out the centre's position, run and flags only.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'half$centre'*\"\n\
         // The input stage's slot: the column core reads rows below 128 and\n\
         // marks columns by their number, not by the row-major flags.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'thr$out'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'row8'*\"\n\
         // The slot buffer's lanes move in step: the centre's lane's valid\n\
         // and level stand for all; a smaller window leaves upper bits and a\n\
         // last lane's labels unread.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits$valid'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'fifo$valid'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*$level'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'hits$dout'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'labels$*\"\n\
         // rust-hdl's widening bit_cast in the column-start check: an AND with\n\
         // the wider mask (the narrower operand is zero-extended, the cast).\n\
         lint_off -rule WIDTH -file \"*{name}.v\" -match \"*Operator AND expects*\"\n\
         // Not a loop: the stage's col_first comes from its registers, and the\n\
         // check's hold from it and its own; rust-hdl writes each block's logic\n\
         // as one always block, whose every output Verilator takes to follow\n\
         // every input.\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*start$hold'*\"\n\
         // The columns begun are counted by the datapath (`FccColSettle`),\n\
         // and the cycles held are its output; the half's probes give the\n\
         // counts.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'*$col_begin'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'*$col_held'*\"\n"
    ));
    s
}

/// The waivers of the record accumulator's probe `name`: rust-hdl emits a
/// widening `bit_cast` as an AND with the wider mask, which zero-extends
/// the narrower operand as intended.
pub fn acc_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// rust-hdl's widening bit_cast: an AND with the wider mask (the\n\
         // narrower operand is zero-extended, which is the cast).\n\
         lint_off -rule WIDTH -file \"*{name}.v\" -match \"*Operator AND expects*\"\n"
    ));
    s
}

/// The waivers of the record store's probe `name`: its enum registers'
/// (as [`enum_block_waivers`]), the widening casts of its close check (as
/// [`acc_waivers`]), the holds merge's second quiet column (the merge's
/// column replaces both) and the merged holds' fields a quiet report does
/// not carry (the open runs and the ring flag: both are 0 then).
pub fn slot_records_waivers(p: &FccParams, name: &str) -> String {
    let mut s = acc_waivers(p, name);
    s.push_str(&enum_register_waivers(&format!("{name}.v")));
    s.push_str(&format!(
        "// `FccHoldsMerge` takes the op's column as the quiet one, not `b`'s.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'b'[39:28]*\"\n\
         // A quiet report carries the first pixel and the quiet column only.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'mh'[8:0]*\"\n\
         // Of stage 1's holds only a close's key (the first pixel) is read.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'ah'[71:28,8:0]*\"\n"
    ));
    s
}

/// The waivers of the closer `name`: its state register's, the widening
/// casts of its due columns (as [`acc_waivers`]), and the wait list's and
/// the sorted entries' outputs it does not read.
pub fn closer_waivers(p: &FccParams, name: &str) -> String {
    let mut s = acc_waivers(p, name);
    s.push_str(&enum_register_waivers(&format!("{name}.v")));
    s.push_str(&format!(
        "// FccFifo offers its fill level and its RAM's ports (for side RAMs);\n\
         // the closer counts its entries itself and has no side RAM.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'list$level'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'list$ram_*\"\n\
         // The sorted entries' drop says when a push finds them full.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'order$full'*\"\n"
    ));
    s
}

/// The waivers of the label lists `name`: the queue's RAM ports it does
/// not use.
pub fn label_lists_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// FccFifo offers its RAM's ports (for side RAMs); the lists have none.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'queue$ram_*\"\n"
    ));
    s
}

/// The waivers of the flushes' wait's probe `name`: the FIFO's RAM ports
/// (it has no side RAM) and level (it counts its places itself).
pub fn flush_wait_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// FccFifo offers its RAM's ports (for side RAMs); the wait has none.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'queue$ram_*\"\n\
         // The wait counts its places exactly; the FIFO's level is a cycle late.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'queue$level'*\"\n"
    ));
    s
}

/// The waivers of the union-find's queue `name`: the FIFO's RAM ports (it
/// has no side RAM) and the parts of its entries some ops leave unused.
pub fn set_queue_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// FccFifo offers its RAM's ports (for side RAMs); the queue has none.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'queue$ram_*\"\n\
         // The queue keeps each op's kind itself, and the record store joins\n\
         // clusters by their slots: a join's gone root is not needed.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'sets$ev_join'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'sets$ev_gone'*\"\n\
         // The gate sees the whole head; a join's second label and its\n\
         // `under` go from the head to the union-find, not through the gate.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'h_op'[36:21,4]*\"\n"
    ));
    s
}

/// The waivers of the run accumulators' probe `name`: the accumulator's
/// (as [`acc_waivers`]), and the pixel's fields the block does not read
/// (it takes the run's fields of `RunPix` and its point, not its
/// thresholds, ring check or held label).
pub fn run_acc_waivers(p: &FccParams, name: &str) -> String {
    let mut s = acc_waivers(p, name);
    s.push_str(&format!(
        "// `FccRunAcc` reads the pixel's run, point and dropped hold only.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'inp'*\"\n\
         // Its steps' valid flags are read in a loop through a whole step\n\
         // (rust-hdl cannot take a field of an element indexed by a loop).\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'ahead_step'*\"\n"
    ));
    s
}

/// The waivers of the word window's probe `name`: at K = 3 the window has
/// one buffer and no cascade, so the cascade's enable and address are not
/// read.
pub fn word_window_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    if p.half() == 1 {
        s.push_str(&format!(
            "// At K = 3 the window has one buffer (buffer 0) and no cascade.\n\
             lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'cas_en'*\"\n\
             lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'cas_addr'*\"\n"
        ));
    }
    s
}

/// Lint `verilog`, generated for `p` (top module [`top_module`]), with the
/// waivers in `vlt`. Returns the log on success.
pub fn lint_files(p: &FccParams, verilog: &Path, vlt: &Path) -> Result<String, RtlError> {
    lint_module(verilog, vlt, &top_module(p))
}

/// Lint `verilog` with top module `top` and the waivers in `vlt`.
pub fn lint_module(verilog: &Path, vlt: &Path, top: &str) -> Result<String, RtlError> {
    let out = Command::new("verilator")
        .arg("--lint-only")
        .arg("-Wall")
        .arg("--top-module")
        .arg(top)
        .arg(vlt)
        .arg(verilog)
        .output()
        .map_err(|source| RtlError::ToolMissing {
            tool: "verilator".into(),
            package: "verilator".into(),
            source,
        })?;
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    if out.status.success() && !log.contains("%Warning") && !log.contains("%Error") {
        Ok(log)
    } else {
        Err(RtlError::Lint {
            path: verilog.to_path_buf(),
            log,
        })
    }
}

/// The waivers of `fcc_merge_table.v`, the merge table generated alone for
/// its bench.
pub fn merge_table_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_merge_table.v holds the merge table and its sub-blocks.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_merge_table.v\"\n",
    );
    s.push_str(&enum_register_waivers("fcc_merge_table.v"));
    s
}

/// The waivers of `fcc_window_probe.v`, the window and its line buffers
/// generated alone for their bench.
pub fn window_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_window_probe.v holds the window, its line buffers and the probe.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_window_probe.v\"\n\
         // The probe brings out the centre's x, column and valid bit, and each\n\
         // entry's point and ok bit (what the bench compares); the rest of the\n\
         // centre and the entries' representatives feed the core's later stages.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_window_probe.v\" -match \"*'window$centre'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_window_probe.v\" -match \"*'window$ent_rep$*\"\n",
    );
    s.push_str(&rep_window_waivers(p, "fcc_window_probe.v"));
    s
}

/// The waivers of `fcc_sort_net.v`, the sort network generated alone for
/// its bench: the core's waivers of the same sub-blocks (see [`waivers`]).
pub fn sort_net_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// fcc_sort_net.v holds the sort network and its sub-blocks.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_sort_net.v\"\n\
         // FccFifo's fill level and side-RAM ports, unused here as in fcc_top.v.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_sort_net.v\" -match \"*'records$level'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_sort_net.v\" -match \"*'queue$ram_*\"\n",
    );
    s.push_str(&enum_register_waivers("fcc_sort_net.v"));
    s
}

/// The waivers of the column core's two halves' probe `name`: its blocks'
/// own, as their probes have them (the input half's, the representative
/// rows', the union-find queue's, the run accumulators' and the flushes'
/// wait's), each without the file's header.
pub fn col_table_waivers(p: &FccParams, name: &str) -> String {
    let base = block_waivers(p, name);
    let mut s = enum_block_waivers(p, name);
    for part in [
        col_in_waivers,
        rep_joins_waivers,
        set_queue_waivers,
        run_acc_waivers,
        flush_wait_waivers,
    ] {
        let w = part(p, name);
        s.push_str(w.strip_prefix(base.as_str()).unwrap_or(&w));
    }
    s.push_str(&format!(
        "// Not a loop: the queue's ev_valid comes from its registers, and the\n\
         // probe's take from it; rust-hdl writes each block's logic as one\n\
         // always block, whose every output Verilator takes to follow every\n\
         // input.\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*sets$ev_take'*\"\n\
         // The slot table half's frame is done at its marker of column C; its\n\
         // queue's and wait's idle flags are not needed.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'queue$idle'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'flushes$idle'*\"\n"
    ));
    s
}

/// The column core's datapath: the halves' waivers.
pub fn col_core_waivers(p: &FccParams, name: &str) -> String {
    let base = block_waivers(p, name);
    let mut s = col_table_waivers(p, name);
    for part in [slot_records_waivers, closer_waivers, label_lists_waivers] {
        let w = part(p, name);
        s.push_str(w.strip_prefix(base.as_str()).unwrap_or(&w));
    }
    s.push_str(&format!(
        "// Not loops: rust-hdl writes each block's logic as one always block,\n\
         // whose every output Verilator takes to follow every input. The\n\
         // store's op goes to the records, whose take (from the op and the\n\
         // slots in flight) comes back to the arbiter's takes; the frame\n\
         // end's clear, marker and end beat go into the closer's, the\n\
         // arbiter's and the record out's registers only.\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*issue$op_take'*\"\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*ends$end_mark'*\"\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*pass$close_valid'*\"\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*closer$caught_up'*\"\n\
         lint_off -rule UNOPTFLAT -file \"*{name}.v\" -match \"*'*order$ev_valid'*\"\n\
         // Slots in use are at most 511, and the slot pool hands out 9-bit\n\
         // slots as 16-bit labels.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'used'[15:10]*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'slots$free_label'[15:9]*\"\n"
    ));
    s
}

/// The header of `fcc_lint.vlt` and the waivers of the top's ports, the
/// same in both cores.
fn top_waivers(p: &FccParams) -> String {
    let mut s = file_header(p, "//");
    s.push_str("`verilator_config\n");
    s.push_str(
        "// The generator writes every module of the core into one file, fcc_top.v;\n\
         // the file is named after the top module only.\n\
         lint_off -rule DECLFILENAME -file \"*fcc_top.v\"\n\
         // Bits 63:49 of an input beat are reserved and ignored by definition.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'s_axis_tdata'[63:49]*\"\n\
         // s_axis_tkeep is ignored by definition: every beat is one whole pixel\n\
         // (the port exists so that an AXI DMA's MM2S stream connects cleanly).\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'s_axis_tkeep'*\"\n",
    );
    s
}

/// The waivers of the column core's `fcc_top.v` (`fcc gen --scan column`):
/// its datapath's ([`col_core_waivers`]), the register file's, and the
/// top's own.
fn col_top_waivers(p: &FccParams) -> String {
    let mut s = top_waivers(p);
    s.push_str(
        "// The column core has at most 4095 columns (fcc-params checks it), so\n\
         // bit 12 of RUN_COLS is 0.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'run_cols'[12]*\"\n\
         // The datapath's fault flags (a label not in its row, a run, flush,\n\
         // accumulator or slot return gone wrong) never rise by design; its\n\
         // bench (col_core) asserts them low on every cycle.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'core$miss'*\"\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'core$bad'*\"\n\
         // The frame's input error rides on its end beat; the status takes it\n\
         // from there.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'core$err'*\"\n\
         // RUN_OPEN_LIMIT is at most 511.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*fcc_top.v\" -match \"*'open_limit'[11:10]*\"\n",
    );
    let core = col_core_waivers(p, "fcc_top");
    let base = block_waivers(p, "fcc_top");
    s.push_str(core.strip_prefix(base.as_str()).unwrap_or(&core));
    s.push_str(&axil_waivers("fcc_top.v"));
    s
}

/// The waivers of the column top's limits behind their probe: the probe
/// takes RUN_COLS as the register holds it (13 bits; the column core's
/// frames have at most 4095 columns) and RUN_OPEN_LIMIT in 12 bits (at
/// most 511).
pub fn col_limits_waivers(p: &FccParams, name: &str) -> String {
    let mut s = block_waivers(p, name);
    s.push_str(&format!(
        "// RUN_COLS is at most 4095 in the column core.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'run_cols'[12]*\"\n\
         // RUN_OPEN_LIMIT is at most 511.\n\
         lint_off -rule UNUSEDSIGNAL -file \"*{name}.v\" -match \"*'open_limit'[11:10]*\"\n"
    ));
    s
}
