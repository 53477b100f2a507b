//! `scripts/fcc_package_ip.tcl`.

use fcc_params::FccParams;

use crate::{file_header, param_summary, top_module};

use super::template::{args_block, fill};
use super::{
    axis_port_maps, ip_version, ip_vlnv, vlnv, Board, Port, AXIL_INTERFACE, AXIS_INTERFACES,
    BOARDS, CLOCK_PORT, DEFAULT_OUT, IP_LIBRARY, IP_TAXONOMY, IP_VENDOR, IRQ_PORT, PACKAGE_SCRIPT,
    RESET_PORT,
};

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
