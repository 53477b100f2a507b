#!/usr/bin/env bash
# Verilator line and toggle coverage of fcc_top over the Verilator regression,
# summarised per block into docs/coverage.md.
#
#   bash sim/coverage.sh                 # the whole regression (cargo test -p fcc-sim)
#   bash sim/coverage.sh fsize3          # only the tests whose name contains fsize3
#
# The coverage models are cached apart from the plain ones (key suffix -cov);
# the counts go to target/fcc-coverage (emptied first).
set -euo pipefail
cd "$(dirname "$0")/.."
out="$PWD/target/fcc-coverage"
rm -rf "$out"
mkdir -p "$out"
FCC_SIM_COVERAGE="$out" cargo test -p fcc-sim --test regression -- "$@"
python3 sim/coverage_summary.py "$out" --command "bash sim/coverage.sh${*:+ $*}" > docs/coverage.md
echo "wrote docs/coverage.md from $(ls "$out"/*.dat | wc -l) coverage files"
