//! The default scene without the box: the jaws close on each other, fingertip on fingertip.
//! Before issue 11 `left_tip` reported 26 kN at x = 4.0, `right_tip` 0 N, and the right jaw
//! drove straight through the other fingertip (it never saw a touch). Now the pair is reported
//! by both fingertips, the gripper stops on it, and the forces are sane and symmetric.
//! Since issue 10 the default scene's pads are `flat` (bonded to their jaws): the law refuses
//! to combine backed bodies, so the plugin presses each pad on the rigid mid-plane in series
//! (identical pads: each takes exactly half the approach and reads its own law there).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;

use softgrip_scene::{DEFAULT_SCENE, PlainRun, Scene};

/// The default scene's text without its `box` body.
fn without_box() -> String {
    let start = DEFAULT_SCENE.find("[[body]]\nname = \"box\"").unwrap();
    let end = start
        + DEFAULT_SCENE[start..]
            .find("\n[[body]]\nname = \"left_jaw\"")
            .unwrap();
    format!("{}{}", &DEFAULT_SCENE[..start], &DEFAULT_SCENE[end + 1..])
}

#[test]
fn default_scene_without_box_jaws_stop_on_each_other() {
    let scene = Scene::parse(&without_box(), "no_box.toml", Path::new(".")).unwrap();
    assert_eq!(scene.body_index("box"), None);
    let mut run = PlainRun::new(&scene);
    let h = run.handles.clone();
    let (left, right) = (
        h.fingertip("left_tip").unwrap(),
        h.fingertip("right_tip").unwrap(),
    );
    let (lj, rj) = (h.body("left_jaw").unwrap(), h.body("right_jaw").unwrap());
    let (mut peak, mut peak_x, mut steps_in_contact) = (0.0f64, 0.0f64, 0);
    let mut min_gap = f64::INFINITY;
    run.run(scene.steps(), |r| {
        let a: Vec<_> = r.world.soft.contacts_of(left).collect();
        let b: Vec<_> = r.world.soft.contacts_of(right).collect();
        assert_eq!(a.len(), b.len(), "both fingertips report the pair");
        if let (Some(a), Some(b)) = (a.first(), b.first()) {
            steps_in_contact += 1;
            assert_eq!(a.normal_force, b.normal_force);
            assert_eq!(a.normal[0], -b.normal[0]);
            // Identical pads in series: the same share of the approach each.
            assert_eq!(a.delta, b.delta);
            assert!(a.normal_force.is_finite());
            peak = peak.max(a.normal_force);
            peak_x = peak_x.max(a.x);
        }
        let x = |b: softgrip_scene::softgrip_rapier::rapier3d::prelude::RigidBodyHandle| {
            r.world.physics.bodies[b].translation().x as f64
        };
        min_gap = min_gap.min(x(rj) - x(lj));
    });
    println!(
        "jaws on each other: peak {peak:.3} N at x = {peak_x:.3} (each pad's share), closest centres {min_gap:.5} m, {steps_in_contact} steps in contact"
    );
    assert!(steps_in_contact > 100);
    // Each jaw squeezes 2 mm past touch: a 4 mm approach of two R = 10 mm pads, 2 mm each on
    // the mid-plane, x = 0.2 of each pad's own radius. The force is each pad's own (flat) law
    // there, not 26 kN.
    let tip = &scene.fingertips()[0];
    assert_eq!(
        tip.backing(),
        softgrip_scene::softgrip_rapier::softgrip_law::Backing::Flat
    );
    let f_law = tip.law().response(0.002).force;
    println!("flat law at half the 4 mm approach: {f_law:.3} N");
    assert!((peak / f_law - 1.0).abs() < 0.03, "{peak} N vs {f_law} N");
    assert!((peak_x - 0.2).abs() < 0.0025, "x = {peak_x}");
    // The jaws stop: the fingertip centres stay ~16 mm apart, never cross.
    assert!((min_gap - 0.016).abs() < 5e-4, "closest {min_gap} m");
}
