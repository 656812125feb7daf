//! [`McapSink`]: the [`StepSink`] that writes a run to an MCAP file with a [`Recorder`] on its
//! own writer thread.

use std::fmt;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::sync::{Arc, Mutex};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use crate::convert::{StepConverter, WORLD_FRAME};
use crate::metadata::{RecordingInfo, RunSummary};
use crate::recorder::{Recorder, RecorderOptions, RecordingStats};
use crate::sink::{SceneInfo, SinkError, StepFrame, StepSink};
use crate::step::StepRecord;

/// An error of the [`McapSink`].
#[derive(Debug, thiserror::Error)]
pub enum McapSinkError {
    /// The recorder failed (I/O, encoding); later steps were not written.
    #[error(transparent)]
    Record(#[from] crate::Error),
    /// The writer thread could not be started.
    #[error("starting the MCAP writer thread: {0}")]
    Spawn(#[source] std::io::Error),
    /// The writer thread panicked (the file is finished by the recorder's `Drop` if it can be).
    #[error("the MCAP writer thread panicked")]
    WriterPanicked,
    /// `write` after `finish`, or after an error was already returned.
    #[error("the MCAP recording was already finished")]
    Finished,
}

/// Writes a run to MCAP: the messages of the step table
/// ([`visit_step`](crate::visit_step)) every `every_n_steps`-th step, the [`RecordingInfo`]
/// (`softgrip` metadata: the scene file's text, every fingertip's law, `dt`, ...) when it is
/// created and the [`RunSummary`] when the run finishes.
///
/// The [`Recorder`] runs on its own writer thread: `write` converts the frame into a
/// [`StepRecord`] and queues it; every 16 steps the batch goes over an unbounded channel (it
/// never blocks and never drops a step); the thread encodes and writes it. An error of the
/// writer thread is returned by the next `write` or by `finish`.
///
/// The file is finished by [`StepSink::finish`] (or [`close`](Self::close)), or by `Drop` (a
/// panic that unwinds through the run): both close the channel, let the thread write every
/// queued step and finish the file, and wait for it. A killed process keeps every closed
/// chunk.
pub struct McapSink {
    /// Batches of steps to the writer thread (`None` once finished).
    tx: Option<Sender<Vec<StepRecord>>>,
    /// Steps converted but not yet sent (sent every [`BATCH`] steps, and by `close`).
    batch: Vec<StepRecord>,
    /// Written batches back from the writer thread, to reuse their allocations (in a `Mutex`
    /// only to make the sink `Sync`; always reached through `get_mut`).
    spent: Mutex<Receiver<Vec<StepRecord>>>,
    /// Steps to fill.
    pool: Vec<StepRecord>,
    writer: Option<JoinHandle<Result<RecordingStats, crate::Error>>>,
    /// Set by the writer thread when it stops on an error.
    failed: Arc<AtomicBool>,
    every_n_steps: u64,
    converter: StepConverter,
    report: Arc<Mutex<McapReport>>,
    /// The run's summary, written by the writer thread just before it finishes the file.
    run_summary: Arc<Mutex<Option<RunSummary>>>,
}

/// What the sink did, readable while the sink is owned by the world
/// ([`McapSink::report_handle`]).
#[derive(Debug, Clone, Default)]
pub struct McapReport {
    /// Steps written to the file (by the writer thread).
    pub frames_written: u64,
    /// Wall-clock time the simulation spent in `write` (converting the frame and queueing
    /// it) \[s\].
    pub write_time: Duration,
    /// Wall-clock time the writer thread spent encoding and writing steps (MCAP, chunks) \[s\].
    pub writer_time: Duration,
    /// The counts of the finished file (after `finish`).
    pub stats: Option<RecordingStats>,
}

impl fmt::Debug for McapSink {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("McapSink")
            .field("finished", &self.tx.is_none())
            .field("every_n_steps", &self.every_n_steps)
            .finish()
    }
}

/// Steps sent to the writer thread at once: one wake-up of the thread per batch, not per step
/// (a batch not yet sent is sent by `finish` and `Drop`; a killed process loses it with the
/// open chunk).
const BATCH: usize = 16;

/// Locks the report (a poisoned report is still a report: it only holds counters).
fn lock(report: &Mutex<McapReport>) -> std::sync::MutexGuard<'_, McapReport> {
    report.lock().unwrap_or_else(|e| e.into_inner())
}

/// The writer thread: writes every step it receives until the channel closes, then finishes
/// the file. On an error it sets `failed` and stops (the recorder's `Drop` finishes the file).
fn writer_loop(
    mut recorder: Recorder,
    batches: &Receiver<Vec<StepRecord>>,
    spent: &Sender<Vec<StepRecord>>,
    report: &Mutex<McapReport>,
    failed: &AtomicBool,
    run_summary: &Mutex<Option<RunSummary>>,
) -> Result<RecordingStats, crate::Error> {
    for mut batch in batches {
        let start = Instant::now();
        for step in &mut batch {
            if let Err(e) = recorder.write_step(step) {
                failed.store(true, Ordering::SeqCst);
                return Err(e);
            }
        }
        let elapsed = start.elapsed();
        {
            let mut r = lock(report);
            r.frames_written += batch.len() as u64;
            r.writer_time += elapsed;
        }
        // The simulation may have stopped listening: then the batch is simply dropped.
        let _ = spent.send(batch);
    }
    let summary = run_summary
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .take();
    if let Some(summary) = summary
        && let Err(e) = recorder.write_record(&summary)
    {
        failed.store(true, Ordering::SeqCst);
        return Err(e);
    }
    match recorder.finish() {
        Ok(stats) => {
            lock(report).stats = Some(stats);
            Ok(stats)
        }
        Err(e) => {
            failed.store(true, Ordering::SeqCst);
            Err(e)
        }
    }
}

impl McapSink {
    /// Creates `path` for the scene `info`; `scene_text` is the scene file's text (for the
    /// metadata). Records every `every_n_steps`-th step (0 is taken as 1).
    pub fn create(
        path: impl AsRef<Path>,
        info: &SceneInfo,
        scene_text: &str,
        every_n_steps: u64,
    ) -> Result<Self, crate::Error> {
        Self::with_options(
            path,
            info,
            scene_text,
            every_n_steps,
            &RecorderOptions::default(),
        )
    }

    /// [`create`](Self::create) with the recorder's options (chunk size, compression;
    /// `compression_threads` is ignored: the writer thread compresses).
    pub fn with_options(
        path: impl AsRef<Path>,
        info: &SceneInfo,
        scene_text: &str,
        every_n_steps: u64,
        options: &RecorderOptions,
    ) -> Result<Self, crate::Error> {
        let every_n_steps = every_n_steps.max(1);
        let metadata = RecordingInfo {
            scene: scene_text.to_owned(),
            origin: info.origin.clone(),
            dt: info.dt,
            every_n_steps,
            steps: info.steps,
            law: info.fingertips.iter().map(|t| t.law.clone()).collect(),
            gravity: info.up.vector(info.gravity),
            controllers: info.controllers.clone(),
            ..RecordingInfo::default()
        };
        let path = path.as_ref();
        // The writer thread is already beside the simulation: it compresses the chunks itself
        // (a zstd worker would be a third thread competing for the cores).
        let options = RecorderOptions {
            compression_threads: 0,
            ..options.clone()
        };
        let recorder = Recorder::with_options(path, &metadata, &options)?;
        let report: Arc<Mutex<McapReport>> = Arc::default();
        let failed = Arc::new(AtomicBool::new(false));
        let (tx, batches) = mpsc::channel::<Vec<StepRecord>>();
        let (spent_tx, spent) = mpsc::channel::<Vec<StepRecord>>();
        let run_summary: Arc<Mutex<Option<RunSummary>>> = Arc::default();
        let writer = {
            let report = Arc::clone(&report);
            let failed = Arc::clone(&failed);
            let run_summary = Arc::clone(&run_summary);
            std::thread::Builder::new()
                .name("softgrip-mcap".into())
                .spawn(move || {
                    writer_loop(
                        recorder,
                        &batches,
                        &spent_tx,
                        &report,
                        &failed,
                        &run_summary,
                    )
                })
                .map_err(|source| crate::Error::Io {
                    path: path.to_path_buf(),
                    source,
                })?
        };
        Ok(Self {
            tx: Some(tx),
            batch: Vec::with_capacity(BATCH),
            spent: Mutex::new(spent),
            pool: Vec::new(),
            writer: Some(writer),
            failed,
            every_n_steps,
            converter: StepConverter::new(info),
            report,
            run_summary,
        })
    }

    /// A handle on what the sink did (steps written, time spent, the finished file's counts).
    pub fn report_handle(&self) -> Arc<Mutex<McapReport>> {
        Arc::clone(&self.report)
    }

    /// Records step `step` (steps `n`, `2n`, ... of `every_n_steps = n`).
    pub fn records_step(&self, step: u64) -> bool {
        step.is_multiple_of(self.every_n_steps)
    }

    /// Closes the channel, waits for the writer thread to write every queued step and finish
    /// the file, and returns the file's counts (or the writer's error). Further calls (and
    /// `write`s) return [`McapSinkError::Finished`].
    pub fn close(&mut self) -> Result<RecordingStats, McapSinkError> {
        if let Some(tx) = self.tx.take()
            && !self.batch.is_empty()
        {
            // If the thread is gone, joining it below says why.
            let _ = tx.send(std::mem::take(&mut self.batch));
        }
        let writer = self.writer.take().ok_or(McapSinkError::Finished)?;
        match writer.join() {
            Ok(Ok(stats)) => Ok(stats),
            Ok(Err(e)) => Err(McapSinkError::Record(e)),
            Err(_) => Err(McapSinkError::WriterPanicked),
        }
    }

    /// Queues one frame for the writer thread.
    fn send(&mut self, frame: &StepFrame) -> Result<(), McapSinkError> {
        if self.failed.load(Ordering::SeqCst) {
            return Err(self.close().err().unwrap_or(McapSinkError::Finished));
        }
        let Some(tx) = self.tx.as_ref() else {
            return Err(McapSinkError::Finished);
        };
        if self.pool.is_empty() {
            let spent = self.spent.get_mut().unwrap_or_else(|e| e.into_inner());
            if let Ok(steps) = spent.try_recv() {
                self.pool = steps;
            }
        }
        let mut step = self.pool.pop().unwrap_or_else(|| StepRecord {
            world_frame: WORLD_FRAME.to_owned(),
            ..StepRecord::default()
        });
        self.converter.convert(frame, &mut step);
        self.batch.push(step);
        if self.batch.len() < BATCH {
            return Ok(());
        }
        let full = std::mem::replace(&mut self.batch, Vec::with_capacity(BATCH));
        if tx.send(full).is_err() {
            // The writer thread is gone: its error (or panic) says why.
            return Err(self.close().err().unwrap_or(McapSinkError::Finished));
        }
        Ok(())
    }
}

impl Drop for McapSink {
    /// Finishes the file if `finish` was not called (also while a panic unwinds): every queued
    /// step is written first. Errors are ignored here: call `finish` to see them.
    fn drop(&mut self) {
        if self.writer.is_some() {
            let _ = self.close();
        }
    }
}

impl StepSink for McapSink {
    fn wants(&self, step: u64) -> bool {
        self.records_step(step)
    }

    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        if !self.records_step(frame.step) {
            return Ok(());
        }
        let start = Instant::now();
        let sent = self.send(frame);
        let elapsed = start.elapsed();
        lock(&self.report).write_time += elapsed;
        Ok(sent?)
    }

    fn run_summary(&mut self, summary: &RunSummary) {
        *self
            .run_summary
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner) = Some(summary.clone());
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if self.writer.is_none() {
            return Ok(());
        }
        self.close()?;
        Ok(())
    }
}
