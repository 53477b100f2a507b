//! Bounded proofs of the generated core with yosys-smtbmc, at a depth that
//! fits CI (`formal/run.sh`, documented in docs/rtl.md, runs them deeper).
//!
//! `formal/run.sh` generates the smallest configuration (K = 3, 16 x 256,
//! 8 label bits) with this crate's `fcc` binary and proves the join queue's
//! and the centre buffer's FIFOs (no underflow, exact level, order) for 12
//! cycles after reset, one test per FIFO (so both run at once). A third test
//! checks that a
//! deliberately false property ends in a counterexample, so the flow can
//! fail. Needs yosys, yosys-smtbmc and z3: when they are missing the tests
//! fail under `CI=true` and say they did not run otherwise.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Why the proofs cannot run here, if they cannot.
fn missing_tool() -> Option<String> {
    for (tool, arg) in [("yosys", "-V"), ("yosys-smtbmc", "-h"), ("z3", "-version")] {
        if Command::new(tool).arg(arg).output().is_err() {
            return Some(format!(
                "{tool} not found: install it (Debian: apt-get install yosys z3)"
            ));
        }
    }
    None
}

/// Runs formal/run.sh with `args` in its own work directory; None when the
/// tools are missing outside CI.
fn run_formal(work: &str, args: &[&str]) -> Option<(bool, String)> {
    if let Some(why) = missing_tool() {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("the bounded proofs cannot run under CI: {why}");
        }
        eprintln!("bounded proofs NOT RUN: {why}");
        return None;
    }
    let root = repo_root();
    let out = Command::new("bash")
        .arg(root.join("formal/run.sh"))
        .arg("--fcc")
        .arg(env!("CARGO_BIN_EXE_fcc"))
        .arg("--work")
        .arg(root.join("target/formal-test").join(work))
        .args(args)
        .output()
        .expect("start formal/run.sh");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    eprintln!("{text}");
    Some((out.status.success(), text))
}

/// One FIFO's proof (`--only`, its own work directory), so that the test
/// threads run the two proofs at once.
fn prove_fifo(name: &str) {
    let Some((ok, text)) = run_formal(name, &["--fifo-depth", "12", "--only", name]) else {
        return;
    };
    assert!(ok, "a bounded proof failed:\n{text}");
    assert!(
        text.contains(&format!("{name}: PASSED")),
        "{name} did not report PASSED:\n{text}"
    );
}

#[test]
fn join_queue_fifo_holds_for_bounded_cycles_after_reset() {
    prove_fifo("join_queue_fifo");
}

#[test]
fn centre_buffer_fifo_holds_for_bounded_cycles_after_reset() {
    prove_fifo("centre_buf_fifo");
}

#[test]
fn false_fifo_level_property_yields_counterexample() {
    let Some((ok, text)) = run_formal("wrong", &["--wrong", "--fifo-depth", "6"]) else {
        return;
    };
    assert!(
        ok,
        "the deliberately false property was not refuted:\n{text}"
    );
    assert!(
        text.contains("join_queue_fifo_wrong: FAILED"),
        "no counterexample reported:\n{text}"
    );
}
