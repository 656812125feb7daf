//! The shipped parallel gripper with `joints = "impulse"` (rapier impulse joints, the right
//! finger's motor following the left's target for its `<mimic>`) grasps as it does as a
//! multibody: on the box, the ball and the cylinder (`scenes/robots/parallel_gripper_*.toml`)
//! at 3, 5 and 7 N per pad, each run in both joint models.
//!
//! Before session 13 the impulse gripper's 5 N grasp on the box peaked at 15 N and dropped the
//! box: its fingers' joint anchors sat at the link origins, 31 mm from their centres of mass,
//! where rapier's one Gauss-Seidel sweep per solver pass does not converge over the finger's
//! joint rows, so the soft solve took each finger as a free body (`Robot::anchor_prismatic_at_com`).
//!
//! The tolerances come from the grasp primitive. It stops closing at the first step whose
//! force (the step average, as it reads it) reaches `F`; a pad's force grows per step by at
//! most the motor's stiffness times the target's advance, `k v dt` (2000 N/m x 10 mm/s x
//! 1/60 s = 0.333 N; the pad in series only softens it), so the force it stops at is in
//! `[F, F + k v dt)`. Once stopped, the motor's velocity target (`-v`) drops to 0 and with
//! it the damping's push `d v` (20 N s/m x 10 mm/s = 0.2 N): the held force is in
//! `[F - d v, F + k v dt)` (1 % of `F` more for the pads' relaxation into the object). The
//! peak (the largest substep force) may exceed the stopping step's average by the rise within
//! that step: 3 % (measured at most 1.2 %). Between the joint models: each stops within one
//! step's increment of `F`, so their peaks and held forces differ by less than `k v dt`. Hold
//! slip (the object's motion relative to the base from the hold's first step): issue 25's 100
//! um, and with the rigid stick (`set_friction_spring(false)`, the default before session 19)
//! below 25 um (measured at most 0.02 um in both models since session 30; before, 11.53 um,
//! the impulse gripper on the box at 3 N).
//!
//! With the friction spring (the default since session 19) the object hangs on the pads'
//! springs, `k_up = sum 8 G* a (1 - n_y^2)` (Mindlin), and the lift's stop (the base's last
//! speed, 0.0324 m/s, taken away in one step: ~1.95 m/s^2) stretches them by up to `m a /
//! k_up` (34-61 um here), which the hold's first steps ring out (`omega dt` ~3-4, not resolved
//! by the step). Session 20, measured: slip 1.6-31 um, 0.03-0.72 of `m a / k_up`, as the
//! multibody (fingers rigid vertically): bounded by it. The impulse fingers' joints are solved
//! by rapier's passes and may give vertically in series with the springs: session 30, slip
//! 0.56-33.8 um, 0.012-0.56 of `m a / k_up`; before session 30 13-61 um, up to 1.8 (the ball
//! at 3 N; 1.14 the cylinder at 7 N), while an impulse-jointed finger's substep count read its
//! motor's push as an approach velocity (its held forces then 2.5 % over the multibody's:
//! 3.126 N at 3 N on the ball, 3.000 N now). That compliance is not derived, so those runs
//! keep issue 25's 100 um. Both: no creep over the hold's second half (< 0.1 um, measured at
//! most 0.030 um), where a slipping pad or a drifting stretch would show.
//! `cargo test -p softgrip-scene --test impulse_grasp -- --nocapture` prints the numbers
//! (the table in SCENES.md; `cargo run --release -p softgrip-scene --example impulse_grasp
//! <scene> 3 5 7` prints the same with the time per step).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::{Path, PathBuf};

use softgrip_scene::control::Phase;
use softgrip_scene::{PlainRun, Scene};

/// The scenes' motor stiffness [N/m], damping [N s/m], closing speed [m/s] and step [s].
const K: f64 = 2000.0;
const D: f64 = 20.0;
const V: f64 = 0.01;
const DT: f64 = 1.0 / 60.0;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// One grasp run's numbers.
#[derive(Debug)]
struct Grasped {
    /// The smallest pad force the squeeze stopped at (the step average it read) \[N\].
    stopped_at: f64,
    /// The largest substep force of any pad \[N\].
    peak: f64,
    /// Each pad's force at the end of the hold \[N\].
    held: Vec<f64>,
    /// The object's largest motion relative to the hand's base over the hold \[m\].
    slip: f64,
    /// The same over the hold's second half (from its middle step) \[m\].
    late: f64,
    /// The stretch the lift's stop puts on the pads' friction springs, `m a / k_up` \[m\]:
    /// the object's mass, the base's velocity change as the hold starts / dt, over the pads'
    /// summed vertical spring stiffness `sum 8 G* a (1 - n_y^2)` (Mindlin; as the plugin) at
    /// the lift's last step.
    ringing: f64,
}

/// `scenes/robots/parallel_gripper_{object}.toml` with `joints = model` and the grasp at
/// `force` \[N\], the pads' friction spring on (the default) or off (the rigid stick).
fn grasp(object: &str, model: &str, force: f64, spring: bool) -> Grasped {
    let path = repo().join(format!("scenes/robots/parallel_gripper_{object}.toml"));
    let mut text = String::new();
    for line in std::fs::read_to_string(&path).unwrap().lines() {
        if line.starts_with("force =") {
            text.push_str(&format!("force = {force}\n"));
            continue;
        }
        text.push_str(line);
        text.push('\n');
        if line.starts_with("urdf =") {
            text.push_str(&format!("joints = \"{model}\"\n"));
        }
    }
    assert!(
        text.contains(&format!("force = {force}\n")),
        "{object}: no force"
    );
    let scene = Scene::parse(&text, "gripper.toml", path.parent().unwrap()).unwrap();
    let mut run = PlainRun::new(&scene);
    run.world.soft.set_friction_spring(spring);
    let obj = run.handles.body(object).unwrap();
    let base = run.handles.robots[0].1.links[scene.robots()[0].root()];
    let pads: Vec<_> = ["left_pad", "right_pad"]
        .iter()
        .map(|n| run.handles.fingertip(n).unwrap())
        .collect();
    let (mut stopped_at, mut peak) = (f64::NAN, 0.0f64);
    let (mut held, mut hold) = (Vec::new(), Vec::<[f64; 3]>::new());
    // The forces the controller read at the start of the step (those of the step before).
    let mut read = vec![0.0; pads.len()];
    // The base's height at the last two steps, its speed as the hold starts, and the pads'
    // summed vertical spring stiffness at the lift's last step.
    let (mut base_y, mut stop, mut k_up) = ([0.0f64; 2], f64::NAN, 0.0);
    for _ in 0..scene.steps() {
        run.step();
        base_y = [
            base_y[1],
            f64::from(run.world.physics.bodies[base].translation().y),
        ];
        if run.control.controllers()[0].phase() == Some(Phase::Lift) {
            k_up = 0.0;
            for c in run.world.soft.contacts() {
                if run.world.physics.colliders[c.other].parent() != Some(obj) {
                    continue;
                }
                let m = run.world.soft.fingertip(c.fingertip).unwrap().material();
                let g_star = m.shear_modulus() / (2.0 - m.poisson_ratio());
                let n = c.reading.normal;
                k_up += 8.0 * g_star * c.patch().equivalent_radius() * (1.0 - n[1] * n[1]);
            }
        }
        let f: Vec<f64> = (pads.iter())
            .map(|&p| run.world.soft.contacts_of(p).map(|c| c.normal_force).sum())
            .collect();
        for &p in &pads {
            for c in run.world.soft.contacts_of(p) {
                peak = peak.max(c.peak_normal_force);
            }
        }
        if !run.events().is_empty() && stopped_at.is_nan() {
            stopped_at = read.iter().copied().fold(f64::INFINITY, f64::min);
        }
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            if hold.is_empty() {
                stop = (base_y[1] - base_y[0]) / DT;
            }
            let b = &run.world.physics.bodies;
            let (o, h) = (b[obj].translation(), b[base].translation());
            hold.push([o.x - h.x, o.y - h.y, o.z - h.z].map(f64::from));
            held.clone_from(&f);
        }
        read = f;
    }
    assert!(hold.len() > 2, "{object} {model} {force} N: never held");
    let slip = common::excursion(&hold, 0);
    let mass = f64::from(run.world.physics.bodies[obj].mass());
    let g = Grasped {
        stopped_at,
        peak,
        held,
        slip,
        late: common::excursion(&hold, hold.len() / 2),
        ringing: mass * (stop.abs() / DT) / k_up,
    };
    eprintln!(
        "{object} {model:9} {force} N spring {spring}: stopped at {:.4} N, peak {:.4} N, held \
         {:.4?} N, slip {:.2} um (m a / k_up {:.2} um: {:.3} of it; k_up {k_up:.1} N/m, the \
         base's last speed {stop:.5} m/s), second half {:.4} um",
        g.stopped_at,
        g.peak,
        g.held,
        g.slip * 1e6,
        g.ringing * 1e6,
        g.slip / g.ringing,
        g.late * 1e6
    );
    g
}

/// Every bound of the module's header on one run at `force` \[N\] in joint model `model`;
/// the hold slip's for the friction spring (`spring`) or the rigid stick.
fn check(g: &Grasped, force: f64, model: &str, what: &str, spring: bool) {
    let step = K * V * DT;
    assert!(
        g.stopped_at >= force && g.stopped_at < force + step,
        "{what}: {g:?}"
    );
    assert!(g.peak < 1.03 * (force + step), "{what}: peak, {g:?}");
    for &f in &g.held {
        assert!(
            f >= force - D * V - 0.01 * force && f < force + step,
            "{what}: held, {g:?}"
        );
    }
    assert!(
        (g.held[0] - g.held[1]).abs() < 0.01 * force,
        "{what}: pads, {g:?}"
    );
    if spring {
        assert!(g.slip < 100e-6, "{what}: slip (issue 25), {g:?}");
        if model == "multibody" {
            assert!(g.slip < g.ringing, "{what}: slip against m a / k_up, {g:?}");
        }
        assert!(
            g.late < 1e-7,
            "{what}: creep over the hold's second half, {g:?}"
        );
    } else {
        assert!(g.slip < 25e-6, "{what}: slip (rigid stick), {g:?}");
    }
}

/// `object` at 3, 5 and 7 N in both joint models, with the friction spring (`spring`) or the
/// rigid stick: each within the bounds, and the impulse run within one step's force increment
/// of the multibody run.
fn both_models(object: &str, spring: bool) {
    for force in [3.0, 5.0, 7.0] {
        let mb = grasp(object, "multibody", force, spring);
        let ij = grasp(object, "impulse", force, spring);
        let what = |model| format!("{object} {model} {force} N spring {spring}");
        check(&mb, force, "multibody", &what("multibody"), spring);
        check(&ij, force, "impulse", &what("impulse"), spring);
        let step = K * V * DT;
        assert!(
            (ij.peak - mb.peak).abs() < step,
            "{object} {force} N: peaks {} vs {}",
            ij.peak,
            mb.peak
        );
        for (a, b) in ij.held.iter().zip(&mb.held) {
            assert!((a - b).abs() < step, "{object} {force} N: held {a} vs {b}");
        }
    }
}

#[test]
fn impulse_gripper_grasps_the_box_as_the_multibody() {
    both_models("box", true);
}

#[test]
fn impulse_gripper_grasps_the_box_as_the_multibody_rigid_stick() {
    both_models("box", false);
}

#[test]
fn impulse_gripper_grasps_the_ball_as_the_multibody() {
    both_models("ball", true);
}

#[test]
fn impulse_gripper_grasps_the_ball_as_the_multibody_rigid_stick() {
    both_models("ball", false);
}

#[test]
fn impulse_gripper_grasps_the_cylinder_as_the_multibody() {
    both_models("cylinder", true);
}

#[test]
fn impulse_gripper_grasps_the_cylinder_as_the_multibody_rigid_stick() {
    both_models("cylinder", false);
}

/// The anchors' move keeps the joints as the URDF has them: built with impulse joints, each
/// finger's joint frames have their origin at the finger's centre of mass (pad included, to
/// 1e-7 m), and every link stands where the multibody build puts it (1e-6 m), its joint at its
/// start position (1e-7 m).
#[test]
fn anchors_at_the_centre_of_mass_keep_the_urdf_joints() {
    use softgrip_scene::robot::{RobotJointHandle, joint_state};
    let build = |model: &str| {
        let to = format!("joints = \"{model}\"\nurdf = ");
        let edits = [("urdf = ", to.as_str())];
        let scene = common::shipped_robot_scene("parallel_gripper_box", &edits).unwrap();
        let built = scene.build();
        (scene, built)
    };
    let (_, mb) = build("multibody");
    let (scene, ij) = build("impulse");
    let robot = &scene.robots()[0];
    let (hm, hi) = (&mb.handles.robots[0].1, &ij.handles.robots[0].1);
    let w = &ij.world.physics;
    for (l, (a, b)) in hm.links.iter().zip(&hi.links).enumerate() {
        let (a, b) = (
            mb.world.physics.bodies[*a].translation(),
            w.bodies[*b].translation(),
        );
        assert!((a - b).length() < 1e-6, "link {l}: {a:?} vs {b:?}");
    }
    let mut moved = 0;
    for (j, (joint, handle)) in robot.joints().iter().zip(&hi.joints).enumerate() {
        let RobotJointHandle::Impulse(handle) = *handle else {
            panic!("joint {j} is not an impulse joint");
        };
        let child = &w.bodies[hi.links[joint.child]];
        let frame2 = w.impulse_joints.get(handle).unwrap().data.local_frame2;
        let off = (frame2.translation - child.local_center_of_mass()).length();
        assert!(off < 1e-7, "{}: anchor {off} m off", joint.name);
        // Not the link's origin (the URDF's joint origin): the centre of mass is 31 mm away.
        assert!(
            child.local_center_of_mass().length() > 0.03,
            "{}",
            joint.name
        );
        let q = joint_state(robot, w, hi, j, 1.0 / 60.0).position;
        assert!((q - 0.028).abs() < 1e-7, "{}: {q}", joint.name);
        moved += 1;
    }
    assert_eq!(moved, 2);
}

/// Each impulse finger joint's effort (minus its own motor's impulse, rapier's write-back of its
/// last solver pass, over that pass) equals `-J^T F` of its own finger's load within 1 % at the end of the hold
/// (issue 25 item 8), for the driven joint and its mimic alike: with impulse joints the mimic
/// has its own motor, so the driven joint carries one pad, not two (`robot::joint_load`).
#[test]
fn impulse_finger_efforts_equal_jt_f() {
    use softgrip_scene::robot::{joint_load, joint_state_loaded};
    let edits = [("urdf = ", "joints = \"impulse\"\nurdf = ")];
    let scene = common::shipped_robot_scene("parallel_gripper_box", &edits).unwrap();
    let mut run = PlainRun::new(&scene);
    let robot = scene.robots()[0].clone();
    let h = run.handles.robots[0].1.clone();
    let mut last = Vec::new();
    for _ in 0..scene.steps() {
        run.step();
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            let n = run.world.soft.counters().substeps_last.max(1) as f64;
            last = (0..robot.joints().len())
                .map(|j| {
                    let s = joint_state_loaded(&robot, &run.world, &h, j, DT / n);
                    (j, s.effort, joint_load(&robot, &run.world, &h, j))
                })
                .collect();
        }
    }
    assert_eq!(last.len(), 2, "the grasp held");
    for (j, effort, load) in last {
        let name = &robot.joints()[j].name;
        let rel = (effort + load).abs() / load.abs();
        eprintln!("{name}: effort {effort:.5} N, J^T F {load:.5} N ({rel:.2e})");
        assert!(rel < 0.01, "{name}: effort {effort} vs J^T F {load}");
        assert!(
            (load.abs() - 5.0).abs() < K * V * DT,
            "{name}: J^T F {load}"
        );
    }
}

/// `SoftCounters::jointed_free` names the failure this file is about: the impulse gripper's
/// fingers are seen through their joints in every (sub)step of the grasp (0), and so are the
/// three-finger hand's hinged fingers with the sweeps the scene gives their links
/// (`Robot::set_jointed_sweeps`, `tests/impulse_hand.rs`), where at rapier's one sweep per
/// pass (those taken away) they are not: counted.
#[test]
fn jointed_free_counts_the_links_the_solve_takes_as_free() {
    let count = |name: &str, steps: u64, own_sweeps_only: bool| {
        let edits = [("urdf = ", "joints = \"impulse\"\nurdf = ")];
        let scene = common::shipped_robot_scene(name, &edits).unwrap();
        let mut run = PlainRun::new(&scene);
        for &l in run.handles.robots[0]
            .1
            .links
            .iter()
            .filter(|_| own_sweeps_only)
        {
            run.world.physics.bodies[l].set_additional_pgs_iterations(0);
        }
        for _ in 0..steps {
            run.step();
        }
        let c = run.world.soft.counters();
        eprintln!(
            "{name}: jointed_free {} over {} substeps",
            c.jointed_free, c.substeps_total
        );
        c.jointed_free
    };
    // The gripper through its grip (step 45) and lift.
    assert_eq!(count("parallel_gripper_box", 100, false), 0);
    assert_eq!(count("three_finger_hand_ball", 40, false), 0);
    assert!(count("three_finger_hand_ball", 40, true) > 0);
}
