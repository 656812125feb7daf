//! A fingertip's `level`, its settings and its `backing` are read through the law's tables
//! (`softgrip_law::LEVELS`, `BACKINGS`): every setting of the table is a scene key, valid
//! only with its level, and a name outside a table is an error listing the table.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;

use softgrip_law::{BACKINGS, Backing, LEVELS, Level, LevelData, setting_keys};
use softgrip_scene::{Scene, SceneError};

fn scene_with(keys: &str) -> String {
    format!(
        "duration = 0.1\n[[body]]\nname = \"jaw\"\nkind = \"kinematic\"\n\
         [[fingertip]]\nname = \"tip\"\nbody = \"jaw\"\nradius = 0.01\npreset = \"dragon-skin-30\"\n{keys}\n"
    )
}

fn parse(keys: &str) -> Result<Scene, SceneError> {
    Scene::parse(&scene_with(keys), "s.toml", Path::new("."))
}

#[test]
fn scene_setting_keys_are_exactly_the_tables() {
    let scene = parse("level = \"hertz\"").unwrap();
    let keys: Vec<&str> = scene.file().fingertips[0]
        .settings()
        .iter()
        .map(|(k, _)| *k)
        .collect();
    assert_eq!(keys, setting_keys());
}

#[test]
fn every_buildable_level_and_setting_reads_from_the_scene() {
    for row in LEVELS.iter().filter(|r| r.data == LevelData::None) {
        let scene = parse(&format!("level = \"{}\"", row.name)).unwrap();
        assert_eq!(scene.fingertips()[0].level(), row.level, "{}", row.name);
        for s in row.settings {
            let value = s.default * 0.5;
            let scene = parse(&format!("level = \"{}\"\n{} = {value}", row.name, s.key)).unwrap();
            assert_eq!(
                scene.fingertips()[0].level(),
                row.level.with_setting(s.key, value).unwrap()
            );
            // Any other level refuses the key, naming the fingertip's key and the level
            // that takes it.
            let other = if row.name == "hertz" { "fit" } else { "hertz" };
            let e = parse(&format!("level = \"{other}\"\n{} = {value}", s.key))
                .unwrap_err()
                .to_string();
            assert!(e.contains(&format!("fingertip[0].{}", s.key)), "{e}");
            assert!(e.contains(&format!("`level = \"{}\"`", row.name)), "{e}");
            // Outside its range: the range from the table.
            let e = parse(&format!("level = \"{}\"\n{} = 1e9", row.name, s.key))
                .unwrap_err()
                .to_string();
            assert!(e.contains(s.range.text()), "{e}");
        }
    }
}

#[test]
fn levels_that_need_data_or_are_unknown_are_refused_listing_the_table() {
    let e = parse("level = \"tabulated\"").unwrap_err().to_string();
    assert!(
        e.contains("tabulated = \\\"tip.csv\\\"") || e.contains("tabulated = "),
        "{e}"
    );
    let e = parse("level = \"custom\"").unwrap_err().to_string();
    assert!(e.contains("from Rust only"), "{e}");
    let e = parse("level = \"spring\"").unwrap_err().to_string();
    let names: Vec<&str> = LEVELS.iter().map(|r| r.name).collect();
    assert!(e.contains(&names.join(", ")), "{e}");
}

#[test]
fn every_backing_reads_through_the_one_parser() {
    for row in BACKINGS {
        let keys = match row.parameter {
            Some(p) => format!("backing = \"{}\"\n{} = 0.004", row.name, p.key),
            None => format!("backing = \"{}\"", row.name),
        };
        // A backed fingertip says which way it faces.
        let keys = match row.kind.with_parameter(0.004) {
            Backing::Free => keys,
            _ => format!("{keys}\nfacing = [1.0, 0.0, 0.0]"),
        };
        let scene = parse(&format!("level = \"hertz\"\n{keys}")).unwrap();
        let want = Backing::try_from_parts(row.name, row.parameter.map(|_| 0.004)).unwrap();
        assert_eq!(scene.fingertips()[0].backing(), want);
    }
    let e = parse("backing = \"steel\"").unwrap_err().to_string();
    let names: Vec<&str> = BACKINGS.iter().map(|r| r.name).collect();
    assert!(e.contains(&names.join(", ")), "{e}");
    let e = parse("backing = \"flat\"\ncore_thickness = 0.004")
        .unwrap_err()
        .to_string();
    assert!(e.contains("fingertip[0].core_thickness"), "{e}");
    let e = parse("backing = \"core\"").unwrap_err().to_string();
    assert!(e.contains("required"), "{e}");
    let e = parse("backing = \"core\"\ncore_thickness = 0.01")
        .unwrap_err()
        .to_string();
    assert!(e.contains("radius = 0.01 m"), "{e}");
    assert_eq!(
        parse("level = \"hertz\"").unwrap().fingertips()[0].level(),
        Level::Hertz
    );
}
