//! `softgrip.run(...)`: a scene through the same bevy_ecs schedule as `softgrip run` (with
//! its summary and, optionally, its MCAP recording), with the per-step readout of every
//! fingertip, body and robot joint kept as arrays.

use std::path::{Path, PathBuf};
use std::time::Instant;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use softgrip_ecs::bevy_ecs::entity::Entity;
use softgrip_ecs::softgrip_rapier::StepError;
use softgrip_ecs::to_record::{JointMemory, joint_rates, joint_samples};
use softgrip_ecs::{
    Controllers, McapSink, Physics, Scene, SceneError, SimClock, Simulation, Summary, TipSummary,
};
use softgrip_record::JointSample;
use softgrip_scene::{ContactDigest, DEFAULT_SCENE};

use crate::args;
use crate::errors::{diverged, parameter, raise, scene_error};
use crate::readout::{BodySeries, JointTable, TactileSeries, TipSeries};

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
    tactile: Vec<Option<TactileSeries>>,
    body_names: Vec<String>,
    bodies: Vec<BodySeries>,
    joints: JointTable,
    summary: Vec<TipSummary>,
    digest: ContactDigest,
    wall: f64,
    recording: Option<Recording>,
    /// The step error that stopped the run, if one did (`steps` were taken before it).
    fault: Option<StepError>,
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
    let mut tactile: Vec<Option<TactileSeries>> = tip_entities.iter().map(|_| None).collect();
    let mut joints = JointReader::default();
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
        if sim.fault().is_some() {
            // The failed step is not read out (nor recorded: the schedule stops at a fault).
            break;
        }
        steps += 1;
        let physics = sim.world.resource::<Physics>();
        let contacts = physics.world.soft.contacts();
        digest.add_step(contacts.iter());
        read_tips(physics, &tip_entities, &mut tips);
        read_tactile(physics, &tip_entities, &mut tactile);
        read_bodies(physics, &body_entities, &mut bodies);
        joints.read(&sim);
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
        tactile,
        body_names: f.bodies.iter().map(|b| b.name.clone()).collect(),
        bodies,
        joints: joints.table,
        summary: summary.tips.iter().map(|(_, t)| t.clone()).collect(),
        digest,
        wall,
        recording,
        fault: sim.fault().cloned(),
    })
}

/// Appends each fingertip's readout of the last step (its contacts' readings with their
/// contact radius, [`TipSeries::push_step`]).
fn read_tips(physics: &Physics, entities: &[Entity], tips: &mut [TipSeries]) {
    let mut rows: Vec<Vec<_>> = tips.iter().map(|_| Vec::new()).collect();
    for c in physics.world.soft.contacts() {
        let Some(k) = physics
            .collider_entity(c.fingertip)
            .and_then(|e| entities.iter().position(|&t| t == e))
        else {
            continue;
        };
        rows[k].push((&c.reading, c.patch().radius));
    }
    for (t, r) in tips.iter_mut().zip(rows) {
        t.push_step(r);
    }
}

/// Reads the robots' joints after each step as the recorder does (the same samples, the same
/// velocities: the rate of motion since the last step, `to_record::joint_rates`).
#[derive(Default)]
struct JointReader {
    table: JointTable,
    memory: Option<JointMemory>,
    states: Vec<JointSample>,
    commands: Vec<JointSample>,
}

impl JointReader {
    /// Appends the joints' states and commands after the last step (nothing in a scene without
    /// robots).
    fn read(&mut self, sim: &Simulation) {
        let Some(control) = sim.world.get_resource::<Controllers>() else {
            return;
        };
        if control.0.robots().is_empty() {
            return;
        }
        let physics = sim.world.resource::<Physics>();
        let time = sim.world.resource::<SimClock>().time;
        joint_samples(&control.0, physics, &mut self.states, &mut self.commands);
        joint_rates(time, &mut self.memory, &mut self.states);
        self.table.push_samples(&self.states, &self.commands);
    }
}

/// Appends each tactile pad's image of the last step (pressures as `f32`, as recorded).
fn read_tactile(physics: &Physics, entities: &[Entity], tactile: &mut [Option<TactileSeries>]) {
    for (handle, image) in physics.world.soft.tactile_images() {
        let Some(k) = physics
            .collider_entity(handle)
            .and_then(|e| entities.iter().position(|&t| t == e))
        else {
            continue;
        };
        let (rows, columns) = (
            image.grid().rows() as usize,
            image.grid().columns() as usize,
        );
        let series = tactile[k].get_or_insert_with(|| TactileSeries::new(rows, columns));
        series.push(image.pressure().iter().map(|&p| p as f32));
    }
}

/// Appends each body's pose after the last step (NaN for a body rapier does not have).
fn read_bodies(physics: &Physics, entities: &[Entity], bodies: &mut [BodySeries]) {
    for (b, &e) in bodies.iter_mut().zip(entities) {
        let rb = physics
            .body_handle(e)
            .and_then(|h| physics.world.physics.bodies.get(h));
        match rb {
            Some(rb) => {
                let t = rb.translation();
                let q = rb.rotation();
                b.push(
                    [f64::from(t.x), f64::from(t.y), f64::from(t.z)],
                    [
                        f64::from(q.x),
                        f64::from(q.y),
                        f64::from(q.z),
                        f64::from(q.w),
                    ],
                );
            }
            None => b.push([f64::NAN; 3], [f64::NAN; 4]),
        }
    }
}

fn tip_summary<'py>(py: Python<'py>, t: &TipSummary) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("peak_force", t.peak_force)?;
    d.set_item("peak_x", t.peak_x)?;
    d.set_item("peak_radius", t.peak_radius)?;
    d.set_item("slips", t.slips)?;
    d.set_item("validity_excursions", t.validity_excursions)?;
    d.set_item("excursion_time", t.excursion_time)?;
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
    let tactile = PyDict::new(py);
    for ((name, t), image) in r.tip_names.iter().zip(r.tips).zip(r.tactile) {
        tips.set_item(name, t.into_py(py)?)?;
        if let Some(image) = image {
            tactile.set_item(name, image.into_py(py))?;
        }
    }
    out.set_item("fingertips", tips)?;
    out.set_item("tactile", tactile)?;
    let bodies = PyDict::new(py);
    for (name, b) in r.body_names.iter().zip(r.bodies) {
        bodies.set_item(name, b.into_py(py)?)?;
    }
    out.set_item("bodies", bodies)?;
    out.set_item("joints", r.joints.into_py(py)?)?;
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
#[pyo3(signature = (path = None, *, toml = None, base_dir = None, mcap = None, every = None, overwrite = None))]
#[allow(clippy::too_many_arguments)]
pub fn run_scene<'py>(
    py: Python<'py>,
    path: Option<&Bound<'py, PyAny>>,
    toml: Option<&Bound<'py, PyAny>>,
    base_dir: Option<&Bound<'py, PyAny>>,
    mcap: Option<&Bound<'py, PyAny>>,
    every: Option<&Bound<'py, PyAny>>,
    overwrite: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let path = args::opt_path(path, "scene")?;
    let toml = match toml.filter(|t| !t.is_none()) {
        Some(t) => Some(args::text(t, "toml", "scene TOML text (a str)")?),
        None => None,
    };
    let base_dir = args::opt_path(base_dir, "base_dir")?;
    let mcap = args::opt_path(mcap, "mcap")?;
    let overwrite = args::opt_flag(overwrite, "overwrite")?;
    let every = match every.filter(|e| !e.is_none()) {
        Some(e) => Some(args::bounded(
            e,
            "every",
            1..=u64::MAX,
            "ParameterError",
            "an integer >= 1 (1 = every step)",
        )?),
        None => None,
    };
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
            let shown = out.display().to_string();
            return Err(raise(
                py,
                "RecordingExistsError",
                format!("{shown}: exists; pass overwrite=True to replace it"),
                Some("mcap"),
                Some(shown),
            ));
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
    let fault = data.fault.clone();
    let result = to_python(py, data)?;
    match fault {
        // The recording is finished; the readout up to the fault goes with the exception.
        Some(e) => Err(diverged(py, &e, result.into_any())),
        None => Ok(result),
    }
}
