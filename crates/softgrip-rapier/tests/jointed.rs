//! A fingertip on a jointed body pressing a box that rests on a fixed table (issue 23, item 4):
//! the last link of a two-link finger (two revolute joints with position motors) and a
//! prismatic jaw with a position motor, built as rapier multibodies (reduced coordinates: a
//! URDF hand's default) and, for the finger, as impulse joints.
//!
//! At rest the soft contact must carry the law's force at the compression the geometry gives
//! (the tip's centre against the box's top face), each motor must hold the joint-space
//! projection of the contact force (`J^T F`: the moment of the contact force about the joint's
//! axis, or its component along a prismatic axis), and the box must be still. A squeeze
//! driven by a joint motor's target must follow the law all the way.
//!
//! `cargo test -p softgrip-rapier --test jointed -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, Level};
use softgrip_rapier::SoftWorld;
use softgrip_testkit::scenes::{RADIUS as R, fingertip};

/// Half extent of the box \[m\] (a 2 cm box on the table, its top face at y = 2 HALF).
const HALF: f32 = 0.01;
/// Length of the finger's first and second link \[m\].
const L1: f32 = 0.05;
const L2: f32 = 0.04;
/// Gap between the tip and the box before the motors press \[m\].
const GAP: f32 = 0.0005;
/// The motors' stiffness [N m/rad] (revolute) or [N/m] (prismatic) and damping.
const K_REV: f32 = 40.0;
const C_REV: f32 = 0.05;
const K_PRI: f32 = 2.0e4;
const C_PRI: f32 = 200.0;

/// How the jointed body is built.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Build {
    Multibody,
    Impulse,
}

/// One joint of the scene: the child body, the joint's origin on it (its body origin) and its
/// axis (world), revolute or prismatic.
#[derive(Debug, Clone, Copy)]
struct Joint {
    child: RigidBodyHandle,
    axis: Vector,
    kind: JointKind,
    handle: Option<ImpulseJointHandle>,
}

struct Scene {
    world: SoftWorld,
    build: Build,
    joints: Vec<Joint>,
    box_body: RigidBodyHandle,
    box_col: ColliderHandle,
    law: ContactLaw,
}

/// A fresh world at `pgs` internal PGS iterations per rapier solver pass
/// (`IntegrationParameters::num_internal_pgs_iterations`, rapier's default 1) with the fixed
/// table (its top at y = 0) and the 2 cm box resting on it at `x`: the world, the box's body
/// and collider.
fn table_and_box(pgs: usize, x: f32) -> (SoftWorld, RigidBodyHandle, ColliderHandle) {
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
enum JointKind {
    Revolute,
    Prismatic,
}

impl JointKind {
    /// The motor's stiffness [N m/rad or N/m] and damping.
    fn gains(self) -> (f32, f32) {
        match self {
            JointKind::Revolute => (K_REV, C_REV),
            JointKind::Prismatic => (K_PRI, C_PRI),
        }
    }

    /// The joint's free axis in rapier's joint frame (`motors`' index).
    fn axis(self) -> JointAxis {
        match self {
            JointKind::Revolute => JointAxis::AngX,
            JointKind::Prismatic => JointAxis::LinX,
        }
    }
}

/// A joint of `kind` about or along `axis`, anchored at `anchor1` on its parent and at the
/// child's origin, with a force-based position motor aiming at `target` [rad or m] with the
/// suite's stiffness and damping (`K_REV`, `C_REV` or `K_PRI`, `C_PRI`).
fn motored_joint(kind: JointKind, axis: Vector, anchor1: Vector, target: f32) -> GenericJoint {
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
const DENSITY: f32 = 1000.0;

/// A light dynamic link (awake, its own gravity scale `gravity`) with its origin at `at`: a
/// cuboid of `density` and half extents `half` centred at `centre` in its frame, colliding
/// with nothing.
fn light_link(
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
fn soft_tip(
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
fn scene(build: Build, prismatic: bool, pgs: usize, link_gravity: f32) -> Scene {
    scene_with(build, prismatic, pgs, (link_gravity, DENSITY))
}

/// [`scene`] with the links' gravity scale and density `links`.
fn scene_with(build: Build, prismatic: bool, pgs: usize, links: (f32, f32)) -> Scene {
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
    fn set_targets(&mut self, targets: &[f32]) {
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
    fn joint_state(&self, i: usize) -> (f64, f64, f64) {
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
    /// wrote back: that of its last solver pass, of `dt / num_solver_iterations` (rapier's
    /// impulse pushes the child against the axis).
    fn motor_effort(&self, i: usize) -> f64 {
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
                let pass = ip.dt as f64 / ip.num_solver_iterations.max(1) as f64;
                let impulse = joint.data.motors[j.kind.axis() as usize].impulse as f64;
                -impulse / pass
            }
        }
    }

    /// The load's joint-space projection at joint `i` (`J^T F`): the contact force's and the
    /// links' weights' moment about the joint's axis, or their component along it.
    fn contact_effort(&self, i: usize) -> f64 {
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

    fn contact(&self) -> &softgrip_rapier::TipContact {
        self.world
            .soft
            .contacts()
            .iter()
            .find(|c| c.other == self.box_col)
            .expect("the tip touches the box")
    }

    /// The compression from the geometry: the tip's centre against the box's top face \[m\].
    fn geometric_delta(&self) -> f64 {
        let p = &self.world.physics;
        let tip = p.colliders[self.contact().fingertip].translation();
        let rb = &p.bodies[self.box_body];
        let top = rb.position().transform_point(Vector::new(0.0, HALF, 0.0)).y;

        R - (tip.y as f64 - top as f64)
    }

    fn box_speed(&self, prev: &Pose) -> f64 {
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
struct Held {
    /// |F / F_law(delta_geometry) - 1| at the end.
    law_error: f64,
    /// The contact's normal force \[N\].
    force: f64,
    /// Per joint: the motor's effort and the contact's joint-space force.
    efforts: Vec<(f64, f64)>,
    /// The box's largest speed over the last half of the hold [m/s].
    box_speed: f64,
}

/// Sets the motors' targets and holds for `steps`, measuring at the end.
fn hold(s: &mut Scene, targets: &[f32], steps: usize) -> Held {
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
const FINGER: [f32; 2] = [-0.02, -0.02];

fn assert_held(name: &str, h: &Held) {
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
const PGS: usize = 2;

#[test]
fn multibody_finger_presses_a_box_and_holds() {
    let mut s = scene(Build::Multibody, false, PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link multibody finger", &h);
}

/// The finger's links under gravity (the motors hold their weight too: the effort is `J^T`
/// of the contact force and of the links' weights).
#[test]
fn multibody_finger_with_heavy_links_holds() {
    let mut s = scene(Build::Multibody, false, PGS, 1.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link multibody finger, links under gravity", &h);
}

/// The same finger at rapier's default of one PGS iteration per solver pass: what it does
/// today (crate README, Limits).
#[test]
fn multibody_finger_at_rapiers_default_iterations() {
    let mut s = scene(Build::Multibody, false, 1, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    println!("two-link multibody finger, 1 PGS iteration: {h:?}");
    assert!(h.force > 1.0, "{h:?}");
    assert!(h.law_error < 0.06, "{h:?}");
    for (motor, contact) in &h.efforts {
        assert!((motor / -contact - 1.0).abs() < 1e-2, "{h:?}");
    }
    assert!(h.box_speed < 1e-6, "{h:?}");
}

#[test]
fn multibody_prismatic_jaw_presses_a_box_and_holds() {
    for pgs in [1, PGS] {
        let mut s = scene(Build::Multibody, true, pgs, 0.0);
        let h = hold(&mut s, &[-0.0015], 240);
        assert_held(&format!("prismatic multibody jaw, {pgs} PGS"), &h);
    }
}

/// A prismatic jaw on a fixed base held by one impulse joint (its motor at 2e4 N/m): the jaw is
/// a jointed body to the soft solve (`jointed`: the joint's locked axes hard rows, its motor
/// rapier's compliant row), so the tip carries the law's force and the motor, read from the
/// impulse rapier writes back, holds `J^T F`. (Seen as a free body before session 11.)
#[test]
fn impulse_prismatic_jaw_presses_a_box_and_holds() {
    for pgs in [1, PGS] {
        let mut s = scene(Build::Impulse, true, pgs, 0.0);
        let h = hold(&mut s, &[-0.0015], 240);
        assert_held(&format!("prismatic impulse-jointed jaw, {pgs} PGS"), &h);
    }
}

/// rapier's Gauss-Seidel sweeps per solver pass at which its own solve of the impulse-jointed
/// two-link finger converges (plain rapier: `tests/impulse_chain_plain.rs`), so that the soft
/// solve sees the chain as one jointed assembly (`joint_sweeps::SWEEP_TOLERANCE`).
const CHAIN_PGS: usize = 256;

/// The finger built with impulse joints (a chain of two dynamic links, revolute joints with
/// position motors) at [`CHAIN_PGS`] sweeps: the solve sees the chain as one assembly (the
/// joints' locked axes hard rows, their motors rapier's compliant rows), so the tip carries the
/// law's force and each motor, read from the impulse rapier writes back, holds `J^T F`; the
/// same numbers as the multibody finger.
#[test]
fn impulse_jointed_finger_presses_a_box_and_holds() {
    let mut s = scene(Build::Impulse, false, CHAIN_PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held(
        &format!("two-link impulse-jointed finger, {CHAIN_PGS} PGS"),
        &h,
    );
    let mut m = scene(Build::Multibody, false, PGS, 0.0);
    let hm = hold(&mut m, &FINGER, 240);
    println!(
        "impulse-jointed vs multibody finger: {:.5} N vs {:.5} N ({:.2e} apart)",
        h.force,
        hm.force,
        (h.force / hm.force - 1.0).abs()
    );
    // The two builds are the same finger: the same force to the law's tolerance.
    assert!((h.force / hm.force - 1.0).abs() < 5e-3, "{h:?} {hm:?}");
}

/// The impulse-jointed finger under gravity: the motors hold the links' weight too.
#[test]
fn impulse_jointed_finger_with_heavy_links_holds() {
    let mut s = scene(Build::Impulse, false, CHAIN_PGS, 1.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link impulse-jointed finger, links under gravity", &h);
}

/// The impulse-jointed finger at the fewest sweeps the solve sees it at (214:
/// `rate^sweeps <= 1e-5` with rate 0.948, `joint_sweeps::SWEEP_TOLERANCE`, set on this finger at
/// 200 / 256 sweeps), and with links 10x denser (rate 0.947, seen from 210), which the
/// tolerance was not set on: both hold within the bounds (0.23 % / 3.8e-5 off the law
/// measured).
#[test]
fn impulse_jointed_finger_holds_from_the_fewest_sweeps_it_is_seen_at() {
    for density in [DENSITY, 10.0 * DENSITY] {
        let mut s = scene_with(Build::Impulse, false, 214, (0.0, density));
        let h = hold(&mut s, &FINGER, 240);
        assert_held(
            &format!("impulse-jointed finger, links of {density} kg/m^3, 214 PGS"),
            &h,
        );
    }
}

/// The impulse-jointed finger with the world at the suite's 2 sweeps and 254 more asked by
/// the finger's links alone (`RigidBody::set_additional_pgs_iterations`: rapier runs them for
/// the links' island component, the finger and the box, not the whole world): seen (the
/// members' extra sweeps count), and the same numbers as at 256 for the world.
#[test]
fn impulse_jointed_finger_with_extra_sweeps_on_its_links_holds() {
    let mut s = scene(Build::Impulse, false, PGS, 0.0);
    for j in &s.joints {
        let rb = s.world.physics.bodies.get_mut(j.child).unwrap();
        rb.set_additional_pgs_iterations(CHAIN_PGS - PGS);
    }
    let h = hold(&mut s, &FINGER, 240);
    assert_held(
        &format!(
            "impulse-jointed finger, {PGS} PGS + {} on its links",
            CHAIN_PGS - PGS
        ),
        &h,
    );
}

/// The impulse-jointed finger at 2 sweeps, where rapier's own solve of the chain does not
/// converge: the solve does not see the chain (`joint_sweeps::SWEEP_TOLERANCE`), each link is a free
/// body and the soft impulse on the last one is predicted with its own mass alone. What it
/// does (crate README, Limits): 0.004 N where the law asks 6.3 N, the tip sinks into the box,
/// nothing is thrown, the box still.
#[test]
fn impulse_jointed_finger_at_few_sweeps_is_not_seen() {
    let mut s = scene(Build::Impulse, false, PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    println!("two-link impulse-jointed finger, {PGS} PGS: {h:?}");
    assert!(h.force.is_finite() && h.force < 0.05, "{h:?}");
    assert!(h.law_error > 0.99, "{h:?}");
    assert!(h.box_speed < 1e-6, "{h:?}");
}

/// The squeeze: joint 1's target turns down slowly (by 0.04 rad over 32 s: the tip moves down
/// at about 0.1 mm/s), the force read every step against the law at the geometry's
/// compression in the middle of the step (the mean of its start and end); for the prismatic
/// jaw its target moves down by 2 mm over the same 32 s. Returns the worst `|F / F_law - 1|`
/// past 2 N and the peak force \[N\].
fn squeeze(build: Build, prismatic: bool, pgs: usize) -> (f64, f64) {
    let mut s = scene(build, prismatic, pgs, 0.0);
    let steps = 1920;
    let (mut worst, mut peak) = (0.0f64, 0.0f64);
    let mut before: Option<f64> = None;
    for i in 0..steps {
        let ramp = (i + 1) as f32 / steps as f32;
        if prismatic {
            s.set_targets(&[-0.0003 - 0.002 * ramp]);
        } else {
            s.set_targets(&[-0.01 - 0.04 * ramp, 0.0]);
        }
        s.world.step();
        let Some(c) = s
            .world
            .soft
            .contacts()
            .iter()
            .find(|c| c.other == s.box_col)
        else {
            before = None;
            continue;
        };
        let f = c.normal_force;
        let after = s.geometric_delta();
        // (past 2 N: the first 0.2 mm, where the lag of one step weighs most, measured 0.52 %
        // at 1 N)
        if let Some(b) = before
            && f > 2.0
        {
            let e = (f / s.law.response(0.5 * (b + after)).force - 1.0).abs();
            worst = worst.max(e);
        }
        before = Some(after);
        peak = peak.max(f);
    }
    println!(
        "squeeze by the motor ({build:?}, prismatic {prismatic}, {pgs} PGS): worst |F/F_law - 1| {worst:.3e}, peak {peak:.2} N"
    );
    (worst, peak)
}

#[test]
fn multibody_finger_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Multibody, false, PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}

#[test]
fn impulse_jointed_finger_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Impulse, false, CHAIN_PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}

#[test]
fn impulse_prismatic_jaw_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Impulse, true, PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}

/// A parallel jaw as one multibody: two prismatic fingers along x on a fixed base, the right one
/// coupled to the left by a mimic (`q_right = -q_left`, a dof coupling), only the left motored
/// (2e4 N/m); a fingertip on each finger squeezes the box on the table from its sides. The two
/// pads are rows on two links of one multibody (coupled through its mobility and the coupling).
/// At rest each pad reads the law at its geometric compression, both the same force, and the
/// left motor holds `J^T F` of both pads through the coupling (`2 F`).
///
/// Not right yet at the suite's 2 PGS iterations: the jaws do not settle. Why (session 10):
/// rapier solves the motor (a compliant row on the left dof) and the coupling (a hard row)
/// by Gauss-Seidel in `num_internal_pgs_iterations` sweeps, while the plugin's mobility folds
/// both in exactly (`multibody::couple`, a Schur complement: the converged answer). The
/// right pad's force reaches the left motor only partly within 2 sweeps, so an unsplit step
/// with 5.6 N on the pads throws both fingers 36 mm open where the plugin predicts 0.3 mm;
/// the motor brings them back, the next contact is split (~460 substeps, 2.1 / 2.4 N), and
/// the cycle repeats every 4 steps; the box creeps along z. At 8 sweeps the cycle is 2 steps
/// (5.48 N unsplit, 3.8 N split, motor 19.4 N against `J^T F` 11.0 N); at 64 sweeps every
/// step is unsplit and settled ([`multibody_mimic_jaws_settle_with_converged_pgs`]). The fix
/// is a mobility that is rapier's PGS after its sweeps (or rapier's coupling carried as an
/// exact elimination), not done. The shipped URDF gripper (a mimic finger at 2000 N/m)
/// reaches 5.07 / 5.09 N against its 5 N, lifts and holds (softgrip-scene `robots`).
#[test]
#[ignore = "the mimic-coupled jaws do not settle at 2 PGS iterations (see the doc comment; crate README, Limits)"]
fn multibody_mimic_jaws_squeeze_a_box() {
    let m = mimic_jaws(PGS);
    assert!(m.forces[0] > 1.0, "{:?}", m.forces);
    assert!(m.worst < 5e-3, "{}", m.worst);
    assert!(m.balance < 1e-3, "{}", m.balance);
    assert!(m.effort_error < 1e-2, "{}", m.effort_error);
}

/// The mimic-coupled jaws of [`multibody_mimic_jaws_squeeze_a_box`] with rapier's PGS run to
/// convergence (64 sweeps), where the plugin's exact fold of the motor and the coupling is
/// what rapier does: every step of the hold unsplit, the two pads equal (3.1e-5), the motor's
/// effort `J^T F` of both pads through the coupling (2.1e-5), both fingers where the coupling
/// puts them (8e-10 m).
#[test]
fn multibody_mimic_jaws_settle_with_converged_pgs() {
    let m = mimic_jaws(64);
    assert!(m.forces[0] > 5.0 && m.forces[0] < 6.0, "{:?}", m.forces);
    assert_eq!(m.max_substeps_hold, 1, "the hold's steps are split");
    assert!(m.balance < 1e-4, "pads differ {}", m.balance);
    assert!(m.effort_error < 1e-4, "motor vs J^T F {}", m.effort_error);
    assert!(
        m.mimic_error < 1e-8,
        "the coupling is {} m off",
        m.mimic_error
    );
    // Bounded at what it does: 2.96e-2 off the law at the geometry's compression, not yet
    // understood (the single prismatic jaw is 1.5e-5 off; the contact's own compression is
    // the law's, the box's pose against the pads' centres is not).
    assert!(m.worst < 0.04, "{}", m.worst);
}

/// What [`mimic_jaws`] measured after its 240 steps.
struct Mimic {
    forces: Vec<f64>,
    /// The worst `|F / F_law(delta_geometry) - 1|` of the two pads.
    worst: f64,
    /// `|F_left / F_right - 1|`.
    balance: f64,
    /// The left motor's effort against `J^T F` of both pads.
    effort_error: f64,
    /// The largest substep count over the last 60 steps.
    max_substeps_hold: u32,
    /// `|q_right + q_left|` \[m\].
    mimic_error: f64,
}

/// The mimic-coupled jaws squeezing the box for 240 steps at `pgs` PGS iterations.
fn mimic_jaws(pgs: usize) -> Mimic {
    let (mut world, box_body, box_col) = table_and_box(pgs, 0.0);
    let y = HALF;
    let base = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(Vector::new(0.0, y + 0.05, 0.0)));
    let open = HALF + R as f32 + GAP;
    let mut fingers = Vec::new();
    let mut tips = Vec::new();
    let mut laws = Vec::new();
    for side in [-1.0f32, 1.0] {
        let body = light_link(
            &mut world,
            Vector::new(side * open, y, 0.0),
            (0.0, DENSITY),
            Vector::new(0.003, 0.02, 0.004),
            Vector::new(side * 0.012, 0.02, 0.0),
        );
        let anchor = Vector::new(side * open, -0.05, 0.0);
        let data: GenericJoint = if side < 0.0 {
            motored_joint(JointKind::Prismatic, Vector::X, anchor, 0.0015)
        } else {
            PrismaticJointBuilder::new(Vector::X)
                .local_anchor1(anchor)
                .local_anchor2(Vector::ZERO)
                .build()
                .into()
        };
        world
            .physics
            .multibody_joints
            .insert(base, body, data, true)
            .unwrap();
        let (tip, law) = soft_tip(&mut world, body, Vector::ZERO);
        laws.push(law);
        fingers.push(body);
        tips.push(tip);
    }
    let links = fingers.map_links(&world);
    {
        let mb = world
            .physics
            .multibody_joints
            .get_multibody_mut(links[0].multibody)
            .unwrap();
        mb.add_dof_coupling(MultibodyDofCoupling {
            link1: links[0].id,
            dof1: 0,
            axis1: 0,
            link2: links[1].id,
            dof2: 0,
            axis2: 0,
            coeff: -1.0,
            offset: 0.0,
        });
    }
    let law = &laws[0];
    let mut max_substeps_hold = 0;
    for i in 0..240 {
        world.step();
        if i >= 180 {
            max_substeps_hold = max_substeps_hold.max(world.soft.counters().substeps_last);
        }
    }
    let p = &world.physics;
    let rb = &p.bodies[box_body];
    let mut forces = Vec::new();
    let mut worst = 0.0f64;
    let mut generalised = 0.0;
    for (k, tip) in tips.iter().enumerate() {
        let c = world
            .soft
            .contacts()
            .iter()
            .find(|c| c.fingertip == *tip && c.other == box_col)
            .expect("each pad touches the box");
        let centre = p.colliders[*tip].translation();
        let side = if k == 0 { -1.0 } else { 1.0 };
        let face = rb
            .position()
            .transform_point(Vector::new(side * HALF, 0.0, 0.0))
            .x;
        let delta = R - (side * (centre.x - face)) as f64;
        worst = worst.max((c.normal_force / law.response(delta).force - 1.0).abs());
        forces.push(c.normal_force);
        let (f, _) = c.wrench_about([0.0; 3]);
        // d q_k / d q_left: 1 for the left finger, the coupling's -1 for the right.
        generalised += f[0] * if k == 0 { 1.0 } else { -1.0 };
    }
    let mb = p
        .multibody_joints
        .get_multibody(links[0].multibody)
        .unwrap();
    let left = mb.link(links[0].id).unwrap();
    let (q, v) = (
        left.joint().coords()[0] as f64,
        mb.joint_velocity(left)[0] as f64,
    );
    let effort = K_PRI as f64 * (0.0015 - q) - C_PRI as f64 * v;
    let effort_error = (effort / -generalised - 1.0).abs();
    let balance = (forces[0] / forces[1] - 1.0).abs();
    let right = mb.link(links[1].id).unwrap();
    let mimic_error = (right.joint().coords()[0] as f64 + q).abs();
    println!(
        "mimic jaws at {pgs} PGS iterations: forces {forces:?} N, worst |F/F_law - 1| \
         {worst:.2e}, pads differ {balance:.2e}, motor {effort:.4} N vs J^T F {:.4} N \
         ({effort_error:.2e}), substeps in the hold <= {max_substeps_hold}, coupling off by \
         {mimic_error:.2e} m",
        -generalised
    );
    Mimic {
        forces,
        worst,
        balance,
        effort_error,
        max_substeps_hold,
        mimic_error,
    }
}

/// The multibody link ids of bodies.
trait MapLinks {
    fn map_links(&self, world: &SoftWorld) -> Vec<MultibodyLinkId>;
}

impl MapLinks for Vec<RigidBodyHandle> {
    fn map_links(&self, world: &SoftWorld) -> Vec<MultibodyLinkId> {
        self.iter()
            .map(|b| *world.physics.multibody_joints.rigid_body_link(*b).unwrap())
            .collect()
    }
}

/// A multibody's kinematic root moved with `set_next_kinematic_translation` (a robot's base
/// lifted) carries its links: rapier 0.36.1 alone overwrites the target at the start of its
/// step and the base stays put; through the plugin the base ends each step at its target and
/// its motored prismatic link rides along at its joint position (a fingertip on the link,
/// in the air). Then rotated with `set_next_kinematic_position`: the link turns with it.
#[test]
fn kinematic_multibody_root_moves_to_its_target() {
    let mut world = SoftWorld::new();
    let base = world.physics.bodies.insert(
        RigidBodyBuilder::kinematic_position_based().translation(Vector::new(0.0, 0.1, 0.0)),
    );
    let link = light_link(
        &mut world,
        Vector::new(0.03, 0.1, 0.0),
        (0.0, DENSITY),
        Vector::new(0.003, 0.02, 0.004),
        Vector::ZERO,
    );
    let data = motored_joint(
        JointKind::Prismatic,
        Vector::X,
        Vector::new(0.03, 0.0, 0.0),
        0.0,
    );
    world
        .physics
        .multibody_joints
        .insert(base, link, data, true)
        .unwrap();
    soft_tip(&mut world, link, Vector::ZERO);
    let dt = world.physics.integration_parameters.dt;
    let mut worst = 0.0f32;
    for k in 1..=30 {
        let y = 0.1 + 0.1 * dt * k as f32;
        world.physics.bodies[base].set_next_kinematic_translation(Vector::new(0.0, y, 0.0));
        world.step();
        let (b, l) = (
            world.physics.bodies[base].translation(),
            world.physics.bodies[link].translation(),
        );
        worst = worst
            .max((b.y - y).abs())
            .max((l.y - y).abs())
            .max((l.x - 0.03).abs());
    }
    println!("kinematic root lifted 5 cm: base and link off their targets by at most {worst:e} m");
    assert!(worst < 1e-6, "{worst}");
    // A quarter turn about y over 30 steps: the link (3 cm along x) ends at -z.
    let top = *world.physics.bodies[base].position();
    for k in 1..=30 {
        let angle = std::f32::consts::FRAC_PI_2 * k as f32 / 30.0;
        let pose = Pose::from_parts(top.translation, Rotation::from_rotation_y(angle));
        world.physics.bodies[base].set_next_kinematic_position(pose);
        world.step();
    }
    let l = world.physics.bodies[link].translation();
    println!("after a quarter turn the link is at {l:?}");
    assert!(
        (l.x).abs() < 1e-5 && (l.z + 0.03).abs() < 1e-5 && (l.y - top.translation.y).abs() < 1e-6,
        "{l:?}"
    );
}
