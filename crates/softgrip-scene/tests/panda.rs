//! A third-party URDF: the Franka Panda of PyPI's `pybullet` (`pybullet_data/franka_panda/
//! panda.urdf`, its `package://meshes/...` OBJ meshes; Apache-2.0, fetched by
//! `.ci/pybullet-data.sh` into target/, never committed; `SOFTGRIP_PYBULLET_DATA` names the
//! folder). The arm stands in its ready pose (q = 0, -pi/4, 0, -3pi/4, 0, pi/2, pi/4) with a
//! Dragon Skin 30 pad (R = 8 mm, `flat`) on each finger's inner face, over a 40 mm, 200 g box on
//! a pedestal between the fingers. The expected pad positions come from the URDF's joint
//! origins by hand (forward kinematics written out in the comments), not from the engine.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::PathBuf;

use softgrip_scene::control::Phase;
use softgrip_scene::robot::JointKind;
use softgrip_scene::{PlainRun, Scene};

/// The pybullet_data folder (`SOFTGRIP_PYBULLET_DATA`).
fn data() -> PathBuf {
    let dir = std::env::var("SOFTGRIP_PYBULLET_DATA").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PYBULLET_DATA is not set: it must name pybullet's pybullet_data folder \
             with franka_panda/; `bash .ci/pybullet-data.sh` fetches it and prints the path"
        )
    });
    PathBuf::from(dir)
}

/// Ready pose: the flange 0.5903 m up at x = 0.3069 m, pointing down; the hand turned so
/// the fingers close along world y. Each finger's frame is at the hand + 0.0584 m (down), its
/// inner face at its frame's y = 0 (finger.obj spans y 0 .. 26.4 mm outwards), so a pad at
/// (0, 0, 0.045) in the finger frame is at z = 0.5903 - 0.0584 - 0.045 = 0.4869 m and y = -+q.
const PAD: [f64; 3] = [0.3069, 0.032, 0.4869];
/// Opening at the start [m]: the pads' poles (R = 8 mm) 4 mm from the box's faces.
const OPEN: f64 = 0.032;

/// panda_joint4's lower limit as panda.urdf writes it (a rounded pi, not pi).
#[allow(clippy::approx_constant)]
const J4_LOWER: f64 = -3.1416;

fn scene_text(grasp: bool) -> String {
    let panda = data().join("franka_panda");
    let pedestal = (PAD[2] - 0.02) / 2.0;
    let mut s = format!(
        r#"duration = 2.5
dt = 0.016666666666666666
gravity = [0.0, 0.0, -9.81]

[[body]]
name = "pedestal"
kind = "fixed"
position = [{x}, 0.0, {pedestal}]
[[body.shape]]
type = "cuboid"
half_extents = [0.05, 0.05, {pedestal}]

[[body]]
name = "box"
kind = "dynamic"
position = [{x}, 0.0, {z}]
[[body.shape]]
type = "cuboid"
half_extents = [0.02, 0.02, 0.02]
density = 3125.0
friction = 0.5

[[robot]]
name = "panda"
urdf = {urdf:?}
package_paths = {{ meshes = {meshes:?} }}
initial = {{ panda_joint2 = -0.7853981633974483, panda_joint4 = -2.356194490192345, panda_joint6 = 1.5707963267948966, panda_joint7 = 0.7853981633974483, panda_finger_joint1 = {OPEN} }}
stiffness = 100000.0
damping = 1000.0
gains = {{ panda_finger_joint1 = [2000.0, 20.0], panda_finger_joint2 = [2000.0, 20.0] }}

[[fingertip]]
name = "left_pad"
link = "panda/panda_leftfinger"
offset = [0.0, 0.0, 0.045]
radius = 0.008
preset = "dragon-skin-30"
backing = "flat"
facing = [0.0, -1.0, 0.0]

[[fingertip]]
name = "right_pad"
link = "panda/panda_rightfinger"
offset = [0.0, 0.0, 0.045]
radius = 0.008
preset = "dragon-skin-30"
backing = "flat"
facing = [0.0, 1.0, 0.0]
"#,
        x = PAD[0],
        z = PAD[2],
        urdf = panda.join("panda.urdf").display().to_string(),
        meshes = panda.join("meshes").display().to_string(),
    );
    if grasp {
        s.push_str(
            r#"
[[controller]]
type = "grasp"
robot = "panda"
joints = ["panda_finger_joint1"]
closed = [0.0]
speed = 0.01
force = 5.0
settle = 0.2
lift = { distance = 0.05, speed = 0.1 }
hold = 1.0
"#,
        );
    }
    s
}

fn scene(grasp: bool) -> Scene {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("panda.toml");
    std::fs::write(&path, scene_text(grasp)).unwrap();
    Scene::from_file(&path).unwrap()
}

#[test]
fn panda_loads_with_its_meshes_joints_limits_and_mimic() {
    let scene = scene(false);
    let robot = &scene.robots()[0];
    assert_eq!(
        robot.links().len(),
        13,
        "link0..8, hand, 2 fingers, grasptarget"
    );
    assert_eq!(robot.joints().len(), 12);
    let moving = (robot.joints().iter()).filter(|j| j.kind.moves()).count();
    assert_eq!(moving, 9, "7 arm joints and 2 fingers");
    let f1 = &robot.joints()[robot.joint_index("panda_finger_joint1").unwrap()];
    assert_eq!(f1.kind, JointKind::Prismatic);
    assert_eq!(f1.limits, [0.0, 0.04]);
    assert_eq!((f1.effort, f1.velocity), (Some(20.0), Some(0.2)));
    let f2 = &robot.joints()[robot.joint_index("panda_finger_joint2").unwrap()];
    let m = f2.mimic.unwrap();
    assert_eq!((m.multiplier, m.offset), (1.0, 0.0));
    let j4 = &robot.joints()[robot.joint_index("panda_joint4").unwrap()];
    assert_eq!(j4.limits, [J4_LOWER, 0.0]);
    assert_eq!((j4.effort, j4.velocity), (Some(87.0), Some(2.175)));

    // Every collision mesh resolved through package:// and loaded: one convex hull per mesh on
    // link0..7, the hand and the two fingers (link8 and grasptarget have none), but link6.obj
    // has 17 materials (`usemtl`), which the mesh loader reads as 17 meshes: 17 hulls.
    let built = scene.build();
    let colliders: Vec<usize> = built.handles.robots[0]
        .1
        .colliders
        .iter()
        .map(Vec::len)
        .collect();
    assert_eq!(colliders, [1, 1, 1, 1, 1, 1, 17, 1, 0, 1, 1, 1, 0]);

    // The pads where the URDF's kinematics put them (see PAD).
    let w = &built.world.physics;
    for (name, sign) in [("left_pad", -1.0), ("right_pad", 1.0)] {
        let t = w.colliders[built.handles.fingertip(name).unwrap()].translation();
        let want = [PAD[0], sign * PAD[1], PAD[2]];
        let got = [t.x as f64, t.y as f64, t.z as f64];
        for i in 0..3 {
            assert!(
                (got[i] - want[i]).abs() < 2e-4,
                "{name}: {got:?}, want {want:?}"
            );
        }
    }
}

/// The grasp closes the fingers at 10 mm/s until each pad presses 5 N, lifts the arm's base 5 cm
/// and holds: the box rises with it, each pad holding about 5 N (the hold does not close
/// further), the weight (1.96 N) carried by friction. Not right yet (issue 25): since the solve
/// sees multibody links the pads reach 5 N, and since the plugin carries a kinematic multibody
/// root the base lifts, but a pad reads 0 N in the hold (the box leaves a finger during the
/// lift; not yet understood: the shipped gripper and hand hold theirs, `tests/robots.rs`).
#[test]
#[ignore = "a Panda pad loses the box in the lift (0 N in the hold): not yet understood (issue 25)"]
fn panda_grasps_lifts_and_holds_the_box_with_soft_pads() {
    let scene = scene(true);
    let mut run = PlainRun::new(&scene);
    let box_h = run.handles.body("box").unwrap();
    let z0 = run.world.physics.bodies[box_h].translation().z as f64;
    let (mut reached, mut hold_forces, mut rise) = (false, Vec::new(), 0.0);
    for _ in 0..scene.steps() {
        run.step();
        reached |= !run.events().is_empty();
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            let mut f = [0.0; 2];
            for c in run.world.soft.contacts() {
                let k = usize::from(Some(c.fingertip) == run.handles.fingertip("right_pad"));
                f[k] += c.normal_force;
            }
            hold_forces.push(f);
            rise = run.world.physics.bodies[box_h].translation().z as f64 - z0;
        }
    }
    assert!(reached, "the grasp never reached 5 N");
    assert!(!hold_forces.is_empty(), "never held");
    for f in &hold_forces {
        for (k, v) in f.iter().enumerate() {
            assert!((4.5..6.5).contains(v), "pad {k} holds {v} N");
        }
    }
    assert!(
        (rise - 0.05).abs() < 2e-3,
        "the box rose {rise} m with the 5 cm lift"
    );
}
