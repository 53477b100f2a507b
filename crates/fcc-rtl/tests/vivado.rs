//! The Vivado deliverables: constraints and scripts follow the parameters and
//! the generated port list, are deterministic, parse as Tcl, and run through
//! `tclsh` with every Vivado command stubbed (a dry run: argument handling,
//! paths, the order of the flow and every value handed to Vivado; not
//! Vivado's own checks, which need Vivado).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use fcc_params::FccParams;
use fcc_rtl::vivado::{self, Board, Port, PortDir, BOARDS};
use fcc_rtl::{file_header, generate, top_module, write_all, Layout};

fn small() -> FccParams {
    FccParams {
        rows: 16,
        cols: 256,
        ..Default::default()
    }
}

fn ports(p: &FccParams) -> Vec<Port> {
    vivado::top_ports(&generate(p).unwrap().verilog, &top_module(p))
}

/// All four generated files of `p` for the repository layout, by name.
fn files(p: &FccParams) -> Vec<(String, String)> {
    let g = generate(p).unwrap();
    let mut out = vec![
        ("fcc_top.xdc".to_string(), vivado::xdc(p)),
        (
            "fcc_build.tcl".to_string(),
            vivado::tcl(
                p,
                Board::Zc706,
                "../rtl_out/fcc_top.v",
                "../constraints/fcc_top.xdc",
            ),
        ),
    ];
    for (n, t) in vivado::extra_scripts(&g, &Layout::default(), Board::Zc706).unwrap() {
        out.push((n.to_string(), t));
    }
    out
}

fn file<'a>(files: &'a [(String, String)], name: &str) -> &'a str {
    &files.iter().find(|(n, _)| n == name).unwrap().1
}

fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("fcc-vivado-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn top_ports_are_read_from_the_generated_verilog() {
    let ps = ports(&FccParams::default());
    let find = |n: &str| {
        ps.iter()
            .find(|p| p.name == n)
            .unwrap_or_else(|| panic!("{n}"))
    };
    assert_eq!(ps.first().unwrap().name, "clk");
    assert_eq!(find("s_axis_tdata").width, 64);
    assert_eq!(find("s_axis_tdata").dir, PortDir::In);
    assert_eq!(find("s_axis_tready").dir, PortDir::Out);
    assert_eq!(find("m_axis_tkeep").width, 8);
    assert_eq!(find("status_unlabelled").width, 20);
    assert_eq!(find("status_idle").width, 1);
    // Only the top module's ports: nothing of the sub-modules.
    let header = generate(&FccParams::default()).unwrap().verilog;
    let list = header
        .lines()
        .find(|l| l.starts_with(&format!("module {}(", top_module(&FccParams::default()))))
        .unwrap();
    assert_eq!(list.matches(',').count() + 1, ps.len(), "{list}");
    assert!(
        vivado::top_ports("module other(a);\n input wire a;\nendmodule\n", "fcc_top").is_empty()
    );
}

#[test]
fn period_follows_clock_mhz() {
    let p = FccParams {
        clock_mhz: 203.6,
        ..small()
    };
    let f = files(&p);
    let xdc = file(&f, "fcc_top.xdc");
    assert!(
        xdc.contains("create_clock -name clk -period 4.912 [get_ports clk]"),
        "{xdc}"
    );
    // 20 % of 4.912 ns outside the core, on the AXI ports, irq and rst.
    assert_eq!(xdc.matches(" 0.982 [get_ports").count(), 4, "{xdc}");
    let build = file(&f, "fcc_build.tcl");
    assert!(build.contains("set clock_mhz 203.6\n"));
    assert!(build.contains("set period_ns 4.912\n"));
    let bd = file(&f, "fcc_zc706_bd.tcl");
    assert!(bd.contains("CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {203.6}"));
    // The default: 200 MHz, 5 ns.
    let d = vivado::xdc(&FccParams::default());
    assert!(d.contains("-period 5.000 "));
    assert!(d.contains("set_input_delay -clock clk 1.000 "));
}

#[test]
fn clock_above_the_zc706_dma_limit_is_refused_at_generation() {
    let p = FccParams {
        clock_mhz: 250.0,
        ..small()
    };
    let g = generate(&p).unwrap();
    let e = vivado::extra_scripts(&g, &Layout::default(), Board::Zc706)
        .unwrap_err()
        .to_string();
    assert!(e.contains("--clock-mhz 250 is above 240 MHz"), "{e}");
    assert!(e.contains("PG022"), "{e}");
    // Nothing is written, not even the RTL.
    let root = std::env::temp_dir().join(format!("fcc-rtl-fclk-{}", std::process::id()));
    let layout = Layout {
        rtl: root.join("rtl_out"),
        constraints: root.join("constraints"),
        scripts: root.join("scripts"),
    };
    assert!(write_all(&p, &layout).is_err());
    assert!(!root.exists(), "a refused configuration left files behind");
    // The limit itself is accepted.
    let at = FccParams {
        clock_mhz: 240.0,
        ..small()
    };
    let f = files(&at);
    let bd = file(&f, "fcc_zc706_bd.tcl");
    assert!(bd.contains("CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {240}"));
}

#[test]
fn scripts_name_the_part_the_board_and_the_top() {
    let p = small();
    let f = files(&p);
    let top = top_module(&p);
    for name in ["fcc_build.tcl", "fcc_package_ip.tcl", "fcc_zc706_bd.tcl"] {
        assert!(
            file(&f, name).contains("set part xc7z045ffg900-2\n"),
            "{name}"
        );
    }
    assert!(file(&f, "fcc_build.tcl")
        .contains("synth_design -top $top -part $part -mode out_of_context\n"));
    assert!(file(&f, "fcc_build.tcl").contains(&format!("set top {top}\n")));
    assert!(file(&f, "fcc_package_ip.tcl").contains(&format!("set top {top}\n")));
    let bd = file(&f, "fcc_zc706_bd.tcl");
    assert!(bd.contains("set board_part xilinx.com:zc706:part0:1.4\n"));
    assert!(bd.contains(&format!(
        "create_bd_cell -type ip -vlnv fcc:fcc:{top}:0.1 fcc\n"
    )));
    assert_eq!(vivado::ip_vlnv(&p), format!("fcc:fcc:{top}:0.1"));
}

#[test]
fn every_file_carries_the_generated_header() {
    for p in [FccParams::default(), small()] {
        for (name, text) in files(&p) {
            let lead = if name.ends_with(".c") || name.ends_with(".h") {
                "//"
            } else {
                "#"
            };
            assert!(text.starts_with(&file_header(&p, lead)), "{name}");
            assert!(text.contains(&p.hash()), "{name}");
        }
    }
}

#[test]
fn generation_is_deterministic() {
    assert_eq!(files(&small()), files(&small()));
    let other = FccParams {
        fsize: 5,
        ..small()
    };
    // Another parameter set changes at least the headers.
    assert_ne!(files(&small()), files(&other));
}

/// `s_axis_*` and `m_axis_*` ports of the Verilog, each with its interface.
fn axis_ports(ps: &[Port]) -> Vec<(&'static str, &Port)> {
    let mut out = vec![];
    for p in ps {
        for (iface, _) in vivado::AXIS_INTERFACES {
            if p.name.starts_with(&format!("{iface}_")) {
                out.push((iface, p));
            }
        }
    }
    out
}

#[test]
fn every_axis_port_is_mapped_in_the_ip_script() {
    for p in [FccParams::default(), small()] {
        let ps = ports(&p);
        let f = files(&p);
        let ip = file(&f, "fcc_package_ip.tcl");
        let axis = axis_ports(&ps);
        assert_eq!(axis.len(), 10, "5 slave + 5 master ports");
        for (iface, port) in axis {
            // The map lines sit in the block `fcc_axis $core <iface> <mode> { ... }`.
            let start = ip
                .find(&format!("fcc_axis $core {iface} "))
                .unwrap_or_else(|| panic!("no interface {iface}"));
            let block = &ip[start..start + ip[start..].find("\n}\n").unwrap() + 1];
            let logical = port.name[iface.len() + 1..].to_uppercase();
            assert!(
                block.contains(&format!("\n    {logical} {}\n", port.name)),
                "{} not mapped to {logical} in {block}",
                port.name
            );
        }
        assert!(ip.contains("fcc_axis $core s_axis slave {"));
        assert!(ip.contains("fcc_axis $core m_axis master {"));
        assert!(ip.contains(
            "set_property value s_axis:m_axis:s_axil [ipx::add_bus_parameter ASSOCIATED_BUSIF $clk_bus]"
        ));
        // The register port: every s_axil_* port mapped, a 4 KiB memory map.
        let start = ip
            .find("fcc_axim $core s_axil slave {")
            .expect("s_axil interface");
        let block = &ip[start..start + ip[start..].find("\n}").unwrap() + 1];
        for port in ps.iter().filter(|p| p.name.starts_with("s_axil_")) {
            let logical = port.name["s_axil_".len()..].to_uppercase();
            assert!(
                block.contains(&format!("\n    {logical} {}\n", port.name)),
                "{} not mapped to {logical} in {block}",
                port.name
            );
        }
        assert!(ip.contains("set_property range 4096 $axil_block"));
        assert!(
            ip.contains("set_property physical_name irq [ipx::add_port_map INTERRUPT $irq_bus]")
        );
        assert!(ip.contains(
            "set_property value LEVEL_HIGH [ipx::add_bus_parameter SENSITIVITY $irq_bus]"
        ));
        assert!(ip
            .contains("set_property value rst [ipx::add_bus_parameter ASSOCIATED_RESET $clk_bus]"));
        assert!(ip
            .contains("set_property value ACTIVE_HIGH [ipx::add_bus_parameter POLARITY $rst_bus]"));
        assert!(ip.contains("xilinx.com:interface:axis_rtl:1.0"));
        assert!(ip.contains("ipx::save_core $core\n"));
    }
}

#[test]
fn every_port_is_constrained_in_the_xdc() {
    let ps = ports(&FccParams::default());
    let xdc = vivado::xdc(&FccParams::default());
    for p in &ps {
        let covered = if p.name == vivado::CLOCK_PORT {
            xdc.contains("create_clock -name clk -period")
        } else if p.name == vivado::RESET_PORT {
            xdc.contains("[get_ports rst]\n")
        } else if p.name.starts_with(vivado::STATUS_PREFIX) {
            p.dir == PortDir::Out && xdc.contains("set_false_path -to [get_ports status_*]")
        } else if p.name == vivado::IRQ_PORT {
            xdc.contains("set_output_delay -clock clk 1.000 [get_ports irq]\n")
        } else if ["s_axis_", "m_axis_", "s_axil_"]
            .iter()
            .any(|pre| p.name.starts_with(pre))
        {
            let filter = match p.dir {
                PortDir::In => "set_input_delay -clock clk 1.000 [get_ports -filter {DIRECTION == IN} {s_axis_* m_axis_* s_axil_*}]",
                PortDir::Out => "set_output_delay -clock clk 1.000 [get_ports -filter {DIRECTION == OUT} {s_axis_* m_axis_* s_axil_*}]",
            };
            xdc.contains(filter)
        } else {
            false
        };
        assert!(covered, "port {} has no constraint in fcc_top.xdc", p.name);
    }
}

#[test]
fn block_design_connects_the_register_port_and_irq() {
    let p = FccParams::default();
    let ps = ports(&p);
    let bd = vivado::bd_tcl(&p, &ps, Board::Zc706).unwrap();
    assert!(bd.contains(
        "connect_bd_intf_net [get_bd_intf_pins ctrl_smc/M01_AXI] [get_bd_intf_pins fcc/s_axil]"
    ));
    assert!(bd.contains("connect_bd_net [get_bd_pins fcc/irq] [get_bd_pins irq_concat/In2]"));
    assert!(bd.contains("CONFIG.NUM_PORTS {3}"));
    assert!(
        !bd.contains("axi_gpio"),
        "no GPIO: the status is in the registers"
    );
    assert!(!bd.contains("fcc/status_"), "status ports stay unconnected");
    for l in vivado::register_map_lines(&p) {
        assert!(bd.contains(&format!("puts $map {{register {l}}}")), "{l}");
    }
    assert_eq!(vivado::register_map_lines(&p)[10], "0x040 CONTROL RW");
}

#[test]
fn a_core_without_its_register_port_is_an_error() {
    let ps: Vec<Port> = ports(&small())
        .into_iter()
        .filter(|p| !p.name.starts_with("s_axil_"))
        .collect();
    let e = vivado::bd_tcl(&small(), &ps, Board::Zc706)
        .unwrap_err()
        .to_string();
    assert!(e.contains("s_axil"), "{e}");
}

#[test]
fn dma_transfers_hold_one_whole_frame() {
    let ps = ports(&small());
    let p = FccParams::default();
    assert_eq!(
        vivado::dma_frame_bytes(&p, &ps).unwrap(),
        (1 << 20, 1 << 18)
    );
    // 1 MiB needs 21 bits of length register.
    assert_eq!(vivado::dma_length_width(&p, &ps).unwrap(), 21);
    // A last beat with fewer labels still moves a whole beat.
    let odd = FccParams {
        rows: 17,
        cols: 257,
        labels_per_beat: 4,
        ..small()
    };
    assert_eq!(
        vivado::dma_frame_bytes(&odd, &ps).unwrap(),
        (17 * 257 * 8, (17 * 257_u64).div_ceil(4) * 8)
    );
    // The largest hardware frame fits the DMA's widest length register.
    let big = FccParams {
        rows: 128,
        cols: 4096,
        labels_per_beat: 1,
        ..small()
    };
    let w = vivado::dma_length_width(&big, &ps).unwrap();
    assert!(w <= vivado::DMA_LENGTH_WIDTH_MAX);
    assert!(1u64 << w > 128 * 4096 * 8);
    let bd = vivado::bd_tcl(&p, &ps, Board::Zc706).unwrap();
    assert!(bd.contains("CONFIG.c_sg_length_width {21}"));
    assert!(bd.contains("CONFIG.c_m_axis_mm2s_tdata_width {64}"));
    assert!(bd.contains("CONFIG.c_s_axis_s2mm_tdata_width {64}"));
    assert!(bd.contains("CONFIG.c_include_sg {0}"));
}

/// Braces balance and never close more than they opened (ignoring `\{`).
fn braces_balance(text: &str) -> bool {
    let mut depth: i64 = 0;
    let mut escaped = false;
    for c in text.chars() {
        match c {
            _ if escaped => escaped = false,
            '\\' => escaped = true,
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth < 0 {
                    return false;
                }
            }
            _ => {}
        }
    }
    depth == 0
}

#[test]
fn braces_balance_in_every_file() {
    for (name, text) in files(&FccParams::default()) {
        assert!(braces_balance(&text), "{name}");
    }
    assert!(!braces_balance("set a {b"));
    assert!(!braces_balance("} {"));
}

#[test]
fn committed_vivado_scripts_are_current() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let g = generate(&FccParams::default()).unwrap();
    for (name, text) in vivado::extra_scripts(&g, &Layout::default(), Board::Zc706).unwrap() {
        let path = root.join("scripts").join(name);
        let got = std::fs::read_to_string(&path).unwrap_or_else(|e| {
            panic!(
                "{}: {e}; run `cargo run -- gen` from the repository root",
                path.display()
            )
        });
        assert!(
            got == text,
            "scripts/{name} differs from the generator's output; run `cargo run -- gen` and commit"
        );
    }
}

#[test]
fn docs_quote_the_dma_lengths_and_the_register_header() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let doc = std::fs::read_to_string(root.join("docs/vivado.md")).unwrap();
    let ps = ports(&FccParams::default());
    let (mm2s, s2mm) = vivado::dma_frame_bytes(&FccParams::default(), &ps).unwrap();
    assert!(doc.contains("fcc_regs.h") && doc.contains("M_AXI_GP0"));
    assert!(doc.contains(&format!("{mm2s}")) && doc.contains(&format!("{s2mm}")));
    assert!(doc.contains("not run"));
}

// ---------------------------------------------------------------------------
// tclsh: parse check and dry run.

/// Whether `tclsh` runs. Missing, it skips a test, except in CI
/// (`CI=true`), where it fails the test: CI must run the dry runs.
fn tclsh_present() -> bool {
    let ok = Command::new("tclsh")
        .stdin(std::process::Stdio::null())
        .arg("/dev/null")
        .output()
        .is_ok();
    if !ok && std::env::var("CI").is_ok_and(|v| v == "true") {
        panic!("tclsh is not installed and CI=true: install it (Debian: apt-get install tcl)");
    }
    ok
}

#[test]
fn dry_runs_fail_in_ci_when_tclsh_is_missing() {
    // Run one dry-run test of this binary again without tclsh on PATH.
    let run = |ci: &str| {
        Command::new(std::env::current_exe().unwrap())
            .args(["--exact", "every_file_is_complete_tcl", "--test-threads=1"])
            .env("PATH", "")
            .env("CI", ci)
            .output()
            .unwrap()
    };
    let ci = run("true");
    assert!(
        !ci.status.success(),
        "with CI=true and no tclsh the dry run passed: {}",
        String::from_utf8_lossy(&ci.stdout)
    );
    assert!(String::from_utf8_lossy(&ci.stdout).contains("apt-get install tcl"));
    assert!(run("").status.success(), "outside CI a missing tclsh skips");
}

/// Logs every command Tcl does not know (all of Vivado's) to the log file as
/// a Tcl list and returns "" (or "100%" for a run's PROGRESS), then sources
/// the script with the remaining arguments as `::argv`.
///
/// Timing: without `FCC_STUB_WNS` no timing path exists (WNS "none") and a
/// run's STATS.WNS and STATS.WHS are 0.250; with it, the worst path's slack
/// and both run statistics are its value. `report_utilization
/// -return_string` returns two rows of a utilisation table.
const HARNESS: &str = r#"set ::fcc_log [open [lindex $argv 0] w]
set ::fcc_util "| Slice LUTs                 | 9304 |     0 |    218600 |  4.26 |
| CLB LUTs                   | 9304 |     0 |    230400 |  4.04 |
|   LUT as Memory            |  304 |     0 |     70400 |  0.43 |"
proc unknown {args} {
    puts $::fcc_log [string map {"\n" " "} $args]
    set cmd [lindex $args 0]
    set stub_wns [expr {[info exists ::env(FCC_STUB_WNS)] ? $::env(FCC_STUB_WNS) : ""}]
    if {$cmd eq "get_property"} {
        switch -- [lindex $args 1] {
            PROGRESS { return 100% }
            STATS.WNS - STATS.WHS - SLACK {
                if {$stub_wns ne ""} { return $stub_wns }
                return 0.250
            }
        }
    }
    if {$cmd eq "get_timing_paths" && $stub_wns ne ""} { return stub_path }
    if {$cmd eq "ipx::get_files"} { return stub_ipx_file }
    if {$cmd eq "report_utilization" && [lsearch -exact $args -return_string] >= 0} { return $::fcc_util }
    return ""
}
set script [lindex $argv 1]
set ::argv [lrange $argv 2 end]
set ::argc [llength $::argv]
set code [catch {source $script} msg]
close $::fcc_log
if {$code == 1} { puts stderr "ERROR: $msg"; exit 1 }
exit 0
"#;

/// The Vivado commands the scripts may call: each is in UG835. A command
/// outside this list in a dry run is a typo (of Vivado's or of a Tcl
/// built-in, which the stub would otherwise swallow).
const VIVADO_COMMANDS: [&str; 61] = [
    "add_files",
    "apply_bd_automation",
    "assign_bd_address",
    "close_project",
    "connect_bd_intf_net",
    "connect_bd_net",
    "create_bd_cell",
    "create_bd_design",
    "create_clock",
    "create_project",
    "current_fileset",
    "current_project",
    "get_bd_addr_segs",
    "get_bd_addr_spaces",
    "get_bd_cells",
    "get_bd_intf_pins",
    "get_bd_pins",
    "get_cells",
    "get_files",
    "get_ports",
    "get_property",
    "get_runs",
    "get_timing_paths",
    "ipx::add_bus_interface",
    "ipx::add_address_block",
    "ipx::add_bus_parameter",
    "ipx::add_memory_map",
    "ipx::add_port_map",
    "ipx::check_integrity",
    "ipx::create_xgui_files",
    "ipx::current_core",
    "ipx::get_file_groups",
    "ipx::get_files",
    "ipx::package_project",
    "ipx::remove_all_bus_interface",
    "ipx::save_core",
    "ipx::update_checksums",
    "launch_runs",
    "make_wrapper",
    "opt_design",
    "phys_opt_design",
    "place_design",
    "read_verilog",
    "read_xdc",
    "report_drc",
    "report_methodology",
    "report_timing_summary",
    "report_utilization",
    "route_design",
    "save_bd_design",
    "set_false_path",
    "set_input_delay",
    "set_output_delay",
    "set_property",
    "synth_design",
    "update_compile_order",
    "update_ip_catalog",
    "validate_bd_design",
    "wait_on_run",
    "write_checkpoint",
    "write_hw_platform",
];

struct DryRun {
    ok: bool,
    stdout: String,
    stderr: String,
    /// The Vivado commands, in order, one string each.
    log: Vec<String>,
}

impl DryRun {
    fn has(&self, prefix: &str) -> bool {
        self.log.iter().any(|l| l.starts_with(prefix))
    }
    /// `prefixes` occur in this order (other commands between them allowed).
    fn in_order(&self, prefixes: &[&str]) {
        let mut it = self.log.iter();
        for p in prefixes {
            assert!(
                it.any(|l| l.starts_with(p)),
                "`{p}` missing or out of order in:\n{}",
                self.log.join("\n")
            );
        }
    }
    fn arg_after<'a>(&'a self, command: &str) -> &'a str {
        let line = self
            .log
            .iter()
            .find(|l| l.starts_with(command))
            .unwrap_or_else(|| panic!("no {command}"));
        line[command.len()..].trim()
    }
}

/// Run `script` in `cwd` under the harness.
fn dry_run(cwd: &Path, script: &Path, args: &[&str]) -> DryRun {
    dry_run_wns(cwd, script, args, None)
}

/// [`dry_run`] with the stubbed timing of the routed design at `wns` ns.
fn dry_run_wns(cwd: &Path, script: &Path, args: &[&str], wns: Option<&str>) -> DryRun {
    let harness = cwd.join("harness.tcl");
    std::fs::write(&harness, HARNESS).unwrap();
    let log = cwd.join("vivado_commands.log");
    let mut cmd = Command::new("tclsh");
    match wns {
        Some(w) => cmd.env("FCC_STUB_WNS", w),
        None => cmd.env_remove("FCC_STUB_WNS"),
    };
    let out = cmd
        .current_dir(cwd)
        .arg(&harness)
        .arg(&log)
        .arg(script)
        .args(args)
        .stdin(std::process::Stdio::null())
        .output()
        .unwrap();
    let r = DryRun {
        ok: out.status.success(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        log: std::fs::read_to_string(&log)
            .unwrap_or_default()
            .lines()
            .map(str::to_string)
            .collect(),
    };
    for line in &r.log {
        let name = line.split(' ').next().unwrap_or_default();
        assert!(
            VIVADO_COMMANDS.contains(&name),
            "{}: `{name}` is not a Vivado command the scripts are meant to call",
            script.display()
        );
    }
    r
}

/// A repository-shaped directory with the generated files of `p`, and a
/// separate working directory to start "Vivado" in.
fn generated_tree(name: &str, p: &FccParams) -> (PathBuf, PathBuf) {
    generated_board_tree(name, p, Board::Zc706)
}

/// [`generated_tree`] for `board`.
fn generated_board_tree(name: &str, p: &FccParams, board: Board) -> (PathBuf, PathBuf) {
    let root = scratch(name);
    let layout = Layout::under(&root.join("repo"));
    let opts = fcc_rtl::WriteOptions {
        board,
        force: false,
    };
    fcc_rtl::write_all_with(p, &layout, &opts).unwrap();
    let work = root.join("work");
    std::fs::create_dir_all(&work).unwrap();
    (layout.scripts, work)
}

#[test]
fn every_file_is_complete_tcl() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: Tcl parse check skipped");
        return;
    }
    let (scripts, _) = generated_tree("complete", &FccParams::default());
    let mut paths: Vec<PathBuf> = ["fcc_build.tcl", "fcc_package_ip.tcl", "fcc_zc706_bd.tcl"]
        .iter()
        .map(|n| scripts.join(n))
        .collect();
    paths.push(scripts.join("../constraints/fcc_top.xdc"));
    let check = scripts.join("check.tcl");
    std::fs::write(
        &check,
        "foreach path $argv {\n    set f [open $path]\n    set text [read $f]\n    close $f\n    \
         if {![info complete $text]} { puts \"incomplete: $path\"; exit 1 }\n}\nputs complete\n",
    )
    .unwrap();
    let out = Command::new("tclsh")
        .arg(&check)
        .args(&paths)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn xdc_dry_run_constrains_clock_axi_ports_irq_reset_and_status() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let (scripts, work) = generated_tree("xdc", &FccParams::default());
    let r = dry_run(&work, &scripts.join("../constraints/fcc_top.xdc"), &[]);
    assert!(r.ok, "{}", r.stderr);
    r.in_order(&[
        "get_ports clk",
        "create_clock -name clk -period 5.000 {}",
        "get_ports clk",
        "set_property HD.CLK_SRC BUFGCTRL_X0Y0 {}",
        "get_ports -filter {DIRECTION == IN} {s_axis_* m_axis_* s_axil_*}",
        "set_input_delay -clock clk 1.000 {}",
        "get_ports -filter {DIRECTION == OUT} {s_axis_* m_axis_* s_axil_*}",
        "set_output_delay -clock clk 1.000 {}",
        "get_ports irq",
        "set_output_delay -clock clk 1.000 {}",
        "get_ports rst",
        "set_input_delay -clock clk 1.000 {}",
        "get_ports status_*",
        "set_false_path -to {}",
    ]);
}

#[test]
fn build_dry_run_runs_the_whole_flow_on_the_generated_files() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let top = top_module(&small());
    let (scripts, work) = generated_tree("build", &small());
    let r = dry_run(&work, &scripts.join("fcc_build.tcl"), &[]);
    assert!(r.ok, "{}", r.stderr);
    let rtl = PathBuf::from(r.arg_after("read_verilog "));
    assert!(
        rtl.ends_with("rtl_out/fcc_top.v") && rtl.is_file(),
        "{rtl:?}"
    );
    let xdc = PathBuf::from(r.arg_after("read_xdc -mode out_of_context "));
    assert!(
        xdc.ends_with("constraints/fcc_top.xdc") && xdc.is_file(),
        "{xdc:?}"
    );
    let out = work.join("vivado_fcc/build");
    r.in_order(&[
        "read_verilog ",
        "read_xdc -mode out_of_context ",
        &format!("synth_design -top {top} -part xc7z045ffg900-2 -mode out_of_context"),
        &format!(
            "write_checkpoint -force {}",
            out.join("post_synth.dcp").display()
        ),
        "report_utilization -file ",
        "report_timing_summary -max_paths 10 -file ",
        "opt_design",
        "place_design",
        "phys_opt_design",
        "route_design",
        &format!(
            "write_checkpoint -force {}",
            out.join("post_route.dcp").display()
        ),
        "report_utilization -file ",
        "report_utilization -hierarchical -file ",
        &format!(
            "report_timing_summary -max_paths 10 -file {}",
            out.join("timing_route.rpt").display()
        ),
        "get_timing_paths -delay_type max -max_paths 1 -nworst 1 -quiet",
        "get_timing_paths -delay_type min -max_paths 1 -nworst 1 -quiet",
        "get_cells -hierarchical -quiet -filter {REF_NAME =~ LUT*}",
    ]);
    let summary = std::fs::read_to_string(out.join("summary.txt")).unwrap();
    for line in [
        "part=xc7z045ffg900-2",
        &format!("top={top}"),
        "clock_mhz=200",
        "period_ns=5.000",
        "wns_ns=none",
        "lut=0",
        "carry4=0",
    ] {
        assert!(summary.lines().any(|l| l == line), "{line} in {summary}");
    }

    // -out and -no_phys_opt.
    let r = dry_run(
        &work,
        &scripts.join("fcc_build.tcl"),
        &["-out", "elsewhere", "-no_phys_opt"],
    );
    assert!(r.ok, "{}", r.stderr);
    assert!(!r.has("phys_opt_design"));
    assert!(work.join("elsewhere/build/summary.txt").is_file());
}

#[test]
fn scripts_answer_help_and_reject_unknown_arguments() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let (scripts, work) = generated_tree("args", &small());
    for name in ["fcc_build.tcl", "fcc_package_ip.tcl", "fcc_zc706_bd.tcl"] {
        let script = scripts.join(name);
        let r = dry_run(&work, &script, &["-help"]);
        assert!(r.ok, "{name}: {}", r.stderr);
        assert!(r.stdout.starts_with(&format!(
            "usage: vivado -mode batch -source {name} -tclargs"
        )));
        assert!(r.log.is_empty(), "{name} ran Vivado commands for -help");

        let r = dry_run(&work, &script, &["-frobnicate"]);
        assert!(!r.ok, "{name}");
        assert!(
            r.stderr.contains("unknown argument '-frobnicate'"),
            "{}",
            r.stderr
        );
        assert!(r.stderr.contains("usage: vivado"), "{}", r.stderr);

        let r = dry_run(&work, &script, &["-out"]);
        assert!(
            !r.ok && r.stderr.contains("-out needs a directory"),
            "{}",
            r.stderr
        );
    }
}

#[test]
fn package_dry_run_maps_every_port_of_the_interfaces() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let p = small();
    let (scripts, work) = generated_tree("package", &p);
    let r = dry_run(&work, &scripts.join("fcc_package_ip.tcl"), &[]);
    assert!(r.ok, "{}", r.stderr);
    let ip_dir = work.join("vivado_fcc/ip_repo").join(top_module(&p));
    r.in_order(&[
        &format!(
            "create_project -force fcc_ip_project {} -part xc7z045ffg900-2",
            work.join("vivado_fcc/ip_project").display()
        ),
        "add_files -norecurse ",
        &format!("set_property top {} {{}}", top_module(&p)),
        "add_files -fileset constrs_1 -norecurse ",
        "set_property USED_IN {synthesis implementation out_of_context} {}",
        &format!(
            "ipx::package_project -root_dir {} -vendor fcc -library fcc -taxonomy /UserIP -import_files -set_current true -force",
            ip_dir.display()
        ),
        "set_property version 0.1 {}",
        "ipx::remove_all_bus_interface {}",
        "ipx::add_bus_interface s_axis {}",
        "set_property interface_mode slave {}",
        "ipx::add_bus_interface m_axis {}",
        "set_property interface_mode master {}",
        "ipx::add_bus_interface s_axil {}",
        "ipx::add_memory_map s_axil {}",
        "ipx::add_address_block regs {}",
        "ipx::add_bus_interface irq {}",
        "ipx::add_bus_parameter SENSITIVITY {}",
        "ipx::add_bus_interface clk {}",
        "ipx::add_bus_parameter ASSOCIATED_BUSIF {}",
        "ipx::add_bus_interface rst {}",
        "ipx::add_bus_parameter POLARITY {}",
        "ipx::create_xgui_files {}",
        "ipx::update_checksums {}",
        "ipx::check_integrity {}",
        "ipx::save_core {}",
        "close_project",
    ]);
    let rtl = PathBuf::from(r.arg_after("add_files -norecurse "));
    assert!(rtl.is_file(), "{rtl:?}");
    // Every port map: logical name, then the physical port.
    let mut mapped = BTreeSet::new();
    for (i, l) in r.log.iter().enumerate() {
        if let Some(rest) = l.strip_prefix("set_property physical_name ") {
            let physical = rest.split(' ').next().unwrap().to_string();
            let logical = r.log[i - 1]
                .strip_prefix("ipx::add_port_map ")
                .unwrap()
                .split(' ')
                .next()
                .unwrap()
                .to_string();
            mapped.insert((logical, physical));
        }
    }
    let mut expected = BTreeSet::new();
    for (iface, port) in axis_ports(&ports(&p)) {
        expected.insert((
            port.name[iface.len() + 1..].to_uppercase(),
            port.name.clone(),
        ));
    }
    for port in ports(&p).iter().filter(|p| p.name.starts_with("s_axil_")) {
        expected.insert((port.name[7..].to_uppercase(), port.name.clone()));
    }
    expected.insert(("INTERRUPT".into(), "irq".into()));
    expected.insert(("CLK".into(), "clk".into()));
    expected.insert(("RST".into(), "rst".into()));
    assert_eq!(mapped, expected);
    assert!(r.has("set_property value s_axis:m_axis:s_axil {}"));
    assert!(r.has("set_property range 4096 {}"));
    assert!(r.has("set_property value rst {}"));
    assert!(r.has("set_property value ACTIVE_HIGH {}"));
}

#[test]
fn block_design_dry_run_needs_the_ip_and_writes_the_software_map() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let p = FccParams::default();
    let (scripts, work) = generated_tree("bd", &p);
    let script = scripts.join("fcc_zc706_bd.tcl");

    let r = dry_run(&work, &script, &[]);
    assert!(!r.ok);
    assert!(r.stderr.contains("run fcc_package_ip.tcl"), "{}", r.stderr);
    assert!(r.log.is_empty());

    let ip = work.join("vivado_fcc/ip_repo").join(top_module(&p));
    std::fs::create_dir_all(&ip).unwrap();
    std::fs::write(ip.join("component.xml"), "").unwrap();
    let r = dry_run(&work, &script, &[]);
    assert!(r.ok, "{}", r.stderr);
    let proj = work.join("vivado_fcc/zc706");
    r.in_order(&[
        &format!(
            "create_project -force fcc_zc706 {} -part xc7z045ffg900-2",
            proj.display()
        ),
        "set_property board_part xilinx.com:zc706:part0:1.4 {}",
        &format!(
            "set_property ip_repo_paths {} {{}}",
            work.join("vivado_fcc/ip_repo").display()
        ),
        "update_ip_catalog",
        "create_bd_design fcc_zc706",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:processing_system7:5.5 ps",
        "apply_bd_automation -rule xilinx.com:bd_rule:processing_system7 -config {make_external \"FIXED_IO, DDR\" apply_board_preset \"1\" Master \"Disable\" Slave \"Disable\"} {}",
        "set_property -dict {CONFIG.PCW_USE_M_AXI_GP0 1 CONFIG.PCW_USE_S_AXI_HP0 1 CONFIG.PCW_USE_FABRIC_INTERRUPT 1 CONFIG.PCW_IRQ_F2P_INTR 1 CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ 200} {}",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:proc_sys_reset:5.0 rst_fclk0",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:axi_dma:7.1 dma",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:smartconnect:1.0 ctrl_smc",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:smartconnect:1.0 mem_smc",
        "create_bd_cell -type ip -vlnv xilinx.com:ip:xlconcat:2.1 irq_concat",
        &format!(
            "create_bd_cell -type ip -vlnv fcc:fcc:{}:0.1 fcc",
            top_module(&p)
        ),
        "connect_bd_net ",
        "connect_bd_intf_net ",
        "assign_bd_address",
        "validate_bd_design",
        "save_bd_design",
        "make_wrapper -files {} -top -import",
        "set_property top fcc_zc706_wrapper {}",
    ]);
    assert!(!r.has("launch_runs"), "no bitstream without -bitstream");
    // Every stubbed pin lookup names a pin the design has.
    let pins: BTreeSet<&str> = r
        .log
        .iter()
        .filter_map(|l| l.strip_prefix("get_bd_pins fcc/"))
        .collect();
    let expected: BTreeSet<&str> = ["clk", "rst", "irq"].into_iter().collect();
    assert_eq!(pins, expected);
    let intf: BTreeSet<&str> = r
        .log
        .iter()
        .filter_map(|l| l.strip_prefix("get_bd_intf_pins fcc/"))
        .collect();
    assert_eq!(intf, ["m_axis", "s_axil", "s_axis"].into_iter().collect());
    let map = std::fs::read_to_string(proj.join("fcc_zc706_map.txt")).unwrap();
    assert!(map.contains("dma MM2S_LENGTH 1048576\n"), "{map}");
    assert!(map.contains("dma S2MM_LENGTH 262144\n"), "{map}");
    assert!(map.contains("register 0x044 STATUS W1C\n"), "{map}");

    let r = dry_run(&work, &script, &["-bitstream", "-jobs", "3"]);
    assert!(r.ok, "{}", r.stderr);
    r.in_order(&[
        "make_wrapper ",
        "launch_runs synth_1 -jobs 3",
        "wait_on_run synth_1",
        "launch_runs impl_1 -to_step route_design -jobs 3",
        "wait_on_run impl_1",
        "get_property STATS.WNS {}",
        "launch_runs impl_1 -next_step -jobs 3",
        "wait_on_run impl_1",
        &format!(
            "write_hw_platform -fixed -include_bit -force -file {}",
            proj.join("fcc_zc706.xsa").display()
        ),
    ]);
}

#[test]
fn build_dry_run_stops_when_the_routed_wns_is_negative() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let (scripts, work) = generated_tree("wns", &small());
    let script = scripts.join("fcc_build.tcl");
    let summary = work.join("vivado_fcc/build/summary.txt");

    // Met: the flow ends normally, with the reports of the routed design.
    let r = dry_run_wns(&work, &script, &[], Some("0.042"));
    assert!(r.ok, "{}", r.stderr);
    r.in_order(&[
        "route_design",
        "report_timing_summary -max_paths 10 -file ",
        "report_methodology -file ",
        "report_drc -file ",
        "report_utilization -return_string",
        "get_timing_paths -delay_type max",
    ]);
    let text = std::fs::read_to_string(&summary).unwrap();
    for line in ["wns_ns=0.042", "slice_luts=9304", "lutram=304"] {
        assert!(text.lines().any(|l| l == line), "{line} in {text}");
    }

    // Missed: the summary is still written, then the script fails loudly.
    std::fs::remove_file(&summary).unwrap();
    let r = dry_run_wns(&work, &script, &[], Some("-0.123"));
    assert!(!r.ok, "a negative WNS passed");
    assert!(
        r.stderr.contains(&format!(
            "the routed {} misses 200 MHz by 0.123 ns (WNS -0.123 ns)",
            top_module(&small())
        )),
        "{}",
        r.stderr
    );
    let text = std::fs::read_to_string(&summary).unwrap();
    assert!(text.lines().any(|l| l == "wns_ns=-0.123"), "{text}");
}

#[test]
fn block_design_dry_run_writes_no_bitstream_or_xsa_when_wns_is_negative() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let (scripts, work) = generated_tree("bd-wns", &small());
    let ip = work.join("vivado_fcc/ip_repo").join(top_module(&small()));
    std::fs::create_dir_all(&ip).unwrap();
    std::fs::write(ip.join("component.xml"), "").unwrap();
    let script = scripts.join("fcc_zc706_bd.tcl");

    let r = dry_run_wns(&work, &script, &["-bitstream"], Some("-0.5"));
    assert!(!r.ok, "a negative WNS passed");
    assert!(r.stderr.contains("misses its clock"), "{}", r.stderr);
    assert!(r.stderr.contains("no bitstream, no .xsa"), "{}", r.stderr);
    assert!(r.has("launch_runs impl_1 -to_step route_design"));
    assert!(
        !r.has("launch_runs impl_1 -next_step"),
        "bitstream launched"
    );
    assert!(!r.has("write_hw_platform"), ".xsa written");

    let r = dry_run_wns(&work, &script, &["-bitstream"], Some("0.0"));
    assert!(r.ok, "{}", r.stderr);
    r.in_order(&["launch_runs impl_1 -next_step", "write_hw_platform "]);
}

#[test]
fn package_dry_run_keeps_the_xdc_out_of_context_and_declares_every_family() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let (scripts, work) = generated_tree("package-ooc", &small());
    let r = dry_run(&work, &scripts.join("fcc_package_ip.tcl"), &[]);
    assert!(r.ok, "{}", r.stderr);
    r.in_order(&[
        "ipx::package_project ",
        "set_property supported_families {zynq Production zynquplus Production} {}",
        "ipx::get_file_groups xilinx_anylanguagesynthesis -of_objects {}",
        "ipx::get_files src/fcc_top.xdc -of_objects {}",
        "set_property USED_IN {synthesis implementation out_of_context} stub_ipx_file",
        "ipx::save_core {}",
    ]);
}

#[test]
fn every_board_gets_a_block_design_that_dry_runs_with_its_own_ps() {
    if !tclsh_present() {
        eprintln!("tclsh not installed: dry run skipped");
        return;
    }
    let p = FccParams {
        clock_mhz: 100.0,
        ..small()
    };
    for board in BOARDS {
        let b = board.info();
        let ps = b.ps.info();
        let (scripts, work) = generated_board_tree(&format!("board-{}", b.name), &p, board);
        // Only this board's block design is written.
        for other in BOARDS.iter().filter(|o| **o != board) {
            assert!(!scripts.join(other.info().bd_script).exists());
        }
        let build = dry_run(&work, &scripts.join("fcc_build.tcl"), &[]);
        assert!(build.ok, "{}: {}", b.name, build.stderr);
        assert!(build.has(&format!(
            "synth_design -top {} -part {} -mode out_of_context",
            top_module(&p),
            b.part
        )));
        let pkg = dry_run(&work, &scripts.join("fcc_package_ip.tcl"), &[]);
        assert!(pkg.ok, "{}: {}", b.name, pkg.stderr);
        let ip = work.join("vivado_fcc/ip_repo").join(top_module(&p));
        std::fs::create_dir_all(&ip).unwrap();
        std::fs::write(ip.join("component.xml"), "").unwrap();
        let r = dry_run(&work, &scripts.join(b.bd_script), &["-bitstream"]);
        assert!(r.ok, "{}: {}", b.name, r.stderr);
        let proj = work.join("vivado_fcc").join(b.name);
        r.in_order(&[
            &format!(
                "create_project -force {} {} -part {}",
                b.bd_name,
                proj.display(),
                b.part
            ),
            &format!("set_property board_part {} {{}}", b.board_part),
            &format!("create_bd_cell -type ip -vlnv {} ps", ps.vlnv),
            &format!("apply_bd_automation -rule {} ", ps.automation_rule),
            "create_bd_cell -type ip -vlnv xilinx.com:ip:axi_dma:7.1 dma",
            "assign_bd_address",
            "validate_bd_design",
            &format!("set_property top {}_wrapper {{}}", b.bd_name),
            "write_hw_platform ",
        ]);
        // The PS pins used are the ones of this PS flavour.
        let pins: BTreeSet<&str> = r
            .log
            .iter()
            .filter_map(|l| l.strip_prefix("get_bd_pins ps/"))
            .collect();
        let want: BTreeSet<&str> = [ps.clock, ps.reset, ps.master_clock, ps.slave_clock, ps.irq]
            .into_iter()
            .collect();
        assert_eq!(pins, want, "{}", b.name);
        let intf: BTreeSet<&str> = r
            .log
            .iter()
            .filter_map(|l| l.strip_prefix("get_bd_intf_pins ps/"))
            .collect();
        assert_eq!(
            intf,
            [ps.master, ps.slave].into_iter().collect(),
            "{}",
            b.name
        );
        let dict = r
            .log
            .iter()
            .find(|l| l.starts_with("set_property -dict {CONFIG.c_include_sg"))
            .unwrap();
        assert!(
            dict.contains(&format!("CONFIG.c_addr_width {}", ps.dma_addr_width)),
            "{dict}"
        );
        match b.ps {
            vivado::Ps::Ps7 => assert_eq!(ps.dma_addr_width, 32),
            vivado::Ps::ZynqUltra => {
                assert!(ps.dma_addr_width > 32);
                assert!(r.has("set_property -dict {CONFIG.PSU__USE__M_AXI_GP0 1 CONFIG.PSU__USE__M_AXI_GP1 0 CONFIG.PSU__USE__S_AXI_GP2 1 CONFIG.PSU__USE__IRQ0 1 CONFIG.PSU__FPGA_PL0_ENABLE 1 CONFIG.PSU__CRL_APB__PL0_REF_CTRL__FREQMHZ 100} {}"));
            }
        }
        assert!(proj.join(format!("{}_map.txt", b.bd_name)).is_file());
        // The C example and its register header sit beside the block design.
        assert!(scripts.join(b.example).is_file());
        assert!(scripts.join("fcc_regs.h").is_file());
    }
}

#[test]
fn xc7z020_boards_refuse_a_clock_their_dma_cannot_meet() {
    for board in [Board::Zedboard, Board::PynqZ2] {
        let root = scratch(&format!("slow-{}", board.info().name));
        let layout = Layout::under(&root.join("out"));
        let opts = fcc_rtl::WriteOptions {
            board,
            force: false,
        };
        let e = fcc_rtl::write_all_with(&FccParams::default(), &layout, &opts)
            .unwrap_err()
            .to_string();
        assert!(e.contains("--clock-mhz 200 is above 150 MHz"), "{e}");
        assert!(e.contains("xc7z020") && e.contains("PG022"), "{e}");
        assert!(!root.join("out").exists(), "a refused board left files");
        let at = FccParams {
            clock_mhz: 150.0,
            ..FccParams::default()
        };
        fcc_rtl::write_all_with(&at, &layout, &opts).unwrap();
    }
}

#[test]
fn another_configuration_is_not_overwritten_without_force() {
    let root = scratch("overwrite");
    let layout = Layout::under(&root);
    write_all(&small(), &layout).unwrap();
    let before = std::fs::read_to_string(root.join("scripts/fcc_build.tcl")).unwrap();
    // The same configuration regenerates in place.
    write_all(&small(), &layout).unwrap();
    let k5 = FccParams {
        fsize: 5,
        ..small()
    };
    let e = write_all(&k5, &layout).unwrap_err().to_string();
    assert!(e.contains("refusing to overwrite"), "{e}");
    assert!(e.contains("rtl_out/fcc_params.json"), "{e}");
    assert!(e.contains("--force"), "{e}");
    assert_eq!(
        std::fs::read_to_string(root.join("scripts/fcc_build.tcl")).unwrap(),
        before,
        "a refused run changed a file"
    );
    // Same parameters, another board: the shared scripts name their board.
    let zcu = fcc_rtl::WriteOptions {
        board: Board::Zcu104,
        force: false,
    };
    let e = fcc_rtl::write_all_with(&small(), &layout, &zcu)
        .unwrap_err()
        .to_string();
    assert!(e.contains("board zc706"), "{e}");
    // A file fcc gen did not write is not replaced either.
    std::fs::write(root.join("constraints/fcc_top.xdc"), "# mine\n").unwrap();
    let e = write_all(&small(), &layout).unwrap_err().to_string();
    assert!(e.contains("not written by fcc gen"), "{e}");
    // --force replaces all of them.
    let force = fcc_rtl::WriteOptions {
        board: Board::Zc706,
        force: true,
    };
    fcc_rtl::write_all_with(&k5, &layout, &force).unwrap();
    assert!(std::fs::read_to_string(root.join("scripts/fcc_build.tcl"))
        .unwrap()
        .contains(&k5.hash()));
}

/// A column build's S2MM is sized for a frame of records (each pixel a
/// cluster at most, then the end beat), as its C example's record buffer
/// is, and its C example reads records, not labels.
#[test]
fn a_column_build_sizes_its_dma_for_records_and_its_example_reads_records() {
    let p = FccParams {
        scan: fcc_params::Scan::Column,
        label_bits: 13,
        ..small()
    };
    let (_, out) = vivado::dma_frame_bytes(&p, &ports(&p)).unwrap();
    assert_eq!(
        out,
        (p.pixels() as u64 * fcc_pixel::record::RECORD_WORDS as u64 + 1) * 8
    );
    let bits = vivado::dma_length_width(&p, &ports(&p)).unwrap();
    assert!(1u64 << bits > out, "{bits} length bits for {out} bytes");
    let fs = files(&p);
    let example = fs
        .iter()
        .find(|(name, _)| name.ends_with("_example.c"))
        .expect("the C example");
    assert!(
        example
            .1
            .contains(&format!("#define FCC_OUT_WORDS {}u", out / 8)),
        "{}",
        example.1
    );
    assert!(example.1.contains("fcc_read_records(fcc_out"));
    assert!(!example.1.contains("fcc_label("));
    // The row-major build's example is the label example.
    let row = files(&small());
    let example = row
        .iter()
        .find(|(name, _)| name.ends_with("_example.c"))
        .expect("the C example");
    assert!(example.1.contains("fcc_label("));
    assert!(!example.1.contains("fcc_read_records"));
}
