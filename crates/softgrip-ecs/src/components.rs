//! Components mirrored into rapier: bodies, colliders, fingertips, and what is read back.
//!
//! The rapier builders come from `softgrip-scene` (`body_builder`, `collider_builder`,
//! `fingertip_builder`), the same functions its scene builder uses: a body spawned as
//! components is the same rapier body as one from a scene file.

use bevy_ecs::prelude::{Component, Entity};
use softgrip_rapier::SoftFingertip;
use softgrip_rapier::rapier3d::prelude::{
    ColliderBuilder, ColliderHandle, RigidBodyBuilder, RigidBodyHandle, SharedShape,
};
use softgrip_scene::{BodyKind, Trajectory, body_builder, collider_builder, fingertip_builder};

/// A rigid body to create in rapier (read once, when it is first synchronised).
#[derive(Component, Debug, Clone, PartialEq)]
#[require(BodyPose)]
pub struct RigidBody {
    /// How it moves.
    pub kind: BodyKind,
    /// Initial position \[m\].
    pub position: [f64; 3],
    /// Initial orientation as a rotation vector (axis * angle) \[rad\].
    pub rotation: [f64; 3],
}

impl RigidBody {
    /// A body of `kind` at `position` \[m\], not rotated.
    pub fn at(kind: BodyKind, position: [f64; 3]) -> Self {
        Self {
            kind,
            position,
            rotation: [0.0; 3],
        }
    }

    /// rapier's builder for this body (sleeping disabled: a held object must not fall asleep
    /// between the jaws).
    pub fn builder(&self) -> RigidBodyBuilder {
        body_builder(self.kind, self.position, self.rotation)
    }
}

/// A collision shape attached to a body ([`AttachedTo`]).
#[derive(Component, Debug, Clone)]
pub struct Collider {
    /// The geometry.
    pub shape: SharedShape,
    /// Offset from the body origin \[m\].
    pub offset: [f64; 3],
    /// Density [kg/m^3], > 0.
    pub density: f64,
    /// rapier's friction coefficient for rigid contacts, >= 0.
    pub friction: f64,
    /// rapier's restitution for rigid contacts, in [0, 1].
    pub restitution: f64,
}

impl Collider {
    /// `shape` at the body origin with the scene file's defaults: density 1000 kg/m^3,
    /// friction 0.5, restitution 0.
    pub fn new(shape: SharedShape) -> Self {
        Self {
            shape,
            offset: [0.0; 3],
            density: 1000.0,
            friction: 0.5,
            restitution: 0.0,
        }
    }

    /// The same with density `density` [kg/m^3].
    pub fn with_density(self, density: f64) -> Self {
        Self { density, ..self }
    }

    /// rapier's builder for this collider.
    pub fn builder(&self) -> ColliderBuilder {
        collider_builder(
            self.shape.clone(),
            self.offset,
            self.density,
            self.friction,
            self.restitution,
        )
    }
}

/// A soft spherical fingertip (the plugin's [`SoftFingertip`], same parameters) attached to a
/// body ([`AttachedTo`]): a ball collider of its radius, registered with the plugin.
#[derive(Component, Debug, Clone)]
#[require(FingertipWrench)]
pub struct Fingertip {
    /// The validated fingertip (radius, material, level, restitution, friction).
    pub tip: SoftFingertip,
    /// Centre of the sphere relative to the body origin \[m\].
    pub offset: [f64; 3],
    /// Density of the ball [kg/m^3], > 0.
    pub density: f64,
}

impl Fingertip {
    /// `tip` centred on its body's origin, density 1070 kg/m^3 (silicone; the scene file's
    /// default).
    pub fn new(tip: SoftFingertip) -> Self {
        Self {
            tip,
            offset: [0.0; 3],
            density: 1070.0,
        }
    }

    /// rapier's builder for the fingertip's ball collider.
    pub fn builder(&self) -> ColliderBuilder {
        fingertip_builder(&self.tip, self.offset, self.density)
    }
}

/// The body a collider or fingertip belongs to.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct AttachedTo(pub Entity);

/// The rapier handle of a synchronised body (inserted by the sync system).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierBody(pub RigidBodyHandle);

/// The rapier handle of a synchronised collider or fingertip (inserted by the sync system).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RapierCollider(pub ColliderHandle);

/// A body's pose after the last step (read back from rapier).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyPose {
    /// Position \[m\].
    pub translation: [f64; 3],
    /// Orientation quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
}

/// Where a kinematic body should be at the end of the coming step \[m\] (written by the
/// controllers, applied by the physics step; `None` = stay).
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct KinematicTarget(pub Option<[f64; 3]>);

/// A scripted path of a kinematic body (followed by the `run_controllers` system).
#[derive(Component, Debug, Clone, PartialEq)]
#[require(KinematicTarget)]
pub struct KinematicPath(pub Trajectory);

/// The total contact wrench on a fingertip over the last step (step averages), world frame.
#[derive(Component, Debug, Clone, Copy, PartialEq, Default)]
pub struct FingertipWrench {
    /// Force \[N\].
    pub force: [f64; 3],
    /// Torque about the fingertip's centre [N m].
    pub torque: [f64; 3],
}
