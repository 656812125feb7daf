//! A user's own URDF (issue 25, "other hands' URDFs"): unusual but valid models load and run
//! 50 steps with finite link poses in both joint models; hostile ones are a
//! [`SceneError::Urdf`] naming the scene field, the URDF file, the link or joint, the value and
//! the valid range; never a panic, a hang, NaN or a silent wrong load. Every URDF and mesh is
//! written here, into a fresh folder.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_scene::robot::JointKind;
use softgrip_scene::{PlainRun, Scene, SceneError};

/// `<inertial>` of `mass` kg with a diagonal inertia `i` kg m^2.
fn inertial(mass: &str, i: &str) -> String {
    format!(
        r#"<inertial><mass value="{mass}"/><inertia ixx="{i}" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="{i}"/></inertial>"#
    )
}

/// A link with an inertial and a 1 x 1 x 10 cm box hanging below its origin.
fn link(name: &str) -> String {
    format!(
        r#"<link name="{name}">{}<collision><origin xyz="0 0 -0.05"/><geometry><box size="0.01 0.01 0.1"/></geometry></collision></link>"#,
        inertial("0.1", "1e-4")
    )
}

/// A joint of `kind` from `parent` to `child` about y, limits +-1, 0.05 m below the parent's
/// origin, with `extra` XML inside.
fn joint(name: &str, kind: &str, parent: &str, child: &str, extra: &str) -> String {
    format!(
        r#"<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/><origin xyz="0 0 -0.1"/><axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="5" velocity="2"/>{extra}</joint>"#
    )
}

fn robot(parts: &[String]) -> String {
    format!("<robot name=\"t\">{}</robot>", parts.concat())
}

/// A 1 cm tetrahedron (OBJ).
const TETRA: &str =
    "v 0 0 0\nv 0.01 0 0\nv 0 0.01 0\nv 0 0 0.01\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

/// A one-link robot whose collision is the mesh `filename` (scale `scale`).
fn mesh_robot(filename: &str, scale: &str) -> String {
    format!(
        r#"<robot name="m"><link name="base">{}<collision><geometry><mesh filename="{filename}"{scale}/></geometry></collision></link></robot>"#,
        inertial("1", "1e-4")
    )
}

/// Loads a scene of one robot (`urdf` written next to it with `files`, `extra` lines in its
/// `[[robot]]`), gravity on, base fixed.
fn load(urdf: &str, extra: &str, files: &[(&str, &[u8])]) -> Result<Scene, SceneError> {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("robot.urdf"), urdf).unwrap();
    for (name, bytes) in files {
        let p = dir.path().join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
    let base = if extra.contains("base =") {
        ""
    } else {
        "base = \"fixed\"\n"
    };
    let scene = format!(
        "duration = 0.1\ngravity = [0.0, 0.0, -9.81]\n[[robot]]\nname = \"r\"\nurdf = \"robot.urdf\"\n{base}{extra}\n"
    );
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, scene).unwrap();
    Scene::from_file(&path)
}

/// Runs 50 steps of `scene` and returns every link's position after them; each must be finite.
fn run_50(scene: &Scene) -> Vec<[f32; 3]> {
    let mut run = PlainRun::new(scene);
    run.run(50, |_| {});
    let links = &run.handles.robots[0].1.links;
    let out: Vec<[f32; 3]> = links
        .iter()
        .map(|h| {
            let t = run.world.physics.bodies[*h].translation();
            [t.x, t.y, t.z]
        })
        .collect();
    for (i, p) in out.iter().enumerate() {
        assert!(p.iter().all(|c| c.is_finite()), "link {i} at {p:?}");
    }
    out
}

/// Loads and runs `urdf` in both joint models; returns the multibody scene.
fn loads_and_runs(urdf: &str, extra: &str, files: &[(&str, &[u8])]) -> Scene {
    for model in ["impulse", "multibody"] {
        let scene = load(urdf, &format!("joints = \"{model}\"\n{extra}"), files)
            .unwrap_or_else(|e| panic!("{model}: {e}"));
        run_50(&scene);
    }
    load(urdf, extra, files).unwrap()
}

/// The error of loading `urdf`: a [`SceneError::Urdf`] on `robot[0].urdf` whose text holds
/// every one of `want`.
fn urdf_error(urdf: &str, files: &[(&str, &[u8])], want: &[&str]) {
    let Err(e) = load(urdf, "", files) else {
        panic!("loaded: {urdf}");
    };
    let text = e.to_string();
    assert!(
        matches!(&e, SceneError::Urdf { field, path, .. }
            if field == "robot[0].urdf" && path.ends_with("robot.urdf")),
        "not a URDF error on robot[0].urdf: {e:?}"
    );
    assert!(text.contains("robot.urdf"), "{text}");
    for w in want {
        assert!(text.contains(w), "`{w}` not in: {text}");
    }
}

#[test]
fn continuous_joints_load_without_limits_and_run() {
    let urdf = robot(&[
        link("a"),
        link("b"),
        joint("spin", "continuous", "a", "b", ""),
    ]);
    let scene = loads_and_runs(&urdf, "initial = { spin = 7.0 }", &[]);
    let j = &scene.robots()[0].joints()[0];
    assert_eq!(j.kind, JointKind::Continuous);
    assert_eq!(j.limits, [f64::NEG_INFINITY, f64::INFINITY]);
    assert_eq!(j.initial, 7.0, "a continuous joint starts past 2 pi");
}

#[test]
fn floating_and_planar_joints_are_errors_naming_the_joint_and_the_types_supported() {
    for kind in ["floating", "planar"] {
        let urdf = robot(&[link("a"), link("b"), joint("free", kind, "a", "b", "")]);
        let shown = if kind == "floating" {
            "Floating"
        } else {
            "Planar"
        };
        urdf_error(
            &urdf,
            &[],
            &[
                "joint `free`",
                shown,
                "revolute, continuous, prismatic, fixed",
            ],
        );
    }
}

#[test]
fn a_limit_lower_than_upper_is_an_error_naming_both_values() {
    for kind in ["revolute", "prismatic"] {
        let urdf = robot(&[link("a"), link("b"), joint("j", kind, "a", "b", "")])
            .replace("lower=\"-1\" upper=\"1\"", "lower=\"0.5\" upper=\"-0.5\"");
        urdf_error(
            &urdf,
            &[],
            &["joint `j`", "lower = 0.5", "upper = -0.5", "lower <= upper"],
        );
    }
}

#[test]
fn a_revolute_or_prismatic_joint_without_limit_is_an_error_naming_it() {
    for kind in ["revolute", "prismatic"] {
        let urdf = robot(&[link("a"), link("b"), joint("j", kind, "a", "b", "")]).replace(
            r#"<limit lower="-1" upper="1" effort="5" velocity="2"/>"#,
            "",
        );
        urdf_error(&urdf, &[], &["joint `j`", kind, "needs a <limit"]);
    }
    // A continuous joint needs none; a <limit> with only effort and velocity is URDF's
    // lower = upper = 0 (a locked joint), as written.
    let urdf = robot(&[link("a"), link("b"), joint("j", "continuous", "a", "b", "")]).replace(
        r#"<limit lower="-1" upper="1" effort="5" velocity="2"/>"#,
        "",
    );
    loads_and_runs(&urdf, "", &[]);
}

#[test]
fn negative_mass_or_inertia_is_an_error_naming_the_link_and_value() {
    let mass = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")]).replacen(
        "<mass value=\"0.1\"/>",
        "<mass value=\"-0.1\"/>",
        1,
    );
    urdf_error(
        &mass,
        &[],
        &["link `a` inertial", "mass", "got -0.1", "[0,"],
    );
    let inertia = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")]).replacen(
        "iyy=\"1e-4\"",
        "iyy=\"-1e-4\"",
        1,
    );
    urdf_error(
        &inertia,
        &[],
        &["link `a` inertial", "iyy", "-0.0001", ">= 0"],
    );
}

#[test]
fn an_inertia_with_a_negative_principal_moment_is_an_error() {
    // [[1, 2, 0], [2, 1, 0], [0, 0, 1]] e-4: principal moments -1, 1, 3 e-4.
    let urdf = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")]).replacen(
        r#"ixy="0""#,
        r#"ixy="2e-4""#,
        1,
    );
    urdf_error(
        &urdf,
        &[],
        &[
            "link `a` inertial",
            "ixy 0.0002",
            "principal moments",
            "must be >= 0",
        ],
    );
}

#[test]
fn zero_mass_or_a_missing_inertial_gets_the_fallback_density_and_runs() {
    // Zero mass and inertia on a link with a collision shape: its shapes get the density.
    let zero = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")])
        .replace(&inertial("0.1", "1e-4"), &inertial("0", "0"));
    let scene = loads_and_runs(&zero, "", &[]);
    assert_eq!(scene.robots()[0].link_mass(1), 0.0);
    // No <inertial> at all.
    let none = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")])
        .replace(&inertial("0.1", "1e-4"), "");
    loads_and_runs(&none, "", &[]);
}

#[test]
fn a_moving_link_with_no_mass_and_no_shape_is_an_error() {
    // Link b has an inertial of zero mass but nothing to give it one: rapier cannot move it.
    let urdf = robot(&[
        link("a"),
        r#"<link name="b"><inertial><origin xyz="0 0 -0.05"/><mass value="0"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial><visual><geometry><sphere radius="0.01"/></geometry></visual></link>"#
            .to_string(),
        joint("j", "revolute", "a", "b", ""),
    ]);
    urdf_error(&urdf, &[], &["link `b`", "mass"]);
}

#[test]
fn an_empty_link_between_two_moving_joints_is_kept_and_moves_as_written() {
    // b has no inertial, collision or visual; rapier3d-urdf keeps it (both its joints move).
    // c's origin: (0, 0, -0.1) + R_y(j1) (0, 0, -0.1) = (-0.1 sin 0.5, 0, -0.1 - 0.1 cos 0.5).
    let urdf = robot(&[
        link("a"),
        r#"<link name="b"/>"#.to_string(),
        link("c"),
        joint("j1", "revolute", "a", "b", ""),
        joint("j2", "revolute", "b", "c", ""),
    ]);
    let want = [-0.1 * 0.5_f64.sin(), 0.0, -0.1 - 0.1 * 0.5_f64.cos()];
    for model in ["multibody", "impulse"] {
        let extra = format!("joints = \"{model}\"\ninitial = {{ j1 = 0.5, j2 = -0.3 }}");
        let scene = load(&urdf, &extra, &[]).unwrap();
        let r = &scene.robots()[0];
        assert_eq!(r.links().len(), 3, "{model}");
        let mut run = PlainRun::new(&scene);
        run.run(100, |_| {});
        let h = &run.handles.robots[0].1;
        for (j, q0) in [(0, 0.5), (1, -0.3)] {
            let q = softgrip_scene::robot::joint_state(r, &run.world.physics, h, j, 1.0).position;
            assert!((q - q0).abs() < 1e-3, "{model}: joint {j} at {q}");
        }
        let p = run.world.physics.bodies[h.links[2]].translation();
        for (got, want) in [p.x, p.y, p.z].iter().zip(want) {
            assert!((f64::from(*got) - want).abs() < 1e-4, "{model}: c at {p:?}");
        }
    }
}

#[test]
fn a_link_with_no_collision_loads_and_runs() {
    let urdf = robot(&[
        link("a"),
        format!(r#"<link name="b">{}</link>"#, inertial("0.1", "1e-4")),
        joint("j", "revolute", "a", "b", ""),
    ]);
    let scene = loads_and_runs(&urdf, "", &[]);
    assert_eq!(scene.robots()[0].links().len(), 2);
    let built = scene.build();
    assert!(built.handles.robots[0].1.colliders[1].is_empty());
}

/// a -j1-> b -j2-> c -j3-> d, j2 mimics j1 (x2), j3 mimics j2 (x -1, +0.1).
fn mimic_chain(j2_mimic: &str, j3_mimic: &str) -> String {
    robot(&[
        link("a"),
        link("b"),
        link("c"),
        link("d"),
        joint("j1", "revolute", "a", "b", ""),
        joint("j2", "revolute", "b", "c", j2_mimic),
        joint("j3", "revolute", "c", "d", j3_mimic),
    ])
    .replace("lower=\"-1\" upper=\"1\"", "lower=\"-2\" upper=\"2\"")
}

/// Joint `j`'s position after 50 steps of `scene`, its joints' motor targets set first by
/// `set` (joint, position).
fn position_after_50(scene: &Scene, set: Option<(usize, f64)>, j: usize) -> (f64, PlainRun) {
    let r = &scene.robots()[0];
    let mut run = PlainRun::new(scene);
    if let Some((k, q)) = set {
        let h = &run.handles.robots[0].1;
        softgrip_scene::robot::set_joint_target(r, &mut run.world.physics, h, k, q, 0.0);
    }
    run.run(50, |_| {});
    let h = &run.handles.robots[0].1;
    let q = softgrip_scene::robot::joint_state(r, &run.world.physics, h, j, 1.0).position;
    assert!(q.is_finite());
    (q, run)
}

#[test]
fn a_mimic_of_a_mimic_follows_through_the_chain() {
    let urdf = mimic_chain(
        r#"<mimic joint="j1" multiplier="2"/>"#,
        r#"<mimic joint="j2" multiplier="-1" offset="0.1"/>"#,
    );
    for model in ["impulse", "multibody"] {
        let extra = format!("joints = \"{model}\"\ninitial = {{ j1 = 0.3 }}");
        let scene = load(&urdf, &extra, &[]).unwrap();
        let r = &scene.robots()[0];
        let j = r.joints();
        assert!((j[1].initial - 0.6).abs() < 1e-12, "{}", j[1].initial);
        assert!((j[2].initial + 0.5).abs() < 1e-12, "{}", j[2].initial);
        // j1 commanded to 0.4: j2's target 0.8, j3's 0.1 - 0.8 = -0.7.
        let (q3, run) = position_after_50(&scene, Some((0, 0.4)), 2);
        let h = &run.handles.robots[0].1;
        let target = |k| softgrip_scene::robot::joint_target(r, &run.world.physics, h, k);
        assert!(
            (target(1).unwrap().0 - 0.8).abs() < 1e-6,
            "{model}: {:?}",
            target(1)
        );
        assert!(
            (target(2).unwrap().0 + 0.7).abs() < 1e-6,
            "{model}: {:?}",
            target(2)
        );
        if model == "multibody" {
            // The couplings hold the chain: j3 = 0.1 - 2 j1 wherever j1 is.
            let q1 = softgrip_scene::robot::joint_state(r, &run.world.physics, h, 0, 1.0).position;
            assert!(
                (q3 - (0.1 - 2.0 * q1)).abs() < 1e-3,
                "j3 = {q3} for j1 = {q1}"
            );
            assert!((q1 - 0.4).abs() < 0.01, "j1 = {q1}");
        }
    }
}

#[test]
fn a_mimic_cycle_is_an_error() {
    let urdf = mimic_chain(r#"<mimic joint="j3"/>"#, r#"<mimic joint="j2"/>"#);
    urdf_error(&urdf, &[], &["mimic", "cycle", "j2", "j3"]);
}

#[test]
fn a_mimic_of_a_missing_joint_or_with_a_bad_multiplier_is_an_error() {
    let missing = mimic_chain(r#"<mimic joint="nope"/>"#, "");
    urdf_error(
        &missing,
        &[],
        &["joint `j2` mimic", "`nope`", "not a joint"],
    );
    let nan = mimic_chain(r#"<mimic joint="j1" multiplier="nan"/>"#, "");
    urdf_error(
        &nan,
        &[],
        &["joint `j2` mimic", "multiplier", "NaN", "finite"],
    );
}

#[test]
fn a_mimic_with_multiplier_zero_holds_its_joint_at_the_offset() {
    let urdf = mimic_chain(r#"<mimic joint="j1" multiplier="0" offset="0.2"/>"#, "");
    let scene = load(&urdf, "initial = { j1 = 0.5 }", &[]).unwrap();
    assert_eq!(scene.robots()[0].joints()[1].initial, 0.2);
    let (q, _) = position_after_50(&scene, Some((0, -0.5)), 1);
    assert!((q - 0.2).abs() < 1e-3, "j2 = {q}");
}

#[test]
fn a_zero_axis_is_an_error_naming_the_joint_and_value() {
    let urdf = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")])
        .replace("xyz=\"0 1 0\"", "xyz=\"0 0 0\"");
    urdf_error(
        &urdf,
        &[],
        &["joint `j`", "axis", "[0.0, 0.0, 0.0]", "non-zero"],
    );
}

#[test]
fn a_closed_loop_duplicate_names_and_empty_robots_are_errors() {
    // Link c is the child of two joints (a loop a-b-c-a).
    let lp = robot(&[
        link("a"),
        link("b"),
        link("c"),
        joint("j1", "revolute", "a", "b", ""),
        joint("j2", "revolute", "b", "c", ""),
        joint("j3", "revolute", "a", "c", ""),
    ]);
    urdf_error(
        &lp,
        &[],
        &["joint `j3`", "link `c`", "already the child of joint `j2`"],
    );
    let dup = robot(&[link("a"), link("a")]);
    urdf_error(&dup, &[], &["link `a` is defined twice"]);
    urdf_error("<robot name=\"e\"></robot>", &[], &["has no <link>"]);
    urdf_error("<robot name=\"e\"/>", &[], &["has no <link>"]);
    urdf_error("this is not XML {", &[], &["not a URDF robot"]);
    urdf_error(
        "<scene><link name=\"a\"/></scene>",
        &[],
        &["not a URDF robot"],
    );
    urdf_error("", &[], &["not a URDF robot"]);
    // A malformed number (pybullet_data's biped2d_pybullet.urdf has `lower="-1.57."`): the
    // parser does not say where; the error does.
    let bad = robot(&[link("a"), link("b"), joint("j", "revolute", "a", "b", "")])
        .replace("lower=\"-1\"", "lower=\"-1.57.\"");
    urdf_error(
        &bad,
        &[],
        &["line 1: <limit lower=\"-1.57.\">: expected a number"],
    );
}

#[test]
fn unsupported_empty_and_badly_scaled_meshes_are_errors_naming_the_file() {
    let tetra: &[u8] = TETRA.as_bytes();
    let cases: [(&str, &str, &[u8], &[&str]); 8] = [
        (
            "m.ply",
            "",
            b"ply\nformat ascii 1.0\nend_header\n",
            &["m.ply", "cannot load"],
        ),
        (
            "m.obj",
            "",
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\n",
            &["m.obj", "no"],
        ),
        ("m.stl", "", b"solid x\nendsolid x\n", &["m.stl", "no"]),
        // As pybullet_data/random_urdfs/168/168.obj (Blender export of NaN vertices).
        (
            "m.obj",
            "",
            b"v nan nan nan\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n",
            &["m.obj", "mesh 0: vertex 0 is not finite: [NaN, NaN, NaN]"],
        ),
        (
            "m.obj",
            " scale=\"1e30 1e30 1e30\"",
            tetra,
            &["m.obj", "scale", "1e30"],
        ),
        (
            "m.obj",
            " scale=\"1e-30 1 1\"",
            tetra,
            &["m.obj", "scale", "1e-30"],
        ),
        (
            "m.obj",
            " scale=\"1e-6 1e-6 1e-6\"",
            tetra,
            &["m.obj", "1.000e-8 m across", "[1e-7"],
        ),
        (
            "m.obj",
            " scale=\"1e7 1e7 1e7\"",
            tetra,
            &["m.obj", "1.000e5 m across", "1e4]"],
        ),
    ];
    for (file, scale, bytes, want) in cases {
        let urdf = mesh_robot(file, scale);
        let mut want = want.to_vec();
        want.push("link `base` collision[0]");
        urdf_error(&urdf, &[(file, bytes)], &want);
    }
}

#[test]
fn a_tiny_but_valid_scale_loads_and_runs() {
    // 1 cm * 1e-3 = 10 um: small but a solid.
    let urdf = mesh_robot("m.obj", " scale=\"1e-3 1e-3 1e-3\"");
    loads_and_runs(&urdf, "", &[("m.obj", TETRA.as_bytes())]);
}

#[test]
fn an_unknown_package_is_an_error_naming_it_and_the_known_ones() {
    let urdf = mesh_robot("package://other_pkg/m.obj", "");
    let e = load(
        &urdf,
        "package_paths = { my_pkg = \".\" }",
        &[("m.obj", TETRA.as_bytes())],
    )
    .map(|_| ())
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("package `other_pkg`")
            && e.contains("[\"my_pkg\"]")
            && e.contains("link `base`"),
        "{e}"
    );
}

#[test]
fn a_dynamic_base_without_mass_is_an_error_naming_the_field() {
    // A visual-only root: rapier would hold a massless dynamic body still (it did not fall).
    let urdf = robot(&[
        r#"<link name="a"><visual><geometry><sphere radius="0.01"/></geometry></visual></link>"#
            .to_string(),
    ]);
    for model in ["multibody", "impulse"] {
        let e = load(
            &urdf,
            &format!("base = \"dynamic\"\njoints = \"{model}\""),
            &[],
        )
        .map(|_| ())
        .unwrap_err();
        assert_eq!(e.field(), Some("robot[0].base"), "{e}");
        assert!(e.to_string().contains("link `a` has none"), "{e}");
    }
    // With a mass it falls: 50 steps of dt = 1/60 s in N substeps of h under
    // 9.81 m/s^2, rapier's symplectic Euler: z = -g h^2 N (N + 1) / 2.
    let heavy = robot(&[format!(
        r#"<link name="a">{}</link>"#,
        inertial("1", "1e-3")
    )]);
    let scene = load(&heavy, "base = \"dynamic\"", &[]).unwrap();
    let mut run = PlainRun::new(&scene);
    run.run(50, |_| {});
    let z = run.world.physics.bodies[run.handles.robots[0].1.links[0]]
        .translation()
        .z;
    // The plugin's substeps times rapier's (its solver iterations are substeps).
    let iterations = run
        .world
        .physics
        .integration_parameters
        .num_solver_iterations;
    let n = (run.world.soft.counters().substeps_total * iterations as u64) as f64;
    let h = 50.0 / 60.0 / n;
    let want = -9.81 * h * h * n * (n + 1.0) / 2.0;
    assert!((f64::from(z) - want).abs() < 1e-3, "z = {z}, want {want}");
}

#[test]
fn a_multibody_of_more_joints_than_rapier_solves_in_time_is_an_error() {
    // A chain of 300 revolute joints: over the cap as a multibody, fine with impulse joints.
    let n = softgrip_scene::robot::MAX_MULTIBODY_JOINTS + 44;
    let mut parts: Vec<String> = (0..=n).map(|i| link(&format!("l{i}"))).collect();
    for i in 1..=n {
        let (p, c) = (format!("l{}", i - 1), format!("l{i}"));
        parts.push(joint(&format!("j{i}"), "revolute", &p, &c, ""));
    }
    let urdf = robot(&parts);
    let e = load(&urdf, "", &[]).map(|_| ()).unwrap_err();
    assert_eq!(e.field(), Some("robot[0].joints"), "{e}");
    assert!(e.to_string().contains("with 300 moving joints"), "{e}");
    assert!(e.to_string().contains("at most 256 moving joints"), "{e}");
    let scene = load(&urdf, "joints = \"impulse\"", &[]).unwrap();
    assert_eq!(scene.robots()[0].joints().len(), 300);
}

/// A chain of `n` revolute links below the fixed base, with a fingertip on its last link
/// (`extra` lines in the `[[robot]]`).
fn padded_chain(n: usize, extra: &str) -> Result<Scene, SceneError> {
    let mut parts: Vec<String> = (0..=n).map(|i| link(&format!("l{i}"))).collect();
    for i in 1..=n {
        let (p, c) = (format!("l{}", i - 1), format!("l{i}"));
        parts.push(joint(&format!("j{i}"), "revolute", &p, &c, ""));
    }
    let pad = format!(
        "{extra}\n[[fingertip]]\nname = \"pad\"\nlink = \"r/l{n}\"\noffset = [0.0, 0.0, -0.12]\n\
         radius = 0.008\npreset = \"dragon-skin-30\"\n"
    );
    load(&robot(&parts), &pad, &[])
}

#[test]
fn a_pad_the_solve_cannot_see_through_impulse_joints_is_an_error_naming_the_link() {
    // Ten moving links held together by impulse joints: more than the 8 bodies of an
    // assembly the contact solve reads, so it would take the padded link as a free body.
    let e = padded_chain(10, "joints = \"impulse\"")
        .map(|_| ())
        .unwrap_err();
    assert!(
        matches!(e, SceneError::JointedUnseen { needed: None, .. }),
        "{e:?}"
    );
    assert_eq!(e.field(), Some("robot[0].joints"), "{e}");
    let text = e.to_string();
    assert!(text.contains("link `l10`"), "{text}");
    assert!(text.contains("more than 8 bodies"), "{text}");
    assert!(text.contains("joints = \"multibody\""), "{text}");
    // The same chain as a multibody (the default) loads and runs; two links with impulse
    // joints are an assembly the solve reads.
    run_50(&padded_chain(10, "").unwrap());
    run_50(&padded_chain(2, "joints = \"impulse\"").unwrap());
}

#[test]
fn a_pad_whose_joints_would_need_more_sweeps_than_given_is_an_error_saying_how_many() {
    // A 1 g proximal link carrying a 10 kg distal one: rapier's sweeps over the two hinges
    // converge so slowly that the solve would need millions per solver pass.
    let l = |name: &str, m: &str, i: &str| {
        format!(
            r#"<link name="{name}">{}<collision><origin xyz="0 0 -0.05"/><geometry><box size="0.01 0.01 0.1"/></geometry></collision></link>"#,
            inertial(m, i)
        )
    };
    let parts = [
        link("l0"),
        l("l1", "0.001", "1e-7"),
        l("l2", "10", "1e-1"),
        joint("j1", "revolute", "l0", "l1", ""),
        joint("j2", "revolute", "l1", "l2", ""),
    ];
    let pad = "[[fingertip]]\nname = \"pad\"\nlink = \"r/l2\"\noffset = [0.0, 0.0, -0.12]\n\
               radius = 0.008\npreset = \"dragon-skin-30\"\n";
    let e = load(&robot(&parts), &format!("joints = \"impulse\"\n{pad}"), &[])
        .map(|_| ())
        .unwrap_err();
    let SceneError::JointedUnseen {
        needed: Some(n),
        max,
        ..
    } = e
    else {
        panic!("{e:?}");
    };
    assert_eq!(max, softgrip_scene::robot::MAX_JOINTED_SWEEPS);
    assert!(n > 1_000_000, "{n}");
    let text = e.to_string();
    assert!(
        text.contains(&format!("would need {n} Gauss-Seidel sweeps")),
        "{text}"
    );
    assert!(
        text.contains("link `l2`") && text.contains("at most 4096"),
        "{text}"
    );
    // As a multibody the same finger loads and runs.
    run_50(&load(&robot(&parts), pad, &[]).unwrap());
}
