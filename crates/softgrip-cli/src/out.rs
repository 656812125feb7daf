//! Standard output that never panics: a closed pipe (`softgrip run | head -1`) ends the
//! printing, not the program, so a run still finishes its recording.

use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set once stdout could not be written (a closed pipe): nothing more is printed.
static CLOSED: AtomicBool = AtomicBool::new(false);

/// Writes `args` and a newline to stdout; on any error (a closed pipe) stops printing.
pub fn line(args: std::fmt::Arguments<'_>) {
    if CLOSED.load(Ordering::Relaxed) {
        return;
    }
    let mut o = std::io::stdout().lock();
    if o.write_fmt(args).and_then(|()| o.write_all(b"\n")).is_err() {
        CLOSED.store(true, Ordering::Relaxed);
    }
}

/// Flushes stdout, ignoring a closed pipe.
pub fn flush() {
    if std::io::stdout().flush().is_err() {
        CLOSED.store(true, Ordering::Relaxed);
    }
}

/// `println!` that never panics (see [`line()`]).
macro_rules! outln {
    () => { $crate::out::line(format_args!("")) };
    ($($arg:tt)*) => { $crate::out::line(format_args!($($arg)*)) };
}
pub(crate) use outln;

/// Writes `text` as it is to stdout (see [`line()`]).
pub fn text(text: &str) {
    line(format_args!("{}", text.strip_suffix('\n').unwrap_or(text)));
}
