//! Regression tests of issue 11's signal defects: SIGTERM and SIGHUP left the recording
//! unfinished (only SIGINT was handled), and a SIGINT before the handler was installed (the
//! first ~30 ms) left no file. Each signal is sent to a real `softgrip run` process; each
//! finishes the file (summary, footer, every step up to the signal) and exits 128 + signal.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::io::{BufRead, BufReader, Read};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use softgrip_record::{Recording, topics};

fn kill(pid: u32, sig: &str) {
    let ok = Command::new("kill")
        .args([&format!("-{sig}"), &pid.to_string()])
        .status()
        .unwrap();
    assert!(ok.success());
}

/// Whether the process's handler of signal `n` is installed (`SigCgt` in /proc).
fn caught(pid: u32, n: u32) -> bool {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("SigCgt:"))
        .and_then(|m| u64::from_str_radix(m.trim(), 16).ok())
        .is_some_and(|mask| mask & (1 << (n - 1)) != 0)
}

/// Runs a long scene, sends `sig` once the recording has grown, and checks the finished file.
fn signal_finishes(sig: &str, code: i32) {
    let dir = common::temp_dir(&format!("sig{sig}"));
    let scene = common::long_scene(&dir, 10_000.0);
    let out = dir.join("s.mcap");
    let mut child = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut first = String::new();
    stdout.read_line(&mut first).unwrap();
    let start = Instant::now();
    while std::fs::metadata(&out).map(|m| m.len()).unwrap_or(0) < 50_000 {
        assert!(start.elapsed() < Duration::from_secs(120));
        std::thread::sleep(Duration::from_millis(20));
    }
    kill(child.id(), sig);
    let status = child.wait().unwrap();
    let mut rest = String::new();
    stdout.read_to_string(&mut rest).unwrap();
    assert_eq!(status.code(), Some(code), "{sig}: {rest}");
    assert!(rest.contains(&format!("by SIG{sig}")), "{rest}");
    let steps: u64 = rest
        .split("(step ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .unwrap()
        .parse()
        .unwrap();
    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered(), "{sig}: the file is finished");
    let summary = rec
        .run_summary()
        .unwrap()
        .expect("the run summary is written");
    assert_eq!(summary.steps, steps);
    // Nothing recorded is lost: every step (every_n_steps = 1) up to the signal.
    assert_eq!(rec.on_topic(topics::CLOCK).count() as u64, steps, "{sig}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn sigint_finishes_the_recording_exit_130() {
    signal_finishes("INT", 130);
}

#[test]
fn sigterm_finishes_the_recording_exit_143() {
    signal_finishes("TERM", 143);
}

#[test]
fn sighup_finishes_the_recording_exit_129() {
    signal_finishes("HUP", 129);
}

/// The handlers are in place before the scene is read (and so before the first step and
/// before the output exists): a signal during a slow start (test-only
/// `SOFTGRIP_TEST_SLOW_START_MS`) still gives a finished file, of zero steps.
#[test]
fn signal_before_the_first_step_still_finishes_the_recording() {
    let dir = common::temp_dir("sigearly");
    let out = dir.join("early.mcap");
    let mut child = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["run", "--out", out.to_str().unwrap()])
        .env("SOFTGRIP_TEST_SLOW_START_MS", "3000")
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let pid = child.id();
    let start = Instant::now();
    while !(caught(pid, 2) && caught(pid, 15) && caught(pid, 1)) {
        assert!(
            start.elapsed() < Duration::from_secs(2),
            "no handlers installed"
        );
        std::thread::sleep(Duration::from_millis(1));
    }
    assert!(!Path::new(&out).exists(), "handlers come before the output");
    kill(pid, "TERM");
    let status = child.wait().unwrap();
    let mut text = String::new();
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut text)
        .unwrap();
    assert_eq!(status.code(), Some(143), "{text}");
    assert!(text.contains("(step 0 of 300) by SIGTERM"), "{text}");
    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered());
    assert_eq!(rec.run_summary().unwrap().unwrap().steps, 0);
    std::fs::remove_dir_all(&dir).ok();
}
