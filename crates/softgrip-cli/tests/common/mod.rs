//! Helpers of the CLI tests: run the binary, temporary directories, long test scenes.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The workspace root.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `softgrip ARGS`, waited for.
pub fn softgrip(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(args)
        .output()
        .expect("the softgrip binary runs")
}

/// A fresh temporary directory named after the test.
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("softgrip-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// The default scene with a hold of `hold` seconds, recording every step: a long run to
/// interrupt or kill.
pub fn long_scene(dir: &Path, hold: f64) -> PathBuf {
    let text = std::fs::read_to_string(root().join("scenes/default.toml")).expect("default scene");
    let text = text
        .replace("hold = 2.0 ", &format!("hold = {hold} "))
        .replace("duration = 5.0 ", &format!("duration = {} ", hold + 3.0))
        .replace("pressure = false", "pressure = false\nevery_n_steps = 1");
    assert!(text.contains(&format!("hold = {hold}")), "{text}");
    let path = dir.join("long.toml");
    std::fs::write(&path, text).expect("write scene");
    path
}

/// `SOFTGRIP_PY`, the Python with `mcap` and `mcap-ros2-support`.
pub fn python() -> String {
    std::env::var("SOFTGRIP_PY").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PY is not set: it must name a Python with the PyPI packages `mcap` and \
             `mcap-ros2-support`; `bash .ci/python-venv.sh` makes one and prints its path"
        )
    })
}

/// `softgrip curve ARGS`, waited for.
pub fn softgrip_curve(args: &[&str]) -> Output {
    let mut all = vec!["curve"];
    all.extend_from_slice(args);
    softgrip(&all)
}

/// The CSV of `softgrip curve ARGS` (success checked): its header and its rows as numbers
/// (a cell that is not a number fails, naming it and its line).
pub fn curve_csv(args: &[&str]) -> (String, Vec<Vec<f64>>) {
    let out = softgrip_curve(args);
    assert!(
        out.status.success(),
        "softgrip curve {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).expect("UTF-8 output");
    let mut lines = text.lines();
    let header = lines.next().expect("a header").to_string();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| {
                    v.parse::<f64>()
                        .unwrap_or_else(|_| panic!("bad number `{v}` in `{l}`"))
                })
                .collect()
        })
        .collect();
    (header, rows)
}
