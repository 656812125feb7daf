//! The jointed scenes the `jointed*` tests share: a fixed table with a 2 cm box on it and a
//! jointed body over it (a two-link finger of revolute joints or a prismatic jaw, position
//! motors, built as a multibody or with impulse joints) with the suite's fingertip, and what a
//! hold measures.

#![allow(dead_code)] // each test file uses a subset
#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, Level};
use softgrip_rapier::SoftWorld;
pub use softgrip_testkit::scenes::RADIUS as R;
use softgrip_testkit::scenes::fingertip;

/// Half extent of the box \[m\] (a 2 cm box on the table, its top face at y = 2 HALF).
pub const HALF: f32 = 0.01;
/// Length of the finger's first and second link \[m\].
pub const L1: f32 = 0.05;
pub const L2: f32 = 0.04;
/// Gap between the tip and the box before the motors press \[m\].
pub const GAP: f32 = 0.0005;
/// The motors' stiffness [N m/rad] (revolute) or [N/m] (prismatic) and damping.
pub const K_REV: f32 = 40.0;
pub const C_REV: f32 = 0.05;
pub const K_PRI: f32 = 2.0e4;
pub const C_PRI: f32 = 200.0;

/// How the jointed body is built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Build {
    Multibody,
    Impulse,
}

/// One joint of the scene: the child body, the joint's origin on it (its body origin) and its
/// axis (world), revolute or prismatic.
#[derive(Debug, Clone, Copy)]
pub struct Joint {
    pub child: RigidBodyHandle,
    pub axis: Vector,
    pub kind: JointKind,
    pub handle: Option<ImpulseJointHandle>,
}

pub struct Scene {
    pub world: SoftWorld,
    pub build: Build,
    pub joints: Vec<Joint>,
    pub box_body: RigidBodyHandle,
    pub box_col: ColliderHandle,
    pub law: ContactLaw,
}

/// A fresh world at `pgs` internal PGS iterations per rapier solver pass
/// (`IntegrationParameters::num_internal_pgs_iterations`, rapier's default 1) with the fixed
/// table (its top at y = 0) and the 2 cm box resting on it at `x`: the world, the box's body
/// and collider.
pub fn table_and_box(pgs: usize, x: f32) -> (SoftWorld, RigidBodyHandle, ColliderHandle) {
    let mut world = SoftWorld::new();
    world
        .physics
        .integration_parameters
        .num_internal_pgs_iterations = pgs;
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.2, 0.01, 0.2).translation(Vector::new(0.0, -0.01, 0.0)));
    let box_body = world.physics.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(x, HALF, 0.0))
            .can_sleep(false),
    );
    let box_col = world.physics.colliders.insert_with_parent(
        ColliderBuilder::cuboid(HALF, HALF, HALF).density(500.0),
        box_body,
        &mut world.physics.bodies,
    );
    (world, box_body, box_col)
}

/// A joint's kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JointKind {
    Revolute,
    Prismatic,
}

impl JointKind {
    /// The motor's stiffness [N m/rad or N/m] and damping.
    pub fn gains(self) -> (f32, f32) {
        match self {
            JointKind::Revolute => (K_REV, C_REV),
            JointKind::Prismatic => (K_PRI, C_PRI),
        }
    }

    /// The joint's free axis in rapier's joint frame (`motors`' index).
    pub fn axis(self) -> JointAxis {
        match self {
            JointKind::Revolute => JointAxis::AngX,
            JointKind::Prismatic => JointAxis::LinX,
        }
    }
}

/// A joint of `kind` about or along `axis`, anchored at `anchor1` on its parent and at the
/// child's origin, with a force-based position motor aiming at `target` [rad or m] with the
/// suite's stiffness and damping (`K_REV`, `C_REV` or `K_PRI`, `C_PRI`).
pub fn motored_joint(kind: JointKind, axis: Vector, anchor1: Vector, target: f32) -> GenericJoint {
    match kind {
        JointKind::Revolute => RevoluteJointBuilder::new(axis)
            .local_anchor1(anchor1)
            .local_anchor2(Vector::ZERO)
            .motor_position(target, K_REV, C_REV)
            .motor_model(MotorModel::ForceBased)
            .build()
            .into(),
        JointKind::Prismatic => PrismaticJointBuilder::new(axis)
            .local_anchor1(anchor1)
            .local_anchor2(Vector::ZERO)
            .motor_position(target, K_PRI, C_PRI)
            .motor_model(MotorModel::ForceBased)
            .build()
            .into(),
    }
}

/// The links' density \[kg/m^3\] (a 5 cm link of the finger weighs 3.2 g).
pub const DENSITY: f32 = 1000.0;

/// A light dynamic link (awake, its own gravity scale `gravity`) with its origin at `at`: a
/// cuboid of `density` and half extents `half` centred at `centre` in its frame, colliding
/// with nothing.
pub fn light_link(
    world: &mut SoftWorld,
    at: Vector,
    (gravity, density): (f32, f32),
    half: Vector,
    centre: Vector,
) -> RigidBodyHandle {
    let p = &mut world.physics;
    let body = p.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(at)
            .gravity_scale(gravity)
            .can_sleep(false),
    );
    p.colliders.insert_with_parent(
        ColliderBuilder::cuboid(half.x, half.y, half.z)
            .translation(centre)
            .density(density)
            .collision_groups(InteractionGroups::none()),
        body,
        &mut p.bodies,
    );
    body
}

/// The suite's fingertip (`R`, calibrated, e = 0.5) on `body` at `offset` in its frame: its
/// collider and its law.
pub fn soft_tip(
    world: &mut SoftWorld,
    body: RigidBodyHandle,
    offset: Vector,
) -> (ColliderHandle, ContactLaw) {
    let tip = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32).translation(offset),
        body,
        &mut world.physics.bodies,
    );
    let ft = fingertip(Level::Calibrated, 0.5).build().unwrap();
    let law = ft.law().clone();
    world.register(tip, ft).unwrap();
    (tip, law)
}

/// The table, the box on it, a fixed base and the jointed chain (`prismatic`: one prismatic
/// joint along y, the tip below it; else two revolute joints about z along x, the tip at the
/// end of the second link) with `pgs` internal PGS iterations per rapier solver pass
/// (`IntegrationParameters::num_internal_pgs_iterations`, rapier's default 1); the links'
/// gravity scale `link_gravity`.
pub fn scene(build: Build, prismatic: bool, pgs: usize, link_gravity: f32) -> Scene {
    scene_with(build, prismatic, pgs, (link_gravity, DENSITY))
}

/// [`scene`] with the links' gravity scale and density `links`.
pub fn scene_with(build: Build, prismatic: bool, pgs: usize, links: (f32, f32)) -> Scene {
    let tip_x = if prismatic { 0.0 } else { L1 + L2 };
    let (mut world, box_body, box_col) = table_and_box(pgs, tip_x);
    let y0 = 2.0 * HALF + R as f32 + GAP;
    let base_pos = if prismatic {
        Vector::new(0.0, y0 + 0.03, 0.0)
    } else {
        Vector::new(0.0, y0, 0.0)
    };
    let base = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(base_pos));
    // The chain: (joint origin, axis, revolute, offset from the joint to the next point).
    let chain: Vec<(Vector, JointKind, Vector)> = if prismatic {
        vec![(
            Vector::Y,
            JointKind::Prismatic,
            Vector::new(0.0, -0.03, 0.0),
        )]
    } else {
        vec![
            (Vector::Z, JointKind::Revolute, Vector::new(L1, 0.0, 0.0)),
            (Vector::Z, JointKind::Revolute, Vector::new(L2, 0.0, 0.0)),
        ]
    };
    let mut parent = base;
    let mut at = base_pos;
    let mut anchor_on_parent = Vector::ZERO;
    let mut joints = Vec::new();
    for (axis, kind, offset) in chain {
        // A light link along its offset.
        let half = (offset.length() * 0.5).max(0.003);
        let body = light_link(
            &mut world,
            at,
            links,
            Vector::new(half, 0.004, 0.004),
            offset * 0.5,
        );
        let data = motored_joint(kind, axis, anchor_on_parent, 0.0);
        let handle = match build {
            Build::Multibody => {
                world
                    .physics
                    .multibody_joints
                    .insert(parent, body, data, true)
                    .unwrap();
                None
            }
            Build::Impulse => Some(
                world
                    .physics
                    .impulse_joints
                    .insert(parent, body, data, true),
            ),
        };
        joints.push(Joint {
            child: body,
            axis,
            kind,
            handle,
        });
        parent = body;
        at += offset;
        anchor_on_parent = offset;
    }
    let (_, law) = soft_tip(&mut world, parent, anchor_on_parent);
    // The box settles on the table.
    for _ in 0..30 {
        world.step();
    }
    Scene {
        world,
        build,
        joints,
        box_body,
        box_col,
        law,
    }
}

impl Scene {
    /// Sets every motor's target: `targets[i]` for joint `i` [rad or m].
    pub fn set_targets(&mut self, targets: &[f32]) {
        let p = &mut self.world.physics;
        for (j, &t) in self.joints.iter().zip(targets) {
            let axis = j.kind.axis();
            let (stiffness, damping) = j.kind.gains();
            match self.build {
                Build::Multibody => {
                    let link = *p.multibody_joints.rigid_body_link(j.child).unwrap();
                    let mb = p
                        .multibody_joints
                        .get_multibody_mut(link.multibody)
                        .unwrap();
                    let joint = &mut mb.link_mut(link.id).unwrap().joint.data;
                    joint.set_motor_position(axis, t, stiffness, damping);
                }
                Build::Impulse => {
                    let joint = p.impulse_joints.get_mut(j.handle.unwrap(), true).unwrap();
                    joint.data.set_motor_position(axis, t, stiffness, damping);
                }
            }
        }
    }

    /// Joint `i`'s position [rad or m] and velocity, and its motor's target.
    pub fn joint_state(&self, i: usize) -> (f64, f64, f64) {
        let p = &self.world.physics;
        let j = &self.joints[i];
        let k = j.kind.axis() as usize;
        match self.build {
            Build::Multibody => {
                let link = *p.multibody_joints.rigid_body_link(j.child).unwrap();
                let mb = p.multibody_joints.get_multibody(link.multibody).unwrap();
                let l = mb.link(link.id).unwrap();
                let q = l.joint().coords()[k] as f64;
                let v = mb.joint_velocity(l)[0] as f64;
                let t = l.joint().data.motors[k].target_pos as f64;
                (q, v, t)
            }
            Build::Impulse => {
                // The joint's coordinate from its frames, as rapier's motor rows read it.
                let joint = p.impulse_joints.get(j.handle.unwrap()).unwrap();
                let (rb1, rb2) = (&p.bodies[joint.body1()], &p.bodies[joint.body2()]);
                let f1 = *rb1.position() * joint.data.local_frame1;
                let f2 = *rb2.position() * joint.data.local_frame2;
                let (q, v) = match j.kind {
                    JointKind::Revolute => {
                        let r = f1.rotation.inverse() * f2.rotation;
                        let w = rb2.angvel() - rb1.angvel();
                        (2.0 * r.x.asin(), w.dot(f1.rotation * Vector::X))
                    }
                    JointKind::Prismatic => {
                        let a = f1.rotation * Vector::X;
                        let v = rb2.velocity_at_point(f2.translation)
                            - rb1.velocity_at_point(f2.translation);
                        ((f2.translation - f1.translation).dot(a), v.dot(a))
                    }
                };
                let t = joint.data.motors[k].target_pos as f64;
                (q as f64, v as f64, t)
            }
        }
    }

    /// Joint `i`'s motor effort [N m or N] (along the joint's positive axis, on the child):
    /// a multibody's from rapier's force-based motor law at the joint's state (rapier 0.36 does
    /// not write a multibody motor's impulse back), an impulse joint's from the impulse rapier
    /// wrote back: that of its last solver pass, of `h / num_solver_iterations` with `h` the
    /// last pipeline step, `dt` over the plugin's substeps (`SoftCounters::substeps_last`), as
    /// the scene's `joint_state` reads it (rapier's impulse pushes the child against the axis).
    pub fn motor_effort(&self, i: usize) -> f64 {
        let j = &self.joints[i];
        match self.build {
            Build::Multibody => {
                let (q, v, t) = self.joint_state(i);
                let (stiffness, damping) = j.kind.gains();
                stiffness as f64 * (t - q) - damping as f64 * v
            }
            Build::Impulse => {
                let joint = self
                    .world
                    .physics
                    .impulse_joints
                    .get(j.handle.unwrap())
                    .unwrap();
                let ip = &self.world.physics.integration_parameters;
                let substeps = self.world.soft.counters().substeps_last.max(1) as f64;
                let pass = ip.dt as f64 / substeps / ip.num_solver_iterations.max(1) as f64;
                let impulse = joint.data.motors[j.kind.axis() as usize].impulse as f64;
                -impulse / pass
            }
        }
    }

    /// The load's joint-space projection at joint `i` (`J^T F`): the contact force's and the
    /// links' weights' moment about the joint's axis, or their component along it.
    pub fn contact_effort(&self, i: usize) -> f64 {
        let j = &self.joints[i];
        let c = self.contact();
        let o = self.world.physics.bodies[j.child].translation();
        let (f, torque) = c.wrench_about([o.x as f64, o.y as f64, o.z as f64]);
        let a = [j.axis.x as f64, j.axis.y as f64, j.axis.z as f64];
        let v = if j.kind == JointKind::Revolute {
            torque
        } else {
            f
        };
        let contact: f64 = (0..3).map(|k| v[k] * a[k]).sum();
        // The links' weight beyond the joint.
        let p = &self.world.physics;
        let g = p.gravity;
        let weight: f64 = self.joints[i..]
            .iter()
            .map(|l| {
                let rb = &p.bodies[l.child];
                let w = g * (rb.mass() * rb.gravity_scale());
                let arm = rb.center_of_mass() - o;
                let e = if j.kind == JointKind::Revolute {
                    arm.cross(w)
                } else {
                    w
                };
                e.dot(j.axis) as f64
            })
            .sum();
        contact + weight
    }

    pub fn contact(&self) -> &softgrip_rapier::TipContact {
        self.world
            .soft
            .contacts()
            .iter()
            .find(|c| c.other == self.box_col)
            .expect("the tip touches the box")
    }

    /// The compression from the geometry: the tip's centre against the box's top face \[m\].
    pub fn geometric_delta(&self) -> f64 {
        let p = &self.world.physics;
        let tip = p.colliders[self.contact().fingertip].translation();
        let rb = &p.bodies[self.box_body];
        let top = rb.position().transform_point(Vector::new(0.0, HALF, 0.0)).y;

        R - (tip.y as f64 - top as f64)
    }

    pub fn box_speed(&self, prev: &Pose) -> f64 {
        let pose = *self.world.physics.bodies[self.box_body].position();
        let dt = self.world.physics.integration_parameters.dt as f64;
        ((pose.translation - prev.translation).length() as f64
            + HALF as f64
                * (pose.rotation * prev.rotation.inverse())
                    .to_axis_angle()
                    .1
                    .abs() as f64)
            / dt
    }
}

/// What one hold measured.
#[derive(Debug)]
pub struct Held {
    /// |F / F_law(delta_geometry) - 1| at the end.
    pub law_error: f64,
    /// The contact's normal force \[N\].
    pub force: f64,
    /// Per joint: the motor's effort and the contact's joint-space force.
    pub efforts: Vec<(f64, f64)>,
    /// The box's largest speed over the last half of the hold [m/s].
    pub box_speed: f64,
}

/// Sets the motors' targets and holds for `steps`, measuring at the end.
pub fn hold(s: &mut Scene, targets: &[f32], steps: usize) -> Held {
    s.set_targets(targets);
    let mut prev = *s.world.physics.bodies[s.box_body].position();
    let mut box_speed = 0.0f64;
    for i in 0..steps {
        s.world.step();
        let v = s.box_speed(&prev);
        prev = *s.world.physics.bodies[s.box_body].position();
        if i >= steps / 2 {
            box_speed = box_speed.max(v);
        }
    }
    let c = s.contact();
    let delta = s.geometric_delta();
    let force = c.normal_force;
    let law_error = (force / s.law.response(delta).force - 1.0).abs();
    let efforts: Vec<(f64, f64)> = (0..s.joints.len())
        .map(|i| (s.motor_effort(i), s.contact_effort(i)))
        .collect();
    Held {
        law_error,
        force,
        efforts,
        box_speed,
    }
}

/// The finger's motor targets: both joints turned down by `angle` [rad].
pub const FINGER: [f32; 2] = [-0.02, -0.02];

pub fn assert_held(name: &str, h: &Held) {
    println!("{name}: {h:?}");
    assert!(h.force > 1.0, "{name}: {h:?}");
    assert!(h.law_error < 5e-3, "{name}: {h:?}");
    for (motor, contact) in &h.efforts {
        assert!((motor / -contact - 1.0).abs() < 1e-2, "{name}: {h:?}");
    }
    assert!(h.box_speed < 1e-6, "{name}: {h:?}");
}

/// rapier's internal PGS iterations per solver pass these tests use: its default (1) leaves
/// the two coupled motor rows of the finger unconverged within a pass (at rest the first
/// joint's stored velocity stays at -0.016 rad/s while it does not move), and the plugin's
/// exact prediction of the motors then misses the force by 3.9 % (bounded below).
pub const PGS: usize = 2;
