//! [`Recording`]: reads a recording back, from its summary when the file was finished, or by
//! recovering every complete chunk of a file whose writer was killed.

use std::collections::{BTreeMap, HashMap};
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
}

impl Scan {
    /// Applies one record (outside or inside a chunk). Errors are strings: the caller decides
    /// whether they mean corruption or the end of a recovery.
    fn apply(&mut self, record: Record<'_>) -> Result<(), ScanStop> {
        match record {
            Record::Schema { header, .. } => {
                self.schemas
                    .insert(header.id, SchemaInfo { name: header.name });
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
            Record::Message { header, data } => {
                let Some(channel) = self.channels.get(&header.channel_id) else {
                    return Err(ScanStop::Damaged(format!(
                        "message on unknown channel {}",
                        header.channel_id
                    )));
                };
                let schema_name = self
                    .schemas
                    .get(&channel.schema)
                    .map(|s| s.name.as_str())
                    .unwrap_or("");
                let message =
                    Message::decode(schema_name, &channel.encoding, &data).map_err(|source| {
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
    /// Reads every record of `bytes` (a whole file, or its complete records when `finished` is
    /// false), decompressing chunks. Each chunk's CRC is checked before any of its records is
    /// used, so a damaged chunk adds nothing; record and chunk sizes are bounded so a corrupt
    /// length cannot exhaust memory.
    fn read(&mut self, bytes: &[u8], finished: bool) -> Result<(), ScanStop> {
        let options = LinearReaderOptions::default()
            .with_skip_end_magic(!finished)
            .with_emit_chunks(false)
            .with_prevalidate_chunk_crcs(true)
            .with_validate_data_section_crc(finished)
            .with_record_length_limit(MAX_RECORD_SIZE);
        let mut reader = LinearReader::new_with_options(options);
        let mut rest = bytes;
        while let Some(event) = reader.next_event() {
            match event {
                Ok(LinearReadEvent::ReadRequest(need)) => {
                    let n = need.min(rest.len());
                    reader.insert(n).copy_from_slice(&rest[..n]);
                    reader.notify_read(n);
                    rest = &rest[n..];
                }
                Ok(LinearReadEvent::Record { data, opcode }) => {
                    let record = mcap::read::parse_record(opcode, data)
                        .map_err(|e| ScanStop::Damaged(e.to_string()))?;
                    self.apply(record)?;
                }
                Err(e) => return Err(ScanStop::Damaged(e.to_string())),
            }
        }
        Ok(())
    }
}

enum ScanStop {
    Damaged(String),
    Decode(Error),
}

/// Largest record or (uncompressed) chunk read [bytes] (softgrip writes 512 KiB chunks; other
/// writers 1-4 MiB).
const MAX_RECORD_SIZE: usize = 256 << 20;

/// The MCAP magic, at both ends of a finished file.
const MAGIC: &[u8] = mcap::MAGIC;

impl Recording {
    /// Reads the file at `path` (see [`from_bytes`](Self::from_bytes)).
    pub fn open(path: impl AsRef<Path>) -> Result<Self> {
        let path = path.as_ref();
        let bytes = std::fs::read(path).map_err(|source| Error::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::from_bytes(&bytes)
    }

    /// Reads a recording from memory.
    ///
    /// - A finished file (ends with the MCAP magic) is read whole with chunk CRCs checked and
    ///   its summary statistics compared with what was read; any damage is
    ///   [`Error::Corrupt`], a message that does not decode is [`Error::Decode`].
    /// - An unfinished file (the writer was killed) is read up to the last complete chunk, and
    ///   [`recovery`](Self::recovery) says how much was kept and why reading stopped.
    /// - A file that does not start with the MCAP magic is [`Error::NotMcap`] (or
    ///   [`Error::Truncated`] if shorter than it).
    ///
    /// It never panics on any input.
    pub fn from_bytes(bytes: &[u8]) -> Result<Self> {
        if bytes.len() < MAGIC.len() {
            return Err(if MAGIC.starts_with(bytes) {
                Error::Truncated { len: bytes.len() }
            } else {
                Error::NotMcap
            });
        }
        if !bytes.starts_with(MAGIC) {
            return Err(Error::NotMcap);
        }
        let finished = bytes.len() >= 2 * MAGIC.len() && bytes.ends_with(MAGIC);
        if finished {
            Self::read_finished(bytes)
        } else {
            Ok(Self::recover(bytes))
        }
    }

    fn read_finished(bytes: &[u8]) -> Result<Self> {
        let corrupt = |reason: String| Error::Corrupt { reason };
        let summary = mcap::Summary::read(bytes).map_err(|e| corrupt(format!("summary: {e}")))?;
        let mut scan = Scan::default();
        match scan.read(bytes, true) {
            Ok(()) => {}
            Err(ScanStop::Damaged(reason)) => return Err(corrupt(reason)),
            Err(ScanStop::Decode(e)) => return Err(e),
        }
        let stats = summary.and_then(|s| s.stats).unwrap_or_default();
        let read = scan.messages.len() as u64;
        if stats.message_count != read {
            return Err(corrupt(format!(
                "the summary counts {} messages, the data section has {read}",
                stats.message_count
            )));
        }
        Ok(Self::from_scan(scan, stats.chunk_count, None))
    }

    fn recover(bytes: &[u8]) -> Self {
        // Frame the top-level records by their lengths (opcode u8, length u64, body) to find
        // the end of the last complete one; a killed writer leaves a partial record after it.
        let mut end = MAGIC.len();
        let mut chunks = 0;
        while let Some(next) = next_record_end(bytes, end) {
            if bytes[end] == mcap::records::op::CHUNK {
                chunks += 1;
            }
            end = next;
        }
        let mut scan = Scan::default();
        let stopped_because = match scan.read(&bytes[..end], false) {
            Ok(()) if end == bytes.len() => "the file ends without a summary and footer".into(),
            Ok(()) => format!("incomplete record at byte {end}"),
            Err(ScanStop::Damaged(reason)) => reason,
            Err(ScanStop::Decode(e)) => e.to_string(),
        };
        let recovery = Recovery {
            chunks,
            bytes_kept: end as u64,
            file_len: bytes.len() as u64,
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

/// The end of the complete record starting at `offset` (opcode u8, body length u64 LE, body),
/// if the bytes hold all of it.
fn next_record_end(bytes: &[u8], offset: usize) -> Option<usize> {
    let len = bytes.get(offset + 1..offset.checked_add(9)?)?;
    let mut a = [0u8; 8];
    a.copy_from_slice(len);
    usize::try_from(u64::from_le_bytes(a))
        .ok()
        .and_then(|l| (offset + 9).checked_add(l))
        .filter(|&end| end <= bytes.len())
}
