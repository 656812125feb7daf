//! Building a [`Law`] from Python's arguments: `softgrip.law(...)`, the level's optional
//! settings ([`Settings`], shared with `fit_material`), the construction's name and thickness,
//! and the unpickling constructor `_law_from_state`.

use pyo3::prelude::*;
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};

use crate::args;
use crate::errors::law_error;
use crate::law::Law;

/// A level's optional settings as given from Python (each only for the level that takes it).
#[derive(Default)]
pub struct Settings {
    /// `k` of `fit`.
    pub k: Option<f64>,
    /// `tolerance` of `auto`.
    pub tolerance: Option<f64>,
    /// `match_x` of `linear`.
    pub match_x: Option<f64>,
}

impl Settings {
    /// Reads the three keyword arguments (None: not given).
    pub fn read(
        k: Option<&Bound<'_, PyAny>>,
        tolerance: Option<&Bound<'_, PyAny>>,
        match_x: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        Ok(Self {
            k: args::opt_float(k, "k")?,
            tolerance: args::opt_float(tolerance, "tolerance")?,
            match_x: args::opt_float(match_x, "match_x")?,
        })
    }
}

/// The level named `name` (a string) with its optional settings.
pub fn level(name: &Bound<'_, PyAny>, settings: &Settings) -> PyResult<Level> {
    let py = name.py();
    let name = args::text(
        name,
        "level",
        "a level name (a str, one of softgrip.LEVELS)",
    )?;
    // The name, each setting and its range through the law's table (softgrip_law::LEVELS).
    let mut level = Level::from_name(&name).map_err(|e| crate::errors::law_error(py, &e))?;
    for (key, value) in [
        ("match_x", settings.match_x),
        ("k", settings.k),
        ("tolerance", settings.tolerance),
    ] {
        if let Some(value) = value {
            level = level
                .with_setting(key, value)
                .map_err(|e| crate::errors::law_error(py, &e))?;
        }
    }
    Ok(level)
}

/// The construction named `name` (one of `softgrip.BACKINGS`) with the core's skin
/// thickness [m].
pub fn backing(name: &Bound<'_, PyAny>, thickness: Option<f64>) -> PyResult<Backing> {
    let py = name.py();
    let name = args::text(
        name,
        "backing",
        "a construction name (\"free\", \"flat\" or \"core\")",
    )?;
    // The one parser of (name, thickness) (softgrip_law::BACKINGS); the thickness against R
    // is the law's check when the parameters are built.
    // Python's argument is `thickness` (the table's key is `core_thickness`, as in scenes).
    Backing::try_from_parts(&name, thickness).map_err(|e| {
        let (field, value) = match &e {
            softgrip_law::Error::UnknownName { value, .. } => ("backing", Some(value.clone())),
            _ => ("thickness", thickness.map(|t| t.to_string())),
        };
        let message = e.to_string().replace("`core_thickness`", "`thickness`");
        crate::errors::raise(py, "ParameterError", message, Some(field), value)
    })
}

/// The law of `level` for a fingertip of E [Pa], nu [-], R [m] and construction `backing`.
fn build(
    py: Python<'_>,
    level: Level,
    youngs_modulus: f64,
    poisson_ratio: f64,
    radius: f64,
    backing: Backing,
) -> PyResult<Law> {
    let e = |e: softgrip_law::Error| law_error(py, &e);
    let material = Material::try_new(youngs_modulus, poisson_ratio).map_err(e)?;
    let params = ContactParams::try_new(material, radius)
        .and_then(|p| p.with_backing(backing))
        .map_err(e)?;
    let law = ContactLaw::try_new(params, level).map_err(e)?;
    Ok(Law {
        law,
        youngs_modulus,
    })
}

/// `softgrip.law(level, youngs_modulus, poisson_ratio, radius, backing="free",
/// thickness=None, *, k=None, tolerance=None, match_x=None)`.
#[pyfunction]
#[pyo3(signature = (level, youngs_modulus, poisson_ratio, radius, backing = None, thickness = None, *, k = None, tolerance = None, match_x = None))]
#[allow(clippy::too_many_arguments)]
pub fn law(
    py: Python<'_>,
    level: &Bound<'_, PyAny>,
    youngs_modulus: &Bound<'_, PyAny>,
    poisson_ratio: &Bound<'_, PyAny>,
    radius: &Bound<'_, PyAny>,
    backing: Option<&Bound<'_, PyAny>>,
    thickness: Option<&Bound<'_, PyAny>>,
    k: Option<&Bound<'_, PyAny>>,
    tolerance: Option<&Bound<'_, PyAny>>,
    match_x: Option<&Bound<'_, PyAny>>,
) -> PyResult<Law> {
    let level = self::level(level, &Settings::read(k, tolerance, match_x)?)?;
    let youngs_modulus = args::float(youngs_modulus, "youngs_modulus")?;
    let poisson_ratio = args::float(poisson_ratio, "poisson_ratio")?;
    let radius = args::float(radius, "radius")?;
    let thickness = args::opt_float(thickness, "thickness")?;
    let free = pyo3::types::PyString::new(py, "free").into_any();
    let backing = self::backing(backing.filter(|b| !b.is_none()).unwrap_or(&free), thickness)?;
    build(py, level, youngs_modulus, poisson_ratio, radius, backing)
}

/// Unpickles a [`Law`] from its state (`Law.__reduce__`): `(level, setting, E, nu, R,
/// backing, thickness)`.
#[pyfunction]
#[allow(clippy::too_many_arguments)]
pub fn _law_from_state(
    py: Python<'_>,
    level: &Bound<'_, PyAny>,
    setting: Option<f64>,
    youngs_modulus: f64,
    poisson_ratio: f64,
    radius: f64,
    backing: &Bound<'_, PyAny>,
    thickness: Option<f64>,
) -> PyResult<Law> {
    let mut lvl = self::level(level, &Settings::default())?;
    if let (
        Level::Fit { k: v } | Level::Auto { tolerance: v } | Level::Linear { match_x: v },
        Some(s),
    ) = (&mut lvl, setting)
    {
        *v = s;
    }
    let backing = self::backing(backing, thickness)?;
    build(py, lvl, youngs_modulus, poisson_ratio, radius, backing)
}
