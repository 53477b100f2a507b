#!/usr/bin/env bash
# Set-up in one command: the system tools the tests need (Verilator, Yosys,
# z3, Icarus Verilog, a C++ compiler, tclsh, python3-venv), the cocotb
# bench's pinned Python tools in .venv, the Python package (python/) with
# its test tools in .venv, and `fcc` on PATH (~/.cargo/bin).
#
#   ./setup.sh               everything
#   ./setup.sh --no-install  without `cargo install` (CI: the tests run the
#                            binary cargo builds for them, not the one on PATH)
#
# Safe to run again: each step does only what is missing or out of date.
# It never reads standard input: with CI=true, sudo must not ask for a
# password. A failing step ends the script with one line naming it.
set -euo pipefail
cd "$(dirname "$0")"

# The Debian/Ubuntu packages (the Verilator models and the C example are
# compiled with g++; tcl for the Vivado script dry runs; z3 and yosys for the
# bounded proofs; iverilog for the cocotb bench).
APT_PACKAGES=(verilator yosys z3 iverilog g++ tcl python3-venv)

install=1
for arg in "$@"; do
    case "$arg" in
        --no-install) install=0 ;;
        -h | --help)
            sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'
            exit 0
            ;;
        *)
            echo "setup: error: unknown argument $arg (see --help)" >&2
            exit 2
            ;;
    esac
done

say() { echo "setup: $*"; }
fail() {
    echo "setup: error: $*" >&2
    exit 1
}
# run STEP CMD...: print and run CMD; on failure, one line naming STEP.
run() {
    local step=$1
    shift
    say "$step: $*"
    "$@" || fail "$step failed (exit $?): $*"
}

# 1. System packages.
missing=()
if command -v dpkg-query >/dev/null 2>&1; then
    for p in "${APT_PACKAGES[@]}"; do
        if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
            missing+=("$p")
        fi
    done
fi
if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    run "apt packages" apt-get update -qq
    run "apt packages" apt-get install -y -qq "${APT_PACKAGES[@]}"
elif ! command -v apt-get >/dev/null 2>&1; then
    for tool in verilator yosys z3 iverilog g++ tclsh python3; do
        command -v "$tool" >/dev/null 2>&1 || fail "no apt-get and $tool is not on PATH: install it with your package manager"
    done
    say "apt packages: no apt-get; the tools are on PATH"
elif [ ${#missing[@]} -eq 0 ]; then
    say "apt packages: already installed (${APT_PACKAGES[*]})"
elif command -v sudo >/dev/null 2>&1; then
    sudo=(sudo)
    if [ "${CI:-}" = "true" ] || [ ! -t 0 ]; then
        sudo=(sudo -n)
    fi
    export DEBIAN_FRONTEND=noninteractive
    run "apt packages" "${sudo[@]}" apt-get update -qq
    run "apt packages" "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${APT_PACKAGES[@]}"
else
    fail "apt packages missing (${missing[*]}) and not root: as root, run apt-get install -y ${APT_PACKAGES[*]}"
fi

# 2. The cocotb bench's Python tools, pinned, in .venv
# (crates/fcc-cli/tests/cocotb_icarus.rs runs it from `cargo test --workspace`).
if [ -x .venv/bin/python ]; then
    say "python: .venv exists"
else
    run "python venv" python3 -m venv .venv
fi
run "python packages" .venv/bin/pip install -q --disable-pip-version-check -r sim/cocotb/requirements.txt
# The third-party MCAP decoder the MCAP sink is tested with (crates/fcc-lidar/tests/mcap_sink.rs).
run "python packages" .venv/bin/pip install -q --disable-pip-version-check -r crates/fcc-lidar/tests/requirements.txt

# 3. The Python package `fcc` (python/, built by maturin from the Rust
# crates; cargo reuses python/target, so a second run takes seconds) and its
# pinned test tools, in .venv (crates/fcc-cli/tests/python_package.rs runs
# its tests).
command -v cargo >/dev/null 2>&1 || fail "cargo not found: install Rust (https://rustup.rs), then run ./setup.sh again"
run "python package" .venv/bin/pip install -q --disable-pip-version-check -r python/requirements-dev.txt
# Without build isolation pip runs the pinned maturin of .venv, found on PATH.
venv_pip() { PATH="$PWD/.venv/bin:$PATH" .venv/bin/pip "$@"; }
run "python package" venv_pip install -q --disable-pip-version-check --no-build-isolation ./python

# 4. `fcc` on PATH.
if [ "$install" = "1" ]; then
    command -v cargo >/dev/null 2>&1 || fail "cargo not found: install Rust (https://rustup.rs), then run ./setup.sh again"
    run "fcc" cargo install --locked --path crates/fcc-cli
    case ":$PATH:" in
        *":${CARGO_HOME:-$HOME/.cargo}/bin:"*) ;;
        *) say "fcc: add ${CARGO_HOME:-\$HOME/.cargo}/bin to PATH to call fcc" ;;
    esac
else
    say "fcc: not installed (--no-install)"
fi
say "done"
