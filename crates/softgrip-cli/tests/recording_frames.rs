//! What a ROS 2 or Foxglove user sees (issue 12), checked from the data of fresh `softgrip run`
//! recordings as an MCAP reader softgrip did not write decodes them (Python `mcap` +
//! `mcap-ros2-support`, `crates/softgrip-record/tests/python/read_recording.py`): one tf tree
//! rooted at `world` with no repeated child in any message; every frame id used exists; the
//! world is z-up (gravity and the table's normal); every body has a marker; max_compression >=
//! compression in every contact; a patch radius > 0
//! whenever a contact exists and `mean_pressure · π a² = normal_force`; wrenches in the
//! fingertip frames; stamps exact multiples of dt to 1 ns; rosbag2's `offered_qos_profiles`
//! on every channel, `/tf_static` transient-local. Needs `SOFTGRIP_PY`.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::collections::{BTreeMap, BTreeSet};
use std::process::Command;

use serde_json::Value;
use softgrip_record::frames::{mul, rotate};

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}
fn vec3(v: &Value) -> [f64; 3] {
    [f(&v["x"]), f(&v["y"]), f(&v["z"])]
}
fn quat(v: &Value) -> [f64; 4] {
    [f(&v["x"]), f(&v["y"]), f(&v["z"]), f(&v["w"])]
}
fn stamp_ns(h: &Value) -> u64 {
    h["stamp"]["sec"].as_u64().unwrap() * 1_000_000_000 + h["stamp"]["nanosec"].as_u64().unwrap()
}

/// Runs `scene` (text) through `softgrip run` and decodes the file with Python.
fn decode(name: &str, text: &str) -> (Value, Vec<Value>) {
    let dir = common::temp_dir(&format!("frames-{name}"));
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let out = dir.join("run.mcap");
    let run = common::softgrip(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let py = Command::new(common::python())
        .arg(common::root().join("crates/softgrip-record/tests/python/read_recording.py"))
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        py.status.success(),
        "{}",
        String::from_utf8_lossy(&py.stderr)
    );
    let mut lines: Vec<Value> = String::from_utf8(py.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let summary = lines.pop().unwrap()["summary"].clone();
    std::fs::remove_dir_all(&dir).ok();
    (summary, lines)
}

/// The tf tree of the recording: child -> (parent, latest translation, rotation). Panics on a
/// repeated child within a message or a child with two parents.
type Tree = BTreeMap<String, (String, [f64; 3], [f64; 4])>;

fn add_transforms(tree: &mut Tree, msg: &Value) {
    let mut seen = BTreeSet::new();
    for t in msg["transforms"].as_array().unwrap() {
        let child = t["child_frame_id"].as_str().unwrap().to_owned();
        let parent = t["header"]["frame_id"].as_str().unwrap().to_owned();
        assert!(
            seen.insert(child.clone()),
            "child {child} repeated in one message"
        );
        assert_ne!(child, parent);
        let tr = (
            parent.clone(),
            vec3(&t["transform"]["translation"]),
            quat(&t["transform"]["rotation"]),
        );
        if let Some(old) = tree.insert(child.clone(), tr) {
            assert_eq!(old.0, parent, "{child} has two parents");
        }
    }
}

/// Pose of `frame` in `world` (translation, rotation) through the tree.
fn world_pose(tree: &Tree, frame: &str) -> ([f64; 3], [f64; 4]) {
    let mut p = [0.0; 3];
    let mut q = [0.0, 0.0, 0.0, 1.0];
    let mut at = frame;
    for _ in 0..16 {
        if at == "world" {
            return (p, q);
        }
        let (parent, t, r) = tree
            .get(at)
            .unwrap_or_else(|| panic!("frame {at} not in the tree"));
        let rp = rotate(*r, p);
        p = [rp[0] + t[0], rp[1] + t[1], rp[2] + t[2]];
        q = mul(*r, q);
        at = parent;
    }
    panic!("{frame}: no path to world (a cycle?)");
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1e-300)
}

/// Every check of the module doc on one decoded recording; returns (contacts, messages).
fn check(name: &str, summary: &Value, messages: &[Value], pressure: bool) -> (usize, usize) {
    let meta = &summary["metadata"]["softgrip"];
    let dt: f64 = meta["dt"].as_str().unwrap().parse().unwrap();
    let dt_ns = dt * 1e9;
    for (topic, m) in summary["channels"].as_object().unwrap() {
        let qos = m["offered_qos_profiles"]
            .as_str()
            .unwrap_or_else(|| panic!("{topic}: no QoS"));
        let durability = if topic == "/tf_static" { 1 } else { 2 };
        assert!(
            qos.contains(&format!("durability: {durability}\n")),
            "{topic}: {qos}"
        );
        let reliability = if topic == "/clock" { 2 } else { 1 };
        assert!(
            qos.contains(&format!("reliability: {reliability}\n")),
            "{topic}: {qos}"
        );
    }
    let mut tree = Tree::new();
    let mut used = BTreeSet::new();
    let mut marked = BTreeSet::new();
    let (mut contacts, mut statics) = (0, 0);
    let on_grid = |t: u64| {
        let k = (t as f64 / dt_ns).round();
        assert!(
            (t as f64 - (k * dt * 1e9).round()).abs() < 0.5,
            "{name}: stamp {t} ns is not k dt"
        );
    };
    for m in messages {
        let t = m["log_time"].as_u64().unwrap();
        on_grid(t);
        let msg = &m["msg"];
        match m["topic"].as_str().unwrap() {
            "/tf_static" => {
                statics += 1;
                add_transforms(&mut tree, msg);
            }
            "/tf" => add_transforms(&mut tree, msg),
            "/clock" => {
                let c = &msg["clock"];
                assert_eq!(
                    c["sec"].as_u64().unwrap() * 1_000_000_000 + c["nanosec"].as_u64().unwrap(),
                    t
                );
            }
            "/softgrip/contacts" => {
                assert_eq!(stamp_ns(&msg["header"]), t);
                for c in msg["contacts"].as_array().unwrap() {
                    contacts += 1;
                    used.insert(c["header"]["frame_id"].as_str().unwrap().to_owned());
                    let a = f(&c["contact_radius"]);
                    assert!(a > 0.0, "{name}: a contact of radius {a} at {t} ns");
                    let (x, x_max) = (f(&c["compression"]), f(&c["max_compression"]));
                    assert!(
                        x_max >= x,
                        "{name}: max_compression {x_max} < compression {x} at {t} ns"
                    );
                    let (fz, p) = (f(&c["normal_force"]), f(&c["mean_pressure"]));
                    if pressure {
                        assert!(
                            close(p * std::f64::consts::PI * a * a, fz, 1e-12),
                            "{p} {a} {fz}"
                        );
                    } else {
                        assert_eq!(p, 0.0);
                    }
                }
            }
            "/softgrip/markers" => {
                for mk in msg["markers"].as_array().unwrap() {
                    let frame = mk["header"]["frame_id"].as_str().unwrap().to_owned();
                    if mk["action"].as_i64() == Some(0) {
                        assert!(f(&mk["scale"]["x"]) > 0.0, "{name}: {mk}");
                        marked.insert(frame.clone());
                    }
                    used.insert(frame);
                }
            }
            topic if topic.ends_with("/wrench") => {
                let frame = msg["header"]["frame_id"].as_str().unwrap();
                assert_ne!(frame, "world", "{topic}: a wrench in the world frame");
                used.insert(frame.to_owned());
            }
            _ => {}
        }
    }
    assert_eq!(statics, 1, "{name}: /tf_static once");
    check_tree(name, &tree, &used, &marked);
    (contacts, messages.len())
}

/// One tree rooted at world; every used frame in it; every body with a marker.
fn check_tree(name: &str, tree: &Tree, used: &BTreeSet<String>, marked: &BTreeSet<String>) {
    // One tree rooted at world: every frame reaches it.
    let frames: BTreeSet<String> = tree.keys().cloned().chain(["world".to_owned()]).collect();
    for frame in tree.keys() {
        world_pose(tree, frame);
    }
    for frame in used {
        assert!(
            frames.contains(frame),
            "{name}: frame id {frame} is not in the tf tree"
        );
    }
    // Every body (a child of world) has a marker in its frame or in a frame it carries.
    for (child, (parent, ..)) in tree {
        if parent == "world" {
            let carried = tree
                .iter()
                .any(|(c, (p, ..))| p == child && marked.contains(c));
            assert!(
                marked.contains(child) || carried,
                "{name}: body {child} has no marker"
            );
        }
    }
}

#[test]
fn default_grasp_is_upright_with_one_tf_tree_and_every_body_drawn() {
    let text = std::fs::read_to_string(common::root().join("scenes/default.toml")).unwrap();
    let (summary, messages) = decode("default", &text);
    let (contacts, n) = check("default", &summary, &messages, false);
    assert!(contacts > 50, "{contacts}");
    // z-up: gravity in the world frame, and the table's slab faces +z in the world.
    let g: Vec<f64> =
        serde_json::from_str(summary["metadata"]["softgrip"]["gravity"].as_str().unwrap()).unwrap();
    assert_eq!(g, vec![0.0, 0.0, -9.81]);
    let mut tree = Tree::new();
    let mut table = None;
    for m in &messages {
        match m["topic"].as_str().unwrap() {
            "/tf" | "/tf_static" => add_transforms(&mut tree, &m["msg"]),
            "/softgrip/markers" if table.is_none() => {
                table = m["msg"]["markers"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .find(|mk| mk["header"]["frame_id"] == "table")
                    .cloned();
            }
            _ => {}
        }
    }
    let table = table.expect("a marker of the table");
    let (_, q_table) = world_pose(&tree, "table");
    let up = rotate(
        mul(q_table, quat(&table["pose"]["orientation"])),
        [0.0, 0.0, 1.0],
    );
    assert!((up[2] - 1.0).abs() < 1e-12, "table normal in world {up:?}");
    // The box rests on the table (z = its half height, 20 mm) at the start.
    let (p_box, _) = world_pose(&tree, "box");
    assert!(p_box[2] > 0.0, "box at {p_box:?}");
    eprintln!("default: {n} messages, {contacts} contacts, table normal {up:?}");
}

#[test]
fn cell_fingertip_named_like_its_body_gets_its_own_frame() {
    let text = std::fs::read_to_string(common::root().join("scenes/cell_live_hmsc.toml")).unwrap();
    let (summary, messages) = decode("cell", &text);
    let (contacts, n) = check("cell", &summary, &messages, true);
    assert!(contacts > 100, "{contacts}");
    let tf_static = messages
        .iter()
        .find(|m| m["topic"] == "/tf_static")
        .unwrap();
    let t = &tf_static["msg"]["transforms"][0];
    assert_eq!(
        (
            t["header"]["frame_id"].as_str(),
            t["child_frame_id"].as_str()
        ),
        (Some("sphere"), Some("sphere_tip"))
    );
    assert!(
        messages
            .iter()
            .any(|m| m["topic"] == "/softgrip/sphere/wrench"
                && m["msg"]["header"]["frame_id"] == "sphere_tip")
    );
    eprintln!("cell: {n} messages, {contacts} contacts");
}
