//! `constraints/fcc_top.xdc`.

use fcc_params::FccParams;

use crate::{file_header, top_module};

use super::template::fill;
use super::{
    period_ns, AXIL_INTERFACE, AXIS_INTERFACES, BUILD_SCRIPT, CLOCK_PORT, IO_DELAY_FRACTION,
    IRQ_PORT, OOC_CLOCK_BUFFER, PACKAGE_SCRIPT, RESET_PORT, STATUS_PREFIX,
};

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
