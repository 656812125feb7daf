//! The force arrows of `/softgrip/markers` stay bounded at large forces (issue 12: a linear
//! `normal_force × arrow_scale` arrow grew with the law's steep force at large x and left the
//! view): linear up to the reference force (one radius), logarithmic above it, capped at
//! `ARROW_MAX_RADII` radii.

use softgrip_record::msgs::geometry_msgs::{Point, Vector3};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::visuals::{self, ARROW_MAX_RADII, NS_FORCES, arrow_length};
use softgrip_record::{FingertipState, StepRecord};

const R: f64 = 0.01;
/// Reference force (the law's force at x = 0.2) [N]: arrow_scale = R / F_REF.
const F_REF: f64 = 5.0;

/// A step with one contact of normal force `force` on a 10 mm fingertip, normal +x.
fn step(force: f64) -> StepRecord {
    StepRecord {
        world_frame: "world".into(),
        fingertips: vec![FingertipState {
            name: "tip".into(),
            orientation: [0.0, 0.0, 0.0, 1.0],
            radius: R,
            arrow_scale: R / F_REF,
            ..Default::default()
        }],
        contacts: vec![SoftContactMsg {
            fingertip: "tip".into(),
            point: Point::from_array([0.01, 0.0, 0.0]),
            normal: Vector3::from_array([1.0, 0.0, 0.0]),
            normal_force: force,
            ..Default::default()
        }],
        ..Default::default()
    }
}

/// Length of the drawn arrow of `step(force)` [m].
fn drawn(force: f64) -> f64 {
    let markers = visuals::markers(&step(force)).markers;
    let arrow = markers
        .iter()
        .find(|m| m.ns == NS_FORCES)
        .expect("an arrow");
    arrow.points[1].x - arrow.points[0].x
}

#[test]
fn arrows_are_linear_up_to_the_reference_force() {
    for f in [0.1, 1.0, 2.5, 5.0] {
        let want = R * f / F_REF;
        assert!(
            (drawn(f) - want).abs() < 1e-17,
            "{f} N: {} vs {want}",
            drawn(f)
        );
    }
}

#[test]
fn arrows_grow_logarithmically_above_it_continuous_in_value_and_slope() {
    for u in [2.0, 5.0, 10.0, 20.0] {
        let want = R * (1.0 + f64::ln(u));
        assert!((drawn(u * F_REF) - want).abs() < 1e-16, "u = {u}");
    }
    // Continuity at the reference force: value and one-sided slopes [m/N].
    let h = 1e-6;
    let below = (drawn(F_REF) - drawn(F_REF - h)) / h;
    let above = (drawn(F_REF + h) - drawn(F_REF)) / h;
    assert!((below - R / F_REF).abs() < 1e-9, "{below}");
    assert!((above - R / F_REF).abs() < 1e-9, "{above}");
}

#[test]
fn arrows_are_capped_at_four_radii() {
    assert_eq!(ARROW_MAX_RADII, 4.0);
    // The cap starts at u = e^3 (1 + ln u = 4).
    let u_cap = f64::exp(3.0);
    assert!((drawn(0.999 * u_cap * F_REF) - R * (4.0 + f64::ln(0.999))).abs() < 1e-16);
    for f in [u_cap * F_REF * 1.001, 1e3, 1e9, f64::MAX] {
        assert_eq!(drawn(f), 4.0 * R, "{f} N");
    }
}

#[test]
fn no_arrow_length_for_odd_input() {
    for (f, r, k) in [
        (0.0, R, 1e-3),
        (-1.0, R, 1e-3),
        (f64::NAN, R, 1e-3),
        (f64::INFINITY, R, 1e-3),
        (1.0, R, 0.0),
        (1.0, 0.0, 1e-3),
        (1.0, f64::NAN, 1e-3),
    ] {
        assert_eq!(arrow_length(f, r, k), 0.0, "{f} {r} {k}");
    }
}
