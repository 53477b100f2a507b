//! `scripts/fcc_<board>_bd.tcl`.

use fcc_params::{FccParams, Scan};

use crate::{file_header, top_module, RtlError, TOP_NAME};

use super::ports::port;
use super::template::{args_block, fill};
use super::{
    axis_port_maps, ip_vlnv, vlnv, Board, Port, Ps, AXIL_INTERFACE, CLOCK_PORT, DEFAULT_OUT,
    DMA_LENGTH_WIDTH_MAX, IRQ_PORT, PACKAGE_SCRIPT, RESET_PORT,
};

/// One line per register of the core, for the software map:
/// `0x040 CONTROL RW` (offset within the core's address segment).
pub fn register_map_lines(p: &FccParams) -> Vec<String> {
    crate::regmap::registers(p)
        .iter()
        .map(|r| format!("0x{:03X} {} {}", r.offset, r.name, r.access.as_str()))
        .collect()
}

/// Bytes the DMA moves per frame at most: (MM2S into `s_axis`, S2MM from
/// `m_axis`: a frame of labels, or of records in a column build).
pub fn dma_frame_bytes(p: &FccParams, ports: &[Port]) -> Result<(u64, u64), RtlError> {
    let pixels = p.pixels() as u64;
    let in_beat = u64::from(port(ports, "s_axis_tdata")?.width / 8);
    let out_beat = u64::from(port(ports, "m_axis_tdata")?.width / 8);
    let out_beats = match p.scan {
        Scan::Row => pixels.div_ceil(u64::from(p.labels_per_beat)),
        // A record per pixel at most (every pixel a cluster), then the end
        // beat (spec §9.4).
        Scan::Column => fcc_pixel::record::frame_beats_max(p.pixels()) as u64,
    };
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
