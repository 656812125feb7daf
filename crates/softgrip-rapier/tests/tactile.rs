//! Tactile pads (issue 12, item 6): the image of a fingertip's contacts integrates to their
//! normal force, moves with the patch by the distance it slides along the surface, reads zero
//! without contact, and bad pads are typed errors naming the field, value and range.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_rapier::{
    Error, Preset, SoftFingertip, SoftWorld, TactileGrid, TactileImage, TactilePad,
};

const R: f64 = 0.01;

fn tip_with(pad: TactilePad) -> SoftFingertip {
    SoftFingertip::builder(R)
        .preset(Preset::DragonSkin30)
        .tactile(pad)
        .build()
        .unwrap()
}

/// A 32 x 32 pad, 16 mm x 16 mm (0.5 mm taxels), facing -y, its top towards +x.
fn down_pad() -> TactilePad {
    TactilePad::new(32, 32, [0.0, -1.0, 0.0], 0.016, 0.016).with_up([1.0, 0.0, 0.0])
}

/// A fixed ground (half-space, normal +y) and a kinematic fingertip pressed `delta` \[m\] into
/// it, its body turned by `angle` \[rad\] about z.
fn pressed(pad: TactilePad, delta: f64) -> (SoftWorld, RigidBodyHandle, ColliderHandle) {
    let mut world = SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    let at = Vector::new(0.0, (R - delta) as f32, 0.0);
    let (body, co) = common::kinematic_tip(&mut world, at, tip_with(pad));
    (world, body, co)
}

fn turn(world: &mut SoftWorld, body: RigidBodyHandle, angle: f64) {
    let t = world.physics.bodies[body].translation();
    let pose = Pose::new(t, Vector::new(0.0, 0.0, angle as f32));
    world.physics.bodies[body].set_next_kinematic_position(pose);
}

#[test]
fn image_integrates_to_the_normal_force_and_slides_with_the_patch() {
    let (mut world, body, co) = pressed(down_pad(), 0.05 * R);
    let (mut worst_force, mut worst_shift, mut first) = (0.0f64, 0.0f64, None);
    let taxel = 0.016 / 32.0;
    for i in 0..=60 {
        // 0.005 rad per step about z: the patch moves 50 µm along the surface per step, to 3 mm.
        let angle = 0.005 * i as f64;
        turn(&mut world, body, angle);
        world.step();
        let c = world.soft.contacts().first().expect("in contact").clone();
        let image = world.soft.tactile_image(co).expect("a pad");
        let ratio = image.total_force() / c.normal_force;
        worst_force = worst_force.max((ratio - 1.0).abs());
        let [u, v] = image.centroid().expect("pressed");
        // The body turned counter-clockwise about z: the ground (world -y) is at
        // (-sin a, -cos a, 0) in its frame, along the surface R a from -y towards -x,
        // i.e. v = -R a (the pad's top is +x), u = 0.
        let q = world.physics.bodies[body].rotation();
        let turned = 2.0 * (q.z as f64).atan2(q.w as f64);
        let (u0, v0) = *first.get_or_insert((u, v + R * turned));
        worst_shift = worst_shift
            .max((u - u0).abs())
            .max((v - (v0 - R * turned)).abs());
    }
    println!(
        "tactile slide (32 x 32, 0.5 mm taxels, a = {:.3} mm, 3 mm along the surface): worst |Σ p A / F - 1| = {worst_force:.2e}, worst centroid error {:.4} taxel, first centroid ({:.2e}, {:.2e}) m",
        world.soft.contacts()[0].patch().radius * 1e3,
        worst_shift / taxel,
        first.unwrap().0,
        first.unwrap().1
    );
    assert!(worst_force < 1e-5, "{worst_force}"); // README: 1.4e-7
    assert!(worst_shift < 0.01 * taxel, "{} taxel", worst_shift / taxel); // README: 0.0011
    assert!(first.unwrap().0.abs() < 1e-3 * taxel && first.unwrap().1.abs() < 1e-3 * taxel);
}

#[test]
fn image_of_a_tilted_pad_sits_at_the_contact_direction() {
    // The pad's centre 20° from the contact, its top towards -z: the patch lies 20° R along u.
    let t = 20f64.to_radians();
    let pad =
        TactilePad::new(24, 20, [t.sin(), -t.cos(), 0.0], 0.02, 0.012).with_up([0.0, 0.0, -1.0]);
    let (mut world, _, co) = pressed(pad, 0.03 * R);
    world.step();
    let c = world.soft.contacts()[0].clone();
    let image = world.soft.tactile_image(co).unwrap();
    let grid: &TactileGrid = image.grid();
    let expected = grid.coordinates([0.0, -1.0, 0.0]).unwrap();
    let [u, v] = image.centroid().unwrap();
    let du = grid.taxel_width();
    println!(
        "tilted pad: centroid ({u:.3e}, {v:.3e}) m vs ({:.3e}, {:.3e}) m, Σ p A / F - 1 = {:.2e}",
        expected[0],
        expected[1],
        image.total_force() / c.normal_force - 1.0
    );
    // e_v = -z, e_u = e_v x d = -(cos t, sin t, 0): the contact, R t along the surface from
    // the centre towards -x, is at u = +R t.
    assert!((expected[0] - R * t).abs() < 1e-12 && expected[1].abs() < 1e-12);
    assert!((u - expected[0]).abs() < 0.05 * du && v.abs() < 0.05 * du);
    assert!((image.total_force() / c.normal_force - 1.0).abs() < 1e-4);
}

#[test]
fn empty_grid_reads_zero_and_a_pad_facing_away_sees_nothing() {
    let (mut world, body, co) = pressed(down_pad(), -0.002);
    world.step();
    assert!(world.soft.contacts().is_empty());
    assert!(
        world
            .soft
            .tactile_image(co)
            .unwrap()
            .pressure()
            .iter()
            .all(|p| *p == 0.0)
    );
    // Pressed, but the pad faces up: the patch is at its antipode.
    let up = TactilePad::new(8, 8, [0.0, 1.0, 0.0], 0.01, 0.01);
    let (mut world2, _, co2) = pressed(up, 0.05 * R);
    world2.step();
    assert_eq!(world2.soft.contacts().len(), 1);
    let image = world2.soft.tactile_image(co2).unwrap();
    assert_eq!(image.total_force(), 0.0);
    assert_eq!(image.centroid(), None);
    // Lifted off again: back to zero.
    common::move_to(&mut world, body, Vector::new(0.0, 0.0095, 0.0));
    world.step();
    world.step();
    assert!(world.soft.tactile_image(co).unwrap().total_force() > 0.0);
    common::move_to(&mut world, body, Vector::new(0.0, 0.02, 0.0));
    world.step();
    assert_eq!(world.soft.tactile_image(co).unwrap().total_force(), 0.0);
}

#[test]
fn soft_on_soft_contact_shows_on_both_pads() {
    // Two kinematic fingertips pressed together along x, each pad facing the other.
    let mut world = SoftWorld::new();
    let pad = |x: f64| TactilePad::new(16, 16, [x, 0.0, 0.0], 0.012, 0.012);
    let gap = 2.0 * R - 0.002;
    let (_, a) = common::kinematic_tip(&mut world, Vector::ZERO, tip_with(pad(1.0)));
    let (_, b) = common::kinematic_tip(
        &mut world,
        Vector::new(gap as f32, 0.0, 0.0),
        tip_with(pad(-1.0)),
    );
    world.step();
    let c = world.soft.contacts()[0].clone();
    for h in [a, b] {
        let image = world.soft.tactile_image(h).unwrap();
        let [u, v] = image.centroid().unwrap();
        assert!((image.total_force() / c.normal_force - 1.0).abs() < 1e-4);
        assert!(u.abs() < 1e-9 && v.abs() < 1e-9, "{u} {v}");
    }
}

#[test]
fn a_disc_on_the_grid_edge_keeps_only_what_lies_on_the_pad() {
    let tip = tip_with(TactilePad::new(10, 10, [0.0, 0.0, 1.0], 0.01, 0.01));
    let mut image = TactileImage::new(*tip.tactile().unwrap());
    // Centred on the right edge (u = +5 mm): half the force is on the pad.
    image.add_disc([0.005, 0.0], 0.002, 2.0);
    assert!(
        (image.total_force() - 1.0).abs() < 1e-6,
        "{}",
        image.total_force()
    );
    // Centred on a corner: a quarter.
    image.clear();
    image.add_disc([-0.005, 0.005], 0.002, 2.0);
    assert!((image.total_force() - 0.5).abs() < 1e-6);
    // A disc smaller than a taxel, inside one taxel, on a taxel corner.
    for c in [[0.00025, 0.00025], [0.0, 0.0]] {
        image.clear();
        image.add_disc(c, 1e-5, 1e-3);
        assert!((image.total_force() / 1e-3 - 1.0).abs() < 1e-6);
    }
}

fn err(pad: TactilePad) -> (String, f64, String) {
    match SoftFingertip::builder(R)
        .preset(Preset::DragonSkin30)
        .tactile(pad)
        .build()
    {
        Err(e @ Error::InvalidTactilePad { .. }) => {
            let Error::InvalidTactilePad { field, value, .. } = &e else {
                unreachable!()
            };
            (field.to_string(), *value, e.to_string())
        }
        other => panic!("expected a tactile error, got {other:?}"),
    }
}

#[test]
fn bad_pads_are_typed_errors_naming_field_value_and_range() {
    let good = TactilePad::new(16, 16, [1.0, 0.0, 0.0], 0.016, 0.016);
    let (f, v, m) = err(TactilePad { rows: 0, ..good });
    assert_eq!((f.as_str(), v), ("tactile.rows", 0.0));
    assert!(m.contains("1..=1024"), "{m}");
    let (f, v, _) = err(TactilePad {
        columns: 2000,
        ..good
    });
    assert_eq!((f.as_str(), v), ("tactile.columns", 2000.0));
    let (f, v, m) = err(TactilePad {
        width: f64::NAN,
        ..good
    });
    assert!(f == "tactile.width" && v.is_nan(), "{m}");
    // πR = 31.4 mm along the surface: a 30 mm x 16 mm pad reaches past a quarter circle.
    let (f, v, m) = err(TactilePad {
        width: 0.03,
        ..good
    });
    assert_eq!((f.as_str(), v), ("tactile.width", 0.03));
    assert!(
        m.contains("0.027036280071580408") && m.contains("quarter great circle"),
        "{m}"
    );
    let (f, _, m) = err(TactilePad {
        height: 0.04,
        ..good
    });
    assert!(
        f == "tactile.height" && m.contains("0.031415926535897934"),
        "{m}"
    );
    let (f, v, _) = err(TactilePad {
        direction: [0.0; 3],
        ..good
    });
    assert_eq!((f.as_str(), v), ("tactile.direction", 0.0));
    let (f, v, m) = err(TactilePad {
        up: [-2.0, 0.0, 0.0],
        ..good
    });
    assert_eq!((f.as_str(), v), ("tactile.up", -1.0));
    assert!(m.contains("not parallel"), "{m}");
    let (f, _, _) = err(TactilePad {
        up: [f64::INFINITY, 0.0, 1.0],
        ..good
    });
    assert_eq!(f, "tactile.up");
    // A fingertip without a pad has no image.
    let mut world = SoftWorld::new();
    let plain = SoftFingertip::builder(R)
        .preset(Preset::DragonSkin30)
        .build()
        .unwrap();
    let (_, co) = common::kinematic_tip(&mut world, Vector::ZERO, plain);
    world.step();
    assert!(world.soft.tactile_image(co).is_none());
}

/// A fingertip pressed on a cylinder's side: the patch is an ellipse, longer along the
/// cylinder's axis, and the image shows it so: it integrates to the normal force, and its
/// spread along the axis is the larger one.
#[test]
fn a_cylinder_shows_an_elliptical_patch_along_its_axis() {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    // A cylinder of radius R along z (rotated from y), top of its side at y = 0.
    world.physics.colliders.insert(
        ColliderBuilder::cylinder(0.05, R as f32)
            .rotation(Vector::new(std::f32::consts::FRAC_PI_2, 0.0, 0.0))
            .translation(Vector::new(0.0, -R as f32, 0.0)),
    );
    let pad = TactilePad::new(32, 32, [0.0, -1.0, 0.0], 0.016, 0.016).with_up([0.0, 0.0, 1.0]);
    let (body, co) = common::kinematic_tip(
        &mut world,
        Vector::new(0.0, (R - 0.002) as f32, 0.0),
        tip_with(pad),
    );
    for _ in 0..5 {
        common::move_to(&mut world, body, Vector::new(0.0, (R - 0.002) as f32, 0.0));
        world.step();
    }
    let c = world.soft.contacts()[0].clone();
    let patch = c.patch();
    assert!(patch.radius > 1.2 * patch.radius2, "{patch:?}");
    let d = c.patch_direction;
    assert!(d[2].abs() > 0.999, "along the axis (z): {d:?}");
    let image = world.soft.tactile_image(co).unwrap();
    assert!((image.total_force() / c.normal_force - 1.0).abs() < 1e-5);
    // Second moments of the image about its centroid: along v (= z, the axis) and u (= x).
    let g = image.grid();
    let (mut su, mut sv) = (0.0, 0.0);
    for r in 0..g.rows() {
        for col in 0..g.columns() {
            let [u, v] = g.taxel_center(r, col);
            su += image.at(r, col) * u * u;
            sv += image.at(r, col) * v * v;
        }
    }
    // For the ellipse's Hertz pressure the second moment along an axis is F a²/5 over its
    // area: the ratio of the two is (a/b)².
    let ratio = sv / su;
    let want = (patch.radius / patch.radius2).powi(2);
    println!("cylinder patch {patch:?}: image moments v/u {ratio:.4}, (a/b)^2 {want:.4}");
    assert!((ratio / want - 1.0).abs() < 0.03, "{ratio} vs {want}");
}

/// The images are laid on their first read after a step: a world whose images are read only
/// every 20th step shows at those steps, bit for bit, what a world read after every step
/// shows (the readout and the pad's orientation of *that* step, not of the last read), and
/// the patch has moved between the reads (the comparison can fail).
#[test]
fn an_image_read_late_is_the_image_of_the_last_step() {
    let (mut every, body_e, co_e) = pressed(down_pad(), 0.05 * R);
    let (mut seldom, body_s, co_s) = pressed(down_pad(), 0.05 * R);
    let mut previous: Option<Vec<f64>> = None;
    for i in 0..=60 {
        let angle = 0.005 * i as f64;
        turn(&mut every, body_e, angle);
        turn(&mut seldom, body_s, angle);
        every.step();
        seldom.step();
        let eager = every.soft.tactile_image(co_e).expect("a pad").clone();
        if i % 20 != 0 {
            continue;
        }
        let late = seldom.soft.tactile_image(co_s).expect("a pad");
        assert_eq!(late, &eager, "step {i}");
        // A second read of the same step is the same image.
        assert_eq!(
            seldom.soft.tactile_images().next().map(|(_, i)| i),
            Some(&eager)
        );
        if let Some(p) = previous.replace(eager.pressure().to_vec()) {
            assert_ne!(p, eager.pressure(), "step {i}: the patch did not move");
        }
    }
}
