//! [`recover`]: rewrites a killed or damaged recording into a finished, indexed MCAP file
//! (what the `mcap recover` CLI does): every schema, channel, metadata record, attachment and
//! message that can still be read, in file order, with a fresh summary.

use std::collections::BTreeSet;
use std::fs::File;
use std::io::{BufReader, BufWriter, Read};
use std::path::{Path, PathBuf};

use mcap::records::{Record, op};
use mcap::{Attachment, Compression, WriteOptions, Writer};

use crate::error::{Error, Result};
use crate::metadata::SOFTGRIP_VERSION;
use crate::recording::MAX_RECORD_SIZE;

/// What [`recover`] kept and skipped.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct RecoverReport {
    /// Messages written to the output.
    pub messages: u64,
    /// Of those, messages salvaged from an unfinished chunk (a killed writer's last one).
    pub from_unfinished_chunk: u64,
    /// Complete chunks read.
    pub chunks: u32,
    /// Input length \[bytes\].
    pub file_len: u64,
    /// Bytes of the input read as complete records.
    pub bytes_read: u64,
    /// Records of unknown opcodes (extension records, opcode >= 0x80) skipped by their
    /// length, as the MCAP spec asks of readers.
    pub unknown_records: u64,
    /// Each damaged or unreadable part skipped, and why (empty for an intact file).
    pub skipped: Vec<String>,
}

/// Reads `input` record by record (never more than one record in memory) and writes what
/// can be read to `output` as a finished MCAP file (zstd chunks, message indexes, summary).
/// A chunk whose CRC does not match is skipped; an unfinished chunk (length 2^64 - 1, as a
/// killed writer leaves it) is decompressed as far as its bytes go and its complete records
/// kept; a channel naming a schema the file does not hold is kept without a schema (its
/// messages as the reader reads them); a record of an unknown opcode (an extension record, opcode >= 0x80) is skipped by its
/// length; the data-end record and the summary section's records are read past (a damaged
/// file may have records after a stray data-end: they are kept; the summary is rebuilt);
/// reading stops at the footer, at a record longer than the file, or at opcode 0x00 (not a
/// record: a zero-filled tail, where a crash left blocks unwritten).
///
/// `output` is written whole or not at all: to a temporary file beside it, renamed over it
/// at the end; if it exists it must be a regular file (a rename would replace a device).
/// [`Error::NothingRecovered`] (and no `output`) when no message could be kept. `output` must
/// not be `input` (the caller checks).
pub fn recover(input: &Path, output: &Path) -> Result<RecoverReport> {
    let io = |source| Error::Io {
        path: output.to_path_buf(),
        source,
    };
    if let Ok(meta) = std::fs::metadata(output)
        && !meta.is_file()
    {
        return Err(io(std::io::Error::other(
            "exists and is not a regular file: give the path of a file to write",
        )));
    }
    let dir = match output.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".softgrip-recover-")
        .suffix(".mcap")
        .tempfile_in(dir)
        .map_err(io)?;
    let report = recover_into(input, tmp.as_file_mut(), output)?;
    tmp.persist(output).map_err(|e| io(e.error))?;
    Ok(report)
}

/// [`recover`] into an open file `out` (which it fills from its start); `out_path` names it in
/// errors. [`Error::NothingRecovered`] when no message could be kept (`out` then holds a
/// valid MCAP file without messages, which the caller discards).
pub fn recover_into(input: &Path, out: &mut File, out_path: &Path) -> Result<RecoverReport> {
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| Error::Io { path, source }
    };
    let file = File::open(input).map_err(io(input))?;
    let file_len = file.metadata().map_err(io(input))?.len();
    let mut src = BufReader::new(file);
    let mut magic = [0u8; 8];
    src.read_exact(&mut magic).map_err(|_| Error::Truncated {
        len: file_len as usize,
    })?;
    if magic != *mcap::MAGIC {
        return Err(Error::NotMcap);
    }
    let writer = WriteOptions::new()
        .profile("ros2")
        .library(format!(
            "softgrip-record {SOFTGRIP_VERSION} recover (mcap-rs)"
        ))
        .compression(Some(Compression::Zstd))
        .create(BufWriter::new(out))
        .map_err(|e| Error::write(out_path, e))?;
    let mut r = Rewriter {
        writer,
        out_path: out_path.to_path_buf(),
        schemas: BTreeSet::new(),
        channels: BTreeSet::new(),
        report: RecoverReport {
            file_len,
            bytes_read: 8,
            ..Default::default()
        },
    };
    r.copy(&mut src)?;
    let Rewriter {
        mut writer,
        out_path,
        report,
        ..
    } = r;
    writer.finish().map_err(|e| Error::write(&out_path, e))?;
    writer
        .into_inner()
        .into_inner()
        .map_err(|e| io(&out_path)(e.into_error()))?;
    if report.messages == 0 {
        return Err(Error::NothingRecovered {
            file_len,
            bytes_read: report.bytes_read,
            skipped: report.skipped,
        });
    }
    Ok(report)
}

struct Rewriter<W: std::io::Write + std::io::Seek> {
    writer: Writer<W>,
    /// The output, named in errors.
    out_path: PathBuf,
    schemas: BTreeSet<u16>,
    channels: BTreeSet<u16>,
    report: RecoverReport,
}

impl<W: std::io::Write + std::io::Seek> Rewriter<W> {
    /// Copies the top-level records of `src` (after the magic).
    fn copy(&mut self, src: &mut impl Read) -> Result<()> {
        loop {
            let at = self.report.bytes_read;
            let mut head = [0u8; 9];
            if read_full(src, &mut head) < 9 {
                return Ok(()); // the end of the file (a killed writer's, or a cut one)
            }
            let opcode = head[0];
            let len = u64::from_le_bytes(head[1..].try_into().expect("invariant: 8 bytes"));
            let left = self.report.file_len.saturating_sub(at + 9);
            if opcode == op::FOOTER {
                return Ok(()); // the summary is rebuilt
            }
            if opcode == 0 {
                // Opcode 0x00 is no record (the MCAP spec reserves it): a zero-filled tail,
                // which a crash leaves where blocks were allocated but never written.
                self.skip(format!(
                    "opcode 0x00 at byte {at}: not a record (the rest of the file, {} bytes, is not MCAP records); stopped there",
                    self.report.file_len.saturating_sub(at)
                ));
                return Ok(());
            }
            if len > left || len > MAX_RECORD_SIZE as u64 {
                if opcode == op::CHUNK {
                    let mut rest = Vec::new();
                    src.take(left.min(MAX_RECORD_SIZE as u64))
                        .read_to_end(&mut rest)
                        .ok();
                    self.unfinished_chunk(at, &rest)?;
                } else {
                    self.skip(format!(
                        "record (opcode 0x{opcode:02x}) at byte {at}: length {len} is past the end of the file; stopped there"
                    ));
                }
                return Ok(());
            }
            if !KNOWN_OPCODES.contains(&opcode) {
                // An extension record (opcode >= 0x80) or one of a later MCAP version: skipped
                // by its length, as the spec asks of readers.
                let skipped = std::io::copy(&mut src.take(len), &mut std::io::sink()).unwrap_or(0);
                if skipped < len {
                    return Ok(());
                }
                self.report.bytes_read = at + 9 + len;
                self.report.unknown_records += 1;
                continue;
            }
            let mut body = vec![0u8; len as usize];
            if read_full(src, &mut body) < body.len() {
                return Ok(());
            }
            self.report.bytes_read = at + 9 + len;
            if opcode == op::CHUNK {
                self.chunk(at, &body)?;
            } else {
                match mcap::read::parse_record(opcode, &body) {
                    Ok(rec) => self.record(rec)?,
                    Err(e) => self.skip(format!("record at byte {at}: {e}; skipped")),
                }
            }
        }
    }

    fn skip(&mut self, why: String) {
        self.report.skipped.push(why);
    }

    /// A complete chunk: decompressed, its CRC checked, then its records copied.
    fn chunk(&mut self, at: u64, body: &[u8]) -> Result<()> {
        let (header, data) = match mcap::read::parse_record(op::CHUNK, body) {
            Ok(Record::Chunk { header, data }) => (header, data),
            Ok(_) => return Ok(()),
            Err(e) => {
                self.skip(format!("chunk at byte {at}: {e}; skipped"));
                return Ok(());
            }
        };
        let size = usize::try_from(header.uncompressed_size)
            .unwrap_or(usize::MAX)
            .min(MAX_RECORD_SIZE);
        let records = match header.compression.as_str() {
            "" => data.to_vec(),
            "zstd" => match zstd::bulk::decompress(&data, size) {
                Ok(d) => d,
                Err(e) => {
                    self.skip(format!("chunk at byte {at}: zstd: {e}; skipped"));
                    return Ok(());
                }
            },
            "lz4" => match lz4_frame(&data, size) {
                Ok(d) => d,
                Err(e) => {
                    self.skip(format!("chunk at byte {at}: lz4: {e}; skipped"));
                    return Ok(());
                }
            },
            other => {
                self.skip(format!(
                    "chunk at byte {at}: compression `{other}` not supported; skipped"
                ));
                return Ok(());
            }
        };
        let crc = crc32fast::hash(&records);
        if header.uncompressed_crc != 0 && crc != header.uncompressed_crc {
            self.skip(format!(
                "chunk at byte {at}: CRC 0x{crc:08x} of its records, 0x{:08x} stored: damaged, skipped",
                header.uncompressed_crc
            ));
            return Ok(());
        }
        self.report.chunks += 1;
        self.records_in(at, &records).map(|_| ())
    }

    /// The chunk a killed writer left open (its length and sizes are placeholders): its
    /// header is read field by field and its data decompressed as far as it goes.
    fn unfinished_chunk(&mut self, at: u64, body: &[u8]) -> Result<()> {
        // start time u64, end time u64, uncompressed size u64, crc u32, compression (u32 length,
        // text), compressed size u64, then the (compressed) records.
        let Some(name_len) = body.get(28..32) else {
            return Ok(());
        };
        let name_len =
            u32::from_le_bytes(name_len.try_into().expect("invariant: 4 bytes")) as usize;
        let data_at = 32usize.saturating_add(name_len).saturating_add(8);
        let (Some(name), Some(data)) = (body.get(32..32 + name_len.min(64)), body.get(data_at..))
        else {
            return Ok(());
        };
        let records = match name {
            b"" => data.to_vec(),
            b"zstd" => partial_zstd(data),
            b"lz4" => partial_lz4(data),
            _ => Vec::new(),
        };
        let n = self.records_in(at, &records)?;
        self.report.from_unfinished_chunk += n;
        self.skip(format!(
            "unfinished chunk at byte {at} (the writer was killed): {n} complete messages kept, the rest lost"
        ));
        Ok(())
    }

    /// Copies the complete records of a chunk's (decompressed) `records`; the messages copied.
    fn records_in(&mut self, at: u64, records: &[u8]) -> Result<u64> {
        let before = self.report.messages;
        let mut i = 0usize;
        while let Some(head) = records.get(i..i + 9) {
            let opcode = head[0];
            let len = u64::from_le_bytes(head[1..].try_into().expect("invariant: 8 bytes"));
            let Some(body) = usize::try_from(len)
                .ok()
                .and_then(|l| records.get(i + 9..(i + 9).checked_add(l)?))
            else {
                break; // cut short: an unfinished chunk's last record
            };
            match mcap::read::parse_record(opcode, body) {
                Ok(rec) => self.record(rec)?,
                Err(e) => self.skip(format!("record in the chunk at byte {at}: {e}; skipped")),
            }
            i += 9 + body.len();
        }
        Ok(self.report.messages - before)
    }

    /// Writes one record (schemas and channels once each, messages on known channels).
    fn record(&mut self, rec: Record<'_>) -> Result<()> {
        let w = &mut self.writer;
        match rec {
            Record::Schema { header, data } if header.id != 0 && self.schemas.insert(header.id) => {
                w.add_schema_with_id(header.id, &header.name, &header.encoding, &data)
                    .map_err(|e| Error::write(&self.out_path, e))?;
            }
            // A channel whose schema was lost (damaged, or never written) keeps its messages
            // as a schemaless channel, as the reader reads them.
            Record::Channel(c) if self.channels.insert(c.id) => {
                let schema_id = if c.schema_id == 0 || self.schemas.contains(&c.schema_id) {
                    c.schema_id
                } else {
                    self.report.skipped.push(format!(
                        "channel {} ({}) names schema {}, which the file does not hold; \
                         kept without a schema",
                        c.id, c.topic, c.schema_id
                    ));
                    0
                };
                w.add_channel_with_id(c.id, schema_id, &c.topic, &c.message_encoding, &c.metadata)
                    .map_err(|e| Error::write(&self.out_path, e))?;
            }
            Record::Message { header, data } => {
                if self.channels.contains(&header.channel_id) {
                    w.write_to_known_channel(&header, &data)
                        .map_err(|e| Error::write(&self.out_path, e))?;
                    self.report.messages += 1;
                } else {
                    self.report.skipped.push(format!(
                        "message on unknown channel {} at log time {} ns; skipped",
                        header.channel_id, header.log_time
                    ));
                }
            }
            Record::Metadata(m) => w
                .write_metadata(&m)
                .map_err(|e| Error::write(&self.out_path, e))?,
            Record::Attachment { header, data, .. } => w
                .attach(&Attachment {
                    log_time: header.log_time,
                    create_time: header.create_time,
                    name: header.name,
                    media_type: header.media_type,
                    data,
                })
                .map_err(|e| Error::write(&self.out_path, e))?,
            _ => {} // indexes and statistics: rebuilt
        }
        Ok(())
    }
}

/// Reads until `buf` is full or the source ends; the bytes read.
fn read_full(src: &mut impl Read, buf: &mut [u8]) -> usize {
    let mut n = 0;
    while n < buf.len() {
        match src.read(&mut buf[n..]) {
            Ok(0) | Err(_) => break,
            Ok(k) => n += k,
        }
    }
    n
}

/// An LZ4 frame (MCAP's `lz4` chunks) decompressed whole, at most `limit` bytes.
fn lz4_frame(data: &[u8], limit: usize) -> std::io::Result<Vec<u8>> {
    let mut out = Vec::new();
    lz4::Decoder::new(data)?
        .take(limit as u64 + 1)
        .read_to_end(&mut out)?;
    if out.len() > limit {
        return Err(std::io::Error::other(format!(
            "decompresses past the chunk's uncompressed size ({limit} bytes)"
        )));
    }
    Ok(out)
}

/// An LZ4 frame decompressed as far as its bytes go (a killed writer's), at most
/// [`MAX_RECORD_SIZE`] bytes.
fn partial_lz4(data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    let Ok(decoder) = lz4::Decoder::new(data) else {
        return out;
    };
    read_partial(decoder, &mut out);
    out
}

/// Reads `src` into `out` until it ends or fails (the bytes before a failure are kept), at
/// most [`MAX_RECORD_SIZE`] bytes.
fn read_partial(src: impl Read, out: &mut Vec<u8>) {
    let mut src = src.take(MAX_RECORD_SIZE as u64);
    let mut buf = vec![0u8; 64 * 1024];
    loop {
        match src.read(&mut buf) {
            Ok(0) | Err(_) => break,
            Ok(k) => out.extend_from_slice(&buf[..k]),
        }
    }
}

/// The opcodes of MCAP version 0 (0x01 header .. 0x10 data end).
const KNOWN_OPCODES: std::ops::RangeInclusive<u8> = 0x01..=0x10;

/// A zstd stream decompressed as far as its bytes go (a killed writer's stream ends in the
/// middle of a frame), at most [`MAX_RECORD_SIZE`] bytes.
fn partial_zstd(data: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    let Ok(decoder) = zstd::stream::read::Decoder::new(data) else {
        return out;
    };
    read_partial(decoder, &mut out);
    out
}
