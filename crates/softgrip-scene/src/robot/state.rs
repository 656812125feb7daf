//! A robot's joints in a rapier world: their position, velocity and effort after a step, their
//! motors' targets, and the forward kinematics of an impulse-jointed robot at given positions.

use softgrip_rapier::rapier3d::prelude::{PhysicsWorld, Pose, Rotation, Vector};

use crate::robot::build::{RobotHandles, RobotJointHandle, motor_axis};
use crate::robot::model::{JointKind, Robot, RobotJoint};
use crate::robot::spec::JointModel;

/// A joint's state after a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JointState {
    /// Position \[m or rad\].
    pub position: f64,
    /// Velocity \[m/s or rad/s\].
    pub velocity: f64,
    /// Force or torque of its motor on the child link along the joint's axis \[N or N m\]:
    /// impulse joints, minus the motor's and the limit's impulses rapier writes back over the
    /// length of the solver pass they are from, its last (`substep / num_solver_iterations`;
    /// rapier's impulse pushes the child against the axis); multibody joints, the motor's spring law
    /// `k (q_target - q) + d (v_target - v)` clamped to the effort limit (rapier does not write
    /// a multibody motor's impulse back); a multibody mimic joint (no motor) 0 here, the load its
    /// coupling carries in [`joint_state_loaded`](crate::robot::joint_state_loaded).
    pub effort: f64,
}

/// The state of joint `j` of `robot` (handles `h`) in `world`; `substep` \[s\] is the length
/// of the last pipeline step (`dt` over the plugin's substeps).
pub fn joint_state(
    robot: &Robot,
    world: &PhysicsWorld,
    h: &RobotHandles,
    j: usize,
    substep: f64,
) -> JointState {
    let joint = &robot.joints()[j];
    if !joint.kind.moves() {
        return JointState::default();
    }
    let axis = motor_axis(joint.kind);
    let i = axis as usize;
    match h.joints[j] {
        RobotJointHandle::Multibody(handle) => {
            let Some((mb, link)) = world.multibody_joints.get(handle) else {
                return JointState::default();
            };
            let Some(l) = mb.link(link) else {
                return JointState::default();
            };
            let q = l.joint.coords()[i] as f64;
            let v = mb.joint_velocity(l).get(0).copied().unwrap_or(0.0) as f64;
            // A mimic joint has no motor (`joint_state_loaded` reads its coupling's load).
            let effort = l.joint.data.motor(axis).map_or(0.0, |m| {
                let tau = m.stiffness as f64 * (m.target_pos as f64 - q)
                    + m.damping as f64 * (m.target_vel as f64 - v);
                let max = m.max_force as f64;
                if joint.mimic.is_some() {
                    0.0
                } else {
                    tau.clamp(-max, max)
                }
            });
            JointState {
                position: q,
                velocity: v,
                effort,
            }
        }
        RobotJointHandle::Impulse(handle) => {
            let Some(ij) = world.impulse_joints.get(handle) else {
                return JointState::default();
            };
            let (Some(b1), Some(b2)) = (world.bodies.get(ij.body1()), world.bodies.get(ij.body2()))
            else {
                return JointState::default();
            };
            let f1 = *b1.position() * ij.data.local_frame1;
            let f2 = *b2.position() * ij.data.local_frame2;
            let rel = f1.inverse() * f2;
            let world_axis = f1.rotation * Vector::X;
            let (q, v) = if joint.kind == JointKind::Prismatic {
                let dv =
                    b2.velocity_at_point(f2.translation) - b1.velocity_at_point(f2.translation);
                (rel.translation.x as f64, dv.dot(world_axis) as f64)
            } else {
                let r = rel.rotation;
                let angle = 2.0 * (r.x as f64).atan2(r.w as f64);
                let angle = (angle + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                    - std::f64::consts::PI;
                (angle, (b2.angvel() - b1.angvel()).dot(world_axis) as f64)
            };
            let impulse = ij.data.motor(axis).map_or(0.0, |m| m.impulse as f64)
                + ij.data.limits(axis).map_or(0.0, |l| l.impulse as f64);
            // The last solver pass's impulse (the pipeline step runs `num_solver_iterations`
            // passes of `substep / num_solver_iterations` each).
            let pass = substep / world.integration_parameters.num_solver_iterations.max(1) as f64;
            JointState {
                position: q,
                velocity: v,
                effort: if pass > 0.0 { -impulse / pass } else { 0.0 },
            }
        }
        RobotJointHandle::None => JointState::default(),
    }
}

/// Sets joint `j`'s motor target: `position` \[m or rad\] and `velocity` \[m/s or rad/s\];
/// in an impulse-jointed robot, its mimic joints' targets follow (`multiplier q + offset`). A
/// multibody mimic joint has no motor (its coupling moves it): nothing is set for it.
pub fn set_joint_target(
    robot: &Robot,
    world: &mut PhysicsWorld,
    h: &RobotHandles,
    j: usize,
    position: f64,
    velocity: f64,
) {
    let joint = &robot.joints()[j];
    if !joint.kind.moves() {
        return;
    }
    // An impulse-jointed robot's mimic joints follow by their motors, through chains of
    // mimics (a mimic of a mimic; the URDF check rules out cycles).
    if robot.joint_model() == JointModel::Impulse {
        let mut leaders = vec![(j, position, velocity)];
        while let Some((leader, position, velocity)) = leaders.pop() {
            for (f, follower) in robot.joints().iter().enumerate() {
                if let Some(m) = follower.mimic.filter(|m| m.joint == leader) {
                    let (p, v) = (m.multiplier * position + m.offset, m.multiplier * velocity);
                    set_motor_target(follower, world, h.joints[f], p, v);
                    leaders.push((f, p, v));
                }
            }
        }
    }
    set_motor_target(joint, world, h.joints[j], position, velocity);
}

/// Sets `joint`'s motor target (`handle` its rapier joint).
fn set_motor_target(
    joint: &RobotJoint,
    world: &mut PhysicsWorld,
    handle: RobotJointHandle,
    position: f64,
    velocity: f64,
) {
    let axis = motor_axis(joint.kind);
    let (k, d) = (joint.stiffness as f32, joint.damping as f32);
    let (p, v) = (position as f32, velocity as f32);
    match handle {
        RobotJointHandle::Multibody(handle) => {
            if joint.mimic.is_some() {
                return;
            }
            if let Some((mb, link)) = world.multibody_joints.get_mut(handle)
                && let Some(l) = mb.link_mut(link)
            {
                l.joint.data.set_motor(axis, p, v, k, d);
            }
        }
        RobotJointHandle::Impulse(handle) => {
            if let Some(ij) = world.impulse_joints.get_mut(handle, false) {
                ij.data.set_motor(axis, p, v, k, d);
            }
        }
        RobotJointHandle::None => {}
    }
}

/// Joint `j`'s motor target: `(position [m or rad], velocity [m/s or rad/s], largest force
/// [N or N m], 0 without a limit)`; `None` for a fixed joint. A multibody mimic joint (driven by
/// its coupling) reads its joint's target through the mimic's multiplier and offset.
pub fn joint_target(
    robot: &Robot,
    world: &PhysicsWorld,
    h: &RobotHandles,
    j: usize,
) -> Option<(f64, f64, f64)> {
    let joint = &robot.joints()[j];
    if !joint.kind.moves() {
        return None;
    }
    if let (Some(m), RobotJointHandle::Multibody(_)) = (joint.mimic, h.joints[j]) {
        let (p, v, _) = joint_target(robot, world, h, m.joint)?;
        return Some((
            m.multiplier * p + m.offset,
            m.multiplier * v,
            joint.effort.unwrap_or(0.0),
        ));
    }
    let axis = motor_axis(joint.kind);
    let motor = match h.joints[j] {
        RobotJointHandle::Multibody(handle) => {
            let (mb, link) = world.multibody_joints.get(handle)?;
            *mb.link(link)?.joint.data.motor(axis)?
        }
        RobotJointHandle::Impulse(handle) => *world.impulse_joints.get(handle)?.data.motor(axis)?,
        RobotJointHandle::None => return None,
    };
    Some((
        motor.target_pos as f64,
        motor.target_vel as f64,
        joint.effort.unwrap_or(0.0),
    ))
}

/// The pose of a joint's child frame relative to its parent frame at position `q`.
fn motion(kind: JointKind, q: f64) -> Pose {
    match kind {
        JointKind::Prismatic => Pose::from_translation(Vector::X * q as f32),
        JointKind::Revolute | JointKind::Continuous => {
            Pose::from_rotation(Rotation::from_axis_angle(Vector::X, q as f32))
        }
        JointKind::Fixed => Pose::IDENTITY,
    }
}

/// Places every link of an impulse-jointed robot at the joint positions `q(joint)`, from its
/// root (which stays where it is) to its leaves.
pub(crate) fn fk_impulse(
    robot: &Robot,
    world: &mut PhysicsWorld,
    h: &RobotHandles,
    q: impl Fn(&RobotJoint) -> f64,
) {
    let mut placed = vec![false; h.links.len()];
    placed[robot.root()] = true;
    let mut progress = true;
    while progress {
        progress = false;
        for (j, handle) in robot.joints().iter().zip(&h.joints) {
            let RobotJointHandle::Impulse(handle) = *handle else {
                continue;
            };
            if placed[j.child] || !placed[j.parent] {
                continue;
            }
            let Some(ij) = world.impulse_joints.get(handle) else {
                continue;
            };
            let (f1, f2) = (ij.data.local_frame1, ij.data.local_frame2);
            let Some(parent) = world.bodies.get(h.links[j.parent]) else {
                continue;
            };
            let pose = *parent.position() * f1 * motion(j.kind, q(j)) * f2.inverse();
            if let Some(child) = world.bodies.get_mut(h.links[j.child]) {
                child.set_position(pose, false);
            }
            placed[j.child] = true;
            progress = true;
        }
    }
}
