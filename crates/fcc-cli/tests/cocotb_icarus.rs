//! The cocotb bench of the generated core on Icarus Verilog (4-state).
//!
//! `sim/cocotb/run_bench.py` generates a 16 x 256 configuration of every K
//! with this crate's `fcc` binary, gets the expected labels from `fcc
//! cluster` (the golden model), and simulates each configuration twice, as
//! generated and with every `initial` block removed (reset only), driving
//! AXI4-Stream with cocotbext-axi and random pauses on both sides. It also
//! runs the column-streaming core (`--scan column`, K = 3 and 11 at 24 x
//! 256, both copies), its output beats against `fcc cluster --stream
//! --beats`.
//!
//! Needs Icarus Verilog and the Python environment of
//! `sim/cocotb/requirements.txt` in `.venv` at the repository root (made by
//! `.ci/run`), or the interpreter named by `FCC_COCOTB_PYTHON`. When they are
//! missing the test fails under `CI=true` and says it did not run otherwise.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Why the bench cannot run here, if it cannot.
fn missing_tool(python: &Path) -> Option<String> {
    for tool in ["iverilog", "vvp"] {
        let found = Command::new(tool).arg("-V").output().is_ok();
        if !found {
            return Some(format!(
                "{tool} not found: install Icarus Verilog (Debian: apt-get install iverilog)"
            ));
        }
    }
    let ok = Command::new(python)
        .args(["-c", "import cocotb, cocotb_tools.runner, cocotbext.axi"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !ok {
        return Some(format!(
            "{} cannot import cocotb and cocotbext-axi: run `python3 -m venv .venv && \
             .venv/bin/pip install -r sim/cocotb/requirements.txt` at the repository root \
             (or set FCC_COCOTB_PYTHON)",
            python.display()
        ));
    }
    None
}

#[test]
fn cocotb_icarus_every_k_as_generated_and_reset_only() {
    let root = repo_root();
    let python = std::env::var_os("FCC_COCOTB_PYTHON")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join(".venv/bin/python"));
    if let Some(why) = missing_tool(&python) {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("the cocotb bench cannot run under CI: {why}");
        }
        eprintln!("cocotb bench NOT RUN: {why}");
        return;
    }
    let status = Command::new(&python)
        .arg(root.join("sim/cocotb/run_bench.py"))
        .arg("--fcc")
        .arg(env!("CARGO_BIN_EXE_fcc"))
        .arg("--work")
        .arg(root.join("target/cocotb"))
        .status()
        .expect("start the cocotb bench");
    assert!(
        status.success(),
        "the cocotb bench failed ({status}); the failing case, pixel, signal or cycle is printed above, \
         logs under target/cocotb/k<K>/<variant>/sim.log"
    );
}
