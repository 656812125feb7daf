//! The paths and velocities of position-based kinematic bodies over a (split) step.

use nalgebra::Vector3;
use rapier3d::prelude::{Pose, RigidBodyHandle, RigidBodySet, RigidBodyType};

use crate::boundary::to_f64;
use crate::fast_hash::FastMap;

/// Velocity of a kinematic body over the coming (sub)step: (linear [m/s], angular [rad/s]).
pub(crate) type KinematicVelocity = FastMap<RigidBodyHandle, (Vector3<f64>, Vector3<f64>)>;

/// A position-based kinematic body's path over one step: (handle, start pose, target pose).
pub(crate) type KinematicPath = (RigidBodyHandle, Pose, Pose);
/// The paths of every position-based kinematic body over the coming step, and the fastest
/// motion of the world (`detect::fastest_motion`, found in the same walk of the body set: a
/// sleeping world of N bodies walked it twice per step).
pub(crate) fn kinematic_paths(bodies: &RigidBodySet) -> (Vec<KinematicPath>, (f32, f32)) {
    let mut paths = Vec::new();
    let mut fastest = (0.0f32, 0.0f32);
    for (h, rb) in bodies.iter() {
        if rb.body_type() == RigidBodyType::KinematicPositionBased {
            paths.push((h, *rb.position(), *rb.next_position()));
        }
        crate::detect::fold_fastest(&mut fastest, rb);
    }
    (paths, fastest)
}

/// The pose at fraction `s` of a path (linear in translation, slerp in rotation).
pub(crate) fn interpolate(start: &Pose, target: &Pose, s: f32) -> Pose {
    Pose::from_parts(
        start.translation.lerp(target.translation, s),
        start.rotation.slerp(target.rotation, s),
    )
}
/// Velocities of the position-based kinematic bodies over the part of their path that ends at
/// fraction `s` of the step, taking `h` seconds.
pub(crate) fn kinematic_velocities(
    bodies: &RigidBodySet,
    kinematic: &[KinematicPath],
    s: f64,
    h: f64,
) -> KinematicVelocity {
    let mut out = KinematicVelocity::default();
    for (handle, start, target) in kinematic {
        let Some(rb) = bodies.get(*handle) else {
            continue;
        };
        let goal = interpolate(start, target, s as f32);
        let now = rb.position();
        let v = to_f64(goal.translation - now.translation) / h;
        let (axis, mut angle) = (goal.rotation * now.rotation.inverse()).to_axis_angle();
        if angle > std::f32::consts::PI {
            angle -= 2.0 * std::f32::consts::PI;
        }
        let w = to_f64(axis * angle) / h;
        out.insert(*handle, (v, w));
    }
    out
}
