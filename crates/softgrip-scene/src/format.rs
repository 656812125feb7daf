//! The scene file's data model, as written in TOML (documented field by field in SCENES.md).
//!
//! Every table rejects unknown fields (`deny_unknown_fields`), so a typo is an error with its
//! line, not a silently ignored setting. Ranges are checked afterwards by
//! [`Scene::parse`](crate::Scene::parse), which names the offending field.

use serde::Deserialize;

use crate::control::ControllerSpec;
use crate::exact::{exact, exact_list_opt, exact_opt};
use crate::level::LevelSpec;
use crate::robot::RobotSpec;

/// A whole experiment: simulation settings, bodies, fingertips, an optional gripper and what
/// to record.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Simulated time \[s\], finite and >= `dt`, at most `max_steps` steps.
    pub duration: f64,
    /// Time step \[s\], in [1e-9, 1] s (default 1/60).
    #[serde(default = "default_dt")]
    pub dt: f64,
    /// Gravity [m/s^2] (default `[0, -9.81, 0]`).
    #[serde(default = "default_gravity", deserialize_with = "exact")]
    pub gravity: [f64; 3],
    /// The cap on the step count `duration / dt`, >= 1 (default
    /// [`DEFAULT_MAX_STEPS`](crate::DEFAULT_MAX_STEPS), 10 million): a run past it is an
    /// error naming `dt` and `duration`. Raise it here for a deliberately long run.
    #[serde(default = "default_max_steps")]
    pub max_steps: u64,
    /// The plugin's accuracy: contact phase per substep \[rad\], in (0, 2] (default 0.05).
    #[serde(default = "default_accuracy")]
    pub accuracy: f64,
    /// What the recorder receives.
    #[serde(default)]
    pub record: RecordSpec,
    /// Rigid bodies, in order.
    #[serde(default, rename = "body")]
    pub bodies: Vec<BodySpec>,
    /// Robots loaded from URDF files, in order (after the bodies).
    #[serde(default, rename = "robot")]
    pub robots: Vec<RobotSpec>,
    /// Soft fingertips, each attached to a body or a robot's link.
    #[serde(default, rename = "fingertip")]
    pub fingertips: Vec<FingertipSpec>,
    /// A parallel-jaw gripper controller (the controller `parallel_jaws`, written the short way).
    #[serde(default)]
    pub gripper: Option<GripperSpec>,
    /// Controllers, in order (after the `[gripper]`): each one of the kinds listed in
    /// SCENES.md ("Controllers").
    #[serde(default, rename = "controller")]
    pub controllers: Vec<ControllerSpec>,
}

fn default_dt() -> f64 {
    1.0 / 60.0
}
fn default_gravity() -> [f64; 3] {
    [0.0, -9.81, 0.0]
}
fn default_max_steps() -> u64 {
    crate::limits::DEFAULT_MAX_STEPS
}
fn default_accuracy() -> f64 {
    0.05
}
fn yes() -> bool {
    true
}

/// What the recording and publishing sinks receive each step.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordSpec {
    /// Body poses by name (default true).
    #[serde(default = "yes")]
    pub poses: bool,
    /// Per-fingertip wrenches (default true).
    #[serde(default = "yes")]
    pub wrenches: bool,
    /// Every soft contact (default true).
    #[serde(default = "yes")]
    pub contacts: bool,
    /// Contact radius and pressure of every contact (default false: not computed at all).
    #[serde(default)]
    pub pressure: bool,
    /// Every robot joint's state and its targets (`/joint_states`, `/joint_commands`; default
    /// true; nothing without robots).
    #[serde(default = "yes")]
    pub joints: bool,
    /// The MCAP recorder writes every n-th step (steps n, 2n, ...), >= 1 (default
    /// [`DEFAULT_EVERY_N_STEPS`]). Publishers still receive every step.
    #[serde(default = "default_every_n_steps")]
    pub every_n_steps: u64,
}

/// Default of `record.every_n_steps` (15 Hz for the default scene's 60 Hz steps). Measured
/// (release, 2 shared cores under load, default scene with a 100 s hold, best of 11): a step
/// costs ~13 µs; recording every 4th step adds ~10 % (the frame is assembled only on recorded
/// steps, the MCAP writer runs on its own thread; see crates/softgrip-cli/README.md).
pub const DEFAULT_EVERY_N_STEPS: u64 = 4;

fn default_every_n_steps() -> u64 {
    DEFAULT_EVERY_N_STEPS
}

impl Default for RecordSpec {
    fn default() -> Self {
        Self {
            poses: true,
            wrenches: true,
            contacts: true,
            pressure: false,
            joints: true,
            every_n_steps: DEFAULT_EVERY_N_STEPS,
        }
    }
}

/// How a body moves (the scene file's `kind`; the ECS's `RigidBody` component uses it too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyKind {
    /// Never moves.
    Fixed,
    /// Moved by forces.
    Dynamic,
    /// Position-based kinematic: moved along a scripted trajectory, by a gripper controller
    /// or by your own controller.
    Kinematic,
}

/// One rigid body.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Unique name (used by fingertips, the gripper and the recording).
    pub name: String,
    /// `fixed`, `dynamic` or `kinematic`.
    pub kind: BodyKind,
    /// Initial position \[m\] (default origin).
    #[serde(default, deserialize_with = "exact")]
    pub position: [f64; 3],
    /// Initial orientation as a rotation vector (axis * angle) \[rad\] (default none).
    #[serde(default, deserialize_with = "exact")]
    pub rotation: [f64; 3],
    /// Scripted path of a kinematic body: waypoints with increasing `t`, linear in between;
    /// the body holds the first position before and the last after.
    #[serde(default)]
    pub trajectory: Vec<WaypointSpec>,
    /// Collision shapes.
    #[serde(default, rename = "shape")]
    pub shapes: Vec<ShapeSpec>,
}

/// A point of a kinematic trajectory.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WaypointSpec {
    /// Time \[s\], >= 0, strictly increasing along the trajectory.
    pub t: f64,
    /// Body position at `t` \[m\].
    #[serde(deserialize_with = "exact")]
    pub position: [f64; 3],
}

/// A collision shape of a body: its `type`, the fields that type takes, placement, material.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShapeSpec {
    /// `plane`, `cuboid`, `ball`, `cylinder`, `convex_mesh` or `triangle_mesh`.
    #[serde(rename = "type")]
    pub kind: ShapeKind,
    /// `plane`: outward normal (normalised on load), non-zero.
    #[serde(default, deserialize_with = "exact_opt")]
    pub normal: Option<[f64; 3]>,
    /// `cuboid`: half extents \[m\], each finite and > 0.
    #[serde(default, deserialize_with = "exact_opt")]
    pub half_extents: Option<[f64; 3]>,
    /// `ball`, `cylinder`: radius \[m\], finite and > 0.
    #[serde(default)]
    pub radius: Option<f64>,
    /// `cylinder` (along the body's y axis): half height \[m\], finite and > 0.
    #[serde(default)]
    pub half_height: Option<f64>,
    /// `convex_mesh`, `triangle_mesh`: OBJ or STL file, relative to the scene file.
    #[serde(default)]
    pub file: Option<String>,
    /// `convex_mesh`, `triangle_mesh`: scale of the vertices, finite and > 0 (default 1).
    #[serde(default)]
    pub scale: Option<f64>,
    /// Offset from the body origin \[m\] (default none).
    #[serde(default, deserialize_with = "exact")]
    pub offset: [f64; 3],
    /// Density [kg/m^3], finite and > 0 (default 1000).
    #[serde(default = "default_density")]
    pub density: f64,
    /// rapier's Coulomb friction for rigid contacts, >= 0 (default 0.5). Soft contacts use the
    /// fingertip's friction.
    #[serde(default = "default_friction")]
    pub friction: f64,
    /// rapier's restitution for rigid contacts, in [0, 1] (default 0).
    #[serde(default)]
    pub restitution: f64,
}

fn default_density() -> f64 {
    1000.0
}
fn default_friction() -> f64 {
    0.5
}

/// A shape's geometry type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShapeKind {
    /// An infinite plane through the offset point, solid below its normal (fixed bodies only).
    Plane,
    /// A box.
    Cuboid,
    /// A sphere.
    Ball,
    /// A cylinder along the body's y axis.
    Cylinder,
    /// The convex hull of a mesh file's vertices.
    ConvexMesh,
    /// A triangle mesh from a file.
    TriangleMesh,
}

/// A material given by its constants.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus E \[Pa\], finite and > 0.
    pub youngs_modulus: f64,
    /// Poisson's ratio nu [-], in (-1, 0.5].
    pub poisson_ratio: f64,
}

/// A soft spherical fingertip on a body.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FingertipSpec {
    /// Unique name (readouts, summary, recording).
    pub name: String,
    /// Name of the body that carries it; exclusive with `link`.
    #[serde(default)]
    pub body: Option<String>,
    /// The robot link that carries it, `<robot>/<link>`; exclusive with `body`. `offset` and
    /// `facing` are then in the link's frame.
    #[serde(default)]
    pub link: Option<String>,
    /// Centre of the sphere relative to the body (or link) origin \[m\] (default none).
    #[serde(default, deserialize_with = "exact")]
    pub offset: [f64; 3],
    /// Radius R \[m\], finite and > 0.
    pub radius: f64,
    /// A literature material by name (`ecoflex-00-30`, `dragon-skin-10`, `dragon-skin-20`,
    /// `dragon-skin-30`, `sylgard-184`, `live-cell`, `fixed-cell`); exclusive with `material`.
    #[serde(default)]
    pub preset: Option<String>,
    /// The material's constants; exclusive with `preset`.
    #[serde(default)]
    pub material: Option<MaterialSpec>,
    /// Level of the law: a built-in level by name (`linear`, `hertz`, `fit`,
    /// `incompressible`, `neo-hookean`, `neo-hookean-exact`, `tatara`, `calibrated`, `auto`;
    /// default `auto`), or `{ tabulated = "tip.csv" }`: a measured squeeze curve.
    #[serde(default)]
    pub level: LevelSpec,
    /// `tolerance` of `auto`: relative force tolerance against `calibrated`, in (0, 0.5]
    /// (default 0.01). Each level setting is a key of its own, valid only with the level whose
    /// row of `softgrip_law::LEVELS` has it ([`settings`](Self::settings)).
    #[serde(default)]
    pub tolerance: Option<f64>,
    /// `k` of `fit`: the slope of 1/chi = 1 - k x, in [0, 10] (default 10/9).
    #[serde(default)]
    pub k: Option<f64>,
    /// `match_x` of `linear`: the compression ratio where the spring's force equals Hertz's,
    /// in (0, 1] (default 0.05).
    #[serde(default)]
    pub match_x: Option<f64>,
    /// Coefficient of restitution e, in (0, 1] (default 0.5).
    #[serde(default = "default_tip_restitution")]
    pub restitution: f64,
    /// Coulomb friction coefficient, >= 0 (default 0.8).
    #[serde(default = "default_tip_friction")]
    pub friction: f64,
    /// Density of the fingertip's ball [kg/m^3], finite and > 0 (default 1070, silicone).
    #[serde(default = "default_tip_density")]
    pub density: f64,
    /// A tactile sensor pad (`[fingertip.tactile]`; default none: no image is computed).
    #[serde(default)]
    pub tactile: Option<TactileSpec>,
    /// How the fingertip is built: `free` (default: a whole soft sphere, the paper's case),
    /// `flat` (a soft hemisphere bonded at its flat face to the rigid finger) or `core` (a soft
    /// skin of thickness `core_thickness` over a rigid core). `flat` and `core` need `facing`.
    #[serde(default)]
    pub backing: Option<String>,
    /// Skin thickness t of a `core` fingertip \[m\], finite and in (0, radius); only with
    /// `backing = "core"`, and required there.
    #[serde(default)]
    pub core_thickness: Option<f64>,
    /// Direction the pad of a `flat` or `core` fingertip faces, from its flat face towards its
    /// pole, in its body's axes: finite and non-zero (normalised). Required for a backed
    /// fingertip; what touches it from the other side touches the rigid finger.
    #[serde(default, deserialize_with = "exact_opt")]
    pub facing: Option<[f64; 3]>,
}

impl FingertipSpec {
    /// The level settings as written, by their key in `softgrip_law::LEVELS` (`match_x`, `k`,
    /// `tolerance`; `None`: not given). A test checks that these are every key of the table.
    pub fn settings(&self) -> [(&'static str, Option<f64>); 3] {
        [
            ("match_x", self.match_x),
            ("k", self.k),
            ("tolerance", self.tolerance),
        ]
    }
}

/// `[fingertip.tactile]`: a pad of `rows` x `columns` taxels over a patch of the fingertip's
/// surface (the plugin's `softgrip_rapier::TactilePad`, which checks the ranges).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TactileSpec {
    /// Rows of taxels (the image's height), in 1..=1024.
    pub rows: u32,
    /// Columns of taxels (the image's width), in 1..=1024.
    pub columns: u32,
    /// Direction of the pad's centre in the fingertip's frame (its body's axes), non-zero;
    /// exactly three components (a fourth was silently dropped).
    #[serde(deserialize_with = "exact")]
    pub direction: [f64; 3],
    /// Direction of the image's top in the fingertip's frame, not parallel to `direction`
    /// (default `+z`, or `+x` when `direction` is within 25° of the z axis); exactly three
    /// components.
    #[serde(default, deserialize_with = "exact_opt")]
    pub up: Option<[f64; 3]>,
    /// Width covered by the columns, along the surface \[m\], > 0.
    pub width: f64,
    /// Height covered by the rows, along the surface \[m\], > 0;
    /// `sqrt(width² + height²) <= π radius`.
    pub height: f64,
}

impl TactileSpec {
    /// The plugin's pad.
    pub fn pad(&self) -> softgrip_rapier::TactilePad {
        let pad = softgrip_rapier::TactilePad::new(
            self.rows,
            self.columns,
            self.direction,
            self.width,
            self.height,
        );
        match self.up {
            Some(up) => pad.with_up(up),
            None => pad,
        }
    }
}

fn default_tip_restitution() -> f64 {
    softgrip_rapier::DEFAULT_RESTITUTION
}
fn default_tip_friction() -> f64 {
    softgrip_rapier::DEFAULT_FRICTION
}
fn default_tip_density() -> f64 {
    1070.0
}

/// A parallel-jaw gripper: kinematic jaws (any number) that approach, squeeze, lift, hold and
/// release.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GripperSpec {
    /// Name of the gripper (default `gripper`).
    #[serde(default = "default_gripper_name")]
    pub name: String,
    /// The jaw bodies (kinematic, each carrying at least one fingertip), at least one.
    pub jaws: Vec<String>,
    /// Closing direction of the first of two jaws (normalised; the second closes along its
    /// opposite). Exclusive with `axes`.
    #[serde(default, deserialize_with = "exact_opt")]
    pub axis: Option<[f64; 3]>,
    /// Closing direction of each jaw (normalised), one per jaw. Exclusive with `axis`.
    #[serde(default, deserialize_with = "exact_list_opt")]
    pub axes: Option<Vec<[f64; 3]>>,
    /// Lift direction (normalised; default opposite to gravity).
    #[serde(default, deserialize_with = "exact_opt")]
    pub up: Option<[f64; 3]>,
    /// Closing speed until the fingertips touch [m/s], finite and > 0.
    pub approach_speed: f64,
    /// The commanded grip.
    pub squeeze: SqueezeSpec,
    /// Lift after the grip is reached.
    pub lift: MoveSpec,
    /// Hold time at the top \[s\], finite and >= 0.
    pub hold: f64,
    /// Opening of each jaw after the hold.
    pub release: MoveSpec,
}

fn default_gripper_name() -> String {
    String::from("gripper")
}

/// The squeeze: position control to a compression depth, or force control to a grip force
/// through the law's inverse.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SqueezeSpec {
    /// Compression of each fingertip past first touch \[m\], finite and > 0; exclusive with
    /// `force`.
    #[serde(default)]
    pub depth: Option<f64>,
    /// Grip force per fingertip \[N\], finite and > 0; the depth is the law's
    /// `compression_for_force(force)`. Exclusive with `depth`.
    #[serde(default)]
    pub force: Option<f64>,
    /// Closing speed while squeezing [m/s], finite and > 0.
    pub speed: f64,
    /// Time to wait at the commanded depth before lifting \[s\], finite and >= 0 (default 0.2).
    #[serde(default = "default_settle")]
    pub settle: f64,
}

fn default_settle() -> f64 {
    0.2
}

/// A straight move of a given length at a given speed.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MoveSpec {
    /// Length of the move \[m\], finite and >= 0.
    pub distance: f64,
    /// Speed [m/s], finite and > 0.
    pub speed: f64,
}
