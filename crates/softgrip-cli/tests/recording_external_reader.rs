//! THE EXTERNAL READER TEST for `softgrip run --out`: the binary records the default scene
//! (every step, with pressure), Python's `mcap` + `mcap-ros2-support` (`read_ros2_messages`,
//! which know only the embedded schema text) decode every message, and the decoded values equal
//! softgrip's own decoding of the file (1e-12 relative) and the run's printed summary (peak
//! force and x to the printed digits). Needs `SOFTGRIP_PY` (`bash .ci/python-venv.sh`).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;
mod tactile;

use std::process::Command;

use serde_json::Value;
use softgrip_record::{Message, Recording, topics};

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

#[test]
fn python_mcap_reader_decodes_a_softgrip_run_recording() {
    let dir = common::temp_dir("external-reader");
    let scene = dir.join("scene.toml");
    let text = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    std::fs::write(
        &scene,
        text.replace("pressure = false", "pressure = true\nevery_n_steps = 1"),
    )
    .unwrap();
    let out = dir.join("run.mcap");
    let run = common::softgrip(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );

    let py = Command::new(common::python())
        .arg(common::root().join("crates/softgrip-record/tests/python/read_recording.py"))
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        py.status.success(),
        "{}",
        String::from_utf8_lossy(&py.stderr)
    );
    let lines: Vec<Value> = String::from_utf8(py.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let (summary, messages) = lines.split_last().unwrap();

    let rec = Recording::open(&out).unwrap();
    assert!(!rec.recovered());
    assert_eq!(messages.len(), rec.messages.len());
    assert_eq!(
        summary["summary"]["statistics_messages"],
        rec.messages.len()
    );
    assert_eq!(summary["summary"]["profile"], "ros2");
    let meta = &summary["summary"]["metadata"]["softgrip"];
    assert_eq!(
        meta["scene"].as_str().unwrap(),
        std::fs::read_to_string(&scene).unwrap()
    );
    // The law is JSON (a typed record): `[{"name":"left_tip","level":{"name":"auto",...},...}]`.
    let law: serde_json::Value = serde_json::from_str(meta["law"].as_str().unwrap()).unwrap();
    assert!(
        law.as_array()
            .unwrap()
            .iter()
            .any(|t| t["name"] == "left_tip" && t["level"]["name"] == "auto"),
        "{law}"
    );
    assert!(meta["softgrip_version"].is_string());
    // 300 steps, 8 messages each (6, and a tactile image per fingertip), and /tf_static once.
    assert_eq!(rec.messages.len(), 300 * 8 + 1);

    let mut contacts_checked = 0;
    let mut images = tactile::Images::default();
    let mut peak = std::collections::HashMap::<String, (f64, f64)>::new();
    for (py, m) in messages.iter().zip(&rec.messages) {
        assert_eq!(py["topic"], m.topic.as_str());
        assert_eq!(py["log_time"].as_u64().unwrap(), m.log_time_ns);
        match &m.message {
            Message::Contacts(a) => {
                let list = py["msg"]["contacts"].as_array().unwrap();
                assert_eq!(list.len(), a.contacts.len());
                for (p, c) in list.iter().zip(&a.contacts) {
                    assert_eq!(p["fingertip"], c.fingertip.as_str());
                    assert_eq!(p["other"], c.other.as_str());
                    assert_eq!(p["level_name"], c.level_name.as_str());
                    assert_eq!(p["level"].as_u64().unwrap(), u64::from(c.level));
                    assert_eq!(p["sliding"], c.sliding);
                    assert_eq!(p["validity_exceeded"], c.validity_exceeded);
                    for (name, want) in [
                        ("compression", c.compression),
                        ("ratio_x", c.ratio_x),
                        ("normal_force", c.normal_force),
                        ("torsional_moment", c.torsional_moment),
                        ("contact_radius", c.contact_radius),
                        ("mean_pressure", c.mean_pressure),
                        ("peak_pressure", c.peak_pressure),
                        ("stiffness", c.stiffness),
                        ("peak_normal_force", c.peak_normal_force),
                        ("max_compression", c.max_compression),
                        ("contact_duration", c.contact_duration),
                        ("point.x", c.point.x),
                        ("normal.x", c.normal.x),
                        ("friction_force.y", c.friction_force.y),
                    ] {
                        let v = match name.split_once('.') {
                            Some((a, b)) => &p[a][b],
                            None => &p[name],
                        };
                        let got = v.as_f64().unwrap();
                        assert!(close(got, want), "{name}: python {got}, softgrip {want}");
                    }
                    let e = peak.entry(c.fingertip.clone()).or_default();
                    e.0 = e.0.max(p["peak_normal_force"].as_f64().unwrap());
                    // Peak x: the step's largest compression over R (every substep and the
                    // step's end), as the run summary defines it.
                    let (x, d) = (
                        p["ratio_x"].as_f64().unwrap(),
                        p["compression"].as_f64().unwrap(),
                    );
                    let max_d = p["max_compression"].as_f64().unwrap();
                    e.1 = e.1.max(if x > 0.0 { x.max(max_d * x / d) } else { x });
                    contacts_checked += 1;
                }
                images.contacts(a);
            }
            Message::Image(img) => images.check(&m.topic, &py["msg"], img),
            Message::Wrench(w) => {
                let f = &py["msg"]["wrench"]["force"];
                assert!(close(f["x"].as_f64().unwrap(), w.wrench.force.x));
                assert!(m.topic.starts_with("/softgrip/") && m.topic.ends_with("/wrench"));
            }
            Message::Clock(c) => {
                let t = &py["msg"]["clock"];
                let ns =
                    t["sec"].as_u64().unwrap() * 1_000_000_000 + t["nanosec"].as_u64().unwrap();
                assert_eq!(ns, c.clock.as_nanos());
            }
            _ => assert!(
                [topics::TF, topics::TF_STATIC, topics::MARKERS].contains(&m.topic.as_str())
            ),
        }
    }
    assert!(contacts_checked > 400, "{contacts_checked}");
    images.finish(300);
    // What the simulation reported: the summary's peak force and peak x (every step recorded).
    for tip in ["left_tip", "right_tip"] {
        let line = stdout
            .lines()
            .find(|l| l.starts_with(&format!("fingertip {tip}:")))
            .unwrap();
        // Printed with four significant digits and an SI prefix (`11.78 N`, `12.35 mN`).
        let num = |after: &str| -> f64 {
            let rest = &line[line.find(after).unwrap() + after.len()..];
            let mut w = rest.split_whitespace();
            let v: f64 = w.next().unwrap().trim_end_matches(',').parse().unwrap();
            match w.next().unwrap_or("").trim_end_matches(',') {
                "mN" => v * 1e-3,
                "µN" => v * 1e-6,
                "kN" => v * 1e3,
                _ => v,
            }
        };
        let (f, x) = peak[tip];
        let near = |a: f64, b: f64| (a - b).abs() <= 6e-4 * a.abs().max(b.abs());
        assert!(near(f, num("peak force ")), "{tip}: {f} vs {line}");
        assert!(near(x, num("peak x ")), "{tip}: {x} vs {line}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
