//! N fingertips resting on the ground through the path users take: a scene file (TOML text,
//! parsed and checked), the bevy_ecs schedule of `softgrip run`, and its MCAP recording, against
//! the plugin alone on the world the same scene builds (what the plugin's own benchmark,
//! `softgrip-bench`'s `OverheadScene`, times).
//!
//! ```sh
//! cargo run --release -p softgrip-ecs --example scaling [N ...]   # default N = 1 10 100 1000
//! ```
//!
//! Prints one row per N: the scene's load (`Scene::parse`: format, validation, every
//! fingertip's law, the start check) and the time per step of (a) the plugin on
//! `Scene::build`'s world (`SoftWorld::step`), (b) the ECS schedule (`Simulation::step`, no
//! sinks), (c) the ECS with the MCAP recorder (every 4th step, the scene default, to a
//! temporary file). Each step time is the best of three runs of `steps` steps after the scene
//! settled; wall time of this thread (the recorder compresses on its own thread).
//!
//! The scene matches `OverheadScene`: R = 10 mm, E = 3 MPa, nu = 0.49, `auto`, e = 0.5,
//! 1070 kg/m^3, a 30 mm square grid on a fixed box, each ball at its resting depth.

#![allow(missing_docs)]

use std::fmt::Write as _;
use std::time::Instant;

use softgrip_ecs::{McapSink, Scene, Simulation};
use softgrip_law::{ContactLaw, ContactParams, Level, Material};

const RADIUS: f64 = 0.01;
const DENSITY: f64 = 1070.0;
const PITCH: f64 = 0.03;
const DT: f64 = 1.0 / 60.0;
/// Steps before timing (the balls settle on the law).
const SETTLE: u64 = 120;

/// The scene text of `n` resting fingertips.
fn scene_text(n: usize, steps: u64) -> String {
    let law = ContactLaw::try_new(
        ContactParams::try_new(
            Material::try_new(3.0e6, 0.49).expect("valid material"),
            RADIUS,
        )
        .expect("valid params"),
        Level::auto(),
    )
    .expect("valid law");
    let mass = DENSITY * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let rest = law
        .compression_for_force(mass * 9.81)
        .expect("the weight is within the law's range");
    let side = (n as f64).sqrt().ceil() as usize;
    let half = 0.5 * side as f64 * PITCH + PITCH;
    let mut s = String::new();
    let duration = (SETTLE + steps) as f64 * DT;
    writeln!(
        s,
        "duration = {duration}\ndt = {DT}\ngravity = [0.0, -9.81, 0.0]"
    )
    .ok();
    writeln!(
        s,
        "[record]\nposes = true\nwrenches = true\ncontacts = true\n"
    )
    .ok();
    writeln!(
        s,
        "[[body]]\nname = \"ground\"\nkind = \"fixed\"\nposition = [0.0, -0.01, 0.0]\n\
         [[body.shape]]\ntype = \"cuboid\"\nhalf_extents = [{half}, 0.01, {half}]\n"
    )
    .ok();
    for i in 0..n {
        let (row, col) = (i / side, i % side);
        let x = (col as f64 - 0.5 * (side - 1) as f64) * PITCH;
        let z = (row as f64 - 0.5 * (side - 1) as f64) * PITCH;
        writeln!(
            s,
            "[[body]]\nname = \"ball{i}\"\nkind = \"dynamic\"\nposition = [{x}, {}, {z}]\n\n\
             [[fingertip]]\nname = \"tip{i}\"\nbody = \"ball{i}\"\nradius = {RADIUS}\n\
             density = {DENSITY}\nmaterial = {{ youngs_modulus = 3.0e6, poisson_ratio = 0.49 }}\n\
             level = \"auto\"\nrestitution = 0.5\n",
            RADIUS - rest
        )
        .ok();
    }
    s
}

/// Best of three: seconds per step of `steps` calls of `step`, after `SETTLE` untimed ones.
fn per_step<S>(make: impl Fn() -> S, mut step: impl FnMut(&mut S), steps: u64) -> f64 {
    (0..3)
        .map(|_| {
            let mut s = make();
            for _ in 0..SETTLE {
                step(&mut s);
            }
            let t = Instant::now();
            for _ in 0..steps {
                step(&mut s);
            }
            t.elapsed().as_secs_f64() / steps as f64
        })
        .fold(f64::MAX, f64::min)
}

fn main() -> anyhow::Result<()> {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let ns = if args.is_empty() {
        vec![1, 10, 100, 1000]
    } else {
        args
    };
    let dir = tempfile::tempdir()?;
    println!(
        "| N | load (parse + check) | plugin alone, per step | ECS, per step | ECS + MCAP, per step | ECS + MCAP / plugin |"
    );
    println!("|---:|---:|---:|---:|---:|---:|");
    for n in ns {
        let steps = (20_000 / n as u64).clamp(60, 2000);
        let text = scene_text(n, steps);
        let t = Instant::now();
        let scene = Scene::parse(&text, "scaling.toml", dir.path())?;
        let load = t.elapsed().as_secs_f64();
        let plugin = per_step(|| scene.build().world, |w| w.step(), steps);
        let ecs = per_step(
            || {
                let mut sim = Simulation::new(&scene);
                sim.initialize();
                sim
            },
            |s| s.step(),
            steps,
        );
        let path = dir.path().join("scaling.mcap");
        let recorded = per_step(
            || {
                let _ = std::fs::remove_file(&path);
                let sink = McapSink::with_options(&path, &scene, &text, 4, &Default::default())
                    .expect("a recording in a temporary directory");
                let mut sim = Simulation::new(&scene).with_recorder(sink);
                sim.initialize();
                sim
            },
            |s| s.step(),
            steps,
        );
        println!(
            "| {n} | {:.1} ms | {:.1} us | {:.1} us | {:.1} us | {:.2}x |",
            load * 1e3,
            plugin * 1e6,
            ecs * 1e6,
            recorded * 1e6,
            recorded / plugin
        );
    }
    Ok(())
}
