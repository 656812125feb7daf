//! Bounded reads: a scene, mesh or curve file is read up to its size limit
//! ([`MAX_SCENE_BYTES`](crate::MAX_SCENE_BYTES), ...), so `/dev/zero` or a wrong path to a
//! huge file is a clear error instead of exhausting the memory.

use std::io::Read;
use std::path::Path;

/// Why a bounded read failed.
#[derive(Debug)]
pub(crate) enum ReadError {
    /// The file could not be opened or read.
    Io(std::io::Error),
    /// The file holds more than `limit` bytes.
    TooLarge {
        /// The limit \[bytes\].
        limit: u64,
    },
}

/// The bytes of `path`, at most `limit` of them.
pub(crate) fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    let file = std::fs::File::open(path).map_err(ReadError::Io)?;
    // A regular file says its size: refuse early. Devices and pipes say 0 and are read up to
    // the limit (one byte more tells that they hold more).
    if let Ok(meta) = file.metadata()
        && meta.is_file()
        && meta.len() > limit
    {
        return Err(ReadError::TooLarge { limit });
    }
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge { limit });
    }
    Ok(bytes)
}

/// `limit` bytes in MiB or bytes, for messages.
pub(crate) fn size(limit: u64) -> String {
    if limit >= 1 << 20 {
        format!("{} MiB", limit >> 20)
    } else {
        format!("{limit} bytes")
    }
}
