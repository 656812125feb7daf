//! A multibody link pushed into a fixed body (rapier only, no fingertip): the parallel
//! gripper's prismatic fingers under their kinematic base, lowered into the ground. Their
//! joints cannot move them along the ground's normal, so rapier's contact rows there have a
//! mobility of `f32` noise and asked an impulse of its inverse: with the plugin's drop
//! disabled a finger was thrown 10.7 km off its path at 6.4e5 m/s (the two mimic-coupled
//! fingers 73 km). The plugin drops those contacts (`link_contacts.rs`): the fingers follow
//! their base into the ground, on their paths. A link on a revolute joint that can swing out
//! of the ground keeps its contacts (none dropped) and is pushed out against its motor.
//!
//! `cargo test -p softgrip-rapier --test locked_link_contacts -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_rapier::SoftWorld;

/// The root's start height \[m\].
const TOP: f32 = 0.1;

/// What [`lower`] measured (over all links).
#[derive(Debug)]
struct Lowered {
    /// A link's largest distance from its commanded path (its start carried down with the
    /// root; the motors hold their joints at 0) \[m\].
    off_path: f32,
    /// A link's largest speed \[m/s\].
    speed: f32,
    /// The lowest of the links' corners \[m\] (0 is the ground's top).
    lowest: f32,
    /// The lowest of their corners at the end \[m\].
    end_lowest: f32,
    /// rapier's link contacts dropped (`SoftCounters::locked_link_contacts`).
    locked: u64,
}

/// A robot of box links on one kinematic root (starts turned as the root by `root_rotation`);
/// with `mimic`, the second link's dof is
/// coupled to the first's (`q_2 = -q_1`, a URDF `<mimic>` as rapier holds it).
struct Robot {
    /// Each link's joint, its start and its box's centre in its own frame.
    joints: Vec<(GenericJoint, Vector, Vector)>,
    /// The boxes' half extents \[m\].
    half: Vector,
    /// Each box's mass \[kg\] (`None`: 1000 kg/m^3).
    mass: Option<f32>,
    root_rotation: Rotation,
    mimic: bool,
}

/// Lowers `robot`'s root by `depth` at 0.12 m/s, then holds it (75 steps in all).
fn lower(robot: Robot, depth: f32) -> Lowered {
    let mut world = SoftWorld::new();
    let p = &mut world.physics;
    let ground = p.bodies.insert(RigidBodyBuilder::fixed());
    p.colliders.insert_with_parent(
        ColliderBuilder::cuboid(1.0, 0.05, 1.0).translation(Vector::new(0.0, -0.05, 0.0)),
        ground,
        &mut p.bodies,
    );
    let turn = robot.root_rotation;
    let root = p.bodies.insert(
        RigidBodyBuilder::kinematic_position_based()
            .pose(Pose::from_parts(Vector::new(0.0, TOP, 0.0), turn)),
    );
    let mut links = Vec::new();
    let h = robot.half;
    let density = robot.mass.map_or(1000.0, |m| m / (8.0 * h.x * h.y * h.z));
    for (joint, start, centre) in &robot.joints {
        let link = p.bodies.insert(
            RigidBodyBuilder::dynamic()
                .pose(Pose::from_parts(*start, turn))
                .can_sleep(false),
        );
        p.colliders.insert_with_parent(
            ColliderBuilder::cuboid(h.x, h.y, h.z)
                .translation(*centre)
                .density(density),
            link,
            &mut p.bodies,
        );
        p.multibody_joints.insert(root, link, *joint, true).unwrap();
        links.push((link, *start, *centre));
    }
    if robot.mimic {
        let mbj = &mut p.multibody_joints;
        let (a, b) = (
            mbj.rigid_body_link(links[0].0).copied().unwrap(),
            mbj.rigid_body_link(links[1].0).copied().unwrap(),
        );
        mbj.get_multibody_mut(a.multibody)
            .unwrap()
            .add_dof_coupling(MultibodyDofCoupling {
                link1: a.id,
                dof1: 0,
                axis1: 0,
                link2: b.id,
                dof2: 0,
                axis2: 0,
                coeff: -1.0,
                offset: 0.0,
            });
    }
    let dt = world.physics.integration_parameters.dt;
    let mut out = Lowered {
        off_path: 0.0,
        speed: 0.0,
        lowest: f32::INFINITY,
        end_lowest: f32::INFINITY,
        locked: 0,
    };
    let mut last: Vec<Vector> = (links.iter())
        .map(|(l, _, _)| world.physics.bodies[*l].translation())
        .collect();
    for k in 1..=75 {
        let y = TOP - (0.12 * dt * k as f32).min(depth);
        let pose = Pose::from_parts(Vector::new(0.0, y, 0.0), turn);
        world.physics.bodies[root].set_next_kinematic_position(pose);
        world.step();
        out.end_lowest = f32::INFINITY;
        for ((link, start, centre), last) in links.iter().zip(&mut last) {
            let b = &world.physics.bodies[*link];
            let (t, v) = (b.translation(), b.linvel());
            assert!(t.is_finite() && v.is_finite(), "step {k}: {t} {v}");
            // (rapier leaves a kinematic-rooted link's `linvel` at 0: its speed from its motion)
            out.speed = out.speed.max((t - *last).length() / dt);
            *last = t;
            let path = *start + Vector::new(0.0, y - TOP, 0.0);
            out.off_path = out.off_path.max((t - path).length());
            for c in 0..8 {
                let sign = |bit: i32| if c & bit == 0 { -1.0 } else { 1.0 };
                let corner = *centre + Vector::new(sign(1) * h.x, sign(2) * h.y, sign(4) * h.z);
                out.end_lowest = out.end_lowest.min((*b.position() * corner).y);
            }
        }
        out.lowest = out.lowest.min(out.end_lowest);
    }
    out.locked = world.soft.counters().locked_link_contacts;
    println!("{out:?}");
    out
}

/// A prismatic joint along `axis` (in its root's frame) at `anchor`, position-motored to 0
/// (2000 N/m, 20 N effort) or bare (a mimic's).
fn prismatic(axis: Vector, anchor: Vector, motored: bool) -> GenericJoint {
    let b = PrismaticJointBuilder::new(axis)
        .local_anchor1(anchor)
        .limits([-0.05, 0.05]);
    if motored {
        b.motor_position(0.0, 2000.0, 20.0)
            .motor_max_force(20.0)
            .motor_model(MotorModel::ForceBased)
            .build()
            .into()
    } else {
        b.build().into()
    }
}

/// The parallel gripper's fingers (`robots/parallel_gripper`, 12 x 20 x 60 mm boxes of 50 g
/// hanging below their joints, which slide along -x and +x, the right one the left's mimic
/// when `mimic`) under their base turned as the shipped scene turns it (a URDF's z up in a
/// y-up world: a quarter turn about x).
fn gripper_fingers(mimic: bool) -> Robot {
    let turn = Rotation::from_rotation_x(-std::f32::consts::FRAC_PI_2);
    let at = |a: Vector| Vector::new(0.0, TOP, 0.0) + turn * a;
    let (left, right) = (Vector::new(-0.006, 0.0, 0.0), Vector::new(0.006, 0.0, 0.0));
    let mut joints = vec![(
        prismatic(-Vector::X, left, true),
        at(left),
        Vector::new(-0.006, 0.0, -0.03),
    )];
    if mimic {
        joints.push((
            prismatic(Vector::X, right, false),
            at(right),
            Vector::new(0.006, 0.0, -0.03),
        ));
    }
    Robot {
        joints,
        half: Vector::new(0.006, 0.01, 0.03),
        mass: Some(0.05),
        root_rotation: turn,
        mimic,
    }
}

/// The gripper's left finger alone, lowered with its base until its box would be 1 cm into
/// the ground: it follows its base exactly on its path (1e-6 m), at the base's 0.12 m/s, its
/// rapier contacts with the ground dropped. With the drop disabled rapier threw it 10.7 km
/// off its path at 6.4e5 m/s (measured).
#[test]
fn a_prismatic_finger_lowered_into_the_ground_follows_its_base() {
    let r = lower(gripper_fingers(false), 0.05);
    assert!(r.off_path < 1e-6, "{r:?}: off its path");
    assert!(r.speed < 0.13, "{r:?}: flung");
    assert!((r.lowest + 0.01).abs() < 1e-4, "{r:?}: not into the ground");
    assert!(r.locked > 0, "{r:?}");
}

/// Both fingers, the right one the left's mimic: both follow the base 1 cm into the ground
/// on their paths (73 km off with the drop disabled, measured).
#[test]
fn mimic_coupled_fingers_lowered_into_the_ground_follow_their_base() {
    let r = lower(gripper_fingers(true), 0.05);
    assert!(r.off_path < 1e-6, "{r:?}: off its path");
    assert!(r.speed < 0.13, "{r:?}: flung");
    assert!((r.lowest + 0.01).abs() < 1e-4, "{r:?}: not into the ground");
    assert!(r.locked > 0, "{r:?}");
}

/// A 2 x 4 x 2 cm link (16 g) on a revolute joint about z (its motor 0.2 N m at most), its
/// centre 3 cm from the pivot, lowered until it would be 1 cm in: the ground pushes it
/// to swing out; its contacts stay (none dropped), it ends held out of the ground (within
/// 1 mm) and is not flung.
#[test]
fn a_revolute_link_lowered_onto_the_ground_swings_out_of_it() {
    // The pivot at the root, the link's centre 3 cm from it along x.
    let joint = RevoluteJointBuilder::new(Vector::Z)
        .local_anchor2(Vector::new(-0.03, 0.0, 0.0))
        .motor_position(0.0, 20.0, 0.2)
        .motor_max_force(0.2)
        .motor_model(MotorModel::ForceBased)
        .build();
    let r = lower(
        Robot {
            joints: vec![(joint.into(), Vector::new(0.03, TOP, 0.0), Vector::ZERO)],
            half: Vector::new(0.01, 0.02, 0.01),
            mass: None,
            root_rotation: Rotation::IDENTITY,
            mimic: false,
        },
        0.09,
    );
    assert_eq!(r.locked, 0, "{r:?}");
    assert!(r.speed < 1.0, "{r:?}: flung");
    // Held out of the ground at the end (rapier's contacts push it out at its correction
    // speed: 4 mm in while the root was still coming down at 2 mm a step).
    assert!(r.end_lowest > -1e-3, "{r:?}: into the ground");
    assert!(r.lowest > -5e-3, "{r:?}: into the ground");
}
