//! The shipped three-finger hand (three fingers of two revolute joints each) with
//! `joints = "impulse"` grasps the ball, the box and the cylinder
//! (`scenes/robots/three_finger_hand_*.toml`: 1, 2 and 1 N per pad) as the multibody hand does.
//!
//! Before session 13 it did not: a hinged finger's assembly converges under rapier's
//! Gauss-Seidel sweeps at a rate of 0.978 per sweep (the motor row turns the link about its
//! centre of mass, off the hinge), so it needs 518 sweeps per solver pass where rapier runs
//! one; the soft solve took the fingers as free bodies (`SoftCounters::jointed_free` 4403 on
//! the ball; still 10420 with 256 sweeps more on the links), the pads read a fraction of their
//! force, the motors drove the fingers through the ball and the ball dropped (default sweeps)
//! or the pads peaked at 122 N (256 more). The scene now gives an impulse robot's links the
//! sweeps their padded assemblies need (`Robot::set_jointed_sweeps`).
//!
//! Tolerances: the grasp primitive stops at the first step whose force reaches `F`, and a
//! pad's force grows per step by at most the motor's torque increment over the pad's lever
//! about the proximal hinge, `k w dt / L`, so every peak is below `F + k w dt / L`: with `L` =
//! 50 mm, the proximal link's length (the pad sits 30 mm further on the distal link, but the
//! lever of its normal force is shorter than that distance where the pad tilts), 3.3 N (the
//! multibody hand's peaks reach 2.14 N at 1 N on the ball and 4.52 N at 2 N on the box).
//! On the ball the two joint models agree within 0.05 N per pad (measured, session 30: peaks
//! 0.026 N apart, held forces 0.034 N; the peaks were 0.0006 N apart while an impulse-jointed
//! member's substep count read its motors' push as an approach velocity, which split the
//! squeeze's last step into 86 substeps where the multibody's rule takes 13). On the box and
//! the cylinder the pads land unevenly, so the test asserts the sum of the held forces within
//! 25 % of the multibody's (measured +3.6 % and -3.0 %; before session 30 +4.0 % and -0.9 %,
//! and -16 % and +3 % when the box's first pad held 0.37 N), and the hold: slip below 10 um.
//! `cargo test -p softgrip-scene --test impulse_hand -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::{Path, PathBuf};

use softgrip_scene::control::Phase;
use softgrip_scene::{PlainRun, Scene};

/// The proximal motors' stiffness [N m/rad], closing speed
/// [rad/s], the step [s] and the pads' lever from the proximal hinge [m].
const K: f64 = 20.0;
const W: f64 = 0.5;
const DT: f64 = 1.0 / 60.0;
const LEVER: f64 = 0.05;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// `scenes/robots/three_finger_hand_{object}.toml` with `joints = model`.
fn scene(object: &str, model: &str) -> Scene {
    let path = repo().join(format!("scenes/robots/three_finger_hand_{object}.toml"));
    let mut text = String::new();
    for line in std::fs::read_to_string(&path).unwrap().lines() {
        text.push_str(line);
        text.push('\n');
        if line.starts_with("urdf =") {
            text.push_str(&format!("joints = \"{model}\"\n"));
        }
    }
    Scene::parse(&text, "hand.toml", path.parent().unwrap()).unwrap()
}

/// One grasp run's numbers.
#[derive(Debug)]
struct Grasped {
    /// Each pad's largest substep force \[N\].
    peak: Vec<f64>,
    /// Each pad's force at the end of the hold \[N\].
    held: Vec<f64>,
    /// The object's largest motion relative to the hand's base over the hold \[m\].
    slip: f64,
    /// `SoftCounters::jointed_free` over the run.
    jointed_free: u64,
    /// The most sweeps a link's assembly needs in the hold (`None`: no assembly) and the most
    /// a link is given (rapier's one plus `additional_pgs_iterations`).
    sweeps_hold: Option<usize>,
    sweeps_given: usize,
}

fn grasp(object: &str, model: &str) -> Grasped {
    let scene = scene(object, model);
    let mut run = PlainRun::new(&scene);
    let obj = run.handles.body(object).unwrap();
    let base = run.handles.robots[0].1.links[scene.robots()[0].root()];
    let pads: Vec<_> = ["f0_pad", "f1_pad", "f2_pad"]
        .iter()
        .map(|n| run.handles.fingertip(n).unwrap())
        .collect();
    let mut peak = vec![0.0f64; pads.len()];
    let (mut held, mut hold) = (Vec::new(), Vec::<[f64; 3]>::new());
    let links = run.handles.robots[0].1.links.clone();
    let mut sweeps_hold = None;
    for _ in 0..scene.steps() {
        run.step();
        for (k, &p) in pads.iter().enumerate() {
            for c in run.world.soft.contacts_of(p) {
                peak[k] = peak[k].max(c.peak_normal_force);
            }
        }
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            let b = &run.world.physics.bodies;
            let (o, h) = (b[obj].translation(), b[base].translation());
            hold.push([o.x - h.x, o.y - h.y, o.z - h.z].map(f64::from));
            held = (pads.iter())
                .map(|&p| run.world.soft.contacts_of(p).map(|c| c.normal_force).sum())
                .collect();
            let need = (links.iter())
                .filter_map(|&l| run.world.jointed_sweeps_needed(l, DT))
                .max();
            sweeps_hold = sweeps_hold.max(need);
        }
    }
    let sweeps_given = (links.iter())
        .map(|&l| run.world.physics.bodies[l].additional_pgs_iterations())
        .max()
        .unwrap()
        + run
            .world
            .physics
            .integration_parameters
            .num_internal_pgs_iterations;
    assert!(hold.len() > 2, "{object} {model}: never held");
    let slip = common::excursion(&hold, 0);
    let g = Grasped {
        peak,
        held,
        slip,
        jointed_free: run.world.soft.counters().jointed_free,
        sweeps_hold,
        sweeps_given,
    };
    println!("{object} {model}: {g:.4?}");
    g
}

/// The checks common to every object: the fingers seen through their joints, every peak
/// below one step's increment over `F`, the hold without slip, and the held forces' sum
/// within `rel` of the multibody hand's.
fn check(object: &str, force: f64, rel: f64) -> (Grasped, Grasped) {
    let (m, i) = (grasp(object, "multibody"), grasp(object, "impulse"));
    assert_eq!(i.jointed_free, 0, "{object}: fingers taken as free bodies");
    // The margin on the start pose's sweeps covers the closed hand's.
    let need = i.sweeps_hold.unwrap();
    assert!(
        need <= i.sweeps_given,
        "{object}: {need} needed, {}",
        i.sweeps_given
    );
    let bound = force + K * W * DT / LEVER;
    for g in [&m, &i] {
        for &p in &g.peak {
            assert!(
                p > force && p < bound,
                "{object}: peak {p} N not in ({force}, {bound})"
            );
        }
    }
    assert!(i.slip < 10e-6, "{object}: slip {} um", i.slip * 1e6);
    let (sm, si) = (m.held.iter().sum::<f64>(), i.held.iter().sum::<f64>());
    assert!(
        (si / sm - 1.0).abs() < rel,
        "{object}: held {si} N, multibody {sm} N"
    );
    (m, i)
}

#[test]
fn the_impulse_hand_grasps_the_ball_as_the_multibody_does() {
    let (m, i) = check("ball", 1.0, 0.05);
    for k in 0..3 {
        assert!((i.peak[k] - m.peak[k]).abs() < 0.05, "pad {k}: {m:?} {i:?}");
        assert!((i.held[k] - m.held[k]).abs() < 0.05, "pad {k}: {m:?} {i:?}");
    }
}

#[test]
fn the_impulse_hand_grasps_the_box() {
    check("box", 2.0, 0.25);
}

#[test]
fn the_impulse_hand_grasps_the_cylinder() {
    check("cylinder", 1.0, 0.25);
}

/// The sweeps the scene gives the links: the hand's hinged fingers need 518 per pass at the
/// start (rate 0.978), times the 1.25 margin; the gripper's prismatic fingers, anchored at
/// their centres of mass, need one (rapier's own) and get none more.
#[test]
fn hinged_links_get_the_sweeps_their_assembly_needs() {
    let hand = PlainRun::new(&scene("ball", "impulse"));
    let (_, h) = &hand.handles.robots[0];
    let extra: Vec<usize> = (h.links.iter())
        .map(|&l| hand.world.physics.bodies[l].additional_pgs_iterations())
        .collect();
    println!("hand links' additional sweeps {extra:?}");
    assert_eq!(extra.len(), 7);
    for &e in &extra {
        assert!((640..=660).contains(&e), "{extra:?}");
    }
    let path = repo().join("scenes/robots/parallel_gripper_box.toml");
    let text = std::fs::read_to_string(&path)
        .unwrap()
        .replace("urdf =", "joints = \"impulse\"\nurdf =");
    let gripper = PlainRun::new(&Scene::parse(&text, "g.toml", path.parent().unwrap()).unwrap());
    for &l in &gripper.handles.robots[0].1.links {
        assert_eq!(
            gripper.world.physics.bodies[l].additional_pgs_iterations(),
            0
        );
    }
}
