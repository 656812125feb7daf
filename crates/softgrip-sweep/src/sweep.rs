//! [`Sweep`]: a checked sweep file; its trials, each one a scene (the base scene with the
//! trial's values set, checked by the scene's own validation), run one by index
//! ([`Sweep::run_trial`]: what a Ray task or an array job calls) or all in parallel
//! ([`Sweep::run`]).

use std::io::Read;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use rayon::prelude::*;
use softgrip_ecs::{BodyKind, Scene, SceneError};
use softgrip_scene::same_file;
use softgrip_scene::softgrip_rapier::softgrip_law::shorten_numbers;

use crate::axis::{Axis, grid_indices, trial_count};
use crate::error::SweepError;
use crate::file::SweepFile;
use crate::shard::Shard;
use crate::table::{ResultsTable, TrialRow};
use crate::trial::run_scene;
use crate::value::Value;

/// How [`Sweep::run`] runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RunOptions {
    /// Worker threads, one trial each at a time; 0 = one per core (rayon's default); at most
    /// [`max_threads`].
    pub threads: usize,
    /// The slice of the trials to run ([`Shard::WHOLE`] by default).
    pub shard: Shard,
}

/// Worker threads per core at most: trials are CPU-bound, so threads beyond the cores only
/// take memory and time to start (`--threads 100000` spent minutes spawning threads).
pub const THREADS_PER_CORE: usize = 4;

/// The largest [`RunOptions::threads`]: [`THREADS_PER_CORE`] times the cores this process may
/// use (`std::thread::available_parallelism`; 1 if unknown).
pub fn max_threads() -> usize {
    THREADS_PER_CORE * std::thread::available_parallelism().map_or(1, |n| n.get())
}

impl RunOptions {
    /// [`SweepError::Options`] naming `threads` unless it is 0 or in 1..=[`max_threads`].
    pub fn check(&self) -> Result<(), SweepError> {
        check_threads(self.threads)
    }
}

/// [`SweepError::Options`] naming `threads` unless `threads` is 0 (one per core) or in
/// 1..=[`max_threads`].
pub fn check_threads(threads: usize) -> Result<(), SweepError> {
    let max = max_threads();
    if threads <= max {
        return Ok(());
    }
    Err(SweepError::Options {
        option: "threads",
        value: threads.to_string(),
        expected: format!(
            "0 (one per core) or in 1..={max} ({THREADS_PER_CORE} per core of the {} this process may use)",
            max / THREADS_PER_CORE
        ),
    })
}

/// A checked sweep: the base scene, the object, the axes. A `Sweep` that exists has a valid
/// base scene with a gripper and an object, and every varied field names a field of the
/// scene's format with a value of its type (values out of range are the trials' errors).
#[derive(Debug, Clone)]
pub struct Sweep {
    origin: String,
    /// The files the sweep reads: the sweep file (when read from one), the base scene, its
    /// meshes and curves.
    inputs: Vec<PathBuf>,
    scene_origin: String,
    scene_dir: PathBuf,
    base: toml::Table,
    object: String,
    mcap_dir: Option<PathBuf>,
    axes: Vec<Axis>,
    trials: u64,
}

impl Sweep {
    /// Reads and checks a sweep file (its scene is relative to it): at most
    /// [`MAX_SWEEP_BYTES`], read once (a pipe works), a leading byte-order mark skipped.
    pub fn from_path(path: &Path) -> Result<Self, SweepError> {
        let io = |source| SweepError::Io {
            path: path.to_path_buf(),
            source,
        };
        let mut bytes = Vec::new();
        std::fs::File::open(path)
            .and_then(|f| f.take(MAX_SWEEP_BYTES + 1).read_to_end(&mut bytes))
            .map_err(io)?;
        if bytes.len() as u64 > MAX_SWEEP_BYTES {
            return Err(io(std::io::Error::other(format!(
                "larger than the {} MiB limit of a sweep file",
                MAX_SWEEP_BYTES >> 20
            ))));
        }
        let text = String::from_utf8(bytes)
            .map_err(|e| io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let mut sweep = Self::parse(&text, &path.display().to_string(), &base)?;
        sweep.inputs.insert(0, path.to_path_buf());
        Ok(sweep)
    }

    /// Checks sweep TOML text whose relative paths (`scene`, `mcap_dir`) are relative to
    /// `base_dir` (for bindings that hold the text; errors name it `<sweep>`).
    #[allow(clippy::should_implement_trait)]
    pub fn from_str(text: &str, base_dir: &Path) -> Result<Self, SweepError> {
        Self::parse(text, "<sweep>", base_dir)
    }

    /// Checks sweep TOML text; `origin` names it in errors.
    pub fn parse(text: &str, origin: &str, base_dir: &Path) -> Result<Self, SweepError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let file: SweepFile = toml::from_str(text).map_err(|e| {
            let (line, column) = e
                .span()
                .map(|s| line_column(text, s.start))
                .unwrap_or((0, 0));
            SweepError::Parse {
                origin: origin.to_string(),
                line,
                column,
                message: shorten_numbers(e.message().trim()),
            }
        })?;
        let scene_err = |message: String| SweepError::Scene {
            origin: origin.to_string(),
            message,
        };
        let invalid = |field: String, value: String, expected: String| SweepError::Invalid {
            origin: origin.to_string(),
            field,
            value,
            expected,
        };
        let scene_path = base_dir.join(&file.scene);
        let (scene, scene_text) = read_base_scene(&scene_path).map_err(scene_err)?;
        let base: toml::Table = toml::from_str(&scene_text)
            .map_err(|e| scene_err(format!("{}: {e}", scene_path.display())))?;
        if !scene.controllers().iter().any(|c| c.grasp().is_some()) {
            return Err(scene_err(format!(
                "{}: has no [gripper] and no `grasp` controller: a sweep's `held` is decided by the grasp's hold",
                scene_path.display()
            )));
        }
        let object = object(&scene, file.object.as_deref()).map_err(scene_err)?;
        let axes = (file.vary.iter().enumerate())
            .map(|(k, v)| Axis::from_spec(k, v).map_err(|(f, v, e)| invalid(f, v, e)))
            .collect::<Result<Vec<_>, _>>()?;
        for (k, a) in axes.iter().enumerate() {
            if let Some(j) = axes[..k].iter().position(|b| b.path == a.path) {
                return Err(invalid(
                    format!("vary[{k}].field"),
                    format!("{:?}", a.path.as_str()),
                    format!("a field not varied already (it is `vary[{j}].field`)"),
                ));
            }
        }
        let trials = trial_count(&axes).ok_or_else(|| {
            let sizes: Vec<String> = axes.iter().map(|a| a.values.len().to_string()).collect();
            invalid(
                "vary".into(),
                format!("{} trials", sizes.join(" x ")),
                format!("at most {} trials", crate::axis::MAX_TRIALS),
            )
        })?;
        let scene_dir = scene_path
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        let inputs = input_files(&scene_path, &scene, &scene_dir, &axes);
        let sweep = Self {
            origin: origin.to_string(),
            inputs,
            scene_origin: scene_path.display().to_string(),
            scene_dir,
            base,
            object,
            mcap_dir: file.mcap_dir.as_ref().map(|d| base_dir.join(d)),
            axes,
            trials,
        };
        sweep.check_fields()?;
        Ok(sweep)
    }

    /// Each varied field, set alone to its first value, must give a scene that parses and whose
    /// names refer to something: a misspelt field, a value of the wrong type or a joint, robot
    /// or link name the scene does not have is the sweep's error, not every trial's.
    /// (A value out of its range is left to the trials: it is a row with the error.)
    fn check_fields(&self) -> Result<(), SweepError> {
        for (k, a) in self.axes.iter().enumerate() {
            let invalid = |expected: String| SweepError::Invalid {
                origin: self.origin.clone(),
                field: format!("vary[{k}].field"),
                value: format!("{:?}", a.path.as_str()),
                expected,
            };
            let mut t = self.base.clone();
            a.path
                .set(&mut t, a.values[0].to_toml())
                .map_err(|m| invalid(format!("a field of the base scene: {m}")))?;
            let text = toml::to_string(&t).map_err(|e| invalid(e.to_string()))?;
            match Scene::parse(&text, &self.scene_origin, &self.scene_dir) {
                Err(SceneError::Parse { message, .. }) => {
                    return Err(invalid(format!(
                        "a scene field taking {} values: {message}",
                        a.values[0]
                    )));
                }
                // A name that refers to nothing (a robot's joint, a controller's robot, a
                // fingertip's link) is the sweep's error: every trial would have it.
                Err(SceneError::Name { field, message, .. }) => {
                    return Err(invalid(format!(
                        "a field naming what the scene has (with {}, `{field}`: {message})",
                        a.values[0]
                    )));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// Number of trials (the product of the axes' lengths; 1 without `[[vary]]`).
    pub fn trials(&self) -> u64 {
        self.trials
    }

    /// The axes, in `[[vary]]` order.
    pub fn axes(&self) -> &[Axis] {
        &self.axes
    }

    /// The varied fields' paths (the results' column names between `trial` and `held`).
    pub fn fields(&self) -> Vec<String> {
        self.axes
            .iter()
            .map(|a| a.path.as_str().to_string())
            .collect()
    }

    /// The files the sweep reads, which no output may replace: the sweep file (when read with
    /// [`from_path`](Self::from_path)), the base scene, its meshes and measured curves, and
    /// every string value of an axis that names an existing file relative to the base scene
    /// (a varied curve or mesh).
    pub fn input_files(&self) -> &[PathBuf] {
        &self.inputs
    }

    /// The body whose hold decides `held`.
    pub fn object(&self) -> &str {
        &self.object
    }

    /// The sweep file (or `<sweep>`).
    pub fn origin(&self) -> &str {
        &self.origin
    }

    /// Where trial `index`'s MCAP recording goes, if the sweep records.
    pub fn mcap_path(&self, index: u64) -> Option<PathBuf> {
        (self.mcap_dir.as_ref()).map(|d| d.join(format!("trial-{index:06}.mcap")))
    }

    fn check_index(&self, index: u64) -> Result<(), SweepError> {
        if index < self.trials {
            Ok(())
        } else {
            Err(SweepError::Invalid {
                origin: self.origin.clone(),
                field: "trial".into(),
                value: index.to_string(),
                expected: format!("in 0..{} (the sweep's trials)", self.trials),
            })
        }
    }

    /// The value of each varied field in trial `index` (< [`trials`](Self::trials)).
    pub fn values(&self, index: u64) -> Result<Vec<Value>, SweepError> {
        self.check_index(index)?;
        let at = grid_indices(&self.axes, index);
        Ok((self.axes.iter().zip(at))
            .map(|(a, j)| a.values[j].clone())
            .collect())
    }

    /// Trial `index`'s scene as TOML text: the base scene with the trial's values set.
    pub fn scene_text(&self, index: u64) -> Result<String, SweepError> {
        let values = self.values(index)?;
        let mut t = self.base.clone();
        for (a, v) in self.axes.iter().zip(&values) {
            a.path
                .set(&mut t, v.to_toml())
                .expect("invariant: every path was set in the base scene by check_fields");
        }
        Ok(toml::to_string(&t).expect("invariant: a TOML table serialises"))
    }

    /// Trial `index`'s scene, checked by the scene's own validation: `Ok(Err(..))` is the
    /// trial's error (it names the field, e.g. `fingertip[0].material.youngs_modulus`).
    pub fn scene(&self, index: u64) -> Result<Result<(Scene, String), SceneError>, SweepError> {
        let text = self.scene_text(index)?;
        let origin = format!("{} (trial {index})", self.scene_origin);
        Ok(Scene::parse(&text, &origin, &self.scene_dir).map(|s| (s, text)))
    }

    /// Runs trial `index`: its row. A bad trial (a value out of range, a panic, a hold that did
    /// not end) is a row with its error; `Err` only for an index past the sweep's trials.
    pub fn run_trial(&self, index: u64) -> Result<TrialRow, SweepError> {
        let start = Instant::now();
        let values = self.values(index)?;
        let scene = self.scene(index)?;
        let mcap = self.mcap_path(index);
        let outcome = match scene {
            Err(e) => Err(e.to_string()),
            Ok((scene, text)) => catch_unwind(AssertUnwindSafe(|| {
                if let Some(path) = &mcap
                    && let Some(input) = self.inputs.iter().find(|i| same_file(path, i))
                {
                    return Err(format!(
                        "the recording {} would replace the sweep's input {}: choose another `mcap_dir`",
                        path.display(),
                        input.display()
                    ));
                }
                if let Some(dir) = &self.mcap_dir {
                    std::fs::create_dir_all(dir)
                        .map_err(|e| format!("creating {}: {e}", dir.display()))?;
                }
                run_scene(&scene, &text, &self.object, mcap.as_deref())
            }))
            .unwrap_or_else(|panic| Err(format!("the trial panicked: {}", panic_text(&panic)))),
        };
        Ok(TrialRow {
            trial: index,
            values,
            outcome,
            wall_time: start.elapsed().as_secs_f64(),
        })
    }

    /// An empty results table with this sweep's columns.
    pub fn table(&self) -> ResultsTable {
        ResultsTable {
            fields: self.fields(),
            kinds: self.axes.iter().map(Axis::kind).collect(),
            rows: Vec::new(),
        }
    }

    /// Runs the trials of `options.shard` on `options.threads` threads; `progress(done,
    /// total)` is called after each trial (from the worker threads). The rows are in trial
    /// order whatever the threads did.
    pub fn run(
        &self,
        options: &RunOptions,
        progress: &(dyn Fn(u64, u64) + Sync),
    ) -> Result<ResultsTable, SweepError> {
        self.run_until(options, progress, &|| false)
    }

    /// [`run`](Self::run), stopping early once `stop()` is true (a signal: `softgrip sweep`
    /// passes its SIGINT/SIGTERM/SIGHUP flag): trials already running finish, no trial starts
    /// after it, and the table holds every finished trial's row, in trial order (the trials
    /// not run are absent, not error rows).
    pub fn run_until(
        &self,
        options: &RunOptions,
        progress: &(dyn Fn(u64, u64) + Sync),
        stop: &(dyn Fn() -> bool + Sync),
    ) -> Result<ResultsTable, SweepError> {
        options.check()?;
        let range = options.shard.range(self.trials);
        let total = range.end - range.start;
        let done = AtomicU64::new(0);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(options.threads)
            .build()
            .map_err(|e| SweepError::Shard {
                value: options.shard.to_string(),
                message: format!("cannot start {} threads: {e}", options.threads),
            })?;
        let rows = pool.install(|| {
            range
                .into_par_iter()
                .filter_map(|i| {
                    if stop() {
                        return None;
                    }
                    let row = self.run_trial(i);
                    progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
                    Some(row)
                })
                .collect::<Result<Vec<_>, _>>()
        })?;
        let mut table = self.table();
        table.rows = rows;
        Ok(table)
    }
}

/// The base scene, its meshes and curves, and every string value of an axis that names an
/// existing file relative to the base scene (a varied curve or mesh), each once.
fn input_files(scene_path: &Path, scene: &Scene, scene_dir: &Path, axes: &[Axis]) -> Vec<PathBuf> {
    let mut files = vec![scene_path.to_path_buf()];
    let texts = (axes.iter().flat_map(|a| &a.values)).filter_map(|v| match v {
        Value::Text(t) => Some(scene_dir.join(t)),
        _ => None,
    });
    for p in scene
        .input_files()
        .into_iter()
        .chain(texts.filter(|p| p.is_file()))
    {
        if !files.contains(&p) {
            files.push(p);
        }
    }
    files
}

/// Largest sweep file read \[bytes\] (16 MiB).
pub const MAX_SWEEP_BYTES: u64 = 16 << 20;

/// The base scene and its text, read once. It must be a regular file: a FIFO named as the
/// base scene would block the read forever.
fn read_base_scene(path: &Path) -> Result<(Scene, String), String> {
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if !meta.is_file() {
        return Err(format!(
            "{}: not a regular file (a directory, FIFO or device): the base scene must be a file",
            path.display()
        ));
    }
    Scene::from_file_with_text(path).map_err(|e| e.to_string())
}

/// The body that decides `held`: `named`, or the scene's only dynamic body.
fn object(scene: &Scene, named: Option<&str>) -> Result<String, String> {
    let bodies = &scene.file().bodies;
    match named {
        Some(name) => match bodies.iter().find(|b| b.name == name) {
            Some(b) if b.kind == BodyKind::Dynamic => Ok(name.to_string()),
            Some(_) => Err(format!("`object` = {name:?} is not a dynamic body")),
            None => Err(format!(
                "`object` = {name:?}: no body of the scene has that name"
            )),
        },
        None => {
            let dynamic: Vec<&str> = (bodies.iter())
                .filter(|b| b.kind == BodyKind::Dynamic)
                .map(|b| b.name.as_str())
                .collect();
            match dynamic[..] {
                [one] => Ok(one.to_string()),
                _ => Err(format!(
                    "the scene has {} dynamic bodies ({}): name the grasped one with `object = \"NAME\"`",
                    dynamic.len(),
                    dynamic.join(", ")
                )),
            }
        }
    }
}

/// A panic's message.
fn panic_text(panic: &Box<dyn std::any::Any + Send>) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".to_string())
}

/// Line and column (from 1) of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
