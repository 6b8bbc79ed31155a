//! Python values in and out: real numbers, arrays of them, and errors.
//!
//! Arrays in are anything numpy turns into an array of real numbers (lists, tuples, numpy
//! arrays of any float or integer dtype, contiguous or not); they are copied into a `Vec<f64>`
//! in C order while attached to the interpreter, so the computation can then run detached
//! without another thread mutating the data under it. The exception is [`series`] (long
//! measured histories): a contiguous float64 array is read in place, as numpy's own functions
//! read their arguments with the GIL released. Arrays out are numpy arrays that take ownership
//! of the `Vec` (no copy).

use numpy::ndarray::{ArrayD, IxDyn};
use numpy::{
    IntoPyArray, PyArray1, PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyReadonlyArray1,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyMemoryError, PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyByteArray, PyBytes, PyFloat, PyString};

/// A `ValueError` carrying a core error's message (the same line the CLI prints).
pub fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The name of an object's type, for error messages.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "?".into())
}

fn is_text(obj: &Bound<'_, PyAny>) -> bool {
    obj.is_instance_of::<PyString>()
        || obj.is_instance_of::<PyBytes>()
        || obj.is_instance_of::<PyByteArray>()
}

/// A real-number argument: an `int`, a `float` or anything with `__float__` (numpy scalars),
/// but not a `bool` or a string (`TypeError`). An `int` too large for a float is a
/// `ValueError`.
pub fn real(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<f64> {
    if obj.is_instance_of::<PyBool>() || is_text(obj) {
        return Err(PyTypeError::new_err(format!(
            "{name} must be a real number, got {}",
            type_name(obj)
        )));
    }
    obj.extract::<f64>().map_err(|e| {
        if e.is_instance_of::<PyOverflowError>(obj.py()) {
            PyValueError::new_err(format!("{name} is too large to be a float: {e}"))
        } else {
            PyTypeError::new_err(format!(
                "{name} must be a real number, got {}",
                type_name(obj)
            ))
        }
    })
}

/// An optional real-number argument with a default.
pub fn real_or(obj: Option<&Bound<'_, PyAny>>, name: &str, default: f64) -> PyResult<f64> {
    match obj {
        Some(o) if !o.is_none() => real(o, name),
        _ => Ok(default),
    }
}

/// A non-negative integer argument (`int` or anything with `__index__`, not `bool`).
pub fn count(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<u64> {
    if obj.is_instance_of::<PyBool>() || obj.is_instance_of::<PyFloat>() || is_text(obj) {
        return Err(PyTypeError::new_err(format!(
            "{name} must be an integer, got {}",
            type_name(obj)
        )));
    }
    let v: i128 = obj.extract::<i128>().map_err(|e: PyErr| {
        if e.is_instance_of::<PyOverflowError>(obj.py()) {
            PyValueError::new_err(format!("{name} is too large, got {obj}"))
        } else {
            PyTypeError::new_err(format!("{name} must be an integer, got {}", type_name(obj)))
        }
    })?;
    if v < 0 {
        return Err(PyValueError::new_err(format!(
            "{name} must be >= 0, got {v}"
        )));
    }
    u64::try_from(v).map_err(|_| PyValueError::new_err(format!("{name} is too large, got {v}")))
}

/// Real numbers from an array-like, as float64 in C order, with the array's shape.
pub struct Floats {
    pub data: Vec<f64>,
    pub shape: Vec<usize>,
    /// Whether the argument was a numpy array (rather than a scalar or a Python sequence).
    pub was_array: bool,
}

impl Floats {
    /// The data of a one-dimensional argument (`TypeError` for a scalar, `ValueError` for
    /// more dimensions).
    pub fn one_dimensional(self, name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
        match self.shape.len() {
            1 => Ok(self.data),
            0 => Err(PyTypeError::new_err(format!(
                "{name} must be a sequence of real numbers, got {}",
                type_name(obj)
            ))),
            _ => Err(PyValueError::new_err(format!(
                "{name} must be one-dimensional, got an array of shape {:?}",
                self.shape
            ))),
        }
    }
}

/// Real numbers from any array-like `obj` (see the module docs). Strings, booleans, complex
/// numbers, `None` and other non-numbers are a `TypeError` naming the argument.
pub fn floats(obj: &Bound<'_, PyAny>, name: &str) -> PyResult<Floats> {
    let py = obj.py();
    let not_real = |what: String| {
        PyTypeError::new_err(format!(
            "{name} must be a real number or a sequence of real numbers, got {what}"
        ))
    };
    if is_text(obj) || obj.is_instance_of::<PyBool>() || obj.is_none() {
        return Err(not_real(type_name(obj)));
    }
    let was_array = obj.is_instance_of::<PyUntypedArray>();
    let np = py.import("numpy")?;
    let array = if was_array {
        obj.clone()
    } else {
        np.call_method1("asarray", (obj,)).map_err(|e| {
            not_real(format!(
                "{} that numpy cannot make an array of ({e})",
                type_name(obj)
            ))
        })?
    };
    let untyped = array.cast::<PyUntypedArray>()?;
    let shape = untyped.shape().to_vec();
    let dtype = untyped.dtype();
    let array = match dtype.kind() {
        b'f' | b'i' | b'u' => {
            if dtype.is_equiv_to(&numpy::dtype::<f64>(py)) && untyped.is_aligned() {
                array
            } else {
                // Other dtypes, byte orders and misaligned buffers: a native float64 copy.
                array.call_method1("astype", ("float64",))?
            }
        }
        b'O' => {
            // Python objects (mixed lists, Fraction, Decimal, ...): each must be a real
            // number; numpy's own cast would turn None into NaN.
            let mut data = try_vec(untyped.len())?;
            for item in array.call_method0("ravel")?.try_iter()? {
                data.push(real(&item?, &format!("each element of {name}"))?);
            }
            return Ok(Floats {
                data,
                shape,
                was_array,
            });
        }
        _ => return Err(not_real(format!("an array of {}", dtype_name(&array)))),
    };
    let typed = array.cast::<PyArrayDyn<f64>>()?;
    let view = typed
        .try_readonly()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    // `as_slice` also accepts Fortran order, which is not the logical (C) order.
    let data = match view.as_slice() {
        Ok(s) if typed.is_c_contiguous() => try_copy(s)?,
        _ => {
            let a = view.as_array();
            let mut v = try_vec(a.len())?;
            v.extend(a.iter().copied());
            v
        }
    };
    Ok(Floats {
        data,
        shape,
        was_array,
    })
}

/// A one-dimensional series of real numbers (see [`series`]).
pub enum Series<'py> {
    /// A contiguous, aligned, native float64 numpy array, read in place.
    Borrowed(PyReadonlyArray1<'py, f64>),
    /// Anything else, converted as [`floats`] does.
    Owned(Vec<f64>),
}

impl Series<'_> {
    pub fn as_slice(&self) -> &[f64] {
        match self {
            // `series` only borrows arrays whose slice exists.
            Series::Borrowed(a) => a.as_slice().unwrap_or(&[]),
            Series::Owned(v) => v,
        }
    }
}

/// A one-dimensional array-like argument of real numbers, as [`floats`] takes it, but without a
/// copy when it is a contiguous, aligned, native float64 numpy array: the array is then read
/// in place (borrowed read-only, so other Rust code cannot write it meanwhile; Python code
/// must not modify it during the call, as for numpy's own functions that release the GIL).
pub fn series<'py>(obj: &Bound<'py, PyAny>, name: &str) -> PyResult<Series<'py>> {
    if let Ok(a) = obj.cast::<PyArray1<f64>>() {
        // A misaligned buffer (as an array unpickled from a Dask worker can be) is copied:
        // reading it in place as `&[f64]` would be undefined behaviour.
        let aligned = a.cast::<PyUntypedArray>().is_ok_and(|u| u.is_aligned());
        if let Some(view) = aligned.then(|| a.try_readonly().ok()).flatten() {
            if view.as_slice().is_ok() {
                return Ok(Series::Borrowed(view));
            }
        }
    }
    Ok(Series::Owned(
        floats(obj, name)?.one_dimensional(name, obj)?,
    ))
}

fn dtype_name(array: &Bound<'_, PyAny>) -> String {
    array
        .getattr("dtype")
        .map(|d| d.to_string())
        .unwrap_or_else(|_| "?".into())
}

/// An empty vector with room for `n` elements, or a `MemoryError`.
pub fn try_vec<T>(n: usize) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| PyMemoryError::new_err(format!("cannot allocate an array of {n} elements")))?;
    Ok(v)
}

fn try_copy(s: &[f64]) -> PyResult<Vec<f64>> {
    let mut v = try_vec(s.len())?;
    v.extend_from_slice(s);
    Ok(v)
}

/// A float64 numpy array of the given shape that owns `data`.
pub fn array_out<'py>(
    py: Python<'py>,
    data: Vec<f64>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyAny>> {
    let a = ArrayD::from_shape_vec(IxDyn(shape), data)
        .map_err(|e| PyValueError::new_err(format!("internal shape error: {e}")))?;
    Ok(a.into_pyarray(py).into_any())
}

/// A one-dimensional float64 numpy array that owns `data`.
pub fn vec_out(py: Python<'_>, data: Vec<f64>) -> Bound<'_, PyAny> {
    data.into_pyarray(py).into_any()
}

/// `repr(float(v))`: the shortest string that reads back as `v`, as Python writes it.
pub fn float_repr(py: Python<'_>, v: f64) -> String {
    PyFloat::new(py, v)
        .repr()
        .map(|r| r.to_string())
        .unwrap_or_else(|_| format!("{v:?}"))
}

/// `[a, b, c]` with Python's float reprs, eliding the middle of long lists.
pub fn list_repr(py: Python<'_>, values: &[f64], max: usize) -> String {
    let items: Vec<String> = if values.len() <= max {
        values.iter().map(|&v| float_repr(py, v)).collect()
    } else {
        let head = max / 2;
        let tail = max - head - 1;
        values[..head]
            .iter()
            .map(|&v| float_repr(py, v))
            .chain(std::iter::once("...".to_string()))
            .chain(
                values[values.len() - tail..]
                    .iter()
                    .map(|&v| float_repr(py, v)),
            )
            .collect()
    };
    format!("[{}]", items.join(", "))
}

/// `f` applied elementwise to a number (returns a float) or an array-like (returns a float64
/// array of its shape), detached from the interpreter.
pub fn map_floats<'py>(
    obj: &Bound<'py, PyAny>,
    name: &str,
    f: impl Fn(f64) -> f64 + Send + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let py = obj.py();
    let x = floats(obj, name)?;
    if x.shape.is_empty() && !x.was_array {
        return Ok(PyFloat::new(py, f(x.data[0])).into_any());
    }
    let mut data = x.data;
    py.detach(|| data.iter_mut().for_each(|v| *v = f(*v)));
    array_out(py, data, &x.shape)
}

/// Real-number arguments by name (a helper for the bimodal corners).
pub fn reals<const N: usize>(
    values: [&Bound<'_, PyAny>; N],
    names: [&str; N],
) -> PyResult<[f64; N]> {
    let mut out = [0.0; N];
    for i in 0..N {
        out[i] = real(values[i], names[i])?;
    }
    Ok(out)
}
