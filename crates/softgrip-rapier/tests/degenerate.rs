//! Hard case 7, degenerate geometry: a fingertip whose centre starts inside a box; a fingertip
//! resting on a shared edge and on a shared vertex of a triangle mesh (one contact, not one
//! per triangle); a fingertip resting on the ground for 10 s without jitter.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::SoftWorld;

const R: f64 = 0.01;

fn dragon_skin() -> softgrip_rapier::SoftFingertip {
    common::tip(R, 0.59e6, Level::auto(), 0.5, 0.8)
}

#[test]
fn fingertip_centre_inside_box_is_pushed_out_finite_and_flagged() {
    let mut world = SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.1, 0.05, 0.1).translation(Vector::new(0.0, -0.05, 0.0)));
    // Centre 2 mm below the top face: delta = 12 mm, x = 1.2.
    let (body, _) = common::dynamic_tip(
        &mut world,
        Vector::new(0.0, -0.002, 0.0),
        1070.0,
        dragon_skin(),
    );
    let mass = world.physics.bodies[body].mass() as f64;
    world.step();
    let first = world.soft.contacts().first().expect("contact").clone();
    let (mut v_max, mut y_max) = (0.0f64, 0.0f64);
    for _ in 0..300 {
        world.step();
        assert!(common::all_finite(&world));
        let rb = &world.physics.bodies[body];
        v_max = v_max.max(rb.linvel().length() as f64);
        y_max = y_max.max(rb.translation().y as f64);
    }
    let c = world
        .soft
        .contacts()
        .first()
        .expect("resting contact")
        .clone();
    let rb = &world.physics.bodies[body];
    println!(
        "centre inside box: first step x = {:.3}, normal {:?}, flagged {}; max speed {v_max:.2} m/s, max height {y_max:.4} m; after 5 s y = {:.5} m, F/mg = {:.5}",
        first.max_delta / R,
        first.normal,
        first.validity_excursion(),
        rb.translation().y,
        c.normal_force / (mass * common::G)
    );
    assert!(first.max_delta / R > 1.1 && first.validity_excursion());
    assert!((first.normal[1] - 1.0).abs() < 1e-6);
    // The README states "pushed out at <= 0.06 m/s, rests at F = m g (1.00000)" (asserted
    // below 20 m/s and within 1 %): a factor 2 on the speed, 1e-4 on the rest force.
    assert!(v_max < 0.12, "{v_max} m/s, README: 0.06");
    assert!(rb.translation().y as f64 > 0.9 * R);
    assert!((c.normal_force / (mass * common::G) - 1.0).abs() < 1e-4);
}

/// A flat 2 x 2 grid of squares (0.1 m), each split into two triangles: the origin is a vertex
/// shared by six triangles, (0.05, 0, 0) lies on an edge shared by two.
fn grid_mesh() -> ColliderBuilder {
    let mut vertices = Vec::new();
    for i in 0..3 {
        for k in 0..3 {
            vertices.push(Vector::new(
                -0.1 + 0.1 * i as f32,
                0.0,
                -0.1 + 0.1 * k as f32,
            ));
        }
    }
    let mut indices = Vec::new();
    for i in 0..2u32 {
        for k in 0..2u32 {
            let (a, b, c, d) = (
                3 * i + k,
                3 * i + k + 1,
                3 * (i + 1) + k,
                3 * (i + 1) + k + 1,
            );
            indices.push([a, b, d]);
            indices.push([a, d, c]);
        }
    }
    ColliderBuilder::trimesh(vertices, indices).unwrap()
}

#[test]
fn fingertip_on_trimesh_edge_and_vertex_gets_one_contact_with_weight() {
    for (name, x, z) in [
        ("vertex", 0.0f32, 0.0f32),
        ("edge", 0.05, 0.0),
        ("diagonal edge", 0.05, 0.05),
    ] {
        let mut world = SoftWorld::new();
        world.physics.colliders.insert(grid_mesh());
        let (body, _) = common::dynamic_tip(
            &mut world,
            Vector::new(x, R as f32, z),
            1070.0,
            dragon_skin(),
        );
        let mass = world.physics.bodies[body].mass() as f64;
        for _ in 0..120 {
            world.step();
            assert!(common::all_finite(&world));
        }
        let contacts = world.soft.contacts();
        let f: f64 = contacts.iter().map(|c| c.normal_force).sum();
        println!(
            "trimesh {name}: {} contact(s), F/mg = {:.5}",
            contacts.len(),
            f / (mass * common::G)
        );
        assert_eq!(contacts.len(), 1, "{name}");
        // The README states F/m g = 1.00000 (was asserted within 1 %).
        assert!((f / (mass * common::G) - 1.0).abs() < 1e-4, "{name}");
        let law = &contacts[0].law().clone();
        let rest = law.compression_for_force(mass * common::G).unwrap();
        assert!((contacts[0].delta / rest - 1.0).abs() < 0.01, "{name}");
    }
}

#[test]
fn ball_resting_10_s_moves_less_than_1_um() {
    let mut world = SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    let (body, _) = common::dynamic_tip(
        &mut world,
        Vector::new(0.0, R as f32, 0.0),
        1070.0,
        dragon_skin(),
    );
    for _ in 0..60 {
        world.step();
    }
    let p0 = world.physics.bodies[body].translation();
    let (mut lo, mut hi) = (p0, p0);
    for _ in 0..600 {
        world.step();
        let p = world.physics.bodies[body].translation();
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let spread = (hi - lo).max_element() as f64;
    println!(
        "resting 10 s: position spread {spread:.3e} m (x, y, z: {:?})",
        hi - lo
    );
    // The README states 9.3e-10 m (one f32 ulp); was asserted below 1 um.
    assert!(spread < 1e-8, "{spread} m, README: 9.3e-10");
}
