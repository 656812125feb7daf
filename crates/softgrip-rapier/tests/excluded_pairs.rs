//! Pairs of bodies kept from touching (`SoftContacts::exclude_pair`, session 32): rapier
//! computes no contact between their colliders and the plugin no soft contact between a
//! fingertip on one and the other, while every other pair, and the user's own pair filter on
//! the pairs it asked for, behaves as before.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::sync::atomic::{AtomicUsize, Ordering};

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::{Error, SoftWorld};
use softgrip_testkit::scenes::{RADIUS as R, fingertip};

/// Two dynamic cubes (half-extent 10 mm) overlapping by 5 mm, no gravity, and a third cube
/// touching neither; a fingertip's ball on the first cube 2 mm into a fixed block.
struct World {
    world: SoftWorld,
    a: RigidBodyHandle,
    b: RigidBodyHandle,
    block: RigidBodyHandle,
}

fn world() -> World {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let w = &mut world.physics;
    let cube = |w: &mut PhysicsWorld, x: f32| {
        let h = w
            .bodies
            .insert(RigidBodyBuilder::dynamic().translation(Vector::new(x, 0.0, 0.0)));
        w.colliders
            .insert_with_parent(ColliderBuilder::cuboid(0.01, 0.01, 0.01), h, &mut w.bodies);
        h
    };
    let a = cube(w, 0.0);
    let b = cube(w, 0.015);
    // The fingertip on `a`, its ball's bottom 2 mm into the fixed block below.
    let tip = w.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32)
            .density(1000.0)
            .translation(Vector::new(0.0, -0.05, 0.0)),
        a,
        &mut w.bodies,
    );
    let block = w
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.05 - R as f32, 0.0)));
    w.colliders.insert_with_parent(
        ColliderBuilder::cuboid(0.02, 0.002, 0.02),
        block,
        &mut w.bodies,
    );
    world
        .register(tip, fingertip(Level::Calibrated, 0.5).build().unwrap())
        .unwrap();
    World { world, a, b, block }
}

/// The cubes' speeds [m/s] and the fingertip's soft contacts after one step.
fn step(mut s: World) -> (f32, f32, usize) {
    s.world.step();
    let v = |h: RigidBodyHandle| s.world.physics.bodies[h].linvel().length();
    (v(s.a), v(s.b), s.world.soft.contacts().len())
}

/// Not excluded: rapier pushes the overlapping cubes apart and the fingertip presses the block.
/// Excluded: the second cube is left untouched (still); the fingertip still presses the
/// block. The block excluded from the fingertip's body: no soft contact.
#[test]
fn an_excluded_pair_never_touches_and_every_other_pair_does() {
    let (va, vb, n) = step(world());
    println!("plain: cubes {va:.4} / {vb:.4} m/s, {n} soft contacts");
    // rapier's push apart of a 5 mm overlap (`a` also carries the fingertip's push).
    assert!(vb > 1e-3, "{va} {vb}");
    assert_eq!(n, 1);

    let mut s = world();
    let (a, b) = (s.a, s.b);
    s.world.exclude_pair(b, a).unwrap();
    assert!(s.world.soft.is_excluded(a, b) && s.world.soft.is_excluded(b, a));
    assert_eq!(s.world.soft.excluded_pairs().len(), 1);
    let (va, vb, n) = step(s);
    println!("cubes excluded: {va:.2e} / {vb:.2e} m/s, {n} soft contacts");
    assert!(vb == 0.0, "{va} {vb}");
    assert_eq!(n, 1);

    let mut s = world();
    let (a, block) = (s.a, s.block);
    s.world.exclude_pair(a, block).unwrap();
    let (_, _, n) = step(s);
    assert_eq!(n, 0, "the fingertip's body and the block are kept apart");
}

/// Bad handles are typed errors, not panics.
#[test]
fn excluding_an_unknown_body_or_a_body_with_itself_is_an_error() {
    let mut s = world();
    let gone = s.b;
    let w = &mut s.world.physics;
    w.bodies.remove(
        gone,
        &mut w.islands,
        &mut w.colliders,
        &mut w.impulse_joints,
        &mut w.multibody_joints,
        &mut w.soft_bodies,
        true,
    );
    let a = s.a;
    assert!(matches!(
        s.world.exclude_pair(a, gone),
        Err(Error::UnknownBody(h)) if h == gone
    ));
    assert!(matches!(
        s.world.exclude_pair(a, a),
        Err(Error::SamePair(h)) if h == a
    ));
    assert!(s.world.soft.excluded_pairs().is_empty());
}

/// Counts the pairs the user's filter is asked about.
#[derive(Default)]
struct Counting(AtomicUsize);

impl PhysicsHooks for Counting {
    fn filter_contact_pair(&self, _: &PairFilterContext) -> Option<SolverFlags> {
        self.0.fetch_add(1, Ordering::Relaxed);
        Some(SolverFlags::default())
    }
}

/// The plugin turns rapier's pair filter on for an excluded pair's colliders; the user's own
/// filter is still asked only about the pairs of colliders the user turned it on for.
#[test]
fn the_users_filter_sees_only_the_pairs_it_asked_for() {
    // The third cube overlaps `b` only; the user's filter is on for none of them.
    let mut s = world();
    let w = &mut s.world.physics;
    let c = w
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.03, 0.0, 0.0)));
    let cc =
        w.colliders
            .insert_with_parent(ColliderBuilder::cuboid(0.01, 0.01, 0.01), c, &mut w.bodies);
    let (a, b) = (s.a, s.b);
    s.world.exclude_pair(a, b).unwrap();
    let hooks = Counting::default();
    s.world.step_with(&hooks, &());
    assert_eq!(hooks.0.load(Ordering::Relaxed), 0);
    // b-c still collide (rapier's default answer): pushed apart.
    assert!(s.world.physics.bodies[c].linvel().length() > 1e-3);
    // The user turns the filter on for c: asked about b-c.
    let co = s.world.physics.colliders.get_mut(cc).unwrap();
    co.set_active_hooks(co.active_hooks() | ActiveHooks::FILTER_CONTACT_PAIRS);
    s.world.step_with(&hooks, &());
    assert!(hooks.0.load(Ordering::Relaxed) >= 1);
}
