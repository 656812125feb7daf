//! `softgrip.fit_material(delta, force, radius, poisson_ratio, x_fit=0.1, level="hertz")`:
//! softgrip-law's `fitting::fit_material` on a squeeze's (delta, F) samples.

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use softgrip_law::fitting::{Sample, fit_material as fit};

use crate::args;
use crate::array::Input;
use crate::errors::{law_error, parameter};
use crate::make_law::Settings;

/// The paper's largest x of the fit (Hertz's range).
const DEFAULT_X_FIT: f64 = 0.1;

/// Fits E* (so E, with the given nu) by least squares of `F = E* R^2 f_level(delta / R)` on the
/// samples with `x = delta / R <= x_fit`, and reports each level's relative errors on the
/// samples past `x_fit`. Returns a dict (see the package's `MaterialFit`).
///
/// NaN samples are refused (`ParameterError` naming `samples`): a fit has no NaN answer.
#[pyfunction]
#[pyo3(signature = (delta, force, radius, poisson_ratio, x_fit = None, level = None, *, k = None, tolerance = None, match_x = None))]
#[allow(clippy::too_many_arguments)]
pub fn fit_material<'py>(
    py: Python<'py>,
    delta: &Bound<'py, PyAny>,
    force: &Bound<'py, PyAny>,
    radius: &Bound<'py, PyAny>,
    poisson_ratio: &Bound<'py, PyAny>,
    x_fit: Option<&Bound<'py, PyAny>>,
    level: Option<&Bound<'py, PyAny>>,
    k: Option<&Bound<'py, PyAny>>,
    tolerance: Option<&Bound<'py, PyAny>>,
    match_x: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let settings = Settings::read(k, tolerance, match_x)?;
    let hertz = PyString::new(py, "hertz").into_any();
    let level = level.filter(|l| !l.is_none()).unwrap_or(&hertz);
    let fit_level = crate::make_law::level(level, &settings)?;
    let radius = args::float(radius, "radius")?;
    let poisson_ratio = args::float(poisson_ratio, "poisson_ratio")?;
    let x_fit = args::opt_float(x_fit, "x_fit")?.unwrap_or(DEFAULT_X_FIT);
    let d = Input::read(delta, "delta")?;
    let f = Input::read(force, "force")?;
    let (d, f) = (d.values(), f.values());
    if d.len() != f.len() {
        return Err(parameter(
            py,
            "force",
            format!("{} samples", f.len()),
            &format!("as many samples as `delta` ({})", d.len()),
        ));
    }
    let samples: Vec<Sample> = (d.iter().zip(f))
        .map(|(&delta, &force)| Sample { delta, force })
        .collect();
    let result = py
        .detach(|| fit(&samples, radius, poisson_ratio, x_fit, fit_level))
        .map_err(|e| law_error(py, &e))?;
    let out = PyDict::new(py);
    let m = result.material;
    out.set_item("youngs_modulus", m.youngs_modulus())?;
    out.set_item("effective_modulus", m.effective_modulus())?;
    out.set_item("poisson_ratio", m.poisson_ratio())?;
    out.set_item("fitted", result.fitted)?;
    out.set_item("predicted", result.predicted.into_pyarray(py))?;
    let residuals = PyDict::new(py);
    for r in result.residuals {
        let e = PyDict::new(py);
        let errors: Vec<f64> = (r.relative_errors.iter())
            .map(|e| e.unwrap_or(f64::NAN))
            .collect();
        e.set_item("relative_errors", errors.into_pyarray(py))?;
        e.set_item("max_abs_error", r.max_abs_error)?;
        e.set_item("rms_error", r.rms_error)?;
        residuals.set_item(r.level.name(), e)?;
    }
    out.set_item("residuals", residuals)?;
    Ok(out)
}
