//! What the ROS 2 robot tests share (`run_ros2_joints`, `run_ros2_gripper_action`, and any
//! other client driving the shipped gripper): the gripper scene without its scripted grasp,
//! a run of `softgrip run --ros2` beside a client in a private network namespace, and the
//! JSON readers of what the client received. Use with `mod common; mod gripper_ros2;`.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;
use softgrip_record::msgs::sensor_msgs::JointState;
use softgrip_record::{Message, Recording, topics};

use crate::common;

/// The shipped scene for closing the gripper from ROS 2 (`scenes/ros2/parallel_gripper_box.toml`:
/// the URDF gripper's box scene without its grasp controller, only commands from outside move
/// it), its URDF path made absolute, with `duration` [s], written to `dir`. Checks first that
/// it is still the box scene (`scenes/robots/parallel_gripper_box.toml`) apart from comments,
/// `duration` and the controller.
pub fn gripper_scene(dir: &Path, duration: f64) -> PathBuf {
    let root = common::root();
    let read = |p: &str| std::fs::read_to_string(root.join(p)).expect("gripper scene");
    let text = read("scenes/ros2/parallel_gripper_box.toml");
    let shipped = read("scenes/robots/parallel_gripper_box.toml");
    let (grasp_head, _grasp) = shipped
        .split_once("[[controller]]")
        .expect("a controller section");
    let plain = |t: &str| -> Vec<String> {
        (t.lines())
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty() && !l.starts_with("duration ="))
            .map(str::to_owned)
            .collect()
    };
    assert_eq!(
        plain(&text),
        plain(grasp_head),
        "scenes/ros2/parallel_gripper_box.toml is no longer the box scene without its grasp"
    );
    assert!(!text.contains("[[controller]]"));
    let urdf = root.join("robots/parallel_gripper/parallel_gripper.urdf");
    let head = text
        .replace(
            "\"../../robots/parallel_gripper/parallel_gripper.urdf\"",
            &format!("{:?}", urdf.display().to_string()),
        )
        .replace("duration = 60.0", &format!("duration = {duration:?}"));
    assert_ne!(head, text);
    let path = dir.join("gripper.toml");
    std::fs::write(&path, head).expect("write scene");
    path
}

/// What a namespaced run gave: the client's JSON, the run's recording (every step) and the
/// run's stdout.
pub struct Ros2Run {
    /// What the client printed (JSON).
    pub received: Value,
    /// The run's own recording.
    pub recording: Recording,
    /// softgrip's stdout.
    pub stdout: String,
}

/// Runs `client` (a shell command printing JSON; started first, in the background) and
/// `softgrip run SCENE --ros2 --every 1 --out run.mcap` on ROS domain `domain`, both inside a
/// private network namespace (`unshare -n`, loopback up), in `dir`; waits for both. Panics with
/// both outputs if either fails.
pub fn run_beside(dir: &Path, scene: &Path, domain: u32, client: &str) -> Ros2Run {
    let mcap = dir.join("run.mcap");
    let json = dir.join("received.json");
    let bin = env!("CARGO_BIN_EXE_softgrip");
    let shell = format!(
        "set -e; ip link set lo up; \
         {client} > '{json}' & sub=$!; \
         ROS_DOMAIN_ID={domain} '{bin}' run '{scene}' --ros2 --every 1 --out '{mcap}'; \
         wait $sub",
        json = json.display(),
        mcap = mcap.display(),
        scene = scene.display(),
    );
    let out = Command::new("unshare")
        .args(["-n", "bash", "-c", &shell])
        .output()
        .expect("unshare runs (util-linux; root or user namespaces needed)");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "stdout:\n{stdout}\nstderr:\n{stderr}");
    let received: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json")).expect("valid json");
    Ros2Run {
        received,
        recording: Recording::open(&mcap).expect("the run's recording"),
        stdout,
    }
}

/// A JSON array of numbers.
pub fn floats(v: &Value) -> Vec<f64> {
    (v.as_array().expect("array").iter())
        .map(|x| x.as_f64().expect("number"))
        .collect()
}

/// A JSON `std_msgs/Header`'s stamp \[ns\].
pub fn stamp(h: &Value) -> u64 {
    h["stamp"]["sec"].as_u64().expect("sec") * 1_000_000_000
        + h["stamp"]["nanosec"].as_u64().expect("nanosec")
}

/// The recording's `/joint_states` by log time \[ns\].
pub fn recorded_joint_states(rec: &Recording) -> std::collections::HashMap<u64, JointState> {
    (rec.on_topic(topics::JOINT_STATES))
        .filter_map(|m| match &m.message {
            Message::JointState(j) => Some((m.log_time_ns, j.clone())),
            _ => None,
        })
        .collect()
}

/// Every `/joint_states` the client received (`received[key]`) equals the recording's at its
/// stamp (floats exactly: the same f64s through CDR); returns how many.
pub fn check_joint_states(received: &Value, key: &str, rec: &Recording) -> usize {
    let recorded = recorded_joint_states(rec);
    let states = received[key].as_array().expect("states");
    for s in states {
        let t = stamp(&s["header"]);
        let want = recorded
            .get(&t)
            .unwrap_or_else(|| panic!("no recorded joint state at {t} ns"));
        let names: Vec<_> = (s["name"].as_array().expect("names").iter())
            .map(|n| n.as_str().expect("name"))
            .collect();
        assert_eq!(names, want.name, "at {t} ns");
        assert_eq!(floats(&s["position"]), want.position, "at {t} ns");
        assert_eq!(floats(&s["velocity"]), want.velocity, "at {t} ns");
        assert_eq!(floats(&s["effort"]), want.effort, "at {t} ns");
    }
    states.len()
}

/// Every `/softgrip/contacts` received equals the recording's; the last has both pads pressing.
pub fn check_contacts(received: &Value, recording: &Recording) {
    let contacts: std::collections::BTreeMap<u64, _> = (recording.messages.iter())
        .filter_map(|m| match &m.message {
            Message::Contacts(a) => Some((m.log_time_ns, a.clone())),
            _ => None,
        })
        .collect();
    let arrays = received["contacts"].as_array().expect("contacts");
    let mut compared = 0;
    for a in arrays {
        let t = stamp(&a["header"]);
        let want = (contacts.get(&t)).unwrap_or_else(|| panic!("no contacts at {t} ns"));
        let got = a["contacts"].as_array().expect("contacts");
        assert_eq!(got.len(), want.contacts.len(), "at {t} ns");
        for (g, w) in got.iter().zip(&want.contacts) {
            assert_eq!(g["fingertip"].as_str(), Some(w.fingertip.as_str()));
            assert_eq!(g["other"].as_str(), Some(w.other.as_str()));
            for (key, value) in [
                ("compression", w.compression),
                ("normal_force", w.normal_force),
                ("contact_radius", w.contact_radius),
                ("peak_pressure", w.peak_pressure),
            ] {
                assert_eq!(g[key].as_f64(), Some(value), "{key} at {t} ns");
            }
            compared += 1;
        }
    }
    assert!(compared >= 20, "compared {compared} contacts");
    let last = arrays.last().expect("a contact array")["contacts"]
        .as_array()
        .expect("contacts");
    let pressing: Vec<&str> = (last.iter())
        .filter(|c| c["other"].as_str() == Some("box") && c["normal_force"].as_f64() > Some(0.0))
        .map(|c| c["fingertip"].as_str().expect("name"))
        .collect();
    assert!(
        pressing.contains(&"left_pad") && pressing.contains(&"right_pad"),
        "{pressing:?}"
    );
}

/// rcl_action's GoalStatus ABORTED: what the server answers a stalled goal with.
pub const STATUS_ABORTED: i64 = 6;

/// The result of the gripper goal both action tests send (close `finger_joint` to 0 at 10 mm/s
/// with at most 5 N): aborted, stalled, not reached, `finger_joint` stopped short of the goal by
/// the box with its effort at the limit: the target froze the step the effort reached 5 N (at
/// most one step's increment over it: 2000 N/m x 10 mm/s x 1/60 s = 0.33 N), then the finger
/// settled a little into the pad. Returns its position [m] and effort [N].
pub fn check_stalled_result(received: &Value) -> (f64, f64) {
    let result = &received["result"];
    assert_eq!(result["status"].as_i64(), Some(STATUS_ABORTED), "{result}");
    let r = &result["result"];
    assert_eq!(r["stalled"].as_bool(), Some(true));
    assert_eq!(r["reached_goal"].as_bool(), Some(false));
    assert_eq!(r["state"]["name"][0].as_str(), Some("finger_joint"));
    let (q, e) = (
        floats(&r["state"]["position"])[0],
        floats(&r["state"]["effort"])[0],
    );
    assert!((4.5..5.4).contains(&e.abs()), "result effort {e} N");
    // Closed from its start (28 mm) and stopped short of the goal (0) by the box. Where exactly
    // (the pads' squeeze at 5 N) is crates/softgrip-scene/tests/gripper_goal.rs's to check.
    assert!(q > 0.005 && q < 0.0275, "result position {q} m");
    (q, e)
}
