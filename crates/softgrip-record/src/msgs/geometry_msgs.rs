//! `geometry_msgs`: points, vectors, poses, transforms and wrenches.

use super::std_msgs::Header;
use crate::message::ros_message;

ros_message! {
    /// A position \[m\].
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct Point {
        name = "geometry_msgs/msg/Point", file = "msg/geometry_msgs/Point.msg", deps = [];
        /// x \[m\].
        pub x: f64,
        /// y \[m\].
        pub y: f64,
        /// z \[m\].
        pub z: f64,
    }
}

ros_message! {
    /// A free vector (its unit is the field's: m, N, N m, ...).
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct Vector3 {
        name = "geometry_msgs/msg/Vector3", file = "msg/geometry_msgs/Vector3.msg", deps = [];
        /// x component.
        pub x: f64,
        /// y component.
        pub y: f64,
        /// z component.
        pub z: f64,
    }
}

ros_message! {
    /// An orientation as a unit quaternion (the default is the identity, as in the `.msg`).
    #[derive(Debug, Clone, Copy, PartialEq)]
    pub struct Quaternion {
        name = "geometry_msgs/msg/Quaternion", file = "msg/geometry_msgs/Quaternion.msg", deps = [];
        /// x (vector part) [-].
        pub x: f64,
        /// y (vector part) [-].
        pub y: f64,
        /// z (vector part) [-].
        pub z: f64,
        /// w (scalar part) [-].
        pub w: f64,
    }
}

ros_message! {
    /// A position and orientation.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct Pose {
        name = "geometry_msgs/msg/Pose", file = "msg/geometry_msgs/Pose.msg", deps = [Point, Quaternion];
        /// Position \[m\].
        pub position: Point,
        /// Orientation.
        pub orientation: Quaternion,
    }
}

ros_message! {
    /// A rigid transform (child frame expressed in the parent frame).
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct Transform {
        name = "geometry_msgs/msg/Transform", file = "msg/geometry_msgs/Transform.msg", deps = [Vector3, Quaternion];
        /// Translation \[m\].
        pub translation: Vector3,
        /// Rotation.
        pub rotation: Quaternion,
    }
}

ros_message! {
    /// A transform from `header.frame_id` to `child_frame_id` at `header.stamp`.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct TransformStamped {
        name = "geometry_msgs/msg/TransformStamped", file = "msg/geometry_msgs/TransformStamped.msg", deps = [Header, Transform];
        /// Stamp and parent frame.
        pub header: Header,
        /// The child frame.
        pub child_frame_id: String,
        /// Pose of the child frame in the parent frame.
        pub transform: Transform,
    }
}

ros_message! {
    /// A force \[N\] and a torque [N m].
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct Wrench {
        name = "geometry_msgs/msg/Wrench", file = "msg/geometry_msgs/Wrench.msg", deps = [Vector3];
        /// Force \[N\].
        pub force: Vector3,
        /// Torque [N m].
        pub torque: Vector3,
    }
}

ros_message! {
    /// A wrench with its stamp and frame.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct WrenchStamped {
        name = "geometry_msgs/msg/WrenchStamped", file = "msg/geometry_msgs/WrenchStamped.msg", deps = [Header, Wrench];
        /// Stamp and frame of the wrench's axes.
        pub header: Header,
        /// The wrench.
        pub wrench: Wrench,
    }
}

impl Default for Quaternion {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl Quaternion {
    /// No rotation.
    pub const IDENTITY: Self = Self {
        x: 0.0,
        y: 0.0,
        z: 0.0,
        w: 1.0,
    };

    /// From `[x, y, z, w]`.
    pub const fn from_xyzw([x, y, z, w]: [f64; 4]) -> Self {
        Self { x, y, z, w }
    }

    /// The shortest rotation taking +z to the direction `n` (need not be unit; +z rotates to
    /// itself for a zero or non-finite `n`).
    ///
    /// ```
    /// use softgrip_record::msgs::geometry_msgs::Quaternion;
    /// let q = Quaternion::z_to([1.0, 0.0, 0.0]); // 90 degrees about +y
    /// assert!((q.y - 0.5f64.sqrt()).abs() < 1e-15 && (q.w - 0.5f64.sqrt()).abs() < 1e-15);
    /// ```
    pub fn z_to(n: [f64; 3]) -> Self {
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        if !(len > 0.0 && len.is_finite()) {
            return Self::IDENTITY;
        }
        let [nx, ny, nz] = n.map(|c| c / len);
        // q = (z x n, 1 + z.n) normalised; z x n = (-ny, nx, 0).
        let w = 1.0 + nz;
        if w < 1e-12 {
            // n = -z: half a turn about x.
            return Self::from_xyzw([1.0, 0.0, 0.0, 0.0]);
        }
        let norm = (nx * nx + ny * ny + w * w).sqrt();
        Self::from_xyzw([-ny / norm, nx / norm, 0.0, w / norm])
    }
}

impl Point {
    /// From `[x, y, z]` \[m\].
    pub const fn from_array([x, y, z]: [f64; 3]) -> Self {
        Self { x, y, z }
    }

    /// As `[x, y, z]` \[m\].
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}

impl Vector3 {
    /// From `[x, y, z]`.
    pub const fn from_array([x, y, z]: [f64; 3]) -> Self {
        Self { x, y, z }
    }

    /// As `[x, y, z]`.
    pub const fn to_array(self) -> [f64; 3] {
        [self.x, self.y, self.z]
    }
}
