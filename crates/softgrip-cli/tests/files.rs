//! Regression tests of issue 11's file defects: `softgrip run s.toml --out s.toml` overwrote
//! the scene with MCAP (exit 0); existing outputs were overwritten silently (now every command
//! that writes refuses without `--force`); `/dev/zero` as a recording was read until memory
//! ran out; a flipped byte in the summary or data section passed inspect/export/plot (their
//! CRCs were present but not checked).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::Path;
use std::time::{Duration, Instant};

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let o = common::softgrip(args);
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn run_out_over_the_scene_is_refused() {
    let dir = common::temp_dir("overinput");
    let scene = dir.join("s.toml");
    std::fs::copy(common::root().join("scenes/default.toml"), &scene).unwrap();
    let before = std::fs::read(&scene).unwrap();
    for out in [scene.clone(), dir.join(".").join("s.toml")] {
        let (code, _, err) = run(&["run", s(&scene), "--out", s(&out), "--force"]);
        assert_eq!(code, Some(1), "{err}");
        assert!(err.contains("over the input"), "{err}");
    }
    assert_eq!(
        std::fs::read(&scene).unwrap(),
        before,
        "the scene is untouched"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn existing_outputs_are_not_overwritten_without_force() {
    let dir = common::temp_dir("force");
    let rec = dir.join("r.mcap");
    let (code, _, err) = run(&["run", "--out", s(&rec)]);
    assert_eq!(code, Some(0), "{err}");
    let png = dir.join("f.png");
    let csv = dir.join("csv");
    let fixed = dir.join("fixed.mcap");
    std::fs::write(&png, "keep").unwrap();
    std::fs::create_dir_all(&csv).unwrap();
    std::fs::write(csv.join("clock.csv"), "keep").unwrap();
    std::fs::write(&fixed, "keep").unwrap();
    let other = dir.join("other.mcap");
    std::fs::write(&other, "keep").unwrap();
    let cases: [(Vec<&str>, &Path); 4] = [
        (vec!["run", "--out", s(&other)], &other),
        (vec!["plot", s(&rec), "-o", s(&png)], &png),
        (
            vec!["export", s(&rec), "--csv", s(&csv)],
            &csv.join("clock.csv"),
        ),
        (vec!["recover", s(&rec), s(&fixed)], &fixed),
    ];
    for (args, target) in &cases {
        let (code, _, err) = run(args);
        assert_eq!(code, Some(1), "{args:?}: {err}");
        assert!(err.contains("exists; pass --force"), "{args:?}: {err}");
        assert_eq!(std::fs::read_to_string(target).unwrap(), "keep");
        let mut forced = args.clone();
        forced.push("--force");
        let (code, _, err) = run(&forced);
        assert_eq!(code, Some(0), "{forced:?}: {err}");
        assert_ne!(std::fs::read(target).unwrap(), b"keep");
    }
    // Never over the input, even with --force.
    let (code, _, err) = run(&["recover", s(&rec), s(&rec), "--force"]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("over the input"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn dev_zero_as_a_recording_is_refused_at_once() {
    let start = Instant::now();
    for cmd in ["inspect", "export", "plot"] {
        let dir = common::temp_dir(&format!("zero-{cmd}"));
        let out = dir.join("o.png");
        let args: Vec<&str> = match cmd {
            "inspect" => vec!["inspect", "/dev/zero"],
            "export" => vec!["export", "/dev/zero", "--csv", s(&dir)],
            _ => vec!["plot", "/dev/zero", "-o", s(&out)],
        };
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(1), "{err}");
        assert!(err.contains("not an MCAP file"), "{err}");
        std::fs::remove_dir_all(&dir).ok();
    }
    assert!(start.elapsed() < Duration::from_secs(30));
}

/// The byte offset of the summary section of a finished file (from its footer).
fn summary_start(bytes: &[u8]) -> usize {
    let footer = bytes.len() - 8 - 29;
    assert_eq!(bytes[footer], 0x02, "footer opcode");
    u64::from_le_bytes(bytes[footer + 9..footer + 17].try_into().unwrap()) as usize
}

fn damaged_copy(dir: &Path, name: &str, at: usize) -> std::path::PathBuf {
    let mut bytes = std::fs::read(common::root().join("recordings/default.mcap")).unwrap();
    bytes[at] ^= 0x20;
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

#[test]
fn flipped_byte_in_the_summary_section_is_found_and_named() {
    let dir = common::temp_dir("summarycrc");
    let bytes = std::fs::read(common::root().join("recordings/default.mcap")).unwrap();
    let start = summary_start(&bytes);
    // The first summary record is a schema: opcode, length, id (2), name length (4), name.
    assert_eq!(bytes[start], 0x03);
    let bad = damaged_copy(&dir, "summary.mcap", start + 9 + 2 + 4 + 3);
    let png = dir.join("f.png");
    let csv = dir.join("csv");
    for args in [
        vec!["inspect", s(&bad)],
        vec!["export", s(&bad), "--csv", s(&csv)],
        vec!["plot", s(&bad), "-o", s(&png)],
    ] {
        let (code, _, err) = run(&args);
        assert_eq!(code, Some(1), "{args:?}: {err}");
        assert!(
            err.contains("Summary section CRC failed"),
            "{args:?}: {err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn flipped_byte_in_the_data_section_outside_chunks_is_found_and_named() {
    let dir = common::temp_dir("datacrc");
    let bytes = std::fs::read(common::root().join("recordings/default.mcap")).unwrap();
    // The scene's text in the `softgrip` metadata record (not in a chunk: no chunk CRC).
    let at = bytes.windows(8).position(|w| w == b"[[body]]").unwrap();
    assert!(at < summary_start(&bytes));
    let bad = damaged_copy(&dir, "data.mcap", at + 3);
    let (code, _, err) = run(&["inspect", s(&bad)]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("Data section CRC failed"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}
