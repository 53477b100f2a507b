//! Resource and timing estimates of the generated FCC core.
//!
//! - [`yosys`] runs `synth_xilinx -family xc7` on a set of Verilog files,
//!   reads `stat -json` into [`Resources`] and Yosys's `sta` (with the Xilinx
//!   cell models and their `specify` delays, in a second Yosys session on the
//!   synthesised netlist) into [`Timing`], and measures the netlist's fanout
//!   and routing hops ([`Routing`]).
//! - [`flow`] generates the RTL of one [`fcc_params::FccParams`] with
//!   `fcc-rtl` and runs the estimate on it.
//! - [`results`] runs the estimate for every K the generator supports and
//!   writes the results table (Markdown and JSON) beside the paper's Table I
//!   and the targets.
//! - [`vivado`] finds Vivado and runs the project's non-project build script,
//!   and reads its utilisation and timing reports.
//!
//! The timing here is a pre-route estimate: cell delays from Yosys's Xilinx
//! simulation models, no routing, no clock skew. It ranks designs and names
//! the longest chain of logic; it is not Vivado timing. `docs/results-method.md`
//! says how every number is measured.

pub mod flow;
pub mod resources;
pub mod results;
pub mod routing;
pub mod sta;
pub mod vivado;
pub mod yosys;

use std::path::PathBuf;

pub use flow::{estimate, estimate_dir};
pub use resources::Resources;
pub use routing::Routing;
pub use sta::Timing;
pub use yosys::{YosysConfig, YosysRun};

/// Everything that can go wrong while measuring.
#[derive(Debug, thiserror::Error)]
pub enum SynthError {
    /// The tool could not be started.
    #[error("cannot run `{tool}` ({reason}); install it ({install}) or put it on PATH")]
    ToolMissing {
        tool: String,
        /// How to install it, e.g. "Debian/Ubuntu: `apt-get install yosys`".
        install: &'static str,
        reason: String,
    },
    /// The tool ran and failed; `step` is the part of the script it was in.
    #[error("{tool} failed in step `{step}` ({status}); full log: {log}\n--- last lines of the log ---\n{tail}")]
    ToolFailed {
        tool: String,
        step: String,
        status: String,
        log: PathBuf,
        tail: String,
    },
    /// A report the tool wrote could not be read as expected.
    #[error("cannot parse {what} in {path}: {reason}\n--- last lines of the log ---\n{tail}")]
    Parse {
        what: String,
        path: PathBuf,
        reason: String,
        tail: String,
    },
    /// No Verilog to synthesise.
    #[error("no Verilog files (*.v) in {0}; generate the RTL there first or pass the directory that holds fcc_top.v")]
    NoVerilog(PathBuf),
    /// A file or directory could not be read or written.
    #[error("cannot {action} {path}: {err}")]
    Io {
        action: &'static str,
        path: PathBuf,
        err: std::io::Error,
    },
    /// The RTL generator refused the parameters or failed.
    #[error(transparent)]
    Rtl(#[from] fcc_rtl::RtlError),
}

/// Map an I/O error on `path` to [`SynthError::Io`].
pub(crate) fn io_err(
    action: &'static str,
    path: &std::path::Path,
) -> impl FnOnce(std::io::Error) -> SynthError {
    let path = path.to_path_buf();
    move |err| SynthError::Io { action, path, err }
}

/// The last `n` lines of `text`, for error messages.
pub(crate) fn tail_lines(text: &str, n: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let start = lines.len().saturating_sub(n);
    lines[start..].join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tail_keeps_the_last_lines() {
        assert_eq!(tail_lines("a\nb\nc\n", 2), "b\nc");
        assert_eq!(tail_lines("a", 5), "a");
        assert_eq!(tail_lines("", 5), "");
    }

    #[test]
    fn missing_tool_message_says_how_to_install() {
        let e = SynthError::ToolMissing {
            tool: "yosys".into(),
            install: yosys::INSTALL,
            reason: "not found".into(),
        };
        assert_eq!(
            e.to_string(),
            "cannot run `yosys` (not found); install it (Debian/Ubuntu: `apt-get install yosys`) or put it on PATH"
        );
    }
}
