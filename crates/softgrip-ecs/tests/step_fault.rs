//! A step that fails stops the schedule: the `StepFault` resource names it, the clock stays at
//! the last good step, and the diverged state is never read out (so never recorded).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_ecs::{BodyPose, Scene, SimClock, Simulation, StepFault};

#[test]
fn a_diverging_scene_stops_at_its_fault() {
    // A stone falling under 1000 g at dt = 1 s, capped by rapier at 400 m/s: past the step's
    // bound on a position (1e6 m) in step 2501.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../softgrip-cli/tests/diverge/falling.toml");
    let scene = Scene::from_file(&path).unwrap();
    let mut sim = Simulation::new(&scene).with_summary();
    let report = sim.run(|_, _| {});
    assert_eq!(report.steps, 2500);
    let e = sim.fault().unwrap().clone();
    assert_eq!(e.step(), 2501);
    assert!(e.to_string().contains("(`stone`)"), "{e}");
    assert_eq!(sim.world.resource::<StepFault>().0.as_ref(), Some(&e));
    assert_eq!(sim.world.resource::<SimClock>().step, 2500);
    // The pose read out is the last good step's (-999 999 m), not the diverged one.
    let stone = sim.entities.bodies[0];
    let y = sim.world.get::<BodyPose>(stone).unwrap().translation[1];
    assert!((y + 999_999.0).abs() < 1.0, "{y}");
    // Faulted: stepping again changes nothing.
    sim.step();
    assert_eq!(sim.world.resource::<SimClock>().step, 2500);
    assert_eq!(sim.try_step().unwrap_err(), e);
}
