//! CDR (XCDR1, little-endian), the wire format of ROS 2 messages: a writer, a reader and the
//! [`CdrField`] trait every field type implements.
//!
//! The rules, all that ROS 2's plain `.msg` types need:
//! - a 4-byte encapsulation header `00 01 00 00` (CDR, little-endian) starts the payload;
//! - a primitive of size `n` (1, 2, 4 or 8 bytes) is aligned to a multiple of `n` counted from
//!   the end of that header (the payload start), padding with zeros;
//! - a string is a `uint32` length that counts the terminating NUL, the UTF-8 bytes, then NUL;
//! - an unbounded sequence (`T[]`) is a `uint32` element count, then the elements;
//! - a nested message is its fields in order, with no alignment or length of its own.

mod field;
mod reader;
mod writer;

pub use field::CdrField;
pub use reader::{CdrError, CdrReader};
pub use writer::CdrWriter;

/// The encapsulation header this crate writes: CDR (XCDR1), little-endian, no options.
pub const ENCAPSULATION_CDR_LE: [u8; 4] = [0x00, 0x01, 0x00, 0x00];
