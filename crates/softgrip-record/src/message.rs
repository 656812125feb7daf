//! [`RosMessage`]: a ROS 2 message type with its name, schema and CDR encoding, and the
//! `ros_message!` macro that declares one field by field.

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::cdr::{self, CdrError, CdrWriter};
use crate::schema::MsgDef;

/// A ROS 2 message type: serde in `.msg` field order, which is its CDR encoding.
pub trait RosMessage: Serialize + DeserializeOwned + Clone + Send + Sync + 'static {
    /// Full ROS 2 name, `pkg/msg/Type` (the MCAP schema name).
    const TYPE_NAME: &'static str;
    /// The `.msg` definition and its dependencies.
    const DEFINITION: &'static MsgDef;
    /// The fields in wire order: `(name, Rust type)` (checked against the `.msg` text in tests).
    const FIELDS: &'static [(&'static str, &'static str)];

    /// The full `ros2msg` schema text (definition and every dependency).
    fn schema_text() -> String {
        Self::DEFINITION.schema_text()
    }

    /// Serialises the message, encapsulation header included, into `w` (replacing its content).
    fn encode_into(&self, w: &mut CdrWriter) {
        w.encode(self);
    }

    /// Serialises the message, encapsulation header included.
    fn to_cdr(&self) -> Vec<u8> {
        let mut w = CdrWriter::new();
        w.encode(self);
        w.into_bytes()
    }

    /// Decodes a whole serialised message (header included); fails on any malformed value or
    /// left-over data.
    fn from_cdr(bytes: &[u8]) -> Result<Self, CdrError> {
        cdr::decode(bytes)
    }
}

/// Declares a ROS 2 message struct whose fields mirror its `.msg` file, with serde
/// `Serialize`/`Deserialize` (fields in the same order: that is its CDR encoding) and its
/// [`RosMessage`] impl.
///
/// `name = "pkg/msg/Type", file = "path from the crate root", deps = [Types...]`.
macro_rules! ros_message {
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            name = $ros2:literal, file = $file:literal, deps = [$($dep:ty),* $(,)?];
            $( $(#[$fmeta:meta])* pub $field:ident : $ty:ty, )*
        }
    ) => {
        $(#[$meta])*
        // serde's data model sees the fields in `.msg` order, so serde CDR (cdr-encoding,
        // RustDDS) writes them in wire order (tested byte for byte in softgrip-ros2).
        #[derive(::serde::Serialize, ::serde::Deserialize)]
        pub struct $name {
            $( $(#[$fmeta])* pub $field: $ty, )*
        }

        impl $crate::RosMessage for $name {
            const TYPE_NAME: &'static str = $ros2;
            const DEFINITION: &'static $crate::schema::MsgDef = &$crate::schema::MsgDef {
                ros2_name: $ros2,
                text: include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/", $file)),
                dependencies: &[$( <$dep as $crate::RosMessage>::DEFINITION ),*],
            };
            const FIELDS: &'static [(&'static str, &'static str)] =
                &[$( (stringify!($field), stringify!($ty)) ),*];
        }
    };
}

pub(crate) use ros_message;
