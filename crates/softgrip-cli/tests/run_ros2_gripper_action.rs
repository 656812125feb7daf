//! `softgrip run --ros2` serves `control_msgs/action/ParallelGripperCommand`: an action client
//! softgrip did not write (Eclipse Cyclone DDS, PyPI `cyclonedds`, its own IDL of the action's
//! Kilted types: crates/softgrip-cli/tests/python/gripper_action.py) sends the shipped parallel
//! gripper (its scene without the scripted grasp) a goal to close at 10 mm/s with at most 5 N.
//! The fingers close on the 40 mm box until the joint's effort reaches 5 N and hold: the result
//! is stalled, not reached, at the box (both pads pressing), with the effort at the limit; the
//! result, every feedback, every `/joint_states` and every `/softgrip/contacts` the client
//! received equal the run's own MCAP recording.
//!
//! Both participants run inside a private network namespace (`unshare -n`, then `ip link set lo
//! up`), on ROS domain 33 set only through `ROS_DOMAIN_ID`.

mod common;
mod gripper_ros2;

use gripper_ros2::{
    check_contacts, check_joint_states, check_stalled_result, floats, recorded_joint_states,
};

#[test]
fn a_gripper_goal_closes_the_hand_on_the_box_and_holds_at_its_effort() {
    let dir = common::temp_dir("ros2-gripper-action");
    let py = common::python();
    let script = common::root().join("crates/softgrip-cli/tests/python/gripper_action.py");
    let client = format!(
        "'{py}' '{}' --domain 33 --action /gripper/gripper_cmd --joint finger_joint \
         --position 0.0 --velocity 0.01 --effort 5.0 --timeout 60",
        script.display()
    );
    let scene = gripper_ros2::gripper_scene(&dir, 5.0);
    let gripper_ros2::Ros2Run {
        received,
        recording,
        stdout,
    } = gripper_ros2::run_beside(&dir, &scene, 33, &client);
    assert!(
        stdout.contains("ros2: gripper actions /gripper/gripper_cmd: 1 goals accepted (0 reached, 1 stalled), 0 refused"),
        "{stdout}"
    );
    assert_eq!(received["answer"]["accepted"].as_bool(), Some(true));

    let recorded = recorded_joint_states(&recording);
    // A (position, effort) of finger_joint the recording holds at some step.
    let in_recording =
        |q: f64, e: f64| (recorded.values()).any(|j| j.position[0] == q && j.effort[0] == e);

    // The result: stalled at the box with the effort at its limit.
    let (q, e) = check_stalled_result(&received);
    assert!(
        in_recording(q, e),
        "the result ({q}, {e}) is no recorded state"
    );

    // Feedback: the joint's state after each step while the goal ran, as recorded.
    let feedback = received["feedback"].as_array().expect("feedback");
    assert!(feedback.len() >= 10, "{} feedback messages", feedback.len());
    for f in feedback {
        let s = &f["feedback"]["state"];
        let (q, e) = (floats(&s["position"])[0], floats(&s["effort"])[0]);
        assert!(
            in_recording(q, e),
            "feedback ({q}, {e}) is no recorded state"
        );
    }

    // Every /joint_states received equals the recording's at its stamp.
    let states = check_joint_states(&received, "states", &recording);
    assert!(states >= 60, "{states} joint states");

    // Every /softgrip/contacts received equals the recording's; the last has both pads pressing.
    check_contacts(&received, &recording);
}
