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

/// The count after `label` in `line` (`slips 2,` or `slip events: 2 (`).
fn count_after(line: &str, label: &str) -> u32 {
    let rest = &line[line
        .find(label)
        .unwrap_or_else(|| panic!("`{label}` in `{line}`"))
        + label.len()..];
    let digits: String = rest
        .chars()
        .skip_while(|c| *c == ' ')
        .take_while(char::is_ascii_digit)
        .collect();
    digits
        .parse()
        .unwrap_or_else(|_| panic!("a count after `{label}` in `{line}`"))
}

#[test]
fn inspect_gives_the_runs_own_slip_counts_when_steps_were_skipped() {
    // The default scene records every 4th step; its fingertips slip for a step or two when the
    // jaws touch and when they open, between recorded steps. inspect must still give the
    // run's counts (written into the file as the run summary), not only what it sees.
    let dir = std::env::temp_dir().join(format!("softgrip-cli-summary-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("squeeze.mcap");
    let file = file.to_str().expect("UTF-8 path");
    let run = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["run", "--out", file])
        .output()
        .expect("the softgrip binary runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let run = String::from_utf8_lossy(&run.stdout).to_string();
    let inspect = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["inspect", file])
        .output()
        .expect("the softgrip binary runs");
    assert!(
        inspect.status.success(),
        "{}",
        String::from_utf8_lossy(&inspect.stderr)
    );
    let inspect = String::from_utf8_lossy(&inspect.stdout).to_string();
    let mut total = 0;
    for tip in ["left_tip", "right_tip"] {
        let summary = run
            .lines()
            .find(|l| l.starts_with(&format!("fingertip {tip}:")))
            .expect("summary line");
        let lines: Vec<&str> = inspect.lines().collect();
        let at = lines
            .iter()
            .position(|l| l.starts_with(&format!("fingertip {tip}:")))
            .expect("inspect line");
        let events = lines[at + 1];
        assert_eq!(
            count_after(events, "slip events:"),
            count_after(summary, "slips"),
            "{events}\n{summary}"
        );
        assert_eq!(
            count_after(events, "validity excursions:"),
            count_after(summary, "validity excursions"),
            "{events}\n{summary}"
        );
        assert!(events.contains("(every step;"), "{events}");
        total += count_after(summary, "slips");
    }
    // The scene does slip (otherwise this test would not test anything).
    assert!(total > 0, "{run}");
    std::fs::remove_dir_all(&dir).ok();
}
