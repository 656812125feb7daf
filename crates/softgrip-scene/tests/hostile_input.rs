//! Issue 11: scene values that f64 validation accepted but rapier (f32) cannot hold, unbounded
//! runs and silent nonsense. Each test is named after what broke on main; each now is a typed
//! error naming the field, the value and the valid range (or the pair and the depth).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};

use softgrip_scene::{DEFAULT_SCENE, Scene, SceneError};

const BASE: &str = "duration = 1.0\n[[body]]\nname = \"table\"\nkind = \"fixed\"\n";
const TIP: &str =
    "[[fingertip]]\nname = \"t\"\nbody = \"jaw\"\nradius = 0.01\npreset = \"dragon-skin-30\"\n";

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, "test.toml", Path::new("."))
}

/// The field an error names (`Invalid`), asserted with a fragment of its message.
fn invalid(text: &str, field: &str, fragment: &str) {
    let err = parse(text).unwrap_err();
    assert_eq!(err.field(), Some(field), "{err}");
    assert!(err.to_string().contains(fragment), "{err}");
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softgrip-hostile-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A scene with one body of `kind` carrying the mesh `file` as a shape of `shape`.
fn mesh_scene(kind: &str, shape: &str, file: &str, obj: &str) -> Result<Scene, SceneError> {
    let d = dir(file);
    std::fs::write(d.join(file), obj).unwrap();
    let text = format!(
        "{BASE}[[body]]\nname = \"m\"\nkind = \"{kind}\"\n[[body.shape]]\ntype = \"{shape}\"\nfile = \"{file}\"\n"
    );
    let r = Scene::parse(&text, "mesh.toml", &d);
    std::fs::remove_dir_all(&d).ok();
    r
}

fn mesh_message(r: Result<Scene, SceneError>) -> String {
    match r {
        Err(SceneError::Mesh { message, .. }) => message,
        Err(e) => panic!("expected a mesh error, got {e}"),
        Ok(_) => panic!("expected a mesh error, got a scene"),
    }
}

const TET: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

#[test]
fn nan_vertex_on_a_kinematic_triangle_mesh_is_an_error_not_a_panic() {
    // Was a panic in parry: "The loosening margin must be non-negative".
    let obj = TET.replace("v 0 0 1", "v nan 0 1");
    let m = mesh_message(mesh_scene("kinematic", "triangle_mesh", "nan.obj", &obj));
    assert!(m.contains("vertex 3") && m.contains("finite"), "{m}");
}

#[test]
fn inf_and_1e300_mesh_vertices_are_errors() {
    for (v, name) in [
        ("inf", "inf.obj"),
        ("1e300", "big.obj"),
        ("1e39", "f32.obj"),
    ] {
        let obj = TET.replace("v 0 1 0", &format!("v 0 {v} 0"));
        let m = mesh_message(mesh_scene("fixed", "triangle_mesh", name, &obj));
        assert!(m.contains("vertex 2"), "{v}: {m}");
    }
}

#[test]
fn degenerate_triangle_is_an_error() {
    let obj = format!("{TET}f 1 1 2\n");
    let m = mesh_message(mesh_scene("fixed", "triangle_mesh", "degen.obj", &obj));
    assert!(m.contains("triangle 4") && m.contains("degenerate"), "{m}");
    // Collinear corners too.
    let obj = "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
    let m = mesh_message(mesh_scene("fixed", "triangle_mesh", "line.obj", obj));
    assert!(m.contains("triangle 0"), "{m}");
}

#[test]
fn coplanar_convex_mesh_is_an_error() {
    // The error text promised "a non-degenerate hull"; a flat one ran without a word.
    let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    let m = mesh_message(mesh_scene("dynamic", "convex_mesh", "flat.obj", obj));
    assert!(m.contains("non-degenerate hull"), "{m}");
    assert!(mesh_scene("dynamic", "convex_mesh", "tet.obj", TET).is_ok());
}

#[test]
fn fingertip_radius_1e39_is_an_error_not_a_panic() {
    let text = format!("{BASE}[[body]]\nname = \"jaw\"\nkind = \"kinematic\"\n{TIP}");
    let err = parse(&text.replace("radius = 0.01", "radius = 1e39")).unwrap_err();
    assert_eq!(err.field(), Some("fingertip[0]"));
    assert!(
        err.to_string()
            .contains("`radius` must be in [1e-9, 1e3] m, got 1e39"),
        "{err}"
    );
}

#[test]
fn positions_half_extents_and_gravity_of_1e39_are_errors() {
    let body = "[[body]]\nname = \"b\"\nkind = \"dynamic\"\n";
    invalid(
        &format!("{BASE}{body}position = [1e39, 0.0, 0.0]\n"),
        "body[1].position",
        "within ±1e5 m",
    );
    invalid(
        &format!(
            "{BASE}{body}[[body.shape]]\ntype = \"cuboid\"\nhalf_extents = [1e39, 0.1, 0.1]\n"
        ),
        "body[1].shape[0].half_extents[0]",
        "in [1e-7, 1e4] m",
    );
    invalid(
        &format!("{BASE}{body}[[body.shape]]\ntype = \"ball\"\nradius = 1e-50\n"),
        "body[1].shape[0].radius",
        "got 1e-50",
    );
    invalid(
        "duration = 1.0\ngravity = [0.0, -1e39, 0.0]\n",
        "gravity",
        "magnitude <= 1e4",
    );
    invalid(
        &format!("{BASE}{body}[[body.shape]]\ntype = \"ball\"\nradius = 0.1\ndensity = 1e39\n"),
        "body[1].shape[0].density",
        "kg/m^3",
    );
}

#[test]
fn rotation_1e20_is_an_error_not_nan_poses() {
    let text =
        format!("{BASE}[[body]]\nname = \"b\"\nkind = \"dynamic\"\nrotation = [1e20, 0.0, 0.0]\n");
    invalid(&text, "body[1].rotation", "angle <= 100 rad");
}

#[test]
fn four_component_gravity_is_an_error_not_truncated() {
    let err = parse("duration = 1.0\ngravity = [0.0, -9.81, 0.0, 5.0]\n").unwrap_err();
    assert!(matches!(err, SceneError::Parse { line: 2, .. }), "{err}");
    assert!(
        err.to_string().contains("exactly 3 components, got 4"),
        "{err}"
    );
    let err = parse("duration = 1.0\ngravity = [0.0, -9.81]\n").unwrap_err();
    assert!(
        err.to_string().contains("exactly 3 components, got 2"),
        "{err}"
    );
    let jaws = DEFAULT_SCENE.replace(
        "jaws = [\"left_jaw\", \"right_jaw\"]",
        "jaws = [\"left_jaw\", \"right_jaw\", \"table\"]",
    );
    // Any number of jaws (issue 25): a third jaw is checked as a jaw, not dropped.
    let err = parse(&jaws).unwrap_err();
    assert!(err.to_string().contains("`gripper.jaws[2]`"), "{err}");
    let axes = DEFAULT_SCENE.replace(
        "axis = [1.0, 0.0, 0.0]",
        "axes = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0, 0.0]]",
    );
    let err = parse(&axes).unwrap_err();
    assert!(
        err.to_string().contains("exactly 3 components, got 4"),
        "{err}"
    );
    let axes = DEFAULT_SCENE.replace(
        "axis = [1.0, 0.0, 0.0]",
        "axes = [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]",
    );
    let err = parse(&axes).unwrap_err();
    assert!(err.to_string().contains("2 jaws, 3 axes"), "{err}");
}

#[test]
fn dt_1e_50_is_an_error_not_a_run_of_2_pow_64_steps() {
    invalid("duration = 1.0\ndt = 1e-50\n", "dt", "in [1e-9, 1e0] s");
    invalid("duration = 1.0\ndt = 1e308\n", "dt", "got 1e308");
}

#[test]
fn duration_1e9_is_past_the_step_cap_naming_dt_and_duration() {
    let err = parse("duration = 1e9\n").unwrap_err();
    let SceneError::TooManySteps {
        steps, max_steps, ..
    } = &err
    else {
        panic!("expected the step cap, got {err}");
    };
    assert_eq!(*max_steps, softgrip_scene::DEFAULT_MAX_STEPS);
    assert_eq!(*steps, 6e10);
    let m = err.to_string();
    assert!(
        m.contains("`duration` = 1000000000 s") && m.contains("`dt` = 0.016666"),
        "{m}"
    );
    assert!(
        m.contains("cap of 10000000") && m.contains("max_steps = "),
        "{m}"
    );
    // The documented way to raise it.
    let long = parse("duration = 1e9\nmax_steps = 100_000_000_000\n").unwrap();
    assert_eq!(long.steps(), 60_000_000_000);
    invalid("duration = 1.0\nmax_steps = 0\n", "max_steps", ">= 1");
}

#[test]
fn dt_10_longer_than_duration_5_is_an_error() {
    // Simulated 10 s for a 5 s scene; dt is now capped at 1 s, and dt <= duration.
    invalid("duration = 5.0\ndt = 10.0\n", "dt", "in [1e-9, 1e0] s");
    invalid(
        "duration = 0.2\ndt = 0.5\n",
        "duration",
        "finite and >= `dt` = 0.5 s",
    );
}

#[test]
fn squeeze_depth_past_the_law_validity_is_an_error() {
    // depth = 11 mm > R = 10 mm ran (x = 1.10, 16 kN on a 32 g box).
    let text = DEFAULT_SCENE.replace("depth = 0.002", "depth = 0.011");
    let err = parse(&text).unwrap_err();
    assert_eq!(err.field(), Some("gripper.squeeze.depth"), "{err}");
    let m = err.to_string();
    assert!(
        m.contains("within the law's validity for `left_tip`") && m.contains("(0 <= x <= "),
        "{m}"
    );
    // Within the range it runs: 0.9 of the pads' own (flat) law's range (a free sphere's
    // reached x = 0.5; the bonded pad's law ends earlier, where its FE stops).
    let law = parse(DEFAULT_SCENE).unwrap().fingertips()[0].law().clone();
    let depth = 0.9 * law.delta_max();
    let text = DEFAULT_SCENE.replace("depth = 0.002", &format!("depth = {depth}"));
    assert!(parse(&text).is_ok(), "depth {depth} m");
}

#[test]
fn fingertip_starting_deep_inside_the_box_is_an_error_naming_the_pair() {
    // The jaw started inside the box: 44 kN at x = 1.52.
    let text = DEFAULT_SCENE.replace(
        "position = [-0.034, 0.02, 0.0]",
        "position = [-0.015, 0.02, 0.0]",
    );
    let err = parse(&text).unwrap_err();
    let SceneError::StartPenetration {
        fingertip,
        other,
        depth,
        x,
        ..
    } = &err
    else {
        panic!("expected a start penetration, got {err}");
    };
    assert_eq!(fingertip, "fingertip[0] (`left_tip`)");
    assert_eq!(other, "body[1].shape[0] (`box`)");
    // The ball (R = 10 mm) at x = -15 mm reaches x = -5 mm: 15 mm into the box face at -20 mm.
    assert!(
        (depth - 0.015).abs() < 1e-6 && (x - 1.5).abs() < 1e-4,
        "{err}"
    );
    // Touching, or within the law's validity, is allowed (the plugin pushes out through the law).
    let shallow = DEFAULT_SCENE.replace(
        "position = [-0.034, 0.02, 0.0]",
        "position = [-0.029, 0.02, 0.0]",
    );
    assert!(parse(&shallow).is_ok());
}

#[test]
fn dev_zero_as_scene_mesh_or_curve_is_a_size_error_not_an_oom() {
    let zero = Path::new("/dev/zero");
    if !zero.exists() {
        return;
    }
    let err = Scene::from_file(zero).err().unwrap();
    assert!(
        matches!(err, SceneError::TooLarge { what: "scene", .. }),
        "{err}"
    );
    assert!(
        err.to_string().contains("larger than the 16 MiB limit"),
        "{err}"
    );
    let text = format!(
        "{BASE}[[body]]\nname = \"m\"\nkind = \"fixed\"\n[[body.shape]]\ntype = \"triangle_mesh\"\nfile = \"/dev/zero.stl\"\n"
    );
    let _ = text; // /dev/zero has no extension: the reader is tested directly.
    // A curve or a mesh must be a regular file (issue 26): /dev/zero is refused from its
    // metadata, before a byte is read.
    let err = softgrip_scene::read_curve(zero).unwrap_err();
    assert!(matches!(err, SceneError::Curve { .. }), "{err}");
    assert!(
        err.to_string().contains("is a device, not a regular file"),
        "{err}"
    );
    let d = dir("zero");
    let link = d.join("zero.stl");
    std::os::unix::fs::symlink(zero, &link).unwrap();
    let err = softgrip_scene::load_mesh(&link).unwrap_err();
    assert!(matches!(err, SceneError::Mesh { .. }), "{err}");
    assert!(
        err.to_string().contains("is a device, not a regular file"),
        "{err}"
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn poisson_ratio_minus_one_message_names_the_field_once() {
    // Was "`fingertip[0].material` must be `poisson_ratio` must be in (-1, 0.5], got -1".
    let text = format!(
        "{BASE}[[body]]\nname = \"jaw\"\nkind = \"kinematic\"\n[[fingertip]]\nname = \"t\"\nbody = \"jaw\"\nradius = 0.01\nmaterial = {{ youngs_modulus = 1e6, poisson_ratio = -1.0 }}\n"
    );
    let err = parse(&text).unwrap_err();
    assert_eq!(err.field(), Some("fingertip[0].material.poisson_ratio"));
    let m = err.to_string();
    assert_eq!(m.matches("must be").count(), 1, "{m}");
    assert!(m.ends_with("got -1.0"), "{m}");
}
