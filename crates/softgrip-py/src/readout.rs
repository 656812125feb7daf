//! The per-step arrays a run returns and a recording opens as, filled the same way from both:
//! a fingertip's contacts of a step (each the law's plain `ContactReading` with its contact
//! radius) become one entry of each of its arrays ([`TipSeries`]), a body's pose one row
//! ([`BodySeries`]), a tactile pad's image one slice ([`TactileSeries`]). `softgrip.run` fills
//! them from the plugin's readings (`TipContact::reading`), and `softgrip.open_recording` from
//! the recorded messages read back as readings (`SoftContactMsg::reading`), so both give the
//! same keys, shapes, dtypes and values. A robot's joints ([`JointTable`]) are filled from the
//! samples the recorder writes (`softgrip_ecs::to_record::joint_samples`) in a run and from
//! `/joint_states` and `/joint_commands` in a recording.

use numpy::IntoPyArray;
use numpy::ndarray::{Array2, Array3};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use softgrip_record::{ContactReading, JointSample};

/// One fingertip's arrays, one entry per step: forces and stiffness summed over its
/// contacts, the deepest contact's compression and contact radius.
#[derive(Default)]
pub struct TipSeries {
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

impl TipSeries {
    /// Appends one step made of `rows`: the fingertip's contacts in that step (maybe none),
    /// each its reading (vectors in the axes returned) and its contact radius a \[m\].
    pub fn push_step<'a>(&mut self, rows: impl IntoIterator<Item = (&'a ContactReading, f64)>) {
        let mut force = 0.0;
        let mut friction = [0.0; 3];
        let mut moment = 0.0;
        let mut stiffness = 0.0;
        let mut peak = 0.0f64;
        let mut count = 0i64;
        let (mut sliding, mut exceeded) = (false, false);
        let mut deepest: Option<(&ContactReading, f64)> = None;
        for (c, radius) in rows {
            force += c.normal_force;
            for (f, cf) in friction.iter_mut().zip(c.friction_force) {
                *f += cf;
            }
            moment += c.torsional_moment;
            stiffness += c.stiffness;
            peak = peak.max(c.peak_normal_force);
            count += 1;
            sliding |= c.sliding;
            exceeded |= c.validity_exceeded;
            if deepest.is_none_or(|(d, _)| c.delta > d.delta) {
                deepest = Some((c, radius));
            }
        }
        self.force.push(force);
        self.friction_force.extend_from_slice(&friction);
        self.torsional_moment.push(moment);
        let (delta, x, radius) = deepest.map_or((0.0, 0.0, 0.0), |(c, a)| (c.delta, c.x, a));
        self.delta.push(delta);
        self.x.push(x);
        self.radius.push(radius);
        self.stiffness.push(stiffness);
        self.peak_force.push(peak);
        self.contacts.push(count);
        self.sliding.push(sliding);
        self.validity_exceeded.push(exceeded);
    }

    /// The arrays as a dict of numpy arrays (the keys of `RunResult.fingertips[name]`).
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("force", self.force.into_pyarray(py))?;
        d.set_item("friction_force", matrix(py, self.friction_force, 3))?;
        d.set_item("torsional_moment", self.torsional_moment.into_pyarray(py))?;
        d.set_item("delta", self.delta.into_pyarray(py))?;
        d.set_item("x", self.x.into_pyarray(py))?;
        d.set_item("radius", self.radius.into_pyarray(py))?;
        d.set_item("stiffness", self.stiffness.into_pyarray(py))?;
        d.set_item("peak_force", self.peak_force.into_pyarray(py))?;
        d.set_item("contacts", self.contacts.into_pyarray(py))?;
        d.set_item("sliding", self.sliding.into_pyarray(py))?;
        d.set_item("validity_exceeded", self.validity_exceeded.into_pyarray(py))?;
        Ok(d)
    }
}

/// One body's pose, one row per step (scene axes; NaN where the body was not there).
#[derive(Default)]
pub struct BodySeries {
    position: Vec<f64>,
    rotation: Vec<f64>,
}

impl BodySeries {
    /// Appends a pose: position [m] and unit quaternion `[x, y, z, w]`.
    pub fn push(&mut self, position: [f64; 3], rotation: [f64; 4]) {
        self.position.extend(position);
        self.rotation.extend(rotation);
    }

    /// The arrays as a dict: `position` (n, 3) and `rotation` (n, 4).
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("position", matrix(py, self.position, 3))?;
        d.set_item("rotation", matrix(py, self.rotation, 4))?;
        Ok(d)
    }
}

/// One tactile pad's images, one per step: taxel pressures [Pa] as `f32` (as recorded),
/// row-major from the pad's top-left taxel.
pub struct TactileSeries {
    rows: usize,
    columns: usize,
    pressure: Vec<f32>,
}

impl TactileSeries {
    /// An empty series of a `rows` x `columns` pad.
    pub fn new(rows: usize, columns: usize) -> Self {
        Self {
            rows,
            columns,
            pressure: Vec::new(),
        }
    }

    /// Whether an image of `rows` x `columns` fits this pad.
    pub fn fits(&self, rows: usize, columns: usize) -> bool {
        (self.rows, self.columns) == (rows, columns)
    }

    /// Appends one image (`rows * columns` pressures, row-major).
    pub fn push(&mut self, pressure: impl IntoIterator<Item = f32>) {
        let before = self.pressure.len();
        self.pressure.extend(pressure);
        // A short or long image (another writer's) is padded or cut to the pad's size.
        self.pressure
            .resize(before + self.rows * self.columns, f32::NAN);
    }

    /// The images as a float32 array (steps, rows, columns).
    pub fn into_py(self, py: Python<'_>) -> Bound<'_, PyAny> {
        let steps = self.pressure.len() / (self.rows * self.columns).max(1);
        Array3::from_shape_vec((steps, self.rows, self.columns), self.pressure)
            .expect("invariant: rows x columns values per image")
            .into_pyarray(py)
            .into_any()
    }
}

/// The keys of a joint's arrays (`softgrip.JOINT_ARRAYS`): its state, then its command.
const JOINT_KEYS: [&str; 6] = [
    "position",
    "velocity",
    "effort",
    "target_position",
    "target_velocity",
    "effort_limit",
];

/// One joint's arrays, one entry per step, in [`JOINT_KEYS`] order: its state and its command
/// (NaN where the step has none: a joint without a motor has no command).
struct JointSeries([Vec<f64>; 6]);

impl JointSeries {
    /// `steps` entries of NaN (a joint first seen after them).
    fn missing(steps: usize) -> Self {
        Self(std::array::from_fn(|_| vec![f64::NAN; steps]))
    }

    fn push(&mut self, state: Option<[f64; 3]>, command: Option<[f64; 3]>) {
        let [p, v, e] = state.unwrap_or([f64::NAN; 3]);
        let [tp, tv, limit] = command.unwrap_or([f64::NAN; 3]);
        for (column, x) in self.0.iter_mut().zip([p, v, e, tp, tv, limit]) {
            column.push(x);
        }
    }
}

/// A joint's `[position, velocity, effort]` in a step (a command's effort: its force limit).
type Values = [f64; 3];

/// Every robot joint's arrays, by name in order of first appearance (the recorder's order:
/// robot by robot, joint by joint), one entry per step.
#[derive(Default)]
pub struct JointTable {
    names: Vec<String>,
    series: Vec<JointSeries>,
    steps: usize,
}

impl JointTable {
    /// Appends one step: the joints' states and commands as `(name, [position, velocity,
    /// effort])` (a command's effort is its force limit). A joint absent from a step reads NaN
    /// there.
    pub fn push_step<'a>(
        &mut self,
        states: impl IntoIterator<Item = (&'a str, [f64; 3])>,
        commands: impl IntoIterator<Item = (&'a str, [f64; 3])>,
    ) {
        let mut rows: Vec<(Option<Values>, Option<Values>)> = vec![(None, None); self.names.len()];
        for (command, (name, values)) in
            (states.into_iter().map(|s| (false, s))).chain(commands.into_iter().map(|c| (true, c)))
        {
            let k = match self.names.iter().position(|n| n == name) {
                Some(k) => k,
                None => {
                    self.names.push(name.to_owned());
                    self.series.push(JointSeries::missing(self.steps));
                    rows.push((None, None));
                    self.names.len() - 1
                }
            };
            let slot = if command {
                &mut rows[k].1
            } else {
                &mut rows[k].0
            };
            // The first of a name in a step counts (a well-formed step names a joint once).
            slot.get_or_insert(values);
        }
        for (series, (state, command)) in self.series.iter_mut().zip(rows) {
            series.push(state, command);
        }
        self.steps += 1;
    }

    /// Appends one step of the recorder's samples ([`JointSample`]).
    pub fn push_samples(&mut self, states: &[JointSample], commands: &[JointSample]) {
        fn row(j: &JointSample) -> (&str, [f64; 3]) {
            (j.name.as_str(), [j.position, j.velocity, j.effort])
        }
        self.push_step(states.iter().map(row), commands.iter().map(row));
    }

    /// The arrays as a dict by joint name (the keys of `RunResult.joints[name]`).
    pub fn into_py(self, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
        let out = PyDict::new(py);
        for (name, s) in self.names.iter().zip(self.series) {
            let d = PyDict::new(py);
            for (key, column) in JOINT_KEYS.iter().zip(s.0) {
                d.set_item(key, column.into_pyarray(py))?;
            }
            out.set_item(name, d)?;
        }
        Ok(out)
    }
}

/// `values` as an (n, width) float64 array.
pub fn matrix(py: Python<'_>, values: Vec<f64>, width: usize) -> Bound<'_, PyAny> {
    let rows = values.len() / width;
    Array2::from_shape_vec((rows, width), values)
        .expect("invariant: width values per step")
        .into_pyarray(py)
        .into_any()
}
