//! A recording's messages sorted into steps: per fingertip the [`TipSeries`] a run returns
//! (from the `SoftContactArray` of each step), per body its poses (from `/tf`), per tactile
//! pad its images, per robot joint its state and command (from `/joint_states` and
//! `/joint_commands`), and every contact row; vectors and poses turned into the axes asked for.

use std::collections::BTreeMap;

use numpy::IntoPyArray;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use softgrip_record::frames::{UpAxis, mul};
use softgrip_record::msgs::sensor_msgs::JointState;
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_record::{Message, Recording, RecordingInfo, WORLD_FRAME, topics};

use softgrip_record::ContactReading;

use crate::readout::{BodySeries, JointTable, TactileSeries, TipSeries, matrix};

/// The axes vectors and poses are returned in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// The scene's own axes (y-up for scene files), as `softgrip.run` returns them.
    Scene,
    /// The recording's world frame, z-up (REP 103).
    World,
}

impl Frame {
    /// `scene` or `world`.
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "scene" => Some(Frame::Scene),
            "world" => Some(Frame::World),
            _ => None,
        }
    }
}

/// From the recorded axes to the wanted ones: recordings since 2026-12-02 are z-up (a y-up
/// scene turned by [`UpAxis::Y`]); earlier ones hold the scene's own axes.
#[derive(Debug, Clone, Copy)]
pub struct Axes {
    z_up: bool,
    want: Frame,
}

impl Axes {
    /// `z_up`: whether the file was recorded z-up.
    pub fn new(z_up: bool, want: Frame) -> Self {
        Self { z_up, want }
    }

    /// `scene` or `world`.
    pub fn frame_name(&self) -> &'static str {
        match self.want {
            Frame::Scene => "scene",
            Frame::World => "world",
        }
    }

    /// A recorded vector in the wanted axes (exact: a permutation with a sign).
    pub fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        match (self.z_up, self.want) {
            // world (x, y, z) = scene (x, -z, y), so scene = (x, z, -y)
            (true, Frame::Scene) => [v[0], v[2], -v[1]],
            (false, Frame::World) => UpAxis::Y.vector(v),
            _ => v,
        }
    }

    /// A recorded orientation `[x, y, z, w]` in the wanted axes.
    pub fn rotation(&self, q: [f64; 4]) -> [f64; 4] {
        match (self.z_up, self.want) {
            (true, Frame::Scene) => {
                let [x, y, z, w] = UpAxis::Y.to_world();
                mul([-x, -y, -z, w], q)
            }
            (false, Frame::World) => UpAxis::Y.rotation(q),
            _ => q,
        }
    }
}

/// Every contact row of the recording, column by column (the `SoftContact` fields).
#[derive(Default)]
pub struct ContactRows {
    step: Vec<i64>,
    fingertip: Vec<String>,
    other: Vec<String>,
    point: Vec<f64>,
    normal: Vec<f64>,
    friction_force: Vec<f64>,
    columns: BTreeMap<&'static str, Vec<f64>>,
    level: Vec<u8>,
    level_name: Vec<String>,
    backing: Vec<u8>,
    validity_exceeded: Vec<bool>,
    sliding: Vec<bool>,
}

impl ContactRows {
    fn push(&mut self, step: i64, c: &SoftContactMsg, axes: Axes) {
        self.step.push(step);
        self.fingertip.push(c.fingertip.clone());
        self.other.push(c.other.clone());
        let v = |p: [f64; 3]| axes.vector(p);
        self.point.extend(v([c.point.x, c.point.y, c.point.z]));
        self.normal.extend(v([c.normal.x, c.normal.y, c.normal.z]));
        let f = &c.friction_force;
        self.friction_force.extend(v([f.x, f.y, f.z]));
        for (name, value) in [
            ("compression", c.compression),
            ("ratio_x", c.ratio_x),
            ("normal_force", c.normal_force),
            ("torsional_moment", c.torsional_moment),
            ("contact_radius", c.contact_radius),
            ("mean_pressure", c.mean_pressure),
            ("peak_pressure", c.peak_pressure),
            ("stiffness", c.stiffness),
            ("peak_normal_force", c.peak_normal_force),
            ("max_compression", c.max_compression),
            ("contact_duration", c.contact_duration),
            ("core_thickness", c.core_thickness),
        ] {
            self.columns.entry(name).or_default().push(value);
        }
        self.level.push(c.level);
        self.level_name.push(c.level_name.clone());
        self.backing.push(c.backing);
        self.validity_exceeded.push(c.validity_exceeded);
        self.sliding.push(c.sliding);
    }

    /// The columns as a dict of numpy arrays (text columns as lists of str).
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        let n = self.step.len();
        d.set_item("step", self.step.into_pyarray(py))?;
        d.set_item("fingertip", self.fingertip)?;
        d.set_item("other", self.other)?;
        d.set_item("point", matrix(py, self.point, 3))?;
        d.set_item("normal", matrix(py, self.normal, 3))?;
        d.set_item("friction_force", matrix(py, self.friction_force, 3))?;
        for name in ContactRows::FLOAT_COLUMNS {
            let values = self.columns.get(name).cloned().unwrap_or_default();
            debug_assert!(values.is_empty() || values.len() == n);
            d.set_item(name, values.into_pyarray(py))?;
        }
        d.set_item("level", self.level.into_pyarray(py))?;
        d.set_item("level_name", self.level_name)?;
        d.set_item("backing", self.backing.into_pyarray(py))?;
        d.set_item("validity_exceeded", self.validity_exceeded.into_pyarray(py))?;
        d.set_item("sliding", self.sliding.into_pyarray(py))?;
        Ok(d)
    }

    /// The float columns besides the vectors, in `SoftContact.msg` order.
    const FLOAT_COLUMNS: [&'static str; 12] = [
        "compression",
        "ratio_x",
        "normal_force",
        "torsional_moment",
        "contact_radius",
        "mean_pressure",
        "peak_pressure",
        "stiffness",
        "peak_normal_force",
        "max_compression",
        "contact_duration",
        "core_thickness",
    ];
}

/// The recording sorted into its recorded steps.
pub struct Steps {
    /// The axes of the vectors and poses.
    pub axes: Axes,
    /// Step number (1-based, as `RunResult.time[step - 1]`) of each recorded step.
    pub step: Vec<i64>,
    /// Simulated time at the end of each recorded step [s] (`step * dt`).
    pub time: Vec<f64>,
    /// The MCAP log time of each recorded step [ns].
    pub log_time_ns: Vec<u64>,
    /// Fingertip names (scene order when the metadata has the laws).
    pub tip_names: Vec<String>,
    /// Per fingertip, one entry per recorded step.
    pub tips: Vec<TipSeries>,
    /// Tactile pads by fingertip name.
    pub tactile: Vec<(String, TactileSeries)>,
    /// Body names (order of first appearance on `/tf`).
    pub body_names: Vec<String>,
    /// Per body, one pose per recorded step.
    pub bodies: Vec<BodySeries>,
    /// Every robot joint, one entry per recorded step.
    pub joints: JointTable,
    /// Every contact row.
    pub rows: ContactRows,
}

/// Index of `name` in `names`, appended if new.
fn index_of(names: &mut Vec<String>, name: &str) -> usize {
    names.iter().position(|n| n == name).unwrap_or_else(|| {
        names.push(name.to_owned());
        names.len() - 1
    })
}

/// What one recorded step holds.
#[derive(Default)]
struct StepMessages<'a> {
    /// Whether the step's `SoftContactArray` is there (it may hold no contact).
    has_contacts: bool,
    contacts: Vec<&'a SoftContactMsg>,
    tf: Vec<&'a TFMessage>,
    images: Vec<(&'a str, Vec<f32>, usize, usize)>,
    joint_states: Vec<&'a JointState>,
    joint_commands: Vec<&'a JointState>,
}

impl Steps {
    /// Sorts `rec`'s messages (contacts, `/tf`, tactile images, clock) into steps.
    pub fn collect(rec: &Recording, info: Option<&RecordingInfo>, axes: Axes) -> Self {
        let mut by_time: BTreeMap<u64, StepMessages<'_>> = BTreeMap::new();
        for m in &rec.messages {
            let wanted = matches!(m.message, Message::Contacts(_) | Message::Clock(_))
                || matches!(m.message, Message::Tf(_) if m.topic == topics::TF)
                || matches!(m.message, Message::Image(_) if m.topic.ends_with("/tactile"))
                || matches!(m.message, Message::JointState(_)
                    if m.topic == topics::JOINT_STATES || m.topic == topics::JOINT_COMMANDS);
            if !wanted {
                continue;
            }
            let step = by_time.entry(m.log_time_ns).or_default();
            match &m.message {
                Message::Contacts(c) => {
                    step.has_contacts = true;
                    step.contacts.extend(&c.contacts);
                }
                Message::Tf(t) => step.tf.push(t),
                Message::Image(i) => {
                    let (rows, columns) = (i.height as usize, i.width as usize);
                    step.images
                        .push((m.topic.as_str(), i.pixels_f32(), rows, columns));
                }
                Message::JointState(j) if m.topic == topics::JOINT_STATES => {
                    step.joint_states.push(j);
                }
                Message::JointState(j) => step.joint_commands.push(j),
                _ => {}
            }
        }
        // Every recorded step has its contact array; a step without one is the cut-off end of
        // a killed writer's file (its other messages in a kept chunk, the contacts in the
        // lost one): it is not a recorded step.
        if by_time.values().any(|s| s.has_contacts) {
            by_time.retain(|_, s| s.has_contacts);
        }
        let dt = info.map_or(0.0, |i| i.dt);
        let tip_names: Vec<String> = info
            .map(|i| i.law.iter().map(|l| l.name.clone()).collect())
            .unwrap_or_default();
        let mut steps = Steps {
            axes,
            step: Vec::new(),
            time: Vec::new(),
            log_time_ns: Vec::new(),
            tips: tip_names.iter().map(|_| TipSeries::default()).collect(),
            tip_names,
            tactile: Vec::new(),
            body_names: Vec::new(),
            bodies: Vec::new(),
            joints: JointTable::default(),
            rows: ContactRows::default(),
        };
        for (k, (&ns, msgs)) in by_time.iter().enumerate() {
            let (step, time) = step_and_time(ns, dt, k);
            steps.step.push(step);
            steps.time.push(time);
            steps.log_time_ns.push(ns);
            steps.push_contacts(k, step, &msgs.contacts);
            steps.push_poses(k, &msgs.tf);
            steps.push_images(k, &msgs.images);
            steps.joints.push_step(
                joint_rows(&msgs.joint_states),
                joint_rows(&msgs.joint_commands),
            );
        }
        steps
    }

    /// Step `k`'s contacts: each fingertip's [`TipSeries`] and the contact rows.
    fn push_contacts(&mut self, k: usize, step: i64, contacts: &[&SoftContactMsg]) {
        let mut rows: Vec<Vec<(ContactReading, f64)>> = vec![Vec::new(); self.tips.len()];
        for c in contacts {
            self.rows.push(step, c, self.axes);
            let t = index_of(&mut self.tip_names, &c.fingertip);
            while self.tips.len() <= t {
                // A fingertip first seen now had no contact in the earlier steps.
                let mut series = TipSeries::default();
                (0..k).for_each(|_| series.push_step([]));
                self.tips.push(series);
            }
            rows.resize(self.tips.len(), Vec::new());
            rows[t].push((contact_reading(c, self.axes), c.contact_radius));
        }
        rows.resize(self.tips.len(), Vec::new());
        for (series, r) in self.tips.iter_mut().zip(rows) {
            series.push_step(r.iter().map(|(c, a)| (c, *a)));
        }
    }

    /// Step `k`'s body poses: the world's children on `/tf` (NaN for a body not there).
    fn push_poses(&mut self, k: usize, tf: &[&TFMessage]) {
        // Before the z-up recordings, /tf listed each fingertip's frame (by its name) before
        // the bodies: the first frame of a fingertip's name in a message is the fingertip's.
        let tips_on_tf = !self.axes.z_up;
        let mut poses: Vec<Option<([f64; 3], [f64; 4])>> = vec![None; self.bodies.len()];
        for message in tf {
            let mut seen_tips: Vec<&str> = Vec::new();
            for t in &message.transforms {
                let child = t.child_frame_id.as_str();
                if t.header.frame_id != WORLD_FRAME {
                    continue;
                }
                let is_tip = self.tip_names.iter().any(|n| n == child);
                if tips_on_tf && is_tip && !seen_tips.contains(&child) {
                    seen_tips.push(child);
                    continue;
                }
                let b = index_of(&mut self.body_names, child);
                while self.bodies.len() <= b {
                    let mut series = BodySeries::default();
                    (0..k).for_each(|_| series.push([f64::NAN; 3], [f64::NAN; 4]));
                    self.bodies.push(series);
                }
                poses.resize(self.bodies.len(), None);
                let (p, q) = (&t.transform.translation, &t.transform.rotation);
                poses[b] = Some((
                    self.axes.vector([p.x, p.y, p.z]),
                    self.axes.rotation([q.x, q.y, q.z, q.w]),
                ));
            }
        }
        poses.resize(self.bodies.len(), None);
        for (series, pose) in self.bodies.iter_mut().zip(poses) {
            let (p, q) = pose.unwrap_or(([f64::NAN; 3], [f64::NAN; 4]));
            series.push(p, q);
        }
    }

    /// Step `k`'s tactile images, by topic (NaN for a pad without one in this step).
    fn push_images(&mut self, k: usize, images: &[(&str, Vec<f32>, usize, usize)]) {
        let mut filled = vec![false; self.tactile.len()];
        for (topic, pixels, rows, columns) in images {
            let name = (self.tip_names.iter())
                .find(|n| topics::tactile(n) == *topic)
                .cloned()
                .unwrap_or_else(|| topic_token(topic));
            let j = match self.tactile.iter().position(|(n, _)| *n == name) {
                Some(j) => j,
                None => {
                    let mut series = TactileSeries::new(*rows, *columns);
                    (0..k).for_each(|_| series.push([]));
                    self.tactile.push((name, series));
                    filled.push(false);
                    self.tactile.len() - 1
                }
            };
            if self.tactile[j].1.fits(*rows, *columns) && !filled[j] {
                self.tactile[j].1.push(pixels.iter().copied());
                filled[j] = true;
            }
        }
        for ((_, series), done) in self.tactile.iter_mut().zip(filled) {
            if !done {
                series.push([]);
            }
        }
    }
}

/// The step number and time of a step recorded at `ns`: with the time step, `round(t / dt)`
/// and `step dt` (what a run's `time` holds; stamps are `round(step dt 1e9)` ns); without it
/// (another writer), the ordinal `k + 1` and the log time.
fn step_and_time(ns: u64, dt: f64, k: usize) -> (i64, f64) {
    let t = ns as f64 * 1e-9;
    if dt > 0.0 && dt * 1e9 >= 1.0 {
        let step = (t / dt).round();
        (step as i64, step * dt)
    } else {
        (k as i64 + 1, t)
    }
}

/// The joints of `messages` as `(name, [position, velocity, effort])` (a value a message leaves
/// out, as `sensor_msgs/JointState` allows, reads NaN).
fn joint_rows<'a>(messages: &[&'a JointState]) -> Vec<(&'a str, [f64; 3])> {
    let at = |v: &[f64], i: usize| v.get(i).copied().unwrap_or(f64::NAN);
    (messages.iter())
        .flat_map(|m| {
            (m.name.iter().enumerate()).map(move |(i, n)| {
                (
                    n.as_str(),
                    [at(&m.position, i), at(&m.velocity, i), at(&m.effort, i)],
                )
            })
        })
        .collect()
}

/// `/softgrip/<token>/tactile` -> `<token>`.
fn topic_token(topic: &str) -> String {
    topic
        .trim_start_matches("/softgrip/")
        .trim_end_matches("/tactile")
        .to_owned()
}

/// A recorded contact as the law's reading (`SoftContactMsg::reading`, the one conversion
/// back from a message), its vectors turned into the wanted axes.
fn contact_reading(c: &SoftContactMsg, axes: Axes) -> ContactReading {
    let mut r = c.reading();
    for v in [
        &mut r.point,
        &mut r.normal,
        &mut r.friction_force,
        &mut r.patch_direction,
    ] {
        *v = axes.vector(*v);
    }
    r
}
