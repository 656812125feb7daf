//! Interrupted recordings: Ctrl-C (SIGINT) finishes the file and the summary says so; a panic
//! inside the step loop (test-only `SOFTGRIP_TEST_PANIC_AT_STEP`) still finishes it; SIGKILL
//! leaves the closed chunks, which `softgrip inspect` recovers and says so.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use softgrip_record::{Recording, topics};

fn wait_for_size(path: &std::path::Path, bytes: u64) {
    let start = Instant::now();
    while std::fs::metadata(path).map(|m| m.len()).unwrap_or(0) < bytes {
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "{} never reached {bytes} bytes",
            path.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// `softgrip run SCENE --out OUT`, not yet started.
fn run_command(scene: &Path, out: &Path) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_softgrip"));
    c.args([
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    c
}

#[test]
fn ctrl_c_finishes_the_recording() {
    let dir = common::temp_dir("sigint");
    let scene = common::long_scene(&dir, 10_000.0);
    let out = dir.join("int.mcap");
    let mut child = run_command(&scene, &out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The first line is printed after the Ctrl-C handler is installed.
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut first = String::new();
    stdout.read_line(&mut first).unwrap();
    assert!(first.starts_with("scene "), "{first}");
    wait_for_size(&out, 100_000);
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let status = child.wait().unwrap();
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut stdout, &mut rest).unwrap();
    assert_eq!(status.code(), Some(130), "{rest}");
    let t: f64 = rest
        .lines()
        .find_map(|l| l.strip_prefix("interrupted at t = "))
        .unwrap_or_else(|| panic!("no `interrupted at t =` in:\n{rest}"))
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(rest.contains("fingertip left_tip:"), "{rest}");
    // Finished: summary and footer, every message readable, up to the interruption.
    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered());
    let last = rec.on_topic(topics::CLOCK).last().unwrap().log_time_ns as f64 * 1e-9;
    assert!(
        (last - t).abs() < 1e-3,
        "last clock {last} vs interrupted at {t}"
    );
    if let Ok(py) = std::env::var("SOFTGRIP_PY") {
        let script = common::root().join("crates/softgrip-record/tests/python/read_recording.py");
        let o = Command::new(py).arg(script).arg(&out).output().unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let last_line = String::from_utf8(o.stdout)
            .unwrap()
            .lines()
            .last()
            .unwrap()
            .to_string();
        assert!(
            last_line.contains(&format!("\"statistics_messages\": {}", rec.messages.len())),
            "{last_line}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_panic_in_the_loop_still_finishes_the_recording() {
    let dir = common::temp_dir("panic");
    let scene = common::long_scene(&dir, 2.0);
    let out = dir.join("panic.mcap");
    let o = run_command(&scene, &out)
        .env("SOFTGRIP_TEST_PANIC_AT_STEP", "50")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(stderr.contains("test panic after step 50"), "{stderr}");
    let rec = Recording::open(&out).unwrap();
    assert!(
        !rec.recovered(),
        "the recorder's Drop finishes the file while the panic unwinds"
    );
    assert_eq!(rec.on_topic(topics::CLOCK).count(), 50);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn sigkill_keeps_the_closed_chunks_and_inspect_says_recovered() {
    let dir = common::temp_dir("sigkill");
    let scene = common::long_scene(&dir, 10_000.0);
    let out = dir.join("killed.mcap");
    let mut child = run_command(&scene, &out)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // A few 512 KiB chunks (~130 KB compressed each) closed.
    wait_for_size(&out, 400_000);
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    let len = std::fs::metadata(&out).unwrap().len();
    let rec = Recording::open(&out).unwrap();
    let r = rec
        .recovery
        .clone()
        .expect("an unfinished file is recovered");
    assert!(r.chunks >= 2, "{r:?}");
    assert_eq!(r.file_len, len);
    assert!(rec.messages.len() > 1000, "{}", rec.messages.len());
    // Whole steps only? Every chunk holds whole messages; the step count per topic may differ
    // by one at the end of the last chunk.
    let clocks = rec.on_topic(topics::CLOCK).count();
    let contacts = rec.on_topic(topics::CONTACTS).count();
    assert!(clocks.abs_diff(contacts) <= 1);

    let o = common::softgrip(&["inspect", out.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let want = format!(
        "recovered: {} chunks, {} bytes of {len}",
        r.chunks, r.bytes_kept
    );
    assert!(stdout.contains(&want), "`{want}` not in:\n{stdout}");
    assert!(
        stdout.contains(&format!("messages: {}", rec.messages.len())),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
