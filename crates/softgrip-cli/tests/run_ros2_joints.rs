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
mod gripper_ros2;

#[test]
fn run_ros2_takes_joint_commands_and_publishes_joint_states() {
    let dir = common::temp_dir("ros2-joints");
    let root = common::root();
    let py = common::python();
    let script = root.join("crates/softgrip-cli/tests/python/joint_commands.py");
    let client = format!(
        "'{py}' '{}' --domain 31 --joint finger_joint --target 0.04 --timeout 60",
        script.display()
    );
    let scene = gripper_ros2::gripper_scene(&dir, 6.0);
    let run = gripper_ros2::run_beside(&dir, &scene, 31, &client);
    let (received, stdout) = (&run.received, &run.stdout);
    assert!(
        stdout.contains("joint command messages on /robot_joint_command"),
        "{stdout}"
    );
    // Every entry named the commandable `finger_joint` with a finite target: none refused.
    assert!(
        stdout.contains("joint targets applied, 0 refused"),
        "{stdout}"
    );
    let urdf_path = root.join("robots/parallel_gripper/parallel_gripper.urdf");
    let urdf = std::fs::read_to_string(&urdf_path).expect("urdf");
    assert_eq!(received["description"].as_str(), Some(urdf.as_str()));
    assert!(received["command_writes"].as_u64().expect("writes") >= 1);

    let n = gripper_ros2::check_joint_states(received, "states", &run.recording);
    assert!(n >= 2, "received {n} joint states");
    // The last state received: both fingers at the target (the mimic follows).
    let states = received["states"].as_array().expect("states");
    let q = gripper_ros2::floats(&states.last().expect("a state")["position"]);
    assert!(
        (q[0] - 0.04).abs() < 1e-3 && (q[1] - 0.04).abs() < 1e-3,
        "{q:?}"
    );
    // And the recording says the gripper opened from its start at 28 mm.
    let recorded = gripper_ros2::recorded_joint_states(&run.recording);
    let first = &recorded[recorded.keys().min().expect("recorded")];
    assert!(
        (first.position[0] - 0.028).abs() < 1e-3,
        "{:?}",
        first.position
    );
}
