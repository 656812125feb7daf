//! Bounded reads: a scene, mesh or curve file is read up to its size limit
//! ([`MAX_SCENE_BYTES`](crate::MAX_SCENE_BYTES), ...), so `/dev/zero` or a wrong path to a
//! huge file is a clear error instead of exhausting the memory. A file a scene *refers to* (a
//! mesh, a curve) must be a regular file: a FIFO would block the read forever, a device or a
//! directory is never a mesh. Text files may start with a UTF-8 byte-order mark (Windows
//! editors write one): it is not part of the text ([`strip_bom`]).

use std::io::Read;
use std::path::Path;

/// The UTF-8 byte-order mark (U+FEFF encoded).
pub const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

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
    /// The path names something other than a regular file (what it is: `a FIFO`, ...).
    NotRegular(&'static str),
}

impl ReadError {
    /// The message of an [`Io`](Self::Io) or [`NotRegular`](Self::NotRegular) error (a
    /// [`TooLarge`](Self::TooLarge) one is its own [`SceneError`](crate::SceneError)).
    pub(crate) fn message(&self) -> String {
        match self {
            ReadError::Io(e) => format!("cannot read: {e}"),
            ReadError::NotRegular(kind) => {
                format!("is {kind}, not a regular file: give the path of a file")
            }
            ReadError::TooLarge { limit } => format!("larger than {}", size(*limit)),
        }
    }
}

/// `bytes` without a leading UTF-8 byte-order mark.
pub fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(UTF8_BOM).unwrap_or(bytes)
}

/// `text` without a leading byte-order mark (U+FEFF).
pub(crate) fn strip_bom_str(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// The bytes of `path`, at most `limit` of them. Any kind of file: a scene may come through
/// a pipe (`softgrip run /dev/stdin`).
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
    read_limited(file, limit)
}

/// The bytes of `reader`, at most `limit` of them.
pub(crate) fn read_limited(reader: impl Read, limit: u64) -> Result<Vec<u8>, ReadError> {
    let mut bytes = Vec::new();
    reader
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge { limit });
    }
    Ok(bytes)
}

/// The bytes of the regular file `path`, at most `limit` of them. Anything else (a FIFO, a
/// socket, a device, a directory) is refused from its metadata, before it is opened: opening
/// a FIFO for reading blocks until a writer comes.
pub(crate) fn read_regular(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    let meta = std::fs::metadata(path).map_err(ReadError::Io)?;
    if !meta.is_file() {
        return Err(ReadError::NotRegular(kind(&meta.file_type())));
    }
    read_bounded(path, limit)
}

/// What a non-regular file is, for messages.
fn kind(t: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "a special file"
    }
}

/// `limit` bytes in MiB or bytes, for messages.
pub(crate) fn size(limit: u64) -> String {
    if limit >= 1 << 20 {
        format!("{} MiB", limit >> 20)
    } else {
        format!("{limit} bytes")
    }
}

/// Whether `a` and `b` name the same existing file, whatever the names (device and inode on
/// Unix, canonical paths elsewhere): how an output is kept from replacing an input.
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
        false
    }
    #[cfg(not(unix))]
    {
        matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y)
    }
}
