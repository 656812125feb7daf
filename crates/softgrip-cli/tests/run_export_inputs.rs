//! Issue 26, `run`, `export`, `recover`, `plot` and `curve`: what broke on main, one test
//! each. An interrupted `export` left CSVs cut mid-row; a scene through a pipe was read twice
//! and its recorded text was empty; output errors blamed the input file or printed a Rust
//! debug dump (and `recover IN /dev/full --force` would have renamed a file over the device);
//! `recover` kept 0 of 601 messages and exited 0; `curve --level neo-hookean-exact` at its
//! allowed million points ran for a minute; 1e300 printed as a 301-digit number.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use softgrip_record::Recording;

const FILES: [&str; 4] = ["contacts.csv", "wrenches.csv", "poses.csv", "clock.csv"];

fn text(o: &std::process::Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// A slow export (test-only delay per message) of the default recording into `dir`.
fn slow_export(dir: &Path) -> std::process::Child {
    let rec = common::root().join("recordings/default.mcap");
    Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args([
            "export",
            rec.to_str().unwrap(),
            "--csv",
            dir.to_str().unwrap(),
        ])
        .env("SOFTGRIP_TEST_EXPORT_DELAY_US", "3000")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Waits until the temporary outputs of all four tables are in `dir` (the export is writing;
/// each table checks its target when it creates its temporary file, so waiting for the first
/// one only raced the test's own write of `poses.csv` against that check).
fn wait_for_partial(dir: &Path) {
    let start = Instant::now();
    loop {
        let partials = std::fs::read_dir(dir)
            .map(|d| {
                d.flatten()
                    .filter(|e| e.file_name().to_string_lossy().contains(".partial"))
                    .count()
            })
            .unwrap_or(0);
        if partials >= FILES.len() {
            return;
        }
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "no export started"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn interrupted_export_leaves_no_csv_cut_mid_row() {
    for (sig, code) in [("INT", 130), ("TERM", 143), ("HUP", 129)] {
        let dir = common::temp_dir(&format!("export-{sig}"));
        let csv = dir.join("csv");
        std::fs::create_dir_all(&csv).unwrap();
        let child = slow_export(&csv);
        wait_for_partial(&csv);
        std::thread::sleep(Duration::from_millis(200));
        let ok = Command::new("kill")
            .args([&format!("-{sig}"), &child.id().to_string()])
            .status()
            .unwrap();
        assert!(ok.success());
        let o = child.wait_with_output().unwrap();
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(code), "{sig}: {err}");
        assert!(err.contains("nothing written"), "{err}");
        assert_eq!(
            entries(&csv),
            Vec::<String>::new(),
            "{sig}: nothing left behind"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}

#[test]
fn export_output_created_meanwhile_writes_no_file() {
    let dir = common::temp_dir("export-meanwhile");
    let csv = dir.join("csv");
    std::fs::create_dir_all(&csv).unwrap();
    let child = slow_export(&csv);
    wait_for_partial(&csv);
    std::fs::write(csv.join("poses.csv"), "theirs\n").unwrap();
    let o = child.wait_with_output().unwrap();
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("poses.csv: created by another process"),
        "{err}"
    );
    assert_eq!(entries(&csv), ["poses.csv"], "whole files or none");
    assert_eq!(
        std::fs::read_to_string(csv.join("poses.csv")).unwrap(),
        "theirs\n"
    );
    // Uninterrupted: the four files, whole (each line has the header's field count).
    std::fs::remove_file(csv.join("poses.csv")).unwrap();
    let rec = common::root().join("recordings/default.mcap");
    let o = common::softgrip(&[
        "export",
        rec.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", text(&o).1);
    assert_eq!(entries(&csv), {
        let mut f = FILES.map(String::from).to_vec();
        f.sort();
        f
    });
    for f in FILES {
        let body = std::fs::read_to_string(csv.join(f)).unwrap();
        let fields = body.lines().next().unwrap().split(',').count();
        assert!(body.ends_with('\n'), "{f}");
        assert!(body.lines().all(|l| l.split(',').count() == fields), "{f}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn scene_through_a_pipe_is_read_once_and_recorded() {
    let scene = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    let dir = common::temp_dir("pipe-scene");
    for arg in ["-", "/dev/stdin"] {
        let out = dir.join(format!("pipe{}.mcap", arg.len()));
        let mut child = Command::new(env!("CARGO_BIN_EXE_softgrip"))
            .args(["run", arg, "--out", out.to_str().unwrap()])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        child
            .stdin
            .take()
            .unwrap()
            .write_all(scene.as_bytes())
            .unwrap();
        let o = child.wait_with_output().unwrap();
        let (stdout, err) = text(&o);
        assert!(o.status.success(), "{arg}: {err}");
        assert!(stdout.contains("300 steps"), "{stdout}");
        let rec = Recording::open(&out).unwrap();
        assert_eq!(
            rec.softgrip_metadata("scene"),
            Some(scene.as_str()),
            "{arg}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn output_errors_name_the_output_and_the_os_error() {
    let rec = common::root().join("recordings/default.mcap");
    let rec = rec.to_str().unwrap();
    let dir = common::temp_dir("out-errors");
    // A folder that is a file: every command names its output and the OS error, once.
    let bad = "/etc/hostname/x";
    for (args, out) in [
        (
            vec!["recover", rec, "/etc/hostname/x.mcap"],
            "/etc/hostname/x.mcap",
        ),
        (
            vec!["plot", rec, "-o", "/etc/hostname/x.png"],
            "/etc/hostname/x.png",
        ),
        (vec!["export", rec, "--csv", bad], bad),
    ] {
        let o = common::softgrip(&args);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{args:?}: {err}");
        assert!(
            err.starts_with(&format!("error: {out}")) || err.contains(&format!("creating {out}")),
            "{err}"
        );
        assert!(err.contains("Not a directory (os error 20)"), "{err}");
        assert!(
            !err.contains(&format!("error: {rec}")),
            "blames the input: {err}"
        );
        assert!(
            !err.contains("Os {") && !err.contains("Error("),
            "debug dump: {err}"
        );
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
    // A device: never replaced by a rename (a FIFO stands in for /dev/full).
    let fifo = dir.join("fifo.mcap");
    assert!(
        Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .unwrap()
            .success()
    );
    let o = common::softgrip(&["recover", rec, fifo.to_str().unwrap(), "--force"]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("is not a regular file"), "{err}");
    use std::os::unix::fs::FileTypeExt;
    assert!(
        std::fs::metadata(&fifo).unwrap().file_type().is_fifo(),
        "still the FIFO"
    );
    // A recording that fills the disk: the output and ENOSPC.
    if Path::new("/dev/full").exists() {
        let o = common::softgrip(&["run", "--out", "/dev/full", "--force"]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(
            err.contains("/dev/full: No space left on device (os error 28)"),
            "{err}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn recover_that_keeps_nothing_fails_and_extension_records_are_skipped() {
    let dir = common::temp_dir("recover-nothing");
    let zeros = dir.join("zeros.mcap");
    std::fs::write(&zeros, [&b"\x89MCAP0\r\n"[..], &[0u8; 4096]].concat()).unwrap();
    let out = dir.join("out.mcap");
    let o = common::softgrip(&["recover", zeros.to_str().unwrap(), out.to_str().unwrap()]);
    let (stdout, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{stdout}{err}");
    assert!(err.contains("nothing to recover"), "{err}");
    assert!(err.contains("opcode 0x00"), "{err}");
    assert!(!out.exists());
    assert_eq!(entries(&dir), ["zeros.mcap"]);
    // The extension records of another writer's file are skipped: every message kept.
    let ext =
        common::root().join("crates/softgrip-record/tests/data/foreign/extension_records.mcap");
    let o = common::softgrip(&["recover", ext.to_str().unwrap(), out.to_str().unwrap()]);
    let (stdout, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(stdout.starts_with("recovered 40 messages"), "{stdout}");
    assert!(stdout.contains("3 records of unknown opcodes"), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn curve_neo_hookean_exact_at_a_million_points_is_refused_naming_its_cap() {
    let start = Instant::now();
    let o = common::softgrip(&[
        "curve",
        "--level",
        "neo-hookean-exact",
        "--nu",
        "0.45",
        "--x",
        "0:0.4999995:0.0000005",
    ]);
    let (stdout, err) = text(&o);
    assert!(start.elapsed() < Duration::from_secs(20));
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(stdout.is_empty());
    assert!(err.contains("`--x` has 1000000 points"), "{err}");
    assert!(err.contains("at most 20000 per call"), "{err}");
    // At the cap it runs.
    let o = common::softgrip(&[
        "curve",
        "--level",
        "neo-hookean-exact",
        "--nu",
        "0.45",
        "--x",
        "0.0001:0.4:0.00002",
    ]);
    assert!(o.status.success(), "{}", text(&o).1);
    assert_eq!(
        String::from_utf8_lossy(&o.stdout).lines().count(),
        1 + 19996
    );
}

/// The longest run of digits in `s`.
fn digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

/// Found by the CLI fuzz target: `curve`'s x column printed 5e-324 as a 325-digit decimal.
#[test]
fn curve_x_column_is_in_shortest_form() {
    let o = common::softgrip(&[
        "curve",
        "--level",
        "hertz",
        "--nu",
        "0.3",
        "--x",
        "5e-324:1e-300:1e-300",
    ]);
    let (stdout, err) = text(&o);
    assert!(o.status.success(), "{err}");
    let xs: Vec<&str> = (stdout.lines().skip(1))
        .map(|l| l.split(',').next().unwrap())
        .collect();
    assert_eq!(xs, ["5e-324", "1e-300"]);
    let o = common::softgrip(&[
        "curve",
        "--level",
        "hertz",
        "--nu",
        "0.3",
        "--x",
        "0.01:0.03:0.01",
    ]);
    let xs: Vec<String> = (text(&o).0.lines().skip(1))
        .map(|l| l.split(',').next().unwrap().to_string())
        .collect();
    assert_eq!(xs, ["0.01", "0.02", "0.03"], "ordinary values as before");
}

#[test]
fn messages_print_1e300_in_shortest_form() {
    for args in [
        &[
            "curve", "--level", "fit", "--k", "1e300", "--nu", "0.3", "--x", "0:1:0.1",
        ][..],
        &[
            "curve",
            "--level",
            "calibrated",
            "--nu",
            "0.3",
            "--profile",
            "1e300",
        ],
        &[
            "curve",
            "--level",
            "calibrated",
            "--nu",
            "1e300",
            "--x",
            "0:1:0.1",
        ],
        &[
            "curve",
            "--level",
            "auto",
            "--tolerance=-1e-300",
            "--nu",
            "0.3",
            "--x",
            "0:1:0.1",
        ],
        &[
            "curve",
            "--level",
            "calibrated",
            "--nu",
            "0.4",
            "--backing",
            "core",
            "--thickness",
            "1e-300",
            "--x",
            "0:1:0.1",
        ],
        &[
            "curve",
            "--level",
            "hertz",
            "--nu",
            "0.3",
            "--x",
            "0:1e300:1e-300",
        ],
        &[
            "curve",
            "--level",
            "hertz",
            "--nu",
            "0.3",
            "--x",
            "1e300:1:1",
        ],
    ] {
        let o = common::softgrip(args);
        let (stdout, err) = text(&o);
        assert_ne!(o.status.code(), Some(0), "{args:?}");
        assert!(
            digit_run(&err) <= 24 && digit_run(&stdout) <= 24,
            "{args:?}: {err}"
        );
        assert!(
            err.contains("e300") || err.contains("e-300"),
            "{args:?}: {err}"
        );
    }
}
