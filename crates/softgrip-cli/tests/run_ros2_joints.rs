//! `softgrip run --ros2` with a robot, driven from outside: a DDS participant softgrip did not
//! write (Eclipse Cyclone DDS, PyPI `cyclonedds`, its own IDL of `sensor_msgs/JointState` and
//! `std_msgs/String`: crates/softgrip-cli/tests/python/joint_commands.py) reads
//! `/robot_description` and `/joint_states` and commands the shipped parallel gripper's
//! `finger_joint` open to 40 mm on `/robot_joint_command`. The gripper opens (its state reaches
//! the target within 1 mm, the mimic finger with it), the description it read is the URDF, and
//! every `/joint_states` it received equals the same step of the run's own MCAP recording
//! (floats exactly: the same f64s through CDR).
//!
//! Both participants run inside a private network namespace (`unshare -n`, then `ip link set lo
//! up`), on ROS domain 31 set only through `ROS_DOMAIN_ID`.

mod common;

use std::collections::HashMap;
use std::process::Command;

use serde_json::Value;
use softgrip_record::{Message, Recording, topics};

#[test]
fn run_ros2_takes_joint_commands_and_publishes_joint_states() {
    let py = common::python();
    let dir = common::temp_dir("ros2-joints");
    let root = common::root();
    // The shipped gripper scene without its grasp: only the commands from outside move it.
    let text = std::fs::read_to_string(root.join("scenes/robots/parallel_gripper_box.toml"))
        .expect("gripper scene");
    let (head, _grasp) = text
        .split_once("[[controller]]")
        .expect("a controller section");
    let urdf_path = root.join("robots/parallel_gripper/parallel_gripper.urdf");
    let head = head
        .replace(
            "\"../../robots/parallel_gripper/parallel_gripper.urdf\"",
            &format!("{:?}", urdf_path.display().to_string()),
        )
        .replace("duration = 5.0", "duration = 6.0");
    let scene = dir.join("gripper.toml");
    std::fs::write(&scene, head).expect("write scene");
    let mcap = dir.join("run.mcap");
    let json = dir.join("received.json");
    let script = root.join("crates/softgrip-cli/tests/python/joint_commands.py");
    let bin = env!("CARGO_BIN_EXE_softgrip");
    let shell = format!(
        "set -e; ip link set lo up; \
         '{py}' '{script}' --domain 31 --joint finger_joint --target 0.04 --timeout 60 \
           > '{json}' & sub=$!; \
         ROS_DOMAIN_ID=31 '{bin}' run '{scene}' --ros2 --every 1 --out '{mcap}'; \
         wait $sub",
        script = script.display(),
        json = json.display(),
        mcap = mcap.display(),
        scene = scene.display(),
    );
    let out = Command::new("unshare")
        .args(["-n", "bash", "-c", &shell])
        .output()
        .expect("unshare runs (util-linux; root or user namespaces needed)");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        stdout.contains("joint command messages on /robot_joint_command"),
        "{stdout}"
    );

    let received: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("json")).expect("valid json");
    let urdf = std::fs::read_to_string(&urdf_path).expect("urdf");
    assert_eq!(received["description"].as_str(), Some(urdf.as_str()));
    assert!(received["command_writes"].as_u64().expect("writes") >= 1);

    let recording = Recording::open(&mcap).expect("the run's recording");
    let recorded: HashMap<u64, _> = (recording.on_topic(topics::JOINT_STATES))
        .filter_map(|m| match &m.message {
            Message::JointState(j) => Some((m.log_time_ns, j.clone())),
            _ => None,
        })
        .collect();
    let states = received["states"].as_array().expect("states");
    assert!(states.len() >= 2, "received {} joint states", states.len());
    for s in states {
        let h = &s["header"]["stamp"];
        let t =
            h["sec"].as_u64().expect("sec") * 1_000_000_000 + h["nanosec"].as_u64().expect("ns");
        let want = recorded
            .get(&t)
            .unwrap_or_else(|| panic!("no recorded joint state at {t} ns"));
        let names: Vec<_> = (s["name"].as_array().expect("names").iter())
            .map(|n| n.as_str().expect("name"))
            .collect();
        assert_eq!(names, want.name);
        for (key, values) in [
            ("position", &want.position),
            ("velocity", &want.velocity),
            ("effort", &want.effort),
        ] {
            let got: Vec<f64> = (s[key].as_array().expect(key).iter())
                .map(|v| v.as_f64().expect("number"))
                .collect();
            assert_eq!(&got, values, "{key} at {t} ns");
        }
    }
    // The last state received: both fingers at the target (the mimic follows).
    let last = states.last().expect("a state");
    let q: Vec<f64> = (last["position"].as_array().expect("position").iter())
        .map(|v| v.as_f64().expect("number"))
        .collect();
    assert!(
        (q[0] - 0.04).abs() < 1e-3 && (q[1] - 0.04).abs() < 1e-3,
        "{q:?}"
    );
    // And the recording says the gripper opened from its start at 28 mm.
    let first = &recorded[recorded.keys().min().expect("recorded")];
    assert!(
        (first.position[0] - 0.028).abs() < 1e-3,
        "{:?}",
        first.position
    );
}
