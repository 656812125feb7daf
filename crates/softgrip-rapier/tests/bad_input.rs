//! Bad input is rejected at construction or registration with a typed error.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{Error, Preset, SoftFingertip, SoftWorld};

#[test]
fn bad_input_is_rejected_with_typed_errors() {
    let m = Material::try_new(3.0e6, 0.49).unwrap();
    let e = SoftFingertip::builder(-0.01)
        .material(m)
        .build()
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidParameter {
                field: "radius",
                ..
            }
        ),
        "{e}"
    );
    assert!(Material::try_new(f64::NAN, 0.49).is_err()); // NaN modulus: the law's typed error
    let e = SoftFingertip::builder(0.01)
        .material(m)
        .restitution(0.0)
        .build()
        .unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            field: "restitution",
            ..
        }
    ));
    for v in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = SoftFingertip::builder(0.01)
            .material(m)
            .restitution_speed(v)
            .build()
            .unwrap_err();
        assert!(matches!(
            e,
            Error::InvalidParameter {
                field: "restitution_speed",
                ..
            }
        ));
    }
    let e = SoftFingertip::builder(0.01)
        .material(m)
        .friction(f64::NAN)
        .build()
        .unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            field: "friction",
            ..
        }
    ));
    // nu = 0.5 is out of range for the compressible neo-Hookean level.
    let e = SoftFingertip::builder(0.01)
        .preset(Preset::Ecoflex0030)
        .level(Level::NeoHookean)
        .build()
        .unwrap_err();
    assert!(
        matches!(e, Error::Law(softgrip_law::Error::IncompatibleLevel { .. })),
        "{e}"
    );
    assert!(matches!(
        SoftFingertip::builder(0.01).build().unwrap_err(),
        Error::MissingMaterial
    ));

    let mut world = SoftWorld::new();
    let boxed = world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.01, 0.01, 0.01));
    let tip = SoftFingertip::builder(0.01).material(m).build().unwrap();
    let e = world.register(boxed, tip.clone()).unwrap_err();
    assert!(matches!(e, Error::NotABall { .. }), "{e}");
    let small = world.physics.colliders.insert(ColliderBuilder::ball(0.005));
    let e = world.register(small, tip.clone()).unwrap_err();
    assert!(matches!(e, Error::RadiusMismatch { .. }), "{e}");
    let ok = world.physics.colliders.insert(ColliderBuilder::ball(0.01));
    world.register(ok, tip).unwrap();
    assert!(world.soft.is_soft(ok));
}
