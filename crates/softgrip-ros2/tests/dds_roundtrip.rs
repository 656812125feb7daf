//! THE DDS ROUND TRIP: a DDS participant softgrip did not write (Eclipse Cyclone DDS through
//! PyPI `cyclonedds`, with its own IDL definitions of the ROS 2 types) receives what
//! `softgrip-ros2-probe` publishes with `Ros2Publisher` and decodes SoftContactArrayMsg and
//! WrenchStamped; every value equals the scripted step's (floats to 1e-12 relative, strings,
//! integers and flags exactly). It then publishes a WrenchStamped on /softgrip/command, which
//! the probe's `Ros2Subscriber` must receive with the same values.
//!
//! Both run inside a private network namespace (only `lo`), on ROS domain 17 set through
//! `ROS_DOMAIN_ID` (a publisher that ignored it would be on domain 0 and never match). Needs
//! `SOFTGRIP_PY` (a Python with cyclonedds; `bash .ci/python-venv.sh`) and `unshare -n`.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;
#[path = "../src/bin/softgrip-ros2-probe/script.rs"]
mod script;

use serde_json::Value;
use softgrip_record::msgs::geometry_msgs::{Vector3, Wrench};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{StepRecord, topics};

const DOMAIN: &str = "17";

/// The command the Python side sends (the same literals are in tests/python/dds_roundtrip.py).
const COMMAND_STAMP_NS: u64 = 42 * 1_000_000_000 + 123_456_789;
const COMMAND_FRAME: &str = "gripper/base \u{2713}";
const COMMAND: Wrench = Wrench {
    force: Vector3 {
        x: 1.5,
        y: -2.25,
        z: 3.333333333333333e-10,
    },
    torque: Vector3 {
        x: 0.1,
        y: -0.2,
        z: 3.3e-300,
    },
};

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

fn f(v: &Value, what: &str) -> f64 {
    v.as_f64()
        .unwrap_or_else(|| panic!("{what}: not a number: {v}"))
}

fn assert_f(got: &Value, want: f64, what: &str) {
    let g = f(got, what);
    assert!(close(g, want), "{what}: received {g}, sent {want}");
}

fn assert_vec3(got: &Value, want: [f64; 3], what: &str) {
    for (axis, w) in ["x", "y", "z"].iter().zip(want) {
        assert_f(&got[axis], w, &format!("{what}.{axis}"));
    }
}

fn stamp_ns(header: &Value) -> u64 {
    header["stamp"]["sec"].as_u64().unwrap() * 1_000_000_000
        + header["stamp"]["nanosec"].as_u64().unwrap()
}

fn assert_header(got: &Value, time_ns: u64, frame: &str, what: &str) {
    assert_eq!(stamp_ns(got), time_ns, "{what}: stamp");
    assert_eq!(got["frame_id"], frame, "{what}: frame_id");
}

fn assert_wrench(got: &Value, want: &Wrench, what: &str) {
    assert_vec3(
        &got["force"],
        want.force.to_array(),
        &format!("{what}.force"),
    );
    assert_vec3(
        &got["torque"],
        want.torque.to_array(),
        &format!("{what}.torque"),
    );
}

fn assert_contact(got: &Value, want: &SoftContactMsg, step: &StepRecord, what: &str) {
    assert_header(&got["header"], step.time_ns, &step.world_frame, what);
    assert_eq!(got["fingertip"], want.fingertip.as_str(), "{what}");
    assert_eq!(got["other"], want.other.as_str(), "{what}");
    assert_vec3(
        &got["point"],
        want.point.to_array(),
        &format!("{what}.point"),
    );
    assert_vec3(
        &got["normal"],
        want.normal.to_array(),
        &format!("{what}.normal"),
    );
    assert_vec3(
        &got["friction_force"],
        want.friction_force.to_array(),
        &format!("{what}.friction_force"),
    );
    assert_vec3(
        &got["patch_direction"],
        want.patch_direction.to_array(),
        &format!("{what}.patch_direction"),
    );
    for (name, v) in [
        ("compression", want.compression),
        ("ratio_x", want.ratio_x),
        ("normal_force", want.normal_force),
        ("torsional_moment", want.torsional_moment),
        ("contact_radius", want.contact_radius),
        ("mean_pressure", want.mean_pressure),
        ("peak_pressure", want.peak_pressure),
        ("stiffness", want.stiffness),
        ("peak_normal_force", want.peak_normal_force),
        ("max_compression", want.max_compression),
        ("contact_duration", want.contact_duration),
        ("contact_radius2", want.contact_radius2),
        ("counterpart_curvature1", want.counterpart_curvature1),
        ("counterpart_curvature2", want.counterpart_curvature2),
    ] {
        assert_f(&got[name], v, &format!("{what}.{name}"));
    }
    assert_eq!(got["level"], u64::from(want.level), "{what}.level");
    assert_eq!(
        got["counterpart"],
        u64::from(want.counterpart),
        "{what}.counterpart"
    );
    assert_eq!(got["level_name"], want.level_name.as_str(), "{what}");
    assert_eq!(got["validity_exceeded"], want.validity_exceeded, "{what}");
    assert_eq!(got["sliding"], want.sliding, "{what}");
}

#[test]
fn cyclone_dds_receives_softgrip_and_softgrip_receives_cyclone_dds() {
    let py = common::python();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let probe = env!("CARGO_BIN_EXE_softgrip-ros2-probe");
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/python/dds_roundtrip.py");
    let tips: Vec<String> = script::TIPS
        .iter()
        .map(|t| topics::ros_name_token(t))
        .collect();
    let steps = script::STEPS.to_string();
    let tips = tips.join(",");

    // Both participants in one private namespace; each stops by itself (the probe 1 s after
    // the command arrived or at 90 s; Python when the probe fell silent or at 60 s).
    let run = common::in_private_netns(
        r#"
        out="$0"; probe="$1"; py="$2"; script="$3"; steps="$4"; tips="$5"
        "$probe" --timeout-s 90 --linger-ms 1000 >"$out/probe.out" 2>"$out/probe.err" &
        pid=$!
        "$py" "$script" --domain "$ROS_DOMAIN_ID" --steps "$steps" --tips "$tips" --timeout 60 \
            >"$out/py.out" 2>"$out/py.err"
        echo $? >"$out/py.rc"
        wait $pid
        echo $? >"$out/probe.rc"
        "#,
        &[out, probe, &py, script, &steps, &tips],
        &[("ROS_DOMAIN_ID", DOMAIN)],
    );
    let read = |name: &str| std::fs::read_to_string(dir.path().join(name)).unwrap_or_default();
    let report = format!(
        "unshare: {}\n{}\n--- probe (rc {}) ---\n{}{}\n--- python (rc {}) ---\n{}{}",
        run.status,
        String::from_utf8_lossy(&run.stderr),
        read("probe.rc").trim(),
        read("probe.out"),
        read("probe.err"),
        read("py.rc").trim(),
        read("py.out"),
        read("py.err"),
    );
    assert!(run.status.success(), "{report}");
    assert_eq!(
        read("py.rc").trim(),
        "0",
        "the Python participant failed:\n{report}"
    );
    assert_eq!(read("probe.rc").trim(), "0", "the probe failed:\n{report}");

    // 1. What Cyclone DDS decoded.
    let got: Value = serde_json::from_str(&read("py.out")).unwrap();
    let contacts = got["contacts"].as_array().unwrap();
    assert_eq!(contacts.len() as u64, script::STEPS, "{report}");
    for (k, array) in contacts.iter().enumerate() {
        let step = script::step(k as u64);
        let what = format!("contacts[{k}]");
        assert_header(&array["header"], step.time_ns, &step.world_frame, &what);
        let list = array["contacts"].as_array().unwrap();
        assert_eq!(list.len(), step.contacts.len(), "{what}");
        for (i, (g, w)) in list.iter().zip(&step.contacts).enumerate() {
            assert_contact(g, w, &step, &format!("{what}.contacts[{i}]"));
        }
    }
    for (i, tip) in script::TIPS.iter().enumerate() {
        let token = topics::ros_name_token(tip);
        let list = got["wrenches"][&token].as_array().unwrap();
        assert_eq!(list.len() as u64, script::STEPS, "/softgrip/{token}/wrench");
        for (k, w) in list.iter().enumerate() {
            let step = script::step(k as u64);
            let what = format!("/softgrip/{token}/wrench[{k}]");
            assert_header(&w["header"], step.time_ns, &step.world_frame, &what);
            assert_wrench(&w["wrench"], &step.fingertips[i].wrench, &what);
        }
    }

    // 2. What the probe's subscriber received from Cyclone DDS.
    let events: Vec<Value> = read("probe.out")
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let ready = events.iter().find(|e| e["event"] == "ready").unwrap();
    assert_eq!(ready["domain_id"], 17, "ROS_DOMAIN_ID not honoured");
    let cmd = &events.iter().find(|e| e["event"] == "command").unwrap()["message"];
    assert_header(&cmd["header"], COMMAND_STAMP_NS, COMMAND_FRAME, "command");
    assert_wrench(&cmd["wrench"], &COMMAND, "command");
    let done = events.iter().find(|e| e["event"] == "done").unwrap();
    assert_eq!(done["publish_failures"], 0, "{report}");
    assert_eq!(done["steps_dropped"], 0, "{report}");
    eprintln!(
        "round trip: {} steps published by the probe in {:.2} s, {} command writes by Python",
        done["steps_published"],
        f(&done["seconds"], "seconds"),
        got["command_writes"]
    );
}
