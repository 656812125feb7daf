//! Property tests of the `tabulated` level over random measured curves: F(0) = 0, F >= 0,
//! monotone, finite for any input, through every sample.

use proptest::prelude::*;
use softgrip_law::{ContactLaw, ContactParams, Regime, TabulatedCurve};

/// A random valid curve: 2..40 samples, positive steps in delta, non-negative steps in force
/// (some of them zero: plateaus), at R = 10 mm.
fn law_strategy() -> impl Strategy<Value = ContactLaw> {
    (
        prop::collection::vec(
            (1e-6f64..1e-3, prop_oneof![Just(0.0), 1e-4f64..10.0]),
            2..40,
        ),
        any::<bool>(),
        1e4f64..1e8,
    )
        .prop_filter_map("valid curve", |(steps, with_origin, e_star)| {
            let (mut delta, mut force) = (Vec::new(), Vec::new());
            if with_origin {
                delta.push(0.0);
                force.push(0.0);
            }
            let (mut d, mut f) = (0.0, 0.0);
            for (dd, df) in steps {
                d += dd;
                f += df;
                delta.push(d);
                force.push(f);
            }
            let curve = TabulatedCurve::try_new(delta, force).ok()?;
            let params = ContactParams::try_from_parts(e_star, 0.010, 0.49).ok()?;
            ContactLaw::tabulated(params, curve).ok()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn force_is_zero_at_contact_and_non_negative(law in law_strategy(), s in 0.0f64..1.5) {
        prop_assert_eq!(law.response(0.0).force, 0.0);
        prop_assert_eq!(law.response(0.0).regime, Regime::Separated);
        let r = law.response(s * law.delta_max());
        prop_assert!(r.force >= 0.0 && r.force.is_finite());
        prop_assert!(r.stiffness >= 0.0 && r.stiffness.is_finite());
    }

    #[test]
    fn force_and_energy_are_monotone(law in law_strategy(), a in 0.0f64..1.5, b in 0.0f64..1.5) {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        let d = law.delta_max();
        prop_assert!(law.response(lo * d).force <= law.response(hi * d).force);
        prop_assert!(law.energy(lo * d) <= law.energy(hi * d));
    }

    #[test]
    fn it_passes_through_every_sample(law in law_strategy()) {
        let curve = law.tabulated_curve().expect("tabulated").clone();
        for (&d, &f) in curve.delta_m().iter().zip(curve.force_n()) {
            let got = law.response(d).force;
            prop_assert!((got - f).abs() <= 1e-12 * curve.force_max(), "delta {} F {} got {}", d, f, got);
        }
    }

    #[test]
    fn hot_path_is_finite_for_any_input(law in law_strategy(), delta in prop::num::f64::ANY) {
        let r = law.response(delta);
        prop_assert!(r.force.is_finite() && r.force >= 0.0);
        prop_assert!(r.stiffness.is_finite() && r.stiffness >= 0.0);
        prop_assert!(law.energy(delta).is_finite());
        let p = law.patch(delta);
        prop_assert!(p.radius.is_finite() && p.mean_pressure.is_finite());
        if !delta.is_finite() {
            prop_assert_eq!(r.regime, Regime::NonFinite);
        }
    }
}
