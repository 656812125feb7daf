//! The one boundary between rapier's `f32` vectors and the plugin's `f64` algebra, and its
//! handles as sortable keys.

use nalgebra::Vector3;
use rapier3d::prelude::{ColliderHandle, Vector};

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

/// A collider handle as a sortable pair (index, generation).
#[inline]
pub(crate) fn raw(h: ColliderHandle) -> (u32, u32) {
    h.into_raw_parts()
}
