//! Where a mimic joint starts (issue 25, "mimic joints coupled"): it follows its joint's start
//! (through a chain, whatever the URDF's joint order); a start given for the mimic itself must
//! be that one, and a start that puts the mimic outside its own limits is refused, each a
//! `SceneError::Invalid` naming `robot[0].initial.<joint>`, the value and the range. Before
//! session 15 both were silently replaced (the mimic put where it followed, beyond its limit).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_scene::{Scene, SceneError};

/// a -j1-> b -j2-> c -j3-> d about y; j3 (written first) mimics j2, j2 mimics j1 (x 2);
/// limits [-1, 1] on j1, `j2_limits` on j2, [-2, 2] on j3.
fn urdf(j2_limits: &str) -> String {
    let link = |n: &str| {
        format!(
            r#"<link name="{n}"><inertial><mass value="0.1"/><inertia ixx="1e-4" ixy="0" ixz="0" iyy="1e-4" iyz="0" izz="1e-4"/></inertial><collision><origin xyz="0 0 -0.05"/><geometry><box size="0.01 0.01 0.1"/></geometry></collision></link>"#
        )
    };
    let joint = |n: &str, p: &str, ch: &str, limits: &str, extra: &str| {
        format!(
            r#"<joint name="{n}" type="revolute"><parent link="{p}"/><child link="{ch}"/><origin xyz="0 0 -0.1"/><axis xyz="0 1 0"/><limit {limits} effort="5" velocity="2"/>{extra}</joint>"#
        )
    };
    format!(
        "<robot name=\"t\">{}{}{}{}{}{}{}</robot>",
        link("a"),
        link("b"),
        link("c"),
        link("d"),
        joint(
            "j3",
            "c",
            "d",
            r#"lower="-2" upper="2""#,
            r#"<mimic joint="j2" multiplier="-1" offset="0.1"/>"#
        ),
        joint("j1", "a", "b", r#"lower="-1" upper="1""#, ""),
        joint(
            "j2",
            "b",
            "c",
            j2_limits,
            r#"<mimic joint="j1" multiplier="2"/>"#
        ),
    )
}

fn load(urdf: &str, initial: &str) -> Result<Scene, SceneError> {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("robot.urdf"), urdf).unwrap();
    let scene = format!(
        "duration = 0.1\n[[robot]]\nname = \"r\"\nurdf = \"robot.urdf\"\nbase = \"fixed\"\ninitial = {{ {initial} }}\n"
    );
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, scene).unwrap();
    Scene::from_file(&path)
}

/// The start of joint `name` of the scene's robot.
fn start(s: &Scene, name: &str) -> f64 {
    let r = &s.robots()[0];
    r.joints()[r.joint_index(name).unwrap()].initial
}

/// The `SceneError::Invalid` of loading, on `field`, whose text holds every one of `want`.
fn invalid(r: Result<Scene, SceneError>, want_field: &str, want: &[&str]) {
    let Err(err) = r else {
        panic!("loaded");
    };
    let SceneError::Invalid { field, .. } = &err else {
        panic!("not an Invalid error: {err}");
    };
    assert_eq!(field, want_field, "{err}");
    for w in want {
        assert!(err.to_string().contains(w), "`{w}` not in: {err}");
    }
}

#[test]
fn a_mimic_chain_starts_where_it_follows_whatever_the_joint_order() {
    let s = load(&urdf(r#"lower="-2" upper="2""#), "j1 = 0.3").unwrap();
    assert!((start(&s, "j2") - 0.6).abs() < 1e-12, "{}", start(&s, "j2"));
    // j3 = 0.1 - j2, though j3 comes first in the file.
    assert!((start(&s, "j3") + 0.5).abs() < 1e-12, "{}", start(&s, "j3"));
    // A mimic's start given as the one it follows to is accepted.
    assert!(load(&urdf(r#"lower="-2" upper="2""#), "j1 = 0.3, j2 = 0.6").is_ok());
}

#[test]
fn a_start_given_for_a_mimic_that_is_not_where_it_follows_is_an_error() {
    invalid(
        load(&urdf(r#"lower="-2" upper="2""#), "j1 = 0.3, j2 = 0.1"),
        "robot[0].initial.j2",
        &[
            "got 0.1",
            "0.6: the joint mimics `j1` (2 x its start + 0)",
            "set `initial.j1`",
        ],
    );
}

#[test]
fn a_start_that_puts_a_mimic_past_its_limits_is_an_error_naming_the_joint_started() {
    // j2 = 2 x 0.3 = 0.6 past its upper limit 0.5.
    invalid(
        load(&urdf(r#"lower="-0.5" upper="0.5""#), "j1 = 0.3"),
        "robot[0].initial.j1",
        &[
            "got 0.3",
            "joint `j2`",
            "= 0.6",
            "within its limits [-0.5, 0.5]",
        ],
    );
    // Within: 2 x 0.2 = 0.4.
    assert!(load(&urdf(r#"lower="-0.5" upper="0.5""#), "j1 = 0.2").is_ok());
}
