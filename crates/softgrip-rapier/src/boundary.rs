//! The one boundary between rapier's `f32` vectors and the plugin's `f64` algebra, and its
//! handles as sortable keys.

use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};
use rapier3d::prelude::{ColliderHandle, Pose, Vector};

/// Converts a glam `f32` vector into the plugin's `f64` algebra (the one boundary).
#[inline]
pub(crate) fn to_f64(v: Vector) -> Vector3<f64> {
    Vector3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// Converts the plugin's `f64` vector back to rapier's `f32` (the other boundary).
#[inline]
pub(crate) fn to_f32(v: &Vector3<f64>) -> Vector {
    Vector::new(v.x as f32, v.y as f32, v.z as f32)
}

/// Converts rapier's `f32` pose into an `f64` isometry (its quaternion re-normalised in `f64`),
/// so that a point carried into a body's frame and back is the same point to `f64` precision.
/// The friction spring's stretch sums, step by step, the slip of material points carried
/// through the poses: in `f32` a resting contact's points came back up to half an ulp (3.7e-9
/// m at 0.1 m) off, the same error every step, which the sum turned into a steady creep.
pub(crate) fn pose_f64(p: &Pose) -> Isometry3<f64> {
    let (t, q) = (p.translation, p.rotation);
    Isometry3::from_parts(
        Translation3::new(t.x as f64, t.y as f64, t.z as f64),
        UnitQuaternion::new_normalize(Quaternion::new(
            q.w as f64, q.x as f64, q.y as f64, q.z as f64,
        )),
    )
}

/// A collider handle as a sortable pair (index, generation).
#[inline]
pub(crate) fn raw(h: ColliderHandle) -> (u32, u32) {
    h.into_raw_parts()
}
