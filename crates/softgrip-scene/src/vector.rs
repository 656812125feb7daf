//! [`vector`]: the one conversion of a scene's `[f64; 3]` to rapier's (f32) `Vector`.

use softgrip_rapier::rapier3d::prelude::Vector;

/// `v` [any unit] as rapier's `Vector` (each component rounded to f32). Every position,
/// offset and direction handed to rapier goes through it, so the ECS and the plain runner
/// round identically.
pub fn vector(v: [f64; 3]) -> Vector {
    Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)
}
