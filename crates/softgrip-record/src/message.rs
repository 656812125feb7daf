//! [`RosMessage`]: a ROS 2 message type with its name, schema and CDR encoding, and the
//! `ros_message!` macro that declares one field by field.

use crate::cdr::{CdrError, CdrField, CdrReader, CdrWriter};
use crate::schema::MsgDef;

/// A ROS 2 message type.
pub trait RosMessage: CdrField {
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

    /// Serialises the message, encapsulation header included, into `w` (after resetting it).
    fn encode_into(&self, w: &mut CdrWriter) {
        w.reset();
        self.write_cdr(w);
    }

    /// Serialises the message, encapsulation header included.
    fn to_cdr(&self) -> Vec<u8> {
        let mut w = CdrWriter::new();
        self.write_cdr(&mut w);
        w.into_bytes()
    }

    /// Decodes a whole serialised message (header included); fails on any malformed byte or
    /// left-over data.
    fn from_cdr(bytes: &[u8]) -> Result<Self, CdrError> {
        let mut r = CdrReader::new(bytes)?;
        let msg = Self::read_cdr(&mut r)?;
        r.finish()?;
        Ok(msg)
    }
}

/// Declares a ROS 2 message struct whose fields mirror its `.msg` file, with its CDR encoding
/// (the fields in order), its [`RosMessage`] impl and serde `Serialize`/`Deserialize` (fields
/// in the same order, for serde-based CDR such as ros2-client's).
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
        // serde's data model sees the fields in `.msg` order, so serde CDR (ros2-client,
        // RustDDS) writes the same bytes as `CdrField` (tested in softgrip-ros2).
        #[derive(::serde::Serialize, ::serde::Deserialize)]
        pub struct $name {
            $( $(#[$fmeta])* pub $field: $ty, )*
        }

        impl $crate::cdr::CdrField for $name {
            fn write_cdr(&self, w: &mut $crate::cdr::CdrWriter) {
                $( $crate::cdr::CdrField::write_cdr(&self.$field, w); )*
            }

            fn read_cdr(
                r: &mut $crate::cdr::CdrReader<'_>,
            ) -> ::core::result::Result<Self, $crate::cdr::CdrError> {
                Ok(Self {
                    $( $field: <$ty as $crate::cdr::CdrField>::read_cdr(r)?, )*
                })
            }
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
