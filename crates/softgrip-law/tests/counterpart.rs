//! The counterpart in the law (`ContactLaw::with_counterpart`): a plane is today's law bit for
//! bit; a ball and a cylinder are Hertz's circular and elliptical contacts at small x; bad
//! counterparts are typed errors.

mod common;

use softgrip_law::{
    Backing, ContactLaw, ContactParams, Counterpart, CounterpartKind, Error, Level, Material,
};

/// Every built-in level of every construction at a few Poisson ratios, on E* = 1 Pa, R = 1 m.
fn every_law() -> Vec<ContactLaw> {
    let mut laws = Vec::new();
    for nu in [0.3, 0.45, 0.49] {
        laws.extend(common::levels_at(nu));
        for backing in [Backing::Flat, Backing::Core { thickness: 0.3 }] {
            let p = ContactParams::try_from_parts(1.0, 1.0, nu)
                .and_then(|p| p.with_backing(backing))
                .expect("valid params");
            for level in [Level::Calibrated, Level::auto(), Level::fit()] {
                laws.push(ContactLaw::try_new(p, level).expect("level builds"));
            }
        }
    }
    laws
}

/// A plane gives exactly today's numbers: every output bit for bit, for every level and
/// construction, inside and past the validity range.
#[test]
fn a_plane_is_todays_law_bit_for_bit() {
    for law in every_law() {
        let plane = law
            .with_counterpart(Counterpart::PLANE)
            .expect("a plane binds");
        assert_eq!(plane.x_max().to_bits(), law.x_max().to_bits());
        assert_eq!(plane.delta_max().to_bits(), law.delta_max().to_bits());
        assert_eq!(plane.force_max().to_bits(), law.force_max().to_bits());
        for i in 0..=300 {
            let delta = law.delta_max() * f64::from(i) / 200.0;
            assert_eq!(plane.response(delta), law.response(delta), "{delta}");
            assert_eq!(plane.energy(delta).to_bits(), law.energy(delta).to_bits());
            assert_eq!(plane.patch(delta), law.patch(delta));
        }
        let f = 0.5 * law.force_max();
        assert_eq!(
            plane.compression_for_force(f).map(f64::to_bits),
            law.compression_for_force(f).map(f64::to_bits)
        );
    }
}

/// A law bound to a ball and then to a plane again is today's law bit for bit: the curves
/// rebuilt for a curved counterpart (the calibrated free sphere's and flat pad's cap, a core's
/// own table) are dropped for the plane's own.
#[test]
fn back_on_a_plane_after_a_ball_is_todays_law_bit_for_bit() {
    let ball = Counterpart::try_ball(0.7).expect("ball");
    for law in every_law() {
        let again = law
            .with_counterpart(ball)
            .and_then(|l| l.with_counterpart(Counterpart::EDGE))
            .and_then(|l| l.with_counterpart(Counterpart::PLANE))
            .expect("binds");
        assert_eq!(again.x_max().to_bits(), law.x_max().to_bits());
        for i in 0..=100 {
            let delta = law.delta_max() * f64::from(i) / 100.0;
            assert_eq!(again.response(delta), law.response(delta), "{delta}");
            assert_eq!(again.energy(delta).to_bits(), law.energy(delta).to_bits());
        }
    }
}

/// At small x every level on a ball is Hertz with the effective radius
/// `R_eff = R R2/(R + R2)`: force `sqrt(R_eff/R)` times the plane's, a disc of radius
/// `sqrt(R_eff delta)`; the Hertz level is exactly that at every x.
#[test]
fn a_ball_is_hertz_with_the_effective_radius_at_small_x() {
    for k in [0.5, 1.0, 3.0, 10.0, 100.0] {
        let ball = Counterpart::try_ball(k).expect("valid ball");
        let rho_h = k / (1.0 + k);
        for law in every_law() {
            let on = law.with_counterpart(ball).expect("a ball binds");
            let level = law.level();
            // Hertz: exact everywhere in its range.
            if level == Level::Hertz {
                for x in [1e-6, 0.01, 0.3, 0.65] {
                    let want = 4.0 / 3.0 * rho_h.sqrt() * x * x.sqrt();
                    let got = on.response(x).force;
                    assert!(
                        (got / want - 1.0).abs() < 1e-13,
                        "k {k} x {x}: {got} {want}"
                    );
                    let p = on.patch(x);
                    assert!((p.radius / (rho_h * x).sqrt() - 1.0).abs() < 1e-13);
                    assert_eq!(p.radius, p.radius2);
                }
            }
            // Every level: Hertz's ratio to the plane at x -> 0 (the levels' finite-size
            // terms c sqrt(x) vanish like sqrt(x): at x = 1e-10, 1e-5 of the force).
            let x = 1e-10;
            let ratio = on.response(x).force / law.response(x).force;
            let tol = if matches!(level, Level::Linear { .. }) {
                // A linear spring scaled as a Hertz contact: F = s k rho x, not Hertz's power.
                continue;
            } else {
                3e-5
            };
            assert!(
                (ratio / rho_h.sqrt() - 1.0).abs() < tol,
                "{level} {:?} k {k}: {ratio} vs {}",
                law.params().backing(),
                rho_h.sqrt()
            );
            let a = on.patch(x).radius;
            let a_plane = law.patch(x).radius;
            assert!(
                (a / a_plane / rho_h.sqrt() - 1.0).abs() < 3e-5,
                "{level} radius k {k}: {a} vs {a_plane}"
            );
        }
    }
}

/// A cylinder at small x: Hertz's elliptical contact (the ellipse's semi-axes and force from
/// `tools/calibration/check_hertz_ellipse.py`, an independent SciPy solution); the long
/// semi-axis along the cylinder's axis (its first direction, curvature 0).
#[test]
fn a_cylinder_is_hertz_elliptical_contact_at_small_x() {
    // Cylinders of radius R and 3R: (A R, B R) = (1/2, 1) and (1/2, 2/3).
    for (k, (alpha, beta, h)) in [
        (
            1.0,
            (1.0554708788231213, 0.6655753991683993, 0.8492997417663052),
        ),
        (
            3.0,
            (1.0236392137109795, 0.8450574359857888, 0.9322089374850906),
        ),
    ] {
        let cyl = Counterpart::try_cylinder(k).expect("valid cylinder");
        for law in every_law() {
            let on = law.with_counterpart(cyl).expect("a cylinder binds");
            if law.level() == Level::Hertz {
                for x in [1e-6, 0.1, 0.5] {
                    let got = on.response(x).force / (4.0 / 3.0 * x * x.sqrt());
                    assert!((got / h - 1.0).abs() < 1e-12, "k {k} x {x}: {got}");
                    let p = on.patch(x);
                    assert!((p.radius / (alpha * x.sqrt()) - 1.0).abs() < 1e-12);
                    assert!((p.radius2 / (beta * x.sqrt()) - 1.0).abs() < 1e-12);
                }
            }
            if matches!(law.level(), Level::Linear { .. }) {
                continue;
            }
            let x = 1e-10;
            let ratio = on.response(x).force / law.response(x).force;
            assert!(
                (ratio / h - 1.0).abs() < 3e-5,
                "{} k {k}: {ratio}",
                law.level()
            );
            let (p, plane) = (on.patch(x), law.patch(x).radius);
            assert!((p.radius / plane / alpha - 1.0).abs() < 3e-5);
            assert!((p.radius2 / plane / beta - 1.0).abs() < 3e-5);
        }
    }
}

/// The two directions are the caller's: swapping the curvatures swaps the semi-axes and
/// changes nothing else.
#[test]
fn swapping_the_curvatures_swaps_the_axes() {
    let law = common::normalised(Level::Calibrated, 0.45);
    let (a, b) = (
        law.with_counterpart(Counterpart::try_curved(0.2, 1.7).expect("valid"))
            .expect("binds"),
        law.with_counterpart(Counterpart::try_curved(1.7, 0.2).expect("valid"))
            .expect("binds"),
    );
    for x in [0.01, 0.2, 0.5] {
        assert_eq!(a.response(x), b.response(x));
        let (pa, pb) = (a.patch(x), b.patch(x));
        assert_eq!((pa.radius, pa.radius2), (pb.radius2, pb.radius));
    }
}

/// Concave counterparts: a bowl is stiffer than the plane (Hertz: `R_eff = R R2/(R2 - R)`),
/// and its validity range ends where the plane law's does, at `rho x = x_max`.
#[test]
fn a_bowl_is_stiffer_than_a_plane() {
    let law = common::normalised(Level::Calibrated, 0.49);
    let bowl = Counterpart::try_curved(-0.5, -0.5).expect("valid");
    let on = law.with_counterpart(bowl).expect("a bowl of 2R binds");
    // R_eff = 2R: Hertz's force sqrt(2) times the plane's.
    let x = 1e-10;
    let ratio = on.response(x).force / law.response(x).force;
    assert!((ratio / 2f64.sqrt() - 1.0).abs() < 3e-5, "{ratio}");
    assert!(on.x_max() < law.x_max());
    assert!(on.evaluate(on.delta_max()).is_ok());
    assert!(on.evaluate(on.delta_max() * 1.001).is_err());
}

#[test]
fn bad_counterparts_are_typed_errors() {
    for (k1, k2) in [
        (f64::NAN, 1.0),
        (1.0, f64::INFINITY),
        (f64::NEG_INFINITY, 0.0),
    ] {
        let err = Counterpart::try_curved(k1, k2).expect_err("non-finite");
        assert!(
            matches!(err, Error::InvalidParameter { field, .. } if field.starts_with("curvature")),
            "{err}"
        );
    }
    for r in [0.0, -1.0, f64::NAN, f64::INFINITY, 1e-320] {
        assert!(Counterpart::try_ball(r).is_err(), "ball {r}");
        assert!(Counterpart::try_cylinder(r).is_err(), "cylinder {r}");
    }
    // A fingertip of R = 10 mm.
    let tip = ContactParams::try_new(Material::try_new(3.0e6, 0.49).expect("valid"), 0.01)
        .expect("valid");
    let law = ContactLaw::try_new(tip, Level::Calibrated).expect("builds");
    // A bowl as tight as the fingertip, or tighter: it would wrap it.
    for k in [-100.0, -150.0] {
        let bowl = Counterpart::try_curved(k, k).expect("finite");
        let err = law.with_counterpart(bowl).expect_err("too concave");
        assert!(
            matches!(err, Error::IncompatibleCounterpart { relative_curvature, .. } if relative_curvature <= -1.0),
            "{err}"
        );
        assert!(err.to_string().contains("-0.999"), "{err}");
    }
    // Sharper than 1e4 times the fingertip: an edge, not a curvature.
    let needle = Counterpart::try_curved(0.0, 2e6).expect("finite");
    let err = law.with_counterpart(needle).expect_err("too sharp");
    assert!(err.to_string().contains("EDGE"), "{err}");
    // The most extreme saddle allowed: nearly conformal one way, a needle the other (an
    // ellipse of axis ratio about 1e4), still finite and Hertz's at small x.
    let saddle = Counterpart::try_curved(-99.89, 1e6).expect("finite");
    let on = law.with_counterpart(saddle).expect("inside both bounds");
    let r = on.response(1e-9);
    assert!(r.force > 0.0 && r.force.is_finite() && r.stiffness.is_finite());
    let p = on.patch(1e-9);
    assert!(p.radius > 100.0 * p.radius2, "{p:?}");
}

#[test]
fn kinds_have_fixed_codes_and_names() {
    for (kind, code, name) in CounterpartKind::ALL {
        assert_eq!(kind.code(), code);
        assert_eq!(kind.name(), name);
        assert_eq!(CounterpartKind::from_code(code), Some(kind));
    }
    assert_eq!(CounterpartKind::Plane.code(), 0);
    assert_eq!(CounterpartKind::Curved.code(), 1);
    assert_eq!(CounterpartKind::Edge.code(), 2);
    let c = Counterpart::try_from_parts(CounterpartKind::Curved, [0.0, 30.0]).expect("valid");
    assert_eq!(c, Counterpart::try_cylinder(1.0 / 30.0).expect("valid"));
    assert_eq!(
        Counterpart::try_from_parts(CounterpartKind::Edge, [1.0, 1.0]).expect("valid"),
        Counterpart::EDGE
    );
}
