//! Issue 26, recordings from other writers: what broke on main. A valid MCAP file without a
//! Statistics record, or without a summary section, and one with lz4 chunks were called
//! "corrupt"; `recover` stopped at an extension record (opcode 0x80) and kept 0 of 601
//! messages, exiting 0; a zero-filled tail was read at 0.4 s per MB. Foreign files come from
//! Python's `mcap` writer: committed small ones (`tests/data/foreign/`, README there says how
//! they were made) and, with `SOFTGRIP_PY`, the whole default recording rewritten in every
//! layout at test time.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};
use std::process::Command;

use softgrip_record::{Error, RecordedMessage, Recording, recover, topics};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn foreign(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/foreign")
        .join(name)
}

fn tempdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softgrip-foreign-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The default recording's first 40 messages without the markers: what the committed foreign
/// files hold.
fn expected_small() -> (Recording, Vec<RecordedMessage>) {
    let rec = Recording::open(root().join("recordings/default.mcap")).unwrap();
    let msgs = (rec.messages.iter())
        .filter(|m| m.topic != topics::MARKERS)
        .take(40)
        .cloned()
        .collect();
    (rec, msgs)
}

/// The offsets of the top-level record heads (after the magic) and their opcodes.
fn heads(b: &[u8]) -> Vec<(usize, u8)> {
    let (mut out, mut at) = (Vec::new(), 8usize);
    while at + 9 <= b.len() {
        let len = u64::from_le_bytes(b[at + 1..at + 9].try_into().unwrap()) as usize;
        out.push((at, b[at]));
        at += 9 + len;
    }
    out
}

#[test]
fn lz4_no_summary_and_no_statistics_files_read_as_written() {
    let (original, want) = expected_small();
    for (name, chunks) in [
        ("lz4_chunks.mcap", 7),
        ("no_summary.mcap", 7),
        ("no_statistics_unchunked.mcap", 0),
        ("extension_records.mcap", 7),
    ] {
        let rec = Recording::open(foreign(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!rec.recovered(), "{name}: a finished file");
        assert_eq!(rec.messages, want, "{name}");
        assert_eq!(rec.metadata, original.metadata, "{name}");
        assert_eq!(rec.chunk_count, chunks, "{name}");
        let bytes = std::fs::read(foreign(name)).unwrap();
        assert_eq!(Recording::from_bytes(&bytes).unwrap(), rec, "{name}");
    }
}

#[test]
fn recover_skips_extension_records_by_their_length_and_reads_lz4() {
    let (_, want) = expected_small();
    let dir = tempdir("recover");
    for (name, unknown) in [("extension_records.mcap", 3), ("lz4_chunks.mcap", 0)] {
        let out = dir.join(name);
        let r = recover(&foreign(name), &out).unwrap();
        assert_eq!(r.messages, 40, "{name}: {r:?}");
        assert_eq!(r.unknown_records, unknown, "{name}");
        assert!(r.skipped.is_empty(), "{name}: {:?}", r.skipped);
        assert_eq!(Recording::open(&out).unwrap().messages, want, "{name}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Found by the fuzz target: a stray data-end record (a damaged opcode) before more chunks made
/// `recover` stop there and keep 14 of the 40 messages the reader read.
#[test]
fn recover_reads_past_a_stray_data_end_record() {
    let b = std::fs::read(foreign("no_summary.mcap")).unwrap();
    let chunk_end = heads(&b)
        .iter()
        .find(|(_, op)| *op == 0x06)
        .map(|(at, _)| at + 9 + u64::from_le_bytes(b[at + 1..at + 9].try_into().unwrap()) as usize)
        .unwrap();
    let stray = [&[0x0fu8][..], &4u64.to_le_bytes(), &[0u8; 4]].concat();
    let damaged = [&b[..chunk_end], &stray, &b[chunk_end..]].concat();
    let dir = tempdir("stray");
    std::fs::write(dir.join("in.mcap"), &damaged).unwrap();
    let r = recover(&dir.join("in.mcap"), &dir.join("out.mcap")).unwrap();
    assert_eq!(r.messages, 40, "{r:?}");
    let read = Recording::open(dir.join("out.mcap")).unwrap();
    assert_eq!(read.messages, expected_small().1);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn zero_filled_tail_stops_at_once() {
    // A killed writer's file whose blocks were allocated but never written: the no-summary
    // file cut before its data-end record, then 4 MiB of zeros.
    let b = std::fs::read(foreign("no_summary.mcap")).unwrap();
    let (cut, _) = *heads(&b).iter().find(|(_, op)| *op == 0x0f).unwrap();
    let mut zeros = b[..cut].to_vec();
    zeros.resize(cut + (4 << 20), 0);
    let dir = tempdir("zeros");
    let path = dir.join("zeros.mcap");
    std::fs::write(&path, &zeros).unwrap();
    let start = std::time::Instant::now();
    let rec = Recording::open(&path).unwrap();
    eprintln!(
        "zero tail of 4 MiB: Recording::open took {:?}",
        start.elapsed()
    );
    let recovery = rec.recovery.as_ref().unwrap();
    assert_eq!(recovery.bytes_kept, cut as u64);
    assert!(
        recovery.stopped_because.contains("opcode 0x00")
            && recovery
                .stopped_because
                .contains(&format!("{} bytes", 4 << 20)),
        "{}",
        recovery.stopped_because
    );
    assert_eq!(rec.messages, expected_small().1);
    let start = std::time::Instant::now();
    let r = recover(&path, &dir.join("fixed.mcap")).unwrap();
    eprintln!("zero tail of 4 MiB: recover took {:?}", start.elapsed());
    assert_eq!(r.messages, 40);
    assert_eq!(
        r.bytes_read, cut as u64,
        "read no further than the first zero record"
    );
    assert!(
        r.skipped.iter().any(|s| s.contains("opcode 0x00")),
        "{:?}",
        r.skipped
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn recover_that_keeps_nothing_is_an_error_and_writes_no_file() {
    let dir = tempdir("nothing");
    for (name, bytes) in [
        ("zeros.mcap", [mcap_magic(), vec![0u8; 1 << 20]].concat()),
        (
            "only_extensions.mcap",
            [mcap_magic(), vec![0x80, 1, 0, 0, 0, 0, 0, 0, 0, 7]].concat(),
        ),
    ] {
        let input = dir.join(name);
        std::fs::write(&input, bytes).unwrap();
        let out = dir.join(format!("out-{name}"));
        let e = recover(&input, &out).unwrap_err();
        assert!(matches!(e, Error::NothingRecovered { .. }), "{name}: {e}");
        assert!(e.to_string().starts_with("nothing to recover"), "{e}");
        assert!(!out.exists(), "{name}: no output");
    }
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(left.len(), 2, "no temporary file left behind");
    std::fs::remove_dir_all(&dir).ok();
}

fn mcap_magic() -> Vec<u8> {
    b"\x89MCAP0\r\n".to_vec()
}

/// `SOFTGRIP_PY`, the Python with `mcap`, `lz4` and `zstandard` (`bash .ci/python-venv.sh`).
fn python() -> String {
    std::env::var("SOFTGRIP_PY").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PY is not set: it must name a Python with the PyPI packages `mcap`, `lz4` \
             and `zstandard`; `bash .ci/python-venv.sh` makes one and prints its path"
        )
    })
}

#[test]
fn python_writer_layouts_of_the_whole_recording_read_like_the_original() {
    let original = Recording::open(root().join("recordings/default.mcap")).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/python/write_foreign.py");
    let dir = tempdir("layouts");
    for (k, options) in [
        &["compression=lz4"][..],
        &["compression=zstd", "statistics=0"],
        &["compression=none", "summary=0"],
        &["compression=lz4", "summary=0", "chunk_size=8192"],
        &["chunked=0", "summary=0"],
        &["chunked=0"],
    ]
    .iter()
    .enumerate()
    {
        let out = dir.join(format!("layout{k}.mcap"));
        let o = Command::new(python())
            .arg(&script)
            .arg(root().join("recordings/default.mcap"))
            .arg(&out)
            .args(*options)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let rec = Recording::open(&out).unwrap_or_else(|e| panic!("{options:?}: {e}"));
        assert!(!rec.recovered(), "{options:?}");
        assert_eq!(rec.messages.len(), 601, "{options:?}");
        assert_eq!(rec.messages, original.messages, "{options:?}");
        assert_eq!(rec.metadata, original.metadata, "{options:?}");
        let fixed = dir.join(format!("fixed{k}.mcap"));
        assert_eq!(recover(&out, &fixed).unwrap().messages, 601, "{options:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
