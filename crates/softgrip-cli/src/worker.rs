//! A background thread that runs until it is told to stop and is joined when its owner ends
//! ([`Worker`]): the ROS 2 bridges' threads (joint commands, gripper actions).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::thread::JoinHandle;

use anyhow::{Context, Result};

/// The flag a worker's body polls: set when the owner stops it.
#[derive(Debug, Clone)]
pub struct StopFlag(Arc<AtomicBool>);

impl StopFlag {
    /// The owner asked the thread to stop.
    pub fn stopped(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// A named thread returning `Result<T>`, stopped (flag set) and joined by [`finish`](Self::finish)
/// or, if its owner is dropped without finishing, by `Drop`.
pub struct Worker<T> {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<Result<T>>>,
    name: &'static str,
}

impl<T: Default + Send + 'static> Worker<T> {
    /// Starts `body` on a thread called `name`. `body` gets the stop flag and a channel on
    /// which it reports once it is ready (or why it cannot start); this returns after that
    /// report, with its error if the body could not start (`what` says what was being
    /// started, in the error).
    pub fn start<F>(name: &'static str, what: &str, body: F) -> Result<Self>
    where
        F: FnOnce(StopFlag, mpsc::Sender<Result<()>>) -> Result<T> + Send + 'static,
    {
        let stop = Arc::new(AtomicBool::new(false));
        let (ready_tx, ready_rx) = mpsc::channel::<Result<()>>();
        let flag = StopFlag(Arc::clone(&stop));
        let thread = std::thread::Builder::new()
            .name(name.into())
            .spawn(move || body(flag, ready_tx))
            .with_context(|| format!("starting the {name} thread"))?;
        let worker = Self {
            stop,
            thread: Some(thread),
            name,
        };
        ready_rx
            .recv()
            .with_context(|| format!("the {name} thread ended at its start"))?
            .with_context(|| what.to_owned())?;
        Ok(worker)
    }

    /// Stops the thread and returns what it returned.
    pub fn finish(mut self) -> Result<T> {
        self.stop.store(true, Ordering::Relaxed);
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(out)) => out,
            Some(Err(_)) => Err(anyhow::anyhow!("the {} thread panicked", self.name)),
            None => Ok(T::default()),
        }
    }
}

impl<T> Drop for Worker<T> {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_worker_runs_until_finished_and_returns_its_value() {
        let w = Worker::start("count", "counting", |stop, ready| {
            ready.send(Ok(())).ok();
            // One count before the first look at `stop`: `finish` may stop the worker before
            // its loop starts (it did on a loaded CI machine), and the value must still come back.
            let mut n = 1u64;
            while !stop.stopped() {
                n += 1;
                std::thread::yield_now();
            }
            Ok(n)
        })
        .unwrap();
        assert!(w.finish().unwrap() > 0);
    }

    #[test]
    fn a_body_that_cannot_start_is_an_error_naming_what_was_started() {
        let e = Worker::<u64>::start("fail", "subscribing to /x", |_, ready| {
            ready.send(Err(anyhow::anyhow!("no network"))).ok();
            Ok(0)
        })
        .err()
        .unwrap();
        let text = format!("{e:#}");
        assert!(
            text.contains("subscribing to /x") && text.contains("no network"),
            "{text}"
        );
    }

    #[test]
    fn dropping_a_worker_stops_and_joins_it() {
        let done = Arc::new(AtomicBool::new(false));
        let seen = Arc::clone(&done);
        let w = Worker::start("drop", "dropping", move |stop, ready| {
            ready.send(Ok(())).ok();
            while !stop.stopped() {
                std::thread::yield_now();
            }
            seen.store(true, Ordering::Relaxed);
            Ok(())
        })
        .unwrap();
        drop(w);
        assert!(done.load(Ordering::Relaxed), "the thread had not ended");
    }
}
