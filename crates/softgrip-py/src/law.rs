//! [`Law`]: one level of softgrip-law's `ContactLaw` bound to a
//! fingertip's E, nu, R and construction, vectorised over numpy arrays of the compression,
//! picklable (its parameters are its state).

use pyo3::prelude::*;
use pyo3::types::PyTuple;
use softgrip_law::{ContactLaw, Level};

use crate::args;
use crate::array::Input;
use crate::errors::law_error;

/// A level of the contact law bound to one fingertip (SI units throughout).
///
/// Every method taking `delta` [m] (the compression, >= 0 in contact; x = delta / R) accepts
/// a number (returns a float) or an array-like of numbers (returns a float64 array of the
/// same shape). By default they are the law's hot path, as inside a rapier step: `delta <= 0`
/// is no contact (0), past `delta_max` the documented extension (a barrier at the wall) is used; as in numpy,
/// a NaN or infinite `delta` gives NaN (the law is defined for finite compressions). With
/// `checked=True` a negative, non-finite or past-`delta_max` value raises `ParameterError` /
/// `OutOfRangeError` naming `delta` instead. None or a string is an `ArgumentTypeError`.
/// Pickles as its parameters (`pickle`, `copy`, Ray, multiprocessing).
#[pyclass(module = "softgrip._native", name = "Law", frozen)]
pub struct Law {
    pub(crate) law: ContactLaw,
    /// Young's modulus E [Pa] as given (the law keeps E* = E / (1 - nu^2)).
    pub(crate) youngs_modulus: f64,
}

/// A NaN or infinite compression has no law value: NaN, as numpy gives for an undefined one
/// (the Rust hot path gives 0 there and counts it; Python users expect NaN to propagate).
fn finite_or_nan(delta: f64, f: impl Fn(f64) -> f64) -> f64 {
    if delta.is_finite() {
        f(delta)
    } else {
        f64::NAN
    }
}

/// The level's own setting (`k`, `tolerance`, `match_x`), if it has one.
pub(crate) fn setting(level: Level) -> Option<f64> {
    match level {
        Level::Fit { k } => Some(k),
        Level::Auto { tolerance } => Some(tolerance),
        Level::Linear { match_x } => Some(match_x),
        _ => None,
    }
}

impl Law {
    /// The parameters the law is rebuilt from: `(level, setting, E, nu, R, backing,
    /// thickness)`, each as `law()` takes it.
    fn state(
        &self,
    ) -> (
        &'static str,
        Option<f64>,
        f64,
        f64,
        f64,
        &'static str,
        Option<f64>,
    ) {
        let p = self.law.params();
        (
            self.law.level().name(),
            setting(self.law.level()),
            self.youngs_modulus,
            p.poisson_ratio(),
            p.radius(),
            p.backing().name(),
            p.backing().thickness(),
        )
    }

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
        checked: Option<&Bound<'py, PyAny>>,
        f: impl Fn(&ContactLaw, f64) -> f64 + Send + Sync,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = delta.py();
        let checked = args::opt_flag(checked, "checked")?;
        let input = Input::read(delta, "delta")?;
        if checked {
            self.check(py, &input)?;
        }
        let law = &self.law;
        input.map(py, |d| finite_or_nan(d, |d| f(law, d)))
    }
}

#[pymethods]
impl Law {
    /// Normal force F(delta) [N].
    #[pyo3(signature = (delta, *, checked = None))]
    fn force<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.response(d).force)
    }

    /// Stiffness K = dF/d delta [N/m], the exact derivative of `force`.
    #[pyo3(signature = (delta, *, checked = None))]
    fn stiffness<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.response(d).stiffness)
    }

    /// Stored elastic energy W = integral of F d delta [J].
    #[pyo3(signature = (delta, *, checked = None))]
    fn energy<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.energy(d))
    }

    /// Contact radius a(delta) [m].
    #[pyo3(signature = (delta, *, checked = None))]
    fn radius<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).radius)
    }

    /// Mean contact pressure F / (pi a^2) [Pa] (0 out of contact).
    #[pyo3(signature = (delta, *, checked = None))]
    fn mean_pressure<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).mean_pressure)
    }

    /// Peak (centre) contact pressure (m + 1)(m + 2)/(m + 2 + b) p_mean [Pa] ((m + 1) p_mean
    /// for b = 0).
    #[pyo3(signature = (delta, *, checked = None))]
    fn peak_pressure<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).peak_pressure)
    }

    /// Shape exponent m [-] of the pressure profile p(r) = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2)
    /// (1/2: Hertz), in [0, 2].
    #[pyo3(signature = (delta, *, checked = None))]
    fn pressure_shape<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).shape)
    }

    /// Taper b [-] of the pressure profile's factor (1 + b r^2/a^2), in [-1, 0]: 0 for a free
    /// sphere and a flat pad, < 0 for a skin over a core.
    #[pyo3(signature = (delta, *, checked = None))]
    fn pressure_taper<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        self.eval(delta, checked, |l, d| l.patch(d).taper)
    }

    /// Pressure p(r) [Pa] at distance `r` [m] from the contact's centre at compression
    /// `delta` [m]: `delta` is one number, `r` a number or an array-like (0 outside the patch).
    /// A NaN `r` gives NaN, an infinite one 0 (outside the patch); a NaN or infinite `delta`
    /// gives NaN everywhere.
    #[pyo3(signature = (delta, r, *, checked = None))]
    fn pressure<'py>(
        &self,
        delta: &Bound<'py, PyAny>,
        r: &Bound<'py, PyAny>,
        checked: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let py = r.py();
        let delta = args::float(delta, "delta")?;
        let checked = args::opt_flag(checked, "checked")?;
        let input = Input::read(r, "r")?;
        if checked {
            self.check(py, &Input::Scalar(delta))?;
        }
        let patch = self.law.patch(delta);
        input.map(py, |r| {
            if r.is_nan() || !delta.is_finite() {
                f64::NAN
            } else {
                patch.pressure_at(r)
            }
        })
    }

    /// 1.0 where 0 <= delta <= delta_max (inside the level's validity range), else 0.0; NaN
    /// for a NaN `delta`.
    fn valid<'py>(&self, delta: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let max = self.law.delta_max();
        let input = Input::read(delta, "delta")?;
        input.map(delta.py(), |d| {
            if d.is_nan() {
                f64::NAN
            } else {
                f64::from(u8::from((0.0..=max).contains(&d)))
            }
        })
    }

    /// Inverse: the compression delta [m] at which the law gives `force` [N] (in
    /// [0, force_max]); NaN for a NaN force; raises `ParameterError` naming `force` for a
    /// negative or infinite force and `OutOfRangeError` past `force_max`.
    fn delta_for_force<'py>(&self, force: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
        let py = force.py();
        let law = &self.law;
        let input = Input::read(force, "force")?;
        let inverse = |f: f64| {
            if f.is_nan() {
                Ok(f64::NAN)
            } else {
                law.compression_for_force(f)
            }
        };
        match input.try_map(py, inverse)? {
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

    /// Young's modulus E [Pa], as given.
    #[getter]
    fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson ratio nu [-].
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.law.params().poisson_ratio()
    }

    /// The level's setting: `k` of `fit`, `tolerance` of `auto`, `match_x` of `linear`, else
    /// None.
    #[getter]
    fn setting(&self) -> Option<f64> {
        setting(self.law.level())
    }

    /// Pickling: rebuilt by `law()` from its parameters (bit for bit the same law).
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let restore = py.import("softgrip._native")?.getattr("_law_from_state")?;
        Ok((restore, self.state().into_pyobject(py)?))
    }

    /// Two laws are equal when built from the same parameters.
    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<Law>()
            .is_ok_and(|o| o.get().state() == self.state())
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let (level, setting, e, nu, r, backing, t) = self.state();
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (level, setting.map(f64::to_bits), e.to_bits(), nu.to_bits()).hash(&mut h);
        (r.to_bits(), backing, t.map(f64::to_bits)).hash(&mut h);
        h.finish()
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
