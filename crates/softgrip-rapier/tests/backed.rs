//! Backed fingertips (issue 10): a `flat` pad (a hemisphere bonded to a rigid finger) and a
//! `core` pad (a skin over a rigid core) use their construction's law; what touches them
//! from behind the flat face meets the rigid finger (rapier's own contact); two pads of which
//! one is backed meet in series on their rigid mid-surface.
//!
//! Every number is compared with `ContactLaw` itself (the backed constants are being fitted:
//! no law number is written here).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};
use softgrip_rapier::{Error, SoftFingertip, SoftWorld};
use softgrip_testkit::scenes::{BallDrop, half_space_ground};

const R: f64 = 0.01;

fn material() -> Material {
    Material::try_new(0.59e6, 0.49).unwrap()
}

fn backed(backing: Backing, facing: [f64; 3], restitution: f64) -> SoftFingertip {
    SoftFingertip::builder(R)
        .material(material())
        .backing(backing)
        .facing(facing)
        .restitution(restitution)
        .build()
        .unwrap()
}

fn core() -> Backing {
    Backing::Core { thickness: 0.4 * R }
}

#[test]
fn backed_fingertip_binds_its_constructions_law() {
    for backing in [Backing::Flat, core()] {
        let tip = backed(backing, [0.0, 0.0, 2.0], 0.5);
        assert_eq!(tip.backing(), backing);
        assert_eq!(tip.facing(), Some([0.0, 0.0, 1.0]));
        let own = ContactLaw::try_new(
            ContactParams::try_new(material(), R)
                .unwrap()
                .with_backing(backing)
                .unwrap(),
            Level::auto(),
        )
        .unwrap();
        assert_eq!(tip.law().params().backing(), backing);
        for x in [0.01, 0.1, 0.3] {
            assert_eq!(
                tip.law().response(x * R).force,
                own.response(x * R).force,
                "{backing} at x = {x}"
            );
        }
    }
    // A free fingertip keeps no facing.
    let free = SoftFingertip::builder(R)
        .material(material())
        .facing([1.0, 0.0, 0.0])
        .build()
        .unwrap();
    assert_eq!(free.facing(), None);
    assert!(free.backing().is_free());
}

#[test]
fn backed_fingertip_without_a_valid_facing_is_a_typed_error() {
    let b = || SoftFingertip::builder(R).material(material());
    let e = b().backing(Backing::Flat).build().unwrap_err();
    assert_eq!(e, Error::MissingFacing("flat"));
    assert!(e.to_string().contains("`facing`"), "{e}");
    for (facing, value) in [
        ([0.0, 0.0, 0.0], 0.0),
        ([f64::NAN, 1.0, 0.0], f64::NAN),
        ([1.0, f64::INFINITY, 0.0], f64::INFINITY),
    ] {
        let e = b().backing(core()).facing(facing).build().unwrap_err();
        match e {
            Error::InvalidParameter {
                field, value: v, ..
            } => {
                assert_eq!(field, "facing");
                assert!(v == value || (v.is_nan() && value.is_nan()), "{v}");
            }
            e => panic!("{e}"),
        }
    }
    // The core's thickness is the law's check: (0, R).
    let e = b()
        .backing(Backing::Core { thickness: R })
        .facing([1.0, 0.0, 0.0])
        .build()
        .unwrap_err();
    assert!(e.to_string().contains("`thickness`"), "{e}");
}

/// Worst |F / F_law - 1| of a kinematic pad facing -y pressed slowly into the rigid
/// ground (1 mm/s) to 0.9 of its law's range, read against the law at the readout's compression and at
/// the geometric one (R - centre height).
fn squeeze_on_ground(backing: Backing) -> (f64, f64, f64) {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    half_space_ground(&mut world);
    let tip = backed(backing, [0.0, -1.0, 0.0], 1.0);
    let law = tip.law().clone();
    let (body, co) = common::kinematic_tip(&mut world, Vector::new(0.0, R as f32, 0.0), tip);
    let dt = world.physics.integration_parameters.dt as f64;
    let (speed, x_end) = (0.001, 0.9 * law.x_max());
    let (mut worst, mut worst_geom, mut x_reached) = (0.0f64, 0.0f64, 0.0);
    let mut samples = 0;
    for i in 1..10_000 {
        let y = R - speed * dt * i as f64;
        if (R - y) / R > x_end {
            break;
        }
        common::move_to(&mut world, body, Vector::new(0.0, y as f32, 0.0));
        world.step();
        let y_now = world.physics.bodies[body].translation().y as f64;
        let x = (R - y_now) / R;
        // From x = 0.05: below, one step's travel (17 um) is a large part of the compression
        // and the readout's step average is off the end-of-step law by its curvature.
        if x < 0.05 {
            continue;
        }
        let c = world.soft.contacts_of(co).next().expect("in contact");
        worst = worst.max((c.normal_force / law.response(c.delta).force - 1.0).abs());
        worst_geom = worst_geom.max((c.normal_force / law.response(R - y_now).force - 1.0).abs());
        x_reached = x;
        samples += 1;
    }
    assert!(samples > 50);
    (worst, worst_geom, x_reached)
}

#[test]
fn flat_and_core_pads_squeezed_quasi_statically_follow_their_own_law() {
    for backing in [Backing::Flat, core()] {
        let (worst, worst_geom, x) = squeeze_on_ground(backing);
        println!(
            "{backing} pad squeezed at 1 mm/s to x = {x:.3}: worst |F/F_law - 1| = {worst:.2e} (readout delta), {worst_geom:.2e} (geometry)"
        );
        assert!(worst < 0.005, "{backing}: {worst}");
        assert!(worst_geom < 0.005, "{backing}: {worst_geom}");
    }
}

/// A box dropped on the back of a kinematic flat pad that faces down (a finger pressing
/// down): it lands on the rigid finger's side, rapier's own contact holds it on the ball's
/// top (no soft readout row, no soft compression). Dropped the same way on a free fingertip,
/// it rests on the soft law, at the law's inverse of its weight.
#[test]
fn box_on_the_back_of_a_flat_pad_is_held_rigidly() {
    let rest = |backing: Backing| {
        let mut world = SoftWorld::new();
        let tip = if backing.is_free() {
            SoftFingertip::builder(R)
                .material(material())
                .build()
                .unwrap()
        } else {
            backed(backing, [0.0, -1.0, 0.0], 0.5)
        };
        let law = tip.law().clone();
        let (_, pad_co) = common::kinematic_tip(&mut world, Vector::ZERO, tip);
        let half = 0.01f32;
        let box_mass = 0.2f32;
        let object = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, R as f32 + half + 0.002, 0.0))
                .lock_rotations()
                .can_sleep(false),
        );
        let box_co = world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(half, half, half).mass(box_mass),
            object,
            &mut world.physics.bodies,
        );
        for _ in 0..240 {
            world.step();
            assert!(common::all_finite(&world));
        }
        let row = world
            .soft
            .contacts_of(pad_co)
            .find(|c| c.other == box_co)
            .cloned();
        let sink = R + half as f64 - world.physics.bodies[object].translation().y as f64;
        let weight = box_mass as f64 * common::G;
        (
            row,
            sink,
            law.compression_for_force(weight).unwrap(),
            weight,
        )
    };
    let (row, sink, _, _) = rest(Backing::Flat);
    assert!(
        row.is_none(),
        "a soft row with the box behind the face: {row:?}"
    );
    let (free_row, free_sink, delta_law, weight) = rest(Backing::Free);
    let free_row = free_row.expect("the free fingertip is soft all round");
    println!(
        "box (1.96 N) on a flat pad's back: sinks {sink:.2e} m into the rigid ball (rapier's contact); on a free tip: {free_sink:.4e} m, soft row {:.4} N at delta {:.4e} m (law inverse {delta_law:.4e} m)",
        free_row.normal_force, free_row.delta
    );
    // rapier's rigid contact: a penetration below its allowed linear error (1 mm at the
    // default length unit); the soft one: the law's compression.
    assert!((-1e-4..1e-3).contains(&sink), "sink {sink} m");
    assert!(sink < 0.5 * delta_law, "{sink} vs the soft {delta_law}");
    assert!((free_row.normal_force / weight - 1.0).abs() < 0.005);
    assert!((free_sink / delta_law - 1.0).abs() < 0.01);
}

/// Two identical flat pads facing each other, pressed together by their kinematic fingers:
/// each is pressed on the rigid mid-plane by half the approach, both read the same force
/// (their own law at half the approach), equal and opposite.
#[test]
fn identical_flat_pads_meet_in_series_half_each() {
    let (worst, pairs) = pads_in_series(Backing::Flat, Backing::Flat, |d1, d2, total| {
        assert_eq!(d1, d2, "identical pads split exactly in half");
        assert_eq!(d1, 0.5 * total);
    });
    println!(
        "two flat pads in series: worst |F/F_law(delta/2) - 1| = {worst:.2e} over {pairs} samples"
    );
    assert!(worst < 0.005);
}

/// A flat pad against a core pad: the split has equal forces, the shares add up to the approach.
#[test]
fn flat_and_core_pads_meet_in_series_with_equal_forces() {
    let (worst, pairs) = pads_in_series(Backing::Flat, core(), |d1, d2, total| {
        assert!(
            (d1 + d2 - total).abs() <= 1e-12 * total,
            "{d1} + {d2} vs {total}"
        );
        // The core skin is stiffer: the flat pad takes the larger share.
        assert!(d1 > d2, "{d1} {d2}");
    });
    println!(
        "flat + core pads in series: worst |F/F_law(delta_i) - 1| = {worst:.2e} over {pairs} samples"
    );
    assert!(worst < 0.005);
}

/// Presses a pad `a` (facing +x) and a pad `b` (facing -x) together quasi-statically; `check`
/// gets each step's shares and total approach. Returns the worst |F / F_i(delta_i) - 1| over
/// both readouts and the number of samples.
fn pads_in_series(a: Backing, b: Backing, check: impl Fn(f64, f64, f64)) -> (f64, usize) {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let (ta, tb) = (
        backed(a, [1.0, 0.0, 0.0], 1.0),
        backed(b, [-1.0, 0.0, 0.0], 1.0),
    );
    let (la, lb) = (ta.law().clone(), tb.law().clone());
    let gap = 0.0005;
    let (ba, ca) = common::kinematic_tip(&mut world, Vector::new(-(R + gap) as f32, 0.0, 0.0), ta);
    let (bb, cb) = common::kinematic_tip(&mut world, Vector::new((R + gap) as f32, 0.0, 0.0), tb);
    let dt = world.physics.integration_parameters.dt as f64;
    let (mut worst, mut samples) = (0.0f64, 0);
    for i in 1..800 {
        let x = -(R + gap) + 0.001 * dt * i as f64;
        if (R + gap + x) > 0.6 * R {
            break;
        }
        common::move_to(&mut world, ba, Vector::new(x as f32, 0.0, 0.0));
        common::move_to(&mut world, bb, Vector::new(-x as f32, 0.0, 0.0));
        world.step();
        let (Some(ra), Some(rb)) = (
            world.soft.contacts_of(ca).next(),
            world.soft.contacts_of(cb).next(),
        ) else {
            continue;
        };
        assert_eq!((ra.other, rb.other), (cb, ca));
        let sep = (world.physics.bodies[bb].translation().x
            - world.physics.bodies[ba].translation().x) as f64;
        let total = ra.delta + rb.delta;
        // Each share from x = 0.05 on (see `squeeze_on_ground`).
        if total < 0.1 * R {
            continue;
        }
        // The readout's approach is the geometric one (end of the step).
        assert!(
            (total - (2.0 * R - sep)).abs() < 1e-3 * total + 1e-9,
            "{total} vs {}",
            2.0 * R - sep
        );
        check(ra.delta, rb.delta, total);
        assert_eq!(ra.normal_force, rb.normal_force);
        for i in 0..3 {
            assert_eq!(ra.normal[i], -rb.normal[i]);
        }
        // Each reads its own law at its own share, with its own patch.
        assert_eq!(ra.law().params().backing(), a);
        assert_eq!(rb.law().params().backing(), b);
        let (fa, fb) = (la.response(ra.delta).force, lb.response(rb.delta).force);
        assert!((fa / fb - 1.0).abs() < 1e-9, "{fa} vs {fb}");
        assert!((ra.patch().radius - la.patch(ra.delta).radius).abs() < 1e-15);
        worst = worst.max((ra.normal_force / fa - 1.0).abs());
        samples += 1;
    }
    assert!(samples > 20, "{samples}");
    (worst, samples)
}

/// A flat pad dropped on its face (facing -y) bounces like the free ball: elastic, its energy
/// (with the backed law's stored energy) kept over 10 bounces.
#[test]
fn elastic_bounce_of_a_flat_pad_keeps_energy() {
    let tip = softgrip_testkit::scenes::fingertip(Level::auto(), 1.0)
        .backing(Backing::Flat)
        .facing([0.0, -1.0, 0.0])
        .friction(0.0)
        .build()
        .unwrap();
    let mut s = BallDrop::new(tip, 0.1);
    let e0 = s.energy();
    let (mut bounces, mut in_contact, mut e_max) = (0, false, e0);
    let mut e10 = e0;
    for _ in 0..400 {
        s.world.step();
        let touching = !s.world.soft.contacts().is_empty();
        let e = s.energy();
        if !touching {
            e_max = e_max.max(e);
        }
        if in_contact && !touching {
            bounces += 1;
            e10 = e;
            if bounces == 10 {
                break;
            }
        }
        in_contact = touching;
    }
    println!(
        "flat pad bounce: {bounces} bounces, E10/E0 - 1 = {:.3e}, max E/E0 - 1 = {:.3e}",
        e10 / e0 - 1.0,
        e_max / e0 - 1.0
    );
    assert_eq!(bounces, 10);
    // The free ball's figures are +0.085 % and +0.089 % (bounce.rs): the same 0.2 % band.
    assert!((e10 / e0 - 1.0).abs() < 0.003, "{}", e10 / e0 - 1.0);
    assert!((e_max / e0 - 1.0).abs() < 0.003, "{}", e_max / e0 - 1.0);
}

/// The torsional friction limit is the law's: two kinematic flat pads squeeze a free box (no
/// gravity) from above and below and are spun about the contact normal; the box cannot follow
/// at once, so each pad's moment is saturated at `ContactPatch::torsion_limit(mu, F)` of its
/// own patch (the integral of `mu p r dA` over the law's pressure shape; it was a fixed
/// `3 pi / 16 mu F a`).
#[test]
fn spun_pads_twist_the_box_at_their_patchs_torsion_limit() {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let half = 0.02f32;
    let object = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::dynamic().can_sleep(false));
    world.physics.colliders.insert_with_parent(
        ColliderBuilder::cuboid(half, half, half).mass(0.5),
        object,
        &mut world.physics.bodies,
    );
    let mu = 0.8;
    // Each pressed 1 mm into the box.
    let y = half as f64 + R - 0.001;
    let pads: Vec<_> = [1.0f64, -1.0]
        .into_iter()
        .map(|side| {
            let tip = SoftFingertip::builder(R)
                .material(material())
                .backing(Backing::Flat)
                .facing([0.0, -side, 0.0])
                .friction(mu)
                .build()
                .unwrap();
            let pos = Vector::new(0.0, (side * y) as f32, 0.0);
            (common::kinematic_tip(&mut world, pos, tip), pos)
        })
        .collect();
    let dt = world.physics.integration_parameters.dt;
    let (mut angle, mut checked) = (0.0f32, 0);
    // The box (I = 1.3e-4 kg m^2) under the two saturated moments spins up at ~100 rad/s^2:
    // 8 steps after the start it is still far below the pads' 60 rad/s.
    for i in 0..20 {
        if i >= 10 {
            // Spin the pads fast about the normal (y): the box cannot follow at once.
            angle += 60.0 * dt;
        }
        for ((body, _), pos) in &pads {
            world.physics.bodies[*body].set_next_kinematic_position(Pose::from_parts(
                *pos,
                Rotation::from_axis_angle(Vector::Y, angle),
            ));
        }
        world.step();
        if i < 12 {
            continue;
        }
        for ((_, co), _) in &pads {
            let c = world
                .soft
                .contacts_of(*co)
                .next()
                .expect("pressed on the box");
            let patch = c.patch();
            let limit = patch.torsion_limit(mu, c.normal_force);
            let hertz = 3.0 * std::f64::consts::PI / 16.0 * mu * c.normal_force * patch.radius;
            if checked == 0 {
                println!(
                    "spun flat pads: |moment| {:.6e} N m, torsion_limit {limit:.6e} N m (shape m = {:.4}; 3 pi/16 would give {hertz:.6e})",
                    c.torsional_moment.abs(),
                    patch.shape
                );
            }
            assert!(
                (c.torsional_moment.abs() / limit - 1.0).abs() < 1e-3,
                "step {i}: {} vs {limit}",
                c.torsional_moment
            );
            checked += 1;
        }
    }
    assert!(checked >= 16);
}

/// A free fingertip pressed on the back of a flat pad (behind its face) meets the rigid
/// finger: one row, the free fingertip's, at its own law of the whole approach; the pad
/// reports nothing.
#[test]
fn free_fingertip_on_the_back_of_a_flat_pad_reads_its_own_law() {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let pad = backed(Backing::Flat, [1.0, 0.0, 0.0], 1.0);
    let free = SoftFingertip::builder(R)
        .material(material())
        .restitution(1.0)
        .build()
        .unwrap();
    let law = free.law().clone();
    let (_, pad_co) = common::kinematic_tip(&mut world, Vector::ZERO, pad);
    let (free_body, free_co) = common::kinematic_tip(
        &mut world,
        Vector::new(-(2.0 * R) as f32 - 0.0005, 0.0, 0.0),
        free,
    );
    let dt = world.physics.integration_parameters.dt as f64;
    let mut samples = 0;
    for i in 1..200 {
        let x = -2.0 * R - 0.0005 + 0.001 * dt * i as f64;
        if -x < 2.0 * R - 0.002 {
            break;
        }
        common::move_to(&mut world, free_body, Vector::new(x as f32, 0.0, 0.0));
        world.step();
        assert_eq!(
            world.soft.contacts_of(pad_co).count(),
            0,
            "the pad's back is rigid"
        );
        let approach = 2.0 * R + world.physics.bodies[free_body].translation().x as f64;
        let Some(c) = world.soft.contacts_of(free_co).next() else {
            assert!(approach < 1e-4, "no row at approach {approach}");
            continue;
        };
        assert_eq!(c.other, pad_co);
        assert!(c.backing.is_free());
        if approach < 0.05 * R {
            continue;
        }
        assert!(
            (c.delta / approach - 1.0).abs() < 1e-3,
            "{} vs {approach}",
            c.delta
        );
        assert!((c.normal_force / law.response(c.delta).force - 1.0).abs() < 0.005);
        samples += 1;
    }
    assert!(samples > 20, "{samples}");
}
