//! The `fcc` Python package's native module (`fcc._fcc`): the golden model,
//! the readers, ground removal, scoring and the stream of the Rust crates,
//! with numpy arrays in and out. The Python layer (`fcc/__init__.py`) adds
//! the documented signatures; nothing here computes what a crate owns.

mod arrays;
mod fast;
mod model;
mod source;
mod stream;

use fcc_lidar::LidarError;
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use std::path::Path;

/// A library error as the Python exception of its kind, with the CLI's
/// message: a missing file is `FileNotFoundError`, another refused read or
/// write `OSError`, everything else (bad data, bad parameters) `ValueError`.
pub(crate) fn lidar_err(e: LidarError) -> PyErr {
    let msg = e.to_string();
    match &e {
        LidarError::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
            PyFileNotFoundError::new_err(msg)
        }
        LidarError::Io { .. } => PyOSError::new_err(msg),
        _ => PyValueError::new_err(msg),
    }
}

/// As [`lidar_err`], and `FileNotFoundError` whenever `path` does not exist
/// (some readers report a missing file in their own words).
pub(crate) fn file_err(e: LidarError, path: &Path) -> PyErr {
    if !path.exists() {
        return PyFileNotFoundError::new_err(e.to_string());
    }
    lidar_err(e)
}

/// A message as `ValueError`.
pub(crate) fn value_err(msg: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(msg.to_string())
}

#[pymodule]
fn _fcc(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<model::Pipeline>()?;
    m.add_class::<stream::Stream>()?;
    m.add_class::<source::Frames>()?;
    m.add_class::<source::Frame>()?;
    m.add_class::<source::Projection>()?;
    m.add_function(wrap_pyfunction!(model::remove_ground, m)?)?;
    m.add_function(wrap_pyfunction!(model::score, m)?)?;
    m.add_function(wrap_pyfunction!(model::scene, m)?)?;
    m.add_function(wrap_pyfunction!(source::open, m)?)?;
    m.add_function(wrap_pyfunction!(source::project, m)?)?;
    Ok(())
}
