//! The Rust errors as the package's Python exceptions (defined in `softgrip/errors.py`, all
//! subclasses of `SoftgripError` and of the built-in a Python user catches):
//! `ParameterError` (a `ValueError`) and its `OutOfRangeError` for the law,
//! `ArgumentTypeError` (a `TypeError`, raised by `args`), `SceneError` for scenes,
//! `SweepError` and `TrialIndexError` (an `IndexError`) for sweeps, `RecordingError` and its
//! `RecordingExistsError` / `RecordingFormatError` for MCAP files, `SimulationDiverged` (an
//! `ArithmeticError`) for a run stopped by a step error. Each carries the Rust
//! error's message and, where the error names one, the field (`.field`) and the value
//! (`.value`).

use pyo3::prelude::*;
use softgrip_ecs::SceneError;
use softgrip_ecs::softgrip_rapier::{Phase, StepError, Subject};
use softgrip_sweep::SweepError;

/// A `softgrip.errors.<class>` exception with `message`, `.field` and `.value` set.
pub fn raise(
    py: Python<'_>,
    class: &str,
    message: impl Into<String>,
    field: Option<&str>,
    value: Option<String>,
) -> PyErr {
    let message = message.into();
    let make = || -> PyResult<PyErr> {
        let cls = py.import("softgrip.errors")?.getattr(class)?;
        let exc = cls.call1((message.clone(),))?;
        exc.setattr("field", field)?;
        exc.setattr("value", value.clone())?;
        Ok(PyErr::from_value(exc))
    };
    // The package is always importable when the extension is (it is `softgrip._native`): a
    // failure here is an installation problem, reported with the original message.
    make().unwrap_or_else(|e| {
        pyo3::exceptions::PyRuntimeError::new_err(format!("{message} (and raising it: {e})"))
    })
}

/// The law's error: `ParameterError` naming the field, `OutOfRangeError` for a compression or
/// a force past the level's validity range.
pub fn law_error(py: Python<'_>, e: &softgrip_law::Error) -> PyErr {
    use softgrip_law::Error as E;
    let message = e.to_string();
    let (class, field, value) = match e {
        E::InvalidParameter { field, value, .. } => {
            ("ParameterError", *field, Some(value.to_string()))
        }
        E::IncompatibleLevel { nu, .. } => ("ParameterError", "level", Some(nu.to_string())),
        E::IncompatibleBacking { .. } => ("ParameterError", "backing", None),
        E::IncompatibleCounterpart {
            field,
            relative_curvature,
            ..
        } => (
            "ParameterError",
            *field,
            Some(relative_curvature.to_string()),
        ),
        E::OutOfRange { x, .. } => ("OutOfRangeError", "delta", Some(x.to_string())),
        E::ForceOutOfRange { force, .. } => ("OutOfRangeError", "force", Some(force.to_string())),
        E::InvalidTable { field, value, .. } => ("ParameterError", *field, Some(value.to_string())),
        E::LevelNeedsData { .. } => ("ParameterError", "level", None),
        E::InvalidCustomLaw { quantity, .. } => ("ParameterError", *quantity, None),
        E::Fit(_) => ("ParameterError", "samples", None),
        E::UnknownName { field, value, .. } => ("ParameterError", *field, Some(value.clone())),
        E::UnexpectedSetting { field, value, .. } => {
            ("ParameterError", *field, Some(value.to_string()))
        }
        E::MissingSetting { field, .. } => ("ParameterError", *field, None),
    };
    raise(py, class, message, Some(field), value)
}

/// A scene's error: `SceneError` with the field it names (`fingertip[0].material...`), if any.
pub fn scene_error(py: Python<'_>, e: &SceneError) -> PyErr {
    let (field, value) = match e {
        SceneError::Invalid { field, value, .. } => (Some(field.as_str()), Some(value.clone())),
        SceneError::Name { field, .. }
        | SceneError::Fingertip { field, .. }
        | SceneError::Law { field, .. } => (Some(field.as_str()), None),
        SceneError::Curve { field, .. } if !field.is_empty() => (Some(field.as_str()), None),
        _ => (None, None),
    };
    raise(py, "SceneError", e.to_string(), field, value)
}

/// A sweep's error: `SweepError` with the sweep field it names (`vary[1].random.n`), if any.
pub fn sweep_error(py: Python<'_>, e: &SweepError) -> PyErr {
    let (field, value) = match e {
        SweepError::Invalid { field, value, .. } => (Some(field.as_str()), Some(value.clone())),
        SweepError::Scene { .. } => (Some("scene"), None),
        SweepError::Shard { value, .. } => (Some("shard"), Some(value.clone())),
        SweepError::Options { option, value, .. } => (Some(*option), Some(value.clone())),
        _ => (None, None),
    };
    let class = if field == Some("trial") {
        "TrialIndexError"
    } else {
        "SweepError"
    };
    raise(py, class, e.to_string(), field, value)
}

/// An argument of a Python function that is wrong before any Rust type sees it.
pub fn parameter(py: Python<'_>, field: &str, value: impl ToString, expected: &str) -> PyErr {
    let value = value.to_string();
    raise(
        py,
        "ParameterError",
        format!("`{field}` must be {expected}, got {value}"),
        Some(field),
        Some(value),
    )
}

/// A step error: `SimulationDiverged` with its fields (`softgrip/errors.py`), and `result`,
/// the run's readout up to the fault.
pub fn diverged(py: Python<'_>, e: &StepError, result: Bound<'_, PyAny>) -> PyErr {
    let message = e.to_string();
    let make = || -> PyResult<PyErr> {
        let cls = py
            .import("softgrip.errors")?
            .getattr("SimulationDiverged")?;
        let exc = cls.call1((message.clone(),))?;
        exc.setattr("step", e.step())?;
        exc.setattr("time", e.time())?;
        exc.setattr("result", result)?;
        match e.divergence() {
            Some(d) => {
                exc.setattr("kind", "diverged")?;
                let subject = match d.subject {
                    Subject::Body(_) => "body",
                    Subject::Joint { .. } => "joint",
                    Subject::Contact { .. } => "contact",
                };
                exc.setattr("subject", subject)?;
                exc.setattr("name", d.name)?;
                exc.setattr("quantity", d.quantity.name())?;
                exc.setattr("field", d.quantity.name())?;
                exc.setattr("found", d.value)?;
                exc.setattr("value", d.value.to_string())?;
                exc.setattr("bound", d.bound)?;
                let phase = match d.phase {
                    Phase::Before => "before",
                    Phase::SoftSolve => "soft_solve",
                    Phase::After => "after",
                };
                exc.setattr("phase", phase)?;
            }
            None => exc.setattr("kind", "engine_panicked")?,
        }
        Ok(PyErr::from_value(exc))
    };
    make().unwrap_or_else(|err| {
        pyo3::exceptions::PyRuntimeError::new_err(format!("{message} (and raising it: {err})"))
    })
}
