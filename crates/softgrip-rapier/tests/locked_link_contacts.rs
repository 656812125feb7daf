//! A multibody link pushed into a fixed body (rapier only, no fingertip): a link on a prismatic
//! joint (motored, 20 N effort) under a kinematic root lowered into the ground. Its joint
//! cannot move it along the ground's normal, so rapier's contact row there has a mobility of
//! `f32` noise; the plugin drops those contacts (`link_contacts.rs`) and the link follows its
//! root into the ground, on its path. A link on a revolute joint that can swing out of the
//! ground keeps its contacts (none dropped) and is pushed out against its motor. (In these
//! worlds, one link or two coupled by a mimic, rapier alone stays bounded with those
//! contacts, measured; the parallel gripper had a finger thrown at 1e10 m/s by them, what in
//! it triggers that is not pinned down: `softgrip-scene/tests/driven_into_table.rs`.)
//!
//! `cargo test -p softgrip-rapier --test locked_link_contacts -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_rapier::SoftWorld;

/// The root's start height \[m\]; the link (a 2 x 4 x 2 cm box, 16 g) hangs from it at x = 3 cm,
/// its bottom 2 cm below the root.
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

/// A robot of links (2 x 4 x 2 cm boxes, 16 g) on one kinematic root: each link's joint and
/// start pose (turned as the root by `root_rotation`); with `mimic`, the second link's dof is
/// coupled to the first's (`q_2 = -q_1`, a URDF `<mimic>` as rapier holds it).
struct Robot {
    joints: Vec<(GenericJoint, Vector)>,
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
    for (joint, start) in &robot.joints {
        let link = p.bodies.insert(
            RigidBodyBuilder::dynamic()
                .pose(Pose::from_parts(*start, turn))
                .can_sleep(false),
        );
        p.colliders.insert_with_parent(
            ColliderBuilder::cuboid(0.01, 0.02, 0.01).density(1000.0),
            link,
            &mut p.bodies,
        );
        p.multibody_joints.insert(root, link, *joint, true).unwrap();
        links.push((link, *start));
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
        .map(|(l, _)| world.physics.bodies[*l].translation())
        .collect();
    for k in 1..=75 {
        let y = TOP - (0.12 * dt * k as f32).min(depth);
        let pose = Pose::from_parts(Vector::new(0.0, y, 0.0), turn);
        world.physics.bodies[root].set_next_kinematic_position(pose);
        world.step();
        out.end_lowest = f32::INFINITY;
        for ((link, start), last) in links.iter().zip(&mut last) {
            let b = &world.physics.bodies[*link];
            let (t, v) = (b.translation(), b.linvel());
            assert!(t.is_finite() && v.is_finite(), "step {k}: {t} {v}");
            // (rapier leaves a kinematic-rooted link's `linvel` at 0: its speed from its motion)
            out.speed = out.speed.max((t - *last).length() / dt);
            *last = t;
            let path = *start + Vector::new(0.0, y - TOP, 0.0);
            out.off_path = out.off_path.max((t - path).length());
            for c in 0..8 {
                let corner = Vector::new(
                    if c & 1 == 0 { -0.01 } else { 0.01 },
                    if c & 2 == 0 { -0.02 } else { 0.02 },
                    if c & 4 == 0 { -0.01 } else { 0.01 },
                );
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

/// A URDF's z-up frame in a y-up world (a quarter turn about x), turned 0.3 rad about the
/// vertical: a joint axis along its local y is horizontal with `f32` noise along the vertical
/// (`cos(pi/2)` in `f32` is -4.4e-8), as the parallel gripper's fingers.
fn urdf_turn() -> Rotation {
    Rotation::from_rotation_y(0.3) * Rotation::from_rotation_x(-std::f32::consts::FRAC_PI_2)
}

/// The prismatic link follows its root 1 cm into the ground, exactly on its path (1e-6 m), its
/// speed the root's 0.12 m/s, its rapier contacts with the ground dropped.
#[test]
fn a_prismatic_link_lowered_into_the_ground_follows_its_root() {
    let turn = urdf_turn();
    let anchor = Vector::new(0.0, 0.03, 0.0);
    let start = Vector::new(0.0, TOP, 0.0) + turn * anchor;
    let r = lower(
        Robot {
            joints: vec![(prismatic(Vector::Y, anchor, true), start)],
            root_rotation: turn,
            mimic: false,
        },
        0.1,
    );
    assert!(r.off_path < 1e-6, "{r:?}: off its path");
    assert!(r.speed < 0.13, "{r:?}: flung");
    assert!((r.lowest + 0.01).abs() < 1e-4, "{r:?}: not into the ground");
    assert!(r.locked > 0, "{r:?}");
}

/// Two such links, the second's joint the first's mimic (`q_2 = -q_1`), as the parallel
/// gripper's fingers: both follow the root 1 cm into the ground on their paths.
#[test]
fn mimic_coupled_prismatic_links_lowered_into_the_ground_follow_their_root() {
    let turn = urdf_turn();
    let (a1, a2) = (Vector::new(0.0, 0.03, 0.0), Vector::new(0.0, -0.03, 0.0));
    let at = |a: Vector| Vector::new(0.0, TOP, 0.0) + turn * a;
    let r = lower(
        Robot {
            joints: vec![
                (prismatic(Vector::Y, a1, true), at(a1)),
                (prismatic(Vector::Y, a2, false), at(a2)),
            ],
            root_rotation: turn,
            mimic: true,
        },
        0.1,
    );
    assert!(r.off_path < 1e-6, "{r:?}: off its path");
    assert!(r.speed < 0.13, "{r:?}: flung");
    assert!((r.lowest + 0.01).abs() < 1e-4, "{r:?}: not into the ground");
    assert!(r.locked > 0, "{r:?}");
}

/// The same link on a revolute joint about z (its motor 0.2 N m at most): the ground pushes it
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
            joints: vec![(joint.into(), Vector::new(0.03, TOP, 0.0))],
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
