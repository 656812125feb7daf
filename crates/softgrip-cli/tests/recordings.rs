//! The committed recordings (`recordings/*.mcap`): each decodes with the current schema, is
//! under 2 MB, was made from its scene (the scene text in its metadata equals the file), and
//! regenerating it (`softgrip run SCENE --out`) gives the same contact values within
//! tolerances (compared after decoding, never byte for byte).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{Message, Recording, topics};

/// (recording, scene file).
const RECORDINGS: [(&str, &str); 11] = [
    ("default.mcap", "scenes/default.toml"),
    ("ecoflex_sphere.mcap", "scenes/ecoflex_sphere.toml"),
    ("cell_live_hmsc.mcap", "scenes/cell_live_hmsc.toml"),
    ("cell_fixed_stained.mcap", "scenes/cell_fixed_stained.toml"),
    ("cell_live_stained.mcap", "scenes/cell_live_stained.toml"),
    // The shipped hands (issue 25): each grasps a box, a ball and a cylinder.
    (
        "parallel_gripper_box.mcap",
        "scenes/robots/parallel_gripper_box.toml",
    ),
    (
        "parallel_gripper_ball.mcap",
        "scenes/robots/parallel_gripper_ball.toml",
    ),
    (
        "parallel_gripper_cylinder.mcap",
        "scenes/robots/parallel_gripper_cylinder.toml",
    ),
    (
        "three_finger_hand_box.mcap",
        "scenes/robots/three_finger_hand_box.toml",
    ),
    (
        "three_finger_hand_ball.mcap",
        "scenes/robots/three_finger_hand_ball.toml",
    ),
    (
        "three_finger_hand_cylinder.mcap",
        "scenes/robots/three_finger_hand_cylinder.toml",
    ),
];

fn contacts(rec: &Recording) -> Vec<(u64, SoftContactMsg)> {
    rec.on_topic(topics::CONTACTS)
        .flat_map(|m| match &m.message {
            Message::Contacts(a) => a
                .contacts
                .iter()
                .map(|c| (m.log_time_ns, c.clone()))
                .collect(),
            _ => Vec::new(),
        })
        .collect()
}

/// |a - b| <= rel * scale: values compared against the run's largest value of that quantity
/// (a contact that is just starting has a force near zero).
fn check(what: &str, got: f64, want: f64, scale: f64) {
    let tol = 1e-4 * scale;
    assert!(
        (got - want).abs() <= tol,
        "{what}: regenerated {got}, committed {want} (tolerance {tol:e})"
    );
}

#[test]
fn committed_recordings_decode_and_regenerate_to_the_same_contacts() {
    let dir = common::temp_dir("recordings");
    for (file, scene) in RECORDINGS {
        let path = common::root().join("recordings").join(file);
        let size = std::fs::metadata(&path).unwrap().len();
        assert!(size < 2_000_000, "{file}: {size} bytes");
        let committed = Recording::open(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(!committed.recovered(), "{file}");
        let scene_path = common::root().join(scene);
        let text = std::fs::read_to_string(&scene_path).unwrap();
        assert_eq!(
            committed.softgrip_metadata("scene"),
            Some(text.as_str()),
            "{file} was not made from the current {scene}: regenerate it (recordings/README.md)"
        );

        let fresh_path = dir.join(file);
        let o = common::softgrip(&[
            "run",
            scene_path.to_str().unwrap(),
            "--out",
            fresh_path.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let fresh = Recording::open(&fresh_path).unwrap();
        for c in &committed.channels {
            let f = fresh.channels.iter().find(|f| f.topic == c.topic).unwrap();
            assert_eq!(
                (c.message_count, &c.schema_name),
                (f.message_count, &f.schema_name)
            );
        }
        let (a, b) = (contacts(&fresh), contacts(&committed));
        assert_eq!(a.len(), b.len(), "{file}: contact count");
        let max =
            |f: fn(&SoftContactMsg) -> f64| b.iter().map(|(_, c)| f(c).abs()).fold(0.0, f64::max);
        let (f_max, x_max, a_max) = (
            max(|c| c.normal_force),
            max(|c| c.ratio_x),
            max(|c| c.contact_radius),
        );
        for ((ta, ca), (tb, cb)) in a.iter().zip(&b) {
            assert_eq!(ta, tb);
            assert_eq!(
                (&ca.fingertip, &ca.other, ca.level),
                (&cb.fingertip, &cb.other, cb.level)
            );
            check("normal_force", ca.normal_force, cb.normal_force, f_max);
            check(
                "peak_normal_force",
                ca.peak_normal_force,
                cb.peak_normal_force,
                f_max,
            );
            check("ratio_x", ca.ratio_x, cb.ratio_x, x_max);
            check(
                "contact_radius",
                ca.contact_radius,
                cb.contact_radius,
                a_max,
            );
        }
        println!(
            "{file}: {size} bytes, {} messages, {} contacts match",
            committed.messages.len(),
            b.len()
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
