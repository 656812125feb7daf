//! A gripper goal (`control_msgs/action/ParallelGripperCommand`'s, through a robot's inbox as
//! `softgrip run --ros2` hands it in): the shipped parallel gripper, its scene without the
//! scripted grasp. Open to a position at the goal's speed: reached. Close on the 40 mm box with
//! at most 5 N: stalled at the pads' squeeze, the joint's effort at the limit and equal to each
//! pad's normal force (the finger is pushed along its joint's axis: J^T F).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};

use softgrip_scene::control::{ControlEvent, GoalJoint, GoalResult, GripperGoal};
use softgrip_scene::{PlainRun, Scene};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn scene() -> Scene {
    let path = repo().join("scenes/robots/parallel_gripper_box.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let (head, _grasp) = text.split_once("[[controller]]").unwrap();
    Scene::parse(head, "gripper.toml", path.parent().unwrap()).unwrap()
}

/// Sends `goal` and steps until it ends (at most `steps`): its result, the step it ended at
/// and the finger joint's positions on the way.
fn run_goal(run: &mut PlainRun, goal: GoalJoint, steps: usize) -> (GoalResult, usize, Vec<f64>) {
    let inbox = run.control.inbox(0).unwrap();
    inbox.lock().unwrap().goals.push(GripperGoal {
        id: 7,
        joints: vec![goal],
    });
    let mut q = Vec::new();
    for k in 0..steps {
        run.step();
        if let Some(f) = inbox.lock().unwrap().feedback.take() {
            q.push(f.joints[0].1);
        }
        for (_, e) in run.events() {
            if let ControlEvent::GoalEnded(r) = e {
                let results = std::mem::take(&mut inbox.lock().unwrap().results);
                assert_eq!(
                    results,
                    std::slice::from_ref(r),
                    "the result is handed to the sender"
                );
                return (r.clone(), k, q);
            }
        }
    }
    panic!("the goal did not end in {steps} steps");
}

#[test]
fn a_goal_opens_at_its_speed_and_is_reached() {
    let scene = scene();
    let mut run = PlainRun::new(&scene);
    let goal = GoalJoint {
        name: "finger_joint".into(),
        position: 0.04,
        max_velocity: Some(0.05),
        max_effort: None,
    };
    let (r, k, q) = run_goal(&mut run, goal, 120);
    assert_eq!((r.id, r.reached_goal, r.stalled), (7, true, false));
    assert_eq!(r.joints[0].0, "finger_joint");
    assert!((r.joints[0].1 - 0.04).abs() < 1e-3, "{:?}", r.joints);
    // 12 mm at 50 mm/s (half the URDF's 0.1 m/s): 0.24 s = 14.4 steps, ending within the
    // 1 mm tolerance a step or two before.
    assert!((12..=16).contains(&k), "ended at step {k}");
    let dt = scene.file().dt;
    let speed = (q[8] - q[3]) / (5.0 * dt);
    assert!((speed - 0.05).abs() < 0.0025, "{speed} m/s");
}

/// A goal naming no joint it can move (unknown, mimic, or with a position that is not finite)
/// ends at once, neither reached nor stalled, and moves nothing.
#[test]
fn a_goal_without_a_joint_to_move_ends_at_once() {
    let scene = scene();
    for (name, position) in [
        ("no_such_joint", 0.01),
        ("right_finger_joint", 0.01),
        ("finger_joint", f64::NAN),
    ] {
        let mut run = PlainRun::new(&scene);
        let goal = GoalJoint {
            name: name.into(),
            position,
            max_velocity: None,
            max_effort: None,
        };
        let (r, k, _) = run_goal(&mut run, goal, 10);
        assert_eq!((r.reached_goal, r.stalled, k), (false, false, 0), "{name}");
        assert!(r.joints.is_empty(), "{name}");
        for _ in 0..10 {
            run.step();
        }
        let robot = &scene.robots()[0];
        let h = run.handles.robots[0].1.clone();
        let j = robot.joint_index("finger_joint").unwrap();
        let q = softgrip_scene::robot::joint_state(robot, &run.world.physics, &h, j, 1.0 / 60.0);
        assert!(
            (q.position - 0.028).abs() < 1e-4,
            "{name}: moved to {}",
            q.position
        );
    }
}

/// The drive joint's motor moves both fingers (the second finger is its mimic), so its effort is
/// the joint-space projection of both pads' forces: `|effort| = F_1 + F_2` (J^T F), each pad
/// at half of it.
#[test]
fn a_goal_closes_on_the_box_and_stalls_at_its_effort_with_the_pads_pressing_it() {
    let scene = scene();
    let mut run = PlainRun::new(&scene);
    let goal = GoalJoint {
        name: "finger_joint".into(),
        position: 0.0,
        max_velocity: Some(0.01),
        max_effort: Some(5.0),
    };
    let (r, _, _) = run_goal(&mut run, goal, 300);
    assert_eq!((r.reached_goal, r.stalled), (false, true));
    let (q, effort) = (r.joints[0].1, r.joints[0].2);
    assert!((4.5..5.4).contains(&effort.abs()), "effort {effort} N");
    // Each pad's pole 4 mm from the box at q = 28 mm: it touches at q = 24 mm and stops at
    // 24 mm less the pad's squeeze at 5 N (~1 mm for R = 10 mm Dragon Skin 30, flat).
    assert!((0.021..0.0238).contains(&q), "stopped at {q} m");
    let total: f64 = run
        .world
        .soft
        .contacts()
        .iter()
        .map(|c| c.normal_force)
        .sum();
    let rel = (total - effort.abs()).abs() / effort.abs();
    assert!(
        rel < 0.01,
        "pads {total} N in all vs joint effort {effort} N"
    );
    for c in run.world.soft.contacts() {
        assert!(c.x < 0.3, "pad squeezed to x = {}", c.x);
    }
    assert_eq!(run.world.soft.contacts().len(), 2);
}
