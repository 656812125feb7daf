//! Property tests over random valid inputs: F(0) = 0, F >= 0, monotone in delta, finite for
//! finite input, the extension continuous, the hot path never NaN.

mod common;

use proptest::prelude::*;
use softgrip_law::{ContactLaw, ContactParams, Level, Material, Regime};

fn level_strategy() -> impl Strategy<Value = Level> {
    prop_oneof![
        (0.001f64..1.0).prop_map(|match_x| Level::Linear { match_x }),
        Just(Level::Hertz),
        (0.0f64..3.0).prop_map(|k| Level::Fit { k }),
        Just(Level::Incompressible),
        Just(Level::NeoHookean),
        Just(Level::NeoHookeanExact),
        Just(Level::Tatara),
        Just(Level::Calibrated),
        (0.002f64..0.2).prop_map(|tolerance| Level::Auto { tolerance }),
    ]
}

fn law_strategy() -> impl Strategy<Value = ContactLaw> {
    (level_strategy(), 1e3f64..1e9, -0.5f64..0.4999, 1e-6f64..1.0).prop_filter_map(
        "level builds",
        |(level, e, nu, r)| {
            let m = Material::try_new(e, nu).ok()?;
            ContactLaw::try_new(ContactParams::try_new(m, r).ok()?, level).ok()
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn force_is_zero_at_contact_and_positive_in_it(law in law_strategy(), s in 1e-6f64..1.5) {
        prop_assert_eq!(law.response(0.0).force, 0.0);
        prop_assert_eq!(law.response(0.0).regime, Regime::Separated);
        let r = law.response(s * law.delta_max());
        prop_assert!(r.force > 0.0 && r.force.is_finite());
        prop_assert!(r.stiffness > 0.0 && r.stiffness.is_finite());
    }

    #[test]
    fn force_is_monotone(law in law_strategy(), a in 0.0f64..1.5, b in 0.0f64..1.5) {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        let d = law.delta_max();
        prop_assert!(law.response(lo * d).force <= law.response(hi * d).force);
        prop_assert!(law.energy(lo * d) <= law.energy(hi * d));
    }

    #[test]
    fn extension_is_continuous(law in law_strategy()) {
        let d = law.delta_max();
        let (inside, outside) = (law.response(d), law.response(d * (1.0 + 1e-12)));
        prop_assert_eq!(outside.regime, Regime::Extended);
        prop_assert!((outside.force / inside.force - 1.0).abs() < 1e-9);
        prop_assert!((outside.stiffness / inside.stiffness - 1.0).abs() < 1e-9);
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

    #[test]
    fn radius_and_pressure_are_positive_in_contact(law in law_strategy(), s in 1e-4f64..1.0) {
        let p = law.patch(s * law.delta_max());
        prop_assert!(p.radius > 0.0);
        // Force-conserving shape (1 - r^2/a^2)^m: peak = (m + 1) mean, m in [0, 2].
        prop_assert!(p.shape >= 0.0 && p.shape <= 2.0);
        prop_assert!((p.peak_pressure / p.mean_pressure - 1.0 - p.shape).abs() < 1e-12);
    }
}
