//! [`Message`]: a recorded message decoded to its Rust type, chosen by its schema name.

use crate::cdr::CdrError;
use crate::message::RosMessage;
use crate::msgs::geometry_msgs::WrenchStamped;
use crate::msgs::rosgraph_msgs::Clock;
use crate::msgs::sensor_msgs::{Image, JointState};
use crate::msgs::softgrip_msgs::SoftContactArrayMsg;
use crate::msgs::std_msgs::StringMsg;
use crate::msgs::tf2_msgs::TFMessage;
use crate::msgs::visualization_msgs::MarkerArray;

/// A decoded message of one of the types softgrip records.
#[derive(Debug, Clone, PartialEq)]
pub enum Message {
    /// `softgrip_msgs/msg/SoftContactArray`.
    Contacts(SoftContactArrayMsg),
    /// `geometry_msgs/msg/WrenchStamped`.
    Wrench(WrenchStamped),
    /// `tf2_msgs/msg/TFMessage`.
    Tf(TFMessage),
    /// `visualization_msgs/msg/MarkerArray`.
    Markers(MarkerArray),
    /// `rosgraph_msgs/msg/Clock`.
    Clock(Clock),
    /// `sensor_msgs/msg/Image` (a fingertip's tactile image).
    Image(Image),
    /// `sensor_msgs/msg/JointState` (`/joint_states`, `/joint_commands`).
    JointState(JointState),
    /// `std_msgs/msg/String` (`/robot_description`).
    String(StringMsg),
    /// Any other schema or encoding: kept as bytes.
    Other {
        /// Schema name (empty without a schema).
        schema_name: String,
        /// The message bytes.
        data: Vec<u8>,
    },
}

impl Message {
    /// Decodes `data` by its schema name when the encoding is `cdr`.
    pub fn decode(
        schema_name: &str,
        message_encoding: &str,
        data: &[u8],
    ) -> Result<Self, CdrError> {
        if message_encoding != "cdr" {
            return Ok(Self::other(schema_name, data));
        }
        Ok(match schema_name {
            SoftContactArrayMsg::TYPE_NAME => Self::Contacts(SoftContactArrayMsg::from_cdr(data)?),
            WrenchStamped::TYPE_NAME => Self::Wrench(WrenchStamped::from_cdr(data)?),
            TFMessage::TYPE_NAME => Self::Tf(TFMessage::from_cdr(data)?),
            MarkerArray::TYPE_NAME => Self::Markers(MarkerArray::from_cdr(data)?),
            Clock::TYPE_NAME => Self::Clock(Clock::from_cdr(data)?),
            Image::TYPE_NAME => Self::Image(Image::from_cdr(data)?),
            JointState::TYPE_NAME => Self::JointState(JointState::from_cdr(data)?),
            StringMsg::TYPE_NAME => Self::String(StringMsg::from_cdr(data)?),
            _ => Self::other(schema_name, data),
        })
    }

    /// Like [`decode`](Self::decode), with the schema text the recording embeds: a message in
    /// a layout of an earlier softgrip version (told by its schema) is decoded into today's
    /// type. A `SoftContactArray` recorded before fingertips had a construction (no `backing`
    /// field in its schema) reads as free fingertips (`backing = 0`, `core_thickness = 0`); one
    /// recorded before the counterpart (no `counterpart` field) as discs on a plane
    /// (`contact_radius2 = contact_radius`, `counterpart = 0`).
    pub fn decode_with_schema(
        schema_name: &str,
        schema_text: &[u8],
        message_encoding: &str,
        data: &[u8],
    ) -> Result<Self, CdrError> {
        if message_encoding == "cdr"
            && schema_name == SoftContactArrayMsg::TYPE_NAME
            && !schema_text.is_empty()
        {
            let text = String::from_utf8_lossy(schema_text);
            if !text.contains(crate::msgs::legacy::BACKING_FIELD) {
                return Ok(Self::Contacts(
                    crate::msgs::legacy::contacts_before_backing(data)?,
                ));
            }
            if !text.contains(crate::msgs::legacy::COUNTERPART_FIELD) {
                return Ok(Self::Contacts(
                    crate::msgs::legacy::contacts_before_counterpart(data)?,
                ));
            }
        }
        Self::decode(schema_name, message_encoding, data)
    }

    fn other(schema_name: &str, data: &[u8]) -> Self {
        Self::Other {
            schema_name: schema_name.to_owned(),
            data: data.to_vec(),
        }
    }
}
