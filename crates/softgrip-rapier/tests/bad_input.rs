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

/// Issue 11: `radius = 1e39` was valid as f64 and infinite as rapier's f32 ball radius (a
/// panic: "invariant ... RadiusMismatch { collider_radius: inf }"). The builder rejects what
/// rapier cannot hold, naming the field, the value and the range.
#[test]
fn fingertip_radius_1e39_is_a_typed_error() {
    let m = Material::try_new(3.0e6, 0.49).unwrap();
    for (r, ok) in [
        (1e39, false),
        (1e-50, false),
        (2e3, false),
        (f64::INFINITY, false),
        (1e3, true),
        (1e-9, true),
        (1.42e-5, true),
    ] {
        let got = SoftFingertip::builder(r).material(m).build();
        assert_eq!(got.is_ok(), ok, "R = {r}");
        if let Err(e) = got {
            assert_eq!(
                e,
                Error::InvalidParameter {
                    field: "radius",
                    value: r,
                    range: "in [1e-9, 1e3] m"
                }
            );
            assert!(
                e.to_string().contains("`radius` must be in [1e-9, 1e3] m"),
                "{e}"
            );
        }
    }
}

/// Issue 11: values the f64 law accepts but that overflow rapier's f32 impulses or the
/// damping: E = 1e300 Pa, v_ref = 1e-300 m/s, friction 1e39.
#[test]
fn fingertip_values_past_f32_range_are_typed_errors() {
    let huge = Material::try_new(1e300, 0.49).unwrap();
    let e = SoftFingertip::builder(0.01)
        .material(huge)
        .build()
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidParameter {
                field: "material.youngs_modulus",
                ..
            }
        ),
        "{e}"
    );
    let m = Material::try_new(3.0e6, 0.49).unwrap();
    let b = || SoftFingertip::builder(0.01).material(m);
    let e = b().restitution_speed(1e-300).build().unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            field: "restitution_speed",
            ..
        }
    ));
    let e = b().friction(1e39).build().unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            field: "friction",
            ..
        }
    ));
    assert!(b().friction(1e3).restitution_speed(1e6).build().is_ok());
}
