//! A scripted squeeze: each transition writes exactly one message, at the step it happens.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::collections::HashMap;

use std::path::Path;

use common::Probe;

use bevy_ecs::prelude::{IntoScheduleConfigs, Message, Messages, World};
use softgrip_ecs::{
    ContactEnded, ContactStarted, Scene, Simulation, SlipStarted, SoftgripSystems,
    ValidityExcursion, bevy_ecs,
};

/// Every message of type `M` ever written, with its time.
#[derive(bevy_ecs::prelude::Resource, Default)]
struct Log(Vec<(&'static str, f64)>);

fn collect<M: Message + Clone>(world: &mut World, name: &'static str, time: impl Fn(&M) -> f64) {
    let times: Vec<f64> = world
        .resource::<Messages<M>>()
        .iter_current_update_messages()
        .map(&time)
        .collect();
    let mut log = world.resource_mut::<Log>();
    log.0.extend(times.into_iter().map(|t| (name, t)));
}

fn log_messages(world: &mut World) {
    collect::<ContactStarted>(world, "started", |m| m.time);
    collect::<ContactEnded>(world, "ended", |m| m.time);
    collect::<SlipStarted>(world, "slip", |m| m.time);
    collect::<ValidityExcursion>(world, "excursion", |m| m.time);
}

#[test]
fn each_transition_writes_one_message() {
    let scene = Scene::from_file(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/scenes/scripted_squeeze.toml"),
    )
    .unwrap();
    let probe = Probe::default();
    let mut sim = Simulation::new(&scene)
        .with_recorder(probe.clone())
        .with_summary();
    sim.world.init_resource::<Log>();
    let dt = scene.file().dt as f32 as f64;
    // A custom exclusive system after the readout collects the messages of the step.
    sim.schedule_mut()
        .add_systems(log_messages.in_set(SoftgripSystems::Record));
    sim.run(|_, _| {});
    let log = &sim.world.resource::<Log>().0;
    let count = |n: &str| log.iter().filter(|(k, _)| *k == n).count();
    let times = |n: &str| {
        log.iter()
            .filter(|(k, _)| *k == n)
            .map(|(_, t)| *t / dt)
            .collect::<Vec<_>>()
    };
    println!("started {:?}", times("started"));
    println!("ended {:?}", times("ended"));
    println!("slip {:?}", times("slip"));
    println!("excursion {:?}", times("excursion"));

    // The transitions, found independently in the plugin's per-step readout.
    let mut expected: HashMap<&str, Vec<f64>> = HashMap::new();
    let mut last: HashMap<(String, String), (bool, bool)> = HashMap::new();
    for f in probe.frames() {
        let step = f.step as f64;
        let mut now = HashMap::new();
        for c in &f.contacts {
            let key = (c.fingertip.clone(), c.other.clone());
            let (sliding, extended) = (c.contact.sliding, c.contact.validity_exceeded);
            let (was_sliding, was_extended) = match last.get(&key) {
                Some(&s) => s,
                None => {
                    expected.entry("started").or_default().push(step);
                    (false, false)
                }
            };
            if sliding && !was_sliding {
                expected.entry("slip").or_default().push(step);
            }
            if extended && !was_extended {
                expected.entry("excursion").or_default().push(step);
            }
            now.insert(key, (sliding, extended));
        }
        for key in last.keys() {
            if !now.contains_key(key) {
                expected.entry("ended").or_default().push(step);
            }
        }
        last = now;
    }
    for kind in ["started", "ended", "slip", "excursion"] {
        let mut got: Vec<f64> = times(kind).iter().map(|t| t.round()).collect();
        let mut want = expected.remove(kind).unwrap_or_default();
        got.sort_by(f64::total_cmp);
        want.sort_by(f64::total_cmp);
        assert_eq!(got, want, "{kind}: messages vs transitions (steps)");
    }
    // Counts and times from the script: first touch after 4 mm at 9 mm/s (26.7 steps -> 27),
    // both fingertips; x = 0.78 (delta 7.8 mm) after 11.8 mm of travel (78.7 steps; the 2 kg box
    // shifts by up to one step between the two sides); two contacts released, two regained and
    // lost again when the weakly held box slips out during the lift.
    assert_eq!(count("started"), 4);
    assert_eq!(count("ended"), 4);
    assert_eq!(count("excursion"), 2);
    assert!(count("slip") >= 2);
    assert_eq!(&times("started")[..2], &[27.0, 27.0]);
    assert!(
        times("excursion")
            .iter()
            .all(|k| (78.0..=80.0).contains(&k.round()))
    );
    assert!(
        times("ended")[2..].iter().all(|k| *k > 600.0 && *k < 660.0),
        "lost during the lift (steps 600-660)"
    );
    // How long the excursions lasted (the summary): per fingertip, dt times the steps in which
    // any of its contacts was past the range, found independently in the readout.
    let summary = sim.world.resource::<softgrip_ecs::Summary>().clone();
    let mut total = 0.0;
    for (_, t) in &summary.tips {
        let steps = probe
            .frames()
            .iter()
            .filter(|f| {
                f.contacts
                    .iter()
                    .any(|c| c.fingertip == t.name && c.contact.validity_exceeded)
            })
            .count();
        println!(
            "{}: excursion time {} s over {steps} steps",
            t.name, t.excursion_time
        );
        assert!((t.excursion_time - steps as f64 * dt).abs() < 1e-9 * (1.0 + t.excursion_time));
        assert_eq!(
            t.excursion_time > 0.0,
            t.validity_excursions > 0,
            "{}",
            t.name
        );
        total += t.excursion_time;
    }
    assert!(total > 0.0);
}
