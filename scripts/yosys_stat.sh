#!/bin/sh
# Resource estimate of the generated core with Yosys (synth_xilinx, 7 series).
# Usage: scripts/yosys_stat.sh [path/to/fcc_top.v]   (default: rtl_out/fcc_top.v)
# Takes several minutes for K = 7 at 64 x 2048; prints the cell statistics.
set -eu
verilog=${1:-rtl_out/fcc_top.v}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
# The top (fcc_top and the configuration's suffix) is the one module nothing
# instantiates: synth_xilinx without -top finds it (hierarchy -auto-top).
yosys -q -l "$log" -p "read_verilog $verilog; synth_xilinx -family xc7 -flatten; stat" >/dev/null
sed -n '/Printing statistics/,$p' "$log" | grep -E 'Number of cells|LUT|FD[RSCP]E|DSP48E1|RAMB|CARRY4|MUXF|SRL'
