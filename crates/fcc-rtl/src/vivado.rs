//! Vivado constraints (XDC) and a build script (Tcl) for the ZC706's XC7Z045.

use fcc_params::FccParams;

use crate::file_header;

/// The FPGA on the ZC706 board.
pub const PART: &str = "xc7z045ffg900-2";

/// `fcc_top.xdc`: the clock at `clock_mhz`. The core is meant to sit behind
/// AXI4-Stream interconnect inside the device, so its ports get no pins; the
/// I/O delays model registers of neighbouring logic on the same clock.
pub fn xdc(p: &FccParams) -> String {
    let period = 1000.0 / p.clock_mhz;
    let mut s = file_header(p, "#");
    s.push_str(&format!(
        "create_clock -name clk -period {period:.3} [get_ports clk]\n\
         set_input_delay -clock clk {io:.3} [get_ports -filter {{DIRECTION == IN && NAME != clk}}]\n\
         set_output_delay -clock clk {io:.3} [get_ports -filter {{DIRECTION == OUT}}]\n",
        io = period * 0.2,
    ));
    s
}

/// `fcc_build.tcl`: out-of-context synthesis, implementation and reports.
/// `rtl` and `xdc` are the Verilog and constraint files relative to the
/// directory of the script.
pub fn tcl(p: &FccParams, rtl: &str, xdc: &str) -> String {
    let mut s = file_header(p, "#");
    s.push_str(&format!(
        "# Usage: vivado -mode batch -source fcc_build.tcl\n\
         #        (from any directory; reports go to ./vivado_fcc/)\n\
         set part {PART}\n\
         set here [file dirname [file normalize [info script]]]\n\
         set out [file normalize vivado_fcc]\n\
         file mkdir $out\n\
         create_project -in_memory -part $part\n\
         read_verilog [file join $here {rtl}]\n\
         read_xdc [file join $here {xdc}]\n\
         synth_design -top fcc_top -part $part -mode out_of_context\n\
         report_utilization -file [file join $out utilization_synth.rpt]\n\
         opt_design\n\
         place_design\n\
         route_design\n\
         report_utilization -file [file join $out utilization.rpt]\n\
         report_timing_summary -file [file join $out timing.rpt]\n\
         write_checkpoint -force [file join $out fcc_top_routed.dcp]\n\
         # Requested clock: {mhz} MHz\n",
        mhz = p.clock_mhz
    ));
    s
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
