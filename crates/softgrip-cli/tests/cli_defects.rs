//! Regression tests of issue 11's command-line defects, each named after what broke:
//! `--realtime-factor 1e-300` panicked (Duration), `softgrip run | head -1` panicked on the
//! broken pipe, `dt = 1e308` printed `real-time factor inf`, error sources were printed twice
//! ("Is a directory (os error 21): Is a directory (os error 21)"), `plot -o DIR` printed a raw
//! `ImageError(Unsupported...)`, and micro scenes printed "peak force 0.0000 N".

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::io::Read;
use std::process::{Command, Stdio};

use softgrip_record::Recording;

fn text(o: &std::process::Output) -> (String, String) {
    (
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn realtime_factor_1e_300_is_a_range_error_not_a_panic() {
    for bad in ["1e-300", "-1", "inf", "NaN", "1e9"] {
        let o = common::softgrip(&["run", &format!("--realtime-factor={bad}")]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(2), "{bad}: {err}");
        assert!(!err.contains("panicked"), "{bad}: {err}");
        assert!(
            err.contains("--realtime-factor") && err.contains("from 0.001 to 1000"),
            "{bad}: {err}"
        );
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
}

#[test]
fn broken_pipe_on_stdout_does_not_panic_and_finishes_the_recording() {
    let dir = common::temp_dir("pipe");
    let out = dir.join("pipe.mcap");
    let mut child = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["run", "--out", out.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // `| head -1`: read the first line, then close the pipe.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    let status = child.wait().unwrap();
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(status.code(), Some(0), "{err}");
    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered());
    assert!(
        rec.run_summary().unwrap().is_some(),
        "finished with its summary"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn huge_dt_never_prints_inf_or_nan() {
    let dir = common::temp_dir("hugedt");
    let text_ = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    let scene = dir.join("huge.toml");
    let t = text_.replace("dt = 0.016666666666666666", "dt = 1e308");
    assert_ne!(t, text_);
    std::fs::write(&scene, t.replace("duration = 5.0 ", "duration = 1e308 ")).unwrap();
    let o = common::softgrip(&["run", scene.to_str().unwrap()]);
    let (out, err) = text(&o);
    // Either refused (a step cap) or run: never inf or NaN in what is printed.
    for s in [&out, &err] {
        let lower = s.to_lowercase();
        assert!(
            !lower.contains("inf") && !lower.contains("nan"),
            "{out}\n{err}"
        );
    }
    assert!(!err.contains("panicked"), "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn doubled_error_source_is_printed_once() {
    let dir = common::temp_dir("doubled");
    let o = common::softgrip(&["run", dir.to_str().unwrap()]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.matches("os error 21").count(), 1, "{err}");
    let o = common::softgrip(&["inspect", dir.to_str().unwrap()]);
    let (_, err) = text(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.matches("directory").count() <= 1, "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn plot_o_dir_is_a_clear_error_not_an_image_error() {
    let dir = common::temp_dir("plotdir");
    let rec = common::root().join("recordings/default.mcap");
    for (out, want) in [
        (dir.clone(), "is a directory"),
        (dir.join("fig.jpg"), "ending in .png"),
        (dir.join("fig"), "ending in .png"),
    ] {
        let o = common::softgrip(&["plot", rec.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        let (_, err) = text(&o);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(!err.contains("ImageError"), "{err}");
        assert!(err.contains(want), "`{want}` not in {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn micro_scene_peak_force_has_significant_digits_and_units() {
    let scene = common::root().join("scenes/cell_live_hmsc.toml");
    let o = common::softgrip(&["run", scene.to_str().unwrap()]);
    let (out, err) = text(&o);
    assert!(o.status.success(), "{err}");
    assert!(!out.contains("0.0000 N"), "{out}");
    let line = out.lines().find(|l| l.starts_with("fingertip ")).unwrap();
    // "peak force 12.34 µN": four significant digits and a prefixed unit.
    let rest = &line[line.find("peak force ").unwrap() + 11..];
    let mut words = rest.split_whitespace();
    let value: f64 = words.next().unwrap().parse().unwrap();
    let unit = words.next().unwrap().trim_end_matches(',');
    assert!((1.0..1000.0).contains(&value), "{line}");
    assert!(["µN", "nN", "mN"].contains(&unit), "{line}");
}
