//! A synthetic two-finger squeeze: deterministic, every field non-trivial.
#![allow(dead_code)]

use softgrip_law::{LevelKind, Regime};
use softgrip_record::msgs::geometry_msgs::{Point, Vector3};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{BodyPose, FingertipState, StepRecord, contact_wrench};

/// Step `k` of a squeeze at `dt_ns`: two fingertips press a box; contacts come and go.
pub fn step(k: u64, dt_ns: u64) -> StepRecord {
    let t = k as f64 * dt_ns as f64 * 1e-9;
    let r = 0.01;
    let delta = 1e-4 + 4e-3 * (t * 3.1).sin().abs();
    let names = ["thumb", "index finger"];
    let mut contacts = Vec::new();
    let mut tips = Vec::new();
    for (i, name) in names.iter().enumerate() {
        let s = if i == 0 { 1.0 } else { -1.0 };
        let center = [s * (0.03 + r - delta), 0.001 * t, 0.05];
        if k % 7 != 3 || i == 0 {
            let mut c = SoftContactMsg {
                fingertip: name.to_string(),
                other: "box".into(),
                point: Point::from_array([s * 0.03, 0.001 * t, 0.05 + 1e-5 * k as f64]),
                normal: Vector3::from_array([s, 0.0, 0.0]),
                compression: delta,
                ratio_x: delta / r,
                normal_force: 1.0e3 * delta + 0.1 * i as f64,
                friction_force: Vector3::from_array([0.0, -0.3 * t, 0.05 * (k as f64).cos()]),
                torsional_moment: 1e-4 * (t * 5.0).sin(),
                contact_radius: (r * delta).sqrt() * 1.1,
                mean_pressure: 1.0e5 + k as f64,
                peak_pressure: 1.5e5 + 1.5 * k as f64,
                stiffness: 2.5e3 / (1.0 + t),
                sliding: k.is_multiple_of(5),
                peak_normal_force: 1.2e3 * delta,
                max_compression: delta * 1.01,
                contact_duration: 1e-3,
                ..Default::default()
            };
            c.set_level(if k.is_multiple_of(2) {
                LevelKind::Calibrated
            } else {
                LevelKind::NeoHookean
            });
            c.set_regime(if delta / r > 0.35 {
                Regime::Extended
            } else {
                Regime::Valid
            });
            // The first fingertip on a cylinder of radius 3 cm (an ellipse along z), the other
            // on a plane (a disc).
            if i == 0 {
                let cylinder = softgrip_law::Counterpart::try_cylinder(0.03)
                    .expect("invariant: a valid radius");
                c.set_counterpart(cylinder, [0.0, 0.0, 1.0]);
                c.contact_radius2 = 0.8 * c.contact_radius;
            } else {
                c.contact_radius2 = c.contact_radius;
            }
            contacts.push(c);
        }
        let wrench = contact_wrench(center, contacts.iter().filter(|c| c.fingertip == *name));
        tips.push(FingertipState {
            name: name.to_string(),
            position: center,
            orientation: [0.0, 0.0, (0.1 * t).sin(), (0.1 * t).cos()],
            radius: r,
            wrench,
            frame: name.to_string(),
            arrow_scale: 1e-3,
            facing: None,
        });
    }
    StepRecord {
        time_ns: k * dt_ns,
        world_frame: "world".into(),
        contacts,
        fingertips: tips,
        bodies: vec![BodyPose {
            name: "box".into(),
            parent: String::new(),
            position: [0.0, 0.001 * t, 0.05],
            orientation: [0.0, 0.0, 0.0, 1.0],
        }],
        ..StepRecord::default()
    }
}

/// Relative closeness `|a - b| <= tol max(|a|, |b|)` (exact for zero).
pub fn close(a: f64, b: f64, tol: f64) -> bool {
    a == b || (a - b).abs() <= tol * a.abs().max(b.abs())
}
