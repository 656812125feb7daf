//! `level = { tabulated = "tip.csv" }`: the curve file is found relative to the scene file,
//! read into its two columns, and a bad file is a `SceneError::Curve` naming file:line and
//! the column.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};

use softgrip_scene::{LevelSpec, Scene, SceneError, parse_curve, read_curve};

/// A fresh folder for one test's files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("softgrip-scene-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const CURVE: &str = "# Dragon Skin 30, R = 10 mm, flat-plate squeeze\ndelta_m,force_n\n0.0,0.0\n0.0005,0.21\n0.001,0.62\n0.002,1.9\n";

fn scene_with(level: &str) -> String {
    format!(
        "duration = 0.1\n[[body]]\nname = \"jaw\"\nkind = \"kinematic\"\n\
         [[fingertip]]\nname = \"tip\"\nbody = \"jaw\"\nradius = 0.01\npreset = \"dragon-skin-30\"\nlevel = {level}\n"
    )
}

#[test]
fn curve_file_reads_both_columns_in_order() {
    let c = parse_curve(CURVE.as_bytes(), Path::new("tip.csv")).unwrap();
    assert_eq!(c.delta_m, vec![0.0, 0.0005, 0.001, 0.002]);
    assert_eq!(c.force_n, vec![0.0, 0.21, 0.62, 1.9]);
    assert_eq!(c.path, Path::new("tip.csv"));
}

#[test]
fn bad_curve_files_name_the_file_line_and_column() {
    let cases = [
        (
            "delta_m,force_n\n0.0,0.0\n0.001,abc\n",
            3,
            "force_n",
            "`abc` is not a number",
        ),
        (
            "delta_m,force_n\n0.0,0.0\nx,1.0\n",
            3,
            "delta_m",
            "`x` is not a number",
        ),
        (
            "delta_m,force_n\n0.0,0.0\n0.001,inf\n",
            3,
            "force_n",
            "finite",
        ),
        ("delta_m,force\n0.0,0.0\n", 1, "header", "delta_m,force_n"),
        ("# provenance\ndelta_m,force_n\n0.0,0.0\n0.1\n", 4, "", "2"),
        ("delta_m,force_n\n", 1, "", "no data rows"),
    ];
    for (text, want_line, want_field, want_message) in cases {
        let err = parse_curve(text.as_bytes(), Path::new("tip.csv")).unwrap_err();
        let SceneError::Curve {
            line,
            field,
            message,
            ..
        } = &err
        else {
            panic!("expected a curve error, got {err}");
        };
        assert_eq!(*line, want_line, "{text:?}: {err}");
        assert_eq!(field, want_field, "{text:?}: {err}");
        assert!(message.contains(want_message), "{text:?}: {err}");
        assert!(
            err.to_string()
                .starts_with(&format!("tip.csv:{want_line}: ")),
            "{err}"
        );
    }
}

#[test]
fn level_key_takes_a_name_or_a_tabulated_file() {
    let scene = Scene::parse(&scene_with("\"hertz\""), "s.toml", Path::new(".")).unwrap();
    assert_eq!(
        scene.file().fingertips[0].level,
        LevelSpec::Named("hertz".into())
    );
    let err = Scene::parse(
        &scene_with("{ tabulated = \"tip.csv\", extra = 1 }"),
        "s.toml",
        Path::new("."),
    )
    .unwrap_err();
    assert!(
        matches!(&err, SceneError::Parse { line: 10, message, .. } if message.contains("extra")),
        "{err}"
    );
}

#[test]
fn tabulated_curve_is_found_relative_to_the_scene_file() {
    let dir = temp_dir("relative");
    std::fs::write(
        dir.join("bad.csv"),
        "delta_m,force_n\n0.0,0.0\n0.001,oops\n",
    )
    .unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, scene_with("{ tabulated = \"bad.csv\" }")).unwrap();
    let err = Scene::from_file(&scene).unwrap_err();
    assert!(
        matches!(&err, SceneError::Curve { path, line: 3, field, .. }
            if path == &dir.join("bad.csv") && field == "force_n"),
        "{err}"
    );
    let missing =
        Scene::parse(&scene_with("{ tabulated = \"none.csv\" }"), "s.toml", &dir).unwrap_err();
    assert!(
        matches!(&missing, SceneError::Curve { line: 0, .. }),
        "{missing}"
    );
    assert_eq!(
        read_curve(&dir.join("bad.csv")).unwrap_err().to_string(),
        err.to_string()
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn tabulated_level_builds_a_fingertip() {
    let dir = temp_dir("tabulated");
    std::fs::write(dir.join("tip.csv"), CURVE).unwrap();
    let text = scene_with("{ tabulated = \"tip.csv\" }");
    let scene = Scene::parse(&text, "s.toml", &dir).unwrap();
    let law = scene.fingertips()[0].law();
    // The law passes through the measured points.
    let f = law.response(0.001).force;
    assert!((f / 0.62 - 1.0).abs() < 1e-9, "{f} N");
    std::fs::remove_dir_all(&dir).ok();
}
