//! [`SceneInfo`]: what a sink learns once, before the first step.

use crate::frames::UpAxis;
use crate::metadata::{ControllerRecord, FingertipLaw};

/// A fingertip of the scene: where it is mounted and its law.
#[derive(Debug, Clone, PartialEq)]
pub struct FingertipInfo {
    /// Fingertip name (`/softgrip/<name>/wrench`; its tf frame is
    /// [`fingertip_frame`](crate::frames::fingertip_frame), the name unless a body has it).
    pub name: String,
    /// Name of the body that carries it (the parent of its tf frame).
    pub body: String,
    /// Centre of the fingertip sphere in its body's frame \[m\].
    pub offset: [f64; 3],
    /// Radius R \[m\], > 0.
    pub radius: f64,
    /// The law's parameters (written in the recording's metadata).
    pub law: FingertipLaw,
    /// A backed fingertip's facing: the unit direction from its flat face (through the
    /// sphere's centre) to its pole, in its body's axes. `None`: a free fingertip (drawn as a
    /// sphere; a backed one as a hemisphere).
    pub facing: Option<[f64; 3]>,
}

/// The geometry of a rigid body's shape, in the shape's own frame (its body's axes, at its
/// offset), as plain numbers \[m\].
#[derive(Debug, Clone, PartialEq)]
pub enum ShapeGeometry {
    /// An infinite plane through the shape's origin, solid below `normal` (unit).
    Plane {
        /// Outward unit normal, body axes.
        normal: [f64; 3],
    },
    /// A box of half extents \[m\], > 0, along the body's axes.
    Cuboid {
        /// Half extents \[m\].
        half_extents: [f64; 3],
    },
    /// A sphere.
    Ball {
        /// Radius \[m\], > 0.
        radius: f64,
    },
    /// A cylinder along the body's y axis.
    Cylinder {
        /// Half height \[m\], > 0.
        half_height: f64,
        /// Radius \[m\], > 0.
        radius: f64,
    },
    /// A triangle mesh (a triangle mesh shape, or a convex hull's faces).
    Mesh {
        /// Vertices \[m\].
        vertices: Vec<[f64; 3]>,
        /// Triangles: indices into `vertices`, counter-clockwise seen from outside.
        triangles: Vec<[u32; 3]>,
    },
}

/// A rigid body's shape (collider), to draw it.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeInfo {
    /// Name of the body it belongs to (the frame it is drawn in).
    pub body: String,
    /// Position of the shape's origin in its body's frame \[m\].
    pub offset: [f64; 3],
    /// Orientation of the shape's frame in its body's frame, unit quaternion `[x, y, z, w]`
    /// (a scene file's shapes have none: `[0, 0, 0, 1]`; a robot link's collision shapes
    /// have their URDF `<origin>`'s).
    pub rotation: [f64; 4],
    /// Its geometry.
    pub geometry: ShapeGeometry,
}

/// What a sink learns once, before the first step.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneInfo {
    /// Where the scene came from (a file path, or a description).
    pub origin: String,
    /// Time step \[s\], > 0 (0: unknown; stamps then come from the frame's `time`).
    pub dt: f64,
    /// Steps the run takes.
    pub steps: u64,
    /// Body names, in scene order.
    pub bodies: Vec<String>,
    /// Fingertips, in scene order.
    pub fingertips: Vec<FingertipInfo>,
    /// Every rigid body's shapes (not the fingertips), in scene order.
    pub shapes: Vec<ShapeInfo>,
    /// The scene's up axis: what the frames' numbers (poses, contacts, wrenches, gravity) are
    /// in. Recordings are z-up whatever it is ([`UpAxis`]).
    pub up: UpAxis,
    /// Gravity, scene axes \[m/s²\] (recorded in world axes in the `softgrip` metadata).
    pub gravity: [f64; 3],
    /// The robots: their URDFs (`/robot_description`).
    pub robots: Vec<RobotInfo>,
    /// The bodies that are not children of the world frame on tf: robot links under their
    /// parent links.
    pub frames: Vec<BodyFrame>,
    /// The controllers, in the order they run (the `softgrip` metadata's `controllers`).
    pub controllers: Vec<ControllerRecord>,
}

/// A robot of the scene.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RobotInfo {
    /// Its name (its links' frames are `<name>/<link>`).
    pub name: String,
    /// Its URDF, as read.
    pub urdf: String,
}

/// A body's place in the tf tree: a robot link under its parent link.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct BodyFrame {
    /// The body (its frame).
    pub body: String,
    /// Its parent body (frame).
    pub parent: String,
    /// Joined by a fixed joint: its pose in the parent is constant and goes on `/tf_static`
    /// (taken at the first step), not on `/tf`.
    pub fixed: bool,
}
