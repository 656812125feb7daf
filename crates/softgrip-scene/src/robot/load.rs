//! The load a robot's joint carries: the joint-space projection `J^T F` of the soft contacts'
//! forces and the weights on the links beyond it, and from it the effort of a multibody mimic
//! joint (rapier's coupling of two joints keeps no impulse to read it from).

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::Vector;

use crate::robot::build::{RobotHandles, RobotJointHandle};
use crate::robot::model::{JointKind, Robot};
use crate::robot::state::{JointState, joint_state};

/// `J^T F` of joint `j` of `robot` (handles `h`) after the last step \[N or N m\]: the
/// generalised force along the joint's axis of the loads on the links beyond it (every soft
/// contact's force and torsional moment on them, whichever side of the contact the link is, and
/// the links' weights), plus, for a multibody joint, `multiplier` times that of each joint
/// mimicking it (a mimic's load reaches its leader through the coupling; an impulse mimic joint
/// has its own motor, which carries its load). Rigid (rapier) contacts on the links are not
/// counted. 0 for a fixed joint or a joint the world does not hold.
pub fn joint_load(robot: &Robot, world: &SoftWorld, h: &RobotHandles, j: usize) -> f64 {
    let own = own_load(robot, world, h, j).unwrap_or(0.0);
    if !matches!(h.joints.get(j), Some(RobotJointHandle::Multibody(_))) {
        return own;
    }
    let mimics: f64 = (robot.joints().iter().enumerate())
        .filter_map(|(m, o)| {
            o.mimic
                .filter(|mm| mm.joint == j && m != j)
                .map(|mm| (m, mm))
        })
        .map(|(m, mm)| mm.multiplier * joint_load(robot, world, h, m))
        .sum();
    own + mimics
}

/// The load of joint `j` without its mimics'; `None` where it has no axis in the world.
fn own_load(robot: &Robot, world: &SoftWorld, h: &RobotHandles, j: usize) -> Option<f64> {
    let joint = robot.joints().get(j)?;
    if !joint.kind.moves() {
        return None;
    }
    let p = &world.physics;
    let frame1 = match h.joints[j] {
        RobotJointHandle::Multibody(mh) => {
            let (mb, id) = p.multibody_joints.get(mh)?;
            mb.link(id)?.joint.data.local_frame1
        }
        RobotJointHandle::Impulse(ih) => p.impulse_joints.get(ih)?.data.local_frame1,
        RobotJointHandle::None => return None,
    };
    let frame = *p.bodies.get(*h.links.get(joint.parent)?)?.position() * frame1;
    let a = frame.rotation * Vector::X;
    let a = [a.x as f64, a.y as f64, a.z as f64];
    let o = frame.translation;
    let o = [o.x as f64, o.y as f64, o.z as f64];
    let revolute = joint.kind != JointKind::Prismatic;
    let beyond = links_beyond(robot, joint.child);
    let on_beyond = |collider| {
        let body = p.colliders.get(collider)?.parent()?;
        let link = h.links.iter().position(|&l| l == body)?;
        beyond[link].then_some(())
    };
    // A force `f` at `x` along the axis (prismatic) or its moment about it (revolute).
    let project = |x: [f64; 3], f: [f64; 3]| {
        if revolute {
            dot(cross(sub(x, o), f), a)
        } else {
            dot(f, a)
        }
    };
    let mut load = 0.0;
    for c in world.soft.contacts() {
        // The reading's force and moment act on the fingertip; the other body gets their
        // opposite.
        let sign = match (on_beyond(c.fingertip), on_beyond(c.other)) {
            (Some(()), None) => 1.0,
            (None, Some(())) => -1.0,
            _ => continue,
        };
        let r = &c.reading;
        let f = [0, 1, 2].map(|k| sign * (r.normal_force * r.normal[k] + r.friction_force[k]));
        load += project(r.point, f);
        if revolute {
            load += sign * r.torsional_moment * dot(r.normal, a);
        }
    }
    for (i, &l) in h.links.iter().enumerate() {
        let Some(rb) = p.bodies.get(l).filter(|_| beyond[i]) else {
            continue;
        };
        let w = p.gravity * (rb.mass() * rb.gravity_scale());
        let com = rb.center_of_mass();
        load += project(
            [com.x as f64, com.y as f64, com.z as f64],
            [w.x as f64, w.y as f64, w.z as f64],
        );
    }
    Some(load)
}

/// Which links are `child` or below it.
fn links_beyond(robot: &Robot, child: usize) -> Vec<bool> {
    let mut beyond = vec![false; robot.links().len()];
    beyond[child] = true;
    for _ in 0..robot.joints().len() {
        for o in robot.joints() {
            beyond[o.child] |= beyond[o.parent];
        }
    }
    beyond
}

/// [`joint_state`] of joint `j`, with the effort of a multibody mimic joint: the force its
/// coupling carries, `-J^T F` of its own load ([`joint_load`]), what holds its links where the
/// coupling puts them (quasi-static: the links' inertia is not counted). rapier solves the
/// coupling as a velocity constraint whose impulse it does not keep, and the joint has no motor;
/// at rest this is the coupling's share of its leader's motor effort (`tau_leader =
/// -J^T F_leader + multiplier tau_mimic`).
pub fn joint_state_loaded(
    robot: &Robot,
    world: &SoftWorld,
    h: &RobotHandles,
    j: usize,
    substep: f64,
) -> JointState {
    let mut s = joint_state(robot, &world.physics, h, j, substep);
    let coupled = robot.joints().get(j).is_some_and(|jt| jt.mimic.is_some());
    if coupled && matches!(h.joints.get(j), Some(RobotJointHandle::Multibody(_))) {
        s.effort = -joint_load(robot, world, h, j);
    }
    s
}

fn dot(u: [f64; 3], v: [f64; 3]) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

fn sub(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [u[0] - v[0], u[1] - v[1], u[2] - v[2]]
}

fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}
