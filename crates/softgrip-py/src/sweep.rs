//! `softgrip._native.Sweep`: softgrip-sweep's checked [`Sweep`](softgrip_sweep::Sweep), its
//! trials run all at once on local threads ([`Sweep::run`]) or one by index
//! ([`Sweep::run_trial`], what a Ray task calls), its rows as Python tuples and back.

use std::path::{Path, PathBuf};

use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use softgrip_sweep::{
    OUTCOME_COLUMNS, Outcome, ResultsTable, RunOptions, Shard, Sweep as RustSweep, SweepError,
    TrialRow, Value, ValueKind,
};

/// Most worker threads a local run takes (more only spends time spawning them: a 2-core
/// machine took minutes for 100 000; `softgrip sweep --threads` has its own bound).
const MAX_THREADS: u64 = 4096;

use crate::args;
use crate::errors::{parameter, raise, sweep_error};

/// A checked sweep file: its base scene, the varied fields, the trials. Pickles as its text,
/// its origin and its directory (absolute): unpickling checks it again there, so the base scene
/// must be readable at the same path (a shared filesystem, or Ray's `working_dir`).
#[pyclass(module = "softgrip._native", name = "Sweep", frozen)]
pub struct Sweep {
    sweep: RustSweep,
    /// The sweep file's text.
    text: String,
    /// Its name in errors (the path as given, or `<sweep>`).
    origin: String,
    /// The directory its relative paths are relative to, absolute.
    base_dir: PathBuf,
}

/// `dir` made absolute against the current directory (as given if that fails).
fn absolute(dir: &Path) -> PathBuf {
    std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf())
}

fn kind_name(k: ValueKind) -> &'static str {
    match k {
        ValueKind::Float => "float",
        ValueKind::Int => "int",
        ValueKind::Bool => "bool",
        ValueKind::Text => "text",
    }
}

fn value_to_py<'py>(py: Python<'py>, v: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Float(x) => x.into_pyobject(py)?.into_any(),
        Value::Int(x) => x.into_pyobject(py)?.into_any(),
        Value::Bool(x) => pyo3::types::PyBool::new(py, *x).to_owned().into_any(),
        Value::Text(x) => x.into_pyobject(py)?.into_any(),
    })
}

/// A row as the tuple `(trial, *values, held, slips, slip_distance, peak_force, peak_x,
/// validity_excursions, hold_force, wall_time, error)`, None for the outcomes of an error row and for
/// the error of an ok row.
fn row_to_py<'py>(py: Python<'py>, r: &TrialRow) -> PyResult<Bound<'py, PyTuple>> {
    let mut items: Vec<Bound<'py, PyAny>> = vec![r.trial.into_pyobject(py)?.into_any()];
    for v in &r.values {
        items.push(value_to_py(py, v)?);
    }
    let none = || py.None().into_bound(py);
    match &r.outcome {
        Ok(o) => {
            items.push(pyo3::types::PyBool::new(py, o.held).to_owned().into_any());
            items.push(o.slips.into_pyobject(py)?.into_any());
            items.push(o.slip_distance.into_pyobject(py)?.into_any());
            items.push(o.peak_force.into_pyobject(py)?.into_any());
            items.push(o.peak_x.into_pyobject(py)?.into_any());
            items.push(o.validity_excursions.into_pyobject(py)?.into_any());
            items.push(o.hold_force.into_pyobject(py)?.into_any());
            items.push(r.wall_time.into_pyobject(py)?.into_any());
            items.push(none());
        }
        Err(e) => {
            items.extend((0..7).map(|_| none()));
            items.push(r.wall_time.into_pyobject(py)?.into_any());
            items.push(e.into_pyobject(py)?.into_any());
        }
    }
    PyTuple::new(py, items)
}

impl Sweep {
    /// Checks sweep `text` named `origin` whose relative paths are relative to `base_dir`.
    fn parse(py: Python<'_>, text: String, origin: String, base_dir: &Path) -> PyResult<Self> {
        let base_dir = absolute(base_dir);
        let sweep = py
            .detach(|| RustSweep::parse(&text, &origin, &base_dir))
            .map_err(|e| sweep_error(py, &e))?;
        Ok(Self {
            sweep,
            text,
            origin,
            base_dir,
        })
    }

    /// `index` as a trial index of this sweep, or `TrialIndexError` naming `trial`.
    fn trial(&self, index: &Bound<'_, PyAny>) -> PyResult<u64> {
        let trials = self.sweep.trials();
        let v = args::integer(index, "trial")?;
        match u64::try_from(v) {
            Ok(i) if i < trials => Ok(i),
            _ => {
                let shown = args::repr(index);
                Err(raise(
                    index.py(),
                    "TrialIndexError",
                    format!(
                        "{}: `trial` must be in 0..{trials} (the sweep's trials), got {shown}",
                        self.origin
                    ),
                    Some("trial"),
                    Some(shown),
                ))
            }
        }
    }

    /// A row tuple (as [`row_to_py`] makes them) back as a [`TrialRow`].
    fn row_from_py(&self, py: Python<'_>, row: &Bound<'_, PyAny>) -> PyResult<TrialRow> {
        let items: Vec<Bound<'_, PyAny>> = row.extract()?;
        let kinds: Vec<ValueKind> = self.sweep.axes().iter().map(|a| a.kind()).collect();
        let width = 1 + kinds.len() + OUTCOME_COLUMNS.len();
        if items.len() != width {
            return Err(parameter(
                py,
                "rows",
                format!("a row of {} items", items.len()),
                &format!("rows of {width} items (the sweep's columns)"),
            ));
        }
        let trial: u64 = items[0].extract()?;
        let mut values = Vec::with_capacity(kinds.len());
        for (k, item) in kinds.iter().zip(&items[1..]) {
            values.push(match k {
                ValueKind::Float => Value::Float(item.extract()?),
                ValueKind::Int => Value::Int(item.extract()?),
                ValueKind::Bool => Value::Bool(item.extract()?),
                ValueKind::Text => Value::Text(item.extract()?),
            });
        }
        let o = &items[1 + kinds.len()..];
        let error: Option<String> = o[8].extract()?;
        let outcome = match error {
            Some(e) => Err(e),
            None => Ok(Outcome {
                held: o[0].extract()?,
                slips: o[1].extract()?,
                slip_distance: o[2].extract()?,
                peak_force: o[3].extract()?,
                peak_x: o[4].extract()?,
                validity_excursions: o[5].extract()?,
                hold_force: o[6].extract()?,
            }),
        };
        Ok(TrialRow {
            trial,
            values,
            outcome,
            wall_time: o[7].extract()?,
        })
    }
}

#[pymethods]
impl Sweep {
    /// Reads and checks the sweep file at `path` (its `scene` is relative to it).
    #[staticmethod]
    fn open(py: Python<'_>, path: &Bound<'_, PyAny>) -> PyResult<Self> {
        let path = args::path(path, "sweep_path")?;
        let text = std::fs::read_to_string(&path).map_err(|source| {
            sweep_error(
                py,
                &SweepError::Io {
                    path: path.clone(),
                    source,
                },
            )
        })?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Self::parse(py, text, path.display().to_string(), &base)
    }

    /// Checks sweep TOML `text` whose `scene` (and `mcap_dir`) are relative to `base_dir`.
    #[staticmethod]
    fn from_toml(
        py: Python<'_>,
        text: &Bound<'_, PyAny>,
        base_dir: &Bound<'_, PyAny>,
    ) -> PyResult<Self> {
        let text = args::text(text, "toml", "sweep TOML text (a str)")?;
        let base_dir = args::path(base_dir, "base_dir")?;
        Self::parse(py, text, "<sweep>".to_owned(), &base_dir)
    }

    /// Unpickles a sweep from its state (`Sweep.__reduce__`).
    #[staticmethod]
    fn _from_state(
        py: Python<'_>,
        text: String,
        origin: String,
        base_dir: PathBuf,
    ) -> PyResult<Self> {
        Self::parse(py, text, origin, &base_dir)
    }

    /// Pickling: `(text, origin, base_dir)`, checked again when unpickled.
    fn __reduce__<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(Bound<'py, PyAny>, (String, String, PathBuf))> {
        let restore = py
            .import("softgrip._native")?
            .getattr("Sweep")?
            .getattr("_from_state")?;
        Ok((
            restore,
            (
                self.text.clone(),
                self.origin.clone(),
                self.base_dir.clone(),
            ),
        ))
    }

    /// The sweep file's text.
    #[getter]
    fn text(&self) -> &str {
        &self.text
    }

    /// Number of trials.
    #[getter]
    fn trials(&self) -> u64 {
        self.sweep.trials()
    }

    /// The sweep file (or `<sweep>`).
    #[getter]
    fn origin(&self) -> &str {
        self.sweep.origin()
    }

    /// The body whose hold decides `held`.
    #[getter]
    fn object(&self) -> &str {
        self.sweep.object()
    }

    /// The varied fields' paths, in `[[vary]]` order.
    fn fields(&self) -> Vec<String> {
        self.sweep.fields()
    }

    /// Every column name of the results: `trial`, the fields, the outcomes.
    fn columns(&self) -> Vec<String> {
        self.sweep.table().columns()
    }

    /// The varied fields' column types: `float`, `int`, `bool` or `text`.
    fn kinds(&self) -> Vec<&'static str> {
        self.sweep
            .axes()
            .iter()
            .map(|a| kind_name(a.kind()))
            .collect()
    }

    /// Trial `index`'s scene as TOML text.
    fn scene_text(&self, py: Python<'_>, index: &Bound<'_, PyAny>) -> PyResult<String> {
        let index = self.trial(index)?;
        self.sweep
            .scene_text(index)
            .map_err(|e| sweep_error(py, &e))
    }

    /// Runs trial `index` (without the GIL): its row tuple. A bad trial is a row with its
    /// error; an index outside 0..trials (negative included) raises `TrialIndexError` naming
    /// `trial`.
    fn run_trial<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let index = self.trial(index)?;
        let row = py
            .detach(|| self.sweep.run_trial(index))
            .map_err(|e| sweep_error(py, &e))?;
        row_to_py(py, &row)
    }

    /// Runs the trials of shard `shard_index` of `shard_count` on `threads` threads (0 = one
    /// per core), without the GIL: the row tuples in trial order.
    #[pyo3(signature = (threads = None, shard_index = None, shard_count = None))]
    fn run<'py>(
        &self,
        py: Python<'py>,
        threads: Option<&Bound<'py, PyAny>>,
        shard_index: Option<&Bound<'py, PyAny>>,
        shard_count: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyList>> {
        let int =
            |v: Option<&Bound<'py, PyAny>>, field: &str, default: u64, max: u64, expected: &str| {
                match v.filter(|v| !v.is_none()) {
                    Some(v) => args::bounded(v, field, 0..=max, "ParameterError", expected),
                    None => Ok(default),
                }
            };
        let threads = int(
            threads,
            "threads",
            0,
            MAX_THREADS,
            &format!("an integer in 0..={MAX_THREADS} (0: one per core)"),
        )? as usize;
        let shard_index = int(shard_index, "shard", 0, u64::MAX, "a shard index >= 0")?;
        let shard_count = int(shard_count, "shard", 1, u64::MAX, "a shard count >= 1")?;
        let shard = Shard::new(shard_index, shard_count).map_err(|e| sweep_error(py, &e))?;
        let options = RunOptions { threads, shard };
        let table = py
            .detach(|| self.sweep.run(&options, &|_, _| {}))
            .map_err(|e| sweep_error(py, &e))?;
        let rows = (table.rows.iter())
            .map(|r| row_to_py(py, r))
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, rows)
    }

    /// Writes `rows` (row tuples of this sweep) as the Rust results file: Parquet or CSV by
    /// the extension of `path`, exactly as `softgrip sweep --out` writes it.
    fn write(
        &self,
        py: Python<'_>,
        rows: Vec<Bound<'_, PyAny>>,
        path: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let path = args::path(path, "out")?;
        let mut table: ResultsTable = self.sweep.table();
        for r in &rows {
            table.rows.push(self.row_from_py(py, r)?);
        }
        let result = match path.extension().and_then(|e| e.to_str()) {
            Some("parquet") => py.detach(|| table.write_parquet(&path)),
            Some("csv") => py.detach(|| table.write_csv(&path)),
            _ => {
                return Err(parameter(
                    py,
                    "out",
                    path.display(),
                    "a path ending in .parquet or .csv (the format is taken from it)",
                ));
            }
        };
        result.map_err(|e| sweep_error(py, &e))
    }

    /// The results as `softgrip sweep` prints them without `--out`: CSV text.
    fn to_csv(&self, py: Python<'_>, rows: Vec<Bound<'_, PyAny>>) -> PyResult<String> {
        let mut table: ResultsTable = self.sweep.table();
        for r in &rows {
            table.rows.push(self.row_from_py(py, r)?);
        }
        Ok(table.to_csv())
    }

    fn __repr__(&self) -> String {
        format!(
            "Sweep({:?}: {} trials over {:?})",
            self.sweep.origin(),
            self.sweep.trials(),
            self.sweep.fields()
        )
    }
}
