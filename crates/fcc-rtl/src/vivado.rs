//! The Vivado deliverables for the ZC706's XC7Z045, written from the same
//! [`FccParams`] and the same generated port list as the RTL:
//!
//! | File | Function | What it does |
//! |---|---|---|
//! | `constraints/fcc_top.xdc` | [`xdc`] | clock, AXI4-Stream and AXI4-Lite port delays, status false paths; out of context only |
//! | `scripts/fcc_build.tcl` | [`tcl`] | non-project synth / opt / place / route with reports |
//! | `scripts/fcc_package_ip.tcl` | [`package_ip_tcl`] | `fcc_top` as an IP with its AXI4-Stream, AXI4-Lite, interrupt, clock and reset interfaces |
//! | `scripts/fcc_zc706_bd.tcl` | [`bd_tcl`] | Zynq PS7 + AXI DMA + the core (registers on M_AXI_GP0, `irq`), for the board |
//!
//! Vivado is not available where this generator is developed and tested: the
//! scripts are written to the letter of the Vivado Tcl reference (UG835) and
//! the user guides on scripting, IP packaging and IP integrator (UG894,
//! UG1118, UG994), parse-checked and dry-run with every Vivado command
//! stubbed (`tests/vivado.rs`), but never run by Vivado here.
//!
//! Every number in these files comes from [`FccParams`] or from the ports of
//! the generated `fcc_top` ([`top_ports`]); the Tcl and XDC retype nothing.

use fcc_params::FccParams;

use crate::{
    file_header, param_summary, Generated, Layout, RtlError, GENERATOR_VERSION, TOP_MODULE,
};

/// The FPGA on the ZC706 board.
pub const PART: &str = "xc7z045ffg900-2";
/// The ZC706 board files shipped with Vivado.
pub const BOARD_PART: &str = "xilinx.com:zc706:part0:1.4";
/// IP-XACT vendor and library of the packaged core.
pub const IP_VENDOR: &str = "fcc";
pub const IP_LIBRARY: &str = "fcc";
/// IP catalogue category.
pub const IP_TAXONOMY: &str = "/UserIP";
/// Default directory (relative to where Vivado is started) for everything the
/// scripts write.
pub const DEFAULT_OUT: &str = "vivado_fcc";
/// Share of the clock period the out-of-context constraints give to the
/// neighbouring logic on every AXI4-Stream input and output (clock-to-out of
/// its register plus routing to or from the core).
pub const IO_DELAY_FRACTION: f64 = 0.2;
/// Global clock buffer assumed to drive `clk` in out-of-context
/// implementation (UG905, `HD.CLK_SRC`); any BUFGCTRL site of the part does.
pub const OOC_CLOCK_BUFFER: &str = "BUFGCTRL_X0Y0";
/// Highest PL fabric clock (FCLK) the Zynq-7000 PS generates, MHz.
pub const PS7_FCLK_MAX_MHZ: f64 = 250.0;
/// Widest buffer length register of the AXI DMA (`c_sg_length_width`), bits.
pub const DMA_LENGTH_WIDTH_MAX: u32 = 26;
/// Name of the block design (and of its project and wrapper).
pub const BD_NAME: &str = "fcc_zc706";

/// The clock port, the reset port and the prefix of the status ports (house
/// naming, `STYLE.md`).
pub const CLOCK_PORT: &str = "clk";
pub const RESET_PORT: &str = "rst";
pub const STATUS_PREFIX: &str = "status_";
/// The AXI4-Stream interfaces of `fcc_top`: name and IP-XACT mode.
pub const AXIS_INTERFACES: [(&str, &str); 2] = [("s_axis", "slave"), ("m_axis", "master")];
/// The AXI4-Lite slave interface of `fcc_top` (the register file).
pub const AXIL_INTERFACE: &str = "s_axil";
/// The interrupt output.
pub const IRQ_PORT: &str = "irq";

/// IP catalogue entries the block design instantiates (one place to change
/// them if a Vivado release retires a version).
pub mod vlnv {
    pub const PS7: &str = "xilinx.com:ip:processing_system7:5.5";
    pub const DMA: &str = "xilinx.com:ip:axi_dma:7.1";
    pub const SMARTCONNECT: &str = "xilinx.com:ip:smartconnect:1.0";
    pub const RESET: &str = "xilinx.com:ip:proc_sys_reset:5.0";
    pub const CONCAT: &str = "xilinx.com:ip:xlconcat:2.1";
    pub const PS7_AUTOMATION: &str = "xilinx.com:bd_rule:processing_system7";
    pub const AXIS: (&str, &str) = (
        "xilinx.com:interface:axis_rtl:1.0",
        "xilinx.com:interface:axis:1.0",
    );
    pub const AXIMM: (&str, &str) = (
        "xilinx.com:interface:aximm_rtl:1.0",
        "xilinx.com:interface:aximm:1.0",
    );
    pub const INTERRUPT: (&str, &str) = (
        "xilinx.com:signal:interrupt_rtl:1.0",
        "xilinx.com:signal:interrupt:1.0",
    );
    pub const CLOCK: (&str, &str) = (
        "xilinx.com:signal:clock_rtl:1.0",
        "xilinx.com:signal:clock:1.0",
    );
    pub const RESET_SIGNAL: (&str, &str) = (
        "xilinx.com:signal:reset_rtl:1.0",
        "xilinx.com:signal:reset:1.0",
    );
}

/// Clock period in ns for `clock_mhz`.
pub fn period_ns(p: &FccParams) -> f64 {
    1000.0 / p.clock_mhz
}

/// IP version: major.minor of the generator (IP-XACT versions have two fields).
pub fn ip_version() -> String {
    let mut it = GENERATOR_VERSION.split('.');
    let major = it.next().unwrap_or("0");
    let minor = it.next().unwrap_or("0");
    format!("{major}.{minor}")
}

/// `vendor:library:name:version` of the packaged core.
pub fn ip_vlnv() -> String {
    format!("{IP_VENDOR}:{IP_LIBRARY}:{TOP_MODULE}:{}", ip_version())
}

// ---------------------------------------------------------------------------
// Ports of the generated top module.

/// Direction of a top-level port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortDir {
    In,
    Out,
}

/// One port of `fcc_top` as the generated Verilog declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: PortDir,
    pub width: u32,
}

/// The ports of the top module, in declaration order, read from the
/// generated Verilog (`input wire [63:0] s_axis_tdata;` ...). Empty if the
/// module is missing.
pub fn top_ports(verilog: &str) -> Vec<Port> {
    let decl = regex::Regex::new(
        r"^\s*(input|output)\s+(?:wire|reg)?\s*(?:\[(\d+):(\d+)\])?\s*([A-Za-z_][A-Za-z0-9_]*)\s*;",
    )
    .expect("valid regex");
    let header = format!("module {TOP_MODULE}(");
    let mut ports = vec![];
    let mut inside = false;
    for line in verilog.lines() {
        if !inside {
            inside = line.trim_start().starts_with(&header);
            continue;
        }
        if line.trim_start().starts_with("endmodule") {
            break;
        }
        if let Some(c) = decl.captures(line) {
            let width = match (c.get(2), c.get(3)) {
                (Some(hi), Some(lo)) => {
                    let hi: u32 = hi.as_str().parse().unwrap_or(0);
                    let lo: u32 = lo.as_str().parse().unwrap_or(0);
                    hi.abs_diff(lo) + 1
                }
                _ => 1,
            };
            ports.push(Port {
                name: c[4].to_string(),
                dir: if &c[1] == "input" {
                    PortDir::In
                } else {
                    PortDir::Out
                },
                width,
            });
        }
    }
    ports
}

fn port<'a>(ports: &'a [Port], name: &str) -> Result<&'a Port, RtlError> {
    ports.iter().find(|p| p.name == name).ok_or_else(|| {
        RtlError::Check(format!(
            "{TOP_MODULE} has no port {name}; the Vivado scripts need it"
        ))
    })
}

/// Ports of one AXI4-Stream interface with their IP-XACT logical names:
/// `s_axis_tdata` is `TDATA` of `s_axis`.
pub fn axis_port_maps<'a>(ports: &'a [Port], interface: &str) -> Vec<(String, &'a Port)> {
    let prefix = format!("{interface}_");
    ports
        .iter()
        .filter_map(|p| {
            p.name
                .strip_prefix(&prefix)
                .map(|logical| (logical.to_uppercase(), p))
        })
        .collect()
}

/// The status ports, in declaration order.
pub fn status_ports(ports: &[Port]) -> Vec<&Port> {
    ports
        .iter()
        .filter(|p| p.name.starts_with(STATUS_PREFIX))
        .collect()
}

// ---------------------------------------------------------------------------
// Templates.

/// Replace every `@KEY@` of `template`; a key left over is a generator bug.
fn fill(template: &str, vars: &[(&str, String)]) -> String {
    let mut s = template.to_string();
    for (k, v) in vars {
        s = s.replace(&format!("@{k}@"), v);
    }
    debug_assert!(
        !regex::Regex::new(r"@[A-Z_0-9]+@")
            .expect("valid regex")
            .is_match(&s),
        "unfilled template key in {s}"
    );
    s
}

/// The argument loop every script shares: `-out DIR` and `-help`, plus the
/// script's own flags (`extra` are `switch` arms).
fn args_block(extra: &str) -> String {
    fill(
        r##"set out_base @DEFAULT_OUT@
set args {}
if {[info exists ::argv]} { set args $::argv }
while {[llength $args] > 0} {
    set args [lassign $args arg]
    switch -exact -- $arg {
        -out {
            if {[llength $args] == 0} { error "-out needs a directory\n$usage" }
            set args [lassign $args out_base]
        }
@EXTRA@        -h - -help { puts $usage; return }
        default { error "unknown argument '$arg'\n$usage" }
    }
}
"##,
        &[
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("EXTRA", extra.to_string()),
        ],
    )
}

// ---------------------------------------------------------------------------
// constraints/fcc_top.xdc

/// `fcc_top.xdc`: out-of-context timing constraints at `clock_mhz`.
pub fn xdc(p: &FccParams) -> String {
    let period = period_ns(p);
    let io = period * IO_DELAY_FRACTION;
    let pct = (IO_DELAY_FRACTION * 100.0).round();
    let axis: Vec<String> = AXIS_INTERFACES
        .iter()
        .map(|(i, _)| format!("{i}_*"))
        .chain([format!("{AXIL_INTERFACE}_*")])
        .collect();
    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"#
# OUT-OF-CONTEXT constraints of @TOP@: its own synthesis and implementation
# (synth_design -mode out_of_context: no I/O buffers, no package pins), as
# scripts/@BUILD@ runs them. The core never drives package pins; in a
# system its ports meet logic on the same clock (AXI DMA, an AXI interconnect,
# the PS's interrupt input, a reset block). The port delays below model that
# logic: @PCT@ % of the period is spent outside the core on every AXI input
# and output and on irq, so paths between the core's registers and its ports
# get the remaining time.
#
# Out of context only, on purpose: scripts/@BUILD@ reads this file with
# read_xdc -mode out_of_context, and scripts/@PACKAGE@ packages it in the
# IP with USED_IN {synthesis implementation out_of_context}, so it constrains
# the IP's own out-of-context synthesis and nothing else. In a block design
# (scripts/@BD@) the core's ports become internal nets and these port
# constraints are dropped: the clock is the Zynq PS's FCLK_CLK0, defined by
# the PS7's own constraints, and the paths between the core and the DMA or
# the interconnect are timed as ordinary register-to-register paths of the
# whole design.
# Scoping this file to the IP instead (SCOPED_TO_REF) would be wrong there:
# get_ports would name the instance's pins, and create_clock would put a
# second clock on the PS clock's net.

# Clock: @MHZ@ MHz (fcc gen --clock-mhz).
create_clock -name @CLK@ -period @PERIOD@ [get_ports @CLK@]
# Out-of-context implementation: the clock comes from a global buffer, as it
# will in the system (UG905, HD.CLK_SRC), so clock skew is estimated.
set_property HD.CLK_SRC @BUFG@ [get_ports @CLK@]

# AXI4-Stream (tdata, tvalid, tlast, tkeep and the opposite tready) and
# AXI4-Lite (every channel): @IO@ ns outside the core on each side.
set_input_delay -clock @CLK@ @IO@ [get_ports -filter {DIRECTION == IN} {@AXIS@}]
set_output_delay -clock @CLK@ @IO@ [get_ports -filter {DIRECTION == OUT} {@AXIS@}]

# @IRQ@: level, from a register; captured by the PS's interrupt input.
set_output_delay -clock @CLK@ @IO@ [get_ports @IRQ@]

# @RST@: synchronous, active high, from a register of the reset block
# (proc_sys_reset in the ZC706 design). Timed like a data input: its release
# must reach every register it resets in the same cycle.
set_input_delay -clock @CLK@ @IO@ [get_ports @RST@]

# @STATUS@*: quasi-static. They are registers that change once per frame (the
# counters when the last label beat is accepted, idle when a frame starts)
# and carry the same values as the status registers, which software reads
# through the AXI4-Lite port; a system that uses the ports samples them long
# after the frame's interrupt: no register captures them on the next edge,
# so the paths to these ports are not timed out of context.
# (status_frame_done is a one-cycle pulse; the ZC706 design leaves the
# status ports unconnected.)
set_false_path -to [get_ports @STATUS@*]
"##,
        &[
            ("TOP", TOP_MODULE.to_string()),
            ("BUILD", BUILD_SCRIPT.to_string()),
            ("PACKAGE", PACKAGE_SCRIPT.to_string()),
            ("BD", BD_SCRIPT.to_string()),
            ("PCT", format!("{pct}")),
            ("MHZ", format!("{}", p.clock_mhz)),
            ("PERIOD", format!("{period:.3}")),
            ("CLK", CLOCK_PORT.to_string()),
            ("RST", RESET_PORT.to_string()),
            ("BUFG", OOC_CLOCK_BUFFER.to_string()),
            ("IO", format!("{io:.3}")),
            ("AXIS", axis.join(" ")),
            ("IRQ", IRQ_PORT.to_string()),
            ("STATUS", STATUS_PREFIX.to_string()),
        ],
    ));
    s
}

// ---------------------------------------------------------------------------
// scripts/fcc_build.tcl

/// File names of the scripts.
pub const BUILD_SCRIPT: &str = "fcc_build.tcl";
pub const PACKAGE_SCRIPT: &str = "fcc_package_ip.tcl";
pub const BD_SCRIPT: &str = "fcc_zc706_bd.tcl";

/// `fcc_build.tcl`: out-of-context synthesis, implementation and reports in
/// non-project mode. `rtl` and `xdc` are the Verilog and constraint files
/// relative to the directory of the script.
pub fn tcl(p: &FccParams, rtl: &str, xdc: &str) -> String {
    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"#
# Out-of-context synthesis, placement and routing of @TOP@ for the ZC706's
# @PART@ in non-project mode, with utilisation and timing reports.
# Written to the Vivado Tcl reference (UG835); not run by the generator's tests.
#
# Usage (from any directory):
#   vivado -mode batch -source <repo>/scripts/@SCRIPT@ [-tclargs ?-out DIR? ?-no_phys_opt?]
#     -out DIR       results in DIR/build (default: ./@DEFAULT_OUT@/build)
#     -no_phys_opt   skip phys_opt_design after placement
# Writes post_synth.dcp, post_route.dcp, utilization_synth.rpt,
# utilization_route.rpt, utilization_route_hier.rpt, timing_synth.rpt,
# timing_route.rpt and summary.txt (key=value: worst slacks, primitive counts).

set usage {usage: vivado -mode batch -source @SCRIPT@ -tclargs ?-out DIR? ?-no_phys_opt?}
set part @PART@
set top @TOP@
set clock_mhz @MHZ@
set period_ns @PERIOD@
set here [file dirname [file normalize [info script]]]
set rtl [file normalize [file join $here @RTL@]]
set xdc [file normalize [file join $here @XDC@]]

set phys_opt 1
@ARGS@set out [file normalize [file join $out_base build]]
file mkdir $out
puts "@SCRIPT@: $top on $part at $clock_mhz MHz ($period_ns ns), results in $out"

read_verilog $rtl
read_xdc -mode out_of_context $xdc
synth_design -top $top -part $part -mode out_of_context
write_checkpoint -force [file join $out post_synth.dcp]
report_utilization -file [file join $out utilization_synth.rpt]
report_timing_summary -max_paths 10 -file [file join $out timing_synth.rpt]

opt_design
place_design
if {$phys_opt} { phys_opt_design }
route_design
write_checkpoint -force [file join $out post_route.dcp]
report_utilization -file [file join $out utilization_route.rpt]
report_utilization -hierarchical -file [file join $out utilization_route_hier.rpt]
report_timing_summary -max_paths 10 -file [file join $out timing_route.rpt]

# Worst slack of the routed design ("none" if no path is constrained) and
# primitive counts in the columns of the Yosys table of docs/rtl.md.
proc fcc_slack {delay_type} {
    set path [get_timing_paths -delay_type $delay_type -max_paths 1 -nworst 1 -quiet]
    if {$path eq ""} { return none }
    return [get_property SLACK $path]
}
proc fcc_count {ref_pattern} {
    return [llength [get_cells -hierarchical -quiet -filter "REF_NAME =~ $ref_pattern"]]
}
set summary [list \
    "part=$part" "top=$top" "clock_mhz=$clock_mhz" "period_ns=$period_ns" \
    "wns_ns=[fcc_slack max]" "whs_ns=[fcc_slack min]" \
    "lut=[fcc_count LUT*]" "srl=[fcc_count SRL*]" "ff=[fcc_count FD*]" \
    "dsp48e1=[fcc_count DSP48E1]" "ramb36e1=[fcc_count RAMB36E1]" \
    "ramb18e1=[fcc_count RAMB18E1]" "carry4=[fcc_count CARRY4]"]
set f [open [file join $out summary.txt] w]
puts $f [join $summary \n]
close $f
puts [join $summary \n]
"##,
        &[
            ("TOP", TOP_MODULE.to_string()),
            ("PART", PART.to_string()),
            ("SCRIPT", BUILD_SCRIPT.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("MHZ", format!("{}", p.clock_mhz)),
            ("PERIOD", format!("{:.3}", period_ns(p))),
            ("RTL", rtl.to_string()),
            ("XDC", xdc.to_string()),
            (
                "ARGS",
                args_block("        -no_phys_opt { set phys_opt 0 }\n"),
            ),
        ],
    ));
    s
}

// ---------------------------------------------------------------------------
// scripts/fcc_package_ip.tcl

/// `fcc_package_ip.tcl`: package `fcc_top` as an IP. `rtl` and `xdc` are
/// relative to the directory of the script.
pub fn package_ip_tcl(p: &FccParams, ports: &[Port], rtl: &str, xdc: &str) -> String {
    let mut axis = String::new();
    for (iface, mode) in AXIS_INTERFACES {
        axis.push_str(&format!("fcc_axis $core {iface} {mode} {{\n"));
        for (logical, port) in axis_port_maps(ports, iface) {
            axis.push_str(&format!("    {logical} {}\n", port.name));
        }
        axis.push_str("}\n");
    }
    let mut axil = format!("fcc_axim $core {AXIL_INTERFACE} slave {{\n");
    for (logical, port) in axis_port_maps(ports, AXIL_INTERFACE) {
        axil.push_str(&format!("    {logical} {}\n", port.name));
    }
    axil.push_str("}\n");
    let busifs: Vec<&str> = AXIS_INTERFACES
        .iter()
        .map(|(i, _)| *i)
        .chain([AXIL_INTERFACE])
        .collect();
    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"#
# Packages @TOP@ as the Vivado IP @VLNV@: AXI4-Stream slave s_axis (pixels),
# AXI4-Stream master m_axis (labels), AXI4-Lite slave @AXIL@ (the register
# file, @AXIL_RANGE@ bytes), level-high interrupt @IRQ@, clock @CLK@ and
# active-high reset @RST@, for the block design of scripts/@BD@.
# Written to UG835 and UG1118; not run by the generator's tests.
#
# Usage (from any directory):
#   vivado -mode batch -source <repo>/scripts/@SCRIPT@ [-tclargs ?-out DIR?]
#     -out DIR   the IP goes to DIR/ip_repo/@TOP@, the scratch project to
#                DIR/ip_project (default DIR: ./@DEFAULT_OUT@)
# The IP holds one configuration (its description names the parameter hash):
# after `fcc gen` with other parameters, run this again.

set usage {usage: vivado -mode batch -source @SCRIPT@ -tclargs ?-out DIR?}
set part @PART@
set top @TOP@
set here [file dirname [file normalize [info script]]]
set rtl [file normalize [file join $here @RTL@]]
set xdc [file normalize [file join $here @XDC@]]

@ARGS@set ip_repo [file normalize [file join $out_base ip_repo]]
set ip_dir [file join $ip_repo $top]
set proj_dir [file normalize [file join $out_base ip_project]]

create_project -force fcc_ip_project $proj_dir -part $part
add_files -norecurse $rtl
set_property top $top [current_fileset]
# The XDC is out-of-context only (see its header): the packager carries the
# USED_IN property into the IP, which uses the file for its own
# out-of-context synthesis and never in the system's implementation.
add_files -fileset constrs_1 -norecurse $xdc
set_property USED_IN {synthesis implementation out_of_context} [get_files $xdc]
update_compile_order -fileset sources_1

ipx::package_project -root_dir $ip_dir -vendor @VENDOR@ -library @LIBRARY@ -taxonomy @TAXONOMY@ -import_files -set_current true -force
set core [ipx::current_core]
set_property name $top $core
set_property version @VERSION@ $core
set_property display_name {FCC: Fast Channel Clustering of LiDAR range images} $core
set_property description {@SUMMARY@ (parameter hash @HASH@)} $core

# The packager has already guessed interfaces from the port names. Replace
# them with explicit ones: each AXI port is mapped by name to its logical
# signal here, so the result does not depend on the heuristics.
ipx::remove_all_bus_interface $core

proc fcc_axis {core name mode maps} {
    set bus [ipx::add_bus_interface $name $core]
    set_property abstraction_type_vlnv @AXIS_ABS@ $bus
    set_property bus_type_vlnv @AXIS_BUS@ $bus
    set_property interface_mode $mode $bus
    foreach {logical physical} $maps {
        set_property physical_name $physical [ipx::add_port_map $logical $bus]
    }
}
@AXIS_MAPS@
# AXI4-Lite register file: the slave interface and its memory map, one
# address block over the whole decoded window.
proc fcc_axim {core name mode maps} {
    set bus [ipx::add_bus_interface $name $core]
    set_property abstraction_type_vlnv @AXIM_ABS@ $bus
    set_property bus_type_vlnv @AXIM_BUS@ $bus
    set_property interface_mode $mode $bus
    foreach {logical physical} $maps {
        set_property physical_name $physical [ipx::add_port_map $logical $bus]
    }
    return $bus
}
set axil_bus [@AXIL_MAPS@]
set axil_map [ipx::add_memory_map @AXIL@ $core]
set_property slave_memory_map_ref @AXIL@ $axil_bus
set axil_block [ipx::add_address_block regs $axil_map]
set_property range @AXIL_RANGE@ $axil_block
set_property width 32 $axil_block

# Interrupt: level high (STATUS.FRAME_DONE while CONTROL.IRQ_ENABLE).
set irq_bus [ipx::add_bus_interface @IRQ@ $core]
set_property abstraction_type_vlnv @IRQ_ABS@ $irq_bus
set_property bus_type_vlnv @IRQ_BUS@ $irq_bus
set_property interface_mode master $irq_bus
set_property physical_name @IRQ@ [ipx::add_port_map INTERRUPT $irq_bus]
set_property value LEVEL_HIGH [ipx::add_bus_parameter SENSITIVITY $irq_bus]

# Clock: every interface is synchronous to it; its reset is @RST@.
set clk_bus [ipx::add_bus_interface @CLK@ $core]
set_property abstraction_type_vlnv @CLK_ABS@ $clk_bus
set_property bus_type_vlnv @CLK_BUS@ $clk_bus
set_property interface_mode slave $clk_bus
set_property physical_name @CLK@ [ipx::add_port_map CLK $clk_bus]
set_property value @BUSIFS@ [ipx::add_bus_parameter ASSOCIATED_BUSIF $clk_bus]
set_property value @RST@ [ipx::add_bus_parameter ASSOCIATED_RESET $clk_bus]

# Reset: synchronous, active high.
set rst_bus [ipx::add_bus_interface @RST@ $core]
set_property abstraction_type_vlnv @RST_ABS@ $rst_bus
set_property bus_type_vlnv @RST_BUS@ $rst_bus
set_property interface_mode slave $rst_bus
set_property physical_name @RST@ [ipx::add_port_map RST $rst_bus]
set_property value ACTIVE_HIGH [ipx::add_bus_parameter POLARITY $rst_bus]

ipx::create_xgui_files $core
ipx::update_checksums $core
ipx::check_integrity $core
ipx::save_core $core
close_project
puts "@SCRIPT@: @VLNV@ packaged in $ip_dir (IP repository: $ip_repo)"
"##,
        &[
            ("TOP", TOP_MODULE.to_string()),
            ("VLNV", ip_vlnv()),
            ("CLK", CLOCK_PORT.to_string()),
            ("RST", RESET_PORT.to_string()),
            ("BD", BD_SCRIPT.to_string()),
            ("SCRIPT", PACKAGE_SCRIPT.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("PART", PART.to_string()),
            ("RTL", rtl.to_string()),
            ("XDC", xdc.to_string()),
            ("ARGS", args_block("")),
            ("VENDOR", IP_VENDOR.to_string()),
            ("LIBRARY", IP_LIBRARY.to_string()),
            ("TAXONOMY", IP_TAXONOMY.to_string()),
            ("VERSION", ip_version()),
            ("SUMMARY", param_summary(p)),
            ("HASH", p.hash()),
            ("AXIS_ABS", vlnv::AXIS.0.to_string()),
            ("AXIS_BUS", vlnv::AXIS.1.to_string()),
            ("AXIS_MAPS", axis),
            ("AXIL", AXIL_INTERFACE.to_string()),
            ("AXIL_MAPS", axil.trim_end().to_string()),
            ("AXIL_RANGE", (1u32 << crate::regmap::ADDR_BITS).to_string()),
            ("AXIM_ABS", vlnv::AXIMM.0.to_string()),
            ("AXIM_BUS", vlnv::AXIMM.1.to_string()),
            ("IRQ", IRQ_PORT.to_string()),
            ("IRQ_ABS", vlnv::INTERRUPT.0.to_string()),
            ("IRQ_BUS", vlnv::INTERRUPT.1.to_string()),
            ("CLK_ABS", vlnv::CLOCK.0.to_string()),
            ("CLK_BUS", vlnv::CLOCK.1.to_string()),
            ("RST_ABS", vlnv::RESET_SIGNAL.0.to_string()),
            ("RST_BUS", vlnv::RESET_SIGNAL.1.to_string()),
            ("BUSIFS", busifs.join(":")),
        ],
    ));
    s
}

// ---------------------------------------------------------------------------
// scripts/fcc_zc706_bd.tcl

/// One line per register of the core, for the software map:
/// `0x040 CONTROL RW` (offset within the core's address segment).
pub fn register_map_lines(p: &FccParams) -> Vec<String> {
    crate::regmap::registers(p)
        .iter()
        .map(|r| format!("0x{:03X} {} {}", r.offset, r.name, r.access.as_str()))
        .collect()
}

/// Bytes the DMA moves per frame: (MM2S into `s_axis`, S2MM from `m_axis`).
pub fn dma_frame_bytes(p: &FccParams, ports: &[Port]) -> Result<(u64, u64), RtlError> {
    let pixels = p.pixels() as u64;
    let in_beat = u64::from(port(ports, "s_axis_tdata")?.width / 8);
    let out_beat = u64::from(port(ports, "m_axis_tdata")?.width / 8);
    let out_beats = pixels.div_ceil(u64::from(p.labels_per_beat));
    Ok((pixels * in_beat, out_beats * out_beat))
}

/// `c_sg_length_width`: bits of the DMA's buffer length registers, enough
/// for one whole frame in either direction.
pub fn dma_length_width(p: &FccParams, ports: &[Port]) -> Result<u32, RtlError> {
    let (a, b) = dma_frame_bytes(p, ports)?;
    let bits = 64 - a.max(b).leading_zeros();
    if bits > DMA_LENGTH_WIDTH_MAX {
        return Err(RtlError::Check(format!(
            "a frame is {} bytes; the AXI DMA moves at most 2^{DMA_LENGTH_WIDTH_MAX} - 1 bytes per transfer",
            a.max(b)
        )));
    }
    Ok(bits)
}

/// The FCLK_CLK0 frequency the block design asks the PS for, MHz: the
/// core's clock, which must be one the PS can give.
pub fn fclk_mhz(p: &FccParams) -> Result<f64, RtlError> {
    if p.clock_mhz > PS7_FCLK_MAX_MHZ {
        return Err(RtlError::Check(format!(
            "--clock-mhz {} is above {PS7_FCLK_MAX_MHZ} MHz, the fastest fabric clock (FCLK) the ZC706's Zynq PS can give the block design; choose at most {PS7_FCLK_MAX_MHZ}",
            p.clock_mhz
        )));
    }
    Ok(p.clock_mhz)
}

/// `fcc_zc706_bd.tcl`: the ZC706 block design around the packaged core.
pub fn bd_tcl(p: &FccParams, ports: &[Port]) -> Result<String, RtlError> {
    let (in_bytes, out_bytes) = dma_frame_bytes(p, ports)?;
    let len_width = dma_length_width(p, ports)?;
    let in_width = port(ports, "s_axis_tdata")?.width;
    let out_width = port(ports, "m_axis_tdata")?.width;
    for name in [CLOCK_PORT, RESET_PORT, IRQ_PORT] {
        port(ports, name)?;
    }
    if axis_port_maps(ports, AXIL_INTERFACE).is_empty() {
        return Err(RtlError::Check(format!(
            "{TOP_MODULE} has no {AXIL_INTERFACE}_* ports; the block design needs its register port"
        )));
    }
    let fclk = fclk_mhz(p)?;
    let map_lines = register_map_lines(p);
    let map_comment: String = map_lines.iter().map(|l| format!("#     {l}\n")).collect();
    let map_puts: String = map_lines
        .iter()
        .map(|l| format!("puts $map {{register {l}}}\n"))
        .collect();

    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"#
# Block design for the ZC706 (@BOARD@, @PART@): the Zynq PS7 with the
# board preset; an AXI DMA in simple (register) mode that reads frames from
# DDR into @TOP@'s s_axis (MM2S) and writes its m_axis labels back to DDR
# (S2MM); the core's register port and the DMA's registers on the PS's
# M_AXI_GP0 through a SmartConnect; memory (PS S_AXI_HP0) through another; a
# processor system reset; the DMA's two interrupts and the core's irq on
# IRQ_F2P. Everything runs on FCLK_CLK0.
# Written to UG835 and UG994; not run by the generator's tests.
#
# Run scripts/@PACKAGE@ first, with the same -out.
# Usage (from any directory):
#   vivado -mode batch -source <repo>/scripts/@SCRIPT@ [-tclargs ?-out DIR? ?-bitstream? ?-jobs N?]
#     -out DIR     project in DIR/zc706, core from DIR/ip_repo (default DIR: ./@DEFAULT_OUT@)
#     -bitstream   also synthesise, implement, write the bitstream and export
#                  DIR/zc706/@BD_NAME@.xsa for the software tools
#     -jobs N      parallel jobs for -bitstream (default 2)
#
# Clock: FCLK_CLK0 is asked for @FCLK@ MHz; the PS rounds it to what its PLL
# dividers give, and the script prints the frequency it got.
#
# Software view (also written to DIR/zc706/@BD_NAME@_map.txt with the addresses):
#   DMA MM2S_LENGTH = @IN_BYTES@ bytes per frame (@PIXELS@ pixels, @IN_BEAT@ bytes each)
#   DMA S2MM_LENGTH = @OUT_BYTES@ bytes per frame (@LPB@ labels per @OUT_BEAT@-byte beat)
#   Interrupts: IRQ_F2P[0] = MM2S done (GIC ID 61), IRQ_F2P[1] = S2MM done (GIC ID 62),
#     IRQ_F2P[2] = fcc irq, frame done (GIC ID 63, level high)
#   fcc registers (offsets in the fcc segment; fields in rtl_out/fcc_regs.h):
@MAP_COMMENT@
set usage {usage: vivado -mode batch -source @SCRIPT@ -tclargs ?-out DIR? ?-bitstream? ?-jobs N?}
set part @PART@
set board_part @BOARD@
set design @BD_NAME@
set bitstream 0
set jobs 2
@ARGS@set ip_repo [file normalize [file join $out_base ip_repo]]
set proj_dir [file normalize [file join $out_base zc706]]
if {![file exists [file join $ip_repo @TOP@ component.xml]]} {
    error "no packaged @TOP@ in $ip_repo: run @PACKAGE@ -tclargs -out $out_base first"
}

create_project -force $design $proj_dir -part $part
set_property board_part $board_part [current_project]
set_property ip_repo_paths [list $ip_repo] [current_project]
update_ip_catalog
create_bd_design $design

# Zynq PS: the board preset first (DDR, MIO, PS clocks of the ZC706), then
# what this design adds to it.
create_bd_cell -type ip -vlnv @PS7@ ps7
apply_bd_automation -rule @PS7_RULE@ -config {make_external "FIXED_IO, DDR" apply_board_preset "1" Master "Disable" Slave "Disable"} [get_bd_cells ps7]
set_property -dict [list \
    CONFIG.PCW_USE_M_AXI_GP0 {1} \
    CONFIG.PCW_USE_S_AXI_HP0 {1} \
    CONFIG.PCW_USE_FABRIC_INTERRUPT {1} \
    CONFIG.PCW_IRQ_F2P_INTR {1} \
    CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {@FCLK@} \
] [get_bd_cells ps7]
puts "FCLK_CLK0: asked @FCLK@ MHz, got [get_property CONFIG.PCW_ACT_FPGA0_PERIPHERAL_FREQMHZ [get_bd_cells ps7]] MHz"

create_bd_cell -type ip -vlnv @RESET@ rst_fclk0

# AXI DMA, simple mode: one frame per MM2S and per S2MM transfer.
create_bd_cell -type ip -vlnv @DMA@ dma
set_property -dict [list \
    CONFIG.c_include_sg {0} \
    CONFIG.c_sg_include_stscntrl_strm {0} \
    CONFIG.c_sg_length_width {@LEN_WIDTH@} \
    CONFIG.c_include_mm2s {1} \
    CONFIG.c_m_axi_mm2s_data_width {@IN_WIDTH@} \
    CONFIG.c_m_axis_mm2s_tdata_width {@IN_WIDTH@} \
    CONFIG.c_include_s2mm {1} \
    CONFIG.c_m_axi_s2mm_data_width {@OUT_WIDTH@} \
    CONFIG.c_s_axis_s2mm_tdata_width {@OUT_WIDTH@} \
] [get_bd_cells dma]

create_bd_cell -type ip -vlnv @SMC@ ctrl_smc
set_property -dict [list CONFIG.NUM_SI {1} CONFIG.NUM_MI {2}] [get_bd_cells ctrl_smc]
create_bd_cell -type ip -vlnv @SMC@ mem_smc
set_property -dict [list CONFIG.NUM_SI {2} CONFIG.NUM_MI {1}] [get_bd_cells mem_smc]
create_bd_cell -type ip -vlnv @CONCAT@ irq_concat
set_property -dict [list CONFIG.NUM_PORTS {3}] [get_bd_cells irq_concat]
create_bd_cell -type ip -vlnv @FCC_VLNV@ fcc

# Clock and resets.
connect_bd_net [get_bd_pins ps7/FCLK_CLK0] \
    [get_bd_pins ps7/M_AXI_GP0_ACLK] [get_bd_pins ps7/S_AXI_HP0_ACLK] \
    [get_bd_pins rst_fclk0/slowest_sync_clk] \
    [get_bd_pins ctrl_smc/aclk] [get_bd_pins mem_smc/aclk] \
    [get_bd_pins dma/s_axi_lite_aclk] [get_bd_pins dma/m_axi_mm2s_aclk] [get_bd_pins dma/m_axi_s2mm_aclk] \
    [get_bd_pins fcc/@CLK@]
connect_bd_net [get_bd_pins ps7/FCLK_RESET0_N] [get_bd_pins rst_fclk0/ext_reset_in]
connect_bd_net [get_bd_pins rst_fclk0/interconnect_aresetn] \
    [get_bd_pins ctrl_smc/aresetn] [get_bd_pins mem_smc/aresetn]
connect_bd_net [get_bd_pins rst_fclk0/peripheral_aresetn] \
    [get_bd_pins dma/axi_resetn]
connect_bd_net [get_bd_pins rst_fclk0/peripheral_reset] [get_bd_pins fcc/@RST@]

# Control: PS -> DMA registers and the core's registers; memory: DMA -> DDR;
# streams.
connect_bd_intf_net [get_bd_intf_pins ps7/M_AXI_GP0] [get_bd_intf_pins ctrl_smc/S00_AXI]
connect_bd_intf_net [get_bd_intf_pins ctrl_smc/M00_AXI] [get_bd_intf_pins dma/S_AXI_LITE]
connect_bd_intf_net [get_bd_intf_pins ctrl_smc/M01_AXI] [get_bd_intf_pins fcc/@AXIL@]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXI_MM2S] [get_bd_intf_pins mem_smc/S00_AXI]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXI_S2MM] [get_bd_intf_pins mem_smc/S01_AXI]
connect_bd_intf_net [get_bd_intf_pins mem_smc/M00_AXI] [get_bd_intf_pins ps7/S_AXI_HP0]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXIS_MM2S] [get_bd_intf_pins fcc/s_axis]
connect_bd_intf_net [get_bd_intf_pins fcc/m_axis] [get_bd_intf_pins dma/S_AXIS_S2MM]

# Interrupts.
connect_bd_net [get_bd_pins dma/mm2s_introut] [get_bd_pins irq_concat/In0]
connect_bd_net [get_bd_pins dma/s2mm_introut] [get_bd_pins irq_concat/In1]
connect_bd_net [get_bd_pins fcc/@IRQ@] [get_bd_pins irq_concat/In2]
connect_bd_net [get_bd_pins irq_concat/dout] [get_bd_pins ps7/IRQ_F2P]

assign_bd_address
validate_bd_design
save_bd_design

file mkdir $proj_dir
set map [open [file join $proj_dir ${design}_map.txt] w]
puts $map "# @BD_NAME@ software view: PS address segments (name offset range), DMA lengths, fcc registers (offset name access)"
foreach seg [get_bd_addr_segs -of_objects [get_bd_addr_spaces ps7/Data]] {
    puts $map "segment [get_property NAME $seg] [get_property OFFSET $seg] [get_property RANGE $seg]"
}
puts $map {dma MM2S_LENGTH @IN_BYTES@}
puts $map {dma S2MM_LENGTH @OUT_BYTES@}
@MAP_PUTS@close $map

make_wrapper -files [get_files $design.bd] -top -import
set_property top ${design}_wrapper [current_fileset]
update_compile_order -fileset sources_1

if {$bitstream} {
    launch_runs synth_1 -jobs $jobs
    wait_on_run synth_1
    if {[get_property PROGRESS [get_runs synth_1]] ne "100%"} {
        error "synth_1 failed: see [get_property DIRECTORY [get_runs synth_1]]"
    }
    launch_runs impl_1 -to_step write_bitstream -jobs $jobs
    wait_on_run impl_1
    if {[get_property PROGRESS [get_runs impl_1]] ne "100%"} {
        error "impl_1 failed: see [get_property DIRECTORY [get_runs impl_1]]"
    }
    puts "impl_1: WNS [get_property STATS.WNS [get_runs impl_1]] ns, WHS [get_property STATS.WHS [get_runs impl_1]] ns"
    write_hw_platform -fixed -include_bit -force -file [file join $proj_dir $design.xsa]
}
puts "@SCRIPT@: $design in $proj_dir"
"##,
        &[
            ("BOARD", BOARD_PART.to_string()),
            ("PART", PART.to_string()),
            ("TOP", TOP_MODULE.to_string()),
            ("PACKAGE", PACKAGE_SCRIPT.to_string()),
            ("SCRIPT", BD_SCRIPT.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("BD_NAME", BD_NAME.to_string()),
            ("FCLK", format!("{fclk}")),
            ("IN_BYTES", in_bytes.to_string()),
            ("OUT_BYTES", out_bytes.to_string()),
            ("PIXELS", p.pixels().to_string()),
            ("IN_BEAT", (in_width / 8).to_string()),
            ("OUT_BEAT", (out_width / 8).to_string()),
            ("LPB", p.labels_per_beat.to_string()),
            ("MAP_COMMENT", map_comment),
            (
                "ARGS",
                args_block(
                    "        -bitstream { set bitstream 1 }\n        -jobs {\n            if {[llength $args] == 0} { error \"-jobs needs a number\\n$usage\" }\n            set args [lassign $args jobs]\n        }\n",
                ),
            ),
            ("MAP_PUTS", map_puts),
            ("AXIL", AXIL_INTERFACE.to_string()),
            ("IRQ", IRQ_PORT.to_string()),
            ("LEN_WIDTH", len_width.to_string()),
            ("IN_WIDTH", in_width.to_string()),
            ("OUT_WIDTH", out_width.to_string()),
            ("CLK", CLOCK_PORT.to_string()),
            ("RST", RESET_PORT.to_string()),
            ("FCC_VLNV", ip_vlnv()),
            ("PS7", vlnv::PS7.to_string()),
            ("PS7_RULE", vlnv::PS7_AUTOMATION.to_string()),
            ("DMA", vlnv::DMA.to_string()),
            ("SMC", vlnv::SMARTCONNECT.to_string()),
            ("RESET", vlnv::RESET.to_string()),
            ("CONCAT", vlnv::CONCAT.to_string()),
        ],
    ));
    Ok(s)
}

/// The scripts that travel with `fcc_build.tcl`: `fcc_package_ip.tcl` and
/// `fcc_zc706_bd.tcl`, for the directories of `layout`.
pub fn extra_scripts(
    g: &Generated,
    layout: &Layout,
) -> Result<Vec<(&'static str, String)>, RtlError> {
    let ports = top_ports(&g.verilog);
    let rtl = relative(&layout.scripts, &layout.rtl.join("fcc_top.v"));
    let xdc = relative(&layout.scripts, &layout.constraints.join("fcc_top.xdc"));
    Ok(vec![
        (
            PACKAGE_SCRIPT,
            package_ip_tcl(&g.params, &ports, &rtl, &xdc),
        ),
        (BD_SCRIPT, bd_tcl(&g.params, &ports)?),
    ])
}

/// The path of `to` relative to the directory `from`, both as given (made
/// absolute against the current directory); `/` separated, for Tcl.
pub fn relative(from: &std::path::Path, to: &std::path::Path) -> String {
    use std::path::Component;
    let abs = |p: &std::path::Path| -> Vec<String> {
        let p = if p.is_absolute() {
            p.to_path_buf()
        } else {
            std::env::current_dir().unwrap_or_default().join(p)
        };
        let mut parts: Vec<String> = vec![];
        for c in p.components() {
            match c {
                Component::Normal(s) => parts.push(s.to_string_lossy().into_owned()),
                Component::ParentDir => {
                    parts.pop();
                }
                _ => {}
            }
        }
        parts
    };
    let (f, t) = (abs(from), abs(to));
    let common = f.iter().zip(&t).take_while(|(a, b)| a == b).count();
    let mut out: Vec<String> = vec!["..".to_string(); f.len() - common];
    out.extend(t[common..].iter().cloned());
    out.join("/")
}
