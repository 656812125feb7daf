//! The plugin reads what a fingertip touches (`src/curvature.rs`): per shape, a kinematic
//! fingertip (R = 10 mm, E = 3 MPa, nu = 0.49, calibrated) is pressed quasi-statically onto
//! one feature of a fixed body (a face, an edge, a corner, a curved side, a cap) to
//! x = delta/R = 0.15 and held; the readout must name the counterpart of that feature and its
//! force must be the fingertip's law on it (`ContactLaw::with_counterpart`) within 0.5 %.
//! Faceted shapes (a convex hull, a triangle mesh, a heightfield of a sphere) must read the
//! sphere's curvature within their fit's tolerance.
//!
//! `cargo test -p softgrip-rapier --test counterparts -- --nocapture` prints every case.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::parry::utils::Array2;
use rapier3d::prelude::*;
use softgrip_law::{Counterpart, CounterpartKind, Level};
use softgrip_rapier::{SoftWorld, TipContact};
use softgrip_testkit::icosphere::icosphere;

const R: f64 = 0.01;
/// The compression the fingertip is pressed to [m] (x = 0.15).
const DELTA: f64 = 0.15 * R;

/// What a case expects the plugin to read.
#[derive(Debug, Clone, Copy)]
enum Expect {
    /// Exactly this counterpart.
    Exactly(Counterpart),
    /// Curved, both curvatures within `tol` (relative) of `k` [1/m].
    Sphere { k: f64, tol: f64 },
}

/// Presses the fingertip onto `body` at the surface point `point` (world) along the outward
/// normal `normal`, quasi-statically (60 steps of a smoothstep, then 10 at rest), and returns
/// its one contact.
fn press(body: ColliderBuilder, point: [f64; 3], normal: [f64; 3]) -> (SoftWorld, TipContact) {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    world.physics.colliders.insert(body);
    let tip = common::tip(R, 3.0e6, Level::Calibrated, 0.5, 0.0);
    let n = nalgebra::Vector3::from(normal).normalize();
    let p = nalgebra::Vector3::from(point);
    let at = |gap: f64| {
        let c = p + n * (R + gap);
        Vector::new(c.x as f32, c.y as f32, c.z as f32)
    };
    let (body, _) = common::kinematic_tip(&mut world, at(0.001), tip);
    for i in 1..=70 {
        let s = common::smoothstep(f64::from(i) / 60.0);
        common::move_to(&mut world, body, at(0.001 - s * (0.001 + DELTA)));
        world.step();
    }
    let contacts = world.soft.contacts();
    assert_eq!(
        contacts.len(),
        1,
        "{contacts:?} {:?}",
        world.soft.counters()
    );
    let c = contacts[0].clone();
    (world, c)
}

/// Checks one case: the counterpart read, and the force against the law on it.
fn check(name: &str, body: ColliderBuilder, point: [f64; 3], normal: [f64; 3], expect: Expect) {
    let (_world, c) = press(body, point, normal);
    let read = c.counterpart;
    let law_on = |cp: Counterpart| c.law().with_counterpart(cp).unwrap();
    match expect {
        Expect::Exactly(want) => {
            assert_eq!(read.kind(), want.kind(), "{name}: read {read}");
            for (got, w) in read.curvatures().iter().zip(want.curvatures()) {
                assert!(
                    (got - w).abs() <= 1e-4 * w.abs() + 1e-9,
                    "{name}: read {read}, want {want}"
                );
            }
        }
        Expect::Sphere { k, tol } => {
            assert_eq!(read.kind(), CounterpartKind::Curved, "{name}: read {read}");
            for got in read.curvatures() {
                assert!(
                    (got / k - 1.0).abs() < tol,
                    "{name}: read {read}, want {k} 1/m"
                );
            }
        }
    }
    let want = match expect {
        Expect::Exactly(cp) => cp,
        Expect::Sphere { .. } => read,
    };
    let f_law = law_on(want).response(c.delta).force;
    let err = c.normal_force / f_law - 1.0;
    println!(
        "{name:>28}: read {read}, x = {:.4}, F = {:.4} N, law {:.4} N ({:+.3} %), patch {:.2} x {:.2} mm",
        c.x,
        c.normal_force,
        f_law,
        100.0 * err,
        1e3 * c.patch().radius,
        1e3 * c.patch().radius2
    );
    assert!((c.x / 0.15 - 1.0).abs() < 0.02, "{name}: x = {}", c.x);
    assert!(
        err.abs() < 0.005,
        "{name}: F = {} vs law {f_law}",
        c.normal_force
    );
}

fn v(x: f32, y: f32, z: f32) -> Vector {
    Vector::new(x, y, z)
}

const S2: f64 = std::f64::consts::FRAC_1_SQRT_2;
const S3: f64 = 0.577_350_269_189_625_8;

#[test]
fn analytic_shapes() {
    let ball = |r: f64| Expect::Exactly(Counterpart::try_ball(r).unwrap());
    let cyl = |r: f64| Expect::Exactly(Counterpart::try_cylinder(r).unwrap());
    let plane = Expect::Exactly(Counterpart::PLANE);
    let edge = Expect::Exactly(Counterpart::EDGE);
    check(
        "half-space",
        ColliderBuilder::new(SharedShape::halfspace(Vector::Y)),
        [0.0; 3],
        [0.0, 1.0, 0.0],
        plane,
    );
    check(
        "ball r = R",
        ColliderBuilder::ball(0.01),
        [0.0, 0.01, 0.0],
        [0.0, 1.0, 0.0],
        ball(0.01),
    );
    check(
        "ball r = 3R",
        ColliderBuilder::ball(0.03),
        [0.03 * S2, 0.03 * S2, 0.0],
        [S2, S2, 0.0],
        ball(0.03),
    );
    // A box 4 x 2 x 6 cm: a face, an edge (along z), a corner.
    let cuboid = || ColliderBuilder::cuboid(0.02, 0.01, 0.03);
    check(
        "cuboid face",
        cuboid(),
        [0.005, 0.01, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
    check(
        "cuboid edge",
        cuboid(),
        [0.02, 0.01, 0.0],
        [S2, S2, 0.0],
        edge,
    );
    check(
        "cuboid corner",
        cuboid(),
        [0.02, 0.01, 0.03],
        [S3, S3, S3],
        edge,
    );
    // A capsule along x (half length 3 cm, r = 1.5 cm): side and cap.
    let capsule = || ColliderBuilder::capsule_x(0.03, 0.015);
    check(
        "capsule side",
        capsule(),
        [0.0, 0.015, 0.0],
        [0.0, 1.0, 0.0],
        cyl(0.015),
    );
    check(
        "capsule cap",
        capsule(),
        [0.045, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        ball(0.015),
    );
    // A cylinder about y (half height 3 cm, r = 2 cm): side, cap, rim.
    let cylinder = || ColliderBuilder::cylinder(0.03, 0.02);
    check(
        "cylinder side",
        cylinder(),
        [0.02, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        cyl(0.02),
    );
    check(
        "cylinder cap",
        cylinder(),
        [0.005, 0.03, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
    check(
        "cylinder rim",
        cylinder(),
        [0.02, 0.03, 0.0],
        [S2, S2, 0.0],
        edge,
    );
    // A cone (half height 3 cm, base r = 3 cm, apex up): side at mid-height, base, rim, apex.
    let cone = || ColliderBuilder::cone(0.03, 0.03);
    let slant = (4.0f64 * 0.03 * 0.03 + 0.03 * 0.03).sqrt();
    let (ny, nr) = (0.03 / slant, 0.06 / slant);
    // At y = 0 the side's radius is 1.5 cm: normal curvature cos(beta)/rho = (0.06/slant)/0.015.
    let side = Counterpart::try_curved(0.0, nr / 0.015).unwrap();
    check(
        "cone side",
        cone(),
        [0.015, 0.0, 0.0],
        [nr, ny, 0.0],
        Expect::Exactly(side),
    );
    check(
        "cone base",
        cone(),
        [0.01, -0.03, 0.0],
        [0.0, -1.0, 0.0],
        plane,
    );
    check("cone rim", cone(), [0.03, -0.03, 0.0], [S2, -S2, 0.0], edge);
    check("cone apex", cone(), [0.0, 0.03, 0.0], [0.0, 1.0, 0.0], edge);
    // A rounded box (border 4 mm): face, edge (a cylinder of the border), corner (a ball).
    let round = || ColliderBuilder::round_cuboid(0.02, 0.01, 0.03, 0.004);
    check(
        "round cuboid face",
        round(),
        [0.0, 0.014, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
    let e = 0.004 * S2;
    check(
        "round cuboid edge",
        round(),
        [0.02 + e, 0.01 + e, 0.0],
        [S2, S2, 0.0],
        cyl(0.004),
    );
    let c = 0.004 * S3;
    check(
        "round cuboid corner",
        round(),
        [0.02 + c, 0.01 + c, 0.03 + c],
        [S3, S3, S3],
        ball(0.004),
    );
    // A rounded cylinder (border 5 mm): its side is a cylinder of r + 5 mm.
    check(
        "round cylinder side",
        ColliderBuilder::round_cylinder(0.03, 0.02, 0.005),
        [0.025, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        cyl(0.025),
    );
    // A compound: a box and a ball side by side; the ball is found.
    let compound = ColliderBuilder::compound(vec![
        (
            Pose::translation(-0.05, 0.0, 0.0),
            SharedShape::cuboid(0.02, 0.02, 0.02),
        ),
        (Pose::translation(0.05, 0.0, 0.0), SharedShape::ball(0.02)),
    ]);
    check(
        "compound (ball part)",
        compound,
        [0.05, 0.02, 0.0],
        [0.0, 1.0, 0.0],
        ball(0.02),
    );
}

#[test]
fn faceted_shapes() {
    let plane = Expect::Exactly(Counterpart::PLANE);
    let edge = Expect::Exactly(Counterpart::EDGE);
    // A box as a triangle mesh and as a convex hull: a face, an edge, a corner.
    let corners: Vec<Vector> = (0..8)
        .map(|i| {
            v(
                if i & 1 == 0 { -0.02 } else { 0.02 },
                if i & 2 == 0 { -0.01 } else { 0.01 },
                if i & 4 == 0 { -0.03 } else { 0.03 },
            )
        })
        .collect();
    let hull = || ColliderBuilder::convex_hull(&corners).unwrap();
    check(
        "hull face",
        hull(),
        [0.005, 0.01, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
    check("hull edge", hull(), [0.02, 0.01, 0.0], [S2, S2, 0.0], edge);
    check(
        "hull corner",
        hull(),
        [0.02, 0.01, 0.03],
        [S3, S3, S3],
        edge,
    );
    let (verts, faces) = (
        corners.clone(),
        vec![
            [0, 2, 3],
            [0, 3, 1],
            [4, 5, 7],
            [4, 7, 6],
            [0, 1, 5],
            [0, 5, 4],
            [2, 6, 7],
            [2, 7, 3],
            [0, 4, 6],
            [0, 6, 2],
            [1, 3, 7],
            [1, 7, 5],
        ],
    );
    let boxmesh = || ColliderBuilder::trimesh(verts.clone(), faces.clone()).unwrap();
    check(
        "box mesh face",
        boxmesh(),
        [0.005, 0.01, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
    check(
        "box mesh edge",
        boxmesh(),
        [0.02, 0.01, 0.0],
        [S2, S2, 0.0],
        edge,
    );
    // A sphere of 2 cm tessellated (icosphere, 5120 faces, edges ~ 1.6 mm): its curvature.
    let (verts, faces) = icosphere(Vector::ZERO, 0.02, 4);
    let k = 1.0 / 0.02;
    let sphere = Expect::Sphere { k, tol: 0.03 };
    let mesh = || ColliderBuilder::trimesh(verts.clone(), faces.clone()).unwrap();
    check(
        "icosphere mesh (top)",
        mesh(),
        [0.0, 0.02, 0.0],
        [0.0, 1.0, 0.0],
        sphere,
    );
    let d = [0.3f64, 0.8, -0.52];
    let nd = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let dir = d.map(|c| c / nd);
    check(
        "icosphere mesh (oblique)",
        mesh(),
        dir.map(|c| 0.02 * c),
        dir,
        sphere,
    );
    let hull_sphere = ColliderBuilder::convex_hull(&verts).unwrap();
    check(
        "icosphere hull",
        hull_sphere,
        [0.0, 0.02, 0.0],
        [0.0, 1.0, 0.0],
        sphere,
    );
    // A heightfield of a spherical cap of radius 5 cm (1 mm cells, 6 cm wide).
    let (n, size, rc) = (61usize, 0.06f32, 0.05f64);
    let data = (0..n * n)
        .map(|k| {
            let (i, j) = (k % n, k / n);
            let (x, z) = (
                (i as f64 / (n - 1) as f64 - 0.5) * f64::from(size),
                (j as f64 / (n - 1) as f64 - 0.5) * f64::from(size),
            );
            ((rc * rc - x * x - z * z).sqrt() - rc) as f32
        })
        .collect();
    let heights = Array2::new(n, n, data);
    let hf = ColliderBuilder::heightfield(heights, v(size, 1.0, size));
    check(
        "heightfield cap",
        hf,
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        Expect::Sphere {
            k: 1.0 / rc,
            tol: 0.03,
        },
    );
    // A flat heightfield: a plane.
    let flat = ColliderBuilder::heightfield(Array2::zeros(9, 9), v(0.2, 1.0, 0.2));
    check(
        "heightfield flat",
        flat,
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        plane,
    );
}
