//! A Python argument as the Rust value it stands for, or softgrip's own exception naming the
//! argument: `ArgumentTypeError` (a `TypeError`) for the wrong type (None, a string where a
//! number goes, a float where an integer goes), `ParameterError` (a `ValueError`) for an
//! integer out of its range. pyo3's own conversions raise plain `TypeError` /
//! `OverflowError` without the field, so every user-facing argument comes in as `PyAny` and is
//! read here.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyInt, PyString};

use crate::errors::raise;

/// `repr(value)`, or `?` if it has none.
pub fn repr(value: &Bound<'_, PyAny>) -> String {
    value
        .repr()
        .map_or_else(|_| "?".to_owned(), |r| r.to_string())
}

/// The type's name (`NoneType`, `str`, ...).
fn type_name(value: &Bound<'_, PyAny>) -> String {
    value
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string())
}

/// `ArgumentTypeError`: `field` must be `expected`, got `value` of its type.
pub fn type_error(value: &Bound<'_, PyAny>, field: &str, expected: &str) -> PyErr {
    let shown = repr(value);
    raise(
        value.py(),
        "ArgumentTypeError",
        format!(
            "`{field}` must be {expected}, got {shown} ({})",
            type_name(value)
        ),
        Some(field),
        Some(shown),
    )
}

/// A real number: a Python int or float, a numpy integer or floating scalar, or anything with
/// `__float__` except a string, bytes or None. NaN and infinities pass (the callee's range
/// check names them).
pub fn float(value: &Bound<'_, PyAny>, field: &str) -> PyResult<f64> {
    let text = value.is_instance_of::<PyString>() || value.is_instance_of::<PyBytes>();
    if value.is_none() || text {
        return Err(type_error(value, field, "a real number"));
    }
    value
        .extract::<f64>()
        .map_err(|_| type_error(value, field, "a real number"))
}

/// [`float`], or None.
pub fn opt_float(value: Option<&Bound<'_, PyAny>>, field: &str) -> PyResult<Option<f64>> {
    match value {
        Some(v) if !v.is_none() => float(v, field).map(Some),
        _ => Ok(None),
    }
}

/// An integer (a Python int or a numpy integer, not a bool and not a float) as i128, so that
/// a negative or huge value reaches the caller's range check instead of an `OverflowError`.
pub fn integer(value: &Bound<'_, PyAny>, field: &str) -> PyResult<i128> {
    let expected = "an integer";
    if value.is_instance_of::<PyBool>() {
        return Err(type_error(value, field, expected));
    }
    let int = if value.is_instance_of::<PyInt>() {
        value.clone()
    } else {
        // numpy integers and other `__index__` types (never floats: they have no `__index__`).
        let index = value.py().import("operator")?.getattr("index")?;
        index
            .call1((value,))
            .map_err(|_| type_error(value, field, expected))?
    };
    match int.extract::<i128>() {
        Ok(v) => Ok(v),
        // Past i128: as far out of any range as i128::MAX (the caller's message shows it).
        Err(_) => {
            let negative = int.lt(0i64)?;
            Ok(if negative { i128::MIN } else { i128::MAX })
        }
    }
}

/// [`integer`] in `range` as u64, else `class` (`ParameterError`, `TrialIndexError`, ...)
/// naming `field` with `expected`.
pub fn bounded(
    value: &Bound<'_, PyAny>,
    field: &str,
    range: std::ops::RangeInclusive<u64>,
    class: &str,
    expected: &str,
) -> PyResult<u64> {
    let v = integer(value, field)?;
    match u64::try_from(v) {
        Ok(u) if range.contains(&u) => Ok(u),
        _ => {
            let shown = repr(value);
            Err(raise(
                value.py(),
                class,
                format!("`{field}` must be {expected}, got {shown}"),
                Some(field),
                Some(shown),
            ))
        }
    }
}

/// A bool (Python's, or numpy's `bool_`); an int or a string is an `ArgumentTypeError`.
pub fn flag(value: &Bound<'_, PyAny>, field: &str) -> PyResult<bool> {
    let numpy_bool = value.py().import("numpy")?.getattr("bool_")?;
    if value.is_instance_of::<PyBool>() || value.is_instance(&numpy_bool)? {
        return value
            .is_truthy()
            .map_err(|_| type_error(value, field, "True or False"));
    }
    Err(type_error(value, field, "True or False"))
}

/// A string.
pub fn text(value: &Bound<'_, PyAny>, field: &str, expected: &str) -> PyResult<String> {
    if !value.is_instance_of::<PyString>() {
        return Err(type_error(value, field, expected));
    }
    value.extract()
}

/// A filesystem path: a str or an `os.PathLike` (`pathlib.Path`), as `os.fspath` takes it.
pub fn path(value: &Bound<'_, PyAny>, field: &str) -> PyResult<PathBuf> {
    let expected = "a path (str or os.PathLike)";
    if value.is_instance_of::<PyBytes>() || value.is_none() {
        return Err(type_error(value, field, expected));
    }
    let fspath = value.py().import("os")?.getattr("fspath")?;
    let s = fspath
        .call1((value,))
        .map_err(|_| type_error(value, field, expected))?;
    if !s.is_instance_of::<PyString>() {
        return Err(type_error(value, field, expected));
    }
    s.extract()
}

/// [`path`], or None.
pub fn opt_path(value: Option<&Bound<'_, PyAny>>, field: &str) -> PyResult<Option<PathBuf>> {
    match value {
        Some(v) if !v.is_none() => path(v, field).map(Some),
        _ => Ok(None),
    }
}

/// [`flag`], or False when not given (None).
pub fn opt_flag(value: Option<&Bound<'_, PyAny>>, field: &str) -> PyResult<bool> {
    match value {
        Some(v) if !v.is_none() => flag(v, field),
        _ => Ok(false),
    }
}
