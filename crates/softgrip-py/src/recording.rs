//! `softgrip.open_recording(path)`: an MCAP recording of any softgrip version opened as the
//! arrays a run returns (the same [`readout`](crate::readout) series, filled from the recorded
//! messages), with its metadata (the fingertips' laws, the run's summary, the scene text), the
//! tactile images and every contact row. Nothing is re-run.

use std::path::{Path, PathBuf};

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use softgrip_record::metadata::legacy;
use softgrip_record::{
    Error as RecordError, METADATA_NAME, RUN_SUMMARY_NAME, Recording, RecordingInfo, RunSummary,
};

use crate::args;
use crate::errors::raise;
use crate::recorded::{Axes, Frame, Steps};

/// What was read, converted without the GIL.
struct Opened {
    recording: Recording,
    info: Option<RecordingInfo>,
    summary: Option<RunSummary>,
    steps: Steps,
}

/// Reads `path` and sorts its messages into steps (in `frame`'s axes).
fn read(path: &Path, frame: Frame) -> Result<Opened, RecordError> {
    let recording = Recording::open(path)?;
    let info = recording
        .metadata
        .get(METADATA_NAME)
        .map(legacy::recording_info)
        .transpose()?;
    let summary = recording
        .metadata
        .get(RUN_SUMMARY_NAME)
        .map(legacy::run_summary)
        .transpose()?;
    // Recordings are z-up since the view's change (2026-12-02); the `gravity` metadata came
    // with it, so a file without it was recorded in the scene's own (y-up) axes.
    let z_up = recording
        .metadata
        .get(METADATA_NAME)
        .is_some_and(|m| m.contains_key("gravity"));
    let axes = Axes::new(z_up, frame);
    let steps = Steps::collect(&recording, info.as_ref(), axes);
    Ok(Opened {
        recording,
        info,
        summary,
        steps,
    })
}

/// The reader's error as softgrip's exception: a missing file is `FileNotFoundError` (as
/// `open` raises), any other I/O failure `RecordingError`, a file that is not MCAP, damaged
/// or not decodable `RecordingFormatError`.
fn recording_error(py: Python<'_>, path: &Path, e: &RecordError) -> PyErr {
    let shown = path.display().to_string();
    match e {
        RecordError::Io { source, .. } if source.kind() == std::io::ErrorKind::NotFound => {
            pyo3::exceptions::PyFileNotFoundError::new_err((2, source.to_string(), shown))
        }
        RecordError::Io { .. } | RecordError::Write { .. } => raise(
            py,
            "RecordingError",
            e.to_string(),
            Some("path"),
            Some(shown),
        ),
        _ => raise(
            py,
            "RecordingFormatError",
            format!("{shown}: {e}"),
            Some("path"),
            Some(shown),
        ),
    }
}

fn laws<'py>(py: Python<'py>, info: Option<&RecordingInfo>) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for l in info.map(|i| i.law.as_slice()).unwrap_or_default() {
        let d = PyDict::new(py);
        d.set_item("level", l.level.name())?;
        d.set_item("setting", crate::law::setting(l.level))?;
        d.set_item("youngs_modulus", l.youngs_modulus)?;
        d.set_item("poisson_ratio", l.poisson_ratio)?;
        d.set_item("radius", l.radius)?;
        d.set_item("friction", l.friction)?;
        d.set_item("restitution", l.restitution)?;
        d.set_item("backing", l.backing.name())?;
        d.set_item("core_thickness", l.backing.thickness())?;
        out.set_item(&l.name, d)?;
    }
    Ok(out)
}

/// The run's controllers as recorded, in the order they ran: `{name, kind, code}` (none in
/// recordings made before they were written).
fn controllers<'py>(py: Python<'py>, info: Option<&RecordingInfo>) -> PyResult<Bound<'py, PyList>> {
    let out = PyList::empty(py);
    for c in info.map(|i| i.controllers.as_slice()).unwrap_or_default() {
        let d = PyDict::new(py);
        d.set_item("name", &c.name)?;
        d.set_item("kind", &c.kind)?;
        d.set_item("code", c.code)?;
        out.append(d)?;
    }
    Ok(out)
}

fn summary<'py>(py: Python<'py>, s: Option<&RunSummary>) -> PyResult<Bound<'py, PyAny>> {
    let Some(s) = s else {
        return Ok(py.None().into_bound(py));
    };
    let out = PyDict::new(py);
    for t in &s.fingertips {
        let d = PyDict::new(py);
        d.set_item("peak_force", t.peak_force)?;
        d.set_item("peak_x", t.peak_x)?;
        d.set_item("slips", t.slips)?;
        d.set_item("validity_excursions", t.validity_excursions)?;
        out.set_item(&t.name, d)?;
    }
    Ok(out.into_any())
}

fn to_python<'py>(py: Python<'py>, path: &Path, o: Opened) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let info = o.info.as_ref();
    out.set_item("path", path.display().to_string())?;
    out.set_item("origin", info.map(|i| i.origin.clone()))?;
    out.set_item("softgrip_version", info.map(|i| i.softgrip_version.clone()))?;
    out.set_item("scene", info.map(|i| i.scene.clone()))?;
    out.set_item("dt", info.map(|i| i.dt).filter(|&dt| dt > 0.0))?;
    out.set_item("every", info.map(|i| i.every_n_steps).filter(|&n| n > 0))?;
    out.set_item("total_steps", info.map(|i| i.steps).filter(|&n| n > 0))?;
    out.set_item("frame", o.steps.axes.frame_name())?;
    out.set_item("laws", laws(py, info)?)?;
    out.set_item("controllers", controllers(py, info)?)?;
    out.set_item("summary", summary(py, o.summary.as_ref())?)?;
    out.set_item("summary_steps", o.summary.as_ref().map(|s| s.steps))?;
    let channels = PyList::empty(py);
    for c in &o.recording.channels {
        let d = PyDict::new(py);
        d.set_item("topic", &c.topic)?;
        d.set_item("schema_name", &c.schema_name)?;
        d.set_item("message_encoding", &c.message_encoding)?;
        d.set_item("message_count", c.message_count)?;
        channels.append(d)?;
    }
    out.set_item("channels", channels)?;
    out.set_item(
        "recovery",
        match &o.recording.recovery {
            None => py.None().into_bound(py),
            Some(r) => {
                let d = PyDict::new(py);
                d.set_item("chunks", r.chunks)?;
                d.set_item("bytes_kept", r.bytes_kept)?;
                d.set_item("file_len", r.file_len)?;
                d.set_item("stopped_because", &r.stopped_because)?;
                d.into_any()
            }
        },
    )?;
    let s = o.steps;
    out.set_item("step", s.step.into_pyarray(py))?;
    out.set_item("time", s.time.into_pyarray(py))?;
    out.set_item("log_time_ns", s.log_time_ns.into_pyarray(py))?;
    let tips = PyDict::new(py);
    for (name, t) in s.tip_names.iter().zip(s.tips) {
        tips.set_item(name, t.into_py(py)?)?;
    }
    out.set_item("fingertips", tips)?;
    let tactile = PyDict::new(py);
    for (name, t) in s.tactile {
        tactile.set_item(name, t.into_py(py))?;
    }
    out.set_item("tactile", tactile)?;
    let bodies = PyDict::new(py);
    for (name, b) in s.body_names.iter().zip(s.bodies) {
        bodies.set_item(name, b.into_py(py)?)?;
    }
    out.set_item("bodies", bodies)?;
    out.set_item("joints", s.joints.into_py(py)?)?;
    out.set_item("contact_rows", s.rows.into_py(py)?)?;
    Ok(out)
}

/// Opens the recording at `path` (any softgrip version; a killed writer's file is recovered
/// up to its last complete chunk) as a dict of arrays (the package's `Recording`). `frame`:
/// `"scene"` (default: vectors and poses in the scene's axes, as a run returns them) or
/// `"world"` (as recorded since 2026-12-02: z-up, REP 103).
#[pyfunction]
#[pyo3(signature = (path, *, frame = None))]
pub fn open_recording<'py>(
    py: Python<'py>,
    path: &Bound<'py, PyAny>,
    frame: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let path: PathBuf = args::path(path, "path")?;
    let frame = match frame.filter(|f| !f.is_none()) {
        None => Frame::Scene,
        Some(f) => {
            let name = args::text(f, "frame", "\"scene\" or \"world\"")?;
            Frame::parse(&name).ok_or_else(|| {
                crate::errors::parameter(py, "frame", format!("{name:?}"), "\"scene\" or \"world\"")
            })?
        }
    };
    let opened = py
        .detach(|| read(&path, frame))
        .map_err(|e| recording_error(py, &path, &e))?;
    to_python(py, &path, opened)
}
