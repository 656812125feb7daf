//! The golden digest of the default scene: every contact value of every step (the bit
//! patterns of forces, compression, x, moment, stiffness, point, normal; see
//! `softgrip_scene::ContactDigest`), hashed. A second process (`softgrip run --digest`,
//! through the ECS) must reproduce, bit for bit, the digest computed here in-process (through
//! the plain runner) and the one committed below.
//!
//! When the physics changes ON PURPOSE (a law, the plugin, rapier, the scene): run
//! `cargo run -p softgrip-cli -- run --digest`, copy its `digest ...` line into [`GOLDEN`],
//! and say in the commit message why the contact values changed. A change that was not meant
//! to move the physics must leave this test green.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_scene::{ContactDigest, PlainRun, Scene};

/// `softgrip run --digest` of the embedded default scene (`scenes/default.toml`).
const GOLDEN: &str = "digest 49d2f07bd2bedf33 steps 300 contacts 447";

#[test]
fn default_scene_digest_is_golden_in_a_second_process() {
    let out = common::softgrip(&["run", "--digest"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let printed = stdout
        .lines()
        .find(|l| l.starts_with("digest "))
        .unwrap_or_else(|| panic!("no digest line in:\n{stdout}"));

    let scene = Scene::default_scene();
    let mut run = PlainRun::new(&scene);
    let mut here = ContactDigest::new();
    run.run(scene.steps(), |r| {
        here.add_step(r.world.soft.contacts().iter())
    });
    assert!(
        here.contacts() > 100,
        "{here}: the fingertips touch the box"
    );

    assert_eq!(
        printed,
        here.to_string(),
        "`softgrip run --digest` (ECS, second process) vs the plain runner in this process"
    );
    assert_eq!(
        printed, GOLDEN,
        "the default scene's contact values changed: if on purpose, update GOLDEN (see the top of this file)"
    );
}
