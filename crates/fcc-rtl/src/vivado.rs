//! The Vivado deliverables for the boards of [`Board`] (ZC706 by default),
//! written from the same [`FccParams`] and the same generated port list as
//! the RTL:
//!
//! | File | Function | What it does |
//! |---|---|---|
//! | `constraints/fcc_top.xdc` | [`xdc`] | clock, AXI4-Stream and AXI4-Lite port delays, status false paths; out of context only |
//! | `scripts/fcc_build.tcl` | [`tcl`] | non-project synth / opt / place / route with reports |
//! | `scripts/fcc_package_ip.tcl` | [`package_ip_tcl`] | `fcc_top` as an IP with its AXI4-Stream, AXI4-Lite, interrupt, clock and reset interfaces |
//! | `scripts/fcc_<board>_bd.tcl` | [`bd_tcl`] | the board's Zynq PS + AXI DMA + the core (registers on the PS's control master, `irq`) |
//! | `scripts/fcc_<board>_example.c` | [`crate::example::c_example`] | bare-metal C: one frame through the DMA, the register sequence |
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
    file_header, param_summary, top_module, Generated, Layout, RtlError, GENERATOR_VERSION,
    TOP_NAME,
};

/// A board the generator writes a block design for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Board {
    /// Xilinx ZC706: XC7Z045-2, the default.
    #[default]
    Zc706,
    /// Avnet/Digilent ZedBoard: XC7Z020-1.
    Zedboard,
    /// TUL PYNQ-Z2: XC7Z020-1.
    PynqZ2,
    /// Xilinx ZCU104: XCZU7EV-2 (Zynq UltraScale+ MPSoC).
    Zcu104,
}

/// The processing system of a board.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ps {
    /// Zynq-7000: `processing_system7`.
    Ps7,
    /// Zynq UltraScale+ MPSoC: `zynq_ultra_ps_e`.
    ZynqUltra,
}

/// Everything the scripts need to know about one board: one row of the
/// table, [`Board::info`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoardInfo {
    /// `fcc gen --board` name.
    pub name: &'static str,
    /// Name for people.
    pub title: &'static str,
    /// The device.
    pub part: &'static str,
    /// Vivado board part (board files).
    pub board_part: &'static str,
    pub ps: Ps,
    /// Device family as IP-XACT names it (`supported_families`).
    pub family: &'static str,
    /// Highest clock of the design: the lower of the PS's fabric clock
    /// limit and the AXI DMA's characterised Fmax on this part, MHz.
    pub clock_max_mhz: f64,
    /// Where [`Self::clock_max_mhz`] comes from.
    pub clock_max_source: &'static str,
    /// Block design name (and its project's and wrapper's).
    pub bd_name: &'static str,
    /// Block design script.
    pub bd_script: &'static str,
    /// Bare-metal C example.
    pub example: &'static str,
}

/// Every board, in `--board` order.
pub const BOARDS: [Board; 4] = [Board::Zc706, Board::Zedboard, Board::PynqZ2, Board::Zcu104];

impl Board {
    /// The board's row of the table.
    pub fn info(self) -> BoardInfo {
        match self {
            Board::Zc706 => BoardInfo {
                name: "zc706",
                title: "ZC706",
                part: "xc7z045ffg900-2",
                board_part: "xilinx.com:zc706:part0:1.4",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 240.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Kintex-7 -2 240 MHz (the Z-7045 fabric); the PS7 FCLK limit is 250 MHz",
                bd_name: "fcc_zc706",
                bd_script: "fcc_zc706_bd.tcl",
                example: "fcc_zc706_example.c",
            },
            Board::Zedboard => BoardInfo {
                name: "zedboard",
                title: "ZedBoard",
                part: "xc7z020clg484-1",
                board_part: "avnet.com:zedboard:part0:1.4",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 150.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Artix-7 -1 150 MHz (the Z-7020 fabric)",
                bd_name: "fcc_zedboard",
                bd_script: "fcc_zedboard_bd.tcl",
                example: "fcc_zedboard_example.c",
            },
            Board::PynqZ2 => BoardInfo {
                name: "pynq-z2",
                title: "PYNQ-Z2",
                part: "xc7z020clg400-1",
                board_part: "tul.com.tw:pynq-z2:part0:1.0",
                ps: Ps::Ps7,
                family: "zynq",
                clock_max_mhz: 150.0,
                clock_max_source: "AXI DataMover (the AXI DMA's engine), PG022 Maximum Frequencies: Artix-7 -1 150 MHz (the Z-7020 fabric)",
                bd_name: "fcc_pynq_z2",
                bd_script: "fcc_pynq_z2_bd.tcl",
                example: "fcc_pynq_z2_example.c",
            },
            Board::Zcu104 => BoardInfo {
                name: "zcu104",
                title: "ZCU104",
                part: "xczu7ev-ffvc1156-2-e",
                board_part: "xilinx.com:zcu104:part0:1.1",
                ps: Ps::ZynqUltra,
                family: "zynquplus",
                clock_max_mhz: 250.0,
                clock_max_source: "not characterised here: PG022's table lists 7-series families only; 250 MHz is this generator's assumption for the -2 UltraScale+ fabric, to be confirmed on the board",
                bd_name: "fcc_zcu104",
                bd_script: "fcc_zcu104_bd.tcl",
                example: "fcc_zcu104_example.c",
            },
        }
    }

    /// The board of a `--board` name.
    pub fn from_name(name: &str) -> Result<Board, String> {
        BOARDS
            .into_iter()
            .find(|b| b.info().name == name)
            .ok_or_else(|| {
                let names: Vec<&str> = BOARDS.iter().map(|b| b.info().name).collect();
                format!("unknown board '{name}'; choose one of {}", names.join(", "))
            })
    }
}

/// The PS side of a block design: IP, pins and settings of one PS flavour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PsInfo {
    pub vlnv: &'static str,
    pub automation_rule: &'static str,
    pub automation_config: &'static str,
    /// The fabric clock, its reset (active low), the control master and
    /// its clock pin, the memory slave and its clock pin, the interrupt input.
    pub clock: &'static str,
    pub reset: &'static str,
    pub master: &'static str,
    pub master_clock: &'static str,
    pub slave: &'static str,
    pub slave_clock: &'static str,
    pub irq: &'static str,
    /// CONFIG properties that enable the master, the slave, the
    /// interrupts, and set the fabric clock (`@FCLK@`).
    pub config: &'static str,
    /// The property that reads back the fabric clock the PS got.
    pub actual_clock: &'static str,
    /// GIC interrupt ID of `irq` bit 0.
    pub gic_base: u32,
    /// Address width the DMA needs to reach the PS's DDR.
    pub dma_addr_width: u32,
}

impl Ps {
    pub fn info(self) -> PsInfo {
        match self {
            Ps::Ps7 => PsInfo {
                vlnv: vlnv::PS7,
                automation_rule: vlnv::PS7_AUTOMATION,
                automation_config: r#"{make_external "FIXED_IO, DDR" apply_board_preset "1" Master "Disable" Slave "Disable"}"#,
                clock: "FCLK_CLK0",
                reset: "FCLK_RESET0_N",
                master: "M_AXI_GP0",
                master_clock: "M_AXI_GP0_ACLK",
                slave: "S_AXI_HP0",
                slave_clock: "S_AXI_HP0_ACLK",
                irq: "IRQ_F2P",
                config: "    CONFIG.PCW_USE_M_AXI_GP0 {1} \\\n    CONFIG.PCW_USE_S_AXI_HP0 {1} \\\n    CONFIG.PCW_USE_FABRIC_INTERRUPT {1} \\\n    CONFIG.PCW_IRQ_F2P_INTR {1} \\\n    CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {@FCLK@} \\\n",
                actual_clock: "CONFIG.PCW_ACT_FPGA0_PERIPHERAL_FREQMHZ",
                gic_base: 61,
                dma_addr_width: 32,
            },
            Ps::ZynqUltra => PsInfo {
                vlnv: vlnv::ZYNQ_ULTRA,
                automation_rule: vlnv::ZYNQ_ULTRA_AUTOMATION,
                automation_config: r#"{apply_board_preset "1"}"#,
                clock: "pl_clk0",
                reset: "pl_resetn0",
                master: "M_AXI_HPM0_FPD",
                master_clock: "maxihpm0_fpd_aclk",
                slave: "S_AXI_HP0_FPD",
                slave_clock: "saxihp0_fpd_aclk",
                irq: "pl_ps_irq0",
                config: "    CONFIG.PSU__USE__M_AXI_GP0 {1} \\\n    CONFIG.PSU__USE__M_AXI_GP1 {0} \\\n    CONFIG.PSU__USE__S_AXI_GP2 {1} \\\n    CONFIG.PSU__USE__IRQ0 {1} \\\n    CONFIG.PSU__FPGA_PL0_ENABLE {1} \\\n    CONFIG.PSU__CRL_APB__PL0_REF_CTRL__FREQMHZ {@FCLK@} \\\n",
                actual_clock: "CONFIG.PSU__CRL_APB__PL0_REF_CTRL__ACT_FREQMHZ",
                gic_base: 121,
                dma_addr_width: 40,
            },
        }
    }
}

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
/// Widest buffer length register of the AXI DMA (`c_sg_length_width`), bits.
pub const DMA_LENGTH_WIDTH_MAX: u32 = 26;

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
    /// Zynq UltraScale+ PS, release 3.5 (Vivado 2023.1 and later).
    pub const ZYNQ_ULTRA: &str = "xilinx.com:ip:zynq_ultra_ps_e:3.5";
    pub const ZYNQ_ULTRA_AUTOMATION: &str = "xilinx.com:bd_rule:zynq_ultra_ps_e";
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

/// `vendor:library:name:version` of the packaged core of `p`. The name is
/// the top module's, so it changes with the configuration
/// (`fcc:fcc:fcc_top_k7_1b2c3d4e:0.1`): two configurations can sit in one
/// IP repository and one project.
pub fn ip_vlnv(p: &FccParams) -> String {
    format!(
        "{IP_VENDOR}:{IP_LIBRARY}:{}:{}",
        top_module(p),
        ip_version()
    )
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

/// The ports of the module `top` (see [`top_module`]), in declaration
/// order, read from the generated Verilog (`input wire [63:0]
/// s_axis_tdata;` ...). Empty if the module is missing.
pub fn top_ports(verilog: &str, top: &str) -> Vec<Port> {
    let decl = regex::Regex::new(
        r"^\s*(input|output)\s+(?:wire|reg)?\s*(?:\[(\d+):(\d+)\])?\s*([A-Za-z_][A-Za-z0-9_]*)\s*;",
    )
    .expect("valid regex");
    let header = format!("module {top}(");
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
            "{TOP_NAME} has no port {name}; the Vivado scripts need it"
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

/// [`fill`] for the generator's other templates.
pub(crate) fn fill_public(template: &str, vars: &[(&str, String)]) -> String {
    fill(template, vars)
}

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
# (scripts/fcc_<board>_bd.tcl) the core's ports become internal nets and these
# port constraints are dropped: the clock is the Zynq PS's fabric clock,
# defined by the PS's own constraints, and the paths between the core and the DMA or
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
# (proc_sys_reset in the block designs). Timed like a data input: its release
# must reach every register it resets in the same cycle.
set_input_delay -clock @CLK@ @IO@ [get_ports @RST@]

# @STATUS@*: quasi-static. The counters and flags are registers that change
# once per frame (when the last label beat is accepted); status_idle is
# combinational (an AND of three state registers) and changes when a frame
# starts and ends. They carry the same values as the status registers,
# which software reads through the AXI4-Lite port; a system that uses the
# ports samples them long after the frame's interrupt: no register captures
# them on the next edge, so the paths to these ports are not timed out of
# context.
# (status_frame_done is a one-cycle pulse; the block designs leave the
# status ports unconnected.)
set_false_path -to [get_ports @STATUS@*]
"##,
        &[
            ("TOP", top_module(p)),
            ("BUILD", BUILD_SCRIPT.to_string()),
            ("PACKAGE", PACKAGE_SCRIPT.to_string()),
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
/// The register header, copied beside the C example.
pub const REGS_HEADER: &str = "fcc_regs.h";

/// Primitives counted in `summary.txt`, per family: (key, REF_NAME pattern).
fn primitive_counts(board: Board) -> [(&'static str, &'static str); 7] {
    match board.info().ps {
        Ps::Ps7 => [
            ("lut", "LUT*"),
            ("srl", "SRL*"),
            ("ff", "FD*"),
            ("dsp48e1", "DSP48E1"),
            ("ramb36e1", "RAMB36E1"),
            ("ramb18e1", "RAMB18E1"),
            ("carry4", "CARRY4"),
        ],
        Ps::ZynqUltra => [
            ("lut", "LUT*"),
            ("srl", "SRL*"),
            ("ff", "FD*"),
            ("dsp48e2", "DSP48E2"),
            ("ramb36e2", "RAMB36E2"),
            ("ramb18e2", "RAMB18E2"),
            ("carry8", "CARRY8"),
        ],
    }
}

/// The `report_utilization` row of all LUTs of the slices or CLBs (logic,
/// LUTRAM and SRL): "Slice LUTs" on 7-series, "CLB LUTs" on UltraScale+.
pub fn lut_row(board: Board) -> &'static str {
    match board.info().ps {
        Ps::Ps7 => "Slice LUTs",
        Ps::ZynqUltra => "CLB LUTs",
    }
}

/// `fcc_build.tcl`: out-of-context synthesis, implementation and reports in
/// non-project mode on the part of `board`; stops with an error when the
/// routed design misses the clock. `rtl` and `xdc` are the Verilog and
/// constraint files relative to the directory of the script.
pub fn tcl(p: &FccParams, board: Board, rtl: &str, xdc: &str) -> String {
    let b = board.info();
    let counts: Vec<String> = primitive_counts(board)
        .iter()
        .map(|(k, pat)| format!("\"{k}=[fcc_count {pat}]\""))
        .collect();
    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"# Board: @BOARD@ (@PART@)
#
# Out-of-context synthesis, placement and routing of @TOP@ for the @TITLE@'s
# @PART@ in non-project mode, with utilisation, timing, methodology and DRC
# reports. Stops with an error when the routed design's worst setup slack is
# negative (the reports and summary.txt are written first).
# Written to the Vivado Tcl reference (UG835); not run by the generator's tests.
#
# Usage (from any directory):
#   vivado -mode batch -source <repo>/scripts/@SCRIPT@ [-tclargs ?-out DIR? ?-no_phys_opt?]
#     -out DIR       results in DIR/build (default: ./@DEFAULT_OUT@/build)
#     -no_phys_opt   skip phys_opt_design after placement
# Writes post_synth.dcp, post_route.dcp, utilization_synth.rpt,
# utilization_route.rpt, utilization_route_hier.rpt, timing_synth.rpt,
# timing_route.rpt, methodology_route.rpt, drc_route.rpt and summary.txt
# (key=value: worst slacks, all slice LUTs with LUTRAM and SRL, primitive counts).

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
report_methodology -file [file join $out methodology_route.rpt]
report_drc -file [file join $out drc_route.rpt]

# Worst slack of the routed design ("none" if no path is constrained),
# the used count of a report_utilization row, and primitive counts in the
# columns of the Yosys table of docs/results.md.
proc fcc_slack {delay_type} {
    set path [get_timing_paths -delay_type $delay_type -max_paths 1 -nworst 1 -quiet]
    if {$path eq ""} { return none }
    return [get_property SLACK $path]
}
proc fcc_used {report row} {
    foreach line [split $report \n] {
        set cells [split $line |]
        if {[llength $cells] > 2 && [string trimright [string trim [lindex $cells 1]] *] eq $row} {
            return [string trim [lindex $cells 2]]
        }
    }
    return none
}
proc fcc_count {ref_pattern} {
    return [llength [get_cells -hierarchical -quiet -filter "REF_NAME =~ $ref_pattern"]]
}
set util [report_utilization -return_string]
set wns [fcc_slack max]
set summary [list \
    "part=$part" "top=$top" "clock_mhz=$clock_mhz" "period_ns=$period_ns" \
    "wns_ns=$wns" "whs_ns=[fcc_slack min]" \
    "slice_luts=[fcc_used $util {@LUT_ROW@}]" "lutram=[fcc_used $util {LUT as Memory}]" \
    @COUNTS@]
set f [open [file join $out summary.txt] w]
puts $f [join $summary \n]
close $f
puts [join $summary \n]
if {$wns ne "none" && $wns < 0} {
    error "@SCRIPT@: the routed $top misses $clock_mhz MHz by [expr {-$wns}] ns (WNS $wns ns); see [file join $out timing_route.rpt], or regenerate with a lower --clock-mhz"
}
"##,
        &[
            ("TOP", top_module(p)),
            ("BOARD", b.name.to_string()),
            ("TITLE", b.title.to_string()),
            ("PART", b.part.to_string()),
            ("SCRIPT", BUILD_SCRIPT.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("MHZ", format!("{}", p.clock_mhz)),
            ("PERIOD", format!("{:.3}", period_ns(p))),
            ("RTL", rtl.to_string()),
            ("XDC", xdc.to_string()),
            ("LUT_ROW", lut_row(board).to_string()),
            ("COUNTS", counts.join(" ")),
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
pub fn package_ip_tcl(p: &FccParams, board: Board, ports: &[Port], rtl: &str, xdc: &str) -> String {
    let b = board.info();
    let families: Vec<String> = {
        let mut f: Vec<&str> = BOARDS.iter().map(|b| b.info().family).collect();
        f.dedup();
        f.iter().map(|f| format!("{f} Production")).collect()
    };
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
        r##"# Board: @BOARD@ (@PART@)
#
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
# Every family a generated block design targets.
set_property supported_families {@FAMILIES@} $core

# The packager imported the XDC into the IP's synthesis file group; keep it
# out-of-context only there too (see the XDC's header).
set ooc_xdc [ipx::get_files src/@XDC_NAME@ -of_objects [ipx::get_file_groups xilinx_anylanguagesynthesis -of_objects $core]]
if {[llength $ooc_xdc] != 1} {
    error "the packaged IP holds no src/@XDC_NAME@ in its synthesis files"
}
set_property USED_IN {synthesis implementation out_of_context} $ooc_xdc

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
            ("TOP", top_module(p)),
            ("VLNV", ip_vlnv(p)),
            ("CLK", CLOCK_PORT.to_string()),
            ("RST", RESET_PORT.to_string()),
            ("BD", b.bd_script.to_string()),
            ("BOARD", b.name.to_string()),
            ("FAMILIES", families.join(" ")),
            (
                "XDC_NAME",
                xdc.rsplit('/').next().unwrap_or(xdc).to_string(),
            ),
            ("SCRIPT", PACKAGE_SCRIPT.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("PART", b.part.to_string()),
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
// scripts/fcc_<board>_bd.tcl

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

/// The fabric clock the block design asks the PS for, MHz: the core's
/// clock, which must be one the board's PS and AXI DMA can run at.
pub fn fclk_mhz(p: &FccParams, board: Board) -> Result<f64, RtlError> {
    let b = board.info();
    if p.clock_mhz > b.clock_max_mhz {
        return Err(RtlError::Board(format!(
            "--clock-mhz {} is above {} MHz, the fastest clock the {}'s block design runs ({}: {}); choose at most {}",
            p.clock_mhz, b.clock_max_mhz, b.title, b.part, b.clock_max_source, b.clock_max_mhz
        )));
    }
    Ok(p.clock_mhz)
}

/// `fcc_<board>_bd.tcl`: the board's block design around the packaged core.
pub fn bd_tcl(p: &FccParams, ports: &[Port], board: Board) -> Result<String, RtlError> {
    let b = board.info();
    let ps = b.ps.info();
    let (in_bytes, out_bytes) = dma_frame_bytes(p, ports)?;
    let len_width = dma_length_width(p, ports)?;
    let in_width = port(ports, "s_axis_tdata")?.width;
    let out_width = port(ports, "m_axis_tdata")?.width;
    for name in [CLOCK_PORT, RESET_PORT, IRQ_PORT] {
        port(ports, name)?;
    }
    if axis_port_maps(ports, AXIL_INTERFACE).is_empty() {
        return Err(RtlError::Check(format!(
            "{TOP_NAME} has no {AXIL_INTERFACE}_* ports; the block design needs its register port"
        )));
    }
    let fclk = fclk_mhz(p, board)?;
    let map_lines = register_map_lines(p);
    let map_comment: String = map_lines.iter().map(|l| format!("#     {l}\n")).collect();
    let map_puts: String = map_lines
        .iter()
        .map(|l| format!("puts $map {{register {l}}}\n"))
        .collect();
    let ps_name = match b.ps {
        Ps::Ps7 => "PS7",
        Ps::ZynqUltra => "Zynq UltraScale+ PS",
    };
    let config = fill(ps.config, &[("FCLK", format!("{fclk}"))]);

    let mut s = file_header(p, "#");
    s.push_str(&fill(
        r##"# Board: @BOARD_NAME@ (@PART@)
#
# Block design for the @TITLE@ (@BOARD@, @PART@): the @PS_NAME@ with the
# board preset; an AXI DMA in simple (register) mode that reads frames from
# DDR into @TOP@'s s_axis (MM2S) and writes its m_axis labels back to DDR
# (S2MM); the core's register port and the DMA's registers on the PS's
# @PS_MASTER@ through a SmartConnect; memory (PS @PS_SLAVE@) through another; a
# processor system reset; the DMA's two interrupts and the core's irq on
# @PS_IRQ@. Everything runs on @PS_CLOCK@.
# Written to UG835 and UG994; not run by the generator's tests.
#
# Run scripts/@PACKAGE@ first, with the same -out.
# Usage (from any directory):
#   vivado -mode batch -source <repo>/scripts/@SCRIPT@ [-tclargs ?-out DIR? ?-bitstream? ?-jobs N?]
#     -out DIR     project in DIR/@BOARD_NAME@, core from DIR/ip_repo (default DIR: ./@DEFAULT_OUT@)
#     -bitstream   also synthesise and implement; if the routed design meets
#                  the clock (WNS >= 0), write the bitstream and export
#                  DIR/@BOARD_NAME@/@BD_NAME@.xsa for the software tools;
#                  otherwise stop with an error and write neither
#     -jobs N      parallel jobs for -bitstream (default 2)
#
# Clock: @PS_CLOCK@ is asked for @FCLK@ MHz (at most @CLOCK_MAX@ MHz on this board:
# @CLOCK_MAX_SOURCE@); the PS rounds it to what its PLL dividers give,
# and the script prints the frequency it got.
#
# Software view (also written to DIR/@BOARD_NAME@/@BD_NAME@_map.txt with the addresses):
#   DMA MM2S_LENGTH = @IN_BYTES@ bytes per frame (@PIXELS@ pixels, @IN_BEAT@ bytes each)
#   DMA S2MM_LENGTH = @OUT_BYTES@ bytes per frame (@LPB@ labels per @OUT_BEAT@-byte beat)
#   DMA addresses: @DMA_ADDR@ bits
#   Interrupts: @PS_IRQ@[0] = MM2S done (GIC ID @GIC0@), @PS_IRQ@[1] = S2MM done (GIC ID @GIC1@),
#     @PS_IRQ@[2] = fcc irq, frame done (GIC ID @GIC2@, level high)
#   fcc registers (offsets in the fcc segment; fields in fcc_regs.h):
@MAP_COMMENT@
set usage {usage: vivado -mode batch -source @SCRIPT@ -tclargs ?-out DIR? ?-bitstream? ?-jobs N?}
set part @PART@
set board_part @BOARD@
set design @BD_NAME@
set bitstream 0
set jobs 2
@ARGS@set ip_repo [file normalize [file join $out_base ip_repo]]
set proj_dir [file normalize [file join $out_base @BOARD_NAME@]]
if {![file exists [file join $ip_repo @TOP@ component.xml]]} {
    error "no packaged @TOP@ in $ip_repo: run @PACKAGE@ -tclargs -out $out_base first"
}

create_project -force $design $proj_dir -part $part
set_property board_part $board_part [current_project]
set_property ip_repo_paths [list $ip_repo] [current_project]
update_ip_catalog
create_bd_design $design

# PS: the board preset first (DDR, MIO, PS clocks of the @TITLE@), then
# what this design adds to it.
create_bd_cell -type ip -vlnv @PS_VLNV@ ps
apply_bd_automation -rule @PS_RULE@ -config @PS_AUTO@ [get_bd_cells ps]
set_property -dict [list \
@PS_CONFIG@] [get_bd_cells ps]
puts "@PS_CLOCK@: asked @FCLK@ MHz, got [get_property @PS_ACT@ [get_bd_cells ps]] MHz"

create_bd_cell -type ip -vlnv @RESET@ rst_fclk0

# AXI DMA, simple mode: one frame per MM2S and per S2MM transfer.
create_bd_cell -type ip -vlnv @DMA@ dma
set_property -dict [list \
    CONFIG.c_include_sg {0} \
    CONFIG.c_sg_include_stscntrl_strm {0} \
    CONFIG.c_sg_length_width {@LEN_WIDTH@} \
    CONFIG.c_addr_width {@DMA_ADDR@} \
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
connect_bd_net [get_bd_pins ps/@PS_CLOCK@] \
    [get_bd_pins ps/@PS_MASTER_CLOCK@] [get_bd_pins ps/@PS_SLAVE_CLOCK@] \
    [get_bd_pins rst_fclk0/slowest_sync_clk] \
    [get_bd_pins ctrl_smc/aclk] [get_bd_pins mem_smc/aclk] \
    [get_bd_pins dma/s_axi_lite_aclk] [get_bd_pins dma/m_axi_mm2s_aclk] [get_bd_pins dma/m_axi_s2mm_aclk] \
    [get_bd_pins fcc/@CLK@]
connect_bd_net [get_bd_pins ps/@PS_RESET@] [get_bd_pins rst_fclk0/ext_reset_in]
connect_bd_net [get_bd_pins rst_fclk0/interconnect_aresetn] \
    [get_bd_pins ctrl_smc/aresetn] [get_bd_pins mem_smc/aresetn]
connect_bd_net [get_bd_pins rst_fclk0/peripheral_aresetn] \
    [get_bd_pins dma/axi_resetn]
connect_bd_net [get_bd_pins rst_fclk0/peripheral_reset] [get_bd_pins fcc/@RST@]

# Control: PS -> DMA registers and the core's registers; memory: DMA -> DDR;
# streams.
connect_bd_intf_net [get_bd_intf_pins ps/@PS_MASTER@] [get_bd_intf_pins ctrl_smc/S00_AXI]
connect_bd_intf_net [get_bd_intf_pins ctrl_smc/M00_AXI] [get_bd_intf_pins dma/S_AXI_LITE]
connect_bd_intf_net [get_bd_intf_pins ctrl_smc/M01_AXI] [get_bd_intf_pins fcc/@AXIL@]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXI_MM2S] [get_bd_intf_pins mem_smc/S00_AXI]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXI_S2MM] [get_bd_intf_pins mem_smc/S01_AXI]
connect_bd_intf_net [get_bd_intf_pins mem_smc/M00_AXI] [get_bd_intf_pins ps/@PS_SLAVE@]
connect_bd_intf_net [get_bd_intf_pins dma/M_AXIS_MM2S] [get_bd_intf_pins fcc/s_axis]
connect_bd_intf_net [get_bd_intf_pins fcc/m_axis] [get_bd_intf_pins dma/S_AXIS_S2MM]

# Interrupts.
connect_bd_net [get_bd_pins dma/mm2s_introut] [get_bd_pins irq_concat/In0]
connect_bd_net [get_bd_pins dma/s2mm_introut] [get_bd_pins irq_concat/In1]
connect_bd_net [get_bd_pins fcc/@IRQ@] [get_bd_pins irq_concat/In2]
connect_bd_net [get_bd_pins irq_concat/dout] [get_bd_pins ps/@PS_IRQ@]

assign_bd_address
validate_bd_design
save_bd_design

file mkdir $proj_dir
set map [open [file join $proj_dir ${design}_map.txt] w]
puts $map "# @BD_NAME@ software view: PS address segments (name offset range), DMA lengths, fcc registers (offset name access)"
foreach seg [get_bd_addr_segs -of_objects [get_bd_addr_spaces ps/Data]] {
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
    # Route first, check the clock is met, and only then write the
    # bitstream and the hardware platform: a failing design leaves neither.
    launch_runs impl_1 -to_step route_design -jobs $jobs
    wait_on_run impl_1
    if {[string match *ERROR* [get_property STATUS [get_runs impl_1]]]} {
        error "impl_1 failed: see [get_property DIRECTORY [get_runs impl_1]]"
    }
    set wns [get_property STATS.WNS [get_runs impl_1]]
    set whs [get_property STATS.WHS [get_runs impl_1]]
    puts "impl_1 routed: WNS $wns ns, WHS $whs ns"
    if {![string is double -strict $wns] || $wns < 0 || ![string is double -strict $whs] || $whs < 0} {
        error "@SCRIPT@: the routed $design misses its clock (WNS '$wns' ns, WHS '$whs' ns): no bitstream, no .xsa; see the timing summary in [get_property DIRECTORY [get_runs impl_1]], or regenerate with a lower --clock-mhz"
    }
    launch_runs impl_1 -next_step -jobs $jobs
    wait_on_run impl_1
    if {[get_property PROGRESS [get_runs impl_1]] ne "100%"} {
        error "impl_1 write_bitstream failed: see [get_property DIRECTORY [get_runs impl_1]]"
    }
    write_hw_platform -fixed -include_bit -force -file [file join $proj_dir $design.xsa]
}
puts "@SCRIPT@: $design in $proj_dir"
"##,
        &[
            ("BOARD", b.board_part.to_string()),
            ("BOARD_NAME", b.name.to_string()),
            ("TITLE", b.title.to_string()),
            ("PART", b.part.to_string()),
            ("TOP", top_module(p)),
            ("PACKAGE", PACKAGE_SCRIPT.to_string()),
            ("SCRIPT", b.bd_script.to_string()),
            ("DEFAULT_OUT", DEFAULT_OUT.to_string()),
            ("BD_NAME", b.bd_name.to_string()),
            ("FCLK", format!("{fclk}")),
            ("CLOCK_MAX", format!("{}", b.clock_max_mhz)),
            ("CLOCK_MAX_SOURCE", b.clock_max_source.to_string()),
            ("IN_BYTES", in_bytes.to_string()),
            ("OUT_BYTES", out_bytes.to_string()),
            ("PIXELS", p.pixels().to_string()),
            ("IN_BEAT", (in_width / 8).to_string()),
            ("OUT_BEAT", (out_width / 8).to_string()),
            ("LPB", p.labels_per_beat.to_string()),
            ("DMA_ADDR", ps.dma_addr_width.to_string()),
            ("GIC0", ps.gic_base.to_string()),
            ("GIC1", (ps.gic_base + 1).to_string()),
            ("GIC2", (ps.gic_base + 2).to_string()),
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
            ("FCC_VLNV", ip_vlnv(p)),
            ("PS_NAME", ps_name.to_string()),
            ("PS_VLNV", ps.vlnv.to_string()),
            ("PS_RULE", ps.automation_rule.to_string()),
            ("PS_AUTO", ps.automation_config.to_string()),
            ("PS_CONFIG", config),
            ("PS_ACT", ps.actual_clock.to_string()),
            ("PS_CLOCK", ps.clock.to_string()),
            ("PS_RESET", ps.reset.to_string()),
            ("PS_MASTER", ps.master.to_string()),
            ("PS_MASTER_CLOCK", ps.master_clock.to_string()),
            ("PS_SLAVE", ps.slave.to_string()),
            ("PS_SLAVE_CLOCK", ps.slave_clock.to_string()),
            ("PS_IRQ", ps.irq.to_string()),
            ("DMA", vlnv::DMA.to_string()),
            ("SMC", vlnv::SMARTCONNECT.to_string()),
            ("RESET", vlnv::RESET.to_string()),
            ("CONCAT", vlnv::CONCAT.to_string()),
        ],
    ));
    Ok(s)
}

/// The scripts and software that travel with `fcc_build.tcl` for `board`:
/// `fcc_package_ip.tcl`, the block design, a copy of `fcc_regs.h` and the
/// bare-metal C example, for the directories of `layout`.
pub fn extra_scripts(
    g: &Generated,
    layout: &Layout,
    board: Board,
) -> Result<Vec<(&'static str, String)>, RtlError> {
    let ports = top_ports(&g.verilog, &top_module(&g.params));
    let rtl = relative(&layout.scripts, &layout.rtl.join("fcc_top.v"));
    let xdc = relative(&layout.scripts, &layout.constraints.join("fcc_top.xdc"));
    let b = board.info();
    Ok(vec![
        (
            PACKAGE_SCRIPT,
            package_ip_tcl(&g.params, board, &ports, &rtl, &xdc),
        ),
        (b.bd_script, bd_tcl(&g.params, &ports, board)?),
        (REGS_HEADER, g.regs_header.clone()),
        (b.example, crate::example::c_example(&g.params, board)),
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
