//! [`CdrReader`]: reads primitives back from a CDR buffer, with a typed error for every way the
//! bytes can be wrong.

use super::ENCAPSULATION_CDR_LE;

/// Why a CDR buffer could not be decoded.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum CdrError {
    /// The buffer is shorter than the 4-byte encapsulation header.
    #[error("CDR buffer of {len} bytes is shorter than the 4-byte encapsulation header")]
    MissingHeader {
        /// Length of the buffer [bytes].
        len: usize,
    },
    /// The encapsulation is not CDR little-endian (`00 01`).
    #[error("unsupported CDR encapsulation {kind:#06x}: only CDR little-endian (0x0001) is read")]
    UnsupportedEncapsulation {
        /// The first two header bytes, big-endian.
        kind: u16,
    },
    /// The buffer ends inside a value.
    #[error("CDR buffer ends at byte {len}, but {needed} more bytes are needed at offset {offset}")]
    UnexpectedEnd {
        /// Offset of the value [bytes from the buffer start].
        offset: usize,
        /// Bytes the value needs.
        needed: usize,
        /// Length of the buffer [bytes].
        len: usize,
    },
    /// A sequence or string claims more elements than the rest of the buffer can hold.
    #[error("length {count} at offset {offset} exceeds the {remaining} bytes left")]
    LengthTooLarge {
        /// Offset of the length field.
        offset: usize,
        /// The claimed count.
        count: u32,
        /// Bytes left after the length field.
        remaining: usize,
    },
    /// A `bool` byte other than 0 or 1.
    #[error("invalid bool byte {value} at offset {offset}")]
    InvalidBool {
        /// Offset of the byte.
        offset: usize,
        /// The byte.
        value: u8,
    },
    /// A string with length 0 (it must count its NUL) or without its terminating NUL.
    #[error("string at offset {offset} is not NUL-terminated")]
    UnterminatedString {
        /// Offset of the string's length field.
        offset: usize,
    },
    /// A string that is not UTF-8.
    #[error("string at offset {offset} is not valid UTF-8")]
    InvalidUtf8 {
        /// Offset of the string's length field.
        offset: usize,
    },
    /// Bytes left over after the message (more than CDR's trailing padding of up to 3 bytes).
    #[error("{extra} bytes left over after the message")]
    TrailingBytes {
        /// Number of bytes left over.
        extra: usize,
    },
}

/// Reads a CDR little-endian buffer (header included) from the front.
#[derive(Debug, Clone)]
pub struct CdrReader<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> CdrReader<'a> {
    /// Checks the encapsulation header and positions the reader at the payload start.
    pub fn new(data: &'a [u8]) -> Result<Self, CdrError> {
        let Some(header) = data.get(..ENCAPSULATION_CDR_LE.len()) else {
            return Err(CdrError::MissingHeader { len: data.len() });
        };
        if header[..2] != ENCAPSULATION_CDR_LE[..2] {
            return Err(CdrError::UnsupportedEncapsulation {
                kind: u16::from_be_bytes([header[0], header[1]]),
            });
        }
        Ok(Self {
            data,
            pos: ENCAPSULATION_CDR_LE.len(),
        })
    }

    /// Current offset from the buffer start (header included) [bytes].
    pub fn position(&self) -> usize {
        self.pos
    }

    /// Bytes not yet read.
    pub fn remaining(&self) -> usize {
        self.data.len() - self.pos
    }

    /// Succeeds if at most the 3 bytes of trailing padding a CDR writer may add are left.
    pub fn finish(&self) -> Result<(), CdrError> {
        match self.remaining() {
            0..=3 => Ok(()),
            extra => Err(CdrError::TrailingBytes { extra }),
        }
    }

    fn align(&mut self, size: usize) -> Result<(), CdrError> {
        let offset = self.pos - ENCAPSULATION_CDR_LE.len();
        let pad = (size - offset % size) % size;
        self.take(pad).map(|_| ())
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], CdrError> {
        let end = self.pos.checked_add(n).filter(|&e| e <= self.data.len());
        let Some(end) = end else {
            return Err(CdrError::UnexpectedEnd {
                offset: self.pos,
                needed: n,
                len: self.data.len(),
            });
        };
        let s = &self.data[self.pos..end];
        self.pos = end;
        Ok(s)
    }

    fn take_array<const N: usize>(&mut self) -> Result<[u8; N], CdrError> {
        self.align(N)?;
        let s = self.take(N)?;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }

    /// Reads a `bool` (a byte that must be 0 or 1).
    pub fn read_bool(&mut self) -> Result<bool, CdrError> {
        let offset = self.pos;
        match self.read_u8()? {
            0 => Ok(false),
            1 => Ok(true),
            value => Err(CdrError::InvalidBool { offset, value }),
        }
    }

    /// Reads a `uint8`.
    pub fn read_u8(&mut self) -> Result<u8, CdrError> {
        Ok(self.take(1)?[0])
    }

    /// Reads an `int32`.
    pub fn read_i32(&mut self) -> Result<i32, CdrError> {
        self.take_array().map(i32::from_le_bytes)
    }

    /// Reads a `uint32`.
    pub fn read_u32(&mut self) -> Result<u32, CdrError> {
        self.take_array().map(u32::from_le_bytes)
    }

    /// Reads an `int64`.
    pub fn read_i64(&mut self) -> Result<i64, CdrError> {
        self.take_array().map(i64::from_le_bytes)
    }

    /// Reads a `uint64`.
    pub fn read_u64(&mut self) -> Result<u64, CdrError> {
        self.take_array().map(u64::from_le_bytes)
    }

    /// Reads a `float32`.
    pub fn read_f32(&mut self) -> Result<f32, CdrError> {
        self.take_array().map(f32::from_le_bytes)
    }

    /// Reads a `float64`.
    pub fn read_f64(&mut self) -> Result<f64, CdrError> {
        self.take_array().map(f64::from_le_bytes)
    }

    /// Reads a sequence length and checks that `count` elements of at least `min_element_size`
    /// bytes each fit in the rest of the buffer (so a corrupt length cannot allocate gigabytes).
    pub fn read_len(&mut self, min_element_size: usize) -> Result<usize, CdrError> {
        self.align(4)?;
        let offset = self.pos;
        let count = self.read_u32()?;
        let remaining = self.remaining();
        let need = (count as usize).saturating_mul(min_element_size.max(1));
        if need > remaining {
            return Err(CdrError::LengthTooLarge {
                offset,
                count,
                remaining,
            });
        }
        Ok(count as usize)
    }

    /// Reads a `string` (length with NUL, bytes, NUL).
    pub fn read_string(&mut self) -> Result<String, CdrError> {
        self.align(4)?;
        let offset = self.pos;
        let len = self.read_len(1)?;
        let bytes = self.take(len)?;
        let Some((&0, text)) = bytes.split_last() else {
            return Err(CdrError::UnterminatedString { offset });
        };
        std::str::from_utf8(text)
            .map(str::to_owned)
            .map_err(|_| CdrError::InvalidUtf8 { offset })
    }

    /// Reads a `uint8[]`.
    pub fn read_bytes(&mut self) -> Result<Vec<u8>, CdrError> {
        let len = self.read_len(1)?;
        Ok(self.take(len)?.to_vec())
    }
}
