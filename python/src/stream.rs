//! The golden stream (`fcc_golden::Stream`, spec §9): columns in, records
//! out as clusters close.

use crate::arrays::{array, floats};
use crate::model::{model_params, records_dict};
use crate::value_err;
use fcc_golden::{oriented_box, Frame, Record};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The golden stream (spec §9): push the C columns of a frame, (R, 3) each,
/// and get the records of the clusters as they close; `finish()` ends the
/// frame, `labels()` gives its label image. No ground removal: the columns
/// are clustered as given.
#[pyclass(module = "fcc._fcc")]
pub struct Stream {
    inner: fcc_golden::Stream,
}

fn golden_err(e: fcc_golden::GoldenError) -> PyErr {
    value_err(e)
}

impl Stream {
    /// The records of the last call, with their oriented boxes.
    fn closed<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let recs: Vec<(Record, _)> = self
            .inner
            .closed()
            .iter()
            .enumerate()
            .map(|(k, r)| (*r, oriented_box(self.inner.points_of(k))))
            .collect();
        records_dict(py, &recs)
    }
}

#[pymethods]
impl Stream {
    #[new]
    #[pyo3(signature = (rows, cols, *, fsize=None, th_h=None, th_v=None, label_bits=None,
        th_h_slope=None, th_v_slope=None, preset=None, bridge=None, ring_reach=None,
        open_limit=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        rows: usize,
        cols: usize,
        fsize: Option<usize>,
        th_h: Option<f64>,
        th_v: Option<f64>,
        label_bits: Option<u32>,
        th_h_slope: Option<f64>,
        th_v_slope: Option<f64>,
        preset: Option<&str>,
        bridge: Option<u32>,
        ring_reach: Option<u32>,
        open_limit: Option<u32>,
    ) -> PyResult<Self> {
        let p = fcc_params::FccParams {
            rows,
            cols,
            open_limit,
            ..model_params(
                fsize, th_h, th_v, label_bits, th_h_slope, th_v_slope, preset, bridge, ring_reach,
            )?
        };
        p.validate().map_err(value_err)?;
        Ok(Stream {
            inner: fcc_golden::Stream::new(&p).map_err(golden_err)?,
        })
    }

    #[getter]
    fn rows(&self) -> usize {
        self.inner.params().rows
    }

    #[getter]
    fn cols(&self) -> usize {
        self.inner.params().cols
    }

    /// Columns taken in the current frame.
    #[getter]
    fn columns_taken(&self) -> usize {
        self.inner.columns_taken()
    }

    /// Take the next column, an (R, 3) float array (row 0 first, NaN for no
    /// return); returns the records of the clusters that closed at it.
    fn push_column<'py>(
        &mut self,
        py: Python<'py>,
        column: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let rows = self.inner.params().rows;
        let (v, _) = floats(
            column,
            "column",
            &[Some(rows), Some(3)],
            &format!("({rows}, 3)"),
        )?;
        let col = Frame::from_xyz_f32(rows, 1, &v);
        self.inner.push_column(&col.points).map_err(golden_err)?;
        self.closed(py)
    }

    /// End the frame after its C columns; returns the records of every
    /// cluster still open.
    fn finish<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.inner.finish().map_err(golden_err)?;
        self.closed(py)
    }

    /// The finished frame's label image (R, C) uint32, numbered by record id.
    fn labels<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let mut out = Vec::new();
        self.inner.labels_into(&mut out).map_err(golden_err)?;
        let p = self.inner.params();
        let shape = [p.rows, p.cols];
        Ok(array(py, out, &shape)?.into_any())
    }

    /// The frame's counts (`fcc_golden::StreamStats`, every field): points,
    /// runs, clusters, overflow, open_refused, unlabelled, peak_labels,
    /// peak_open, peak_counted, merges, peak_col_merges, peak_col_closed,
    /// peak_col_freed.
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let fcc_golden::StreamStats {
            points,
            runs,
            clusters,
            overflow,
            open_refused,
            unlabelled,
            peak_labels,
            peak_open,
            peak_counted,
            merges,
            peak_col_merges,
            peak_col_closed,
            peak_col_freed,
        } = self.inner.stats();
        let d = PyDict::new(py);
        d.set_item("points", points)?;
        d.set_item("runs", runs)?;
        d.set_item("clusters", clusters)?;
        d.set_item("overflow", overflow)?;
        d.set_item("open_refused", open_refused)?;
        d.set_item("unlabelled", unlabelled)?;
        d.set_item("peak_labels", peak_labels)?;
        d.set_item("peak_open", peak_open)?;
        d.set_item("peak_counted", peak_counted)?;
        d.set_item("merges", merges)?;
        d.set_item("peak_col_merges", peak_col_merges)?;
        d.set_item("peak_col_closed", peak_col_closed)?;
        d.set_item("peak_col_freed", peak_col_freed)?;
        Ok(d)
    }
}
