//! The Python package's test suite (`python/tests`, pytest).
//!
//! The suite compares the package's labels with this crate's `fcc` binary
//! (passed as `FCC_BIN`), so it runs from here. Needs the package and
//! pytest installed in `.venv` at the repository root (`./setup.sh` does
//! it; `.ci/run` calls it), or the interpreter named by `FCC_PYTHON`. When
//! they are missing the test fails under `CI=true` and says it did not run
//! otherwise.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Why the suite cannot run with `python`, if it cannot.
fn missing(python: &Path) -> Option<String> {
    let ok = Command::new(python)
        .args(["-c", "import fcc, numpy, pytest"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    (!ok).then(|| {
        format!(
            "{} cannot import fcc, numpy and pytest: run ./setup.sh (or `.venv/bin/pip install \
             -r python/requirements-dev.txt ./python`) at the repository root, or set FCC_PYTHON",
            python.display()
        )
    })
}

#[test]
fn python_package_pytest_suite() {
    let root = repo_root();
    let python = std::env::var_os("FCC_PYTHON")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join(".venv/bin/python"));
    if let Some(why) = missing(&python) {
        if std::env::var("CI").is_ok_and(|v| v == "true") {
            panic!("the Python package's tests cannot run under CI: {why}");
        }
        eprintln!("Python package tests NOT RUN: {why}");
        return;
    }
    let status = Command::new(&python)
        .args([
            "-m",
            "pytest",
            "python/tests",
            "-q",
            "-p",
            "no:cacheprovider",
        ])
        .current_dir(&root)
        .env("FCC_BIN", env!("CARGO_BIN_EXE_fcc"))
        .status()
        .expect("start pytest");
    assert!(
        status.success(),
        "the Python package's tests failed ({status}); pytest's report is above \
         (after changing the Rust crates, reinstall the package: ./setup.sh)"
    );
}
