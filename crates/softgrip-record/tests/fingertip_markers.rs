//! The fingertips' markers on `/softgrip/markers`: a free fingertip is drawn as a sphere of
//! radius R, a backed one (flat or core: its flat face bonded to the finger) as a hemisphere
//! whose dome faces where the pad faces, nothing of it on the finger's side.

use softgrip_record::msgs::visualization_msgs::Marker;
use softgrip_record::visuals::{self, NS_FINGERTIPS};
use softgrip_record::{FingertipState, StepRecord};

const R: f64 = 0.01;

fn fingertip_marker(facing: Option<[f64; 3]>) -> Marker {
    let step = StepRecord {
        world_frame: "world".into(),
        fingertips: vec![FingertipState {
            name: "tip".into(),
            frame: "tip".into(),
            orientation: [0.0, 0.0, 0.0, 1.0],
            radius: R,
            facing,
            ..Default::default()
        }],
        ..Default::default()
    };
    visuals::markers(&step)
        .markers
        .into_iter()
        .find(|m| m.ns == NS_FINGERTIPS)
        .expect("a fingertip marker")
}

#[test]
fn a_free_fingertip_is_a_sphere_of_its_radius() {
    let m = fingertip_marker(None);
    assert_eq!(m.r#type, Marker::SPHERE);
    assert_eq!(
        (m.scale.x, m.scale.y, m.scale.z),
        (2.0 * R, 2.0 * R, 2.0 * R)
    );
    assert!(m.points.is_empty());
}

#[test]
fn a_backed_fingertip_is_a_hemisphere_facing_its_pad() {
    // Facing -x (e.g. a right jaw's pad facing the box), given unnormalised.
    let m = fingertip_marker(Some([-3.0, 0.0, 0.0]));
    assert_eq!(m.r#type, Marker::TRIANGLE_LIST);
    assert_eq!(m.header.frame_id, "tip");
    assert_eq!(m.points.len() % 3, 0);
    let (mut pole, mut min_x, mut max_x) = (0.0f64, f64::INFINITY, f64::NEG_INFINITY);
    for p in &m.points {
        let r = (p.x * p.x + p.y * p.y + p.z * p.z).sqrt();
        // On the dome (|p| = R) or on the flat face (x = 0), inside the sphere.
        assert!(r <= R * (1.0 + 1e-12), "{p:?} outside the sphere");
        assert!(
            p.x.abs() < 1e-15 || (r - R).abs() < 1e-15,
            "{p:?} neither dome nor face"
        );
        pole = pole.max(-p.x);
        min_x = min_x.min(p.x);
        max_x = max_x.max(p.x);
    }
    // The pole reaches R along the facing; nothing on the finger's side (x > 0).
    assert!(
        (pole - R).abs() < 1e-15 && (min_x + R).abs() < 1e-15,
        "{min_x}"
    );
    assert!(max_x <= 1e-15, "{max_x}");
    // Every triangle faces outwards: its normal points away from the centroid of the solid
    // (on the axis, 3R/8 from the face).
    let c = [-3.0 * R / 8.0, 0.0, 0.0];
    for t in m.points.chunks(3) {
        let (a, b, d) = (&t[0], &t[1], &t[2]);
        let u = [b.x - a.x, b.y - a.y, b.z - a.z];
        let v = [d.x - a.x, d.y - a.y, d.z - a.z];
        let n = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let mid = [
            (a.x + b.x + d.x) / 3.0 - c[0],
            (a.y + b.y + d.y) / 3.0 - c[1],
            (a.z + b.z + d.z) / 3.0 - c[2],
        ];
        let out = n[0] * mid[0] + n[1] * mid[1] + n[2] * mid[2];
        assert!(out > 0.0, "triangle {t:?} faces inwards");
    }
}
