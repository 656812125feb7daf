//! The one error type of `softgrip-rapier`: raised at construction and registration, never in
//! the step.

use rapier3d::prelude::{ColliderHandle, RigidBodyHandle};
use softgrip_law::Shortest;

/// Everything that can go wrong when building a fingertip or registering it with rapier.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A fingertip parameter is outside its valid range.
    #[error("`{field}` must be {range}, got {}", Shortest(*value))]
    InvalidParameter {
        /// Name of the offending field.
        field: &'static str,
        /// The value that was passed.
        value: f64,
        /// The valid range, with its unit.
        range: &'static str,
    },
    /// A tactile pad is outside its valid range ([`TactilePad`](crate::TactilePad)).
    #[error("`{field}` must be {range}, got {}", Shortest(*value))]
    InvalidTactilePad {
        /// Name of the offending field, e.g. `tactile.width`.
        field: &'static str,
        /// The value that was passed (a count as a number).
        value: f64,
        /// The valid range, with its unit and the numbers of this fingertip.
        range: String,
    },
    /// The builder was given neither a material nor a preset.
    #[error("a fingertip needs a material: call `.material(..)` or `.preset(..)`")]
    MissingMaterial,
    /// A backed fingertip (`flat` or `core`) was given no `facing` direction.
    #[error(
        "a `{0}` fingertip needs `facing`: the direction its pad faces (flat face towards the pole) in its collider's frame, a finite non-zero [x, y, z]"
    )]
    MissingFacing(&'static str),
    /// A law given with `SoftFingertipBuilder::law` was built for another construction than
    /// the fingertip's `backing`.
    #[error("the law was built for backing {law}, the fingertip's backing is {fingertip}")]
    BackingMismatch {
        /// The fingertip's backing.
        fingertip: String,
        /// The backing of the law's parameters.
        law: String,
    },
    /// The contact law rejected the material, radius or level.
    #[error("contact law: {0}")]
    Law(#[from] softgrip_law::Error),
    /// The collider handle is not in the collider set.
    #[error("collider {0:?} is not in the collider set")]
    UnknownCollider(ColliderHandle),
    /// The rigid-body handle is not in the body set.
    #[error("rigid body {0:?} is not in the body set")]
    UnknownBody(RigidBodyHandle),
    /// A pair of bodies to keep apart names one body twice.
    #[error("rigid body {0:?} was named twice: an excluded pair needs two bodies")]
    SamePair(RigidBodyHandle),
    /// Only ball colliders can be soft fingertips.
    #[error("collider {handle:?} has shape {shape}: a soft fingertip must be a ball collider")]
    NotABall {
        /// The collider that was passed.
        handle: ColliderHandle,
        /// Its shape type, as rapier names it.
        shape: String,
    },
    /// The collider's ball radius differs from the fingertip's radius.
    #[error(
        "collider {handle:?} is a ball of radius {} m, the fingertip has radius {} m (they must agree to 1e-5 relative)",
        Shortest(*collider_radius),
        Shortest(*fingertip_radius)
    )]
    RadiusMismatch {
        /// The collider that was passed.
        handle: ColliderHandle,
        /// Radius of the collider's ball \[m\].
        collider_radius: f64,
        /// Radius of the fingertip \[m\].
        fingertip_radius: f64,
    },
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
