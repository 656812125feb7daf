//! [`McapSink`]: the [`StepSink`] that writes a run to an MCAP file with softgrip-record's
//! [`Recorder`](softgrip_record::Recorder), and [`FingertipLaw`], the per-fingertip law
//! parameters it writes in the metadata (and that `softgrip plot` reads back).

use std::collections::BTreeMap;
use std::fmt;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use softgrip_law::{ContactLaw, ContactParams, Level, Material};
use softgrip_rapier::SoftFingertip;
use softgrip_record::msgs::geometry_msgs::{Point, Vector3, Wrench};
use softgrip_record::msgs::softgrip_msgs::SoftContact;
use softgrip_record::{
    BodyPose, FingertipState, RUN_SUMMARY_NAME, Recorder, RecorderOptions, RecordingInfo,
    RecordingStats, StepRecord,
};

use crate::scene::Scene;
use crate::sink::{ContactSample, SinkError, StepFrame, StepSink};

/// Name of the world frame (the `/tf` root) in softgrip's recordings.
pub const WORLD_FRAME: &str = "world";

/// A fingertip's law as recorded in the `law` metadata value, one line per fingertip:
/// `NAME: level=auto tolerance=0.01 youngs_modulus=590000 poisson_ratio=0.49 radius=0.01
/// friction=0.8 restitution=0.5`.
#[derive(Debug, Clone, PartialEq)]
pub struct FingertipLaw {
    /// Fingertip name.
    pub name: String,
    /// The level as configured (with its setting: `k`, `tolerance` or `match_x`).
    pub level: Level,
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson ratio nu [-].
    pub poisson_ratio: f64,
    /// Radius R [m].
    pub radius: f64,
    /// Coulomb friction coefficient [-].
    pub friction: f64,
    /// Coefficient of restitution e [-].
    pub restitution: f64,
}

impl FingertipLaw {
    /// The law parameters of a fingertip.
    pub fn of(tip: &SoftFingertip) -> Self {
        let m = tip.material();
        Self {
            name: tip.name().to_string(),
            level: tip.level(),
            youngs_modulus: m.youngs_modulus(),
            poisson_ratio: m.poisson_ratio(),
            radius: tip.radius(),
            friction: tip.friction(),
            restitution: tip.restitution(),
        }
    }

    /// The law (fails only for parameters no scene could have had).
    pub fn law(&self) -> Result<ContactLaw, softgrip_law::Error> {
        self.law_at(self.level)
    }

    /// The same fingertip with another level (for overlays: Hertz, Tatara, ...).
    pub fn law_at(&self, level: Level) -> Result<ContactLaw, softgrip_law::Error> {
        let material = Material::try_new(self.youngs_modulus, self.poisson_ratio)?;
        ContactLaw::try_new(ContactParams::try_new(material, self.radius)?, level)
    }

    /// Parses one line written by `Display`.
    pub fn parse(line: &str) -> Result<Self, String> {
        let (name, rest) = line
            .rsplit_once(": level=")
            .ok_or_else(|| format!("no `: level=` in `{line}`"))?;
        let mut fields = BTreeMap::new();
        let mut words = rest.split_whitespace();
        let level_name = words.next().ok_or("no level")?;
        for w in words {
            let (k, v) = w
                .split_once('=')
                .ok_or_else(|| format!("`{w}` is not key=value"))?;
            let v: f64 = v.parse().map_err(|_| format!("`{w}`: not a number"))?;
            fields.insert(k, v);
        }
        let get = |k: &str| {
            fields
                .get(k)
                .copied()
                .ok_or_else(|| format!("no `{k}=` in `{line}`"))
        };
        let mut level: Level = level_name.parse()?;
        match &mut level {
            Level::Fit { k } => *k = get("k")?,
            Level::Auto { tolerance } => *tolerance = get("tolerance")?,
            Level::Linear { match_x } => *match_x = get("match_x")?,
            _ => {}
        }
        Ok(Self {
            name: name.to_string(),
            level,
            youngs_modulus: get("youngs_modulus")?,
            poisson_ratio: get("poisson_ratio")?,
            radius: get("radius")?,
            friction: get("friction")?,
            restitution: get("restitution")?,
        })
    }

    /// Parses the `law` metadata value (one line per fingertip).
    pub fn parse_all(text: &str) -> Result<Vec<Self>, String> {
        text.lines()
            .filter(|l| !l.trim().is_empty())
            .map(Self::parse)
            .collect()
    }
}

impl fmt::Display for FingertipLaw {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: level={}", self.name, self.level.name())?;
        match self.level {
            Level::Fit { k } => write!(f, " k={k}")?,
            Level::Auto { tolerance } => write!(f, " tolerance={tolerance}")?,
            Level::Linear { match_x } => write!(f, " match_x={match_x}")?,
            _ => {}
        }
        write!(
            f,
            " youngs_modulus={} poisson_ratio={} radius={} friction={} restitution={}",
            self.youngs_modulus, self.poisson_ratio, self.radius, self.friction, self.restitution
        )
    }
}

/// Where a fingertip sits on its body, to place its `/tf` frame and marker.
#[derive(Debug, Clone)]
struct TipMount {
    name: String,
    body: String,
    offset: [f64; 3],
    radius: f64,
}

fn tip_mounts(scene: &Scene) -> Vec<TipMount> {
    scene
        .file()
        .fingertips
        .iter()
        .map(|t| TipMount {
            name: t.name.clone(),
            body: t.body.clone(),
            offset: t.offset,
            radius: t.radius,
        })
        .collect()
}

/// Turns the ECS's [`StepFrame`]s into the messages of a step ([`StepRecord`]): what the MCAP
/// recorder writes and the ROS 2 publisher sends, converted by one function for both.
#[derive(Debug, Clone)]
pub struct StepConverter {
    tips: Vec<TipMount>,
}

impl StepConverter {
    /// The converter of a scene (it needs where each fingertip is mounted).
    pub fn for_scene(scene: &Scene) -> Self {
        Self {
            tips: tip_mounts(scene),
        }
    }

    /// Fills `step` from `frame`, reusing its allocations.
    pub fn convert(&self, frame: &StepFrame, step: &mut StepRecord) {
        convert(&self.tips, frame, step);
    }
}

/// An error of the [`McapSink`].
#[derive(Debug, thiserror::Error)]
pub enum McapSinkError {
    /// The recorder failed (I/O, encoding); later steps were not written.
    #[error(transparent)]
    Record(#[from] softgrip_record::Error),
    /// The writer thread could not be started.
    #[error("starting the MCAP writer thread: {0}")]
    Spawn(#[source] std::io::Error),
    /// The writer thread panicked (the file is finished by the recorder's `Drop` if it can be).
    #[error("the MCAP writer thread panicked")]
    WriterPanicked,
    /// `write` after `finish`, or after an error was already returned.
    #[error("the MCAP recording was already finished")]
    Finished,
}

/// Writes a run to MCAP: `/clock`, `/tf`, `/softgrip/contacts`, one
/// `/softgrip/<fingertip>/wrench` per fingertip and `/softgrip/markers`, every
/// `record.every_n_steps`-th step (see softgrip-record's README for the topics), and a
/// `softgrip` metadata record with `scene` (the scene file's text), `law` (one
/// [`FingertipLaw`] line per fingertip), `softgrip_version`, `origin`, `dt` and
/// `every_n_steps`.
///
/// The [`Recorder`] runs on its own writer thread: `write` converts the frame into a
/// [`StepRecord`] and queues it; every 16 steps the batch goes over an unbounded channel (it
/// never blocks and never drops a step); the thread encodes and writes it. An error of the writer thread is returned by the
/// next `write` or by `finish`.
///
/// The file is finished by [`StepSink::finish`] (or [`close`](Self::close)), or by `Drop` (a
/// panic that unwinds through the run): both close the channel, let the thread write every
/// queued step and finish the file, and wait for it. A killed process keeps every closed
/// chunk.
pub struct McapSink {
    /// Batches of steps to the writer thread (`None` once finished).
    tx: Option<Sender<Vec<StepRecord>>>,
    /// Steps converted but not yet sent (sent every [`BATCH`] steps, and by `close`).
    batch: Vec<StepRecord>,
    /// Written batches back from the writer thread, to reuse their allocations (in a `Mutex`
    /// only to make the sink `Sync`; always reached through `get_mut`).
    spent: Mutex<Receiver<Vec<StepRecord>>>,
    /// Steps to fill.
    pool: Vec<StepRecord>,
    writer: Option<JoinHandle<Result<RecordingStats, softgrip_record::Error>>>,
    /// Set by the writer thread when it stops on an error.
    failed: Arc<AtomicBool>,
    every_n_steps: u64,
    tips: Vec<TipMount>,
    report: Arc<Mutex<McapReport>>,
    /// The run's summary, written by the writer thread just before it finishes the file.
    run_summary: Arc<Mutex<Option<BTreeMap<String, String>>>>,
}

/// What the sink did, readable while the sink is owned by the world
/// ([`McapSink::report_handle`]).
#[derive(Debug, Clone, Default)]
pub struct McapReport {
    /// Steps written to the file (by the writer thread).
    pub frames_written: u64,
    /// Wall-clock time the simulation spent in `write` (converting the frame and queueing
    /// it) [s].
    pub write_time: Duration,
    /// Wall-clock time the writer thread spent encoding and writing steps (MCAP, chunks) [s].
    pub writer_time: Duration,
    /// The counts of the finished file (after `finish`).
    pub stats: Option<RecordingStats>,
}

impl fmt::Debug for McapSink {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("McapSink")
            .field("finished", &self.tx.is_none())
            .field("every_n_steps", &self.every_n_steps)
            .finish()
    }
}

/// Steps sent to the writer thread at once: one wake-up of the thread per batch, not per step
/// (a batch not yet sent is sent by `finish` and `Drop`; a killed process loses it with the
/// open chunk).
const BATCH: usize = 16;

/// Locks the report (a poisoned report is still a report: it only holds counters).
fn lock(report: &Mutex<McapReport>) -> std::sync::MutexGuard<'_, McapReport> {
    report.lock().unwrap_or_else(|e| e.into_inner())
}

/// The writer thread: writes every step it receives until the channel closes, then finishes
/// the file. On an error it sets `failed` and stops (the recorder's `Drop` finishes the file).
fn writer_loop(
    mut recorder: Recorder,
    batches: &Receiver<Vec<StepRecord>>,
    spent: &Sender<Vec<StepRecord>>,
    report: &Mutex<McapReport>,
    failed: &AtomicBool,
    run_summary: &Mutex<Option<BTreeMap<String, String>>>,
) -> Result<RecordingStats, softgrip_record::Error> {
    for mut batch in batches {
        let start = Instant::now();
        for step in &mut batch {
            if let Err(e) = recorder.write_step(step) {
                failed.store(true, Ordering::SeqCst);
                return Err(e);
            }
        }
        let elapsed = start.elapsed();
        {
            let mut r = lock(report);
            r.frames_written += batch.len() as u64;
            r.writer_time += elapsed;
        }
        // The simulation may have stopped listening: then the batch is simply dropped.
        let _ = spent.send(batch);
    }
    let summary = run_summary
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .take();
    if let Some(summary) = summary
        && let Err(e) = recorder.write_metadata(RUN_SUMMARY_NAME, summary)
    {
        failed.store(true, Ordering::SeqCst);
        return Err(e);
    }
    match recorder.finish() {
        Ok(stats) => {
            lock(report).stats = Some(stats);
            Ok(stats)
        }
        Err(e) => {
            failed.store(true, Ordering::SeqCst);
            Err(e)
        }
    }
}

impl McapSink {
    /// Creates `path` for `scene`; `scene_text` is the scene file's text (for the metadata).
    /// Records every `scene.file().record.every_n_steps`-th step.
    pub fn create(
        path: impl AsRef<Path>,
        scene: &Scene,
        scene_text: &str,
    ) -> Result<Self, softgrip_record::Error> {
        let n = scene.file().record.every_n_steps;
        Self::with_options(path, scene, scene_text, n, &RecorderOptions::default())
    }

    /// [`create`](Self::create) writing every `every_n_steps`-th step (0 is taken as 1), with
    /// the recorder's options (chunk size, compression; `compression_threads` is ignored: the
    /// writer thread compresses).
    pub fn with_options(
        path: impl AsRef<Path>,
        scene: &Scene,
        scene_text: &str,
        every_n_steps: u64,
        options: &RecorderOptions,
    ) -> Result<Self, softgrip_record::Error> {
        let file = scene.file();
        let every_n_steps = every_n_steps.max(1);
        let law = scene
            .fingertips()
            .iter()
            .zip(&file.fingertips)
            .map(|(t, spec)| {
                let mut law = FingertipLaw::of(t);
                law.name.clone_from(&spec.name);
                law.to_string()
            })
            .collect::<Vec<_>>()
            .join("\n");
        let mut extra = BTreeMap::new();
        extra.insert("origin".to_string(), scene.origin().to_string());
        extra.insert("dt".to_string(), file.dt.to_string());
        extra.insert("every_n_steps".to_string(), every_n_steps.to_string());
        extra.insert("steps".to_string(), scene.steps().to_string());
        let info = RecordingInfo {
            scene: scene_text.to_string(),
            law,
            extra,
        };
        let path = path.as_ref();
        // The writer thread is already beside the simulation: it compresses the chunks itself
        // (a zstd worker would be a third thread competing for the cores).
        let options = RecorderOptions {
            compression_threads: 0,
            ..options.clone()
        };
        let recorder = Recorder::with_options(path, &info, &options)?;
        let tips = tip_mounts(scene);
        let report: Arc<Mutex<McapReport>> = Arc::default();
        let failed = Arc::new(AtomicBool::new(false));
        let (tx, batches) = mpsc::channel::<Vec<StepRecord>>();
        let (spent_tx, spent) = mpsc::channel::<Vec<StepRecord>>();
        let run_summary: Arc<Mutex<Option<BTreeMap<String, String>>>> = Arc::default();
        let writer = {
            let report = Arc::clone(&report);
            let failed = Arc::clone(&failed);
            let run_summary = Arc::clone(&run_summary);
            std::thread::Builder::new()
                .name("softgrip-mcap".into())
                .spawn(move || {
                    writer_loop(
                        recorder,
                        &batches,
                        &spent_tx,
                        &report,
                        &failed,
                        &run_summary,
                    )
                })
                .map_err(|source| softgrip_record::Error::Io {
                    path: path.to_path_buf(),
                    source,
                })?
        };
        Ok(Self {
            tx: Some(tx),
            batch: Vec::with_capacity(BATCH),
            spent: Mutex::new(spent),
            pool: Vec::new(),
            writer: Some(writer),
            failed,
            every_n_steps,
            tips,
            report,
            run_summary,
        })
    }

    /// A handle on what the sink did (steps written, time spent, the finished file's counts).
    pub fn report_handle(&self) -> Arc<Mutex<McapReport>> {
        Arc::clone(&self.report)
    }

    /// Records step `step` (steps `n`, `2n`, ... of `every_n_steps = n`).
    pub fn records_step(&self, step: u64) -> bool {
        step.is_multiple_of(self.every_n_steps)
    }

    /// Closes the channel, waits for the writer thread to write every queued step and finish
    /// the file, and returns the file's counts (or the writer's error). Further calls (and
    /// `write`s) return [`McapSinkError::Finished`].
    pub fn close(&mut self) -> Result<RecordingStats, McapSinkError> {
        if let Some(tx) = self.tx.take()
            && !self.batch.is_empty()
        {
            // If the thread is gone, joining it below says why.
            let _ = tx.send(std::mem::take(&mut self.batch));
        }
        let writer = self.writer.take().ok_or(McapSinkError::Finished)?;
        match writer.join() {
            Ok(Ok(stats)) => Ok(stats),
            Ok(Err(e)) => Err(McapSinkError::Record(e)),
            Err(_) => Err(McapSinkError::WriterPanicked),
        }
    }

    /// Queues one frame for the writer thread.
    fn send(&mut self, frame: &StepFrame) -> Result<(), McapSinkError> {
        if self.failed.load(Ordering::SeqCst) {
            return Err(self.close().err().unwrap_or(McapSinkError::Finished));
        }
        let Some(tx) = self.tx.as_ref() else {
            return Err(McapSinkError::Finished);
        };
        if self.pool.is_empty() {
            let spent = self.spent.get_mut().unwrap_or_else(|e| e.into_inner());
            if let Ok(steps) = spent.try_recv() {
                self.pool = steps;
            }
        }
        let mut step = self.pool.pop().unwrap_or_else(|| StepRecord {
            world_frame: WORLD_FRAME.to_string(),
            ..StepRecord::default()
        });
        convert(&self.tips, frame, &mut step);
        self.batch.push(step);
        if self.batch.len() < BATCH {
            return Ok(());
        }
        let full = std::mem::replace(&mut self.batch, Vec::with_capacity(BATCH));
        if tx.send(full).is_err() {
            // The writer thread is gone: its error (or panic) says why.
            return Err(self.close().err().unwrap_or(McapSinkError::Finished));
        }
        Ok(())
    }
}

impl Drop for McapSink {
    /// Finishes the file if `finish` was not called (also while a panic unwinds): every queued
    /// step is written first. Errors are ignored here: call `finish` to see them.
    fn drop(&mut self) {
        if self.writer.is_some() {
            let _ = self.close();
        }
    }
}

/// Fills `s` from a frame (reusing its allocations).
fn convert(tips: &[TipMount], frame: &StepFrame, s: &mut StepRecord) {
    s.time_ns = (frame.time * 1e9).round() as u64;
    s.bodies.truncate(frame.bodies.len());
    for (i, b) in frame.bodies.iter().enumerate() {
        match s.bodies.get_mut(i) {
            Some(p) => {
                p.name.clone_from(&b.name);
                p.position = b.translation;
                p.orientation = b.rotation;
            }
            None => s.bodies.push(BodyPose {
                name: b.name.clone(),
                position: b.translation,
                orientation: b.rotation,
            }),
        }
    }
    s.fingertips.truncate(frame.wrenches.len());
    for (i, w) in frame.wrenches.iter().enumerate() {
        let mount = tips
            .iter()
            .find(|t| t.name == w.fingertip)
            .or_else(|| tips.get(i));
        let (position, orientation, radius) = match mount {
            Some(m) => {
                let body = frame.bodies.iter().find(|b| b.name == m.body);
                let (p, q) = body.map_or(([0.0; 3], [0.0, 0.0, 0.0, 1.0]), |b| {
                    (b.translation, b.rotation)
                });
                let o = rotate(q, m.offset);
                ([p[0] + o[0], p[1] + o[1], p[2] + o[2]], q, m.radius)
            }
            None => ([0.0; 3], [0.0, 0.0, 0.0, 1.0], 0.0),
        };
        let wrench = Wrench {
            force: Vector3::from_array(w.force),
            torque: Vector3::from_array(w.torque),
        };
        match s.fingertips.get_mut(i) {
            Some(t) => {
                t.name.clone_from(&w.fingertip);
                t.position = position;
                t.orientation = orientation;
                t.radius = radius;
                t.wrench = wrench;
            }
            None => s.fingertips.push(FingertipState {
                name: w.fingertip.clone(),
                position,
                orientation,
                radius,
                wrench,
            }),
        }
    }
    s.contacts.clear();
    s.contacts.extend(frame.contacts.iter().map(soft_contact));
}

/// A contact of the frame as a `softgrip_msgs/SoftContact` (header set by the recorder).
pub fn soft_contact(c: &ContactSample) -> SoftContact {
    let k = &c.contact;
    let patch = c.patch.unwrap_or(softgrip_law::ContactPatch::EMPTY);
    let [px, py, pz] = k.point;
    let mut m = SoftContact {
        fingertip: c.fingertip.clone(),
        other: c.other.clone(),
        point: Point {
            x: px,
            y: py,
            z: pz,
        },
        normal: Vector3::from_array(k.normal),
        compression: k.delta,
        ratio_x: k.x,
        normal_force: k.normal_force,
        friction_force: Vector3::from_array(k.friction_force),
        torsional_moment: k.torsional_moment,
        contact_radius: patch.radius,
        mean_pressure: patch.mean_pressure,
        peak_pressure: patch.peak_pressure,
        stiffness: k.stiffness,
        sliding: k.sliding,
        peak_normal_force: k.peak_normal_force,
        max_compression: k.max_delta,
        contact_duration: k.contact_duration,
        ..SoftContact::default()
    };
    m.set_level(k.level);
    m.validity_exceeded = k.validity_exceeded;
    m
}

/// `q v q*` for a unit quaternion `[x, y, z, w]`.
fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let [x, y, z, w] = q;
    // t = 2 (q_v x v); v' = v + w t + q_v x t
    let t = [
        2.0 * (y * v[2] - z * v[1]),
        2.0 * (z * v[0] - x * v[2]),
        2.0 * (x * v[1] - y * v[0]),
    ];
    [
        v[0] + w * t[0] + (y * t[2] - z * t[1]),
        v[1] + w * t[1] + (z * t[0] - x * t[2]),
        v[2] + w * t[2] + (x * t[1] - y * t[0]),
    ]
}

impl StepSink for McapSink {
    fn wants(&self, step: u64) -> bool {
        self.records_step(step)
    }

    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        if !self.records_step(frame.step) {
            return Ok(());
        }
        let start = Instant::now();
        let sent = self.send(frame);
        let elapsed = start.elapsed();
        lock(&self.report).write_time += elapsed;
        Ok(sent?)
    }

    fn run_summary(&mut self, summary: &BTreeMap<String, String>) {
        *self
            .run_summary
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(summary.clone());
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if self.writer.is_none() {
            return Ok(());
        }
        self.close()?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn law_line_round_trips() {
        for level in [
            Level::auto(),
            Level::fit(),
            Level::Hertz,
            Level::Linear { match_x: 0.05 },
        ] {
            let law = FingertipLaw {
                name: "left tip".into(),
                level,
                youngs_modulus: 5.9e5,
                poisson_ratio: 0.49,
                radius: 0.01,
                friction: 0.8,
                restitution: 0.5,
            };
            assert_eq!(FingertipLaw::parse(&law.to_string()), Ok(law));
        }
    }

    #[test]
    fn rotate_by_quarter_turn_about_z() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let v = rotate([0.0, 0.0, h, h], [1.0, 0.0, 0.0]);
        assert!((v[0]).abs() < 1e-12 && (v[1] - 1.0).abs() < 1e-12);
    }
}
