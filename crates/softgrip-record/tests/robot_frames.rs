//! Robots in the converter (issue 25, item 5): a robot link is a child of its parent link on
//! `/tf` (its pose relative to it), a link on a fixed joint goes on `/tf_static` once, the URDF
//! on `/robot_description` on the first step only, joint states and commands on
//! `/joint_states` and `/joint_commands`, and all of it reads back from an MCAP.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_record::frames::{UpAxis, rotate};
use softgrip_record::{
    BodyFrame, BodySample, JointSample, Recorder, RecorderOptions, RecordingInfo, RobotInfo,
    SceneInfo, StepConverter, StepFrame, StepRecord, topics,
};

const URDF: &str = "<robot name=\"g\"><link name=\"base\"/></robot>";

fn scene() -> SceneInfo {
    SceneInfo {
        origin: "robot test".into(),
        dt: 0.01,
        steps: 3,
        bodies: vec!["g/base".into(), "g/finger".into(), "g/pad".into()],
        up: UpAxis::Y,
        gravity: [0.0, -9.81, 0.0],
        robots: vec![RobotInfo {
            name: "g".into(),
            urdf: URDF.into(),
        }],
        frames: vec![
            BodyFrame {
                body: "g/finger".into(),
                parent: "g/base".into(),
                fixed: false,
            },
            BodyFrame {
                body: "g/pad".into(),
                parent: "g/finger".into(),
                fixed: true,
            },
        ],
        ..SceneInfo::default()
    }
}

/// Quarter turn about scene +y.
const QY: [f64; 4] = [
    0.0,
    std::f64::consts::FRAC_1_SQRT_2,
    0.0,
    std::f64::consts::FRAC_1_SQRT_2,
];

fn body(name: &str, translation: [f64; 3], rotation: [f64; 4]) -> BodySample {
    BodySample {
        name: name.into(),
        translation,
        rotation,
    }
}

fn joint(name: &str, position: f64, velocity: f64, effort: f64) -> JointSample {
    JointSample {
        name: name.into(),
        position,
        velocity,
        effort,
    }
}

/// The base turned a quarter turn about y at (1, 2, 3); the finger 0.1 m along the base's x
/// (world -z) with the base's orientation; the pad 0.02 m further along it.
fn frame(step: u64, q: f64) -> StepFrame {
    StepFrame {
        step,
        time: step as f64 * 0.01,
        bodies: vec![
            body("g/base", [1.0, 2.0, 3.0], QY),
            body("g/finger", [1.0, 2.0, 3.0 - 0.1 - q], QY),
            body("g/pad", [1.0, 2.0, 3.0 - 0.12 - q], QY),
        ],
        joints: vec![joint("slide", q, 0.5, -2.0)],
        commands: vec![joint("slide", 0.04, 0.0, 20.0)],
        ..StepFrame::default()
    }
}

fn close(a: [f64; 3], b: [f64; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
}

#[test]
fn links_are_children_of_their_parent_links_and_fixed_ones_static() {
    let mut conv = StepConverter::new(&scene());
    let mut first = StepRecord::default();
    conv.convert(&frame(1, 0.01), &mut first);
    let tf = first.tf();
    let edges: Vec<_> = (tf.transforms.iter())
        .map(|t| (t.header.frame_id.as_str(), t.child_frame_id.as_str()))
        .collect();
    assert_eq!(edges, [("world", "g/base"), ("g/base", "g/finger")]);
    // The finger is 0.11 m along the base's own x.
    let finger = tf.transforms[1].transform.translation.to_array();
    assert!(close(finger, [0.11, 0.0, 0.0]), "{finger:?}");
    let r = &tf.transforms[1].transform.rotation;
    assert!(close([r.x, r.y, r.z], [0.0; 3]) && (r.w.abs() - 1.0).abs() < 1e-12);
    // The base in world axes (z-up): scene (1, 2, 3) -> (3, 1, 2)... as the converter rotates.
    let base = tf.transforms[0].transform.translation.to_array();
    assert!(close(base, UpAxis::Y.vector([1.0, 2.0, 3.0])), "{base:?}");
    let statics = first.tf_static.as_ref().unwrap();
    let fixed: Vec<_> = (statics.transforms.iter())
        .map(|t| (t.header.frame_id.as_str(), t.child_frame_id.as_str()))
        .collect();
    assert_eq!(fixed, [("g/finger", "g/pad")]);
    let pad = statics.transforms[0].transform.translation.to_array();
    assert!(close(pad, [0.02, 0.0, 0.0]), "{pad:?}");
    assert_eq!(
        rotate(QY, [1.0, 0.0, 0.0]).map(|v| v.round()),
        [0.0, 0.0, -1.0]
    );

    let mut second = StepRecord::default();
    conv.convert(&frame(2, 0.02), &mut second);
    assert!(second.tf_static.is_none());
    assert!(second.robot_descriptions.is_empty());
    let finger = second.tf().transforms[1].transform.translation.to_array();
    assert!(close(finger, [0.12, 0.0, 0.0]), "{finger:?}");
}

#[test]
fn description_and_joints_are_recorded_and_read_back() {
    let dir = std::env::temp_dir().join(format!("softgrip-robot-frames-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("robot.mcap");
    let info = scene();
    let mut conv = StepConverter::new(&info);
    let mut rec = Recorder::with_options(
        &path,
        &RecordingInfo::default(),
        &RecorderOptions::default(),
    )
    .unwrap();
    let mut step = StepRecord::default();
    for k in 1..=3 {
        conv.convert(&frame(k, 0.01 * k as f64), &mut step);
        if k == 1 {
            assert_eq!(step.robot_descriptions.len(), 1);
            assert_eq!(step.robot_descriptions[0].0, "");
        }
        rec.write_step(&mut step).unwrap();
    }
    rec.finish().unwrap();
    let recording = softgrip_record::Recording::open(&path).unwrap();
    let mut descriptions = Vec::new();
    let mut states = Vec::new();
    let mut commands = Vec::new();
    for m in &recording.messages {
        match (m.topic.as_str(), m.message.clone()) {
            (topics::ROBOT_DESCRIPTION, softgrip_record::Message::String(s)) => {
                descriptions.push(s.data)
            }
            (topics::JOINT_STATES, softgrip_record::Message::JointState(j)) => states.push(j),
            (topics::JOINT_COMMANDS, softgrip_record::Message::JointState(j)) => commands.push(j),
            _ => {}
        }
    }
    assert_eq!(descriptions, [URDF]);
    assert_eq!(states.len(), 3);
    assert_eq!(commands.len(), 3);
    assert_eq!(states[2].name, ["slide"]);
    assert_eq!(states[2].position, [0.03]);
    assert_eq!(states[2].velocity, [0.5]);
    assert_eq!(states[2].effort, [-2.0]);
    assert_eq!(states[2].header.stamp.nanosec, 30_000_000);
    assert_eq!(commands[0].position, [0.04]);
    assert_eq!(commands[0].effort, [20.0]);
    std::fs::remove_dir_all(&dir).unwrap();
}
