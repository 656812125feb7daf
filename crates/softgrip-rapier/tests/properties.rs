//! Property tests of the plugin (issue 11): random valid scenes of bounded size (1-4
//! fingertips of random radius, modulus, Poisson ratio, restitution and friction, dynamic or
//! kinematic, at random positions and velocities, some on each other, over a ground plane with
//! random boxes and balls, at a random dt and gravity) never panic, never produce a non-finite
//! pose or velocity, and keep every fingertip's force finite (and every soft-soft pair reported
//! by both fingertips, exactly opposite).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use proptest::prelude::*;
use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{SoftFingertip, SoftWorld};

/// One random fingertip: radius [m], E [Pa], nu, restitution, friction, dynamic, position [m],
/// velocity [m/s], level index.
type TipSpec = (f64, f64, f64, f64, f64, bool, [f32; 3], [f32; 3], usize);

fn tip_spec() -> impl Strategy<Value = TipSpec> {
    (
        1e-3f64..0.05,
        1e4f64..1e8,
        0.0f64..0.4999,
        0.05f64..=1.0,
        0.0f64..2.0,
        any::<bool>(),
        prop::array::uniform3(-0.05f32..0.05),
        prop::array::uniform3(-5.0f32..5.0),
        0usize..Level::ALL.len(),
    )
}

/// A rigid obstacle: cuboid (half extents) or ball (radius), position, dynamic.
type Obstacle = (bool, [f32; 3], [f32; 3], bool);

fn obstacle() -> impl Strategy<Value = Obstacle> {
    (
        any::<bool>(),
        prop::array::uniform3(0.002f32..0.05),
        prop::array::uniform3(-0.05f32..0.05),
        any::<bool>(),
    )
}

fn build(tips: &[TipSpec], obstacles: &[Obstacle], dt: f32, g: [f32; 3]) -> Option<SoftWorld> {
    let mut world = SoftWorld::new();
    world.physics.integration_parameters.dt = dt;
    world.physics.gravity = Vector::new(g[0], g[1], g[2]);
    world.physics.colliders.insert(
        ColliderBuilder::new(SharedShape::halfspace(Vector::Y))
            .translation(Vector::new(0.0, -0.06, 0.0)),
    );
    for &(cuboid, size, pos, dynamic) in obstacles {
        let body = if dynamic {
            RigidBodyBuilder::dynamic()
        } else {
            RigidBodyBuilder::fixed()
        };
        let b = world
            .physics
            .bodies
            .insert(body.translation(Vector::new(pos[0], pos[1], pos[2])));
        let shape = if cuboid {
            ColliderBuilder::cuboid(size[0], size[1], size[2])
        } else {
            ColliderBuilder::ball(size[0])
        };
        world
            .physics
            .colliders
            .insert_with_parent(shape, b, &mut world.physics.bodies);
    }
    for &(r, e, nu, rest, mu, dynamic, pos, vel, level) in tips {
        // Some levels refuse some Poisson ratios (a typed error): such a scene is not valid.
        let tip = SoftFingertip::builder(r)
            .material(Material::try_new(e, nu).ok()?)
            .level(Level::ALL[level])
            .restitution(rest)
            .friction(mu)
            .build()
            .ok()?;
        let p = Vector::new(pos[0], pos[1], pos[2]);
        let (body, _) = if dynamic {
            common::dynamic_tip(&mut world, p, 1070.0, tip)
        } else {
            common::kinematic_tip(&mut world, p, tip)
        };
        if dynamic {
            world.physics.bodies[body].set_linvel(Vector::new(vel[0], vel[1], vel[2]), true);
        }
    }
    Some(world)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_valid_scenes_stay_finite(
        tips in prop::collection::vec(tip_spec(), 1..=4),
        obstacles in prop::collection::vec(obstacle(), 0..=3),
        dt in 1e-4f32..(1.0 / 30.0),
        g in prop::array::uniform3(-20.0f32..20.0),
    ) {
        let Some(mut world) = build(&tips, &obstacles, dt, g) else {
            return Ok(());
        };
        for step in 0..30 {
            world.step();
            prop_assert!(common::all_finite(&world), "non-finite pose or velocity at step {}", step);
            for c in world.soft.contacts() {
                let (f, t) = c.wrench_about([0.0; 3]);
                prop_assert!(c.normal_force.is_finite() && c.normal_force >= 0.0, "{:?}", c);
                prop_assert!(f.iter().chain(&t).all(|x| x.is_finite()), "{:?}", c);
                if world.soft.is_soft(c.other) {
                    let m = world.soft.contacts_of(c.other).find(|d| d.other == c.fingertip);
                    prop_assert!(m.is_some_and(|d| d.normal_force == c.normal_force), "{:?}", c);
                }
            }
        }
    }
}
