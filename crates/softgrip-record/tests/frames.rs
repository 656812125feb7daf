//! The converter's frames and fields (issue 12): z-up world from a y-up scene, the tf tree
//! world -> body -> fingertip with `/tf_static` once, unique frame names, wrenches in the
//! fingertip frame, stamps from the f64 step, `mean_pressure · π a² = normal_force`, every
//! shape drawn, patch discs relative to the patch, rosbag2 QoS metadata.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::{ContactPatch, Level, LevelKind, Regime};
use softgrip_record::frames::{UpAxis, fingertip_frame, rotate};
use softgrip_record::msgs::visualization_msgs::Marker;
use softgrip_record::visuals::{self, DISC_THICKNESS, NS_BODIES, NS_FORCES, NS_PATCHES};
use softgrip_record::{
    BodySample, ContactReading, ContactSample, Delivery, FingertipInfo, FingertipLaw, SceneInfo,
    ShapeGeometry, ShapeInfo, StepConverter, StepFrame, StepRecord, StepTopic, WrenchSample,
    arrow_scale,
};

fn tip(name: &str, body: &str, radius: f64) -> FingertipInfo {
    FingertipInfo {
        name: name.into(),
        body: body.into(),
        offset: [0.01, 0.0, 0.0],
        radius,
        law: FingertipLaw {
            name: name.into(),
            level: Level::auto(),
            youngs_modulus: 5.9e5,
            poisson_ratio: 0.49,
            radius,
            friction: 0.8,
            restitution: 0.5,
            backing: softgrip_law::Backing::Free,
            curve: None,
            custom_name: None,
        },
        facing: None,
    }
}

fn shape(body: &str, geometry: ShapeGeometry) -> ShapeInfo {
    ShapeInfo {
        body: body.into(),
        offset: [0.0; 3],
        rotation: [0.0, 0.0, 0.0, 1.0],
        geometry,
    }
}

fn scene() -> SceneInfo {
    SceneInfo {
        origin: "test".into(),
        dt: 1.0 / 60.0,
        steps: 300,
        bodies: vec!["table".into(), "jaw".into(), "sphere".into()],
        fingertips: vec![tip("thumb", "jaw", 0.01), tip("sphere", "sphere", 1.42e-5)],
        shapes: vec![
            shape(
                "table",
                ShapeGeometry::Plane {
                    normal: [0.0, 1.0, 0.0],
                },
            ),
            shape(
                "jaw",
                ShapeGeometry::Cuboid {
                    half_extents: [0.01, 0.02, 0.03],
                },
            ),
            shape("jaw", ShapeGeometry::Ball { radius: 0.004 }),
            shape(
                "jaw",
                ShapeGeometry::Cylinder {
                    half_height: 0.01,
                    radius: 0.002,
                },
            ),
            shape(
                "sphere",
                ShapeGeometry::Mesh {
                    vertices: vec![[0.0; 3], [1e-5, 0.0, 0.0], [0.0, 1e-5, 0.0]],
                    triangles: vec![[0, 1, 2]],
                },
            ),
        ],
        up: UpAxis::Y,
        gravity: [0.0, -9.81, 0.0],
        robots: Vec::new(),
        frames: Vec::new(),
        controllers: Vec::new(),
    }
}

fn reading(force: f64, radius: f64, pressure: bool) -> ContactReading {
    let patch = ContactPatch::new(1.1 * force, radius);
    ContactReading {
        point: [0.0, 0.02, 0.0],
        normal: [1.0, 0.0, 0.0],
        delta: 1e-3,
        x: 0.1,
        normal_force: force,
        friction_force: [0.0, 0.5, 0.0],
        torsional_moment: 0.0,
        stiffness: 1e3,
        level: LevelKind::Hertz,
        regime: Regime::Valid,
        validity_exceeded: false,
        sliding: false,
        peak_normal_force: force,
        max_delta: 1e-3,
        max_x: 0.1,
        contact_duration: 1.0 / 60.0,
        backing: softgrip_law::Backing::Core { thickness: 0.004 },
        counterpart: softgrip_law::Counterpart::PLANE,
        patch_direction: [0.0, 0.0, 1.0],
        patch: Some(if pressure {
            patch
        } else {
            ContactPatch {
                radius: patch.radius,
                radius2: patch.radius2,
                ..ContactPatch::EMPTY
            }
        }),
    }
}

/// A frame with the jaw turned a quarter turn about scene +y.
fn frame(step: u64, pressure: bool) -> StepFrame {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    StepFrame {
        step,
        tactile: Vec::new(),
        joints: Vec::new(),
        commands: Vec::new(),
        time: step as f64 * (1.0 / 60.0) as f32 as f64, // an f32-rounded time: not used
        bodies: vec![
            BodySample {
                name: "table".into(),
                translation: [0.0; 3],
                rotation: [0.0, 0.0, 0.0, 1.0],
            },
            BodySample {
                name: "jaw".into(),
                translation: [0.0, 0.02, 0.0],
                rotation: [0.0, h, 0.0, h],
            },
            BodySample {
                name: "sphere".into(),
                translation: [0.0; 3],
                rotation: [0.0, 0.0, 0.0, 1.0],
            },
        ],
        wrenches: vec![
            WrenchSample {
                fingertip: "thumb".into(),
                force: [2.0, 0.0, 0.0],
                torque: [0.0, 0.0, 0.1],
            },
            WrenchSample {
                fingertip: "sphere".into(),
                force: [0.0; 3],
                torque: [0.0; 3],
            },
        ],
        contacts: vec![ContactSample {
            fingertip: "thumb".into(),
            other: "box".into(),
            contact: reading(2.0, 1e-3, pressure),
        }],
    }
}

fn convert(conv: &mut StepConverter, step: u64, pressure: bool) -> StepRecord {
    let mut rec = StepRecord::default();
    conv.convert(&frame(step, pressure), &mut rec);
    rec
}

#[test]
fn fingertip_named_like_a_body_gets_its_own_frame() {
    let s = scene();
    assert_eq!(fingertip_frame(&s, "thumb"), "thumb");
    assert_eq!(fingertip_frame(&s, "sphere"), "sphere_tip");
}

#[test]
fn tf_static_once_with_fingertips_as_children_of_their_bodies() {
    let mut conv = StepConverter::new(&scene());
    let first = convert(&mut conv, 1, true);
    let tf = first.tf_static.as_ref().unwrap();
    let edges: Vec<_> = tf
        .transforms
        .iter()
        .map(|t| (t.header.frame_id.as_str(), t.child_frame_id.as_str()))
        .collect();
    assert_eq!(edges, [("jaw", "thumb"), ("sphere", "sphere_tip")]);
    assert_eq!(
        tf.transforms[0].transform.translation.to_array(),
        [0.01, 0.0, 0.0]
    );
    assert!(convert(&mut conv, 2, true).tf_static.is_none());
    // /tf: the bodies only, children of world, no child twice.
    let dynamic = first.tf();
    let children: Vec<_> = dynamic
        .transforms
        .iter()
        .map(|t| t.child_frame_id.as_str())
        .collect();
    assert_eq!(children, ["table", "jaw", "sphere"]);
    assert!(
        dynamic
            .transforms
            .iter()
            .all(|t| t.header.frame_id == "world")
    );
}

#[test]
fn y_up_scene_is_recorded_z_up() {
    let mut conv = StepConverter::new(&scene());
    let rec = convert(&mut conv, 1, true);
    // The jaw at scene y = 0.02 is at world z = 0.02.
    assert_eq!(rec.bodies[1].position, [0.0, 0.0, 0.02]);
    // A body at rest: its frame's y axis (the scene's up) points up in the world.
    let up = rotate(rec.bodies[0].orientation, [0.0, 1.0, 0.0]);
    assert!((up[2] - 1.0).abs() < 1e-15, "{up:?}");
    // The table's slab: its top face normal (marker z) is world +z.
    let slab = visuals::markers(&rec)
        .markers
        .into_iter()
        .find(|m| m.ns == NS_BODIES)
        .unwrap();
    let q = softgrip_record::frames::mul(
        rec.bodies[0].orientation,
        [
            slab.pose.orientation.x,
            slab.pose.orientation.y,
            slab.pose.orientation.z,
            slab.pose.orientation.w,
        ],
    );
    let n = rotate(q, [0.0, 0.0, 1.0]);
    assert!((n[2] - 1.0).abs() < 1e-15, "{n:?}");
    // Contact point and friction in world axes.
    assert_eq!(rec.contacts[0].point.to_array(), [0.0, 0.0, 0.02]);
    assert_eq!(rec.contacts[0].friction_force.to_array(), [0.0, 0.0, 0.5]);
}

#[test]
fn wrench_is_in_the_fingertip_frame() {
    let mut conv = StepConverter::new(&scene());
    let rec = convert(&mut conv, 1, true);
    let thumb = &rec.fingertips[0];
    assert_eq!(rec.frame_of(thumb), "thumb");
    // The jaw is turned +90 deg about scene y: scene +x is the jaw's +z, scene +z its -x.
    let f = thumb.wrench.force.to_array();
    let t = thumb.wrench.torque.to_array();
    assert!((f[2] - 2.0).abs() < 1e-15 && f[0].abs() < 1e-15, "{f:?}");
    assert!((t[0] + 0.1).abs() < 1e-15 && t[2].abs() < 1e-15, "{t:?}");
    // And back: the frame's world orientation turns it into the scene's force, z-up.
    let w = rotate(thumb.orientation, f);
    let want = UpAxis::Y.vector([2.0, 0.0, 0.0]);
    for i in 0..3 {
        assert!((w[i] - want[i]).abs() < 1e-14, "{w:?}");
    }
}

#[test]
fn stamps_are_exact_multiples_of_dt() {
    let mut conv = StepConverter::new(&scene());
    let dt_ns = 1e9 / 60.0;
    for step in 1..=300 {
        let t = convert(&mut conv, step, true).time_ns;
        assert!(
            (t as f64 - step as f64 * dt_ns).abs() <= 0.5,
            "step {step}: {t}"
        );
    }
    assert_eq!(convert(&mut conv, 300, true).time_ns, 5_000_000_000);
    assert_eq!(convert(&mut conv, 4, true).time_ns, 66_666_667);
}

#[test]
fn mean_pressure_times_area_is_the_normal_force() {
    let mut conv = StepConverter::new(&scene());
    let c = &convert(&mut conv, 1, true).contacts[0];
    let area = std::f64::consts::PI * c.contact_radius * c.contact_radius;
    assert!((c.mean_pressure * area / c.normal_force - 1.0).abs() < 1e-14);
    assert!((c.peak_pressure / c.mean_pressure - 1.5).abs() < 1e-12);
    // The construction goes with every contact (issue 10).
    assert_eq!((c.backing, c.core_thickness), (2, 0.004));
    // Without pressure: the radius stays, the pressures are 0.
    let c = &convert(&mut conv, 2, false).contacts[0];
    assert_eq!(
        (c.contact_radius, c.mean_pressure, c.peak_pressure),
        (1e-3, 0.0, 0.0)
    );
}

#[test]
fn every_shape_is_drawn_and_patches_scale_with_their_radius() {
    let mut conv = StepConverter::new(&scene());
    let rec = convert(&mut conv, 1, true);
    let markers = visuals::markers(&rec).markers;
    let bodies: Vec<&Marker> = markers.iter().filter(|m| m.ns == NS_BODIES).collect();
    let types: Vec<i32> = bodies.iter().map(|m| m.r#type).collect();
    assert_eq!(
        types,
        [
            Marker::CUBE,
            Marker::CUBE,
            Marker::SPHERE,
            Marker::CYLINDER,
            Marker::TRIANGLE_LIST
        ]
    );
    let ids: Vec<i32> = bodies.iter().map(|m| m.id).collect();
    assert_eq!(ids, [0, 1, 2, 3, 4]);
    let frames: Vec<&str> = bodies.iter().map(|m| m.header.frame_id.as_str()).collect();
    assert_eq!(frames, ["table", "jaw", "jaw", "jaw", "sphere"]);
    assert_eq!(bodies[1].scale.to_array(), [0.02, 0.04, 0.06]);
    assert_eq!(bodies[4].points.len(), 3);
    assert!(bodies.iter().all(|m| m.header.stamp == rec.header().stamp));
    let patch = markers.iter().find(|m| m.ns == NS_PATCHES).unwrap();
    assert_eq!(patch.scale.z, DISC_THICKNESS * 1e-3);
    let arrow = markers.iter().find(|m| m.ns == NS_FORCES).unwrap();
    let len = arrow.points[1].x - arrow.points[0].x;
    let scale = arrow_scale(&scene().fingertips[0]);
    assert!((len - 2.0 * scale).abs() < 1e-15, "{len}");
    // One radius at the law's force at x = 0.2.
    let law = scene().fingertips[0].law.law().unwrap();
    assert!((scale * law.response(0.2 * 0.01).force - 0.01).abs() < 1e-15);
}

#[test]
fn rosbag2_qos_metadata_makes_tf_static_transient_local() {
    let yaml = Delivery::Static.offered_qos_profiles();
    assert!(
        yaml.starts_with("- history: 1\n  depth: 1\n  reliability: 1\n  durability: 1\n"),
        "{yaml}"
    );
    assert!(yaml.ends_with("avoid_ros_namespace_conventions: false"));
    assert!(
        Delivery::Clock
            .offered_qos_profiles()
            .contains("reliability: 2\n")
    );
    assert!(
        Delivery::Data
            .offered_qos_profiles()
            .contains("depth: 10\n  reliability: 1\n  durability: 2\n")
    );
    assert_eq!(StepTopic::TfStatic.delivery(), Delivery::Static);
    assert_eq!(StepTopic::TfStatic.name(""), "/tf_static");
}
