//! The command line reads the law's tables (issue 26 item 2): `--level` and `--backing`
//! list exactly `softgrip_law::LEVELS` (those that parameters build) and `BACKINGS`, with
//! their descriptions; a level's setting is checked by the law; and a run with a `tabulated`
//! level records its curve, so that `softgrip inspect` and `softgrip_record` read back the
//! same law (before, `inspect` said "unknown level"). A recording made before curves were
//! recorded still inspects. A recording's metadata lists the run's controllers with their
//! kinds' names and fixed codes from `softgrip_scene::CONTROLLERS`, and `inspect` prints them.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_law::{BACKINGS, ContactLaw, LEVELS, Level, LevelData, TabulatedCurve};
use softgrip_record::{ControllerRecord, Recording};
use softgrip_scene::control::{CONTROLLERS, ControllerKind};

/// The `Possible values:` entries (`- name: description`) of one option in `--help`.
fn possible_values(help: &str, option: &str) -> Vec<String> {
    let start = help
        .find(&format!("--{option} <"))
        .unwrap_or_else(|| panic!("no --{option} in:\n{help}"));
    let rest = &help[start..];
    let list = &rest[rest.find("Possible values:").unwrap()..];
    list.lines()
        .skip(1)
        .map(str::trim)
        .take_while(|l| l.starts_with("- "))
        .map(|l| {
            // `- name:   description` (clap pads the names to one column).
            let (name, description) = l[2..].split_once(':').unwrap();
            format!("{name}: {}", description.trim_start())
        })
        .collect()
}

#[test]
fn curve_help_lists_exactly_the_tables() {
    let o = common::softgrip(&["curve", "--help"]);
    assert!(o.status.success());
    let help = String::from_utf8_lossy(&o.stdout);
    let want: Vec<String> = LEVELS
        .iter()
        .filter(|r| r.data == LevelData::None)
        .map(|r| format!("{}: {}", r.name, r.description))
        .collect();
    assert_eq!(possible_values(&help, "level"), want);
    let want: Vec<String> = BACKINGS
        .iter()
        .map(|r| format!("{}: {}", r.name, r.description))
        .collect();
    assert_eq!(possible_values(&help, "backing"), want);
    // Every setting of the table has its flag.
    for s in LEVELS.iter().flat_map(|r| r.settings) {
        assert!(help.contains(&format!("{} <", s.flag())), "{}", s.flag());
    }
}

#[test]
fn a_setting_for_the_wrong_level_is_refused_by_the_law() {
    let o = common::softgrip(&[
        "curve",
        "--level",
        "fit",
        "--tolerance",
        "0.1",
        "--nu",
        "0.3",
        "--x",
        "0:0.1:0.05",
    ]);
    assert!(!o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("`--tolerance`: `tolerance` applies only to level `auto`, not to level `fit`"),
        "{e}"
    );
    let o = common::softgrip(&[
        "curve",
        "--level",
        "fit",
        "--k",
        "11",
        "--nu",
        "0.3",
        "--x",
        "0:0.1:0.05",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(e.contains("`k` must be finite and in [0, 10]"), "{e}");
    let o = common::softgrip(&[
        "curve",
        "--level",
        "hertz",
        "--backing",
        "flat",
        "--thickness",
        "0.5",
        "--nu",
        "0.3",
        "--x",
        "0:0.1:0.05",
    ]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("`--thickness` applies only to `--backing core`, not to `--backing flat`"),
        "{e}"
    );
}

#[test]
fn a_tabulated_run_reads_back_as_the_same_law() {
    let dir = common::temp_dir("kinds-tabulated");
    // 1.2 x Hertz's force of the default fingertip (Dragon Skin 30, R = 10 mm), to 4 mm.
    let mut csv = String::from("delta_m,force_n\n");
    let (e_star, r) = (5.9e5 / (1.0 - 0.49 * 0.49), 0.01_f64);
    for i in 1..=16 {
        let d = 0.00025 * f64::from(i);
        csv.push_str(&format!(
            "{d},{}\n",
            1.2 * 4.0 / 3.0 * e_star * r.sqrt() * d.powf(1.5)
        ));
    }
    std::fs::write(dir.join("tip.csv"), &csv).unwrap();
    let scene = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    let scene = scene
        .replacen(
            "level = \"auto\"\ntolerance = 0.01",
            "level = { tabulated = \"tip.csv\" }",
            1,
        )
        .replace("duration = 5.0", "duration = 0.5");
    assert!(scene.contains("tabulated"));
    std::fs::write(dir.join("scene.toml"), &scene).unwrap();
    let rec_path = dir.join("run.mcap");
    let o = common::softgrip(&[
        "run",
        dir.join("scene.toml").to_str().unwrap(),
        "--out",
        rec_path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));

    let o = common::softgrip(&["inspect", rec_path.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.contains("left_tip: level=tabulated"), "{out}");
    assert!(out.contains("curve_samples=17"), "{out}");

    let rec = Recording::open(&rec_path).unwrap();
    let info = rec.info().unwrap().unwrap();
    let left = &info.law[0];
    assert_eq!(left.level, Level::Tabulated);
    let (delta, force): (Vec<f64>, Vec<f64>) = csv
        .lines()
        .skip(1)
        .map(|l| {
            let (a, b) = l.split_once(',').unwrap();
            (a.parse::<f64>().unwrap(), b.parse::<f64>().unwrap())
        })
        .unzip();
    let want = ContactLaw::tabulated(
        left.params().unwrap(),
        TabulatedCurve::try_new(delta, force).unwrap(),
    )
    .unwrap();
    let got = left.law().unwrap();
    for i in 0..=50 {
        let d = 0.0001 * f64::from(i);
        assert_eq!(
            got.response(d).force.to_bits(),
            want.response(d).force.to_bits(),
            "delta {d}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_tabulated_recording_made_before_curves_still_inspects() {
    let old = common::root().join("crates/softgrip-record/tests/data/tabulated_before_curve.mcap");
    let o = common::softgrip(&["inspect", old.to_str().unwrap()]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{out}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(out.contains("left_tip: level=tabulated"), "{out}");
}

/// Runs `scene` (its text, written to `dir/NAME.toml`) for its duration into `dir/NAME.mcap`
/// and returns the recording's controllers and `softgrip inspect`'s output.
fn recorded_controllers(
    dir: &std::path::Path,
    name: &str,
    scene: &str,
) -> (Vec<ControllerRecord>, String) {
    let scene_path = dir.join(format!("{name}.toml"));
    std::fs::write(&scene_path, scene).unwrap();
    let rec_path = dir.join(format!("{name}.mcap"));
    let o = common::softgrip(&[
        "run",
        scene_path.to_str().unwrap(),
        "--out",
        rec_path.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let info = Recording::open(&rec_path).unwrap().info().unwrap().unwrap();
    let o = common::softgrip(&["inspect", rec_path.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    (
        info.controllers,
        String::from_utf8_lossy(&o.stdout).into_owned(),
    )
}

/// The record of a controller named `name` of `kind`, from the kind's row of the table.
fn row(name: &str, kind: ControllerKind) -> ControllerRecord {
    let row = CONTROLLERS.iter().find(|r| r.kind == kind).unwrap();
    ControllerRecord {
        name: name.into(),
        kind: row.name.into(),
        code: row.code,
    }
}

#[test]
fn a_run_records_its_controllers_with_the_tables_names_and_codes() {
    let dir = common::temp_dir("kinds-controllers");
    // The default scene: its `[gripper]`, parallel_jaws (code 0).
    let scene = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    let scene = scene.replace("duration = 5.0", "duration = 0.1");
    assert!(scene.contains("duration = 0.1") && scene.contains("[gripper]"));
    let (got, out) = recorded_controllers(&dir, "default", &scene);
    assert_eq!(got, vec![row("gripper", ControllerKind::ParallelJaws)]);
    assert_eq!(got[0].code, 0, "a code written to files never changes");
    assert!(
        out.contains("controllers:\n  gripper: parallel_jaws (code 0)\n"),
        "{out}"
    );

    // A robot scene: its `[[controller]] type = "grasp"` (code 2), then the robot's commands
    // from outside (joint_commands, code 3), in the order they run.
    let urdf = common::root().join("robots/parallel_gripper/parallel_gripper.urdf");
    let urdf = format!("{:?}", urdf.to_str().unwrap());
    let scene =
        std::fs::read_to_string(common::root().join("scenes/robots/parallel_gripper_box.toml"))
            .unwrap()
            .replace("duration = 5.0", "duration = 0.05")
            .replace(
                "\"../../robots/parallel_gripper/parallel_gripper.urdf\"",
                &urdf,
            );
    assert!(scene.contains("duration = 0.05") && scene.contains(&format!("urdf = {urdf}")));
    let (got, out) = recorded_controllers(&dir, "robot", &scene);
    assert_eq!(
        got,
        vec![
            row("grasp", ControllerKind::Grasp),
            row("gripper/commands", ControllerKind::JointCommands),
        ]
    );
    assert_eq!(
        (got[0].code, got[1].code),
        (2, 3),
        "codes written to files never change"
    );
    assert!(
        out.contains(
            "controllers:\n  grasp: grasp (code 2)\n  gripper/commands: joint_commands (code 3)\n"
        ),
        "{out}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
