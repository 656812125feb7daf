//! `[[robot]]` as written in a scene file (SCENES.md, "Robots from URDF").

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::exact::exact;

/// A robot loaded from a URDF file.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotSpec {
    /// Unique name among robots and bodies; its links are addressed `<name>/<link>` (their tf
    /// frames, fingertips' `link`, controllers).
    pub name: String,
    /// The URDF file, relative to the scene file.
    pub urdf: String,
    /// `package://<name>/...` resolved against these folders (relative to the scene file):
    /// `{ my_robot = "robots/my_robot" }`. `file://` paths and plain relative paths need none
    /// (a plain relative mesh path is relative to the URDF file).
    #[serde(default)]
    pub package_paths: BTreeMap<String, String>,
    /// Position of the URDF's root link frame \[m\] (default origin).
    #[serde(default, deserialize_with = "exact")]
    pub position: [f64; 3],
    /// Orientation of the root link frame as a rotation vector (axis * angle) \[rad\] (default
    /// none). URDF models are z-up; a y-up scene turns them with `[-1.5707963, 0, 0]`.
    #[serde(default, deserialize_with = "exact")]
    pub rotation: [f64; 3],
    /// How the root link moves: `kinematic` (default: held where it is, moved by controllers),
    /// `fixed` or `dynamic` (free, moved by forces).
    #[serde(default)]
    pub base: BaseKind,
    /// How the joints are simulated: `multibody` (default; reduced coordinates, rapier's
    /// `MultibodyJointSet`) or `impulse` (each link a rigid body, rapier's `ImpulseJointSet`).
    #[serde(default)]
    pub joints: JointModel,
    /// How a URDF mesh becomes a collision shape: `convex_hull` (default, as MuJoCo does) or
    /// `trimesh` (the triangles as they are).
    #[serde(default)]
    pub mesh: MeshShape,
    /// Start position of joints by name \[m or rad\]; joints not named start at 0 (or their
    /// limit nearest to 0). Within the joint's limits.
    #[serde(default)]
    pub initial: BTreeMap<String, f64>,
    /// Stiffness of every joint's position motor (force-based: \[N/m\] for a prismatic joint,
    /// \[N m/rad\] for a revolute one), finite and >= 0 (default 1000).
    #[serde(default = "default_stiffness")]
    pub stiffness: f64,
    /// Damping of every joint's motor (\[N s/m\] or \[N m s/rad\]), finite and >= 0 (default 10).
    #[serde(default = "default_damping")]
    pub damping: f64,
    /// Per-joint `[stiffness, damping]` overriding `stiffness` and `damping`.
    #[serde(default)]
    pub gains: BTreeMap<String, [f64; 2]>,
    /// Whether two links of the robot collide with each other (default `true`). rapier skips
    /// only the pairs joined directly by a joint, so links welded through a chain of fixed
    /// joints (the Panda's link7 - link8 - hand) or closing a chain written as a tree (the
    /// xArm gripper's four-bars) still collide where their collision shapes overlap, at every
    /// pose, and the solve then fights its own joints (the Panda blew up to NaN): with `true`,
    /// the pairs in contact in at least 95 % of 128 configurations sampled over the joints'
    /// ranges are kept from touching (`robot::always_in_contact`, as MoveIt's setup assistant
    /// disables "always in collision" pairs), every other pair collides, and one of those that
    /// starts overlapping deeper than rapier's allowed linear error is an error naming both
    /// links. `false` turns every contact
    /// between the robot's links off (pybullet's and Gazebo's default;
    /// `Multibody::set_self_contacts_enabled`, or, with `joints = "impulse"`, every pair of its
    /// links kept apart by `SoftWorld::exclude_pair`).
    #[serde(default = "default_self_contacts")]
    pub self_contacts: bool,
}

fn default_self_contacts() -> bool {
    true
}

fn default_stiffness() -> f64 {
    1000.0
}
fn default_damping() -> f64 {
    10.0
}

/// How a robot's root link moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BaseKind {
    /// Never moves.
    Fixed,
    /// Position-based kinematic: held at its pose, moved by controllers (a lift).
    #[default]
    Kinematic,
    /// Moved by forces (a free-floating robot).
    Dynamic,
}

/// How a robot's joints are simulated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum JointModel {
    /// Reduced coordinates (rapier's multibody): joints hold exactly; mimic joints are
    /// couplings of the generalised coordinates.
    #[default]
    Multibody,
    /// Each link a free rigid body held by impulse joints (rapier's `ImpulseJointSet`); a mimic
    /// joint's motor follows the joint it mimics.
    Impulse,
}

/// How a URDF mesh becomes a collision shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MeshShape {
    /// The convex hull of the mesh's vertices.
    #[default]
    ConvexHull,
    /// The triangles, as a triangle mesh.
    Trimesh,
}
