//! The embedded default scene: its squeeze force equals the law at the commanded depth, and
//! two runs are bit-identical.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{Probe, contact_bits};
use softgrip_ecs::{Scene, Simulation, bevy_ecs};

#[test]
fn default_scene_squeeze_force_equals_the_law_at_the_commanded_depth() {
    let scene = Scene::default_scene();
    let mut sim = Simulation::new(&scene).with_summary();
    let report = sim.run(|_, _| {});
    let summary = sim.world.resource::<softgrip_ecs::Summary>().clone();
    for (tip, (_, s)) in scene.fingertips().iter().zip(&summary.tips) {
        println!("{s}");
        let depth = s.commanded_depth.unwrap();
        let force = s.squeeze_force.unwrap();
        // The default scene's pads are bonded to their jaws (issue 10): the `flat` law,
        // rebuilt here from the fingertip's own material, radius and level.
        let flat = softgrip_ecs::scene::softgrip_rapier::softgrip_law::Backing::Flat;
        assert_eq!(tip.backing(), flat);
        let own = softgrip_ecs::scene::softgrip_rapier::softgrip_law::ContactLaw::try_new(
            softgrip_ecs::scene::softgrip_rapier::softgrip_law::ContactParams::try_new(
                tip.material(),
                tip.radius(),
            )
            .unwrap()
            .with_backing(flat)
            .unwrap(),
            tip.level(),
        )
        .unwrap();
        let law = own.response(depth).force;
        let err = force / law - 1.0;
        println!(
            "{}: squeeze {force:.5} N, law({:.4} mm) = {law:.5} N, error {:+.3e}; delta {:.6} mm",
            s.name,
            depth * 1e3,
            err,
            s.squeeze_delta.unwrap() * 1e3
        );
        assert!(err.abs() < 0.01, "{}: {force} N vs law {law} N", s.name);
        assert_eq!(s.validity_excursions, 0);
    }
    // The backing flows through the ECS spawn: the plugin's registered pads are flat, facing
    // the box, and bonded pads keep rapier's narrow phase for their rigid back (issue 10).
    let physics = sim.world.resource::<softgrip_ecs::Physics>();
    let mut registered: Vec<_> = physics
        .world
        .physics
        .colliders
        .iter()
        .filter_map(|(h, _)| physics.world.soft.fingertip(h))
        .map(|t| (t.name().to_string(), t.backing(), t.facing()))
        .collect();
    registered.sort_by(|a, b| a.0.cmp(&b.0));
    let flat = softgrip_ecs::scene::softgrip_rapier::softgrip_law::Backing::Flat;
    assert_eq!(
        registered,
        [
            ("left_tip".to_string(), flat, Some([1.0, 0.0, 0.0])),
            ("right_tip".to_string(), flat, Some([-1.0, 0.0, 0.0]))
        ]
    );
    println!("{report:?}, rtf {:.1}", report.real_time_factor());
}

#[test]
fn default_scene_is_deterministic() {
    let scene = Scene::default_scene();
    let run = || {
        let probe = Probe::default();
        let mut sim = Simulation::new(&scene).with_recorder(probe.clone());
        sim.run(|_, _| {});
        contact_bits(&probe.frames())
    };
    let (a, b) = (run(), run());
    assert_eq!(a.len() as u64, scene.steps());
    assert!(
        a.iter().filter(|f| !f.is_empty()).count() > 100,
        "the fingertips touch the box"
    );
    assert_eq!(a, b);
}

/// Every `GripReached` of a run: (time, depth of jaw 0).
#[derive(bevy_ecs::prelude::Resource, Default)]
struct Reached(Vec<(f64, f64)>);

fn log_reached(
    mut reader: bevy_ecs::prelude::MessageReader<softgrip_ecs::GripReached>,
    mut log: bevy_ecs::prelude::ResMut<Reached>,
) {
    log.0.extend(reader.read().map(|m| (m.time, m.depth[0])));
}

#[test]
fn force_controlled_squeeze_reaches_the_grip_force_once() {
    use bevy_ecs::prelude::IntoScheduleConfigs;
    use softgrip_ecs::SoftgripSystems;
    let text = softgrip_ecs::scene::DEFAULT_SCENE.replace("depth = 0.002", "force = 5.0");
    let scene = Scene::parse(&text, "force.toml", std::path::Path::new(".")).unwrap();
    let mut sim = Simulation::new(&scene).with_summary();
    sim.world.init_resource::<Reached>();
    sim.schedule_mut()
        .add_systems(log_reached.in_set(SoftgripSystems::Record));
    sim.run(|_, _| {});
    let reached = &sim.world.resource::<Reached>().0;
    let depth = scene.fingertips()[0]
        .law()
        .compression_for_force(5.0)
        .unwrap();
    assert_eq!(reached.len(), 1, "{reached:?}");
    assert_eq!(reached[0].1, depth);
    for (_, s) in &sim.world.resource::<softgrip_ecs::Summary>().tips {
        let f = s.squeeze_force.unwrap();
        println!(
            "{}: {f:.4} N for 5 N (depth {:.4} mm), GripReached at {:.4} s",
            s.name,
            depth * 1e3,
            reached[0].0
        );
        assert!((f / 5.0 - 1.0).abs() < 0.01, "{}: {f} N", s.name);
    }
}
