//! `ROS_DOMAIN_ID` is validated (an integer in 0..=232, unset or empty = 0) and a bad one is a
//! typed error before any participant exists.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_ros2::{
    Error, MAX_DOMAIN_ID, NodeOptions, Ros2Publisher, Ros2PublisherOptions, parse_domain_id,
};

#[test]
fn valid_domain_ids_parse() {
    for (text, id) in [
        ("0", 0),
        ("17", 17),
        ("101", 101),
        ("232", 232),
        (" 42\n", 42),
        ("", 0),
        ("007", 7),
    ] {
        assert_eq!(parse_domain_id(text).unwrap(), id, "{text:?}");
    }
    assert_eq!(MAX_DOMAIN_ID, 232);
}

#[test]
fn invalid_domain_ids_are_typed_errors_naming_the_value() {
    for text in [
        "233",
        "65536",
        "-1",
        "1.5",
        "abc",
        "4 2",
        "0x10",
        "+3",
        "99999999999999999999",
    ] {
        match parse_domain_id(text) {
            Err(Error::DomainId { value }) => assert_eq!(value, text),
            other => panic!("{text:?}: {other:?}"),
        }
        let msg = parse_domain_id(text).unwrap_err().to_string();
        assert!(
            msg.contains("ROS_DOMAIN_ID") && msg.contains("0..=232"),
            "{msg}"
        );
    }
}

#[test]
fn publisher_rejects_a_bad_domain_or_capacity_before_touching_the_network() {
    let bad_domain = Ros2PublisherOptions {
        node: NodeOptions {
            domain_id: Some(233),
            ..Default::default()
        },
        ..Default::default()
    };
    assert!(matches!(
        Ros2Publisher::new(&bad_domain),
        Err(Error::DomainId { value }) if value == "233"
    ));
    let no_room = Ros2PublisherOptions {
        queue_capacity: 0,
        ..Default::default()
    };
    assert!(matches!(
        Ros2Publisher::new(&no_room),
        Err(Error::QueueCapacity)
    ));
}

#[test]
fn probe_reports_a_bad_ros_domain_id_and_exits() {
    // In a private namespace all the same: if validation were broken, the probe would join
    // the DDS network.
    for value in ["233", "abc", "-5"] {
        let out = common::in_private_netns(
            r#"exec "$0" --timeout-s 5"#,
            &[env!("CARGO_BIN_EXE_softgrip-ros2-probe")],
            &[("ROS_DOMAIN_ID", value)],
        );
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{value}: {stderr}");
        assert!(
            stderr.contains("ROS_DOMAIN_ID must be an integer in 0..=232")
                && stderr.contains(&format!("{value:?}")),
            "{value}: {stderr}"
        );
    }
}
