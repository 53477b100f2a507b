//! The one error type of this crate. Every variant that comes from a file
//! names the file, and every message says what is wrong with it.

use std::path::{Path, PathBuf};
use thiserror::Error;

/// Why reading, converting or writing LiDAR data failed.
#[derive(Debug, Error)]
pub enum LidarError {
    /// The operating system refused a read or a write.
    #[error("{path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// The file is not in the format its name or the caller promised.
    #[error("{path}: not a {format} file: {reason}")]
    NotFormat {
        path: PathBuf,
        format: &'static str,
        reason: String,
    },
    /// The file is in the right format but its content is broken.
    #[error("{path}: {reason}")]
    Malformed { path: PathBuf, reason: String },
    /// The Ouster metadata is missing something the decoder needs, or
    /// contradicts itself.
    #[error("{path}: Ouster metadata: {reason}")]
    Metadata { path: PathBuf, reason: String },
    /// An option or argument is out of range.
    #[error("{0}")]
    Config(String),
    /// Two inputs that must agree in size do not.
    #[error("{what}: expected {expected}, got {got}")]
    Mismatch {
        what: String,
        expected: usize,
        got: usize,
    },
    /// The golden model refused a frame.
    #[error(transparent)]
    Golden(#[from] fcc_golden::GoldenError),
    /// A parameter is out of range.
    #[error(transparent)]
    Params(#[from] fcc_params::ParamError),
}

/// Shorthand for results of this crate.
pub type Result<T, E = LidarError> = std::result::Result<T, E>;

impl LidarError {
    pub(crate) fn io(path: &Path, source: std::io::Error) -> Self {
        LidarError::Io {
            path: path.to_path_buf(),
            source,
        }
    }

    pub(crate) fn malformed(path: &Path, reason: impl Into<String>) -> Self {
        LidarError::Malformed {
            path: path.to_path_buf(),
            reason: reason.into(),
        }
    }

    pub(crate) fn not_format(path: &Path, format: &'static str, reason: impl Into<String>) -> Self {
        LidarError::NotFormat {
            path: path.to_path_buf(),
            format,
            reason: reason.into(),
        }
    }

    pub(crate) fn metadata(path: &Path, reason: impl Into<String>) -> Self {
        LidarError::Metadata {
            path: path.to_path_buf(),
            reason: reason.into(),
        }
    }
}
