//! Vectorising a function of one (or two) numbers over numpy float64 arrays: a Python number
//! gives a Python float, anything array-like (a numpy array of any shape and numeric dtype, a
//! list) gives a new float64 array of its shape. The loop runs without the GIL.

use numpy::ndarray::{ArrayD, IxDyn};
use numpy::{AllowTypeChange, IntoPyArray, PyArrayLikeDyn, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyFloat, PyInt, PyList, PyString, PyTuple};

use crate::args::type_error;

/// The input: one number, or an array's values (row-major) and shape.
pub enum Input {
    /// A Python number (or a numpy scalar).
    Scalar(f64),
    /// An array-like's values as float64, and its shape.
    Array(Vec<f64>, Vec<usize>),
}

impl Input {
    /// Reads `value`: a number (a Python int, float or bool, a numpy scalar, anything with
    /// `__float__`) or an array-like whose numpy dtype is bool, integer or floating. None, a
    /// string, bytes, or an array of objects, strings or complex numbers is an
    /// `ArgumentTypeError` (a `TypeError`) naming `field`, as numpy's ufuncs refuse them.
    pub fn read(value: &Bound<'_, PyAny>, field: &str) -> PyResult<Self> {
        let expected = "a number or an array-like of numbers";
        let text = value.is_instance_of::<PyString>() || value.is_instance_of::<PyBytes>();
        if value.is_none() || text {
            return Err(type_error(value, field, expected));
        }
        let is_array = value.cast::<PyUntypedArray>().is_ok();
        if !is_array && (value.is_instance_of::<PyFloat>() || value.is_instance_of::<PyInt>()) {
            return Ok(Input::Scalar(value.extract()?));
        }
        if !is_array
            && !value.is_instance_of::<PyList>()
            && !value.is_instance_of::<PyTuple>()
            && let Ok(v) = value.extract::<f64>()
        {
            return Ok(Input::Scalar(v));
        }
        // Lists, tuples, arrays: numpy decides the dtype, which must be numeric.
        let py = value.py();
        let array = py
            .import("numpy")?
            .call_method1("asarray", (value,))
            .map_err(|_| type_error(value, field, expected))?;
        let kind: String = array.getattr("dtype")?.getattr("kind")?.extract()?;
        if !matches!(kind.as_str(), "b" | "i" | "u" | "f") {
            return Err(type_error(value, field, expected));
        }
        let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = array
            .extract()
            .map_err(|_| type_error(value, field, expected))?;
        let shape = array.shape().to_vec();
        let values = array.as_array().iter().copied().collect();
        Ok(Input::Array(values, shape))
    }

    /// The values (one for a scalar).
    pub fn values(&self) -> &[f64] {
        match self {
            Input::Scalar(v) => std::slice::from_ref(v),
            Input::Array(v, _) => v,
        }
    }

    /// `out` (one value per input value) as a float, or an array of the input's shape.
    pub fn output<'py>(&self, py: Python<'py>, out: Vec<f64>) -> PyResult<Bound<'py, PyAny>> {
        match self {
            Input::Scalar(_) => Ok(PyFloat::new(py, out[0]).into_any()),
            Input::Array(_, shape) => {
                let a = ArrayD::from_shape_vec(IxDyn(shape), out)
                    .expect("invariant: one output per input value");
                Ok(a.into_pyarray(py).into_any())
            }
        }
    }

    /// `f` at every value, without the GIL; a float or an array of the input's shape.
    pub fn map<'py>(
        &self,
        py: Python<'py>,
        f: impl Fn(f64) -> f64 + Send + Sync,
    ) -> PyResult<Bound<'py, PyAny>> {
        let values = self.values();
        let out: Vec<f64> = py.detach(|| values.iter().map(|&v| f(v)).collect());
        self.output(py, out)
    }

    /// Like [`map`](Self::map), but `f` may fail on a value (with the value's flat index).
    pub fn try_map<'py, E: Send>(
        &self,
        py: Python<'py>,
        f: impl Fn(f64) -> Result<f64, E> + Send + Sync,
    ) -> PyResult<Result<Bound<'py, PyAny>, (usize, E)>> {
        let values = self.values();
        let out: Result<Vec<f64>, (usize, E)> = py.detach(|| {
            values
                .iter()
                .enumerate()
                .map(|(i, &v)| f(v).map_err(|e| (i, e)))
                .collect()
        });
        match out {
            Ok(out) => Ok(Ok(self.output(py, out)?)),
            Err(e) => Ok(Err(e)),
        }
    }
}
