//! `[[robot]]`: URDF robots in scenes (issue 25): the shipped parallel gripper loads with its
//! links, joints, limits and mimic; meshes resolved through `package://` and `file://`; every
//! bad input is an error naming the file, the link or joint and the value.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::{Path, PathBuf};

use softgrip_scene::control::Phase;
use softgrip_scene::robot::JointKind;
use softgrip_scene::{PlainRun, Scene};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn gripper_scene() -> Scene {
    Scene::from_file(&repo().join("scenes/robots/parallel_gripper_box.toml")).unwrap()
}

#[test]
fn shipped_gripper_loads_with_its_joints_limits_and_mimic() {
    let scene = gripper_scene();
    let robot = &scene.robots()[0];
    let links: Vec<_> = robot.links().iter().map(|l| l.name.as_str()).collect();
    assert_eq!(links, ["base_link", "left_finger", "right_finger"]);
    let j = &robot.joints()[robot.joint_index("finger_joint").unwrap()];
    assert_eq!(j.kind, JointKind::Prismatic);
    assert_eq!(j.limits, [0.0, 0.0425]);
    assert_eq!((j.effort, j.velocity), (Some(20.0), Some(0.1)));
    assert_eq!(j.initial, 0.028);
    let m = robot.joints()[robot.joint_index("right_finger_joint").unwrap()]
        .mimic
        .unwrap();
    assert_eq!((m.multiplier, m.offset), (1.0, 0.0));
    assert_eq!(robot.frame(1), "gripper/left_finger");
}

/// The pads start where the scene puts them: 4 mm from the box's faces, at its mid-height.
#[test]
fn pads_start_on_the_fingers_at_the_initial_opening() {
    let scene = gripper_scene();
    let built = scene.build();
    let w = &built.world.physics;
    let pos = |name: &str| {
        let c = built.handles.fingertip(name).unwrap();
        let t = w.colliders[c].translation();
        [t.x as f64, t.y as f64, t.z as f64]
    };
    let (l, r) = (pos("left_pad"), pos("right_pad"));
    assert!(
        (l[0] + 0.034).abs() < 1e-6 && (r[0] - 0.034).abs() < 1e-6,
        "{l:?} {r:?}"
    );
    assert!(
        (l[1] - 0.02).abs() < 1e-6 && (r[1] - 0.02).abs() < 1e-6,
        "{l:?} {r:?}"
    );
}

/// The mimic finger follows the driven one in both joint models: the gripper closes in the air
/// (the box moved 0.5 m away) from 28 mm to 10 mm and opens again; the two finger joints stay
/// equal.
#[test]
fn mimic_finger_follows_in_both_joint_models() {
    for model in ["multibody", "impulse"] {
        let path = repo().join("scenes/robots/parallel_gripper_box.toml");
        let text = std::fs::read_to_string(&path)
            .unwrap()
            .replace("position = [0.0, 0.02, 0.0]", "position = [0.5, 0.02, 0.0]")
            .replace("closed = [0.0]", "closed = [0.01]") // pads 12 mm apart
            .replace(
                "initial = { finger_joint = 0.028 }",
                &format!("initial = {{ finger_joint = 0.028 }}\njoints = \"{model}\""),
            );
        let scene = Scene::parse(&text, "gripper.toml", path.parent().unwrap()).unwrap();
        let mut run = PlainRun::new(&scene);
        let robot = &scene.robots()[0];
        let h = run.handles.robots[0].1.clone();
        let (left, right) = (
            robot.joint_index("finger_joint").unwrap(),
            robot.joint_index("right_finger_joint").unwrap(),
        );
        let (mut worst, mut closed) = (0.0f64, f64::INFINITY);
        for _ in 0..scene.steps() {
            run.step();
            let s = |j| {
                softgrip_scene::robot::joint_state(robot, &run.world.physics, &h, j, 1.0 / 60.0)
            };
            worst = worst.max((s(left).position - s(right).position).abs());
            closed = closed.min(s(left).position);
        }
        eprintln!("{model}: mimic off by at most {worst:e} m, closed to {closed:e} m");
        assert!(worst < 1e-5, "{model}: the mimic finger is {worst:e} m off");
        assert!(
            (closed - 0.01).abs() < 1e-4,
            "{model}: closed to {closed} m"
        );
    }
}

/// What [`gripper_grasp`] measured.
#[derive(Debug)]
struct GripperGrasp {
    reached: bool,
    peak_x: f64,
    /// How far the box and the base rose by the end of the hold \[m\].
    lifted: f64,
    base_lift: f64,
    /// The box's largest motion relative to the base over the hold: from its first step, from
    /// its second (creep) and over its second half (from its middle step) \[m\].
    slip: f64,
    creep: f64,
    late: f64,
    /// The pads' total normal force at the end of the hold \[N\].
    hold_force: f64,
    /// The ringing's bound `m a / k_up` \[m\]: the box's mass, the base's velocity change
    /// over the hold's first step (the lift's last) / dt, over the pads' friction springs'
    /// summed vertical stiffness `sum 8 G* a (1 - n_y^2)` (Mindlin; as the plugin) at the
    /// lift's last step.
    ringing: f64,
}

/// The shipped gripper grasps, lifts and holds the 200 g box, its pads' friction spring on
/// (the default) or off (the rigid stick).
fn gripper_grasp(spring: bool) -> GripperGrasp {
    let scene = gripper_scene();
    let dt = scene.file().dt;
    let mut run = PlainRun::new(&scene);
    run.world.soft.set_friction_spring(spring);
    let box_h = run.handles.body("box").unwrap();
    let base = run.handles.robots[0].1.links[0];
    let (mut reached, mut peak_x, mut lifted, mut base_lift) = (false, 0.0f64, 0.0, 0.0);
    // The box relative to the base at each hold step.
    let mut hold: Vec<[f64; 3]> = Vec::new();
    let mut hold_force = 0.0;
    // The base's height at the last two steps, and the pads' summed vertical spring stiffness
    // at the lift's last step.
    let (mut base_y, mut k_up) = ([0.0f64; 2], 0.0);
    let mut stop = f64::NAN;
    for _ in 0..scene.steps() {
        run.step();
        reached |= !run.events().is_empty();
        let w = &run.world.physics;
        peak_x = run
            .world
            .soft
            .contacts()
            .iter()
            .map(|c| c.max_x)
            .fold(peak_x, f64::max);
        base_y = [base_y[1], w.bodies[base].translation().y as f64];
        let phase = run.control.controllers()[0].phase();
        if phase == Some(Phase::Lift) {
            k_up = 0.0;
            for c in run.world.soft.contacts() {
                if w.colliders[c.other].parent() != Some(box_h) {
                    continue;
                }
                let m = run.world.soft.fingertip(c.fingertip).unwrap().material();
                let g_star = m.shear_modulus() / (2.0 - m.poisson_ratio());
                let n = c.reading.normal;
                k_up += 8.0 * g_star * c.patch().equivalent_radius() * (1.0 - n[1] * n[1]);
            }
        }
        if phase == Some(Phase::Hold) {
            if hold.is_empty() {
                // The base's speed at the lift's last step, stopped over this one [m/s].
                stop = (base_y[1] - base_y[0]) / dt;
            }
            let rel = w.bodies[box_h].translation() - w.bodies[base].translation();
            hold.push([rel.x as f64, rel.y as f64, rel.z as f64]);
            lifted = w.bodies[box_h].translation().y as f64 - 0.02;
            base_lift = w.bodies[base].translation().y as f64 - 0.065;
            hold_force = run
                .world
                .soft
                .contacts()
                .iter()
                .map(|c| c.normal_force)
                .sum();
        }
    }
    assert!(hold.len() > 2, "the grasp never held");
    let mass = run.world.physics.bodies[box_h].mass() as f64;
    let g = GripperGrasp {
        reached,
        peak_x,
        lifted,
        base_lift,
        slip: common::excursion(&hold, 0),
        creep: common::excursion(&hold, 1),
        late: common::excursion(&hold, hold.len() / 2),
        hold_force,
        ringing: mass * (stop.abs() / dt) / k_up,
    };
    eprintln!(
        "spring {spring}: base lifted {:.6} m, box lifted {:.6} m, hold slip {:.2} um (after \
         the stop step {:.3} um, over the second half {:.4} um), m a / k_up {:.3} um (mass \
         {mass:.4} kg, the base's last speed {stop:.5} m/s, k_up {k_up:.1} N/m), pads' total \
         force at the end of the hold {:.4} N, peak x {:.4}",
        g.base_lift,
        g.lifted,
        g.slip * 1e6,
        g.creep * 1e6,
        g.late * 1e6,
        g.ringing * 1e6,
        g.hold_force,
        g.peak_x
    );
    g
}

/// The checks of both runs: reached, peak x, lifted, slip, the pads' force.
fn check_gripper_grasp(g: &GripperGrasp) {
    assert!(g.reached, "the grasp never reached its force");
    assert!(
        g.peak_x < 0.3,
        "peak x {}: a 5 N squeeze of this pad is x ~ 0.1",
        g.peak_x
    );
    assert!((g.base_lift - 0.1).abs() < 1e-6, "{g:?}: hand lifted");
    assert!((g.lifted - 0.1).abs() < 5e-4, "{g:?}: box lifted");
    assert!(g.slip < 100e-6, "{g:?}: hold slip");
    assert!(
        (g.hold_force - 10.0).abs() < 0.5,
        "{g:?}: pads hold 2 x 5 N"
    );
}

/// The grasp reaches its force on the 200 g box (5 N per pad), lifts it 10 cm and holds it
/// 2 s (issue 25 item 8: hold slip < 100 um). The hand's base is the multibody's kinematic
/// root: the plugin moves it (rapier 0.36.1 overwrites a root's `next_position`), the soft rows
/// carry the links by the root's displacement. Slip: the box's motion relative to the hand's
/// base over the hold, from the first hold step (6.9 um: the lift slows down at 1 m/s^2; it was
/// 92 um when the hand stopped dead from 0.1 m/s in one step) and after that step (creep while
/// held).
///
/// With the friction spring (the default since session 19) the box hangs on the pads' springs
/// (`omega dt` ~3-4, not resolved by the step): the hold's first step stops the base from the
/// lift's last speed, and the box rings that out over the next steps (session 20: 1.90 um from
/// the second step). That motion is bounded by the stretch the stop puts on the springs, `m a
/// / k_up` (`GripperGrasp::ringing`), and none is left over the hold's second half (< 0.1
/// um: a slipping pad or a drifting stretch would show there). The old creep bound (< 0.1 um
/// from the second step) was set for the rigid stick: kept in its run
/// (`grasp_lifts_the_box_with_the_rigid_stick`).
#[test]
fn grasp_reaches_its_force_and_lifts_the_box() {
    let g = gripper_grasp(true);
    check_gripper_grasp(&g);
    assert!(g.creep < g.ringing, "{g:?}: creep against m a / k_up");
    assert!(g.late < 1e-7, "{g:?}: creep over the hold's second half");
}

/// [`grasp_reaches_its_force_and_lifts_the_box`] with the rigid stick
/// (`set_friction_spring(false)`): no creep after the hold's first step (< 0.1 um).
#[test]
fn grasp_lifts_the_box_with_the_rigid_stick() {
    let g = gripper_grasp(false);
    check_gripper_grasp(&g);
    assert!(g.creep < 1e-7, "{g:?}: the held box creeps");
}

/// A scene of one robot from `urdf` (text, written to a fresh folder with `files`).
fn robot_scene(
    urdf: &str,
    robot_extra: &str,
    files: &[(&str, &str)],
) -> (tempfile::TempDir, Result<Scene, String>) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("robot.urdf"), urdf).unwrap();
    for (name, text) in files {
        let p = dir.path().join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
    let scene =
        format!("duration = 0.1\n[[robot]]\nname = \"r\"\nurdf = \"robot.urdf\"\n{robot_extra}\n");
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, scene).unwrap();
    let s = Scene::from_file(&path).map_err(|e| e.to_string());
    (dir, s)
}

const TETRA: &str =
    "v 0 0 0\nv 0.01 0 0\nv 0 0.01 0\nv 0 0 0.01\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

fn mesh_urdf(filename: &str) -> String {
    format!(
        r#"<robot name="m"><link name="base"><inertial><mass value="1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial>
        <collision><geometry><mesh filename="{filename}"/></geometry></collision></link></robot>"#
    )
}

#[test]
fn package_and_file_meshes_resolve_and_load() {
    let files = [("pkg/meshes/tetra.obj", TETRA)];
    let (_d, s) = robot_scene(
        &mesh_urdf("package://my_pkg/meshes/tetra.obj"),
        "package_paths = { my_pkg = \"pkg\" }",
        &files,
    );
    let scene = s.unwrap();
    let built = scene.build();
    assert_eq!(
        built.handles.robots[0].1.colliders[0].len(),
        1,
        "the mesh is a collider"
    );
    let (d, _) = robot_scene("<robot name=\"x\"><link name=\"a\"/></robot>", "", &files);
    let abs = d.path().join("pkg/meshes/tetra.obj");
    let (_d2, s) = robot_scene(&mesh_urdf(&format!("file://{}", abs.display())), "", &[]);
    assert_eq!(s.unwrap().build().handles.robots[0].1.colliders[0].len(), 1);
}

#[test]
fn a_mesh_that_does_not_load_is_an_error_naming_the_file() {
    let (_d, s) = robot_scene(&mesh_urdf("meshes/missing.stl"), "", &[]);
    let e = s.unwrap_err();
    assert!(
        e.contains("robot[0].urdf")
            && e.contains("link `base`")
            && e.contains("meshes/missing.stl"),
        "{e}"
    );
    let (_d, s) = robot_scene(
        &mesh_urdf("bad.obj"),
        "",
        &[("bad.obj", "v 0 0 0\nf 1 2 3\n")],
    );
    let e = s.unwrap_err();
    assert!(e.contains("bad.obj"), "{e}");
    let (_d, s) = robot_scene(&mesh_urdf("package://nope/a.obj"), "", &[]);
    let e = s.unwrap_err();
    assert!(e.contains("package `nope`"), "{e}");
}

const TWO_LINKS: &str = r#"<robot name="t">
  <link name="a"><inertial><mass value="1"/><inertia ixx="1e-3" ixy="0" ixz="0" iyy="1e-3" iyz="0" izz="1e-3"/></inertial></link>
  <link name="b"><inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial>
    <collision><origin xyz="0 0 -0.05"/><geometry><box size="0.01 0.01 0.1"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="2"/></joint>
</robot>"#;

#[test]
fn bad_joints_and_keys_are_errors_naming_the_joint_and_value() {
    let cases = [
        (
            TWO_LINKS.replace("lower=\"-1\"", "lower=\"2\""),
            "",
            "joint `j`",
        ),
        (
            TWO_LINKS.replace("xyz=\"0 1 0\"", "xyz=\"0 0 0\""),
            "",
            "axis",
        ),
        (TWO_LINKS.replace("revolute", "planar"), "", "Planar"),
        (
            TWO_LINKS.replace("effort=\"5\"", "effort=\"-5\""),
            "",
            "effort",
        ),
        (
            TWO_LINKS.replace("<parent link=\"a\"/>", "<parent link=\"zz\"/>"),
            "",
            "`zz`",
        ),
        (
            TWO_LINKS.to_string(),
            "initial = { j = 3.0 }",
            "robot[0].initial.j",
        ),
        (
            TWO_LINKS.to_string(),
            "initial = { k = 0.0 }",
            "robot[0].initial.k",
        ),
        (
            TWO_LINKS.to_string(),
            "joints = \"rigid\"",
            "unknown variant",
        ),
        (
            TWO_LINKS.replace("<mass value=\"0.1\"/>", "<mass value=\"nan\"/>"),
            "",
            "mass",
        ),
        (
            TWO_LINKS.to_string(),
            "self_contacts = 0",
            "scene.toml:5:17: invalid type: integer `0`, expected a boolean",
        ),
    ];
    for (urdf, extra, want) in cases {
        let (_d, s) = robot_scene(&urdf, extra, &[]);
        let e = s.unwrap_err();
        assert!(e.contains(want), "`{want}` not in: {e}");
    }
}

/// The start position is applied, in both joint models; the link hangs where the URDF says.
#[test]
fn start_positions_place_the_links_in_both_joint_models() {
    for model in ["multibody", "impulse"] {
        let (_d, s) = robot_scene(
            TWO_LINKS,
            &format!("joints = \"{model}\"\ninitial = {{ j = 0.5 }}"),
            &[],
        );
        let scene = s.unwrap();
        let built = scene.build();
        let h = &built.handles.robots[0].1;
        let b = &built.world.physics.bodies[h.links[1]];
        // Rotated 0.5 rad about +y: the link's frame's z axis tilts towards +x.
        let z = b.rotation() * softgrip_scene::softgrip_rapier::rapier3d::prelude::Vector::Z;
        assert!((z.x as f64 - 0.5f64.sin()).abs() < 1e-5, "{model}: {z:?}");
        let s = softgrip_scene::robot::joint_state(
            &scene.robots()[0],
            &built.world.physics,
            h,
            0,
            1.0 / 60.0,
        );
        assert!((s.position - 0.5).abs() < 1e-5, "{model}: {}", s.position);
    }
}

/// A position command from outside moves a joint no faster than its URDF `velocity`: the
/// shipped gripper (0.1 m/s) commanded from 28 mm to 40 mm moves at 0.1 m/s, not 13 mm in one
/// 16.7 ms step as before, and holds the command (after a 1.3 mm overshoot when the ramp's
/// velocity target drops to 0).
#[test]
fn outside_commands_move_joints_at_most_at_their_urdf_velocity() {
    let path = repo().join("scenes/robots/parallel_gripper_box.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let (head, _grasp) = text.split_once("[[controller]]").unwrap();
    let scene = Scene::parse(head, "gripper.toml", path.parent().unwrap()).unwrap();
    let mut run = PlainRun::new(&scene);
    let robot = &scene.robots()[0];
    let h = run.handles.robots[0].1.clone();
    let j = robot.joint_index("finger_joint").unwrap();
    let inbox = run.control.inbox(0).unwrap();
    inbox
        .lock()
        .unwrap()
        .commands
        .push(softgrip_scene::control::JointCommand {
            name: "finger_joint".into(),
            position: Some(0.04),
            velocity: None,
        });
    let dt = scene.file().dt;
    let mut q = Vec::new();
    for _ in 0..30 {
        run.step();
        q.push(softgrip_scene::robot::joint_state(robot, &run.world.physics, &h, j, dt).position);
    }
    // The ramp's target after k steps is 28 mm + k · 0.1 m/s · dt; rapier's motor ends a step
    // at about its position target + velocity target · dt (one step ahead, as the grasp's).
    let step = 0.1 * dt;
    assert!(q[0] - 0.028 < 2.0 * step + 1e-4, "first step to {} m", q[0]);
    let speed = (q[5] - q[1]) / (4.0 * dt);
    assert!((speed - 0.1).abs() < 0.005, "{speed} m/s");
    let last = q[29];
    assert!((last - 0.04).abs() < 2e-4, "held at {last} m");
}

/// The shipped three-finger hand closes on the ball symmetrically: the three fingers' joint
/// frames are 120 degrees apart, so the three pads touch the ball in the same step with the
/// same force (to 1e-3 relative) and the ball is not pushed off the hand's axis (< 1 um). What
/// the pads press is the solver's business (issue 23: the links are solved as free bodies, and
/// a multibody link loses the soft impulse), so the force itself is not asserted here.
#[test]
fn three_finger_hand_closes_on_the_ball_symmetrically() {
    let path = repo().join("scenes/robots/three_finger_hand_ball.toml");
    let scene = Scene::from_file(&path).unwrap();
    assert_eq!(scene.robots()[0].joints().len(), 6);
    let mut run = PlainRun::new(&scene);
    let ball = run.handles.body("ball").unwrap();
    let pads: Vec<_> = (0..3)
        .map(|f| run.handles.fingertip(&format!("f{f}_pad")).unwrap())
        .collect();
    let mut touched = 0;
    for _ in 0..60 {
        run.step();
        let force = |h| -> f64 {
            (run.world.soft.contacts_of(h))
                .map(|c| c.normal_force)
                .sum()
        };
        let f: Vec<f64> = pads.iter().map(|&h| force(h)).collect();
        let k: f64 = (pads.iter())
            .flat_map(|&h| run.world.soft.contacts_of(h).map(|c| c.stiffness))
            .fold(0.0, f64::max);
        let touching = f.iter().filter(|&&x| x > 0.0).count();
        assert!(touching == 0 || touching == 3, "pads touching alone: {f:?}");
        if touching == 3 {
            touched += 1;
            let mean = f.iter().sum::<f64>() / 3.0;
            for x in &f {
                // The fingers are rotated copies in f32: a pad's pole is placed to a few 1e-8 m
                // (f32 steps at 0.1 m), worth K x 3e-8 of force at first touch (0.0039 N per
                // pad, 2.6e-5 N apart). In the hold the pads stay within 0.15 % of their mean
                // (1.3 N; the solve's friction sweeps visit them in order); 0.3 % bounds it.
                let tol = 3e-3 * mean + k * 3e-8;
                assert!((x - mean).abs() <= tol, "pad forces {f:?}");
            }
        }
        let p = run.world.physics.bodies[ball].translation();
        let off = ((p.x as f64).powi(2) + (p.z as f64).powi(2)).sqrt();
        assert!(off < 1e-6, "ball pushed {off} m off the axis");
    }
    assert!(
        touched > 10,
        "the pads touched the ball in {touched} of 60 steps"
    );
}

/// The shipped three-finger hand grasps its 50 g ball at 1 N per pad, lifts it 5 cm with the
/// hand's base (a multibody's kinematic root, carried by the plugin) and holds it: the ball
/// rises with the hand and stays put in it after the hold's first step; each pad presses at
/// least the grasp's 1 N through the hold.
#[test]
fn three_finger_hand_lifts_and_holds_the_ball() {
    let path = repo().join("scenes/robots/three_finger_hand_ball.toml");
    let scene = Scene::from_file(&path).unwrap();
    let mut run = PlainRun::new(&scene);
    let ball = run.handles.body("ball").unwrap();
    let base = run.handles.robots[0].1.links[0];
    let start = run.world.physics.bodies[ball].translation().y as f64;
    let mut hold: Vec<f64> = Vec::new();
    let (mut rise, mut weakest) = (0.0f64, f64::INFINITY);
    for _ in 0..scene.steps() {
        run.step();
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            let w = &run.world.physics;
            let y = w.bodies[ball].translation().y as f64;
            hold.push(y - w.bodies[base].translation().y as f64);
            rise = y - start;
            for c in run.world.soft.contacts() {
                weakest = weakest.min(c.normal_force);
            }
        }
    }
    assert!(hold.len() > 2, "the hand never held");
    let worst_from = |k: usize| {
        hold[k..]
            .iter()
            .map(|r| (r - hold[k]).abs())
            .fold(0.0, f64::max)
    };
    let (slip, creep) = (worst_from(0), worst_from(1));
    eprintln!(
        "three-finger hand: ball rose {rise:.6} m, hold slip {:.3} um ({:.3} um after the \
         stop step), weakest pad {weakest:.4} N",
        slip * 1e6,
        creep * 1e6
    );
    assert!((rise - 0.05).abs() < 1e-3, "ball rose {rise} m");
    // Issue 25's hold slip (< 100 um); the creep after the stop within a tenth of it.
    assert!(slip < 100e-6, "hold slip {slip} m");
    assert!(creep < 10e-6, "the held ball creeps {creep} m");
    assert!(weakest > 1.0 && weakest < 1.5, "weakest pad {weakest} N");
}
