//! The schema text and the bytes agree: every Rust type's fields, in order, are the fields of
//! the `.msg` text it embeds (what Foxglove and mcap-ros2-support decode with).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::LevelKind;
use softgrip_record::RosMessage;
use softgrip_record::msgs::builtin_interfaces::{Duration, Time};
use softgrip_record::msgs::geometry_msgs::*;
use softgrip_record::msgs::rosgraph_msgs::Clock;
use softgrip_record::msgs::sensor_msgs::{CompressedImage, Image};
use softgrip_record::msgs::softgrip_msgs::{SoftContactArrayMsg, SoftContactMsg, code_constants};
use softgrip_record::msgs::std_msgs::{ColorRGBA, Header};
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_record::msgs::visualization_msgs::*;
use softgrip_record::schema::SCHEMA_SEPARATOR;

/// `(name, type)` of each field of a `.msg` text, constants and comments skipped.
fn msg_fields(text: &str) -> Vec<(String, String)> {
    text.lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
        .filter_map(|l| {
            let mut it = l.split_whitespace();
            let ty = it.next()?;
            let name = it.next()?;
            (!name.contains('=') && !l.contains('=')).then(|| (name.to_owned(), ty.to_owned()))
        })
        .collect()
}

/// The Rust type a `.msg` type maps to.
fn rust_type(msg_type: &str) -> String {
    if let Some(inner) = msg_type.strip_suffix("[]") {
        return format!("Vec<{}>", rust_type(inner));
    }
    match msg_type {
        "float64" => "f64".into(),
        "float32" => "f32".into(),
        "int32" => "i32".into(),
        "uint32" => "u32".into(),
        "int64" => "i64".into(),
        "uint64" => "u64".into(),
        "uint8" => "u8".into(),
        "bool" => "bool".into(),
        "string" => "String".into(),
        // softgrip_msgs types are suffixed `Msg` in Rust (`SoftContactMsg`), the ROS names are not.
        "SoftContact" | "SoftContactArray" => format!("{msg_type}Msg"),
        other => other.rsplit('/').next().unwrap_or(other).to_owned(),
    }
}

fn check<M: RosMessage>() {
    let def = M::DEFINITION;
    let expected: Vec<(String, String)> = msg_fields(def.text)
        .into_iter()
        .map(|(n, t)| (n, rust_type(&t)))
        .collect();
    let actual: Vec<(String, String)> = M::FIELDS
        .iter()
        .map(|(n, t)| (n.trim_start_matches("r#").to_owned(), t.replace(' ', "")))
        .collect();
    assert_eq!(actual, expected, "{}", M::TYPE_NAME);
    // Every message type a field uses is listed as a dependency (so the schema has it).
    let deps: Vec<String> = def
        .all_dependencies()
        .iter()
        .map(|d| d.short_name())
        .collect();
    for (_, t) in msg_fields(def.text) {
        let base = t.trim_end_matches("[]");
        if base.chars().next().is_some_and(|c| c.is_ascii_uppercase()) || base.contains('/') {
            let short = if base.contains('/') {
                base.to_owned()
            } else {
                format!("{}/{base}", def.ros2_name.split('/').next().unwrap())
            };
            assert!(deps.contains(&short), "{}: {short} missing", M::TYPE_NAME);
        }
    }
    // The full schema: the root, then one `MSG:` block per dependency.
    let text = M::schema_text();
    assert_eq!(
        text.matches(SCHEMA_SEPARATOR).count(),
        deps.len(),
        "{}",
        M::TYPE_NAME
    );
    for d in &deps {
        assert_eq!(text.matches(&format!("\nMSG: {d}\n")).count(), 1);
    }
}

#[test]
fn fields_match_msg_text() {
    check::<Time>();
    check::<Duration>();
    check::<Header>();
    check::<ColorRGBA>();
    check::<Point>();
    check::<Vector3>();
    check::<Quaternion>();
    check::<Pose>();
    check::<Transform>();
    check::<TransformStamped>();
    check::<Wrench>();
    check::<WrenchStamped>();
    check::<TFMessage>();
    check::<Clock>();
    check::<CompressedImage>();
    check::<Image>();
    check::<UVCoordinate>();
    check::<MeshFile>();
    check::<Marker>();
    check::<MarkerArray>();
    check::<SoftContactMsg>();
    check::<SoftContactArrayMsg>();
}

#[test]
fn marker_array_schema_lists_the_whole_tree() {
    let text = MarkerArray::schema_text();
    for d in [
        "visualization_msgs/Marker",
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/Pose",
        "geometry_msgs/Point",
        "geometry_msgs/Quaternion",
        "geometry_msgs/Vector3",
        "std_msgs/ColorRGBA",
        "builtin_interfaces/Duration",
        "sensor_msgs/CompressedImage",
        "visualization_msgs/UVCoordinate",
        "visualization_msgs/MeshFile",
    ] {
        assert!(text.contains(&format!("\nMSG: {d}\n")), "{d}");
    }
}

#[test]
fn msg_code_constants_are_exactly_the_law_tables() {
    // Every `uint8 LEVEL_*` / `uint8 BACKING_*` / `uint8 COUNTERPART_*` line of
    // SoftContact.msg, in file order, is the tables': no code missing, none extra, none
    // renumbered.
    let text = SoftContactMsg::DEFINITION.text;
    let in_file: Vec<&str> = text
        .lines()
        .filter(|l| {
            ["uint8 LEVEL_", "uint8 BACKING_", "uint8 COUNTERPART_"]
                .iter()
                .any(|p| l.starts_with(p))
        })
        .collect();
    assert_eq!(in_file, code_constants());
    assert!(in_file.contains(&"uint8 LEVEL_TABULATED=8"));
    assert!(in_file.contains(&"uint8 LEVEL_CUSTOM=9"));
    assert!(in_file.contains(&"uint8 COUNTERPART_CURVED=1"));
    // Each code written by a message reads back as its level, by code and by name.
    for row in softgrip_law::LEVELS.iter().filter(|r| r.kind.is_some()) {
        let kind = row.kind.unwrap();
        let mut c = SoftContactMsg::default();
        c.set_level(kind);
        assert_eq!((Some(c.level), c.level_name.as_str()), (row.code, row.name));
        assert_eq!(c.level_kind(), Some(kind));
    }
    let mut c = SoftContactMsg::default();
    c.set_level(LevelKind::Tatara);
    assert_eq!((c.level, c.level_name.as_str()), (6, "tatara"));
    c.level = 200;
    assert_eq!(c.level_kind(), None);
    for row in softgrip_law::BACKINGS {
        let backing = row.kind.with_parameter(0.004);
        let mut c = SoftContactMsg::default();
        c.set_backing(backing);
        assert_eq!(c.backing, row.code);
        assert_eq!(c.backing(), Some(backing));
    }
}
