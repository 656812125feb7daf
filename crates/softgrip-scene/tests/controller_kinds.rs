//! Controller kinds are listed once, in `softgrip_scene::control::CONTROLLERS` (issue 26 item
//! 2): fixed file codes, one row per kind, `[[controller]] type = ...` read through the table
//! (an unknown `type` is refused listing it), every controller's `kind()` a row of it, and
//! SCENES.md's table row for row.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::{Path, PathBuf};

use softgrip_scene::control::{CONTROLLERS, ControllerKind, ControllerSource};
use softgrip_scene::{Scene, SceneError};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Every kind, by an exhaustive match: a new variant does not compile until it is added here,
/// and then `every_kind_has_one_row` fails until the table has its row.
fn all_kinds() -> Vec<ControllerKind> {
    let all = [
        ControllerKind::ParallelJaws,
        ControllerKind::Trajectory,
        ControllerKind::Grasp,
        ControllerKind::JointCommands,
    ];
    for k in all {
        match k {
            ControllerKind::ParallelJaws
            | ControllerKind::Trajectory
            | ControllerKind::Grasp
            | ControllerKind::JointCommands => {}
        }
    }
    all.to_vec()
}

#[test]
fn every_kind_has_one_row_with_its_own_name_and_code() {
    for kind in all_kinds() {
        let rows: Vec<_> = CONTROLLERS.iter().filter(|r| r.kind == kind).collect();
        assert_eq!(rows.len(), 1, "{kind:?}");
        assert_eq!(ControllerKind::from_code(kind.code()), Some(kind));
        assert_eq!(kind.to_string(), kind.name());
    }
    assert_eq!(CONTROLLERS.len(), all_kinds().len());
    for (i, a) in CONTROLLERS.iter().enumerate() {
        for b in &CONTROLLERS[i + 1..] {
            assert_ne!(a.name, b.name);
            assert_ne!(a.code, b.code);
        }
        assert!(!a.description.is_empty(), "{}", a.name);
    }
}

/// The codes written to files never change: these are the codes of the first table.
#[test]
fn codes_are_fixed() {
    let codes: Vec<(&str, u8)> = CONTROLLERS.iter().map(|r| (r.name, r.code)).collect();
    for (name, code) in [
        ("parallel_jaws", 0),
        ("trajectory", 1),
        ("grasp", 2),
        ("joint_commands", 3),
    ] {
        assert!(codes.contains(&(name, code)), "{name} {code}: {codes:?}");
    }
    assert_eq!(ControllerKind::from_code(4), None);
}

/// The shipped gripper scene with `extra` appended (its `grasp`, then what `extra` adds).
fn gripper_scene_with(extra: &str) -> Result<Scene, SceneError> {
    let path = repo().join("scenes/robots/parallel_gripper_box.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    Scene::parse(
        &format!("{text}\n{extra}"),
        "gripper.toml",
        path.parent().unwrap(),
    )
}

const TRAJECTORY: &str = "[[controller]]\ntype = \"trajectory\"\nrobot = \"gripper\"\n\
     joints = [\"finger_joint\"]\npoints = [{ t = 0.0, positions = [0.028] }]\n";

#[test]
fn every_kind_a_scene_names_reads_through_the_table_and_reports_its_row() {
    // `[gripper]` written as the controller `parallel_jaws`.
    let text = std::fs::read_to_string(repo().join("scenes/default.toml")).unwrap();
    let (head, gripper) = text.split_once("[gripper]\n").unwrap();
    let jaws = format!("{head}[[controller]]\ntype = \"parallel_jaws\"\n{gripper}");
    let scene = Scene::parse(&jaws, "jaws.toml", &repo().join("scenes")).unwrap();
    let kinds: Vec<_> = scene.controllers().iter().map(|c| c.kind()).collect();
    assert_eq!(kinds, [ControllerKind::ParallelJaws]);
    assert_eq!(
        scene.file().controllers[0].kind(),
        ControllerKind::ParallelJaws
    );

    // The grasp, a trajectory without a name (its default name is its kind's), and the robot's
    // commands from outside.
    let scene = gripper_scene_with(TRAJECTORY).unwrap();
    let kinds: Vec<_> = scene.controllers().iter().map(|c| c.kind()).collect();
    assert_eq!(
        kinds,
        [
            ControllerKind::Grasp,
            ControllerKind::Trajectory,
            ControllerKind::JointCommands
        ]
    );
    let names: Vec<_> = scene
        .controllers()
        .iter()
        .map(|c| c.name().to_owned())
        .collect();
    assert_eq!(names, ["grasp", "trajectory", "gripper/commands"]);
    // Every kind a scene file names was read above; the others are added for every robot.
    for row in &CONTROLLERS {
        assert_eq!(
            row.source == ControllerSource::SceneFile,
            row.kind != ControllerKind::JointCommands,
            "{}",
            row.name
        );
    }
}

#[test]
fn a_type_outside_the_table_is_refused_listing_the_table() {
    let scene_names: Vec<String> = (CONTROLLERS.iter())
        .filter(|r| r.source == ControllerSource::SceneFile)
        .map(|r| format!("`{}`", r.name))
        .collect();
    let e = gripper_scene_with("[[controller]]\ntype = \"gripper_command\"\nrobot = \"gripper\"\n")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("unknown controller type `gripper_command`"),
        "{e}"
    );
    assert!(e.contains(&scene_names.join(", ")), "{e}");
    // The kind the scene adds for every robot is not written in a scene file.
    let e = gripper_scene_with("[[controller]]\ntype = \"joint_commands\"\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("added for every robot"), "{e}");
    let e = gripper_scene_with("[[controller]]\ntype = 3\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("`type` must be a string"), "{e}");
    let e = gripper_scene_with("[[controller]]\nrobot = \"gripper\"\n")
        .unwrap_err()
        .to_string();
    assert!(e.contains("missing field `type`"), "{e}");
    // A kind's own fields are still checked by name, the message naming the kind.
    let e = gripper_scene_with(&TRAJECTORY.replace("robot =", "robto ="))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`[[controller]]` of type `trajectory`: unknown field `robto`"),
        "{e}"
    );
}

/// SCENES.md's "Controllers" table lists exactly the kinds a scene file names, in table order,
/// each row's "what" starting with the table's description; the prose names the others.
#[test]
fn scenes_md_lists_the_table() {
    let md =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("SCENES.md")).unwrap();
    let section = md
        .split("## `[[controller]]`")
        .nth(1)
        .unwrap()
        .split("\n## ")
        .next()
        .unwrap();
    let rows: Vec<(String, String)> = section
        .lines()
        .filter(|l| l.starts_with("| `") && !l.starts_with("| `type`"))
        .map(|l| {
            let cells: Vec<&str> = l.split(" | ").collect();
            (
                cells[0]
                    .trim_start_matches("| ")
                    .trim_matches('`')
                    .to_owned(),
                cells[1].to_owned(),
            )
        })
        .collect();
    let want: Vec<_> = (CONTROLLERS.iter())
        .filter(|r| r.source == ControllerSource::SceneFile)
        .collect();
    assert_eq!(rows.len(), want.len(), "{rows:?}");
    for ((name, what), row) in rows.iter().zip(&want) {
        assert_eq!(name, row.name);
        assert!(what.starts_with(row.description), "{name}: {what}");
    }
    for row in CONTROLLERS
        .iter()
        .filter(|r| r.source != ControllerSource::SceneFile)
    {
        assert!(section.contains(&format!("`{}`", row.name)), "{}", row.name);
    }
}
