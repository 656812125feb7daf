//! `sensor_msgs`: [`CompressedImage`] (only because `visualization_msgs/Marker` embeds one).

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
