#!/usr/bin/env bash
# Verilator line and toggle coverage of fcc_top over the Verilator regression
# (sim/tests/regression.rs, the directed corners of sim/tests/corners.rs, the
# run registers of sim/tests/run_params.rs and the driver on the virtual
# board of sim/tests/board.rs),
# summarised per block into docs/coverage.md (what is never reached) and
# docs/coverage.json, then rendered into the coverage table of docs/results.md
# (`fcc synth --all --from-json docs/results.json --coverage-json docs/coverage.json`:
# nothing else in the results changes).
#
#   bash sim/coverage.sh                          # the whole regression
#   bash sim/coverage.sh --skip scenes_64x2048 --skip real_ouster
#                                                 # without the full-size frames (docs/coverage.md)
#   bash sim/coverage.sh fsize3                   # only the tests whose name contains fsize3
#
# Arguments go to the test binaries (name filters, --skip). The coverage
# models are cached apart from the plain ones (key suffix -cov); the counts go
# to target/fcc-coverage (emptied first).
set -euo pipefail
cd "$(dirname "$0")/.."
out="$PWD/target/fcc-coverage"
# The commit whose generator builds the models, read before they are built.
rtl="$(git rev-parse --short HEAD)"
if [ -n "$(git status --porcelain -- crates/fcc-rtl)" ]; then
    rtl="$rtl with local changes to crates/fcc-rtl"
fi
rm -rf "$out"
mkdir -p "$out"
FCC_SIM_COVERAGE="$out" cargo test -p fcc-sim --test regression --test corners \
    --test run_params --test board -- "$@"
python3 sim/coverage_summary.py "$out" --command "bash sim/coverage.sh${*:+ $*}" \
    --rtl "$rtl" --json docs/coverage.json > docs/coverage.md.tmp
mv docs/coverage.md.tmp docs/coverage.md
echo "wrote docs/coverage.md and docs/coverage.json from $(ls "$out"/*.dat | wc -l) coverage files"
cargo run --release -q -p fcc-cli -- synth --all --from-json docs/results.json \
    --coverage-json docs/coverage.json
