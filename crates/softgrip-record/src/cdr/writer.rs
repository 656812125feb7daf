//! [`CdrWriter`]: serialises primitives into a CDR little-endian buffer.

use super::ENCAPSULATION_CDR_LE;

/// A growable CDR little-endian buffer that starts with the encapsulation header.
///
/// Reuse one writer across messages with [`reset`](Self::reset): it keeps its allocation.
///
/// ```
/// use softgrip_record::cdr::CdrWriter;
/// let mut w = CdrWriter::new();
/// w.write_u8(7);
/// w.write_f64(1.0); // aligned to 8 from the payload start: 7 bytes of padding
/// assert_eq!(w.as_bytes().len(), 4 + 1 + 7 + 8);
/// ```
#[derive(Debug, Clone)]
pub struct CdrWriter {
    buf: Vec<u8>,
}

impl Default for CdrWriter {
    fn default() -> Self {
        Self::new()
    }
}

impl CdrWriter {
    /// An empty message: just the encapsulation header.
    pub fn new() -> Self {
        Self::with_capacity(256)
    }

    /// An empty message with room for `capacity` bytes.
    pub fn with_capacity(capacity: usize) -> Self {
        let mut buf = Vec::with_capacity(capacity.max(ENCAPSULATION_CDR_LE.len()));
        buf.extend_from_slice(&ENCAPSULATION_CDR_LE);
        Self { buf }
    }

    /// Starts a new message, keeping the allocation.
    pub fn reset(&mut self) {
        self.buf.clear();
        self.buf.extend_from_slice(&ENCAPSULATION_CDR_LE);
    }

    /// The serialised message so far, header included.
    pub fn as_bytes(&self) -> &[u8] {
        &self.buf
    }

    /// The serialised message, header included.
    pub fn into_bytes(self) -> Vec<u8> {
        self.buf
    }

    /// Pads with zeros to a multiple of `size` from the payload start.
    #[inline]
    fn align(&mut self, size: usize) {
        let offset = self.buf.len() - ENCAPSULATION_CDR_LE.len();
        let pad = (size - offset % size) % size;
        self.buf.resize(self.buf.len() + pad, 0);
    }

    /// Writes a `bool` as one byte, 0 or 1.
    #[inline]
    pub fn write_bool(&mut self, v: bool) {
        self.buf.push(u8::from(v));
    }

    /// Writes a `uint8` (no alignment).
    #[inline]
    pub fn write_u8(&mut self, v: u8) {
        self.buf.push(v);
    }

    /// Writes an `int32`, aligned to 4.
    #[inline]
    pub fn write_i32(&mut self, v: i32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes a `uint32`, aligned to 4.
    #[inline]
    pub fn write_u32(&mut self, v: u32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes an `int64`, aligned to 8.
    #[inline]
    pub fn write_i64(&mut self, v: i64) {
        self.align(8);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes a `uint64`, aligned to 8.
    #[inline]
    pub fn write_u64(&mut self, v: u64) {
        self.align(8);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes a `float32`, aligned to 4.
    #[inline]
    pub fn write_f32(&mut self, v: f32) {
        self.align(4);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes a `float64`, aligned to 8.
    #[inline]
    pub fn write_f64(&mut self, v: f64) {
        self.align(8);
        self.buf.extend_from_slice(&v.to_le_bytes());
    }

    /// Writes a sequence length (`uint32`, aligned to 4). Saturates at `u32::MAX` (a sequence
    /// that long cannot be sent by ROS 2 anyway).
    #[inline]
    pub fn write_len(&mut self, len: usize) {
        self.write_u32(u32::try_from(len).unwrap_or(u32::MAX));
    }

    /// Writes a `string`: `uint32` length counting the terminating NUL, the bytes, NUL.
    ///
    /// ROS 2 strings are NUL-terminated: a string with an interior NUL is cut there by C and
    /// C++ readers (this crate's reader keeps it).
    pub fn write_string(&mut self, s: &str) {
        self.write_len(s.len() + 1);
        self.buf.extend_from_slice(s.as_bytes());
        self.buf.push(0);
    }

    /// Writes a `uint8[]`: `uint32` count, then the bytes.
    pub fn write_bytes(&mut self, bytes: &[u8]) {
        self.write_len(bytes.len());
        self.buf.extend_from_slice(bytes);
    }
}
