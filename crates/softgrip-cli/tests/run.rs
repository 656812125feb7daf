//! `softgrip run` with the embedded default scene: exits 0 and prints the summary.

use std::process::Command;

#[test]
fn run_default_scene_prints_a_summary() {
    let out = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .arg("run")
        .output()
        .expect("the softgrip binary runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for tip in ["left_tip", "right_tip"] {
        let line = stdout
            .lines()
            .find(|l| l.starts_with(&format!("fingertip {tip}:")))
            .unwrap_or_else(|| panic!("no summary line for {tip} in:\n{stdout}"));
        for field in [
            "peak force",
            "peak x",
            "peak contact radius",
            "slips",
            "validity excursions",
        ] {
            assert!(line.contains(field), "`{field}` missing in `{line}`");
        }
    }
    assert!(stdout.contains("real-time factor"), "{stdout}");
}

#[test]
fn run_reports_a_bad_scene_with_its_line() {
    let dir = std::env::temp_dir().join(format!("softgrip-cli-run-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("bad.toml");
    std::fs::write(&path, "duration = 1.0\ndurration = 2.0\n").expect("write");
    let out = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["run", path.to_str().expect("UTF-8 path")])
        .output()
        .expect("the softgrip binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("bad.toml:2:") && stderr.contains("durration"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
