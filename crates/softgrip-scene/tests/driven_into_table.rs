//! A robot link driven into a fixed body during a run (issue 25): the shipped hands' grasps
//! with their lift turned into a descent (`up = [0, -1, 0]`), so that their links are pushed
//! into the table. Before session 13 the parallel gripper's 5.5 mm descent blew up inside
//! rapier's own finger-table contact: the fingers' prismatic joints cannot move them along the
//! table's normal, rapier's contact row there has an `f32`-noise mobility (6.46e-14 1/kg) and
//! asked an impulse of its inverse (peak x 8e10, 47 kN, a finger flung along its joint).
//! Such rows are now dropped before rapier's solver (`softgrip_rapier`'s `link_contacts.rs`,
//! counted in `SoftCounters::locked_link_contacts`); a row a joint can move along (the
//! three-finger hand's revolute fingers on the table) stays, and its motors stall at their
//! URDF effort. `cargo test -p softgrip-scene --test driven_into_table -- --nocapture` prints
//! the numbers (SCENES.md, "A link driven into a fixed body").

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};

use softgrip_scene::control::Phase;
use softgrip_scene::softgrip_rapier::rapier3d::prelude::{ColliderHandle, RigidBodyHandle};
use softgrip_scene::{PlainRun, Scene};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Shipped scene `name` with its lift (`lift`, the scene's line) turned into a descent of
/// `depth` metres at the same speed and acceleration.
fn descending(name: &str, lift: &str, depth: f64) -> Scene {
    let path = repo().join(format!("scenes/robots/{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains(lift), "the shipped scene's lift changed");
    let (speed, rest) = lift.split_once("speed = ").unwrap();
    assert!(speed.contains("distance"));
    let down = format!("lift = {{ distance = {depth}, speed = {rest}\nup = [0.0, -1.0, 0.0]");
    let text = text.replace(lift, &down);
    Scene::parse(&text, "down.toml", path.parent().unwrap()).unwrap()
}

/// What [`run_down`] measured.
#[derive(Debug, Default)]
struct Down {
    /// The largest speed of any link \[m/s\].
    link_speed: f64,
    /// The largest force rapier's contacts put on the robot's links from the table, summed
    /// over the links, in any step \[N\].
    table_force: f64,
    /// The largest soft (pad) force of any step \[N\].
    pad_force: f64,
    /// Each pad's force at the end of the hold \[N\].
    pads_held: Vec<f64>,
    /// The object's height over its start at the end of the hold \[m\].
    object_drop: f64,
    /// Steps in the hold.
    held: usize,
    /// rapier's link contacts dropped as locked (`SoftCounters::locked_link_contacts`).
    locked: u64,
}

/// Runs `scene` to its end checking each step that every link's pose and velocity and every
/// soft force are finite.
fn run_down(scene: &Scene, object: &str) -> Down {
    let mut run = PlainRun::new(scene);
    let h = run.handles.robots[0].1.clone();
    let table = run.handles.body("table").unwrap();
    let obj = run.handles.body(object).unwrap();
    let table_cols: Vec<ColliderHandle> = run.world.physics.bodies[table].colliders().to_vec();
    let pads: Vec<_> = (scene.file().fingertips.iter())
        .map(|t| run.handles.fingertip(&t.name).unwrap())
        .collect();
    let y0 = run.world.physics.bodies[obj].translation().y as f64;
    let dt = scene.file().dt;
    let mut out = Down::default();
    for step in 0..scene.steps() {
        run.step();
        let w = &run.world.physics;
        for &l in &h.links {
            let rb = &w.bodies[l];
            let (t, v) = (rb.translation(), rb.linvel());
            assert!(
                t.is_finite() && v.is_finite(),
                "step {step}: link at {t}, {v}"
            );
            out.link_speed = out.link_speed.max(v.length() as f64);
        }
        let substeps = run.world.soft.counters().substeps_last.max(1) as f64;
        let mut table_force = 0.0f64;
        for &tc in &table_cols {
            for pair in w.narrow_phase.contact_pairs_with(tc) {
                let other = if pair.collider1 == tc {
                    pair.collider2
                } else {
                    pair.collider1
                };
                let on_link = (w.colliders.get(other).and_then(|c| c.parent()))
                    .is_some_and(|b: RigidBodyHandle| h.links.contains(&b));
                if on_link {
                    table_force += pair.total_impulse_magnitude() as f64 * substeps / dt;
                }
            }
        }
        out.table_force = out.table_force.max(table_force);
        for c in run.world.soft.contacts() {
            assert!(c.normal_force.is_finite(), "step {step}: pad force");
            out.pad_force = out.pad_force.max(c.normal_force);
        }
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            out.held += 1;
            out.object_drop = y0 - w.bodies[obj].translation().y as f64;
            out.pads_held = (pads.iter())
                .map(|&p| run.world.soft.contacts_of(p).map(|c| c.normal_force).sum())
                .collect();
        }
    }
    let c = run.world.soft.counters();
    assert_eq!(c.non_finite, 0);
    out.locked = c.locked_link_contacts;
    eprintln!("{out:?}");
    out
}

/// The parallel gripper holding its 200 g box descends 5.5 mm instead of lifting: its fingers'
/// boxes (5 mm above the table at the shipped height) are pushed 0.5 mm into the table by the
/// kinematic base. The fingers' prismatic joints cannot move them along the table's normal and
/// the base is kinematic: no finite force stops that motion, so the fingers go on along their
/// commanded path into the table, rapier's contacts along that locked direction dropped; the
/// grasp holds (each pad within 4 % of its 5 N), nothing is flung
/// (links at most the base's lift speed, 0.1 m/s, plus 10 %), the box goes down with the hand.
#[test]
fn gripper_pushed_into_the_table_holds_its_box() {
    let scene = descending(
        "parallel_gripper_box",
        "lift = { distance = 0.1, speed = 0.1, acceleration = 1.0 }",
        0.0055,
    );
    let d = run_down(&scene, "box");
    assert!(d.held > 60, "{d:?}");
    assert!(d.link_speed < 0.11, "{d:?}: a link flung");
    assert!(
        d.locked > 0,
        "{d:?}: the finger-table contacts were never met"
    );
    // Along the locked vertical rapier's contacts carry nothing; along the fingers' joint
    // (horizontal) at most the motor's effort.
    assert!(d.table_force <= 20.0, "{d:?}: table force");
    assert!(d.pad_force < 5.5, "{d:?}: pad force");
    // The pads slid 5.5 mm down the sides of the box the table holds: each ends within 4 %
    // of the grasp's 5 N (4.83 / 5.03 N measured; 4.93 / 4.99 N at the shipped lift).
    for f in &d.pads_held {
        assert!((f - 5.0).abs() < 0.2, "{d:?}: a pad holds {f} N");
    }
    // The box went down with the hand (5.5 mm) until the table stopped it: it rests on it.
    assert!(
        d.object_drop.abs() < 1e-4,
        "{d:?}: box moved {} m",
        d.object_drop
    );
}
