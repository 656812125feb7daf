//! `softgrip recover IN OUT` (issue 11): after SIGKILL mid-chunk (the open chunk's length field
//! is 2^64 - 1) Python's documented reader (`mcap_ros2.reader.read_ros2_messages`) got 0
//! messages from the file. The recovered file is finished and indexed: the Python reader
//! decodes every message softgrip reads from it, which are at least those of the closed chunks
//! plus what the unfinished chunk still holds.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use softgrip_record::Recording;

#[test]
fn sigkilled_recording_is_recovered_for_the_python_reader() {
    let dir = common::temp_dir("recover");
    let scene = common::long_scene(&dir, 10_000.0);
    let killed = dir.join("killed.mcap");
    let mut child = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args([
            "run",
            scene.to_str().unwrap(),
            "--out",
            killed.to_str().unwrap(),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while std::fs::metadata(&killed).map(|m| m.len()).unwrap_or(0) < 300_000 {
        assert!(start.elapsed() < Duration::from_secs(120));
        std::thread::sleep(Duration::from_millis(10));
    }
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    let bytes = std::fs::read(&killed).unwrap();
    let as_is = Recording::open(&killed).unwrap();
    let closed = as_is.messages.len();
    assert!(as_is.recovered());

    let fixed = dir.join("fixed.mcap");
    let o = common::softgrip(&["recover", killed.to_str().unwrap(), fixed.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    println!("{stdout}");
    let rec = Recording::open(&fixed).unwrap();
    assert!(!rec.recovered(), "the output is a finished file");
    assert!(
        rec.messages.len() >= closed,
        "{} < {closed}",
        rec.messages.len()
    );
    assert!(stdout.contains(&format!("recovered {} messages", rec.messages.len())));
    // The killed file's last chunk was open (a placeholder length) if the kill hit one.
    let open_chunk = bytes
        .windows(9)
        .any(|w| w[0] == 0x06 && w[1..] == [0xff; 8]);
    if open_chunk {
        assert!(stdout.contains("unfinished chunk"), "{stdout}");
    }
    // Python's default reader, which the project did not write.
    let script = common::root().join("crates/softgrip-record/tests/python/read_recording.py");
    let o = Command::new(common::python())
        .arg(script)
        .arg(&fixed)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = String::from_utf8(o.stdout).unwrap();
    let decoded = out.lines().filter(|l| l.starts_with("{\"topic\"")).count();
    assert_eq!(decoded, rec.messages.len(), "python decoded every message");
    let last = out.lines().last().unwrap();
    assert!(
        last.contains(&format!("\"statistics_messages\": {}", rec.messages.len())),
        "{last}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn recovering_an_intact_recording_keeps_every_message() {
    let dir = common::temp_dir("recover-intact");
    let input = common::root().join("recordings/default.mcap");
    let out = dir.join("copy.mcap");
    let o = common::softgrip(&["recover", input.to_str().unwrap(), out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let a = Recording::open(&input).unwrap();
    let b = Recording::open(&out).unwrap();
    assert_eq!(a.messages, b.messages);
    assert_eq!(a.metadata, b.metadata);
    std::fs::remove_dir_all(&dir).ok();
}
