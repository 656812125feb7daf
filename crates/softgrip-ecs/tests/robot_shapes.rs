//! Every robot link's collision shapes reach the recorder in the link's own frame (issue 25,
//! item 5, "every link's collision shapes drawn in its own tf frame"), one per collider, none
//! dropped: a URDF `<box>`, `<sphere>`, `<cylinder>` and `<capsule>` (a capsule has no Marker
//! type: it is drawn as a triangle mesh of its surface; before session 15 it was left out, so
//! such a link was simulated but invisible in Foxglove).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_ecs::{Scene, scene_info};
use softgrip_record::ShapeGeometry;

const URDF: &str = r#"<robot name="shapes">
  <link name="base"><inertial><mass value="1"/><inertia ixx="1e-3" ixy="0" ixz="0" iyy="1e-3" iyz="0" izz="1e-3"/></inertial>
    <collision><geometry><box size="0.04 0.04 0.02"/></geometry></collision>
    <collision><origin xyz="0 0 0.03"/><geometry><sphere radius="0.01"/></geometry></collision></link>
  <link name="arm"><inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial>
    <collision><origin xyz="0 0 -0.05"/><geometry><capsule radius="0.01" length="0.06"/></geometry></collision>
    <collision><origin xyz="0 0 -0.12"/><geometry><cylinder radius="0.008" length="0.02"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 -0.02"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="2"/></joint>
</robot>"#;

#[test]
fn every_link_shape_is_drawn_in_its_link_frame_capsules_as_meshes() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("shapes.urdf"), URDF).unwrap();
    let path = dir.path().join("scene.toml");
    std::fs::write(
        &path,
        "duration = 0.1\n[[robot]]\nname = \"r\"\nurdf = \"shapes.urdf\"\n",
    )
    .unwrap();
    let scene = Scene::from_file(&path).unwrap();
    let colliders: usize = (scene.robots()[0].rapier().links.iter())
        .map(|l| l.colliders.len())
        .sum();
    assert_eq!(colliders, 4);
    let info = scene_info(&scene);
    let shapes: Vec<_> = info
        .shapes
        .iter()
        .filter(|s| s.body.starts_with("r/"))
        .collect();
    let kinds: Vec<(&str, &str)> = (shapes.iter())
        .map(|s| {
            let kind = match &s.geometry {
                ShapeGeometry::Cuboid { .. } => "cuboid",
                ShapeGeometry::Ball { .. } => "ball",
                ShapeGeometry::Cylinder { .. } => "cylinder",
                ShapeGeometry::Mesh { .. } => "mesh",
                ShapeGeometry::Plane { .. } => "plane",
            };
            (s.body.as_str(), kind)
        })
        .collect();
    assert_eq!(
        kinds,
        [
            ("r/base", "cuboid"),
            ("r/base", "ball"),
            ("r/arm", "mesh"),
            ("r/arm", "cylinder")
        ]
    );
    // The capsule's mesh: its surface in the link frame, along its axis (URDF z) from
    // -0.05 - 0.03 - 0.01 to -0.05 + 0.03 + 0.01, radius 0.01 around it (f32).
    let capsule = shapes[2];
    let ShapeGeometry::Mesh {
        vertices,
        triangles,
    } = &capsule.geometry
    else {
        unreachable!()
    };
    assert!(triangles.len() > 100, "{} triangles", triangles.len());
    let at = |v: &[f64; 3]| {
        let p = softgrip_ecs::softgrip_rapier::rapier3d::prelude::Vector::new(
            v[0] as f32,
            v[1] as f32,
            v[2] as f32,
        );
        let q = capsule.rotation.map(|c| c as f32);
        let r = softgrip_ecs::softgrip_rapier::rapier3d::prelude::Rotation::from_xyzw(
            q[0], q[1], q[2], q[3],
        );
        let w = r * p;
        [0, 1, 2].map(|i| capsule.offset[i] + w[i] as f64)
    };
    let world: Vec<[f64; 3]> = vertices.iter().map(at).collect();
    let (lo, hi) = world.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| {
        (lo.min(p[2]), hi.max(p[2]))
    });
    assert!(
        (lo + 0.09).abs() < 1e-6 && (hi + 0.01).abs() < 1e-6,
        "z from {lo} to {hi}"
    );
    let radial = world
        .iter()
        .map(|p| p[0].hypot(p[1]))
        .fold(0.0f64, f64::max);
    assert!((radial - 0.01).abs() < 1e-6, "radius {radial}");
}
