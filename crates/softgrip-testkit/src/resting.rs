//! N fingertips resting on a fixed ground on a square grid: the scene of the plugin's
//! overhead benchmark (`softgrip-bench`, `OverheadScene`, at [`PITCH`]) and of its group-size
//! tests (`softgrip-rapier/tests/groups.rs`, at any pitch), built once here so that both
//! measure the same balls inserted in the same order.

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::SoftWorld;

use crate::scenes::{DENSITY, G, RADIUS, fingertip};

/// The benchmarks' grid pitch \[m\]: three radii, so neighbours never touch (gaps of 10 mm).
pub const PITCH: f32 = 0.03;

/// `n` dynamic balls of radius [`RADIUS`] and density [`DENSITY`] that never sleep, centred on
/// a square grid of `pitch` \[m\] (centre to centre, `ceil(sqrt(n))` a side, centred on the
/// origin) over a fixed cuboid ground whose top face is at y = 0, each at the scenes'
/// fingertip's resting depth (`F(delta) = m g`, [`fingertip`]`(Level::auto(), 0.5)`).
/// Registered as that fingertip if `soft` (else rapier's own contacts hold them). Inserted in
/// this order: the ground, then each ball's body and collider, row by row.
pub fn resting_grid(n: usize, pitch: f32, soft: bool) -> SoftWorld {
    resting_grid_with(n, pitch, soft, false)
}

/// [`resting_grid`] with the balls' sleep policy: `can_sleep` lets them sleep under rapier's
/// default thresholds (`RigidBodyBuilder::dynamic()`'s: still for 0.5 s), as a user's scene
/// would.
pub fn resting_grid_with(n: usize, pitch: f32, soft: bool, can_sleep: bool) -> SoftWorld {
    let mut world = SoftWorld::new();
    let side = (n as f64).sqrt().ceil() as usize;
    let half = 0.5 * side as f32 * pitch + pitch;
    world.physics.colliders.insert(
        ColliderBuilder::cuboid(half, 0.01, half).translation(Vector::new(0.0, -0.01, 0.0)),
    );
    let tip = fingertip(Level::auto(), 0.5)
        .build()
        .expect("invariant: valid fingertip");
    let mass = DENSITY as f64 * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let rest = tip
        .law()
        .compression_for_force(mass * G)
        .expect("invariant: the weight is within the law's range");
    for i in 0..n {
        let (row, col) = (i / side, i % side);
        let x = (col as f32 - 0.5 * (side - 1) as f32) * pitch;
        let z = (row as f32 - 0.5 * (side - 1) as f32) * pitch;
        let body = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, (RADIUS - rest) as f32, z))
                .can_sleep(can_sleep),
        );
        let ball = world.physics.colliders.insert_with_parent(
            ColliderBuilder::ball(RADIUS as f32).density(DENSITY),
            body,
            &mut world.physics.bodies,
        );
        if soft {
            world
                .register(ball, tip.clone())
                .expect("invariant: a ball of the fingertip's radius");
        }
    }
    world
}
