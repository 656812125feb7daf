#![doc = include_str!("../README.md")]
// pyo3's `#[pymethods]`/`#[pyfunction]` expand to items the workspace's `missing_docs` lint
// would flag; every Python-visible item has its docstring (from the `///` comments).

mod args;
mod array;
mod errors;
mod fit;
mod law;
mod make_law;
mod readout;
mod recorded;
mod recording;
mod run;
mod sweep;

use pyo3::prelude::*;

/// The extension module `softgrip._native` (the Python package `softgrip` wraps it).
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<law::Law>()?;
    m.add_class::<sweep::Sweep>()?;
    m.add_function(wrap_pyfunction!(make_law::law, m)?)?;
    m.add_function(wrap_pyfunction!(make_law::_law_from_state, m)?)?;
    m.add_function(wrap_pyfunction!(recording::open_recording, m)?)?;
    m.add_function(wrap_pyfunction!(fit::fit_material, m)?)?;
    m.add_function(wrap_pyfunction!(run::run_scene, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    // The kinds, from the law's tables (softgrip_law::LEVELS, BACKINGS): the level names `law`
    // accepts (those built from parameters alone) and the constructions.
    let levels: Vec<&str> = softgrip_law::LEVELS
        .iter()
        .filter(|row| row.data == softgrip_law::LevelData::None)
        .map(|row| row.name)
        .collect();
    m.add("LEVELS", pyo3::types::PyTuple::new(m.py(), levels)?)?;
    let backings: Vec<&str> = softgrip_law::BACKINGS.iter().map(|row| row.name).collect();
    m.add("BACKINGS", pyo3::types::PyTuple::new(m.py(), backings)?)?;
    // The controller kinds, from the scene's table (softgrip_scene::control::CONTROLLERS): the
    // `kind` of each of a recording's `controllers`.
    let controllers: Vec<&str> = (softgrip_scene::control::CONTROLLERS.iter())
        .map(|row| row.name)
        .collect();
    m.add(
        "CONTROLLERS",
        pyo3::types::PyTuple::new(m.py(), controllers)?,
    )?;
    // The results table's columns after the varied fields (softgrip_sweep::OUTCOME_COLUMNS).
    m.add(
        "OUTCOME_COLUMNS",
        pyo3::types::PyTuple::new(m.py(), softgrip_sweep::OUTCOME_COLUMNS)?,
    )?;
    Ok(())
}
