#!/usr/bin/env bash
# Bounded proofs of the generated core with yosys-smtbmc (see docs/rtl.md,
# "Bounded proofs"). Generates the smallest configuration the generator
# accepts, reads module names and widths from the generated files, and runs
# one bounded model check per property set:
#   join_queue_fifo    the join queue's FIFO (no underflow, level exact, order)
#   centre_buf_fifo    the centre buffer's record FIFO (same properties)
#   top_axis           AXI4-Stream rules on both stream ports of the core,
#                      RAMs abstracted; only with --only top_axis (z3 did not
#                      finish depth 4 in 5 minutes)
#
# Usage: formal/run.sh [--fcc PATH] [--work DIR] [--fifo-depth N]
#                      [--top-depth N] [--solver z3|boolector] [--only NAME]
#                      [--wrong]
# --wrong checks a deliberately false FIFO property instead: the run must end
# in a counterexample (exit status 0 when it does, 1 when the false property
# passes or gives no verdict). Exit status otherwise: 0 when every proof
# passes, 1 when one fails or ends without a verdict (a solver that stopped).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/.." && pwd)"

fcc="$root/target/release/fcc"
work="$root/target/formal"
fifo_depth=12
top_depth=12
solver=z3
only=""
wrong=0
while [ $# -gt 0 ]; do
    case "$1" in
        --fcc) fcc="$2"; shift 2 ;;
        --work) work="$2"; shift 2 ;;
        --fifo-depth) fifo_depth="$2"; shift 2 ;;
        --top-depth) top_depth="$2"; shift 2 ;;
        --solver) solver="$2"; shift 2 ;;
        --only) only="$2"; shift 2 ;;
        --wrong) wrong=1; shift ;;
        -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
        *) echo "formal/run.sh: unknown argument '$1' (try --help)" >&2; exit 2 ;;
    esac
done
for tool in yosys yosys-smtbmc "$solver"; do
    if ! command -v "$tool" >/dev/null 2>&1; then
        echo "formal/run.sh: $tool not found (Debian: apt-get install yosys $solver)" >&2
        exit 2
    fi
done
if [ ! -x "$fcc" ]; then
    echo "formal/run.sh: no fcc binary at $fcc (cargo build --release -p fcc-cli, or --fcc PATH)" >&2
    exit 2
fi

# The smallest configuration the generator accepts (K, rows, columns and
# label width at their hardware minima).
mkdir -p "$work"
"$fcc" gen --smallest --out "$work/gen" --force --no-lint >"$work/gen.log"
rtl="$work/gen/rtl_out"
top=$(sed -n 's/^`define FCC_TOP_MODULE \([A-Za-z0-9_]*\).*/\1/p' "$rtl/fcc_params.vh")
suffix="${top#fcc_top}"
[ -n "$top" ] && [ "$suffix" != "$top" ] || { echo "formal/run.sh: no FCC_TOP_MODULE in $rtl/fcc_params.vh" >&2; exit 2; }

# Width of port PORT of module MOD in the generated Verilog (1 for a bit).
port_width() {
    local mod="$1" port="$2" w
    w=$(awk -v m="module $mod(" -v p="$port" '
        index($0, m) == 1 { inmod = 1; next }
        inmod && /^endmodule/ { exit }
        inmod && ($1 == "input" || $1 == "output") {
            name = $NF; sub(/;$/, "", name)
            if (name == p) { if (match($0, /\[[0-9]+:0\]/)) { print substr($0, RSTART + 1, RLENGTH - 4) + 1 } else { print 1 }; exit }
        }' "$rtl/fcc_top.v")
    [ -n "$w" ] || { echo "formal/run.sh: no port $port in module $mod" >&2; exit 2; }
    echo "$w"
}

# One proof: NAME WRAPPER TOPMODULE DEPTH DEFINES...
failed=0
no_result=0
prove() {
    local name="$1" wrapper="$2" wtop="$3" depth="$4"; shift 4
    local defs=("$@") dir="$work/$name"
    mkdir -p "$dir"
    yosys -q -l "$dir/yosys.log" -p "
        read_verilog -formal ${rtl_top:-$rtl/fcc_top.v}
        read_verilog -formal ${defs[*]} $here/$wrapper
        prep -top $wtop
        async2sync
        dffunmap
        write_smt2 -wires $dir/model.smt2" >/dev/null
    local t0 t1 status=0
    t0=$(date +%s.%N)
    yosys-smtbmc -s "$solver" --presat -t "$depth" --dump-vcd "$dir/trace.vcd" "$dir/model.smt2" >"$dir/smtbmc.log" 2>&1 || status=$?
    t1=$(date +%s.%N)
    local secs
    secs=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
    if [ "$status" = 0 ] && grep -q "Status: PASSED" "$dir/smtbmc.log"; then
        echo "$name: PASSED, depth $depth cycles after reset, ${secs} s ($solver)"
    elif grep -q "Status: FAILED" "$dir/smtbmc.log"; then
        echo "$name: FAILED at depth $depth (${secs} s); counterexample: $dir/trace.vcd"
        grep -E "Assert failed|failed" "$dir/smtbmc.log" | head -5 || true
        failed=1
    else
        # No verdict: the solver or yosys-smtbmc stopped (a crash, a
        # timeout, a solver that cannot take this model).
        echo "$name: NO RESULT at depth $depth (${secs} s): yosys-smtbmc ended without a verdict (exit status $status); see $dir/smtbmc.log"
        tail -n 3 "$dir/smtbmc.log" | sed 's/^/    /'
        no_result=1
    fi
}

fifo_proof() {
    local name="$1" mod="$2"
    local w a
    w=$(port_width "$mod" din)
    a=$(port_width "$mod" ram_raddr)
    local defs=(-DFIFO_MOD="$mod" -DFIFO_W="$w" -DFIFO_A="$a")
    [ "$wrong" = 1 ] && defs+=(-DFORMAL_WRONG)
    prove "$name" fifo_props.sv fifo_props "$fifo_depth" "${defs[@]}"
}

want() { [ -z "$only" ] || [ "$only" = "$1" ]; }

echo "formal: $(tail -n 1 "$work/gen.log"), solver $solver"
if [ "$wrong" = 1 ]; then
    fifo_proof join_queue_fifo_wrong "fcc_sort_net__join_queue__queue$suffix"
    if [ "$no_result" = 1 ]; then
        echo "formal: no verdict on the deliberately false property" >&2
        exit 1
    fi
    if [ "$failed" = 1 ]; then
        echo "formal: the deliberately false property has a counterexample, as it must"
        exit 0
    fi
    echo "formal: the deliberately false property PASSED: the flow cannot find failures" >&2
    exit 1
fi
want join_queue_fifo && fifo_proof join_queue_fifo "fcc_sort_net__join_queue__queue$suffix"
want centre_buf_fifo && fifo_proof centre_buf_fifo "fcc_sort_net__centre_buf__records$suffix"
if [ "$only" = top_axis ]; then
    # The core with its RAMs abstracted (a read returns any value, through
    # the same output registers): every run of the core is a run of this
    # model, and the solver does not carry the RAM contents.
    sed -E -e 's/^( *)reg (\[[0-9]+:0\]) mem \[0:[0-9]+\];/\1wire \2 mem_free = $anyseq;/' \
        -e 's/<= mem\[read_addr[^]]*\]\];|<= mem\[read_addr\];/<= mem_free;/' \
        -e 's/^( *)mem\[write_addr[^;]*;/\1;/' "$rtl/fcc_top.v" >"$work/fcc_top_ram_free.v"
    if grep -q 'mem\[' "$work/fcc_top_ram_free.v"; then
        echo "formal/run.sh: a RAM of the generated core is not in the abstracted form" >&2
        exit 2
    fi
    rtl_top="$work/fcc_top_ram_free.v"
    prove top_axis top_axis.sv top_axis "$top_depth" \
        -DTOP_MOD="$top" \
        -DS_DW="$(port_width "$top" s_axis_tdata)" -DS_KW="$(port_width "$top" s_axis_tkeep)" \
        -DM_DW="$(port_width "$top" m_axis_tdata)" -DM_KW="$(port_width "$top" m_axis_tkeep)" \
        -DAW="$(port_width "$top" s_axil_awaddr)" -DDW="$(port_width "$top" s_axil_wdata)"
fi
[ "$failed" = 0 ] && [ "$no_result" = 0 ]
