//! A run whose simulation diverges (here a valid scene whose stone falls past the step's
//! bound on a position, 1000 km, after ~2500 steps at rapier's 400 m/s cap) exits non-zero
//! with the error on stderr, prints its summary, and leaves a finished recording with every
//! step before the fault.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_record::{Recording, topics};

#[test]
fn a_diverging_run_exits_non_zero_with_its_recording_finished() {
    let dir = common::temp_dir("diverge");
    let scene = common::root().join("crates/softgrip-cli/tests/diverge/falling.toml");
    let out = dir.join("falling.mcap");
    let o = common::softgrip(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stdout}\n{stderr}");
    // The stone falls 400 m a step from the second step on (rapier's speed cap) and leaves
    // 1e6 m in the step after it passed 999 601 m: the step and time are exact.
    let line = stdout
        .lines()
        .find(|l| l.starts_with("diverged at t = "))
        .unwrap_or_else(|| panic!("no `diverged at` line in:\n{stdout}"));
    let step: u64 = line
        .split("(step ")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((2495..=2505).contains(&step), "{line}");
    assert!(
        line.contains("`stone`") && line.contains("position [m]"),
        "{line}"
    );
    assert!(line.contains("after the step"), "{line}");
    assert!(
        stdout.contains("fingertip tip:"),
        "summary printed:\n{stdout}"
    );
    assert!(stdout.contains("real-time factor"), "{stdout}");
    assert!(
        stderr
            .lines()
            .any(|l| l.starts_with("error: the simulation diverged at step")),
        "{stderr}"
    );
    assert!(
        // Every step before the fault, not the failed one (its state is not read out).
        stdout.contains(&format!("recorded {0} of {0} steps", step - 1)),
        "{stdout}"
    );
    // Finished (not recovered), every step before the fault on /clock, the last one at the
    // fault's start time, nothing non-finite in it.
    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered());
    let clock: Vec<_> = rec.on_topic(topics::CLOCK).collect();
    assert_eq!(clock.len() as u64, step - 1);
    let last = clock.last().unwrap().log_time_ns as f64 * 1e-9;
    assert!((last - (step - 1) as f64).abs() < 1e-6, "{last}");
    // The mcap crate's own reader agrees: every message decodes, the same count.
    let bytes = std::fs::read(&out).unwrap();
    let mut n = 0;
    for m in mcap::MessageStream::new(&bytes).unwrap() {
        assert!(!m.unwrap().data.is_empty());
        n += 1;
    }
    assert_eq!(n, rec.messages.len());
    assert!(n as u64 > 2 * (step - 1), "{n} messages");
    std::fs::remove_dir_all(&dir).ok();
}
