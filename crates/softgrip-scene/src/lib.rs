#![doc = include_str!("../README.md")]

mod build;
pub mod control;
mod curve;
mod digest;
mod error;
mod exact;
mod fingertips;
mod format;
mod level;
mod limits;
mod mesh;
mod names;
mod plain;
mod read;
pub mod robot;
mod robots;
mod scene;
mod shape;
mod start;
mod trajectory;
mod validate;
mod vector;

pub use build::{BuiltScene, SceneHandles, body_builder, collider_builder, fingertip_builder};
pub use control::{
    Carrier, ControlEvent, ControlSet, Controller, GripperEvent, GripperProgram, GripperState,
    JawState, Phase, Squeeze, jaw_compressions,
};
pub use curve::{CURVE_HEADER, MeasuredCurve, parse_curve, read_curve};
pub use digest::ContactDigest;
pub use error::SceneError;
pub use format::{
    BodyKind, BodySpec, DEFAULT_EVERY_N_STEPS, FingertipSpec, GripperSpec, MaterialSpec, MoveSpec,
    RecordSpec, SceneFile, ShapeKind, ShapeSpec, SqueezeSpec, TactileSpec, WaypointSpec,
};
pub use level::LevelSpec;
pub use limits::{
    DEFAULT_MAX_STEPS, MAX_COORDINATE, MAX_CURVE_BYTES, MAX_DENSITY, MAX_DT, MAX_FRICTION,
    MAX_GRAVITY, MAX_MESH_BYTES, MAX_ROTATION_ANGLE, MAX_SCENE_BYTES, MAX_SIZE, MAX_SPEED,
    MAX_TIME, MIN_DENSITY, MIN_DT, MIN_SIZE, RESERVED_FRAME_NAMES,
};
pub use mesh::{Mesh, load_mesh, parse_obj, parse_stl};
pub use names::SubjectNames;
pub use plain::PlainRun;
pub use read::{UTF8_BOM, same_file, strip_bom};
pub use robot::{JointState, Robot, RobotHandles, RobotSpec};
pub use scene::{DEFAULT_SCENE, Scene, read_text, read_text_from};
pub use trajectory::Trajectory;
pub use vector::vector;

/// Re-exports of the crates the API uses.
pub use rapier3d_urdf;
pub use softgrip_rapier;
