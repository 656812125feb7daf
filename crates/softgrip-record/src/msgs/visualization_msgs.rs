//! `visualization_msgs`: [`Marker`] and [`MarkerArray`] (ROS 2 Jazzy definition; the field list
//! is the same as Humble's), with [`UVCoordinate`] and [`MeshFile`] that a marker embeds.

use super::builtin_interfaces::Duration;
use super::geometry_msgs::{Point, Pose, Vector3};
use super::sensor_msgs::CompressedImage;
use super::std_msgs::{ColorRGBA, Header};
use crate::message::ros_message;

ros_message! {
    /// A texture coordinate.
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct UVCoordinate {
        name = "visualization_msgs/msg/UVCoordinate", file = "msg/visualization_msgs/UVCoordinate.msg", deps = [];
        /// u, as a ratio of the texture's width [-].
        pub u: f32,
        /// v, as a ratio of the texture's height [-].
        pub v: f32,
    }
}

ros_message! {
    /// A mesh file sent inside a marker.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct MeshFile {
        name = "visualization_msgs/msg/MeshFile", file = "msg/visualization_msgs/MeshFile.msg", deps = [];
        /// File name (gives the parser its extension).
        pub filename: String,
        /// The file's bytes.
        pub data: Vec<u8>,
    }
}

ros_message! {
    /// A shape for RViz and Foxglove's 3D panel.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct Marker {
        name = "visualization_msgs/msg/Marker", file = "msg/visualization_msgs/Marker.msg",
        deps = [Header, Pose, Vector3, ColorRGBA, Duration, Point, CompressedImage, UVCoordinate, MeshFile];
        /// Stamp and the frame `pose` is in.
        pub header: Header,
        /// Namespace; (`ns`, `id`) names the marker.
        pub ns: String,
        /// Id within the namespace.
        pub id: i32,
        /// Shape: one of the `Marker::` shape constants.
        pub r#type: i32,
        /// [`Marker::ADD`], [`Marker::DELETE`] or [`Marker::DELETEALL`].
        pub action: i32,
        /// Pose of the shape in `header.frame_id` \[m\].
        pub pose: Pose,
        /// Size along the shape's axes \[m\] (for a sphere or cylinder: diameters and height).
        pub scale: Vector3,
        /// Colour.
        pub color: ColorRGBA,
        /// Time before it disappears; zero: forever.
        pub lifetime: Duration,
        /// Re-transform into its frame every frame.
        pub frame_locked: bool,
        /// Points of a point, line or list shape \[m\].
        pub points: Vec<Point>,
        /// Per-point colours (empty or as many as `points`).
        pub colors: Vec<ColorRGBA>,
        /// Texture URI.
        pub texture_resource: String,
        /// Embedded texture.
        pub texture: CompressedImage,
        /// Texture coordinates per vertex.
        pub uv_coordinates: Vec<UVCoordinate>,
        /// Text of a text marker.
        pub text: String,
        /// Mesh URI.
        pub mesh_resource: String,
        /// Embedded mesh.
        pub mesh_file: MeshFile,
        /// Use the mesh's own materials.
        pub mesh_use_embedded_materials: bool,
    }
}

ros_message! {
    /// A batch of markers (softgrip's `/softgrip/markers`).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct MarkerArray {
        name = "visualization_msgs/msg/MarkerArray", file = "msg/visualization_msgs/MarkerArray.msg", deps = [Marker];
        /// The markers, applied in order.
        pub markers: Vec<Marker>,
    }
}

impl Marker {
    /// Arrow shape.
    pub const ARROW: i32 = 0;
    /// Box shape.
    pub const CUBE: i32 = 1;
    /// Sphere (scale: diameters).
    pub const SPHERE: i32 = 2;
    /// Cylinder along its z axis (scale: diameters, height).
    pub const CYLINDER: i32 = 3;
    /// Line strip through `points`.
    pub const LINE_STRIP: i32 = 4;
    /// Line segments between pairs of `points`.
    pub const LINE_LIST: i32 = 5;
    /// A cube at each point.
    pub const CUBE_LIST: i32 = 6;
    /// A sphere at each point.
    pub const SPHERE_LIST: i32 = 7;
    /// Points.
    pub const POINTS: i32 = 8;
    /// Text facing the viewer.
    pub const TEXT_VIEW_FACING: i32 = 9;
    /// Mesh from `mesh_resource`.
    pub const MESH_RESOURCE: i32 = 10;
    /// Triangles from `points`.
    pub const TRIANGLE_LIST: i32 = 11;
    /// Add or replace the marker.
    pub const ADD: i32 = 0;
    /// Delete the marker (`ns`, `id`).
    pub const DELETE: i32 = 2;
    /// Delete every marker (of `ns` if not empty).
    pub const DELETEALL: i32 = 3;
}
