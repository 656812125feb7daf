//! `softgrip run --ros2` against a DDS participant softgrip did not write: Eclipse Cyclone DDS
//! (PyPI `cyclonedds`, with its own IDL definitions of the ROS 2 types, in
//! crates/softgrip-ros2/tests/python/dds_roundtrip.py) subscribes to /softgrip/contacts and
//! both fingertips' wrench topics while the default scene runs at real time, and every
//! SoftContactArrayMsg and WrenchStamped it decodes equals the same step of the run's own MCAP
//! recording (floats to 1e-12 relative, strings and flags exactly).
//!
//! Both participants run inside a private network namespace (`unshare -n`, then `ip link set lo
//! up`): no discovery traffic leaves the machine. The domain (29) is set only through
//! `ROS_DOMAIN_ID`, so a publisher that ignored it would never match.

mod common;

use std::collections::HashMap;
use std::process::Command;

use serde_json::Value;
use softgrip_record::{Message, Recording};

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

fn num(v: &Value, what: &str) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("{what}: not a number: {v}"))
}

fn stamp(h: &Value) -> u64 {
    h["stamp"]["sec"].as_u64().expect("sec") * 1_000_000_000
        + h["stamp"]["nanosec"].as_u64().expect("nanosec")
}

#[test]
fn run_ros2_is_received_by_cyclone_dds() {
    let py = common::python();
    let dir = common::temp_dir("ros2");
    let mcap = dir.join("run.mcap");
    let json = dir.join("received.json");
    let script = common::root().join("crates/softgrip-ros2/tests/python/dds_roundtrip.py");
    let bin = env!("CARGO_BIN_EXE_softgrip");
    let shell = format!(
        "set -e; ip link set lo up; \
         '{py}' '{script}' --domain 29 --steps 100 --tips left_tip,right_tip --no-command \
           --timeout 60 > '{json}' & sub=$!; \
         ROS_DOMAIN_ID=29 '{bin}' run --ros2 --realtime-factor 1 --every 1 --out '{mcap}'; \
         wait $sub",
        script = script.display(),
        json = json.display(),
        mcap = mcap.display(),
    );
    let out = Command::new("unshare")
        .args(["-n", "bash", "-c", &shell])
        .output()
        .expect("unshare runs (util-linux; root or user namespaces needed)");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        stdout.contains("ros2: 300 steps published, 0 dropped"),
        "{stdout}"
    );

    let received: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json")).expect("valid json");
    let recording = Recording::open(&mcap).expect("the run's recording");
    let mut contacts = HashMap::new();
    let mut wrenches = HashMap::new();
    for m in &recording.messages {
        match &m.message {
            Message::Contacts(a) => {
                contacts.insert(m.log_time_ns, a.clone());
            }
            Message::Wrench(w) => {
                wrenches.insert((m.topic.clone(), m.log_time_ns), w.clone());
            }
            _ => {}
        }
    }

    let arrays = received["contacts"].as_array().expect("contacts");
    assert!(
        arrays.len() >= 100,
        "received {} contact arrays",
        arrays.len()
    );
    let mut compared = 0;
    for a in arrays {
        let t = stamp(&a["header"]);
        let want = contacts
            .get(&t)
            .unwrap_or_else(|| panic!("no recorded step at {t} ns"));
        let got = a["contacts"].as_array().expect("contacts array");
        assert_eq!(got.len(), want.contacts.len(), "contacts at {t} ns");
        for (g, w) in got.iter().zip(&want.contacts) {
            assert_eq!(g["fingertip"].as_str(), Some(w.fingertip.as_str()));
            assert_eq!(g["other"].as_str(), Some(w.other.as_str()));
            assert_eq!(g["level_name"].as_str(), Some(w.level_name.as_str()));
            assert_eq!(g["level"].as_u64(), Some(u64::from(w.level)));
            assert_eq!(g["validity_exceeded"].as_bool(), Some(w.validity_exceeded));
            assert_eq!(g["sliding"].as_bool(), Some(w.sliding));
            for (key, value) in [
                ("compression", w.compression),
                ("ratio_x", w.ratio_x),
                ("normal_force", w.normal_force),
                ("torsional_moment", w.torsional_moment),
                ("stiffness", w.stiffness),
                ("contact_radius", w.contact_radius),
                ("peak_normal_force", w.peak_normal_force),
            ] {
                let v = num(&g[key], key);
                assert!(
                    close(v, value),
                    "{key} at {t} ns: DDS {v}, recorded {value}"
                );
            }
            for (axis, value) in [("x", w.normal.x), ("y", w.normal.y), ("z", w.normal.z)] {
                assert!(close(num(&g["normal"][axis], "normal"), value));
            }
            compared += 1;
        }
    }
    assert!(compared >= 20, "compared {compared} contacts");

    for tip in ["left_tip", "right_tip"] {
        let list = received["wrenches"][tip].as_array().expect("wrenches");
        assert!(list.len() >= 100, "{tip}: {} wrenches", list.len());
        let topic = format!("/softgrip/{tip}/wrench");
        for w in list {
            let t = stamp(&w["header"]);
            let want = wrenches
                .get(&(topic.clone(), t))
                .unwrap_or_else(|| panic!("{topic}: no recorded wrench at {t} ns"));
            let f = &w["wrench"]["force"];
            assert!(
                close(num(&f["x"], "fx"), want.wrench.force.x),
                "{topic} at {t}"
            );
            assert!(
                close(num(&f["y"], "fy"), want.wrench.force.y),
                "{topic} at {t}"
            );
            assert!(
                close(num(&f["z"], "fz"), want.wrench.force.z),
                "{topic} at {t}"
            );
        }
    }
}
