//! The ECS side of recording: the plugin's readout and the scene converted into
//! softgrip-record's plain sink types ([`SceneInfo`], [`ContactReading`], [`FingertipLaw`],
//! [`RunSummary`]), and [`McapSink`], softgrip-record's MCAP sink created from a scene.

use std::path::Path;
use std::sync::{Arc, Mutex};

use bevy_ecs::prelude::{Name, Query};
use softgrip_law::ContactPatch;
use softgrip_rapier::rapier3d::prelude::{SharedShape, Vector};
use softgrip_rapier::{SoftFingertip, TipContact};
use softgrip_record::{
    BodyFrame, ContactReading, ControllerRecord, FingertipInfo, FingertipLaw, JointSample,
    McapReport, McapSinkError, RecorderOptions, RecordingStats, RobotInfo, RunSummary, SceneInfo,
    ShapeGeometry, ShapeInfo, SinkError, StepFrame, StepSink, TactileSample, TipRunSummary, UpAxis,
};
use softgrip_scene::ControlSet;
use softgrip_scene::robot::{JointKind, joint_state_loaded, joint_target};

use crate::resources::Physics;

use crate::scene::Scene;
use crate::summary::Summary;

/// The law of a fingertip as recorded (named `name`: the scene's name for it): its level and
/// parameters, and for a `tabulated` or `custom` level the curve that stands for it
/// (`ContactLaw::recorded_curve`; a custom law whose curve cannot be sampled is recorded
/// without one, and reads back as parameters without a law).
pub fn fingertip_law(tip: &SoftFingertip, name: &str) -> FingertipLaw {
    let m = tip.material();
    let law = tip.law();
    FingertipLaw {
        name: name.to_owned(),
        level: tip.level(),
        youngs_modulus: m.youngs_modulus(),
        poisson_ratio: m.poisson_ratio(),
        radius: tip.radius(),
        friction: tip.friction(),
        restitution: tip.restitution(),
        backing: tip.backing(),
        curve: law.recorded_curve().ok().flatten(),
        custom_name: law.custom_name().map(str::to_owned),
    }
}

fn array(v: Vector) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

/// How finely a capsule is drawn: subdivisions around its axis and along its two caps.
const CAPSULE_SUBDIVISIONS: [u32; 2] = [24, 12];

/// A built shape's geometry as plain numbers (`None` for a kind softgrip's scenes do not
/// make). A capsule (a URDF link's `<capsule>`) becomes a triangle mesh of its surface: before
/// session 15 it was `None`, and such a link was simulated but not drawn.
pub fn shape_geometry(shape: &SharedShape) -> Option<ShapeGeometry> {
    if let Some(h) = shape.as_halfspace() {
        return Some(ShapeGeometry::Plane {
            normal: array(h.normal),
        });
    }
    if let Some(c) = shape.as_cuboid() {
        return Some(ShapeGeometry::Cuboid {
            half_extents: array(c.half_extents),
        });
    }
    if let Some(b) = shape.as_ball() {
        return Some(ShapeGeometry::Ball {
            radius: f64::from(b.radius),
        });
    }
    if let Some(c) = shape.as_cylinder() {
        return Some(ShapeGeometry::Cylinder {
            half_height: f64::from(c.half_height),
            radius: f64::from(c.radius),
        });
    }
    let (vertices, triangles) = if let Some(c) = shape.as_convex_polyhedron() {
        let (v, t) = c.to_trimesh();
        (v.into_iter().map(array).collect(), t)
    } else if let Some(c) = shape.as_capsule() {
        // A URDF `<capsule>` (no Marker type draws one): its surface as triangles.
        let (v, t) = c.to_trimesh(CAPSULE_SUBDIVISIONS[0], CAPSULE_SUBDIVISIONS[1]);
        (v.into_iter().map(array).collect(), t)
    } else {
        let m = shape.as_trimesh()?;
        let v = m.vertices().iter().copied().map(array).collect();
        (v, m.indices().to_vec())
    };
    Some(ShapeGeometry::Mesh {
        vertices,
        triangles,
    })
}

/// Every rigid body's shapes of `scene`, in scene order, in their body frames; then every
/// robot link's collision shapes in its link frame (`<robot>/<link>`).
fn shapes(scene: &Scene) -> Vec<ShapeInfo> {
    let f = scene.file();
    let bodies = f.bodies.iter().enumerate().flat_map(|(i, body)| {
        scene
            .shapes(i)
            .iter()
            .zip(&body.shapes)
            .filter_map(|(shape, spec)| {
                Some(ShapeInfo {
                    body: body.name.clone(),
                    offset: spec.offset,
                    rotation: [0.0, 0.0, 0.0, 1.0],
                    geometry: shape_geometry(shape)?,
                })
            })
    });
    let links = scene.robots().iter().flat_map(|robot| {
        (robot.rapier().links.iter().enumerate()).flat_map(move |(l, link)| {
            link.colliders.iter().filter_map(move |c| {
                let p = c.collider.position();
                let (t, q) = (p.translation, p.rotation);
                Some(ShapeInfo {
                    body: robot.frame(l),
                    offset: array(t),
                    rotation: [q.x, q.y, q.z, q.w].map(f64::from),
                    geometry: shape_geometry(c.collider.shared_shape())?,
                })
            })
        })
    });
    bodies.chain(links).collect()
}

/// Every body's name, then every robot link's (`<robot>/<link>`), in scene order.
fn body_names(scene: &Scene) -> Vec<String> {
    let f = scene.file();
    let links = (scene.robots().iter()).flat_map(|r| (0..r.links().len()).map(move |l| r.frame(l)));
    f.bodies
        .iter()
        .map(|b| b.name.clone())
        .chain(links)
        .collect()
}

/// Each robot's links under their parent links (fixed joints' children marked fixed).
fn frames(scene: &Scene) -> Vec<BodyFrame> {
    let mut out = Vec::new();
    for robot in scene.robots() {
        for j in robot.joints() {
            out.push(BodyFrame {
                body: robot.frame(j.child),
                parent: robot.frame(j.parent),
                fixed: j.kind == JointKind::Fixed,
            });
        }
    }
    out
}

/// The name a joint is recorded and commanded by: its URDF name in a scene with one robot,
/// `<robot>/<joint>` with several.
pub fn joint_name(scene_robots: usize, robot: &str, joint: &str) -> String {
    if scene_robots == 1 {
        joint.to_owned()
    } else {
        format!("{robot}/{joint}")
    }
}

/// Every robot's moving joints' states after the last step into `joints`, and their motor
/// targets into `commands` (cleared first), robot by robot, in joint order.
pub fn joint_samples(
    control: &ControlSet,
    physics: &Physics,
    joints: &mut Vec<JointSample>,
    commands: &mut Vec<JointSample>,
) {
    joints.clear();
    commands.clear();
    let world = &physics.world;
    let n = world.soft.counters().substeps_last.max(1) as f64;
    let substep = world.physics.integration_parameters.dt as f64 / n;
    let robots = control.robots();
    for (robot, (_, h)) in robots.iter().zip(&control.handles().robots) {
        for (j, joint) in robot.joints().iter().enumerate() {
            if !joint.kind.moves() {
                continue;
            }
            let name = joint_name(robots.len(), robot.name(), &joint.name);
            let s = joint_state_loaded(robot, world, h, j, substep);
            if let Some((p, v, e)) = joint_target(robot, &world.physics, h, j) {
                commands.push(JointSample {
                    name: name.clone(),
                    position: p,
                    velocity: v,
                    effort: e,
                });
            }
            joints.push(JointSample {
                name,
                position: s.position,
                velocity: s.velocity,
                effort: s.effort,
            });
        }
    }
}

/// The joints' positions at the last assembled frame ([`joint_rates`]).
#[derive(Debug, Clone, Default)]
pub struct JointMemory {
    /// Its simulated time \[s\].
    time: f64,
    /// Each joint's position then, in [`joint_samples`] order.
    positions: Vec<f64>,
}

/// Replaces each joint's velocity by its rate of motion since the last assembled frame
/// (`(q - q_last) / (time - t_last)`, over every step in between when frames are assembled
/// only every n-th step) and remembers this frame's positions; the first frame keeps rapier's
/// velocity. Why: rapier keeps a joint's velocity without the position-correction part of
/// its solve (it removes the bias in its relaxation), so a joint driven by a position motor
/// reads slower than it moves (the shipped gripper closing at 10 mm/s reads 2.7 mm/s).
pub fn joint_rates(time: f64, memory: &mut Option<JointMemory>, joints: &mut [JointSample]) {
    if let Some(m) = memory.as_ref()
        && m.positions.len() == joints.len()
        && time > m.time
    {
        let dt = time - m.time;
        for (j, q) in joints.iter_mut().zip(&m.positions) {
            j.velocity = (j.position - q) / dt;
        }
    }
    let m = memory.get_or_insert_with(JointMemory::default);
    m.time = time;
    m.positions.clear();
    m.positions.extend(joints.iter().map(|j| j.position));
}

/// What the sinks learn of a scene before its first step (scene files are y-up: recordings
/// turn them z-up, [`UpAxis::Y`]).
pub fn scene_info(scene: &Scene) -> SceneInfo {
    let f = scene.file();
    SceneInfo {
        shapes: shapes(scene),
        up: UpAxis::Y,
        gravity: f.gravity,
        origin: scene.origin().to_owned(),
        dt: f.dt,
        steps: scene.steps(),
        bodies: body_names(scene),
        robots: (scene.robots().iter())
            .map(|r| RobotInfo {
                name: r.name().to_owned(),
                urdf: r.urdf_text().to_owned(),
            })
            .collect(),
        frames: frames(scene),
        controllers: controller_records(scene),
        fingertips: scene
            .fingertips()
            .iter()
            .zip(&f.fingertips)
            .zip(scene.carriers())
            .map(|((tip, spec), carrier)| FingertipInfo {
                name: spec.name.clone(),
                body: scene.carrier_name(*carrier),
                offset: spec.offset,
                radius: spec.radius,
                law: fingertip_law(tip, &spec.name),
                // The scene's fingertip colliders have no rotation of their own: the
                // collider's frame is the body's axes.
                facing: tip.facing(),
            })
            .collect(),
    }
}

/// The scene's controllers in the order they run, each with its kind's name and fixed code
/// from the one table of controller kinds (`softgrip_scene::CONTROLLERS`).
fn controller_records(scene: &Scene) -> Vec<ControllerRecord> {
    (scene.controllers().iter())
        .map(|c| {
            let row = c.kind().info();
            ControllerRecord {
                name: c.name().to_owned(),
                kind: row.name.to_owned(),
                code: row.code,
            }
        })
        .collect()
}

/// The numbers of a plugin readout with its patch (radius and pressure; pass a patch with zero
/// pressures when the scene does not record pressure: the radius is always recorded).
pub fn contact_reading(c: &TipContact, patch: Option<ContactPatch>) -> ContactReading {
    ContactReading {
        patch,
        ..c.reading()
    }
}

/// The plugin's tactile images (`SoftContacts::tactile_images`) as the sinks' plain
/// [`TactileSample`]s (pressure \[Pa\] as `f32`), named by their fingertip entity, written to
/// `out` (its allocations reused).
pub fn tactile_samples(physics: &Physics, names: &Query<&Name>, out: &mut Vec<TactileSample>) {
    let images = physics.world.soft.tactile_images();
    let mut n = 0;
    for (handle, image) in images {
        let name = physics
            .collider_entity(handle)
            .and_then(|e| names.get(e).ok())
            .map_or("", |n| n.as_str());
        if n == out.len() {
            out.push(TactileSample::default());
        }
        let s = &mut out[n];
        s.fingertip.clear();
        s.fingertip.push_str(name);
        s.rows = image.grid().rows();
        s.columns = image.grid().columns();
        s.pressure.clear();
        s.pressure
            .extend(image.pressure().iter().map(|p| *p as f32));
        n += 1;
    }
    out.truncate(n);
}

/// The run's summary for the sinks: `steps` run, and per fingertip its slips, validity
/// excursions, peak force \[N\] and peak x.
pub fn run_summary(summary: &Summary, steps: u64) -> RunSummary {
    RunSummary {
        steps,
        fingertips: summary
            .tips
            .iter()
            .map(|(_, t)| TipRunSummary {
                name: t.name.clone(),
                slips: t.slips,
                validity_excursions: t.validity_excursions,
                peak_force: t.peak_force,
                peak_x: t.peak_x,
            })
            .collect(),
    }
}

/// softgrip-record's [`McapSink`](softgrip_record::McapSink), created from a scene (its
/// [`scene_info`] and the scene file's text); everything else is the inner sink's.
#[derive(Debug)]
pub struct McapSink(pub softgrip_record::McapSink);

impl McapSink {
    /// Creates `path` for `scene`, recording every `scene.file().record.every_n_steps`-th step.
    pub fn create(
        path: impl AsRef<Path>,
        scene: &Scene,
        scene_text: &str,
    ) -> Result<Self, softgrip_record::Error> {
        let n = scene.file().record.every_n_steps;
        Self::with_options(path, scene, scene_text, n, &RecorderOptions::default())
    }

    /// See [`softgrip_record::McapSink::with_options`].
    pub fn with_options(
        path: impl AsRef<Path>,
        scene: &Scene,
        scene_text: &str,
        every_n_steps: u64,
        options: &RecorderOptions,
    ) -> Result<Self, softgrip_record::Error> {
        let info = scene_info(scene);
        softgrip_record::McapSink::with_options(path, &info, scene_text, every_n_steps, options)
            .map(Self)
    }

    /// See [`softgrip_record::McapSink::report_handle`].
    pub fn report_handle(&self) -> Arc<Mutex<McapReport>> {
        self.0.report_handle()
    }

    /// See [`softgrip_record::McapSink::close`].
    pub fn close(&mut self) -> Result<RecordingStats, McapSinkError> {
        self.0.close()
    }
}

impl StepSink for McapSink {
    fn start(&mut self, info: &SceneInfo) -> Result<(), SinkError> {
        self.0.start(info)
    }
    fn wants(&self, step: u64) -> bool {
        self.0.wants(step)
    }
    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        self.0.write(frame)
    }
    fn run_summary(&mut self, summary: &RunSummary) {
        self.0.run_summary(summary);
    }
    fn finish(&mut self) -> Result<(), SinkError> {
        self.0.finish()
    }
}
