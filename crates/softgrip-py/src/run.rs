//! `softgrip.run(...)`: a scene through the same bevy_ecs schedule as `softgrip run` (with
//! its summary and, optionally, its MCAP recording), with the per-step readout of every
//! fingertip and body kept as arrays.

use std::path::{Path, PathBuf};
use std::time::Instant;

use numpy::IntoPyArray;
use numpy::ndarray::Array2;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use softgrip_ecs::{McapSink, Physics, Scene, SceneError, Simulation, Summary, TipSummary};
use softgrip_scene::{ContactDigest, DEFAULT_SCENE};

use crate::errors::{parameter, raise, scene_error};

/// Steps between two checks for a pending Python signal (Ctrl-C) during a run.
const SIGNAL_CHECK_STEPS: u64 = 512;

/// Where the scene comes from.
enum Source {
    /// A scene file.
    File(PathBuf),
    /// TOML text, its relative paths relative to the directory.
    Text(String, PathBuf),
    /// The embedded default grasp.
    Default,
}

/// One fingertip's readout, one entry per step.
#[derive(Default)]
struct TipSeries {
    force: Vec<f64>,
    friction_force: Vec<f64>,
    torsional_moment: Vec<f64>,
    delta: Vec<f64>,
    x: Vec<f64>,
    radius: Vec<f64>,
    stiffness: Vec<f64>,
    peak_force: Vec<f64>,
    contacts: Vec<i64>,
    sliding: Vec<bool>,
    validity_exceeded: Vec<bool>,
}

/// One body's pose, one entry per step.
#[derive(Default)]
struct BodySeries {
    position: Vec<f64>,
    rotation: Vec<f64>,
}

/// What the recorder wrote.
struct Recording {
    path: PathBuf,
    frames: u64,
    messages: u64,
    chunks: u32,
    bytes: u64,
    every: u64,
}

/// A finished (or interrupted) run, as plain data.
struct RunData {
    origin: String,
    dt: f64,
    total: u64,
    steps: u64,
    tip_names: Vec<String>,
    tips: Vec<TipSeries>,
    body_names: Vec<String>,
    bodies: Vec<BodySeries>,
    summary: Vec<TipSummary>,
    digest: ContactDigest,
    wall: f64,
    recording: Option<Recording>,
}

/// Why a run has no result.
enum Failure {
    Scene(SceneError),
    Recording(String),
}

fn load(source: &Source) -> Result<(Scene, String), Failure> {
    match source {
        // Read once: a pipe gives its text only once (it was read twice, the text empty).
        Source::File(path) => Scene::from_file_with_text(path).map_err(Failure::Scene),
        Source::Text(text, base) => Scene::parse(text, "<toml>", base)
            .map(|s| (s, text.clone()))
            .map_err(Failure::Scene),
        Source::Default => Ok((Scene::default_scene(), DEFAULT_SCENE.to_string())),
    }
}

/// Runs the scene for its duration (or until Ctrl-C: then `interrupted` holds the
/// `KeyboardInterrupt`), reading out every step. Called without the GIL.
fn simulate(
    source: &Source,
    mcap: Option<&Path>,
    every: Option<u64>,
    interrupted: &mut Option<PyErr>,
) -> Result<RunData, Failure> {
    let (scene, text) = load(source)?;
    let f = scene.file();
    let every = every.unwrap_or(f.record.every_n_steps).max(1);
    let mut sim = Simulation::new(&scene).with_summary();
    let mut report = None;
    if let Some(path) = mcap {
        let sink = McapSink::with_options(path, &scene, &text, every, &Default::default())
            .map_err(|e| {
                Failure::Recording(format!("creating the recording {}: {e}", path.display()))
            })?;
        report = Some(sink.report_handle());
        sim = sim.with_recorder(sink);
    }
    sim.initialize();
    let total = sim.total_steps();
    let tip_entities = sim.entities.fingertips.clone();
    let body_entities = sim.entities.bodies.clone();
    let mut tips: Vec<TipSeries> = tip_entities.iter().map(|_| TipSeries::default()).collect();
    let mut bodies: Vec<BodySeries> = body_entities
        .iter()
        .map(|_| BodySeries::default())
        .collect();
    let mut digest = ContactDigest::new();
    let start = Instant::now();
    let mut steps = 0;
    while steps < total {
        if steps % SIGNAL_CHECK_STEPS == 0
            && steps > 0
            && let Err(e) = Python::attach(|py| py.check_signals())
        {
            *interrupted = Some(e);
            break;
        }
        sim.step();
        steps += 1;
        let physics = sim.world.resource::<Physics>();
        let contacts = physics.world.soft.contacts();
        digest.add_step(contacts.iter());
        read_tips(physics, &tip_entities, &mut tips);
        read_bodies(physics, &body_entities, &mut bodies);
    }
    let wall = start.elapsed().as_secs_f64();
    sim.finish()
        .map_err(|e| Failure::Recording(format!("recorder: {e}")))?;
    let summary = sim.world.resource::<Summary>();
    let recording = match (mcap, report) {
        (Some(path), Some(handle)) => {
            let r = handle.lock().unwrap_or_else(|e| e.into_inner()).clone();
            let stats = r.stats.ok_or_else(|| {
                Failure::Recording(format!(
                    "{}: the recording was not finished",
                    path.display()
                ))
            })?;
            Some(Recording {
                path: path.to_path_buf(),
                frames: r.frames_written,
                messages: stats.messages,
                chunks: stats.chunks,
                bytes: std::fs::metadata(path).map(|m| m.len()).unwrap_or(0),
                every,
            })
        }
        _ => None,
    };
    Ok(RunData {
        origin: scene.origin().to_string(),
        dt: f.dt,
        total,
        steps,
        tip_names: f.fingertips.iter().map(|t| t.name.clone()).collect(),
        tips,
        body_names: f.bodies.iter().map(|b| b.name.clone()).collect(),
        bodies,
        summary: summary.tips.iter().map(|(_, t)| t.clone()).collect(),
        digest,
        wall,
        recording,
    })
}

/// Appends each fingertip's readout of the last step: forces and stiffness summed over its
/// contacts, the deepest contact's compression and contact radius.
fn read_tips(
    physics: &Physics,
    entities: &[softgrip_ecs::bevy_ecs::entity::Entity],
    tips: &mut [TipSeries],
) {
    let n = tips.len();
    let mut force = vec![0.0; n];
    let mut friction = vec![[0.0; 3]; n];
    let mut moment = vec![0.0; n];
    let mut deepest: Vec<Option<&softgrip_ecs::softgrip_rapier::TipContact>> = vec![None; n];
    let mut stiffness = vec![0.0; n];
    let mut peak = vec![0.0f64; n];
    let mut count = vec![0i64; n];
    let mut sliding = vec![false; n];
    let mut exceeded = vec![false; n];
    for c in physics.world.soft.contacts() {
        let Some(k) = physics
            .collider_entity(c.fingertip)
            .and_then(|e| entities.iter().position(|&t| t == e))
        else {
            continue;
        };
        force[k] += c.normal_force;
        for (f, cf) in friction[k].iter_mut().zip(c.friction_force) {
            *f += cf;
        }
        moment[k] += c.torsional_moment;
        stiffness[k] += c.stiffness;
        peak[k] = peak[k].max(c.peak_normal_force);
        count[k] += 1;
        sliding[k] |= c.sliding;
        exceeded[k] |= c.validity_exceeded;
        if deepest[k].is_none_or(|d| c.delta > d.delta) {
            deepest[k] = Some(c);
        }
    }
    for (k, t) in tips.iter_mut().enumerate() {
        t.force.push(force[k]);
        t.friction_force.extend_from_slice(&friction[k]);
        t.torsional_moment.push(moment[k]);
        let (delta, x, radius) =
            deepest[k].map_or((0.0, 0.0, 0.0), |c| (c.delta, c.x, c.patch().radius));
        t.delta.push(delta);
        t.x.push(x);
        t.radius.push(radius);
        t.stiffness.push(stiffness[k]);
        t.peak_force.push(peak[k]);
        t.contacts.push(count[k]);
        t.sliding.push(sliding[k]);
        t.validity_exceeded.push(exceeded[k]);
    }
}

/// Appends each body's pose after the last step (NaN for a body rapier does not have).
fn read_bodies(
    physics: &Physics,
    entities: &[softgrip_ecs::bevy_ecs::entity::Entity],
    bodies: &mut [BodySeries],
) {
    for (b, &e) in bodies.iter_mut().zip(entities) {
        let rb = physics
            .body_handle(e)
            .and_then(|h| physics.world.physics.bodies.get(h));
        match rb {
            Some(rb) => {
                let t = rb.translation();
                let q = rb.rotation();
                b.position
                    .extend([f64::from(t.x), f64::from(t.y), f64::from(t.z)]);
                b.rotation.extend([
                    f64::from(q.x),
                    f64::from(q.y),
                    f64::from(q.z),
                    f64::from(q.w),
                ]);
            }
            None => {
                b.position.extend([f64::NAN; 3]);
                b.rotation.extend([f64::NAN; 4]);
            }
        }
    }
}

/// `values` as an (n, width) float64 array.
fn matrix<'py>(py: Python<'py>, values: Vec<f64>, width: usize) -> Bound<'py, PyAny> {
    let rows = values.len() / width;
    Array2::from_shape_vec((rows, width), values)
        .expect("invariant: width values per step")
        .into_pyarray(py)
        .into_any()
}

fn tip_summary<'py>(py: Python<'py>, t: &TipSummary) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("peak_force", t.peak_force)?;
    d.set_item("peak_x", t.peak_x)?;
    d.set_item("peak_radius", t.peak_radius)?;
    d.set_item("slips", t.slips)?;
    d.set_item("validity_excursions", t.validity_excursions)?;
    d.set_item("commanded_depth", t.commanded_depth)?;
    d.set_item("squeeze_force", t.squeeze_force)?;
    d.set_item("squeeze_delta", t.squeeze_delta)?;
    Ok(d)
}

fn to_python<'py>(py: Python<'py>, r: RunData) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    let time: Vec<f64> = (1..=r.steps).map(|k| k as f64 * r.dt).collect();
    out.set_item("origin", &r.origin)?;
    out.set_item("dt", r.dt)?;
    out.set_item("steps", r.steps)?;
    out.set_item("total_steps", r.total)?;
    out.set_item("time", time.into_pyarray(py))?;
    let tips = PyDict::new(py);
    for (name, t) in r.tip_names.iter().zip(r.tips) {
        let d = PyDict::new(py);
        d.set_item("force", t.force.into_pyarray(py))?;
        d.set_item("friction_force", matrix(py, t.friction_force, 3))?;
        d.set_item("torsional_moment", t.torsional_moment.into_pyarray(py))?;
        d.set_item("delta", t.delta.into_pyarray(py))?;
        d.set_item("x", t.x.into_pyarray(py))?;
        d.set_item("radius", t.radius.into_pyarray(py))?;
        d.set_item("stiffness", t.stiffness.into_pyarray(py))?;
        d.set_item("peak_force", t.peak_force.into_pyarray(py))?;
        d.set_item("contacts", t.contacts.into_pyarray(py))?;
        d.set_item("sliding", t.sliding.into_pyarray(py))?;
        d.set_item("validity_exceeded", t.validity_exceeded.into_pyarray(py))?;
        tips.set_item(name, d)?;
    }
    out.set_item("fingertips", tips)?;
    let bodies = PyDict::new(py);
    for (name, b) in r.body_names.iter().zip(r.bodies) {
        let d = PyDict::new(py);
        d.set_item("position", matrix(py, b.position, 3))?;
        d.set_item("rotation", matrix(py, b.rotation, 4))?;
        bodies.set_item(name, d)?;
    }
    out.set_item("bodies", bodies)?;
    let summary = PyDict::new(py);
    for t in &r.summary {
        summary.set_item(&t.name, tip_summary(py, t)?)?;
    }
    out.set_item("summary", summary)?;
    // The lines `softgrip run` prints that do not depend on the wall clock.
    let mut lines = vec![format!(
        "scene {}: {} steps of {:.6} s",
        r.origin, r.total, r.dt
    )];
    lines.extend(r.summary.iter().map(|t| format!("fingertip {t}")));
    out.set_item("summary_lines", PyList::new(py, lines)?)?;
    out.set_item("digest", r.digest.to_string())?;
    out.set_item("wall_time", r.wall)?;
    match r.recording {
        None => out.set_item("recording", py.None())?,
        Some(rec) => {
            let d = PyDict::new(py);
            d.set_item("path", rec.path.display().to_string())?;
            d.set_item("frames", rec.frames)?;
            d.set_item("messages", rec.messages)?;
            d.set_item("chunks", rec.chunks)?;
            d.set_item("bytes", rec.bytes)?;
            d.set_item("every", rec.every)?;
            out.set_item("recording", d)?;
        }
    }
    Ok(out)
}

/// Runs a scene: `path` (a scene file), or `toml` (scene text; relative paths in it are
/// relative to `base_dir`, default the current directory), or neither (the embedded default
/// grasp). Records to `mcap` if given (every `every`-th step, default the scene's
/// `record.every_n_steps`); an existing file is replaced only with `overwrite`. Returns a
/// dict: the per-step readout, the summary, the contact digest.
#[pyfunction]
#[pyo3(signature = (path = None, *, toml = None, base_dir = None, mcap = None, every = None, overwrite = false))]
pub fn run_scene<'py>(
    py: Python<'py>,
    path: Option<PathBuf>,
    toml: Option<String>,
    base_dir: Option<PathBuf>,
    mcap: Option<PathBuf>,
    every: Option<i64>,
    overwrite: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let source = match (path, toml) {
        (Some(_), Some(_)) => {
            return Err(parameter(
                py,
                "toml",
                "a scene text",
                "None when a scene path is given (one of the two)",
            ));
        }
        (Some(p), None) => Source::File(p),
        (None, Some(t)) => Source::Text(t, base_dir.unwrap_or_else(|| PathBuf::from("."))),
        (None, None) => Source::Default,
    };
    let every = match every {
        None => None,
        Some(n) if n >= 1 => Some(n as u64),
        Some(n) => {
            return Err(parameter(
                py,
                "every",
                n,
                "an integer >= 1 (1 = every step)",
            ));
        }
    };
    if let Some(out) = &mcap {
        if let Source::File(scene) = &source
            && std::fs::canonicalize(out).ok() == std::fs::canonicalize(scene).ok()
            && out.exists()
        {
            return Err(parameter(
                py,
                "mcap",
                out.display(),
                "a path other than the scene file",
            ));
        }
        if out.exists() && !overwrite {
            return Err(pyo3::exceptions::PyFileExistsError::new_err(format!(
                "{}: exists; pass overwrite=True to replace it",
                out.display()
            )));
        }
    }
    let mut interrupted = None;
    let result = py.detach(|| simulate(&source, mcap.as_deref(), every, &mut interrupted));
    let data = match result {
        Ok(d) => d,
        Err(Failure::Scene(e)) => return Err(scene_error(py, &e)),
        Err(Failure::Recording(m)) => {
            return Err(raise(py, "RecordingError", m, Some("mcap"), None));
        }
    };
    if let Some(e) = interrupted {
        // The recording is finished; the interrupt goes on to the caller.
        return Err(e);
    }
    to_python(py, data)
}
