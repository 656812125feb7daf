//! THE EXTERNAL READER TEST: a fresh recording is decoded by an MCAP reader softgrip did not
//! write (Python `mcap` + `mcap-ros2-support`'s `read_ros2_messages`, which parse the embedded
//! `ros2msg` schema text), and every decoded value equals what was written (1e-12 relative for
//! floats, exact for strings, integers and flags).
//!
//! Needs `SOFTGRIP_PY`: a Python with those packages (`bash .ci/python-venv.sh` makes one in
//! `target/pyvenv` and prints the path).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::process::Command;

use serde_json::Value;
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{Recorder, RecorderOptions, RecordingInfo, StepRecord, topics};

const DT_NS: u64 = 1_000_000;
const STEPS: u64 = 300;

fn python() -> String {
    std::env::var("SOFTGRIP_PY").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PY is not set: it must name a Python with the PyPI packages `mcap` and \
             `mcap-ros2-support`. Create one with `bash .ci/python-venv.sh` (or \
             `python3 -m venv target/pyvenv && target/pyvenv/bin/pip install mcap mcap-ros2-support`) \
             and run `SOFTGRIP_PY=$PWD/target/pyvenv/bin/python cargo test -p softgrip-record`."
        )
    })
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn assert_close(got: &Value, want: f64, what: &str) {
    let g = f(got);
    assert!(
        common::close(g, want, 1e-12),
        "{what}: decoded {g}, wrote {want}"
    );
}

fn assert_vec3(got: &Value, want: [f64; 3], what: &str) {
    for (axis, w) in ["x", "y", "z"].iter().zip(want) {
        assert_close(&got[axis], w, &format!("{what}.{axis}"));
    }
}

fn assert_header(got: &Value, step: &StepRecord) {
    let stamp = &got["stamp"];
    let ns = stamp["sec"].as_u64().unwrap() * 1_000_000_000 + stamp["nanosec"].as_u64().unwrap();
    assert_eq!(ns, step.time_ns);
    assert_eq!(got["frame_id"], step.world_frame.as_str());
}

fn assert_contact(got: &Value, want: &SoftContactMsg, step: &StepRecord) {
    assert_header(&got["header"], step);
    assert_eq!(got["fingertip"], want.fingertip.as_str());
    assert_eq!(got["other"], want.other.as_str());
    assert_vec3(&got["point"], want.point.to_array(), "point");
    assert_vec3(&got["normal"], want.normal.to_array(), "normal");
    assert_vec3(
        &got["friction_force"],
        want.friction_force.to_array(),
        "friction_force",
    );
    assert_vec3(
        &got["patch_direction"],
        want.patch_direction.to_array(),
        "patch_direction",
    );
    for (name, w) in [
        ("compression", want.compression),
        ("ratio_x", want.ratio_x),
        ("normal_force", want.normal_force),
        ("torsional_moment", want.torsional_moment),
        ("contact_radius", want.contact_radius),
        ("mean_pressure", want.mean_pressure),
        ("peak_pressure", want.peak_pressure),
        ("stiffness", want.stiffness),
        ("peak_normal_force", want.peak_normal_force),
        ("max_compression", want.max_compression),
        ("contact_duration", want.contact_duration),
        ("core_thickness", want.core_thickness),
        ("contact_radius2", want.contact_radius2),
        ("counterpart_curvature1", want.counterpart_curvature1),
        ("counterpart_curvature2", want.counterpart_curvature2),
    ] {
        assert_close(&got[name], w, name);
    }
    assert_eq!(got["backing"].as_u64(), Some(u64::from(want.backing)));
    assert_eq!(
        got["counterpart"].as_u64(),
        Some(u64::from(want.counterpart))
    );
    assert_eq!(got["level"].as_u64(), Some(u64::from(want.level)));
    assert_eq!(got["level_name"], want.level_name.as_str());
    assert_eq!(
        got["validity_exceeded"].as_bool(),
        Some(want.validity_exceeded)
    );
    assert_eq!(got["sliding"].as_bool(), Some(want.sliding));
}

#[test]
fn python_mcap_ros2_decodes_every_message() {
    let python = python();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("squeeze.mcap");
    let info = RecordingInfo {
        scene: "external reader test".into(),
        ..Default::default()
    };
    // Small chunks, so the reader crosses many chunk boundaries.
    let options = RecorderOptions {
        chunk_size: 32 * 1024,
        ..Default::default()
    };
    let mut rec = Recorder::with_options(&path, &info, &options).unwrap();
    let mut steps = Vec::new();
    for k in 0..STEPS {
        let mut s = common::step(k, DT_NS);
        rec.write_step(&mut s).unwrap();
        steps.push(s);
    }
    let stats = rec.finish().unwrap();

    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/python/read_recording.py"
    );
    let out = Command::new(&python)
        .arg(script)
        .arg(&path)
        .output()
        .unwrap_or_else(|e| panic!("cannot run SOFTGRIP_PY={python}: {e}"));
    assert!(
        out.status.success(),
        "the Python reader failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let (summary, messages) = lines.split_last().unwrap();
    let summary = &summary["summary"];
    assert_eq!(summary["messages"].as_u64(), Some(stats.messages));
    assert_eq!(
        summary["statistics_messages"].as_u64(),
        Some(stats.messages)
    );
    assert_eq!(summary["chunks"].as_u64(), Some(u64::from(stats.chunks)));
    assert_eq!(
        summary["chunk_indexes"].as_u64(),
        Some(u64::from(stats.chunks))
    );
    assert!(stats.chunks > 5, "{stats:?}");
    assert_eq!(summary["profile"], "ros2");
    let meta = &summary["metadata"]["softgrip"];
    assert_eq!(meta["scene"], "external reader test");
    assert_eq!(meta["softgrip_version"], softgrip_record::SOFTGRIP_VERSION);

    // File order: per step clock, tf, contacts, one wrench per fingertip, markers.
    let mut it = messages.iter();
    let mut counted = 0;
    for step in &steps {
        let mut next = |topic: &str, schema: &str| {
            let m = it.next().expect("fewer messages than written");
            assert_eq!(m["topic"], topic);
            assert_eq!(m["schema"], schema);
            assert_eq!(m["schema_encoding"], "ros2msg");
            assert_eq!(m["encoding"], "cdr");
            assert_eq!(m["log_time"].as_u64(), Some(step.time_ns));
            assert_eq!(m["publish_time"].as_u64(), Some(step.time_ns));
            counted += 1;
            m["msg"].clone()
        };
        let clock = next(topics::CLOCK, "rosgraph_msgs/msg/Clock");
        assert_eq!(
            clock["clock"]["sec"].as_u64(),
            Some(step.time_ns / 1_000_000_000)
        );
        assert_eq!(
            clock["clock"]["nanosec"].as_u64(),
            Some(step.time_ns % 1_000_000_000)
        );

        let tf = next(topics::TF, "tf2_msgs/msg/TFMessage");
        let transforms = tf["transforms"].as_array().unwrap();
        let want = step.tf().transforms;
        assert_eq!(transforms.len(), want.len());
        for (g, w) in transforms.iter().zip(&want) {
            assert_header(&g["header"], step);
            assert_eq!(g["child_frame_id"], w.child_frame_id.as_str());
            assert_vec3(
                &g["transform"]["translation"],
                w.transform.translation.to_array(),
                "t",
            );
            let q = &g["transform"]["rotation"];
            let wq = w.transform.rotation;
            for (k, v) in [("x", wq.x), ("y", wq.y), ("z", wq.z), ("w", wq.w)] {
                assert_close(&q[k], v, "rotation");
            }
        }

        let contacts = next(topics::CONTACTS, "softgrip_msgs/msg/SoftContactArray");
        assert_header(&contacts["header"], step);
        let got = contacts["contacts"].as_array().unwrap();
        assert_eq!(got.len(), step.contacts.len());
        for (g, w) in got.iter().zip(&step.contacts) {
            assert_contact(g, w, step);
        }

        for tip in &step.fingertips {
            let w = next(
                &topics::wrench(&tip.name),
                "geometry_msgs/msg/WrenchStamped",
            );
            assert_eq!(w["header"]["frame_id"], step.frame_of(tip));
            assert_vec3(&w["wrench"]["force"], tip.wrench.force.to_array(), "force");
            assert_vec3(
                &w["wrench"]["torque"],
                tip.wrench.torque.to_array(),
                "torque",
            );
        }

        let markers = next(topics::MARKERS, "visualization_msgs/msg/MarkerArray");
        let got = markers["markers"].as_array().unwrap();
        let want = softgrip_record::visuals::markers(step).markers;
        assert_eq!(got.len(), want.len());
        for (g, w) in got.iter().zip(&want) {
            assert_eq!(g["ns"], w.ns.as_str());
            assert_eq!(g["id"].as_i64(), Some(i64::from(w.id)));
            assert_eq!(g["type"].as_i64(), Some(i64::from(w.r#type)));
            assert_eq!(g["action"].as_i64(), Some(i64::from(w.action)));
            assert_vec3(
                &g["pose"]["position"],
                w.pose.position.to_array(),
                "marker position",
            );
            assert_vec3(&g["scale"], w.scale.to_array(), "marker scale");
            // float32 colour: exact in JSON as the f32's value.
            assert_eq!(f(&g["color"]["a"]), f64::from(w.color.a));
            assert_eq!(g["frame_locked"].as_bool(), Some(w.frame_locked));
            assert_eq!(g["header"]["frame_id"], w.header.frame_id.as_str());
            let points = g["points"].as_array().unwrap();
            assert_eq!(points.len(), w.points.len());
            for (p, q) in points.iter().zip(&w.points) {
                assert_vec3(p, q.to_array(), "marker point");
            }
            assert_eq!(g["mesh_use_embedded_materials"].as_bool(), Some(false));
        }
    }
    assert!(it.next().is_none(), "more messages than written");
    assert_eq!(counted, stats.messages);
    eprintln!(
        "python mcap-ros2-support decoded {counted} messages in {} chunks",
        stats.chunks
    );
}
