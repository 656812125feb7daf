//! What a scene may ask of the engine: rapier stores poses, shapes, masses and velocities in
//! `f32`, so every number that reaches it must be finite as `f32` and leave room for the
//! squares and cubes rapier forms of it (a mass is density times a length cubed, an inertia a
//! mass times a length squared). The checks in `validate.rs` use these limits; SCENES.md
//! lists them.

/// Largest |coordinate| of a position, offset, trajectory point or mesh vertex \[m\] (100 km:
/// rapier holds a coordinate c to ~6e-8 c, so 6 mm here).
pub const MAX_COORDINATE: f64 = 1.0e5;
/// Smallest size of a shape (half extent, radius, half height) \[m\] (0.1 µm).
pub const MIN_SIZE: f64 = 1.0e-7;
/// Largest size of a shape \[m\] (10 km).
pub const MAX_SIZE: f64 = 1.0e4;
/// Smallest density of a shape or fingertip [kg/m³].
pub const MIN_DENSITY: f64 = 1.0e-3;
/// Largest density of a shape or fingertip [kg/m³] (45x osmium).
pub const MAX_DENSITY: f64 = 1.0e6;
/// Largest magnitude of gravity [m/s²] (1000 g).
pub const MAX_GRAVITY: f64 = 1.0e4;
/// Largest rapier friction coefficient of a rigid shape [-].
pub const MAX_FRICTION: f64 = 1.0e3;
/// Largest angle of a body's rotation vector \[rad\]: rapier's `f32` rotation of a larger
/// angle loses its accuracy (`rotation = [1e20, 0, 0]` gave NaN poses).
pub const MAX_ROTATION_ANGLE: f64 = 100.0;
/// Smallest time step \[s\] (1 ns).
pub const MIN_DT: f64 = 1.0e-9;
/// Largest time step \[s\].
pub const MAX_DT: f64 = 1.0;
/// Largest time of a trajectory waypoint, settle or hold \[s\] (~32 years).
pub const MAX_TIME: f64 = 1.0e9;
/// Largest speed of the gripper's moves [m/s].
pub const MAX_SPEED: f64 = 1.0e4;
/// Largest acceleration of a grasp's lift \[m/s^2\].
pub const MAX_ACCELERATION: f64 = 1.0e6;
/// The default cap on a run's step count `duration / dt` (10 million steps: ~2 min of a warm
/// default scene in a release build). Raise it with the scene key `max_steps`.
pub const DEFAULT_MAX_STEPS: u64 = 10_000_000;
/// Largest scene file read \[bytes\] (16 MiB).
pub const MAX_SCENE_BYTES: u64 = 16 << 20;
/// Largest mesh file read \[bytes\] (256 MiB: a binary STL of 5 million triangles).
pub const MAX_MESH_BYTES: u64 = 256 << 20;
/// Largest curve (CSV) file read \[bytes\] (16 MiB).
pub const MAX_CURVE_BYTES: u64 = 16 << 20;
/// Body names a scene may not use: the tf frames a recording and the ROS 2 publisher put above
/// the bodies (`world`, `softgrip_record::WORLD_FRAME`): a body named `world` made the frame
/// `world -> world` on /tf, a cycle no tf reader accepts.
pub const RESERVED_FRAME_NAMES: [&str; 1] = ["world"];
