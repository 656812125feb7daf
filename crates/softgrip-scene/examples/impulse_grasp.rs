//! A robot grasp scene run with both joint models (`joints = "multibody"` and `"impulse"`),
//! at the grasp forces given: each run's peak pad force, the pads' forces at the end of the
//! hold, the hold's slip (the object's largest motion relative to the hand's base) and the
//! time per step.
//!
//! `cargo run --release -p softgrip-scene --example impulse_grasp [scene.toml] [force N]... [--pgs N] [--trace]`
//! (`--pgs N`: N Gauss-Seidel sweeps per solver pass more on the robot's links than the scene
//! gives them; the row ends with `SoftCounters::jointed_free`)
//! (default: `scenes/robots/parallel_gripper_box.toml` at 3, 5 and 7 N).

#[path = "../tests/common/mod.rs"]
mod common;

use std::path::{Path, PathBuf};
use std::time::Instant;

use softgrip_scene::control::Phase;
use softgrip_scene::robot::{joint_state, joint_target};
use softgrip_scene::{PlainRun, Scene};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenes/robots/parallel_gripper_box.toml"
    ));
    let mut forces = Vec::new();
    let mut trace = false;
    let mut pgs = 0usize;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--trace" {
            trace = true;
        } else if a == "--pgs" {
            pgs = args
                .next()
                .and_then(|n| n.parse().ok())
                .ok_or("--pgs takes a count")?;
        } else if let Ok(f) = a.parse::<f64>() {
            forces.push(f);
        } else {
            path = PathBuf::from(a);
        }
    }
    if forces.is_empty() {
        forces = vec![3.0, 5.0, 7.0];
    }
    let text = std::fs::read_to_string(&path)?;
    println!("{}", path.display());
    println!("joints     force  peak pads [N]          hold pads [N]          slip [um]  ms/step");
    for &force in &forces {
        for model in ["multibody", "impulse"] {
            let scene = variant(&text, &path, model, force)?;
            run(&scene, model, force, trace, pgs);
        }
    }
    Ok(())
}

/// The scene with its (first) robot's `joints = model` and its grasp's `force`.
fn variant(
    text: &str,
    path: &Path,
    model: &str,
    force: f64,
) -> Result<Scene, Box<dyn std::error::Error>> {
    let mut out = String::new();
    let mut in_robot = false;
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("[[") || t.starts_with('[') && !t.starts_with("[[") {
            in_robot = t.starts_with("[[robot]]");
        }
        if t.starts_with("force =") || t.starts_with("force=") {
            out.push_str(&format!("force = {force}\n"));
            continue;
        }
        if in_robot && t.starts_with("joints") {
            continue;
        }
        out.push_str(line);
        out.push('\n');
        if t.starts_with("[[robot]]") {
            out.push_str(&format!("joints = \"{model}\"\n"));
        }
    }
    let dir = path.parent().unwrap_or(Path::new("."));
    Ok(Scene::parse(&out, &path.display().to_string(), dir)?)
}

/// Runs `scene` and prints its row (and with `trace` each step).
fn run(scene: &Scene, model: &str, force: f64, trace: bool, pgs: usize) {
    let mut run = PlainRun::new(scene);
    let robot = &scene.robots()[0];
    let h = run.handles.robots[0].1.clone();
    // `--pgs N`: N sweeps more than the scene gives the robot's links.
    for &l in h.links.iter().filter(|_| pgs > 0) {
        if let Some(rb) = run.world.physics.bodies.get_mut(l) {
            rb.set_additional_pgs_iterations(rb.additional_pgs_iterations() + pgs);
        }
    }
    let base = h.links[robot.root()];
    let pads: Vec<_> = (scene.file().fingertips.iter())
        .filter_map(|t| run.handles.fingertip(&t.name))
        .collect();
    let obj = run
        .handles
        .bodies
        .iter()
        .find(|(_, b)| run.world.physics.bodies[*b].is_dynamic());
    let obj = obj.map(|(_, b)| *b);
    let mut peak = vec![0.0f64; pads.len()];
    let mut held = vec![0.0f64; pads.len()];
    let mut hold: Vec<[f64; 3]> = Vec::new();
    let t0 = Instant::now();
    for step in 0..scene.steps() {
        run.step();
        let f: Vec<f64> = (pads.iter())
            .map(|&p| run.world.soft.contacts_of(p).map(|c| c.normal_force).sum())
            .collect();
        for (k, &p) in pads.iter().enumerate() {
            for c in run.world.soft.contacts_of(p) {
                peak[k] = peak[k].max(c.peak_normal_force);
            }
        }
        let phase = run.control.controllers()[0].phase();
        if phase == Some(Phase::Hold)
            && let Some(o) = obj
        {
            let (o, b) = (
                run.world.physics.bodies[o].translation(),
                run.world.physics.bodies[base].translation(),
            );
            hold.push([(o.x - b.x) as f64, (o.y - b.y) as f64, (o.z - b.z) as f64]);
            held.clone_from(&f);
        }
        if trace {
            let w = &run.world.physics;
            let js: Vec<String> = (0..robot.joints().len())
                .filter(|&j| robot.joints()[j].kind.moves())
                .map(|j| {
                    let s = joint_state(robot, w, &h, j, 1.0);
                    let t = joint_target(robot, w, &h, j).map_or(f64::NAN, |t| t.0);
                    format!("q{j} {:.6} t {:.6} v {:.4}", s.position, t, s.velocity)
                })
                .collect();
            let ox = obj.map_or([f64::NAN; 3], |o| {
                let t = w.bodies[o].translation();
                [t.x as f64, t.y as f64, t.z as f64]
            });
            // The step's largest pad force over its substeps.
            let step_peak: Vec<f64> = (pads.iter())
                .map(|&p| {
                    (run.world.soft.contacts_of(p)).fold(0.0f64, |a, c| a.max(c.peak_normal_force))
                })
                .collect();
            println!(
                "{step:4} {phase:?} pads {f:.3?} peak {step_peak:.3?} {} obj {ox:.6?} substeps {}",
                js.join(" "),
                run.world.soft.counters().substeps_last
            );
        }
    }
    let ms = t0.elapsed().as_secs_f64() * 1e3 / scene.steps() as f64;
    let slip = common::excursion(&hold, 0);
    println!(
        "{model:10} {force:5.2}  {peak:8.4?}  {held:8.4?}  {:9.2}  {ms:.2}  jointed_free {}",
        slip * 1e6,
        run.world.soft.counters().jointed_free
    );
}
