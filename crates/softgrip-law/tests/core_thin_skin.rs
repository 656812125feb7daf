//! Regression (issue 26): `core_thickness = 1e-22` was accepted and the calibrated core's force
//! turned negative (NaN below t/R 1e-200), so the fingertip fell through the floor. The
//! calibrated level of a `core` fingertip (and `auto`, whose reference it is) now refuses a
//! skin thinner than `MIN_CORE_THICKNESS_RATIO` with a typed error naming `thickness_ratio`, its
//! value and the range; from that boundary up the law is finite, positive and increasing, with
//! an increasing energy, at every Poisson ratio it takes.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::{
    Backing, ContactLaw, ContactParams, Error, Level, MIN_CORE_THICKNESS_RATIO, Material,
};

fn law(nu: f64, tau: f64, level: Level) -> Result<ContactLaw, Error> {
    let p = ContactParams::try_new(Material::try_new(1.0e6, nu).unwrap(), 0.01)
        .unwrap()
        .with_backing(Backing::Core {
            thickness: tau * 0.01,
        })?;
    ContactLaw::try_new(p, level)
}

#[test]
fn core_thickness_1e_22_made_the_force_negative_and_is_refused() {
    for tau in [1e-300, 1e-200, 1e-22, 1e-8, 1e-3, 0.01, 0.049_999] {
        for level in [Level::Calibrated, Level::Auto { tolerance: 0.01 }] {
            let e = law(0.49, tau, level).unwrap_err();
            match &e {
                Error::InvalidParameter { field, value, .. } => {
                    assert_eq!(*field, "thickness_ratio", "{e}");
                    assert!((value / tau - 1.0).abs() < 1e-12, "{e}");
                }
                other => panic!("t/R = {tau:e}: {other}"),
            }
            let text = e.to_string();
            assert!(text.contains("[0.05, 1)"), "{text}");
            // The value in shortest form (1e-22, not 0.000...0001).
            assert!(text.len() < 300, "{text}");
        }
    }
    // A measured curve holds any thickness: the bound is the calibrated form's.
    assert!(law(0.49, 1e-3, Level::Hertz).is_ok());
}

/// At the boundary and just above it, over nu in [0.3, 0.5] every 0.005: over the validity
/// range (2000 points) the force is finite, > 0 and increasing, the stiffness finite and > 0,
/// the energy increasing, the contact radius finite and > 0; and the force lies between
/// Hertz's and 170x Hertz's (20x at t/R = 0.05, nu 0.45, x_max) (a thin bonded skin is stiffer than Hertz, never softer).
/// The largest is at nu 0.5, t/R 0.05, x_max (delta/t 0.8): 106.9x since session 24's
/// deviatoric stiffening of the squeezed skin (below 100x before; the bound was 100x then),
/// 112.1x since session 28's thin-skin form (the exact shell on its core; bound unchanged).
/// Matthewson's incompressible thin layer alone, on the unsqueezed skin, is `(3 pi/8)(a_H/t)^3`
/// = 75x there, and the squeeze to 0.2 t stiffens it further, so 107-112x is not unphysical.
/// Session 29's squeezed film (the thin-skin form SFF) takes it to 158.8x (nu 0.49 there: 70.7x
/// -> 73.7x), so the bound is raised from 120x to 170x, a loosening with this reason: at nu 0.5
/// the film's flow share is 1, and the incompressible film squeezed to h = 0.2 t between the
/// plane and the core's sphere is `Phi_c = 3.1` times stiffer than unsqueezed (its `h^-3`
/// lubrication), i.e. about 230x for Matthewson's 75x; the form takes 0.35 of that excess (its
/// fitted `cf`). No FE exists at nu 0.5 on a thin skin; the nearest, nu 0.49 t/R 0.12 to delta/t
/// 0.79 (held out), is met within 1.86 % (`backed` tests).
#[test]
fn thinnest_accepted_core_is_finite_positive_and_monotone_over_nu() {
    let mut checked = 0;
    let mut top = (0.0, String::new());
    for tau in [
        MIN_CORE_THICKNESS_RATIO,
        MIN_CORE_THICKNESS_RATIO * 1.001,
        0.07,
        0.1,
    ] {
        for j in 0..=40 {
            let nu = 0.3 + 0.005 * f64::from(j);
            let law = law(nu, tau, Level::Calibrated).unwrap();
            let (mut f0, mut e0) = (0.0, 0.0);
            for k in 1..=2000 {
                let delta = law.delta_max() * f64::from(k) / 2000.0;
                let s = law.evaluate(delta).unwrap();
                let hertz =
                    4.0 / 3.0 * law.params().effective_modulus() * 0.01f64.sqrt() * delta.powf(1.5);
                let at = format!("t/R {tau}, nu {nu}, delta {delta:e}: {s:?}");
                assert!(s.force.is_finite() && s.force > f0, "{at}");
                assert!(s.stiffness.is_finite() && s.stiffness > 0.0, "{at}");
                assert!(s.energy.is_finite() && s.energy > e0, "{at}");
                assert!(s.patch.radius.is_finite() && s.patch.radius > 0.0, "{at}");
                if s.force / hertz > top.0 {
                    top = (s.force / hertz, at.clone());
                }
                assert!(s.force >= hertz && s.force <= 170.0 * hertz, "{at}");
                (f0, e0) = (s.force, s.energy);
                checked += 1;
            }
        }
    }
    eprintln!("largest F/F_Hertz {:.2}: {}", top.0, top.1);
    assert_eq!(checked, 4 * 41 * 2000);
}
