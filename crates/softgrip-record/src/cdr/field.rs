//! [`CdrField`]: a value that CDR can write and read: the primitives, `string`, sequences and
//! whole messages (every type in [`msgs`](crate::msgs)).

use super::{CdrError, CdrReader, CdrWriter};

/// A type with a CDR encoding.
pub trait CdrField: Sized {
    /// Smallest encoded size [bytes] (bounds sequence lengths when reading corrupt data).
    const MIN_SIZE: usize = 1;

    /// Appends the value to `w`.
    fn write_cdr(&self, w: &mut CdrWriter);

    /// Reads the value from `r`.
    fn read_cdr(r: &mut CdrReader<'_>) -> Result<Self, CdrError>;
}

macro_rules! primitive {
    ($t:ty, $size:expr, $write:ident, $read:ident) => {
        impl CdrField for $t {
            const MIN_SIZE: usize = $size;
            #[inline]
            fn write_cdr(&self, w: &mut CdrWriter) {
                w.$write(*self);
            }
            #[inline]
            fn read_cdr(r: &mut CdrReader<'_>) -> Result<Self, CdrError> {
                r.$read()
            }
        }
    };
}

primitive!(bool, 1, write_bool, read_bool);
primitive!(u8, 1, write_u8, read_u8);
primitive!(i32, 4, write_i32, read_i32);
primitive!(u32, 4, write_u32, read_u32);
primitive!(i64, 8, write_i64, read_i64);
primitive!(u64, 8, write_u64, read_u64);
primitive!(f32, 4, write_f32, read_f32);
primitive!(f64, 8, write_f64, read_f64);

impl CdrField for String {
    const MIN_SIZE: usize = 5;

    fn write_cdr(&self, w: &mut CdrWriter) {
        w.write_string(self);
    }

    fn read_cdr(r: &mut CdrReader<'_>) -> Result<Self, CdrError> {
        r.read_string()
    }
}

impl<T: CdrField> CdrField for Vec<T> {
    const MIN_SIZE: usize = 4;

    fn write_cdr(&self, w: &mut CdrWriter) {
        w.write_len(self.len());
        for item in self {
            item.write_cdr(w);
        }
    }

    fn read_cdr(r: &mut CdrReader<'_>) -> Result<Self, CdrError> {
        let len = r.read_len(T::MIN_SIZE)?;
        let mut out = Vec::with_capacity(len);
        for _ in 0..len {
            out.push(T::read_cdr(r)?);
        }
        Ok(out)
    }
}
