//! Helpers shared by the integration tests of the workspace: running the
//! `fcc` binary, scratch directories, fixtures and the checks on its error
//! output. Used only as a dev-dependency.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub mod live;

/// Run the binary `exe` with `args`, in `dir` if given (pass
/// `env!("CARGO_BIN_EXE_fcc")` from the test).
pub fn run_in(exe: &str, dir: Option<&Path>, args: &[&str]) -> Output {
    let mut c = Command::new(exe);
    c.args(args);
    if let Some(d) = dir {
        c.current_dir(d);
    }
    c.output()
        .unwrap_or_else(|e| panic!("cannot run {exe}: {e}"))
}

/// A scratch directory: removed when the test that made it passes, kept
/// for a look when it fails (dropped while panicking). Reads as a `Path`.
#[derive(Debug)]
pub struct Scratch(PathBuf);

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

/// A fresh, empty scratch directory named after the test binary, the process
/// and `name`.
pub fn tmpdir(name: &str) -> Scratch {
    let exe = std::env::current_exe().ok();
    let test = exe
        .as_deref()
        .and_then(Path::file_stem)
        .and_then(|s| s.to_str())
        .map(|s| s.split('-').next().unwrap_or(s))
        .unwrap_or("test");
    let d = std::env::temp_dir().join(format!("fcc-{test}-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap_or_else(|e| panic!("cannot create {}: {e}", d.display()));
    Scratch(d)
}

/// A path as `&str`, for command-line arguments.
pub fn s(p: &Path) -> &str {
    p.to_str()
        .unwrap_or_else(|| panic!("not UTF-8: {}", p.display()))
}

/// The standard error of a run.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Standard output then standard error of a run.
pub fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(o))
}

/// The LiDAR capture fixtures (`crates/fcc-lidar/tests/data`).
pub fn lidar_data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../fcc-lidar/tests/data")
}

/// The run failed with exit code 2 and one line naming `file` and `problem`.
pub fn assert_one_line_error(o: &Output, file: &Path, problem: &str) {
    assert_eq!(o.status.code(), Some(2), "{}", stderr(o));
    let e = stderr(o);
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(e.contains(s(file)) && e.contains(problem), "{e}");
}

/// Same partition: a bijection between the non-zero labels, zeros in the
/// same places (the golden model's check, for the tests).
pub use fcc_golden::same_partition;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_partition_needs_a_bijection_and_the_same_zeros() {
        assert!(same_partition(&[0, 1, 1, 2], &[0, 7, 7, 3]));
        assert!(
            !same_partition(&[0, 1, 1, 2], &[0, 7, 7, 7]),
            "two labels onto one"
        );
        assert!(
            !same_partition(&[0, 1, 2, 2], &[0, 7, 7, 3]),
            "one label onto two"
        );
        assert!(!same_partition(&[0, 1], &[1, 1]), "zero moved");
        assert!(!same_partition(&[1, 1], &[1]), "lengths differ");
    }

    #[test]
    fn tmpdir_is_empty_even_when_it_existed() {
        let d = tmpdir("reuse");
        std::fs::write(d.join("old"), b"x").unwrap();
        let d2 = tmpdir("reuse");
        assert_eq!(&*d, &*d2);
        assert_eq!(std::fs::read_dir(&d2).unwrap().count(), 0);
    }

    #[test]
    fn tmpdir_goes_when_its_test_passes_and_stays_when_it_fails() {
        let d = tmpdir("passes");
        std::fs::write(d.join("f"), b"x").unwrap();
        let path = d.to_path_buf();
        drop(d);
        assert!(!path.exists(), "a passing test's scratch was left behind");
        let kept = std::panic::catch_unwind(|| {
            let d = tmpdir("fails");
            let path = d.to_path_buf();
            std::fs::write(d.join("f"), b"x").unwrap();
            std::panic::panic_any(path);
        })
        .unwrap_err();
        let path = kept.downcast::<PathBuf>().unwrap();
        assert!(
            path.join("f").exists(),
            "a failing test's scratch was removed"
        );
        std::fs::remove_dir_all(&*path).unwrap();
    }

    /// The full regression's switch (this crate's `full-regression`
    /// feature) is turned on by fcc-synth, a workspace member outside
    /// `default-members`: were fcc-synth a default member, `cargo test`
    /// would run the full regression; without the switch, `cargo test
    /// --workspace` would leave out the targets that require it.
    #[test]
    fn full_regression_is_switched_on_by_a_member_the_quick_tests_leave_out() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let read =
            |f: &str| std::fs::read_to_string(root.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        let list = |toml: &str, key: &str| -> Vec<String> {
            let start = toml
                .find(&format!("\n{key} = ["))
                .unwrap_or_else(|| panic!("Cargo.toml lacks {key}"));
            let rest = &toml[start..];
            rest[rest.find('[').unwrap() + 1..rest.find(']').unwrap()]
                .split(',')
                .map(|m| m.trim().trim_matches('"').to_string())
                .filter(|m| !m.is_empty())
                .collect()
        };
        let workspace = read("Cargo.toml");
        let (members, defaults) = (
            list(&workspace, "members"),
            list(&workspace, "default-members"),
        );
        assert!(members.contains(&"crates/fcc-synth".to_string()));
        assert!(
            !defaults.contains(&"crates/fcc-synth".to_string()),
            "fcc-synth switches on the full regression: keep it out of default-members"
        );
        let synth = read("crates/fcc-synth/Cargo.toml");
        let dev = &synth[synth
            .find("[dev-dependencies]")
            .expect("fcc-synth has dev-dependencies")..];
        assert!(
            dev.lines()
                .any(|l| l.starts_with("fcc-testkit")
                    && l.contains("features = [\"full-regression\"]")),
            "fcc-synth's dev-dependencies switch on fcc-testkit/full-regression"
        );
    }
}
