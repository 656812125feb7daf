//! SIGINT, SIGTERM and SIGHUP in `softgrip run`: the first one only records which signal came
//! (the step loop checks it after every step, leaves the loop, and the recording is finished);
//! a second one of any of them exits at once with 128 + its number (closed chunks stay
//! readable: `softgrip recover` rewrites the file).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};

/// The signals that finish a run.
pub const FINISHING: [i32; 3] = [SIGINT, SIGTERM, SIGHUP];

/// The signal received, 0 for none yet.
#[derive(Debug, Clone)]
pub struct Stop {
    signal: Arc<AtomicUsize>,
}

impl Stop {
    /// Installs the handlers of [`FINISHING`] (call it before anything is written). A handler
    /// that cannot be installed is a warning: that signal then ends the run at once.
    pub fn install() -> Self {
        let signal = Arc::new(AtomicUsize::new(0));
        let seen = Arc::new(AtomicBool::new(false));
        for sig in FINISHING {
            let code = 128 + sig;
            // Registered first, so it runs before `seen` is set by this same signal: only a
            // second signal exits.
            let r = signal_hook::flag::register_conditional_shutdown(sig, code, seen.clone())
                .and_then(|_| signal_hook::flag::register(sig, seen.clone()))
                .and_then(|_| signal_hook::flag::register_usize(sig, signal.clone(), sig as usize));
            if let Err(e) = r {
                eprintln!(
                    "warning: no handler for signal {sig} ({e}); it will not finish the recording"
                );
            }
        }
        Self { signal }
    }

    /// The signal received so far, if any.
    pub fn received(&self) -> Option<i32> {
        match self.signal.load(Ordering::SeqCst) {
            0 => None,
            s => i32::try_from(s).ok(),
        }
    }
}

/// The signal's name (`SIGINT`, ...).
pub fn name(sig: i32) -> String {
    match sig {
        SIGINT => "SIGINT".into(),
        SIGTERM => "SIGTERM".into(),
        SIGHUP => "SIGHUP".into(),
        s => format!("signal {s}"),
    }
}

/// The exit code of a run ended by `sig`: 128 + its number, as shells report it.
pub fn exit_code(sig: i32) -> u8 {
    u8::try_from(128 + sig).unwrap_or(u8::MAX)
}
