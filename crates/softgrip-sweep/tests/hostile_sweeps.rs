//! Issue 26, sweeps: what broke on main, one test each. `values = [nan, inf]` was accepted and
//! NaN reached the results; a random axis from -1e308 to 1e308 drew the same value every time
//! (`high - low` overflowed); `--threads 100000` spent minutes spawning threads; a signal lost
//! every finished row (the library side: `run_until` stops starting trials and returns the
//! finished rows); outputs replaced the base scene or its curve (the library side: the inputs
//! a sweep reads are listed, and a trial's recording never replaces one); a FIFO named as the
//! base scene would block.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use softgrip_sweep::{RunOptions, Shard, Sweep, SweepError, Value, max_threads};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

fn parse(vary: &str) -> Result<Sweep, SweepError> {
    Sweep::from_str(&format!("scene = \"grasp.toml\"\n{vary}"), &data(""))
}

#[test]
fn nan_and_inf_values_are_errors_naming_the_field_and_index() {
    for (values, field, got) in [
        ("[nan, inf]", "vary[0].values[0]", "NaN"),
        ("[0.002, inf]", "vary[0].values[1]", "inf"),
        ("[0.001, 0.002, -inf]", "vary[0].values[2]", "-inf"),
    ] {
        let e = parse(&format!(
            "[[vary]]\nfield = \"gripper.squeeze.depth\"\nvalues = {values}\n"
        ))
        .unwrap_err();
        match &e {
            SweepError::Invalid {
                field: f,
                value,
                expected,
                ..
            } => {
                assert_eq!(f, field, "{e}");
                assert_eq!(value, got, "{e}");
                assert!(expected.contains("finite"), "{e}");
            }
            other => panic!("{values}: {other}"),
        }
    }
}

#[test]
fn random_axis_from_minus_1e308_to_1e308_drew_one_value() {
    let s = parse(
        "[[vary]]\nfield = \"body[1].position[2]\"\nrandom = { low = -1e308, high = 1e308, n = 200, seed = 3 }\n",
    )
    .unwrap();
    let v: Vec<f64> = (s.axes()[0].values.iter())
        .map(|v| match v {
            Value::Float(x) => *x,
            other => panic!("{other}"),
        })
        .collect();
    let mut distinct = v.clone();
    distinct.sort_by(f64::total_cmp);
    distinct.dedup();
    assert_eq!(distinct.len(), 200, "every draw differs");
    assert!(v.iter().all(|x| (-1e308..1e308).contains(x)));
    // Both halves of the range are drawn (mean of 200 uniform draws: 0 +- 4e307 at 1 sigma).
    assert!(v.iter().filter(|x| **x < 0.0).count() > 70);
    assert!(v.iter().filter(|x| **x > 0.0).count() > 70);
    let mean = v.iter().map(|x| x / 200.0).sum::<f64>();
    assert!(
        mean.abs() < 4.0 * 1e308 / 3f64.sqrt() / 200f64.sqrt(),
        "{mean}"
    );
}

#[test]
fn threads_100000_is_an_error_with_the_valid_range() {
    let s = Sweep::from_path(&data("grasp_sweep.toml")).unwrap();
    let options = RunOptions {
        threads: 100_000,
        shard: Shard::WHOLE,
    };
    let start = std::time::Instant::now();
    let e = s.run(&options, &|_, _| {}).unwrap_err();
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "refused before any thread starts"
    );
    let m = e.to_string();
    assert!(
        matches!(
            e,
            SweepError::Options {
                option: "threads",
                ..
            }
        ),
        "{m}"
    );
    assert!(m.contains(&format!("in 1..={}", max_threads())), "{m}");
    assert!(m.ends_with("got 100000"), "{m}");
    assert!(
        RunOptions {
            threads: max_threads(),
            ..options
        }
        .check()
        .is_ok()
    );
    assert!(
        RunOptions {
            threads: 0,
            ..options
        }
        .check()
        .is_ok()
    );
}

#[test]
fn run_until_stops_starting_trials_and_keeps_the_finished_rows() {
    let s = Sweep::from_path(&data("grasp_sweep.toml")).unwrap();
    let done = AtomicU64::new(0);
    let options = RunOptions {
        threads: 1,
        shard: Shard::WHOLE,
    };
    let table = s
        .run_until(&options, &|n, _| done.store(n, Ordering::SeqCst), &|| {
            done.load(Ordering::SeqCst) >= 3
        })
        .unwrap();
    // One thread: trials 0, 1, 2 ran; the stop was seen before trial 3.
    let trials: Vec<u64> = table.rows.iter().map(|r| r.trial).collect();
    assert_eq!(trials, [0, 1, 2]);
    let whole = s.run(&options, &|_, _| {}).unwrap();
    for (a, b) in table.rows.iter().zip(&whole.rows) {
        assert_eq!(
            (a.trial, &a.values, &a.outcome),
            (b.trial, &b.values, &b.outcome)
        );
    }
}

#[test]
fn input_files_are_the_sweep_scene_and_its_curves_and_varied_files() {
    let dir = tempdir("inputs");
    let scene = std::fs::read_to_string(data("grasp.toml")).unwrap();
    let scene = scene.replacen(
        "[[fingertip]]\n",
        "[[fingertip]]\nlevel = { tabulated = \"tip.csv\" }\n",
        1,
    );
    std::fs::write(dir.join("base.toml"), scene).unwrap();
    let curve = "delta_m,force_n\n0.0005,0.4\n0.001,1.2\n0.002,3.5\n0.003,6.8\n0.004,11.0\n";
    std::fs::write(dir.join("tip.csv"), curve).unwrap();
    std::fs::write(dir.join("other.csv"), curve).unwrap();
    std::fs::write(
        dir.join("s.toml"),
        "scene = \"base.toml\"\n[[vary]]\nfield = \"fingertip[0].level.tabulated\"\nvalues = [\"tip.csv\", \"other.csv\", \"missing.csv\"]\n",
    )
    .unwrap();
    let s = Sweep::from_path(&dir.join("s.toml")).unwrap();
    let names: Vec<String> = (s.input_files().iter())
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["s.toml", "base.toml", "tip.csv", "other.csv"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn trial_recording_never_replaces_an_input() {
    let dir = tempdir("mcapover");
    // The base scene happens to be named like trial 0's recording, in the recordings' folder.
    std::fs::copy(data("grasp.toml"), dir.join("trial-000000.mcap")).unwrap();
    std::fs::write(
        dir.join("s.toml"),
        "scene = \"trial-000000.mcap\"\nmcap_dir = \".\"\n[[vary]]\nfield = \"gripper.hold\"\nvalues = [0.1, 0.2]\n",
    )
    .unwrap();
    let before = std::fs::read(dir.join("trial-000000.mcap")).unwrap();
    let s = Sweep::from_path(&dir.join("s.toml")).unwrap();
    let row = s.run_trial(0).unwrap();
    let e = row.outcome.unwrap_err();
    assert!(e.contains("would replace the sweep's input"), "{e}");
    assert_eq!(
        std::fs::read(dir.join("trial-000000.mcap")).unwrap(),
        before
    );
    // Trial 1's recording is another file: written.
    assert!(s.run_trial(1).unwrap().outcome.is_ok());
    assert!(dir.join("trial-000001.mcap").is_file());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn fifo_as_base_scene_is_refused_and_a_byte_order_mark_is_skipped() {
    let dir = tempdir("fifo");
    let made = std::process::Command::new("mkfifo")
        .arg(dir.join("base.toml"))
        .status()
        .unwrap();
    assert!(made.success());
    std::fs::write(dir.join("s.toml"), "scene = \"base.toml\"\n").unwrap();
    let path = dir.join("s.toml");
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || tx.send(Sweep::from_path(&path).map(|_| ())).ok());
    let e = rx
        .recv_timeout(Duration::from_secs(20))
        .expect("blocked on the FIFO")
        .unwrap_err();
    assert!(e.to_string().contains("not a regular file"), "{e}");
    // A sweep file with a byte-order mark (a Windows editor's) reads as without.
    let text = std::fs::read_to_string(data("grasp_sweep.toml")).unwrap();
    std::fs::write(dir.join("bom.toml"), format!("\u{feff}{text}")).unwrap();
    std::fs::copy(data("grasp.toml"), dir.join("grasp.toml")).unwrap();
    let s = Sweep::from_path(&dir.join("bom.toml")).unwrap();
    assert_eq!(s.trials(), 8);
    std::fs::remove_dir_all(&dir).ok();
}

fn tempdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softgrip-sweeps-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}
