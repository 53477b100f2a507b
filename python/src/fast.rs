//! `Pipeline.labels` without ground removal: the golden model reads the
//! numpy buffer in place.
//!
//! With `ground="none"`, `fcc_lidar::pipeline::cluster_image` is an
//! all-false ground mask, a copy of the image, its quantisation
//! (`RangeImage::to_frame`, i.e. `Frame::from_xyz_f32`), `cluster_with` and
//! the min-points filter. Here the same calls run without the copies: the
//! array is quantised by `fcc_golden::quantize_point` straight from its
//! buffer (float64 rounded to float32 first, as the `.npy` reader does)
//! into a frame kept by the thread, and `cluster_with` reuses the thread's
//! workspace. The test suite checks these labels against `fcc cluster` and
//! against `cluster_image`.

use crate::arrays::array;
use crate::lidar_err;
use fcc_golden::{cluster_with, quantize_point, runs_needed, Frame, Workspace};
use fcc_lidar::labels::filter_min_points;
use fcc_lidar::pipeline::PipelineConfig;
use numpy::ndarray::ArrayViewD;
use numpy::{PyArrayDyn, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use std::cell::RefCell;

thread_local! {
    static BUFFERS: RefCell<(Workspace, Frame)> = RefCell::new((Workspace::default(), Frame::empty(0, 0)));
}

/// What the CLI warns about after a frame.
#[derive(Debug, Clone, Copy)]
pub struct Losses {
    pub overflow: bool,
    pub unlabelled: usize,
    pub points: usize,
    pub labels_needed: u64,
    pub out_of_range: usize,
}

/// Quantise `xyz` values (x y z per pixel) into `frame`; returns the points
/// with finite coordinates that do not fit Q7.8.
fn quantize_into(frame: &mut Frame, rows: usize, cols: usize, xyz: &[f32]) -> usize {
    frame.rows = rows;
    frame.cols = cols;
    frame.points.clear();
    let mut out_of_range = 0;
    frame.points.extend(xyz.chunks_exact(3).map(|p| {
        let q = quantize_point(f64::from(p[0]), f64::from(p[1]), f64::from(p[2]));
        out_of_range += usize::from(q.is_none() && p.iter().all(|v| v.is_finite()));
        q
    }));
    out_of_range
}

/// Fill the thread's frame from a checked (R, C, 3) float32 or float64
/// array, with the GIL held (no Python thread writes the array meanwhile):
/// a C-contiguous float32 array is read in place, any other is first
/// converted (float64 rounded to float32) through its strides.
fn fill(obj: &Bound<'_, PyAny>, frame: &mut Frame, rows: usize, cols: usize) -> PyResult<usize> {
    if let Ok(arr) = obj.downcast::<PyArrayDyn<f32>>() {
        let ro = arr.try_readonly()?;
        let view: ArrayViewD<'_, f32> = ro.as_array();
        return Ok(match view.as_slice() {
            Some(s) => quantize_into(frame, rows, cols, s),
            None => quantize_into(frame, rows, cols, &view.iter().copied().collect::<Vec<_>>()),
        });
    }
    let arr = obj.downcast::<PyArrayDyn<f64>>()?;
    let ro = arr.try_readonly()?;
    let v: Vec<f32> = ro.as_array().iter().map(|&v| v as f32).collect();
    Ok(quantize_into(frame, rows, cols, &v))
}

/// The label image (R, C) of `xyz` under `cfg` (ground removal `none`),
/// and what was lost.
pub fn labels<'py>(
    py: Python<'py>,
    xyz: &Bound<'py, PyAny>,
    cfg: &PipelineConfig,
) -> PyResult<(Bound<'py, PyAny>, Losses)> {
    // Shape and dtype checks (and their messages) are the common ones.
    crate::arrays::check_image(xyz)?;
    let shape = xyz.downcast::<PyUntypedArray>()?.shape().to_vec();
    let (rows, cols) = (shape[0], shape[1]);
    let params = fcc_params::FccParams {
        rows,
        cols,
        ..cfg.params.clone()
    };
    params.validate().map_err(crate::value_err)?;
    BUFFERS.with(|b| -> PyResult<(Bound<'py, PyAny>, Losses)> {
        let mut b = b.borrow_mut();
        let (ws, frame) = &mut *b;
        let out_of_range = fill(xyz, frame, rows, cols)?;
        let frame: &Frame = frame;
        let (labels, losses) = py
            .allow_threads(|| -> fcc_lidar::Result<(Vec<u32>, Losses)> {
                let c = cluster_with(ws, &params, frame, cfg.mode)?;
                let labels_needed = if c.overflow {
                    runs_needed(&params, frame)
                } else {
                    u64::from(c.provisional)
                };
                let losses = Losses {
                    overflow: c.overflow,
                    unlabelled: c.unlabelled,
                    points: c.points,
                    labels_needed,
                    out_of_range,
                };
                let labels = if cfg.min_points > 0 {
                    let l = filter_min_points(&c.labels, cfg.min_points).0;
                    ws.recycle(c);
                    l
                } else {
                    c.labels
                };
                Ok((labels, losses))
            })
            .map_err(lidar_err)?;
        Ok((array(py, labels, &[rows, cols])?.into_any(), losses))
    })
}

impl Losses {
    pub fn of(out: &fcc_lidar::pipeline::PipelineResult) -> Losses {
        Losses {
            overflow: out.clustering.overflow,
            unlabelled: out.clustering.unlabelled,
            points: out.clustering.points,
            labels_needed: out.labels_needed,
            out_of_range: out.out_of_range,
        }
    }

    /// The CLI's warnings on lost points, as `RuntimeWarning`s pointing
    /// `stacklevel` Python frames up (2: the caller of the package function).
    pub fn warn(
        &self,
        py: Python<'_>,
        params: &fcc_params::FccParams,
        stacklevel: i32,
    ) -> PyResult<()> {
        let warning = py.get_type::<pyo3::exceptions::PyRuntimeWarning>();
        if self.overflow {
            let msg = format!(
                "label overflow: {} of {} points left unlabelled; the frame needs {} provisional labels, label_bits={} has {}; use label_bits={}",
                self.unlabelled,
                self.points,
                self.labels_needed,
                params.label_bits,
                params.max_label(),
                fcc_params::FccParams::label_bits_for(self.labels_needed)
            );
            PyErr::warn(py, &warning, &std::ffi::CString::new(msg)?, stacklevel)?;
        }
        if self.out_of_range > 0 {
            let msg = format!(
                "{} points beyond the Q7.8 coordinate range (about \u{b1}128 m) were not clustered",
                self.out_of_range
            );
            PyErr::warn(py, &warning, &std::ffi::CString::new(msg)?, stacklevel)?;
        }
        Ok(())
    }
}
