//! Every invalid parameter and every out-of-range call gets its typed error.

mod common;

use common::normalised;
use softgrip_law::fitting::{Sample, fit_material};
use softgrip_law::{ContactLaw, ContactParams, Error, Level, LevelKind, Material};

fn invalid(field: &str, r: Result<impl std::fmt::Debug, Error>) {
    match r {
        Err(Error::InvalidParameter { field: f, .. }) => assert_eq!(f, field),
        other => panic!("expected InvalidParameter({field}), got {other:?}"),
    }
}

#[test]
fn invalid_materials_are_rejected() {
    invalid("youngs_modulus", Material::try_new(-3e6, 0.3));
    invalid("youngs_modulus", Material::try_new(0.0, 0.3));
    invalid("youngs_modulus", Material::try_new(f64::NAN, 0.3));
    invalid("youngs_modulus", Material::try_new(f64::INFINITY, 0.3));
    invalid("poisson_ratio", Material::try_new(3e6, 0.5000001));
    invalid("poisson_ratio", Material::try_new(3e6, -1.0));
    invalid("poisson_ratio", Material::try_new(3e6, f64::NAN));
    invalid("shear_modulus", Material::try_from_shear_modulus(-1.0, 0.3));
    invalid(
        "effective_modulus",
        Material::try_from_effective_modulus(f64::NAN, 0.5),
    );
    let e = Material::try_new(-3e6, 0.3).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`youngs_modulus` must be finite and > 0 Pa, got -3000000"
    );
}

#[test]
fn invalid_radii_are_rejected() {
    let m = Material::try_new(3e6, 0.49).expect("valid");
    invalid("radius", ContactParams::try_new(m, -0.01));
    invalid("radius", ContactParams::try_new(m, 0.0));
    invalid("radius", ContactParams::try_new(m, f64::INFINITY));
    invalid("radius2", ContactParams::try_combine(m, 0.01, m, -1.0));
    invalid(
        "radius1",
        ContactParams::try_combine(m, f64::INFINITY, m, f64::INFINITY),
    );
    // A flat second body is allowed and gives the first radius.
    let p = ContactParams::try_combine(m, 0.01, m, f64::INFINITY).expect("flat");
    assert_eq!(p.radius(), 0.01);
}

#[test]
fn invalid_level_settings_are_rejected() {
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.3).expect("valid");
    invalid("k", ContactLaw::try_new(p, Level::Fit { k: -1.0 }));
    invalid("k", ContactLaw::try_new(p, Level::Fit { k: f64::NAN }));
    invalid(
        "tolerance",
        ContactLaw::try_new(p, Level::Auto { tolerance: 0.0 }),
    );
    invalid(
        "match_x",
        ContactLaw::try_new(p, Level::Linear { match_x: 0.0 }),
    );
}

#[test]
fn compressible_theory_needs_nu_below_half() {
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.5).expect("valid");
    for (level, kind) in [
        (Level::NeoHookean, LevelKind::NeoHookean),
        (Level::NeoHookeanExact, LevelKind::NeoHookeanExact),
    ] {
        match ContactLaw::try_new(p, level) {
            Err(Error::IncompatibleLevel { level, nu, .. }) => {
                assert_eq!(level, kind);
                assert_eq!(nu, 0.5);
            }
            other => panic!("expected IncompatibleLevel, got {other:?}"),
        }
    }
    // Auto uses the incompressible law as its reference at nu = 0.5.
    assert!(ContactLaw::try_new(p, Level::auto()).is_ok());
}

#[test]
fn compression_past_the_validity_range_is_an_error() {
    for level in Level::ALL {
        let law = normalised(level, 0.3);
        let x = law.x_max() * 1.001;
        match law.evaluate(x) {
            Err(Error::OutOfRange { x: got, x_max, .. }) => {
                assert_eq!(got, x);
                assert_eq!(x_max, law.x_max());
            }
            other => panic!("{level}: expected OutOfRange, got {other:?}"),
        }
        assert!(law.evaluate(law.x_max()).is_ok());
        invalid("delta", law.evaluate(-1e-3));
        invalid("delta", law.evaluate(f64::NAN));
        invalid("delta", law.try_response(f64::INFINITY));
    }
}

#[test]
fn force_past_the_validity_range_is_an_error() {
    let law = normalised(Level::fit(), 0.3);
    let f = law.force_max() * 1.01;
    assert!(matches!(
        law.compression_for_force(f),
        Err(Error::ForceOutOfRange { .. })
    ));
    invalid("force", law.compression_for_force(-1.0));
    invalid("force", law.compression_for_force(f64::NAN));
}

#[test]
fn material_fit_rejects_bad_samples() {
    let ok = Sample {
        delta: 1e-4,
        force: 1.0,
    };
    let bad = Sample {
        delta: f64::NAN,
        force: 1.0,
    };
    assert!(matches!(
        fit_material(&[ok, bad], 0.01, 0.5, 0.1, Level::Hertz),
        Err(Error::Fit(_))
    ));
    assert!(matches!(
        fit_material(&[ok], 0.01, 0.5, 0.1, Level::Hertz),
        Err(Error::Fit(_))
    ));
    invalid(
        "radius",
        fit_material(&[ok, ok], -0.01, 0.5, 0.1, Level::Hertz),
    );
    invalid(
        "poisson_ratio",
        fit_material(
            &[
                ok,
                Sample {
                    delta: 2e-4,
                    force: 3.0,
                },
            ],
            0.01,
            0.7,
            0.1,
            Level::Hertz,
        ),
    );
}

/// Found by `tests/fuzz_law.rs` (seed 0x5eed1a3, case 38): `try_combine` with a subnormal
/// radius (5e-324, 1/R = inf) gave a combined radius of 0, a law with `inv_radius = inf`, and
/// `evaluate(0)` panicked (debug) on a NaN x. Now a typed error.
#[test]
fn try_combine_with_a_subnormal_radius_is_an_error() {
    let m = softgrip_law::Material::try_new(3.0e6, 0.49).unwrap();
    let e = softgrip_law::ContactParams::try_combine(m, 5e-324, m, 0.01).unwrap_err();
    assert!(
        matches!(
            e,
            softgrip_law::Error::InvalidParameter {
                field: "radius",
                ..
            }
        ),
        "{e}"
    );
    assert!(softgrip_law::ContactParams::try_combine(m, 1e-100, m, 0.01).is_ok());
    // E* R^2 underflowing to 0 N made compression_for_force(0) NaN.
    assert!(softgrip_law::ContactParams::try_new(m, 1e-200).is_err());
}

/// Found by `tests/fuzz_law.rs` (seed 0x5eed1a3, case 125): R = 1e308 m was accepted, the
/// force scale E* R^2 was infinite and `response` returned an infinite force.
#[test]
fn radius_1e308_overflowing_the_force_scale_is_an_error() {
    let m = softgrip_law::Material::try_new(3.0e6, 0.49).unwrap();
    let e = softgrip_law::ContactParams::try_new(m, 1e308).unwrap_err();
    assert!(
        matches!(
            e,
            softgrip_law::Error::InvalidParameter {
                field: "radius",
                ..
            }
        ),
        "{e}"
    );
    assert!(softgrip_law::ContactParams::try_new(m, 1e30).is_ok());
}

/// Found by tests/fuzz_law.rs (case 257 of seed 0x5eed1a3): the exact neo-Hookean radius
/// integrates the uniaxial volume change down to sub-compressions where the bracket search of
/// Eq. 33 started at a probe that underflowed to 0 and never moved: `evaluate` hung.
#[test]
fn neo_hookean_exact_radius_at_tiny_sub_compressions_returns() {
    let m = Material::try_from_effective_modulus(5.537_434_755_495_728e11, 0.3).unwrap();
    let p = ContactParams::try_new(m, 0.551_833_923_042_262_1).unwrap();
    let law = ContactLaw::try_new(p, Level::NeoHookeanExact).unwrap();
    let s = law.evaluate(0.109_650_201_182_690_99).unwrap();
    assert!(s.patch.radius.is_finite() && s.patch.radius > 0.0, "{s:?}");
    // a/R at x = 0.199 is close to artanh(sqrt x) = 0.47 for the full theory (MODEL.md)
    let a = s.patch.radius / p.radius();
    assert!((a - 0.199f64.sqrt().atanh()).abs() < 0.05, "a/R = {a}");
}

/// Found by tests/fuzz_law.rs (case 603): E* = 1.3e308 passed the scale checks and `response`
/// returned an infinite stiffness. The effective modulus keeps 1e12 of room below f64::MAX.
#[test]
fn effective_modulus_1e308_is_an_error_not_an_infinite_stiffness() {
    let m = Material::try_new(1e308, 0.49).unwrap();
    let err = ContactParams::try_new(m, 0.187_528_446_568_229_15).unwrap_err();
    assert!(err.to_string().contains("effective_modulus"), "{err}");
}

/// Found by softgrip-py's hostile-input test: at a subnormal compression (5e-324 m, level
/// `linear`) the patch radius squared underflowed to 0 and the mean pressure F / (pi a^2) was
/// inf. The pressure now tends to 0 with the compression, at every level.
#[test]
fn pressure_at_a_subnormal_compression_is_finite() {
    let m = Material::try_new(3.0e6, 0.49).unwrap();
    let p = ContactParams::try_new(m, 0.01).unwrap();
    for level in [
        Level::linear(),
        Level::Hertz,
        Level::fit(),
        Level::Calibrated,
        Level::Incompressible,
        Level::NeoHookean,
        Level::Tatara,
        Level::auto(),
    ] {
        let law = ContactLaw::try_new(p, level).unwrap();
        let mut previous = 0.0;
        for delta in [5e-324, 1e-320, 1e-310, 1e-300, 1e-200] {
            let patch = law.patch(delta);
            assert!(
                patch.mean_pressure.is_finite() && patch.peak_pressure.is_finite(),
                "{level:?} at {delta:e}: {patch:?}"
            );
            if matches!(level, Level::Linear { .. }) {
                // A linear spring over Hertz's radius: F / (pi a^2) = k delta / (pi R delta),
                // the same at every compression.
                // (A subnormal force carries few significant bits: 0.6 % at 5e-324 m.)
                let reference = law.patch(1e-9 * 0.01).mean_pressure;
                let tolerance = if delta < f64::MIN_POSITIVE {
                    1e-2
                } else {
                    1e-9
                };
                assert!(
                    (patch.mean_pressure / reference - 1.0).abs() < tolerance,
                    "{level:?} at {delta:e}: {patch:?} vs {reference}"
                );
            } else {
                // p ~ E* sqrt(delta / R): below 1 Pa here, and not decreasing with delta.
                assert!(
                    patch.mean_pressure < 1.0,
                    "{level:?} at {delta:e}: {patch:?}"
                );
                assert!(
                    patch.mean_pressure >= previous,
                    "{level:?} at {delta:e}: {patch:?}"
                );
                previous = patch.mean_pressure;
            }
        }
    }
}
