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
    Ok(())
}
