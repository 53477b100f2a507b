//! `scripts/fcc_build.tcl`.

use fcc_params::FccParams;

use crate::{file_header, top_module};

use super::template::{args_block, fill};
use super::{period_ns, Board, Ps, BUILD_SCRIPT, DEFAULT_OUT};

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
