//! The scripted squeeze the probe publishes: known values that the DDS round-trip test
//! compares with what a foreign DDS participant decoded.
//! (Shared with `tests/dds_roundtrip.rs` through `#[path]`.)

use softgrip_law::{Counterpart, LevelKind, Regime};
use softgrip_record::msgs::geometry_msgs::{Point, Vector3};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{BodyPose, FingertipState, StepRecord, contact_wrench};

/// Steps in the script (published in a loop, each keeping its stamp).
pub const STEPS: u64 = 4;
/// The fingertips (the second's wrench topic is sanitised: `/softgrip/index_finger/wrench`).
pub const TIPS: [&str; 2] = ["thumb", "index finger"];
/// The other body: not ASCII, so strings are checked byte for byte through UTF-8.
pub const OTHER: &str = "box \u{fc}ber-gr\u{f6}\u{df}e";
/// Fingertip radius R \[m\].
pub const RADIUS: f64 = 0.0125;

/// Simulation time of step `k` \[ns\]: distinct seconds and nanoseconds.
pub fn time_ns(k: u64) -> u64 {
    (k + 1) * 1_250_000_017 + 3
}

/// Step `k` of the script (`k < STEPS`): every float non-round, every flag exercised.
pub fn step(k: u64) -> StepRecord {
    let kf = k as f64;
    let mut contacts = Vec::new();
    let mut tips = Vec::new();
    for (i, name) in TIPS.iter().enumerate() {
        let s = if i == 0 { 1.0 } else { -1.0 };
        let delta = 1e-4 * (1.0 + kf) + 1.0 / 3.0 * 1e-3 * i as f64;
        let center = [
            s * (0.03 + RADIUS - delta),
            1e-3 * kf / 7.0,
            0.05 + kf * 1e-6,
        ];
        let mut c = SoftContactMsg {
            fingertip: (*name).to_owned(),
            other: OTHER.to_owned(),
            point: Point::from_array([s * 0.03, center[1], center[2] - 1e-5 / 3.0]),
            normal: Vector3::from_array([s * 0.6, 0.0, 0.8]),
            compression: delta,
            ratio_x: delta / RADIUS,
            normal_force: 1234.5678 * delta + 0.1 * i as f64,
            friction_force: Vector3::from_array([-0.3 / 7.0 * kf, 1e-9, -std::f64::consts::PI]),
            torsional_moment: -1e-4 * (kf + 0.5).sin(),
            contact_radius: (RADIUS * delta).sqrt(),
            mean_pressure: 1.0e5 + kf / 3.0,
            peak_pressure: 1.5e5 + kf / 2.0,
            stiffness: 2.5e3 / (1.0 + kf),
            sliding: (k + i as u64).is_multiple_of(2),
            peak_normal_force: 1.2e3 * delta,
            max_compression: delta * 1.01,
            contact_duration: 1e-3 * (kf + 1.0),
            ..Default::default()
        };
        c.set_level(if i == 0 {
            LevelKind::Calibrated
        } else {
            LevelKind::NeoHookean
        });
        c.set_regime(if k == 2 {
            Regime::Extended
        } else {
            Regime::Valid
        });
        // A cylinder's side for one fingertip (an ellipse along z), a plane for the other.
        if i == 0 {
            let cylinder = Counterpart::try_curved(0.0, 1.0 / (0.03 + kf * 1e-3))
                .expect("invariant: a finite, non-zero curvature");
            c.set_counterpart(cylinder, [0.0, 0.6, -0.8]);
            c.contact_radius2 = 0.7 * c.contact_radius;
        } else {
            c.set_counterpart(Counterpart::PLANE, [0.8, 0.0, -0.6]);
            c.contact_radius2 = c.contact_radius;
        }
        let wrench = contact_wrench(center, [&c]);
        contacts.push(c);
        tips.push(FingertipState {
            name: (*name).to_owned(),
            position: center,
            orientation: [0.0, 0.0, (0.1 * kf).sin(), (0.1 * kf).cos()],
            radius: RADIUS,
            wrench,
            ..Default::default()
        });
    }
    StepRecord {
        time_ns: time_ns(k),
        world_frame: "world".into(),
        contacts,
        fingertips: tips,
        bodies: vec![BodyPose {
            name: "box".into(),
            parent: String::new(),
            position: [0.0, 1e-3 * kf / 7.0, 0.05],
            orientation: [0.0, 0.0, 0.0, 1.0],
        }],
        ..StepRecord::default()
    }
}
