//! `softgrip.law(...)` -> [`Law`]: one level of softgrip-law's `ContactLaw` bound to a
//! fingertip's E, nu, R and construction, vectorised over numpy arrays of the compression.

use pyo3::prelude::*;
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};

use crate::array::Input;
use crate::errors::{law_error, parameter};

/// A level of the contact law bound to one fingertip (SI units throughout).
///
/// Every method taking `delta` [m] (the compression, >= 0 in contact; x = delta / R) accepts
/// a number (returns a float) or an array-like of numbers (returns a float64 array of the
/// same shape). By default they are the law's hot path, as inside a rapier step: `delta <= 0`
/// is no contact (0), past `delta_max` the documented tangent extension is used, NaN gives 0.
/// With `checked=True` a negative, non-finite or past-`delta_max` value raises
/// `ParameterError` / `OutOfRangeError` naming `delta` instead.
#[pyclass(module = "softgrip._native", name = "Law", frozen)]
pub struct Law {
    law: ContactLaw,
}

impl Law {
    fn check(&self, py: Python<'_>, input: &Input) -> PyResult<()> {
        let law = &self.law;
        let bad = py.detach(|| {
            input
                .values()
                .iter()
                .enumerate()
                .find_map(|(i, &d)| law.evaluate(d).err().map(|e| (i, e)))
        });
        match bad {
            None => Ok(()),
            Some((i, e)) => {
                let err = law_error(py, &e);
                if let Input::Array(..) = input {
                    let v = err.value(py);
                    let note = format!("{v} (at flat index {i} of `delta`)");
                    v.setattr("args", (note,))?;
                }
                Err(err)
            }
        }
    }

    fn eval<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
        f: impl Fn(&ContactLaw, f64) -> f64 + Send + Sync,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = delta.py();
        let input = Input::read(delta, "delta")?;
        if checked {
            self.check(py, &input)?;
        }
        let law = &self.law;
        input.map(py, |d| f(law, d))
    }
}

#[pymethods]
impl Law {
    /// Normal force F(delta) [N].
    #[pyo3(signature = (delta, *, checked = false))]
    fn force<'py>(&self, delta: &Bound<'py, PyAny>, checked: bool) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.response(d).force)
    }

    /// Stiffness K = dF/d delta [N/m], the exact derivative of `force`.
    #[pyo3(signature = (delta, *, checked = false))]
    fn stiffness<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.response(d).stiffness)
    }

    /// Stored elastic energy W = integral of F d delta [J].
    #[pyo3(signature = (delta, *, checked = false))]
    fn energy<'py>(&self, delta: &Bound<'py, PyAny>, checked: bool) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.energy(d))
    }

    /// Contact radius a(delta) [m].
    #[pyo3(signature = (delta, *, checked = false))]
    fn radius<'py>(&self, delta: &Bound<'py, PyAny>, checked: bool) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).radius)
    }

    /// Mean contact pressure F / (pi a^2) [Pa] (0 out of contact).
    #[pyo3(signature = (delta, *, checked = false))]
    fn mean_pressure<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).mean_pressure)
    }

    /// Peak (centre) contact pressure (m + 1)(m + 2)/(m + 2 + b) p_mean [Pa] ((m + 1) p_mean
    /// for b = 0).
    #[pyo3(signature = (delta, *, checked = false))]
    fn peak_pressure<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).peak_pressure)
    }

    /// Shape exponent m [-] of the pressure profile p(r) = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2)
    /// (1/2: Hertz), in [0, 2].
    #[pyo3(signature = (delta, *, checked = false))]
    fn pressure_shape<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).shape)
    }

    /// Taper b [-] of the pressure profile's factor (1 + b r^2/a^2), in [-1, 0]: 0 for a free
    /// sphere and a flat pad, < 0 for a skin over a core.
    #[pyo3(signature = (delta, *, checked = false))]
    fn pressure_taper<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).taper)
    }

    /// Pressure p(r) [Pa] at distance `r` [m] from the contact's centre at compression
    /// `delta` [m]: `delta` is one number, `r` a number or an array-like (0 outside the patch).
    #[pyo3(signature = (delta, r, *, checked = false))]
    fn pressure<'py>(
        &self,
        delta: f64,
        r: &Bound<'py, PyAny>,
        checked: bool,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = r.py();
        if checked {
            self.check(py, &Input::Scalar(delta))?;
        }
        let patch = self.law.patch(delta);
        Input::read(r, "r")?.map(py, |r| patch.pressure_at(r))
    }

    /// 1.0 where 0 <= delta <= delta_max (inside the level's validity range), else 0.0.
    fn valid<'py>(&self, delta: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let max = self.law.delta_max();
        let input = Input::read(delta, "delta")?;
        input.map(delta.py(), |d| {
            f64::from(u8::from((0.0..=max).contains(&d)))
        })
    }

    /// Inverse: the compression delta [m] at which the law gives `force` [N] (finite, in
    /// [0, force_max]); raises `OutOfRangeError` naming `force` otherwise.
    fn delta_for_force<'py>(&self, force: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = force.py();
        let law = &self.law;
        let input = Input::read(force, "force")?;
        match input.try_map(py, |f| law.compression_for_force(f))? {
            Ok(out) => Ok(out),
            Err((i, e)) => {
                let err = law_error(py, &e);
                if let Input::Array(..) = input {
                    let v = err.value(py);
                    v.setattr("args", (format!("{v} (at flat index {i} of `force`)"),))?;
                }
                Err(err)
            }
        }
    }

    /// Largest compression ratio of the validity range, x_max [-].
    #[getter]
    fn x_max(&self) -> f64 {
        self.law.x_max()
    }

    /// Largest compression of the validity range, x_max R [m].
    #[getter]
    fn delta_max(&self) -> f64 {
        self.law.delta_max()
    }

    /// Force at delta_max [N].
    #[getter]
    fn force_max(&self) -> f64 {
        self.law.force_max()
    }

    /// The level's name (`calibrated`, `auto`, ...).
    #[getter]
    fn level(&self) -> &'static str {
        self.law.level().name()
    }

    /// The construction: `free`, `flat` or `core`.
    #[getter]
    fn backing(&self) -> &'static str {
        self.law.params().backing().name()
    }

    /// Skin thickness t [m] of a `core` fingertip, else None.
    #[getter]
    fn thickness(&self) -> Option<f64> {
        self.law.params().backing().thickness()
    }

    /// Outer radius R of the fingertip [m].
    #[getter]
    fn tip_radius(&self) -> f64 {
        self.law.params().radius()
    }

    /// Effective modulus E* = E / (1 - nu^2) [Pa].
    #[getter]
    fn effective_modulus(&self) -> f64 {
        self.law.params().effective_modulus()
    }

    /// Young's modulus E [Pa].
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        let p = self.law.params();
        p.effective_modulus() * (1.0 - p.poisson_ratio().powi(2))
    }

    /// Poisson ratio nu [-].
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.law.params().poisson_ratio()
    }

    fn __repr__(&self) -> String {
        let p = self.law.params();
        format!(
            "Law(level={:?}, effective_modulus={:e} Pa, poisson_ratio={}, radius={} m, backing={})",
            self.law.level().name(),
            p.effective_modulus(),
            p.poisson_ratio(),
            p.radius(),
            p.backing()
        )
    }
}

/// The level `name` with its optional settings (each only for the level that takes it).
pub fn level(
    py: Python<'_>,
    name: &str,
    k: Option<f64>,
    tolerance: Option<f64>,
    match_x: Option<f64>,
) -> PyResult<Level> {
    let mut level: Level = name.parse().map_err(|e: String| {
        crate::errors::raise(py, "ParameterError", e, Some("level"), Some(name.into()))
    })?;
    let only = |field: &str, value: f64, level: &str| {
        parameter(
            py,
            field,
            value,
            &format!("given only with level \"{level}\""),
        )
    };
    if let Some(k) = k {
        match level {
            Level::Fit { .. } => level = Level::Fit { k },
            _ => return Err(only("k", k, "fit")),
        }
    }
    if let Some(tolerance) = tolerance {
        match level {
            Level::Auto { .. } => level = Level::Auto { tolerance },
            _ => return Err(only("tolerance", tolerance, "auto")),
        }
    }
    if let Some(match_x) = match_x {
        match level {
            Level::Linear { .. } => level = Level::Linear { match_x },
            _ => return Err(only("match_x", match_x, "linear")),
        }
    }
    Ok(level)
}

/// The construction `name` (`free`, `flat`, `core`) with the core's skin thickness [m].
pub fn backing(py: Python<'_>, name: &str, thickness: Option<f64>) -> PyResult<Backing> {
    match (name, thickness) {
        ("core", Some(t)) => Ok(Backing::Core { thickness: t }),
        ("core", None) => Err(crate::errors::raise(
            py,
            "ParameterError",
            "`thickness` must be given for backing \"core\" (the skin thickness t in (0, R) m), got None",
            Some("thickness"),
            None,
        )),
        ("free" | "flat", Some(t)) => Err(parameter(
            py,
            "thickness",
            t,
            &format!("None for backing \"{name}\" (only \"core\" has a skin thickness)"),
        )),
        (name, _) => name.parse().map_err(|e: String| {
            crate::errors::raise(py, "ParameterError", e, Some("backing"), Some(name.into()))
        }),
    }
}

/// `softgrip.law(level, youngs_modulus, poisson_ratio, radius, backing="free",
/// thickness=None, *, k=None, tolerance=None, match_x=None)`.
#[pyfunction]
#[pyo3(signature = (level, youngs_modulus, poisson_ratio, radius, backing = "free", thickness = None, *, k = None, tolerance = None, match_x = None))]
#[allow(clippy::too_many_arguments)]
pub fn law(
    py: Python<'_>,
    level: &str,
    youngs_modulus: f64,
    poisson_ratio: f64,
    radius: f64,
    backing: &str,
    thickness: Option<f64>,
    k: Option<f64>,
    tolerance: Option<f64>,
    match_x: Option<f64>,
) -> PyResult<Law> {
    let level = self::level(py, level, k, tolerance, match_x)?;
    let backing = self::backing(py, backing, thickness)?;
    let e = |e: softgrip_law::Error| law_error(py, &e);
    let material = Material::try_new(youngs_modulus, poisson_ratio).map_err(e)?;
    let params = ContactParams::try_new(material, radius)
        .and_then(|p| p.with_backing(backing))
        .map_err(e)?;
    let law = ContactLaw::try_new(params, level).map_err(e)?;
    Ok(Law { law })
}
