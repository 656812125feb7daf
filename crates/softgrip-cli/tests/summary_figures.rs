//! One definition of every summary figure (issue 11): the run summary printed by `softgrip
//! run`, the recording's `softgrip_run_summary` metadata and `softgrip inspect` agree on peak
//! force, peak x and validity excursions when every step is recorded. Before, peak x was read
//! at the end of a step while peak force was a substep maximum (a 10 m drop printed 290.9 N
//! at x = 0.0000), and excursions counted end-of-step regimes while the recording flagged any
//! substep. Also issue 12 item 5: every recorded `max_compression >= compression`.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_record::{Message, Recording, topics};

/// "12.35 µN" (or "0.1234") after `key` in `line`, in SI units.
fn si_after(line: &str, key: &str) -> f64 {
    let rest = &line[line.find(key).unwrap() + key.len()..];
    let mut w = rest.split_whitespace();
    let v: f64 = w.next().unwrap().trim_end_matches(',').parse().unwrap();
    let unit = w.next().unwrap_or("");
    let scale = match unit.chars().next() {
        Some('µ') => 1e-6,
        Some('n') => 1e-9,
        Some('m') if unit.len() > 1 => 1e-3,
        Some('k') => 1e3,
        _ => 1.0,
    };
    v * scale
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-3 * a.abs().max(b.abs()) + 1e-300
}

#[test]
fn run_summary_metadata_and_inspect_agree_and_max_compression_covers_compression() {
    let dir = common::temp_dir("figures");
    // A scene past the law's validity in some substeps: the live cell squeezed to x = 0.75.
    for scene in ["scenes/default.toml", "scenes/cell_live_hmsc.toml"] {
        let out = dir.join("f.mcap");
        let path = common::root().join(scene);
        let o = common::softgrip(&[
            "run",
            path.to_str().unwrap(),
            "--every",
            "1",
            "--out",
            out.to_str().unwrap(),
            "--force",
        ]);
        let run = String::from_utf8_lossy(&o.stdout).into_owned();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let rec = Recording::open(&out).unwrap();
        for m in rec.on_topic(topics::CONTACTS) {
            if let Message::Contacts(a) = &m.message {
                for c in &a.contacts {
                    assert!(
                        c.max_compression >= c.compression,
                        "{scene}: max_compression {} < compression {}",
                        c.max_compression,
                        c.compression
                    );
                }
            }
        }
        let summary = rec.run_summary().unwrap().unwrap();
        let o = common::softgrip(&["inspect", out.to_str().unwrap()]);
        let inspect = String::from_utf8_lossy(&o.stdout).into_owned();
        for tip in &summary.fingertips {
            let r = run
                .lines()
                .find(|l| l.starts_with(&format!("fingertip {}:", tip.name)))
                .unwrap();
            let i = inspect
                .lines()
                .find(|l| l.starts_with(&format!("fingertip {}:", tip.name)))
                .unwrap();
            for line in [r, i] {
                assert!(
                    close(si_after(line, "peak force "), tip.peak_force),
                    "{scene}: {line} vs {tip:?}"
                );
                assert!(
                    close(si_after(line, "peak x "), tip.peak_x),
                    "{scene}: {line} vs {tip:?}"
                );
            }
            assert!(
                r.contains(&format!("validity excursions {}", tip.validity_excursions)),
                "{r}"
            );
            let events = inspect.lines().skip_while(|l| *l != i).nth(1).unwrap();
            let n = tip.validity_excursions;
            assert!(
                events.contains(&format!(
                    "validity excursions: {n} (every step; {n} in the recorded steps"
                )),
                "{scene}: {events}"
            );
        }
        std::fs::remove_dir_all(&out).ok();
        std::fs::remove_file(&out).ok();
    }
    std::fs::remove_dir_all(&dir).ok();
}
