//! `softgrip._native.Sweep`: softgrip-sweep's checked [`Sweep`](softgrip_sweep::Sweep), its
//! trials run all at once on local threads ([`Sweep::run`]) or one by index
//! ([`Sweep::run_trial`], what a Ray task calls), its rows as Python tuples and back.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};
use softgrip_sweep::{
    OUTCOME_COLUMNS, Outcome, ResultsTable, RunOptions, Shard, Sweep as RustSweep, TrialRow, Value,
    ValueKind,
};

use crate::errors::{parameter, sweep_error};

/// A checked sweep file: its base scene, the varied fields, the trials.
#[pyclass(module = "softgrip._native", name = "Sweep", frozen)]
pub struct Sweep {
    sweep: RustSweep,
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
/// validity_excursions, wall_time, error)`, None for the outcomes of an error row and for
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
            items.push(r.wall_time.into_pyobject(py)?.into_any());
            items.push(none());
        }
        Err(e) => {
            items.extend((0..6).map(|_| none()));
            items.push(r.wall_time.into_pyobject(py)?.into_any());
            items.push(e.into_pyobject(py)?.into_any());
        }
    }
    PyTuple::new(py, items)
}

impl Sweep {
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
        let error: Option<String> = o[7].extract()?;
        let outcome = match error {
            Some(e) => Err(e),
            None => Ok(Outcome {
                held: o[0].extract()?,
                slips: o[1].extract()?,
                slip_distance: o[2].extract()?,
                peak_force: o[3].extract()?,
                peak_x: o[4].extract()?,
                validity_excursions: o[5].extract()?,
            }),
        };
        Ok(TrialRow {
            trial,
            values,
            outcome,
            wall_time: o[6].extract()?,
        })
    }
}

#[pymethods]
impl Sweep {
    /// Reads and checks the sweep file at `path` (its `scene` is relative to it).
    #[staticmethod]
    fn open(py: Python<'_>, path: PathBuf) -> PyResult<Self> {
        let sweep = py
            .detach(|| RustSweep::from_path(&path))
            .map_err(|e| sweep_error(py, &e))?;
        Ok(Self { sweep })
    }

    /// Checks sweep TOML `text` whose `scene` (and `mcap_dir`) are relative to `base_dir`.
    #[staticmethod]
    fn from_toml(py: Python<'_>, text: &str, base_dir: PathBuf) -> PyResult<Self> {
        let sweep = py
            .detach(|| RustSweep::from_str(text, &base_dir))
            .map_err(|e| sweep_error(py, &e))?;
        Ok(Self { sweep })
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
    fn scene_text(&self, py: Python<'_>, index: u64) -> PyResult<String> {
        self.sweep
            .scene_text(index)
            .map_err(|e| sweep_error(py, &e))
    }

    /// Runs trial `index` (without the GIL): its row tuple. A bad trial is a row with its
    /// error; an index past the trials raises `SweepError` naming `trial`.
    fn run_trial<'py>(&self, py: Python<'py>, index: u64) -> PyResult<Bound<'py, PyTuple>> {
        let row = py
            .detach(|| self.sweep.run_trial(index))
            .map_err(|e| sweep_error(py, &e))?;
        row_to_py(py, &row)
    }

    /// Runs the trials of shard `shard_index` of `shard_count` on `threads` threads (0 = one
    /// per core), without the GIL: the row tuples in trial order.
    #[pyo3(signature = (threads = 0, shard_index = 0, shard_count = 1))]
    fn run<'py>(
        &self,
        py: Python<'py>,
        threads: usize,
        shard_index: u64,
        shard_count: u64,
    ) -> PyResult<Bound<'py, PyList>> {
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
    fn write(&self, py: Python<'_>, rows: Vec<Bound<'_, PyAny>>, path: PathBuf) -> PyResult<()> {
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
