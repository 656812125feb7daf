//! [`StepConverter`]: a sink's [`StepFrame`] to the messages of a step ([`StepRecord`]),
//! converted by one function for the MCAP recorder and the ROS 2 publisher alike.

use std::collections::HashMap;
use std::sync::Arc;

use softgrip_law::ContactPatch;

pub use crate::frames::WORLD_FRAME;
use crate::frames::{FrameNames, UpAxis, rotate, rotate_inverse};
use crate::msgs::geometry_msgs::{Point, Quaternion, Transform, TransformStamped, Vector3, Wrench};
use crate::msgs::sensor_msgs::{Image, JointState};
use crate::msgs::softgrip_msgs::SoftContactMsg;
use crate::msgs::std_msgs::Header;
use crate::msgs::std_msgs::StringMsg;
use crate::msgs::tf2_msgs::TFMessage;
use crate::msgs::visualization_msgs::Marker;
use crate::sink::{
    BodyFrame, BodySample, ContactSample, FingertipInfo, JointSample, SceneInfo, StepFrame,
    TactileSample, WrenchSample,
};
use crate::step::{BodyPose, FingertipState, StepRecord};
use crate::visuals;

/// Where a fingertip sits on its body, to place its `/tf` frame and marker.
#[derive(Debug, Clone)]
struct TipMount {
    name: String,
    frame: String,
    body: String,
    /// The index of `body` in the scene's bodies (where a frame's poses normally list it).
    body_hint: usize,
    offset: [f64; 3],
    radius: f64,
    arrow_scale: f64,
    facing: Option<[f64; 3]>,
}

/// Turns [`StepFrame`]s into the messages of a step ([`StepRecord`]): what the MCAP recorder
/// writes and the ROS 2 publisher sends.
///
/// What is recorded is z-up under the fixed root [`WORLD_FRAME`] (REP 103): every position,
/// orientation and vector of the frame (scene axes, [`SceneInfo::up`]) is rotated into world
/// axes here, once. Bodies are children of the world on `/tf`; each fingertip is a child of its
/// body ([`fingertip_frame`](crate::frames::fingertip_frame)), its constant offset on `/tf_static`, which the first converted
/// step carries. Wrenches are in the fingertip's frame. Stamps are `round(step · dt · 1e9)` ns
/// from the f64 step index and `dt` (the frame's `time` only when `dt` is unknown).
#[derive(Debug, Clone, Default)]
pub struct StepConverter {
    tips: Vec<TipMount>,
    /// The index in `tips` of each fingertip's name (the first, if two had one name).
    tip_index: HashMap<String, usize>,
    up: UpAxis,
    dt: f64,
    shapes: Arc<[Marker]>,
    /// `/tf_static` (the fingertips' frames; the fixed links' are added from the first step),
    /// until a step has carried it.
    tf_static: Option<TFMessage>,
    /// The robots' descriptions, until a step has carried them.
    descriptions: Vec<(String, StringMsg)>,
    /// The robot links under their parent links.
    frames: Vec<BodyFrame>,
    /// No step converted yet.
    first: bool,
}

/// Length of a contact's force arrow per newton for a fingertip \[m/N\], up to its reference
/// force: one fingertip radius R at the force of its law at x = 0.2 (`R / F(0.2 R)`; 0 if that
/// force is not positive); above it the length grows logarithmically and is capped
/// ([`visuals::arrow_length`](crate::visuals::arrow_length)). Scale-free: the arrows of a 20 mm fingertip and of a 30 um cell squeezed alike
/// are alike relative to the fingertip.
pub fn arrow_scale(tip: &FingertipInfo) -> f64 {
    let force = tip
        .law
        .law()
        .map(|law| law.response(0.2 * tip.radius).force)
        .unwrap_or(0.0);
    if force > 0.0 && force.is_finite() && tip.radius > 0.0 {
        tip.radius / force
    } else {
        0.0
    }
}

impl StepConverter {
    /// The converter of a scene (it needs where each fingertip is mounted, the up axis, `dt`
    /// and the bodies' shapes).
    pub fn new(info: &SceneInfo) -> Self {
        let names = FrameNames::new(info);
        let mut bodies: HashMap<&str, usize> = HashMap::new();
        for (i, b) in info.bodies.iter().enumerate() {
            bodies.entry(b.as_str()).or_insert(i);
        }
        let tips: Vec<TipMount> = info
            .fingertips
            .iter()
            .map(|t| TipMount {
                name: t.name.clone(),
                frame: names.fingertip_frame(&t.name),
                body: t.body.clone(),
                body_hint: bodies.get(t.body.as_str()).copied().unwrap_or(usize::MAX),
                offset: t.offset,
                radius: t.radius,
                arrow_scale: arrow_scale(t),
                facing: t.facing,
            })
            .collect();
        let header = Header::new(0, "");
        let tf_static = Some(TFMessage {
            transforms: tips
                .iter()
                .map(|t| TransformStamped {
                    header: Header {
                        frame_id: t.body.clone(),
                        ..header.clone()
                    },
                    child_frame_id: t.frame.clone(),
                    transform: Transform {
                        translation: Vector3::from_array(t.offset),
                        rotation: Quaternion::IDENTITY,
                    },
                })
                .collect(),
        });
        let one = info.robots.len() == 1;
        let descriptions = (info.robots.iter())
            .map(|r| {
                let key = if one { String::new() } else { r.name.clone() };
                (
                    key,
                    StringMsg {
                        data: r.urdf.clone(),
                    },
                )
            })
            .collect();
        let mut tip_index = HashMap::new();
        for (i, t) in tips.iter().enumerate() {
            tip_index.entry(t.name.clone()).or_insert(i);
        }
        Self {
            tips,
            tip_index,
            up: info.up,
            dt: info.dt,
            shapes: visuals::shape_markers(info).into(),
            tf_static,
            descriptions,
            frames: info.frames.clone(),
            first: true,
        }
    }

    /// The stamp of step `step` \[ns\]: `round(step · dt · 1e9)` in f64 (an exact multiple of
    /// dt to 1 ns), or `round(time · 1e9)` when `dt` is unknown (0).
    pub fn stamp_ns(&self, step: u64, time: f64) -> u64 {
        let t = if self.dt > 0.0 {
            step as f64 * self.dt
        } else {
            time
        };
        (t * 1e9).round() as u64
    }

    /// Fills `step` from `frame`, reusing its allocations (the world frame is
    /// [`WORLD_FRAME`]). The first call also fills `step.tf_static`; later calls clear it.
    pub fn convert(&mut self, frame: &StepFrame, step: &mut StepRecord) {
        step.time_ns = self.stamp_ns(frame.step, frame.time);
        if step.world_frame != WORLD_FRAME {
            step.world_frame = WORLD_FRAME.to_owned();
        }
        let first = std::mem::take(&mut self.first);
        step.tf_static = self.tf_static.take().map(|mut tf| {
            tf.transforms.extend(self.fixed_links(frame));
            for t in &mut tf.transforms {
                t.header.stamp = step.header().stamp;
            }
            tf
        });
        step.tf_static = step.tf_static.take().filter(|tf| !tf.transforms.is_empty());
        step.robot_descriptions = if first {
            std::mem::take(&mut self.descriptions)
        } else {
            Vec::new()
        };
        step.joint_states = joint_state(&frame.joints, step.time_ns);
        step.joint_commands = joint_state(&frame.commands, step.time_ns);
        if !Arc::ptr_eq(&step.shapes, &self.shapes) {
            step.shapes = Arc::clone(&self.shapes);
        }
        let up = self.up;
        let mut n = 0;
        for b in &frame.bodies {
            let (parent, (position, orientation)) = match self.frame_of(&b.name) {
                // A fixed link is on `/tf_static`.
                Some(f) if f.fixed => continue,
                Some(f) => match frame.bodies.iter().find(|p| p.name == f.parent) {
                    Some(p) => (f.parent.as_str(), relative(p, b)),
                    None => ("", (up.vector(b.translation), up.rotation(b.rotation))),
                },
                None => ("", (up.vector(b.translation), up.rotation(b.rotation))),
            };
            match step.bodies.get_mut(n) {
                Some(p) => {
                    p.name.clone_from(&b.name);
                    if p.parent != parent {
                        parent.clone_into(&mut p.parent);
                    }
                    p.position = position;
                    p.orientation = orientation;
                }
                None => step.bodies.push(BodyPose {
                    name: b.name.clone(),
                    parent: parent.to_owned(),
                    position,
                    orientation,
                }),
            }
            n += 1;
        }
        step.bodies.truncate(n);
        step.fingertips.truncate(frame.wrenches.len());
        for (i, w) in frame.wrenches.iter().enumerate() {
            let state = self.fingertip_state(i, w, frame);
            match step.fingertips.get_mut(i) {
                Some(t) => {
                    t.name.clone_from(&w.fingertip);
                    t.frame.clone_from(&state.frame);
                    t.position = state.position;
                    t.orientation = state.orientation;
                    t.radius = state.radius;
                    t.wrench = state.wrench;
                    t.arrow_scale = state.arrow_scale;
                    t.facing = state.facing;
                }
                None => step.fingertips.push(FingertipState {
                    name: w.fingertip.clone(),
                    ..state
                }),
            }
        }
        step.contacts.clear();
        step.contacts
            .extend(frame.contacts.iter().map(|c| soft_contact_msg_in(c, up)));
        step.tactile.clear();
        step.tactile.extend(frame.tactile.iter().map(|s| {
            let frame = self
                .mount(&s.fingertip)
                .map_or(s.fingertip.as_str(), |t| t.frame.as_str());
            (s.fingertip.clone(), tactile_image(s, frame, step.time_ns))
        }));
    }

    /// A body's place under its parent link, if it is a robot link.
    fn frame_of(&self, body: &str) -> Option<&BodyFrame> {
        self.frames.iter().find(|f| f.body == body)
    }

    /// The fixed links' poses in their parents at `frame` (`/tf_static`).
    fn fixed_links<'a>(
        &'a self,
        frame: &'a StepFrame,
    ) -> impl Iterator<Item = TransformStamped> + 'a {
        self.frames.iter().filter(|f| f.fixed).filter_map(|f| {
            let child = frame.bodies.iter().find(|b| b.name == f.body)?;
            let parent = frame.bodies.iter().find(|b| b.name == f.parent)?;
            let (position, orientation) = relative(parent, child);
            Some(TransformStamped {
                header: Header::new(0, &f.parent),
                child_frame_id: f.body.clone(),
                transform: Transform {
                    translation: Vector3::from_array(position),
                    rotation: Quaternion::from_xyzw(orientation),
                },
            })
        })
    }

    /// The mount of the fingertip named `name`.
    fn mount(&self, name: &str) -> Option<&TipMount> {
        self.tip_index.get(name).map(|&i| &self.tips[i])
    }

    /// The `i`-th fingertip's pose (world, from its body's and its mount), radius, frame and
    /// wrench in that frame (its name is left empty: the caller reuses its own string).
    fn fingertip_state(&self, i: usize, w: &WrenchSample, frame: &StepFrame) -> FingertipState {
        let mount = self.mount(&w.fingertip).or_else(|| self.tips.get(i));
        let Some(m) = mount else {
            // Not in the scene info: a world-axes wrench on a world-fixed frame.
            return FingertipState {
                orientation: [0.0, 0.0, 0.0, 1.0],
                wrench: Wrench {
                    force: Vector3::from_array(self.up.vector(w.force)),
                    torque: Vector3::from_array(self.up.vector(w.torque)),
                },
                ..FingertipState::default()
            };
        };
        // The frame lists the scene's bodies in order: the hint finds it at once.
        let body = frame
            .bodies
            .get(m.body_hint)
            .filter(|b| b.name == m.body)
            .or_else(|| frame.bodies.iter().find(|b| b.name == m.body));
        let (p, q) = body.map_or(([0.0; 3], [0.0, 0.0, 0.0, 1.0]), |b| {
            (b.translation, b.rotation)
        });
        let o = rotate(q, m.offset);
        let centre = [p[0] + o[0], p[1] + o[1], p[2] + o[2]];
        FingertipState {
            name: String::new(),
            position: self.up.vector(centre),
            orientation: self.up.rotation(q),
            radius: m.radius,
            // The fingertip frame has its body's axes: scene axes -> body axes is q*.
            wrench: Wrench {
                force: Vector3::from_array(rotate_inverse(q, w.force)),
                torque: Vector3::from_array(rotate_inverse(q, w.torque)),
            },
            frame: m.frame.clone(),
            arrow_scale: m.arrow_scale,
            facing: m.facing,
        }
    }
}

/// A contact of the frame as a `softgrip_msgs/SoftContact`, its vectors as they are (a z-up
/// frame; its header is set per step, by [`StepRecord::take_contact_array`]).
///
/// `contact_radius` and `contact_radius2` are the law's semi-axes a, b at the end-of-step
/// compression (whenever the patch is given; a = b for a disc). `mean_pressure` is
/// `normal_force / (π a b)` (the step-average force over that patch), so
/// `mean_pressure · π a b = normal_force`; `peak_pressure` keeps the law's ratio of peak to
/// mean pressure (3/2 for Hertz). Both are 0 when the patch carries no pressure.
pub fn soft_contact_msg(c: &ContactSample) -> SoftContactMsg {
    soft_contact_msg_in(c, UpAxis::Z)
}

/// `(mean, peak)` pressure \[Pa\] of `patch` carrying `normal_force` \[N\]: 0 without a patch
/// or when the patch carries no pressure (the scene does not record pressure).
fn pressures(patch: &ContactPatch, normal_force: f64) -> (f64, f64) {
    let area = std::f64::consts::PI * patch.radius * patch.radius2;
    if !(area > 0.0 && normal_force > 0.0 && patch.mean_pressure > 0.0) {
        return (0.0, 0.0);
    }
    let mean = normal_force / area;
    (mean, mean * (patch.peak_pressure / patch.mean_pressure))
}

/// [`soft_contact_msg`] of a contact whose vectors are in the axes of a scene with up axis `up`.
fn soft_contact_msg_in(c: &ContactSample, up: UpAxis) -> SoftContactMsg {
    let k = &c.contact;
    let patch = k.patch.unwrap_or(ContactPatch::EMPTY);
    let (mean_pressure, peak_pressure) = pressures(&patch, k.normal_force);
    let mut m = SoftContactMsg {
        fingertip: c.fingertip.clone(),
        other: c.other.clone(),
        point: Point::from_array(up.vector(k.point)),
        normal: Vector3::from_array(up.vector(k.normal)),
        compression: k.delta,
        ratio_x: k.x,
        normal_force: k.normal_force,
        friction_force: Vector3::from_array(up.vector(k.friction_force)),
        torsional_moment: k.torsional_moment,
        contact_radius: patch.radius,
        mean_pressure,
        peak_pressure,
        stiffness: k.stiffness,
        sliding: k.sliding,
        peak_normal_force: k.peak_normal_force,
        max_compression: k.max_delta,
        contact_duration: k.contact_duration,
        validity_exceeded: k.validity_exceeded,
        ..SoftContactMsg::default()
    };
    m.set_level(k.level);
    m.set_backing(k.backing);
    m.set_counterpart(k.counterpart, up.vector(k.patch_direction));
    m.contact_radius2 = patch.radius2;
    m
}

/// A fingertip's tactile image as a `sensor_msgs/Image` (`32FC1`, pressure \[Pa\],
/// little-endian, row-major, `step = 4 columns`) stamped `time_ns` \[ns\], in the
/// fingertip's tf frame `frame` ([`fingertip_frame`](crate::frames::fingertip_frame)).
pub fn tactile_image(s: &TactileSample, frame: &str, time_ns: u64) -> Image {
    Image::tactile(Header::new(time_ns, frame), s.rows, s.columns, &s.pressure)
}

/// The pose of `child` in `parent`'s frame: `(q_p* (p_c - p_p), q_p* q_c)` (the same in any
/// axes both are given in).
fn relative(parent: &BodySample, child: &BodySample) -> ([f64; 3], [f64; 4]) {
    let q = parent.rotation;
    let d: [f64; 3] = std::array::from_fn(|i| child.translation[i] - parent.translation[i]);
    let inv = [-q[0], -q[1], -q[2], q[3]];
    (
        rotate_inverse(q, d),
        crate::frames::mul(inv, child.rotation),
    )
}

/// A `sensor_msgs/JointState` of `joints` stamped `time_ns` \[ns\]; `None` without joints.
fn joint_state(joints: &[JointSample], time_ns: u64) -> Option<JointState> {
    (!joints.is_empty()).then(|| JointState {
        header: Header::new(time_ns, ""),
        name: joints.iter().map(|j| j.name.clone()).collect(),
        position: joints.iter().map(|j| j.position).collect(),
        velocity: joints.iter().map(|j| j.velocity).collect(),
        effort: joints.iter().map(|j| j.effort).collect(),
    })
}
