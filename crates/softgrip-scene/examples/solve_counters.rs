//! The default grasp (`scenes/default.toml`, or the scene file given) on the plain plugin: its
//! wall time, the plugin's own timers and how its coupled solves settled
//! (`SoftCounters::coupled_*`, `group_*`), its substeps per step (`SoftCounters::substeps_total`), and
//! the golden digest line, to compare solver changes.
//!
//! `cargo run --release -p softgrip-scene --example solve_counters [scene.toml] [--rigid-stick]`
//!
//! The plugin's default friction: Mindlin's tangential spring (`SoftContacts::set_friction_spring`,
//! the default since session 20). `--rigid-stick`: the rigid stick (`set_friction_spring(false)`),
//! the default before. `--friction-spring` (the spring, explicitly) is still accepted.

use std::time::Instant;

use softgrip_scene::{ContactDigest, PlainRun, Scene};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rigid = args.iter().any(|a| a == "--rigid-stick");
    if rigid && args.iter().any(|a| a == "--friction-spring") {
        return Err("give at most one of `--rigid-stick` and `--friction-spring`".into());
    }
    let scene = match args.iter().find(|a| !a.starts_with("--")) {
        Some(path) => Scene::from_file(std::path::Path::new(path))?,
        None => Scene::default_scene(),
    };
    let mut run = PlainRun::new(&scene);
    if rigid {
        run.world.soft.set_friction_spring(false);
    }
    let mut digest = ContactDigest::new();
    // The largest substep normal force of each fingertip (the summary's peak force) [N].
    let mut peaks: Vec<(String, f64)> = Vec::new();
    let t = Instant::now();
    run.run(scene.steps(), |r| {
        digest.add_step(r.world.soft.contacts().iter());
        for c in r.world.soft.contacts() {
            let name = format!("{:?}", c.fingertip);
            match peaks.iter_mut().find(|(n, _)| *n == name) {
                Some((_, p)) => *p = p.max(c.peak_normal_force),
                None => peaks.push((name, c.peak_normal_force)),
            }
        }
    });
    let wall = t.elapsed().as_secs_f64();
    let c = run.world.soft.counters();
    let dt = f64::from(run.world.physics.integration_parameters.dt);
    println!(
        "{} steps in {:.1} ms ({:.1} us/step, {:.0}x real time)",
        c.steps,
        wall * 1e3,
        wall * 1e6 / c.steps as f64,
        c.steps as f64 * dt / wall
    );
    println!(
        "detect {:.1} ms, solve {:.1} ms, pipeline {:.1} ms",
        c.detect_time.as_secs_f64() * 1e3,
        c.solve_time.as_secs_f64() * 1e3,
        c.pipeline_time.as_secs_f64() * 1e3
    );
    println!(
        "coupled solves {}, passes {} ({:.2} per solve), unsettled {}",
        c.coupled_solves,
        c.coupled_passes,
        c.coupled_passes as f64 / c.coupled_solves.max(1) as f64,
        c.coupled_unsettled
    );
    println!(
        "group solves {}, passes {} ({:.2} per solve), unsettled {}, answered as sticking {}",
        c.group_solves,
        c.group_passes,
        c.group_passes as f64 / c.group_solves.max(1) as f64,
        c.group_unsettled,
        c.group_stuck
    );
    println!(
        "substeps {} ({:.2} per step, {} at the cap), largest group {} rows",
        c.substeps_total,
        c.substeps_total as f64 / c.steps.max(1) as f64,
        c.substep_cap_hits,
        c.largest_group
    );
    println!(
        "bodies held by impulse joints solved as free bodies: {} (per substep, total)",
        c.jointed_free
    );
    for (name, peak) in &peaks {
        println!("fingertip {name}: peak force {peak:.4} N");
    }
    println!("{digest}");
    Ok(())
}
