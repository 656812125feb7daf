//! Issue 26, `softgrip sweep` as a user runs it: what broke on main, one test each. Ctrl-C,
//! SIGTERM and SIGHUP lost every finished row; `--out F --force` overwrote the base scene's
//! measured curve; `--out` was checked only before the trials, so a file created meanwhile was
//! replaced; `--threads 100000` spent minutes spawning threads.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use softgrip_sweep::{ResultsTable, Value};

/// A sweep of `n` trials of the sweep tests' short grasp (`gripper.hold` varied), each
/// recording to `runs/` (whose files say which trials have started), in `dir`.
fn long_sweep(dir: &Path, n: usize) -> PathBuf {
    let data = common::root().join("crates/softgrip-sweep/tests/data");
    std::fs::copy(data.join("grasp.toml"), dir.join("grasp.toml")).unwrap();
    let holds: Vec<String> = (0..n)
        .map(|k| format!("{:.3}", 0.1 + 0.001 * k as f64))
        .collect();
    let text = format!(
        "scene = \"grasp.toml\"\nmcap_dir = \"runs\"\n[[vary]]\nfield = \"gripper.hold\"\nvalues = [{}]\n",
        holds.join(", ")
    );
    let path = dir.join("long.toml");
    std::fs::write(&path, text).unwrap();
    path
}

fn spawn(args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap()
}

/// Waits until `path` exists (the trial recording it names has started).
fn wait_for(path: &Path) {
    let start = Instant::now();
    while !path.exists() {
        assert!(
            start.elapsed() < Duration::from_secs(300),
            "{}",
            path.display()
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

fn kill(pid: u32, sig: &str) {
    let ok = Command::new("kill")
        .args([&format!("-{sig}"), &pid.to_string()])
        .status()
        .unwrap();
    assert!(ok.success());
}

/// No temporary output (`.NAME.XXXXXX.partial.EXT`) is left in `dir`.
fn no_partial(dir: &Path) {
    for e in std::fs::read_dir(dir).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(!name.contains(".partial"), "left behind: {name}");
    }
}

fn signal_keeps_finished_rows(sig: &str, code: i32) {
    let dir = common::temp_dir(&format!("sweep-sig{sig}"));
    let sweep = long_sweep(&dir, 400);
    let out = dir.join("results.csv");
    let child = spawn(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "1",
    ]);
    // One thread: once trial 3 has started, trials 0, 1 and 2 have finished.
    wait_for(&dir.join("runs/trial-000003.mcap"));
    kill(child.id(), sig);
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(code), "{sig}: {err}");
    assert!(err.contains(&format!("stopped by SIG{sig}")), "{err}");
    let table = ResultsTable::read_csv(&out).unwrap();
    let n = table.rows.len();
    assert!((4..400).contains(&n), "{sig}: {n} rows");
    assert!(err.contains(&format!("{n} of 400 trials")), "{err}");
    for (k, row) in table.rows.iter().enumerate() {
        assert_eq!(row.trial, k as u64, "one thread: trials 0..{n} in order");
        let hold: f64 = format!("{:.3}", 0.1 + 0.001 * k as f64).parse().unwrap();
        assert_eq!(row.values, [Value::Float(hold)]);
        assert!(row.outcome.is_ok(), "{:?}", row.outcome);
    }
    no_partial(&dir);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn sigint_during_a_sweep_writes_the_finished_rows_exit_130() {
    signal_keeps_finished_rows("INT", 130);
}

#[test]
fn sigterm_during_a_sweep_writes_the_finished_rows_exit_143() {
    signal_keeps_finished_rows("TERM", 143);
}

#[test]
fn sighup_during_a_sweep_writes_the_finished_rows_exit_129() {
    signal_keeps_finished_rows("HUP", 129);
}

#[test]
fn out_force_over_the_base_scene_curve_is_refused() {
    let dir = common::temp_dir("sweep-over-input");
    let scene =
        std::fs::read_to_string(common::root().join("crates/softgrip-sweep/tests/data/grasp.toml"))
            .unwrap();
    let scene = scene.replacen(
        "[[fingertip]]\n",
        "[[fingertip]]\nlevel = { tabulated = \"tip.csv\" }\n",
        1,
    );
    std::fs::write(dir.join("base.toml"), scene).unwrap();
    let curve = "delta_m,force_n\n0.0005,0.4\n0.001,1.2\n0.002,3.5\n0.003,6.8\n0.004,11.0\n";
    std::fs::write(dir.join("tip.csv"), curve).unwrap();
    std::fs::write(dir.join("s.toml"), "scene = \"base.toml\"\n").unwrap();
    std::os::unix::fs::symlink(dir.join("tip.csv"), dir.join("alias.csv")).unwrap();
    for out in ["tip.csv", "alias.csv", "./tip.csv"] {
        let target = dir.join(out);
        let o = common::softgrip(&[
            "sweep",
            dir.join("s.toml").to_str().unwrap(),
            "--out",
            target.to_str().unwrap(),
            "--force",
        ]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{out}: {err}");
        assert!(
            err.contains("refusing to write the output over the input"),
            "{err}"
        );
        assert_eq!(std::fs::read_to_string(dir.join("tip.csv")).unwrap(), curve);
    }
    no_partial(&dir);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn out_created_meanwhile_is_not_replaced_and_the_results_are_kept() {
    let dir = common::temp_dir("sweep-meanwhile");
    let sweep = long_sweep(&dir, 4);
    let out = dir.join("results.csv");
    let child = spawn(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--threads",
        "1",
    ]);
    wait_for(&dir.join("runs/trial-000000.mcap"));
    std::fs::write(&out, "another sweep's results\n").unwrap();
    let o = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("created by another process"), "{err}");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "another sweep's results\n"
    );
    let kept = err.split("the output is kept in ").nth(1).unwrap().trim();
    let table = ResultsTable::read_csv(Path::new(kept)).unwrap();
    assert_eq!(table.rows.len(), 4);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn threads_100000_is_a_range_error_at_once() {
    let sweep = common::root().join("crates/softgrip-sweep/tests/data/grasp_sweep.toml");
    let start = Instant::now();
    let o = common::softgrip(&["sweep", sweep.to_str().unwrap(), "--threads", "100000"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        start.elapsed() < Duration::from_secs(20),
        "no thread started"
    );
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("`threads` must be 0 (one per core) or in 1..="),
        "{err}"
    );
    assert!(err.trim_end().ends_with("got 100000"), "{err}");
    assert!(o.stdout.is_empty(), "no results");
}
