//! CDR (XCDR1, little-endian), the wire format of ROS 2 messages, through the `cdr-encoding`
//! crate (the serialiser RustDDS, and so ros2-client, publishes with): every message type
//! derives serde, in `.msg` field order.
//!
//! A payload is a 4-byte encapsulation header `00 01 00 00` (CDR, little-endian), then the
//! fields: a primitive of size n aligned to n from the end of the header, a string as a
//! `uint32` length counting its NUL, the bytes and the NUL, a sequence as a `uint32` count and
//! the elements.
//!
//! Speed: not re-measured when the hand-written writer was replaced (the shared 2-core machine
//! had no time for a release build of the bench); `cargo bench -p softgrip-record --bench
//! record` ("encode SoftContactArrayMsg", "write_step") gives the before/after figure. The
//! README's earlier figure was 0.26 µs to encode two contacts out of ~10 µs per recorded step.

use byteorder::LittleEndian;
use serde::Serialize;
use serde::de::DeserializeOwned;

/// The encapsulation header this crate writes: CDR (XCDR1), little-endian, no options.
pub const ENCAPSULATION_CDR_LE: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

/// Why a CDR buffer could not be decoded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CdrError {
    /// The buffer is shorter than the 4-byte encapsulation header.
    #[error("CDR buffer of {len} bytes is shorter than the 4-byte encapsulation header")]
    MissingHeader {
        /// Length of the buffer \[bytes\].
        len: usize,
    },
    /// The encapsulation is not CDR little-endian (`00 01`).
    #[error("unsupported CDR encapsulation {kind:#06x}: only CDR little-endian (0x0001) is read")]
    UnsupportedEncapsulation {
        /// The first two header bytes, big-endian.
        kind: u16,
    },
    /// The buffer ends inside a value (or a string or sequence claims more than is left).
    #[error("the CDR buffer ends inside a value")]
    UnexpectedEnd,
    /// A `bool` byte other than 0 or 1.
    #[error("invalid bool byte {value}")]
    InvalidBool {
        /// The byte.
        value: u8,
    },
    /// A string that is not UTF-8.
    #[error("a string is not valid UTF-8")]
    InvalidUtf8,
    /// Bytes left after the message.
    #[error("{extra} bytes left after the message")]
    TrailingBytes {
        /// Bytes left \[bytes\].
        extra: usize,
    },
    /// Anything else `cdr-encoding` refused.
    #[error("invalid CDR: {reason}")]
    Invalid {
        /// `cdr-encoding`'s message.
        reason: String,
    },
}

impl From<cdr_encoding::Error> for CdrError {
    fn from(e: cdr_encoding::Error) -> Self {
        match e {
            cdr_encoding::Error::Eof => CdrError::UnexpectedEnd,
            cdr_encoding::Error::BadBoolean(value) => CdrError::InvalidBool { value },
            cdr_encoding::Error::BadUTF8(_) | cdr_encoding::Error::BadChar(_) => {
                CdrError::InvalidUtf8
            }
            other => CdrError::Invalid {
                reason: other.to_string(),
            },
        }
    }
}

/// A reusable buffer that holds one encoded message, encapsulation header included.
///
/// ```
/// use softgrip_record::cdr::CdrWriter;
/// let mut w = CdrWriter::new();
/// w.encode(&(7u8, 1.0f64)); // the f64 is aligned to 8 from the payload start: 7 bytes of padding
/// assert_eq!(w.as_bytes().len(), 4 + 1 + 7 + 8);
/// ```
#[derive(Debug, Clone, Default)]
pub struct CdrWriter {
    buf: Vec<u8>,
}

impl CdrWriter {
    /// An empty buffer.
    pub fn new() -> Self {
        Self::with_capacity(256)
    }

    /// An empty buffer with room for `capacity` bytes.
    pub fn with_capacity(capacity: usize) -> Self {
        Self {
            buf: Vec::with_capacity(capacity),
        }
    }

    /// Replaces the buffer's content with `value`, encoded (keeping the allocation).
    pub fn encode<T: Serialize>(&mut self, value: &T) {
        self.buf.clear();
        self.buf.extend_from_slice(&ENCAPSULATION_CDR_LE);
        // Writing into a Vec cannot fail, and every type softgrip encodes has a known length
        // (CDR's only other serialisation error).
        cdr_encoding::to_writer::<T, LittleEndian, _>(&mut self.buf, value)
            .expect("invariant: CDR into a Vec of a type with known sequence lengths");
    }

    /// The encoded message, header included.
    pub fn as_bytes(&self) -> &[u8] {
        &self.buf
    }

    /// The encoded message, header included.
    pub fn into_bytes(self) -> Vec<u8> {
        self.buf
    }
}

/// Decodes a whole message (header included); fails on a malformed value or left-over bytes,
/// never panics.
///
/// `cdr-encoding`, like RustDDS, reads a string whose last byte is not the NUL terminator by
/// dropping that byte (it logs a warning).
pub fn decode<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, CdrError> {
    let (header, payload) = bytes
        .split_first_chunk::<4>()
        .ok_or(CdrError::MissingHeader { len: bytes.len() })?;
    if header[..2] != ENCAPSULATION_CDR_LE[..2] {
        return Err(CdrError::UnsupportedEncapsulation {
            kind: u16::from_be_bytes([header[0], header[1]]),
        });
    }
    let (value, used) = cdr_encoding::from_bytes::<T, LittleEndian>(payload)?;
    match payload.len() - used {
        0 => Ok(value),
        extra => Err(CdrError::TrailingBytes { extra }),
    }
}
