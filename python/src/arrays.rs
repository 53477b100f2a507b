//! numpy arrays in and out. Inputs are checked for shape and dtype before a
//! single value is read; strided (non-contiguous) arrays are read through
//! their strides, never as if they were contiguous.

use numpy::ndarray::{ArrayViewD, IxDyn};
use numpy::{
    Element, PyArray1, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// The values of a float32 or float64 array of `expected` shape (`None`
/// matches any size), in C order, as f32 (float64 rounded as the `.npy`
/// reader rounds it). Returns the values and the shape.
pub fn floats(
    obj: &Bound<'_, PyAny>,
    what: &str,
    expected: &[Option<usize>],
    shape_text: &str,
) -> PyResult<(Vec<f32>, Vec<usize>)> {
    let arr = untyped(obj, what, shape_text)?;
    let shape = check_shape(&arr, what, expected, shape_text)?;
    let values = if float_kind(&arr, what)? {
        read::<f32, _>(obj, |v| v)?
    } else {
        read::<f64, _>(obj, |v| v as f32)?
    };
    Ok((values, shape))
}

/// Check an (R, C, 3) float32 or float64 range image `xyz` without reading it.
pub fn check_image(obj: &Bound<'_, PyAny>) -> PyResult<()> {
    let shape_text = "(R, C, 3)";
    let arr = untyped(obj, "xyz", shape_text)?;
    check_shape(&arr, "xyz", &[None, None, Some(3)], shape_text)?;
    float_kind(&arr, "xyz").map(|_| ())
}

/// Whether the array holds float32 (true) or float64 (false) values.
fn float_kind(arr: &Bound<'_, PyUntypedArray>, what: &str) -> PyResult<bool> {
    let dtype = arr.dtype();
    let py = arr.py();
    if dtype.is_equiv_to(&numpy::dtype::<f32>(py)) {
        Ok(true)
    } else if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) {
        Ok(false)
    } else {
        Err(PyTypeError::new_err(format!(
            "{what}: expected float32 or float64 values, got {dtype}; convert with .astype(numpy.float32)"
        )))
    }
}

/// The values of a uint32 array of `expected` shape, in C order.
pub fn labels(
    obj: &Bound<'_, PyAny>,
    what: &str,
    expected: &[Option<usize>],
    shape_text: &str,
) -> PyResult<(Vec<u32>, Vec<usize>)> {
    let arr = untyped(obj, what, shape_text)?;
    let shape = check_shape(&arr, what, expected, shape_text)?;
    let dtype = arr.dtype();
    if !dtype.is_equiv_to(&numpy::dtype::<u32>(obj.py())) {
        return Err(PyTypeError::new_err(format!(
            "{what}: expected uint32 labels, got {dtype}"
        )));
    }
    Ok((read::<u32, _>(obj, |v| v)?, shape))
}

fn untyped<'py>(
    obj: &Bound<'py, PyAny>,
    what: &str,
    shape_text: &str,
) -> PyResult<Bound<'py, PyUntypedArray>> {
    obj.downcast::<PyUntypedArray>().cloned().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what}: expected a numpy array of shape {shape_text}, got {}",
            obj.get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_else(|_| "an object".into())
        ))
    })
}

fn check_shape(
    arr: &Bound<'_, PyUntypedArray>,
    what: &str,
    expected: &[Option<usize>],
    shape_text: &str,
) -> PyResult<Vec<usize>> {
    let shape = arr.shape().to_vec();
    let fits = shape.len() == expected.len()
        && shape
            .iter()
            .zip(expected)
            .all(|(&n, e)| !matches!(e, Some(e) if *e != n));
    if !fits {
        let got: Vec<String> = shape.iter().map(usize::to_string).collect();
        return Err(PyValueError::new_err(format!(
            "{what}: expected shape {shape_text}, got ({}{})",
            got.join(", "),
            if got.len() == 1 { "," } else { "" }
        )));
    }
    Ok(shape)
}

/// Copy out the values: one memcpy for a C-contiguous array, a walk through
/// the strides otherwise.
fn read<T: Element + Copy, U>(obj: &Bound<'_, PyAny>, f: impl Fn(T) -> U) -> PyResult<Vec<U>> {
    let arr = obj.downcast::<PyArrayDyn<T>>()?;
    let ro = arr.try_readonly()?;
    let view: ArrayViewD<'_, T> = ro.as_array();
    Ok(match view.as_slice() {
        Some(s) => s.iter().map(|&v| f(v)).collect(),
        None => view.iter().map(|&v| f(v)).collect(),
    })
}

/// A flat vector as a numpy array of `shape` (the vector becomes the
/// array's buffer, no copy).
pub fn array<'py, T: Element>(
    py: Python<'py>,
    v: Vec<T>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<T>>> {
    PyArray1::from_vec(py, v).reshape(IxDyn(shape))
}
