//! `sensor_msgs`: [`Image`] (the fingertips' tactile images), [`JointState`] (robots' joints:
//! `/joint_states` and the commands) and [`CompressedImage`] (only because
//! `visualization_msgs/Marker` embeds one).

use super::std_msgs::Header;
use crate::message::ros_message;

ros_message! {
    /// A compressed image (a marker's texture; softgrip leaves it empty).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct CompressedImage {
        name = "sensor_msgs/msg/CompressedImage", file = "msg/sensor_msgs/CompressedImage.msg", deps = [Header];
        /// Stamp and camera frame.
        pub header: Header,
        /// Image format, e.g. `png`.
        pub format: String,
        /// The compressed bytes.
        pub data: Vec<u8>,
    }
}

ros_message! {
    /// An uncompressed image: softgrip's tactile images (`/softgrip/<fingertip>/tactile`),
    /// encoding [`Image::TACTILE_ENCODING`], one little-endian `f32` pressure \[Pa\] per taxel,
    /// row-major from the pad's top-left taxel.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct Image {
        name = "sensor_msgs/msg/Image", file = "msg/sensor_msgs/Image.msg", deps = [Header];
        /// Stamp and frame (a tactile image: the fingertip's frame).
        pub header: Header,
        /// Rows (the image's height).
        pub height: u32,
        /// Columns (the image's width).
        pub width: u32,
        /// Pixel encoding, e.g. `32FC1`.
        pub encoding: String,
        /// 1 if the pixels are big-endian (softgrip writes 0).
        pub is_bigendian: u8,
        /// Bytes per row.
        pub step: u32,
        /// The pixels, `step * height` bytes.
        pub data: Vec<u8>,
    }
}

ros_message! {
    /// The state of a set of joints (`/joint_states`), or commands to them (the
    /// topic_based_ros2_control convention: a position and/or velocity target per named joint).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct JointState {
        name = "sensor_msgs/msg/JointState", file = "msg/sensor_msgs/JointState.msg", deps = [Header];
        /// Stamp (the step's time) and frame (empty).
        pub header: Header,
        /// The joints' names.
        pub name: Vec<String>,
        /// Positions \[m or rad\] (empty: none given).
        pub position: Vec<f64>,
        /// Velocities \[m/s or rad/s\] (empty: none given).
        pub velocity: Vec<f64>,
        /// Efforts \[N or N m\] (empty: none given).
        pub effort: Vec<f64>,
    }
}

impl Image {
    /// Encoding of a tactile image: one 32-bit float channel (pressure \[Pa\]).
    pub const TACTILE_ENCODING: &'static str = "32FC1";

    /// A `32FC1` image of `rows` x `columns` pressures \[Pa\] (row-major, little-endian,
    /// `step = 4 columns`); `pressure` has `rows * columns` values (missing ones read 0,
    /// extra ones are dropped).
    ///
    /// ```
    /// use softgrip_record::msgs::sensor_msgs::Image;
    /// let img = Image::tactile(Default::default(), 1, 2, &[1.5, -2.0]);
    /// assert_eq!((img.step, img.data.len()), (8, 8));
    /// assert_eq!(img.pixels_f32(), vec![1.5, -2.0]);
    /// ```
    pub fn tactile(header: Header, rows: u32, columns: u32, pressure: &[f32]) -> Self {
        let n = rows as usize * columns as usize;
        let mut data = Vec::with_capacity(4 * n);
        for i in 0..n {
            data.extend_from_slice(&pressure.get(i).copied().unwrap_or(0.0).to_le_bytes());
        }
        Self {
            header,
            height: rows,
            width: columns,
            encoding: Self::TACTILE_ENCODING.to_owned(),
            is_bigendian: 0,
            step: 4 * columns,
            data,
        }
    }

    /// The pixels of a little-endian `32FC1` image, row-major (empty for another encoding).
    pub fn pixels_f32(&self) -> Vec<f32> {
        if self.encoding != Self::TACTILE_ENCODING || self.is_bigendian != 0 {
            return Vec::new();
        }
        self.data
            .chunks_exact(4)
            .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .collect()
    }
}
