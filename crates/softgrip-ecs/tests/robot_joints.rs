//! Joint states and commands in the ECS's frames (issue 25, item 5): the shipped parallel
//! gripper (`scenes/robots/parallel_gripper_box.toml`, a `<mimic>` finger) closing at 10 mm/s.
//! What the frames say is checked against what the links do: the fingers' separation is
//! 12 mm + q_left + q_right (the URDF's geometry), the mimic joint follows its joint, and
//! while closing freely each joint's velocity (its rate of motion between frames, not rapier's
//! bias-free velocity, which reads 2.7 mm/s here) is the grasp's commanded -10 mm/s.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;
use std::sync::{Arc, Mutex};

use softgrip_ecs::{Scene, Simulation};
use softgrip_record::{SinkError, StepFrame, StepSink};

/// Keeps every frame.
struct Frames(Arc<Mutex<Vec<StepFrame>>>);

impl StepSink for Frames {
    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        self.0.lock().unwrap().push(frame.clone());
        Ok(())
    }
}

fn translation(frame: &StepFrame, body: &str) -> [f64; 3] {
    (frame.bodies.iter().find(|b| b.name == body))
        .unwrap_or_else(|| panic!("no body {body}"))
        .translation
}

#[test]
fn gripper_joint_states_match_the_links_and_the_commands() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/robots/parallel_gripper_box.toml");
    let scene = Scene::from_file(&path).unwrap();
    let frames = Arc::new(Mutex::new(Vec::new()));
    let mut sim = Simulation::new(&scene).with_recorder(Frames(Arc::clone(&frames)));
    // 0.2 s: the pads start 4 mm from the box and close at 10 mm/s: no contact yet.
    for _ in 0..12 {
        sim.step();
    }
    let frames = frames.lock().unwrap();
    assert_eq!(frames.len(), 12);
    for f in frames.iter() {
        let names: Vec<_> = f.joints.iter().map(|j| j.name.as_str()).collect();
        assert_eq!(names, ["finger_joint", "right_finger_joint"]);
        let cmd: Vec<_> = f.commands.iter().map(|j| j.name.as_str()).collect();
        assert_eq!(cmd, names);
        let (q, qm) = (f.joints[0].position, f.joints[1].position);
        // The mimic (multiplier 1, offset 0) follows its joint.
        assert!((q - qm).abs() < 2e-6, "step {}: {q} vs mimic {qm}", f.step);
        let l = translation(f, "gripper/left_finger");
        let r = translation(f, "gripper/right_finger");
        let sep = ((0..3).map(|i| (l[i] - r[i]).powi(2)).sum::<f64>()).sqrt();
        assert!(
            (sep - (0.012 + q + qm)).abs() < 2e-6,
            "step {}: separation {sep} m, joints {q} + {qm} m",
            f.step
        );
        // The motors' force limit is the URDF's effort.
        assert_eq!(f.commands[0].effort, 20.0);
    }
    // Started at 28 mm, closing: the command's velocity is the grasp's speed and the joints
    // follow it once the motor has caught up (the last steps); targets are f32 in rapier.
    assert!((frames[0].joints[0].position - 0.028).abs() < 1e-3);
    for f in &frames[6..] {
        assert!(
            (f.commands[0].velocity + 0.01).abs() < 1e-9,
            "{:?}",
            f.commands[0]
        );
        let v = f.joints[0].velocity;
        assert!(
            (v + 0.01).abs() < 0.05 * 0.01,
            "step {}: velocity {v} m/s",
            f.step
        );
    }
    let dq = frames[11].joints[0].position - frames[6].joints[0].position;
    let dt = 5.0 * scene.file().dt;
    assert!(
        (dq / dt + 0.01).abs() < 0.01 * 0.01,
        "mean velocity {} m/s",
        dq / dt
    );
}
