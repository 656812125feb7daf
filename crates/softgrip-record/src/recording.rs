//! [`Recording`]: reads a recording back, from its summary when the file was finished, or by
//! recovering every complete chunk of a file whose writer was killed.

use std::collections::{BTreeMap, HashMap};
use std::fs::File;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::Path;

use mcap::records::Record;
use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};

use crate::decoded::Message;
use crate::error::{Error, Result};
use crate::metadata::{MetadataError, MetadataRecord, RecordingInfo, RunSummary};

/// A topic of the recording.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChannelInfo {
    /// Topic name.
    pub topic: String,
    /// Schema name (`pkg/msg/Type`), empty without a schema.
    pub schema_name: String,
    /// Message encoding (`cdr`).
    pub message_encoding: String,
    /// Messages read on it.
    pub message_count: u64,
}

/// A message with its timing, decoded.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordedMessage {
    /// Topic name.
    pub topic: String,
    /// Log time = simulation time \[ns\].
    pub log_time_ns: u64,
    /// Publish time \[ns\] (softgrip writes the log time).
    pub publish_time_ns: u64,
    /// Sequence number in the file.
    pub sequence: u32,
    /// The decoded message.
    pub message: Message,
}

/// How an unfinished file was recovered.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Recovery {
    /// Complete chunks kept.
    pub chunks: u32,
    /// Bytes of the file up to the end of the last record kept.
    pub bytes_kept: u64,
    /// File length \[bytes\].
    pub file_len: u64,
    /// Why reading stopped there (the damaged or incomplete record).
    pub stopped_because: String,
}

/// A recording read back.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// Metadata records by name, as stored (softgrip writes [`RecordingInfo`] and
    /// [`RunSummary`]: read them typed with [`info`](Self::info) and
    /// [`run_summary`](Self::run_summary)).
    pub metadata: BTreeMap<String, BTreeMap<String, String>>,
    /// Topics, in channel-id order.
    pub channels: Vec<ChannelInfo>,
    /// Every message, in file order (= simulation order for softgrip's recordings).
    pub messages: Vec<RecordedMessage>,
    /// Chunks read.
    pub chunk_count: u32,
    /// `None` for a finished file; for an unfinished one (no summary or footer: the writer was
    /// killed), what was recovered.
    pub recovery: Option<Recovery>,
}

struct SchemaInfo {
    name: String,
    /// The schema text (a `.msg` definition), which tells a layout of an earlier version.
    text: Vec<u8>,
}

struct Channel {
    topic: String,
    schema: u16,
    encoding: String,
}

/// What a scan collected.
#[derive(Default)]
struct Scan {
    schemas: HashMap<u16, SchemaInfo>,
    channels: BTreeMap<u16, Channel>,
    metadata: BTreeMap<String, BTreeMap<String, String>>,
    messages: Vec<RecordedMessage>,
    /// The summary's statistics record (a finished file).
    statistics: Option<mcap::records::Statistics>,
}

impl Scan {
    /// Applies one record (outside or inside a chunk). Errors are strings: the caller decides
    /// whether they mean corruption or the end of a recovery.
    fn apply(&mut self, record: Record<'_>) -> Result<(), ScanStop> {
        match record {
            Record::Schema { header, data } => {
                self.schemas.insert(
                    header.id,
                    SchemaInfo {
                        name: header.name,
                        text: data.into_owned(),
                    },
                );
            }
            Record::Channel(c) => {
                self.channels.insert(
                    c.id,
                    Channel {
                        topic: c.topic,
                        schema: c.schema_id,
                        encoding: c.message_encoding,
                    },
                );
            }
            Record::Metadata(m) => {
                self.metadata.insert(m.name, m.metadata);
            }
            Record::Statistics(st) => self.statistics = Some(st),
            Record::Message { header, data } => {
                let Some(channel) = self.channels.get(&header.channel_id) else {
                    return Err(ScanStop::Damaged(format!(
                        "message on unknown channel {}",
                        header.channel_id
                    )));
                };
                let (schema_name, schema_text) = self
                    .schemas
                    .get(&channel.schema)
                    .map(|s| (s.name.as_str(), s.text.as_slice()))
                    .unwrap_or(("", &[]));
                let message =
                    Message::decode_with_schema(schema_name, schema_text, &channel.encoding, &data)
                        .map_err(|source| {
                            ScanStop::Decode(Error::Decode {
                                topic: channel.topic.clone(),
                                log_time_ns: header.log_time,
                                source,
                            })
                        })?;
                self.messages.push(RecordedMessage {
                    topic: channel.topic.clone(),
                    log_time_ns: header.log_time,
                    publish_time_ns: header.publish_time,
                    sequence: header.sequence,
                    message,
                });
            }
            _ => {}
        }
        Ok(())
    }
}

impl Scan {
    /// Reads every record of `src` (a whole file, or its complete records when `finished` is
    /// false), decompressing chunks, in pieces of at most 64 KiB at a time beyond the record
    /// being read. Every CRC the file carries is checked (each chunk's before any of its
    /// records is used, the data section's, the summary section's; attachments' when parsed);
    /// record and chunk sizes are bounded so a corrupt length cannot exhaust memory.
    fn read(&mut self, src: &mut impl Read, finished: bool) -> Result<(), ScanStop> {
        let options = LinearReaderOptions::default()
            .with_skip_end_magic(!finished)
            .with_emit_chunks(false)
            .with_prevalidate_chunk_crcs(true)
            .with_validate_data_section_crc(finished)
            .with_validate_summary_section_crc(finished)
            .with_record_length_limit(MAX_RECORD_SIZE);
        let mut reader = LinearReader::new_with_options(options);
        let mut read = 0u64;
        let at = |read: u64, e: &dyn std::fmt::Display| format!("{e} (read up to byte {read})");
        while let Some(event) = reader.next_event() {
            match event {
                Ok(LinearReadEvent::ReadRequest(need)) => {
                    let buf = reader.insert(need.min(READ_PIECE));
                    let n = read_some(src, buf).map_err(|e| ScanStop::Damaged(e.to_string()))?;
                    reader.notify_read(n);
                    read += n as u64;
                }
                Ok(LinearReadEvent::Record { data, opcode }) => {
                    let record = mcap::read::parse_record(opcode, data)
                        .map_err(|e| ScanStop::Damaged(at(read, &e)))?;
                    self.apply(record)?;
                }
                Err(e) => return Err(ScanStop::Damaged(at(read, &e))),
            }
        }
        Ok(())
    }
}

/// Fills as much of `buf` as the source gives in one go (0 at its end).
fn read_some(src: &mut impl Read, buf: &mut [u8]) -> std::io::Result<usize> {
    loop {
        match src.read(buf) {
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            r => return r,
        }
    }
}

enum ScanStop {
    Damaged(String),
    Decode(Error),
}

/// Largest record or (uncompressed) chunk read [bytes] (softgrip writes 512 KiB chunks; other
/// writers 1-4 MiB).
pub(crate) const MAX_RECORD_SIZE: usize = 256 << 20;

/// Bytes handed to the MCAP reader at a time.
const READ_PIECE: usize = 64 << 10;

/// The MCAP magic, at both ends of a finished file.
const MAGIC: &[u8] = mcap::MAGIC;

impl Recording {
    /// Reads the file at `path`, streamed: the file is never read whole into memory (a
    /// device such as `/dev/zero` is refused after its first 8 bytes), see
    /// [`from_bytes`](Self::from_bytes) for what is checked.
    pub fn open(path: impl AsRef<Path>) -> Result<Self> {
        let path = path.as_ref();
        let io = |source| Error::Io {
            path: path.to_path_buf(),
            source,
        };
        let mut file = File::open(path).map_err(io)?;
        let meta = file.metadata().map_err(io)?;
        if meta.is_dir() {
            return Err(io(std::io::Error::from(std::io::ErrorKind::IsADirectory)));
        }
        let mut head = [0u8; 8];
        let n = read_full(&mut file, &mut head).map_err(io)?;
        check_magic(&head[..n])?;
        if !meta.is_file() {
            // A pipe or device: its length is unknown, so it is read as a stream up to a bound.
            let mut bytes = head.to_vec();
            (&mut file)
                .take(MAX_STREAM_SIZE + 1)
                .read_to_end(&mut bytes)
                .map_err(io)?;
            if bytes.len() as u64 > MAX_STREAM_SIZE {
                return Err(Error::Corrupt {
                    reason: format!(
                        "not a regular file and longer than {MAX_STREAM_SIZE} bytes: refused"
                    ),
                });
            }
            return Self::from_bytes(&bytes);
        }
        let len = meta.len();
        let mut tail = [0u8; 8];
        let finished = len >= 16
            && file.seek(SeekFrom::End(-8)).is_ok()
            && read_full(&mut file, &mut tail).is_ok_and(|k| k == 8)
            && tail == *MAGIC;
        file.seek(SeekFrom::Start(0)).map_err(io)?;
        let mut src = BufReader::with_capacity(READ_PIECE, file);
        if finished {
            let rec = Self::read_finished(&mut src, || 0)?;
            if rec.chunk_count > 0 || rec.messages.is_empty() {
                return Ok(rec);
            }
            // No Statistics record: the chunks counted from the record heads.
            let counted = complete_records_end(&mut src, len).map_err(io)?.chunks;
            Ok(Self {
                chunk_count: counted,
                ..rec
            })
        } else {
            let records = complete_records_end(&mut src, len).map_err(io)?;
            src.seek(SeekFrom::Start(0)).map_err(io)?;
            Ok(Self::recover(&mut src.take(records.end), &records, len))
        }
    }

    /// Reads a recording from memory.
    ///
    /// - A finished file (ends with the MCAP magic) is read whole with every CRC checked
    ///   (chunks, data section, summary section, attachments) and its summary statistics
    ///   compared with what was read; any damage is [`Error::Corrupt`] naming the damaged
    ///   part, a message that does not decode is [`Error::Decode`].
    /// - An unfinished file (the writer was killed) is read up to the last complete chunk, and
    ///   [`recovery`](Self::recovery) says how much was kept and why reading stopped.
    /// - A file that does not start with the MCAP magic is [`Error::NotMcap`] (or
    ///   [`Error::Truncated`] if shorter than it).
    ///
    /// It never panics on any input.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self> {
        check_magic(&bytes[..bytes.len().min(MAGIC.len())])?;
        let finished = bytes.len() >= 2 * MAGIC.len() && bytes.ends_with(MAGIC);
        if finished {
            Self::read_finished(&mut &bytes[..], || {
                let mut src = BufReader::new(std::io::Cursor::new(bytes));
                complete_records_end(&mut src, bytes.len() as u64).map_or(0, |r| r.chunks)
            })
        } else {
            let len = bytes.len() as u64;
            let mut src = BufReader::new(std::io::Cursor::new(bytes));
            let records = complete_records_end(&mut src, len)
                .expect("invariant: reading memory does not fail");
            Ok(Self::recover(
                &mut &bytes[..records.end as usize],
                &records,
                len,
            ))
        }
    }

    /// Reads a finished file; `count_chunks` counts its chunks when it has no Statistics
    /// record to say how many.
    fn read_finished(src: &mut impl Read, count_chunks: impl FnOnce() -> u32) -> Result<Self> {
        let corrupt = |reason: String| Error::Corrupt { reason };
        let mut scan = Scan::default();
        match scan.read(src, true) {
            Ok(()) => {}
            Err(ScanStop::Damaged(reason)) => return Err(corrupt(reason)),
            Err(ScanStop::Decode(e)) => return Err(e),
        }
        // The Statistics record is optional (the MCAP spec; the MCAP CLI and Python's writer
        // can leave it out, or the whole summary section): when present, it must agree.
        let read = scan.messages.len() as u64;
        let chunks = match scan.statistics.take() {
            Some(stats) if stats.message_count != read => {
                return Err(corrupt(format!(
                    "summary section: the statistics count {} messages, the data section has {read}",
                    stats.message_count
                )));
            }
            Some(stats) => stats.chunk_count,
            None => count_chunks(),
        };
        Ok(Self::from_scan(scan, chunks, None))
    }

    /// Reads the complete records (`records`) of an unfinished file of `file_len` bytes.
    fn recover(src: &mut impl Read, records: &Records, file_len: u64) -> Self {
        let (end, chunks) = (records.end, records.chunks);
        let mut scan = Scan::default();
        let stopped_because = match scan.read(src, false) {
            Ok(()) if end == file_len => "the file ends without a summary and footer".into(),
            Ok(()) if records.zeros => format!(
                "opcode 0x00 at byte {end}: not a record (a zero-filled tail of {} bytes)",
                file_len - end
            ),
            Ok(()) => format!("incomplete record at byte {end}"),
            Err(ScanStop::Damaged(reason)) => reason,
            Err(ScanStop::Decode(e)) => e.to_string(),
        };
        let recovery = Recovery {
            chunks,
            bytes_kept: end,
            file_len,
            stopped_because,
        };
        Self::from_scan(scan, chunks, Some(recovery))
    }

    fn from_scan(scan: Scan, chunk_count: u32, recovery: Option<Recovery>) -> Self {
        let mut counts: HashMap<u16, u64> = HashMap::new();
        let topic_ids: HashMap<&str, u16> = scan
            .channels
            .iter()
            .map(|(&id, c)| (c.topic.as_str(), id))
            .collect();
        for m in &scan.messages {
            if let Some(&id) = topic_ids.get(m.topic.as_str()) {
                *counts.entry(id).or_default() += 1;
            }
        }
        let channels = scan
            .channels
            .iter()
            .map(|(id, c)| ChannelInfo {
                topic: c.topic.clone(),
                schema_name: scan
                    .schemas
                    .get(&c.schema)
                    .map(|s| s.name.clone())
                    .unwrap_or_default(),
                message_encoding: c.encoding.clone(),
                message_count: counts.get(id).copied().unwrap_or(0),
            })
            .collect();
        Self {
            metadata: scan.metadata,
            channels,
            messages: scan.messages,
            chunk_count,
            recovery,
        }
    }

    /// Whether the file was unfinished and recovered.
    pub fn recovered(&self) -> bool {
        self.recovery.is_some()
    }

    /// The messages on `topic`.
    pub fn on_topic<'a>(&'a self, topic: &'a str) -> impl Iterator<Item = &'a RecordedMessage> {
        self.messages.iter().filter(move |m| m.topic == topic)
    }

    /// A value of softgrip's metadata record as stored (`scene`, `softgrip_version`, ...; the
    /// typed record is [`info`](Self::info)).
    pub fn softgrip_metadata(&self, key: &str) -> Option<&str> {
        self.metadata
            .get(crate::recorder::METADATA_NAME)
            .and_then(|m| m.get(key))
            .map(String::as_str)
    }

    /// The typed metadata record `R` (`None` if the file has no record of that name).
    pub fn record<R: MetadataRecord>(&self) -> Result<Option<R>, MetadataError> {
        self.metadata.get(R::NAME).map(R::from_metadata).transpose()
    }

    /// What the recording is of: its [`RecordingInfo`] (`softgrip` record).
    pub fn info(&self) -> Result<Option<RecordingInfo>, MetadataError> {
        self.record()
    }

    /// The run's own summary ([`RunSummary`], counted over every simulated step); `None` if
    /// the run did not finish normally.
    pub fn run_summary(&self) -> Result<Option<RunSummary>, MetadataError> {
        self.record()
    }
}

/// Largest pipe or device read as a recording [bytes] (a regular file is streamed, whatever
/// its size).
const MAX_STREAM_SIZE: u64 = 1 << 30;

/// [`Error::NotMcap`] or [`Error::Truncated`] unless `head` (the first 8 bytes, or all there
/// are) is the magic.
fn check_magic(head: &[u8]) -> Result<()> {
    if head.len() < MAGIC.len() {
        return Err(if MAGIC.starts_with(head) {
            Error::Truncated { len: head.len() }
        } else {
            Error::NotMcap
        });
    }
    if head != MAGIC {
        return Err(Error::NotMcap);
    }
    Ok(())
}

/// Reads until `buf` is full or the source ends; the bytes read.
fn read_full(src: &mut impl Read, buf: &mut [u8]) -> std::io::Result<usize> {
    let mut n = 0;
    while n < buf.len() {
        match read_some(src, &mut buf[n..])? {
            0 => break,
            k => n += k,
        }
    }
    Ok(n)
}

/// Where the complete top-level records of an unfinished file end.
struct Records {
    /// The end of the last complete record \[bytes\].
    end: u64,
    /// Chunks among them.
    chunks: u32,
    /// Reading stopped at opcode 0x00 (no record: a zero-filled tail).
    zeros: bool,
}

/// The end of the last complete top-level record of a file of `len` bytes (after the magic;
/// opcode u8, body length u64 LE, body): a killed writer leaves a partial record after it,
/// a crash may leave a zero-filled tail (opcode 0x00 is no record: it ends the walk at once).
/// Only the 9-byte record heads are read; bodies are skipped within the buffer when they can
/// be (`seek_relative`), so many small records cost no system call each.
fn complete_records_end<R: Read + Seek>(
    src: &mut BufReader<R>,
    len: u64,
) -> std::io::Result<Records> {
    let mut end = MAGIC.len() as u64;
    let mut chunks = 0;
    src.seek(SeekFrom::Start(end))?;
    loop {
        let mut head = [0u8; 9];
        if read_full(src, &mut head)? < 9 {
            return Ok(Records {
                end,
                chunks,
                zeros: false,
            });
        }
        if head[0] == 0 {
            return Ok(Records {
                end,
                chunks,
                zeros: true,
            });
        }
        let body = u64::from_le_bytes(head[1..].try_into().expect("invariant: 8 bytes"));
        match (end + 9).checked_add(body) {
            Some(next) if next <= len => end = next,
            _ => {
                return Ok(Records {
                    end,
                    chunks,
                    zeros: false,
                });
            }
        }
        if head[0] == mcap::records::op::CHUNK {
            chunks += 1;
        }
        match i64::try_from(body) {
            Ok(b) => src.seek_relative(b)?,
            Err(_) => {
                src.seek(SeekFrom::Start(end))?;
            }
        }
    }
}
