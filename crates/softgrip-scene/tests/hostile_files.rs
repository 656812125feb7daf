//! Issue 26, the second round of hostile inputs on scene files: what broke on main, one test
//! each. A byte-order mark before an OBJ's first line lost its first vertex (the geometry
//! changed); a FIFO named as a mesh or a curve blocked forever; a body named `world` made the
//! tf frame `world -> world`; a tactile pad's `direction` and `up` dropped a fourth component;
//! `core_thickness = 1e-22` was accepted (the law's force was negative); a backed pad buried
//! past the box's centre ran while a shallower one was refused; a 1e-300 m tactile pad
//! recorded NaN pressures; and messages printed 1e300 as a 301-digit number.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

use softgrip_scene::{
    DEFAULT_SCENE, Scene, SceneError, UTF8_BOM, load_mesh, parse_obj, parse_stl, read_curve,
};

const BASE: &str = "duration = 1.0\n[[body]]\nname = \"table\"\nkind = \"fixed\"\n";
const TET: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const CURVE: &str = "delta_m,force_n\n0.0005,0.4\n0.001,1.2\n0.002,3.5\n0.003,6.8\n";

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softgrip-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn bom(text: &str) -> Vec<u8> {
    [UTF8_BOM, text.as_bytes()].concat()
}

/// A scene with a fixed body carrying the mesh `file` and a fingertip whose level is the
/// measured curve `curve` (both relative to the scene's folder).
fn files_scene(file: &str, curve: &str) -> String {
    format!(
        "{BASE}[[body]]\nname = \"m\"\nkind = \"fixed\"\n[[body.shape]]\ntype = \"triangle_mesh\"\nfile = \"{file}\"\n\
         [[body]]\nname = \"jaw\"\nkind = \"kinematic\"\nposition = [0.0, 5.0, 0.0]\n\
         [[fingertip]]\nname = \"t\"\nbody = \"jaw\"\nradius = 0.01\npreset = \"dragon-skin-30\"\nlevel = {{ tabulated = \"{curve}\" }}\n"
    )
}

#[test]
fn obj_with_a_byte_order_mark_kept_its_first_vertex() {
    let plain = parse_obj(TET).unwrap();
    let text = String::from_utf8(bom(TET)).unwrap();
    assert_eq!(parse_obj(&text).unwrap(), plain);
    let d = dir("bom");
    std::fs::write(d.join("tet.obj"), bom(TET)).unwrap();
    let m = load_mesh(&d.join("tet.obj")).unwrap();
    assert_eq!(m.vertices.len(), 4);
    assert_eq!(m.vertices[0], [0.0, 0.0, 0.0]);
    assert_eq!(m, plain);
    // ASCII STL too (a binary STL's header is not text and is left alone).
    let stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n\
               endloop\nendfacet\nendsolid t\n";
    assert_eq!(
        parse_stl(&bom(stl)).unwrap(),
        parse_stl(stl.as_bytes()).unwrap()
    );
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn curve_csv_and_scene_toml_with_a_byte_order_mark_read_as_without() {
    let d = dir("bomcsv");
    std::fs::write(d.join("plain.csv"), CURVE).unwrap();
    std::fs::write(d.join("bom.csv"), bom(CURVE)).unwrap();
    let (a, b) = (
        read_curve(&d.join("plain.csv")).unwrap(),
        read_curve(&d.join("bom.csv")).unwrap(),
    );
    assert_eq!((a.delta_m, a.force_n), (b.delta_m, b.force_n));
    std::fs::write(d.join("bom.toml"), bom(DEFAULT_SCENE)).unwrap();
    let (scene, text) = Scene::from_file_with_text(&d.join("bom.toml")).unwrap();
    assert_eq!(text, DEFAULT_SCENE, "the text as read, without the mark");
    assert_eq!(scene.file(), Scene::default_scene().file());
    let with_mark = String::from_utf8(bom(DEFAULT_SCENE)).unwrap();
    let parsed = Scene::parse(&with_mark, "bom.toml", Path::new(".")).unwrap();
    assert_eq!(parsed.file(), scene.file());
    std::fs::remove_dir_all(&d).ok();
}

/// `f` on another thread; its result within `secs`, or a failure saying it blocked.
fn within<T: Send + 'static>(secs: u64, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || tx.send(f()).ok());
    rx.recv_timeout(Duration::from_secs(secs))
        .expect("blocked: a non-regular file was opened for reading")
}

#[test]
fn fifo_as_mesh_or_curve_is_refused_instead_of_blocking() {
    let d = dir("fifo");
    std::fs::write(d.join("tet.obj"), TET).unwrap();
    std::fs::write(d.join("tip.csv"), CURVE).unwrap();
    for name in ["pipe.obj", "pipe.csv"] {
        let made = std::process::Command::new("mkfifo")
            .arg(d.join(name))
            .status()
            .unwrap();
        assert!(made.success());
    }
    std::fs::create_dir(d.join("folder.obj")).unwrap();
    std::fs::create_dir(d.join("folder.csv")).unwrap();
    assert!(Scene::parse(&files_scene("tet.obj", "tip.csv"), "s.toml", &d).is_ok());
    for (mesh, curve, what) in [
        (
            "pipe.obj",
            "tip.csv",
            "a FIFO (named pipe), not a regular file",
        ),
        (
            "tet.obj",
            "pipe.csv",
            "a FIFO (named pipe), not a regular file",
        ),
        ("folder.obj", "tip.csv", "a directory, not a regular file"),
        ("tet.obj", "folder.csv", "a directory, not a regular file"),
        ("/dev/null", "tip.csv", "a device, not a regular file"),
        ("tet.obj", "/dev/zero", "a device, not a regular file"),
    ] {
        let (text, base) = (files_scene(mesh, curve), d.clone());
        let err = within(20, move || {
            Scene::parse(&text, "s.toml", &base).unwrap_err()
        });
        let m = err.to_string();
        assert!(
            matches!(err, SceneError::Mesh { .. } | SceneError::Curve { .. }),
            "{m}"
        );
        assert!(m.contains(what), "{mesh} {curve}: {m}");
        let file = if mesh == "tet.obj" { curve } else { mesh };
        assert!(m.contains(file), "names the file: {m}");
    }
    std::fs::remove_dir_all(&d).ok();
}

#[test]
fn body_named_world_made_world_to_world_on_tf_and_is_refused() {
    let text = DEFAULT_SCENE.replace("name = \"table\"", "name = \"world\"");
    let err = Scene::parse(&text, "w.toml", Path::new(".")).unwrap_err();
    assert_eq!(err.field(), Some("body[0].name"), "{err}");
    assert!(err.to_string().contains("`world` is reserved"), "{err}");
    // A fingertip may be called `world`: its frame is renamed (`world_tip`).
    let tip = DEFAULT_SCENE.replace("name = \"left_tip\"", "name = \"world\"");
    assert!(Scene::parse(&tip, "w.toml", Path::new(".")).is_ok());
}

#[test]
fn tactile_direction_and_up_with_a_fourth_component_are_refused() {
    for (from, to) in [
        (
            "direction = [1.0, 0.0, 0.0]",
            "direction = [1.0, 0.0, 0.0, 5.0]",
        ),
        ("up = [0.0, 1.0, 0.0]", "up = [0.0, 1.0, 0.0, 5.0]"),
        ("direction = [1.0, 0.0, 0.0]", "direction = [1.0, 0.0]"),
    ] {
        let text = DEFAULT_SCENE.replacen(from, to, 1);
        assert_ne!(text, DEFAULT_SCENE);
        let err = Scene::parse(&text, "t.toml", Path::new(".")).unwrap_err();
        let m = err.to_string();
        assert!(matches!(err, SceneError::Parse { .. }), "{m}");
        assert!(m.contains("expected exactly 3 components"), "{to}: {m}");
    }
}

#[test]
fn core_thickness_1e_22_is_refused_naming_the_field_value_and_range() {
    let core = |t: &str| {
        DEFAULT_SCENE.replacen(
            "backing = \"flat\" ",
            &format!("backing = \"core\"\ncore_thickness = {t}\n"),
            1,
        )
    };
    for t in ["1e-22", "1e-200", "0.0004999"] {
        let err = Scene::parse(&core(t), "c.toml", Path::new(".")).unwrap_err();
        assert_eq!(err.field(), Some("fingertip[0].core_thickness"), "{err}");
        let m = err.to_string();
        assert!(m.contains("in [0.0005 m, radius)"), "{m}");
        assert!(m.ends_with(&format!("got {t}")), "{m}");
    }
    // From t/R = 0.05 the core builds (its squeeze is then checked against its validity).
    let err = Scene::parse(&core("0.0005"), "c.toml", Path::new("."));
    assert!(err.as_ref().err().and_then(SceneError::field) != Some("fingertip[0].core_thickness"));
}

/// The default scene with the left jaw (its fingertip facing +x, towards the box) at `x`, and
/// no gripper (the jaws stay where they are put).
fn jaw_at(x: f64) -> String {
    let text = DEFAULT_SCENE.replace(
        "position = [-0.034, 0.02, 0.0]",
        &format!("position = [{x}, 0.02, 0.0]"),
    );
    let text = text.replace(
        "position = [0.034, 0.02, 0.0]",
        "position = [0.2, 0.02, 0.0]",
    );
    text[..text.find("[gripper]").unwrap()].to_string()
}

#[test]
fn backed_pad_buried_past_the_box_centre_is_refused_as_a_shallower_one() {
    // The box spans x in [-0.02, 0.02]; the tip (R = 0.01) faces +x. Its depth into the box
    // goes from 0 (pole on the box's -x face, centre at -0.03) to past the box's centre, where
    // the nearest face is +x, behind the pad: 3.1R ran on main while 2.5R was refused.
    for depth_r in [1.5, 2.0, 2.5, 2.9, 3.0001, 3.1, 3.5, 4.0, 4.9] {
        let x = -0.02 + depth_r * 0.01 - 0.01;
        let err = Scene::parse(&jaw_at(x), "b.toml", Path::new(".")).unwrap_err();
        let m = err.to_string();
        assert!(
            matches!(
                err,
                SceneError::StartPenetration { .. } | SceneError::StartBuried { .. }
            ),
            "{depth_r} R: {m}"
        );
        assert!(
            m.contains("fingertip[0] (`left_tip`)") && m.contains("`box`"),
            "{m}"
        );
    }
    // Behind the pad, with the centre outside the box, is the rigid finger's contact: allowed.
    // The centre 5 mm outside the +x face (a 0.5R overlap of the back with the box).
    assert!(Scene::parse(&jaw_at(0.025), "b.toml", Path::new(".")).is_ok());
    // The centre inside the box from behind (1.5R): refused, naming the depth and R.
    let err = Scene::parse(&jaw_at(0.015), "b.toml", Path::new(".")).unwrap_err();
    assert!(matches!(err, SceneError::StartBuried { .. }), "{err}");
    assert!(
        err.to_string().contains("more than its radius R = 0.01 m"),
        "{err}"
    );
}

#[test]
fn tactile_pad_of_1e_300_m_is_refused_naming_its_size() {
    for (from, to, field) in [
        (
            "width = 0.016 ",
            "width = 1e-300 ",
            "fingertip[0].tactile.width",
        ),
        (
            "height = 0.016 ",
            "height = 1e-300 ",
            "fingertip[0].tactile.height",
        ),
        (
            "width = 0.016 ",
            "width = 1.5e-7 ",
            "fingertip[0].tactile.width",
        ),
    ] {
        let text = DEFAULT_SCENE.replacen(from, to, 1);
        assert_ne!(text, DEFAULT_SCENE);
        let err = Scene::parse(&text, "p.toml", Path::new(".")).unwrap_err();
        assert_eq!(err.field(), Some(field), "{err}");
        let m = err.to_string();
        // 16 taxels of at least 1e-6 R = 1e-8 m each.
        assert!(m.contains("at least 16 x 1e-8 m"), "{m}");
    }
    // 16 taxels of 1e-8 m: the smallest pad of a 10 mm fingertip.
    let text = DEFAULT_SCENE.replacen("width = 0.016 ", "width = 1.6e-7 ", 1);
    assert!(Scene::parse(&text, "p.toml", Path::new(".")).is_ok());
}

#[test]
fn messages_print_1e300_in_shortest_form() {
    for (from, to, shown) in [
        ("dt = 0.016666666666666666", "dt = 1e-300", "1e-300"),
        ("density = 500.0", "density = 1e300", "1e300"),
        ("radius = 0.01", "radius = 1e300", "1e300"),
        ("friction = 0.8", "friction = -1e300", "-1e300"),
        ("approach_speed = 0.01 ", "approach_speed = 1e300 ", "1e300"),
        // serde's message of a value of the wrong type quoted it with 301 digits.
        (
            "gravity = [0.0, -9.81, 0.0]",
            "gravity = 1e300",
            "floating point `1e300`",
        ),
        // The law's message inside the scene's: x = delta/R printed 302 digits.
        ("depth = 0.002", "depth = 1e300", "x = delta/R = 1e302"),
    ] {
        let text = DEFAULT_SCENE.replacen(from, to, 1);
        assert_ne!(text, DEFAULT_SCENE, "{from}");
        let m = Scene::parse(&text, "n.toml", Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(m.contains(shown), "{to}: {m}");
        assert!(!m.contains("0000000000"), "{to}: {m}");
    }
}
