//! Damaged files given to `inspect`, `export` and `plot`: a missing file, an empty file, a file
//! that is not MCAP, one cut inside the magic, and a finished recording with a damaged chunk
//! each give one line on stderr (`error: FILE: ...`) and exit code 1, never a panic.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

fn check(file: &std::path::Path, dir: &std::path::Path, want: &str) {
    let f = file.to_str().unwrap();
    let csv = dir.join("csv");
    let png = dir.join("fig.png");
    for args in [
        vec!["inspect", f],
        vec!["export", f, "--csv", csv.to_str().unwrap()],
        vec!["plot", f, "-o", png.to_str().unwrap()],
    ] {
        let o = common::softgrip(&args);
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert_eq!(
            stderr.trim_end().lines().count(),
            1,
            "{args:?}: not one line: {stderr}"
        );
        assert!(
            stderr.starts_with("error: ") && stderr.contains(f),
            "{args:?}: {stderr}"
        );
        assert!(stderr.contains(want), "{args:?}: `{want}` not in {stderr}");
    }
}

#[test]
fn damaged_files_get_one_line_and_exit_1() {
    let dir = common::temp_dir("corrupt");
    let good = common::root().join("recordings/default.mcap");
    let bytes = std::fs::read(&good).unwrap();

    check(&dir.join("missing.mcap"), &dir, "No such file");

    let empty = dir.join("empty.mcap");
    std::fs::write(&empty, b"").unwrap();
    check(&empty, &dir, "not an MCAP file");

    let text = dir.join("text.mcap");
    std::fs::write(&text, "duration = 1.0\n".repeat(20)).unwrap();
    check(&text, &dir, "not an MCAP file: the magic bytes are missing");

    let cut = dir.join("cut.mcap");
    std::fs::write(&cut, &bytes[..5]).unwrap();
    check(&cut, &dir, "not an MCAP file");

    // A finished file with a byte flipped in its (only) chunk's compressed data.
    let mut damaged = bytes.clone();
    let mid = damaged.len() / 2;
    damaged[mid] ^= 0xff;
    let bad = dir.join("damaged.mcap");
    std::fs::write(&bad, &damaged).unwrap();
    check(&bad, &dir, "corrupt MCAP file");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_file_cut_mid_way_is_recovered_not_refused() {
    let dir = common::temp_dir("cut-mid");
    let bytes = std::fs::read(common::root().join("recordings/ecoflex_sphere.mcap")).unwrap();
    let cut = dir.join("cut.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() * 3 / 4]).unwrap();
    let o = common::softgrip(&["inspect", cut.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("recovered: "), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}
