//! `self_contacts = true` (the default): a robot's pairs of links that are always in contact
//! (in at least 95 % of 128 sampled configurations over its joints' ranges, as MoveIt's setup
//! assistant disables "always in collision" pairs) are kept from touching; any other pair of
//! links that starts overlapping is refused, naming both links; pairs apart at the start
//! collide (`robot::always_in_contact`, `start::check_self_overlap`).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_scene::{PlainRun, Scene};

const INERTIAL: &str = r#"<inertial><mass value="0.1"/><inertia ixx="1e-5" ixy="0" ixz="0" iyy="1e-5" iyz="0" izz="1e-5"/></inertial>"#;

/// A base with two fingers on revolute joints about z (limits +-1.5 rad). Without `hub`: `a`
/// at the origin with a 60 mm arm along +x, `b` at x = 80 mm with its arm along -x; at 0 rad
/// both lie on the x axis, crossed over 40 mm, and turned apart they do not touch. With `hub`:
/// both joints on the z axis, each link a 20 mm cube on it (`a`'s centred 25 mm up, `b`'s 30
/// mm), overlapping by 15 mm at every angle.
fn urdf(hub: bool) -> String {
    let (b_at, b_box) = if hub {
        (
            "0 0 0.03",
            r#"<collision><geometry><box size="0.02 0.02 0.02"/></geometry></collision>"#,
        )
    } else {
        (
            "0.08 0 0",
            r#"<collision><origin xyz="-0.03 0 0"/><geometry><box size="0.06 0.01 0.01"/></geometry></collision>"#,
        )
    };
    let a_box = if hub {
        r#"<collision><origin xyz="0 0 0.025"/><geometry><box size="0.02 0.02 0.02"/></geometry></collision>"#
    } else {
        r#"<collision><origin xyz="0.03 0 0"/><geometry><box size="0.06 0.01 0.01"/></geometry></collision>"#
    };
    format!(
        r#"<robot name="two">
  <link name="base">{INERTIAL}</link>
  <link name="a">{INERTIAL}{a_box}</link>
  <link name="b">{INERTIAL}{b_box}</link>
  <joint name="ja" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" effort="5" velocity="2"/></joint>
  <joint name="jb" type="revolute"><parent link="base"/><child link="b"/><origin xyz="{b_at}"/><axis xyz="0 0 1"/>
    <limit lower="-1.5" upper="1.5" effort="5" velocity="2"/></joint>
</robot>"#
    )
}

fn scene(
    hub: bool,
    initial: &str,
) -> (tempfile::TempDir, Result<Scene, softgrip_scene::SceneError>) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("two.urdf"), urdf(hub)).unwrap();
    let text = format!(
        "duration = 0.1\ngravity = [0.0, 0.0, 0.0]\n[[robot]]\nname = \"two\"\nurdf = \"two.urdf\"\nbase = \"kinematic\"\ninitial = {{ {initial} }}\n"
    );
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let s = Scene::from_file(&path);
    (dir, s)
}

/// The two arms cross at 0 rad: a pair that is in contact only near there over the joints'
/// ranges (far from 95 % of the samples) and starts overlapping is refused, naming both links
/// and how deep they overlap.
#[test]
fn links_that_start_overlapping_but_move_apart_are_refused() {
    let (_d, s) = scene(false, "ja = 0.0, jb = 0.0");
    let e = s.map(|_| ()).unwrap_err();
    let msg = e.to_string();
    assert_eq!(e.field(), Some("robot[0].self_contacts"), "{msg}");
    assert!(
        msg.contains("links `a` and `b` start overlapping by "),
        "{msg}"
    );
    println!("{msg}");
}

/// Turned apart at the start (ja = 1, jb = -1: the arms point away from each other's) the
/// same robot loads, no pair is kept apart, and its two links collide.
#[test]
fn links_apart_at_the_start_load_and_still_collide() {
    let (_d, s) = scene(false, "ja = 1.0, jb = -1.0");
    let scene = s.unwrap();
    let robot = &scene.robots()[0];
    assert_eq!(softgrip_scene::robot::always_in_contact(robot), vec![]);
    let run = PlainRun::new(&scene);
    assert!(run.world.soft.excluded_pairs().is_empty());
}

/// Two cubes on one axis overlap at every pose: the pair is always in contact, kept apart
/// (`SoftWorld::exclude_pair`) and the robot loads.
#[test]
fn links_always_in_contact_are_kept_apart_and_load() {
    let (_d, s) = scene(true, "ja = 0.0, jb = 0.0");
    let scene = s.unwrap();
    let robot = &scene.robots()[0];
    let pairs = softgrip_scene::robot::always_in_contact(robot);
    let names: Vec<_> = (pairs.iter())
        .map(|&(a, b)| {
            (
                robot.links()[a].name.as_str(),
                robot.links()[b].name.as_str(),
            )
        })
        .collect();
    assert_eq!(names, [("a", "b")]);
    let run = PlainRun::new(&scene);
    assert_eq!(run.world.soft.excluded_pairs().len(), 1);
}
