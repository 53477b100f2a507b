//! Names and numbers every Vivado file shares: the IP's identity, the
//! output directory, the house port names, the IP catalogue entries, the
//! scripts' file names.

use fcc_params::FccParams;

use crate::{top_module, GENERATOR_VERSION};

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

/// File names of the scripts.
pub const BUILD_SCRIPT: &str = "fcc_build.tcl";
pub const PACKAGE_SCRIPT: &str = "fcc_package_ip.tcl";
/// The register header, copied beside the C example.
pub const REGS_HEADER: &str = "fcc_regs.h";
