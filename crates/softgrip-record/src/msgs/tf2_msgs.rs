//! `tf2_msgs`: [`TFMessage`], the `/tf` topic's type.

use super::geometry_msgs::TransformStamped;
use crate::message::ros_message;

ros_message! {
    /// A batch of transforms (one per body and fingertip per step on `/tf`).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct TFMessage {
        name = "tf2_msgs/msg/TFMessage", file = "msg/tf2_msgs/TFMessage.msg", deps = [TransformStamped];
        /// The transforms.
        pub transforms: Vec<TransformStamped>,
    }
}
