//! A user's own `NormalisedLaw`, used through `ContactLaw::custom`: the law's checks, the hot
//! path, the checked API and the inverse work on it as on a built-in level.

use std::sync::Arc;

use softgrip_law::{ContactLaw, ContactParams, Error, Level, LevelKind, NormalisedLaw, Regime};

/// The paper's explicit law with its own k and Hertz's radius, written as a user would:
/// `f = (4/3) x^(3/2) / (1 - k x)`.
#[derive(Debug)]
struct MyFit {
    k: f64,
}

impl NormalisedLaw for MyFit {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let d = 1.0 / (1.0 - self.k * x);
        let (fh, dfh) = (4.0 / 3.0 * x * x.sqrt(), 2.0 * x.sqrt());
        (fh * d, dfh * d + fh * self.k * d * d)
    }
    fn energy(&self, x: f64) -> f64 {
        // Simpson in u = sqrt(x), fine enough for a test law.
        let n = 2000;
        let h = x.sqrt() / n as f64;
        let g = |u: f64| 2.0 * u * self.force_stiffness(u * u).0;
        let mut s = g(0.0) + g(x.sqrt());
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * g(i as f64 * h);
        }
        s * h / 3.0
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        0.6
    }
}

fn params() -> ContactParams {
    ContactParams::try_from_parts(2.0e6, 0.010, 0.49).expect("valid")
}

#[test]
fn a_user_law_behaves_like_a_level() {
    let law = ContactLaw::custom(params(), Arc::new(MyFit { k: 10.0 / 9.0 })).expect("valid");
    let fit = ContactLaw::try_new(params(), Level::fit()).expect("builds");
    assert_eq!(law.level(), Level::Custom);
    assert_eq!(law.x_max(), 0.6);
    for delta in [1e-4, 1e-3, 3e-3, 5.9e-3] {
        let (r, f) = (law.response(delta), fit.response(delta));
        assert_eq!((r.regime, r.level), (Regime::Valid, LevelKind::Custom));
        assert!((r.force / f.force - 1.0).abs() < 1e-12, "delta {delta}");
        assert!(
            (r.stiffness / f.stiffness - 1.0).abs() < 1e-12,
            "delta {delta}"
        );
        assert!(
            (law.energy(delta) / fit.energy(delta) - 1.0).abs() < 1e-9,
            "delta {delta}"
        );
        let back = law.compression_for_force(r.force).expect("in range");
        assert!((back / delta - 1.0).abs() < 1e-9, "delta {delta}");
    }
    assert_eq!(law.kind_at(0.3), LevelKind::Custom);
    assert!(matches!(
        law.evaluate(0.007),
        Err(Error::OutOfRange {
            level: LevelKind::Custom,
            ..
        })
    ));
    assert_eq!(law.response(0.007).regime, Regime::Extended);
}

/// A law that is wrong in one way or another.
#[derive(Debug)]
struct Broken {
    x_max: f64,
    /// Force at x: 1 - x (decreasing) if true, else x.
    softens: bool,
    /// NaN force inside (0.5, 0.51), between the construction checks' sample points.
    hole: bool,
}

impl NormalisedLaw for Broken {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        if self.hole && x > 0.5 && x < 0.51 {
            return (f64::NAN, f64::NAN);
        }
        if self.softens {
            (1.0 - x, -1.0)
        } else {
            (x, 1.0)
        }
    }
    fn energy(&self, x: f64) -> f64 {
        0.5 * x * x
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        self.x_max
    }
}

#[test]
fn a_broken_user_law_is_rejected_or_contained() {
    let custom = |x_max, softens, hole| {
        ContactLaw::custom(
            params(),
            Arc::new(Broken {
                x_max,
                softens,
                hole,
            }),
        )
    };
    for x_max in [f64::NAN, 0.0, -1.0, 5.0] {
        assert!(
            matches!(
                custom(x_max, false, false),
                Err(Error::InvalidCustomLaw {
                    quantity: "x_max",
                    ..
                })
            ),
            "x_max {x_max}"
        );
    }
    match custom(1.0, true, false) {
        Err(
            e @ Error::InvalidCustomLaw {
                quantity: "stiffness",
                ..
            },
        ) => {
            assert!(e.to_string().contains("must be finite and >= 0"), "{e}");
        }
        other => panic!("expected InvalidCustomLaw(stiffness), got {other:?}"),
    }
    // A NaN the checks did not sample is contained on the hot path: zero force, never NaN.
    let law = custom(1.0, false, true).expect("passes the sampled checks");
    let r = law.response(0.505 * 0.010);
    assert_eq!((r.force, r.stiffness), (0.0, 0.0));
}
