//! [`Recorder`]: writes a simulation's messages to an MCAP file (ROS 2 profile, CDR, chunked,
//! zstd-compressed, with summary, indexes and statistics), and finishes the file on drop.

use std::collections::{BTreeMap, HashMap};
use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use mcap::records::{MessageHeader, Metadata};
use mcap::{Compression, WriteOptions, Writer};

use crate::cdr::CdrWriter;
use crate::error::{Error, Result};
use crate::message::RosMessage;
use crate::metadata::{MetadataRecord, RecordingInfo, RunSummary, SOFTGRIP_VERSION};
use crate::step::StepRecord;
use crate::step_messages::{StepTopic, StepVisitor, visit_step};

/// Name of the metadata record softgrip writes ([`RecordingInfo`]).
pub const METADATA_NAME: &str = RecordingInfo::NAME;
/// Name of the metadata record with the run's own summary ([`RunSummary`]), counted over
/// every simulated step (a recording may hold only every n-th step), written when the run
/// finishes.
pub const RUN_SUMMARY_NAME: &str = RunSummary::NAME;

/// The channel metadata key rosbag2 reads the offered QoS from (the step table's channels
/// carry it: [`Delivery::offered_qos_profiles`](crate::Delivery::offered_qos_profiles)).
pub const OFFERED_QOS_PROFILES: &str = "offered_qos_profiles";

/// How the file is written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RecorderOptions {
    /// Uncompressed size at which a chunk is closed \[bytes\]. A killed process loses at most
    /// the open chunk. Default 512 KiB (about 0.4 s of a two-finger squeeze at 1 kHz).
    pub chunk_size: u64,
    /// Compress chunks with zstd. Default true.
    pub compress: bool,
    /// zstd worker threads; 0 compresses on the caller's thread when a chunk closes. Default 1:
    /// the chunk is compressed beside the simulation, not inside its step.
    pub compression_threads: u32,
    /// zstd level; 0 is zstd's default (3). Default 0.
    pub compression_level: u32,
    /// Create the file only if it does not exist (`O_EXCL`): a file that appeared since the
    /// caller checked is an error, never replaced. Default false: an existing file is
    /// truncated.
    pub create_new: bool,
}

impl Default for RecorderOptions {
    fn default() -> Self {
        Self {
            chunk_size: 512 * 1024,
            compress: true,
            compression_threads: 1,
            compression_level: 0,
            create_new: false,
        }
    }
}

/// Counts of a finished recording.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RecordingStats {
    /// Messages written.
    pub messages: u64,
    /// Chunks written.
    pub chunks: u32,
    /// Channels (topics).
    pub channels: u32,
    /// First and last log time \[ns\].
    pub time_range_ns: (u64, u64),
}

/// Writes a recording.
///
/// ```
/// use softgrip_record::{Recorder, RecordingInfo, StepRecord};
/// # fn main() -> Result<(), softgrip_record::Error> {
/// let dir = std::env::temp_dir().join(format!("softgrip-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("squeeze.mcap");
/// let mut rec = Recorder::create(&path, &RecordingInfo::default())?;
/// let mut step = StepRecord { time_ns: 1_000_000, world_frame: "world".into(), ..Default::default() };
/// rec.write_step(&mut step)?;
/// let stats = rec.finish()?;
/// assert_eq!(stats.messages, 4); // clock, tf, contacts, markers (no fingertips: no wrench)
/// # std::fs::remove_dir_all(&dir).ok();
/// # Ok(()) }
/// ```
///
/// Interruption: the file is finished (summary, indexes, footer) by [`finish`](Self::finish)
/// and, if that was never called, by `Drop`, which also runs while a panic unwinds. A process
/// that is killed (SIGKILL, power loss) keeps every closed chunk; [`crate::Recording::open`]
/// recovers them. For Ctrl-C, install a handler that sets a flag the simulation loop checks,
/// then leave the loop and call `finish()` (see the crate README).
pub struct Recorder {
    writer: Option<Writer<BufWriter<File>>>,
    path: PathBuf,
    schemas: HashMap<&'static str, u16>,
    channels: HashMap<String, u16>,
    /// Channels of the step table's topics, by topic and fingertip (`""` for the others).
    step_channels: HashMap<StepTopic, HashMap<String, u16>>,
    buf: CdrWriter,
    sequence: u32,
}

impl std::fmt::Debug for Recorder {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Recorder")
            .field("path", &self.path)
            .field("finished", &self.writer.is_none())
            .field("sequence", &self.sequence)
            .finish()
    }
}

impl Recorder {
    /// Creates (or truncates) `path` with the default [`RecorderOptions`] and writes the
    /// metadata record.
    pub fn create(path: impl AsRef<Path>, info: &RecordingInfo) -> Result<Self> {
        Self::with_options(path, info, &RecorderOptions::default())
    }

    /// Creates (or truncates, unless [`RecorderOptions::create_new`]) `path` with `options`
    /// and writes the metadata record.
    pub fn with_options(
        path: impl AsRef<Path>,
        info: &RecordingInfo,
        options: &RecorderOptions,
    ) -> Result<Self> {
        let path = path.as_ref().to_path_buf();
        let file = std::fs::OpenOptions::new()
            .write(true)
            .create(true)
            .create_new(options.create_new)
            .truncate(true)
            .open(&path)
            .map_err(|source| Error::Io {
                path: path.clone(),
                source,
            })?;
        let compression = options.compress.then_some(Compression::Zstd);
        let mut writer = WriteOptions::new()
            .profile("ros2")
            .library(format!("softgrip-record {SOFTGRIP_VERSION} (mcap-rs)"))
            .compression(compression)
            .compression_threads(options.compression_threads)
            .compression_level(options.compression_level)
            .chunk_size(Some(options.chunk_size.max(1)))
            .create(BufWriter::with_capacity(64 * 1024, file))
            .map_err(|e| Error::write(&path, e))?;
        writer
            .write_metadata(&Metadata {
                name: METADATA_NAME.into(),
                metadata: info.to_metadata()?,
            })
            .map_err(|e| Error::write(&path, e))?;
        Ok(Self {
            writer: Some(writer),
            path,
            schemas: HashMap::new(),
            channels: HashMap::new(),
            step_channels: HashMap::new(),
            buf: CdrWriter::with_capacity(4096),
            sequence: 0,
        })
    }

    /// The file being written.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Messages written so far.
    pub fn messages_written(&self) -> u64 {
        u64::from(self.sequence)
    }

    fn writer(&mut self) -> &mut Writer<BufWriter<File>> {
        self.writer
            .as_mut()
            .expect("invariant: the writer is only taken by finish(self) and drop")
    }

    fn schema_id<M: RosMessage>(&mut self) -> Result<u16> {
        if let Some(&id) = self.schemas.get(M::TYPE_NAME) {
            return Ok(id);
        }
        let text = M::schema_text();
        let id = self
            .writer()
            .add_schema(M::TYPE_NAME, "ros2msg", text.as_bytes())
            .map_err(|e| Error::write(&self.path, e))?;
        self.schemas.insert(M::TYPE_NAME, id);
        Ok(id)
    }

    fn add_channel<M: RosMessage>(
        &mut self,
        topic: &str,
        metadata: &BTreeMap<String, String>,
    ) -> Result<u16> {
        let schema = self.schema_id::<M>()?;
        self.writer()
            .add_channel(schema, topic, "cdr", metadata)
            .map_err(|e| Error::write(&self.path, e))
    }

    fn channel_id<M: RosMessage>(&mut self, topic: &str) -> Result<u16> {
        if let Some(&id) = self.channels.get(topic) {
            return Ok(id);
        }
        let id = self.add_channel::<M>(topic, &BTreeMap::new())?;
        self.channels.insert(topic.to_owned(), id);
        Ok(id)
    }

    fn write_encoded(&mut self, channel_id: u16, time_ns: u64) -> Result<()> {
        self.sequence = self.sequence.wrapping_add(1);
        let header = MessageHeader {
            channel_id,
            sequence: self.sequence,
            log_time: time_ns,
            publish_time: time_ns,
        };
        let writer = self
            .writer
            .as_mut()
            .expect("invariant: the writer is only taken by finish(self) and drop");
        writer
            .write_to_known_channel(&header, self.buf.as_bytes())
            .map_err(|e| Error::write(&self.path, e))
    }

    /// Writes `msg` on `topic` at simulation time `time_ns` \[ns\] (log time = publish time).
    /// The topic's schema and channel are registered on first use. A topic keeps the type it
    /// was first written with.
    pub fn write<M: RosMessage>(&mut self, topic: &str, time_ns: u64, msg: &M) -> Result<()> {
        let channel = self.channel_id::<M>(topic)?;
        msg.encode_into(&mut self.buf);
        self.write_encoded(channel, time_ns)
    }

    /// Writes one step: the messages of [`visit_step`] (`/clock`, `/tf`, `/softgrip/contacts`
    /// with each contact's header set to the step's, one `/softgrip/<fingertip>/wrench` per
    /// fingertip, `/softgrip/markers`).
    pub fn write_step(&mut self, step: &mut StepRecord) -> Result<()> {
        visit_step(step, self)
    }

    /// Writes a typed metadata record ([`RunSummary`], ...).
    pub fn write_record<R: MetadataRecord>(&mut self, record: &R) -> Result<()> {
        self.write_metadata(R::NAME, record.to_metadata()?)
    }

    /// Writes a metadata record `name` (MCAP metadata may come anywhere before the summary
    /// section; readers find it through the metadata index).
    pub fn write_metadata(&mut self, name: &str, metadata: BTreeMap<String, String>) -> Result<()> {
        self.writer()
            .write_metadata(&Metadata {
                name: name.into(),
                metadata,
            })
            .map_err(|e| Error::write(&self.path, e))
    }

    /// Closes the current chunk and hands the file everything written so far (it then
    /// survives a kill). Not needed in normal use: chunks close at `chunk_size`.
    pub fn flush(&mut self) -> Result<()> {
        self.writer()
            .flush()
            .map_err(|e| Error::write(&self.path, e))
    }

    /// Finishes the file: closes the last chunk, writes the summary (schemas, channels,
    /// statistics, chunk and metadata indexes), the footer, and flushes.
    pub fn finish(mut self) -> Result<RecordingStats> {
        let mut writer = self
            .writer
            .take()
            .expect("invariant: the writer is only taken by finish(self) and drop");
        let summary = writer.finish().map_err(|e| Error::write(&self.path, e))?;
        let path = self.path.clone();
        writer.into_inner().into_inner().map_err(|e| Error::Io {
            path,
            source: e.into_error(),
        })?;
        let stats = summary.stats.unwrap_or_default();
        Ok(RecordingStats {
            messages: stats.message_count,
            chunks: stats.chunk_count,
            channels: stats.channel_count,
            time_range_ns: (stats.message_start_time, stats.message_end_time),
        })
    }
}

impl StepVisitor for Recorder {
    type Error = Error;

    fn message<M: RosMessage>(
        &mut self,
        topic: StepTopic,
        fingertip: &str,
        time_ns: u64,
        msg: &M,
    ) -> Result<()> {
        let known = self
            .step_channels
            .get(&topic)
            .and_then(|by_tip| by_tip.get(fingertip));
        let channel = match known {
            Some(&id) => id,
            None => {
                // rosbag2's channel metadata: `ros2 bag play` offers the recorded QoS.
                let qos = BTreeMap::from([(
                    OFFERED_QOS_PROFILES.to_owned(),
                    topic.delivery().offered_qos_profiles(),
                )]);
                let id = self.add_channel::<M>(&topic.name(fingertip), &qos)?;
                self.step_channels
                    .entry(topic)
                    .or_default()
                    .insert(fingertip.to_owned(), id);
                id
            }
        };
        msg.encode_into(&mut self.buf);
        self.write_encoded(channel, time_ns)
    }
}

impl Drop for Recorder {
    /// Finishes the file if [`finish`](Recorder::finish) was not called (errors are ignored
    /// here: call `finish` to see them).
    fn drop(&mut self) {
        if let Some(mut writer) = self.writer.take() {
            let _ = writer.finish();
        }
    }
}
