//! `/tf_static` is transient local (issue 12 item 2, tf2's `StaticBroadcasterQoS`): a subscriber
//! that joins after the publisher sent it, with nothing published since, still receives it,
//! value for value. The control: a subscriber of the volatile `/softgrip/contacts` that joins at
//! the same time receives none of the steps published before it (so the test sees durability,
//! not a late send). Inside a private network namespace:
//! the `#[ignore]`d test is run there by its `*_in_private_netns` parent.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;
#[path = "../src/bin/softgrip-ros2-probe/script.rs"]
mod script;

use std::time::{Duration, Instant};

use softgrip_record::msgs::geometry_msgs::{Quaternion, Transform, TransformStamped, Vector3};
use softgrip_record::msgs::softgrip_msgs::SoftContactArrayMsg;
use softgrip_record::msgs::std_msgs::Header;
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_ros2::{NodeOptions, Ros2Publisher, Ros2PublisherOptions, Ros2Subscriber, qos};

const DOMAIN: u16 = 23;

/// The static frames: each fingertip on its body, non-round offsets and a turned frame.
fn tf_static() -> TFMessage {
    let frame = |child: &str, parent: &str, t: [f64; 3], q: [f64; 4]| TransformStamped {
        header: Header::new(script::time_ns(0), parent),
        child_frame_id: child.to_owned(),
        transform: Transform {
            translation: Vector3::from_array(t),
            rotation: Quaternion {
                x: q[0],
                y: q[1],
                z: q[2],
                w: q[3],
            },
        },
    };
    let h = std::f64::consts::FRAC_1_SQRT_2;
    TFMessage {
        transforms: vec![
            frame(
                "thumb",
                "jaw_left",
                [0.0125, -1.0 / 3.0 * 1e-3, 7e-4],
                [0.0, 0.0, 0.0, 1.0],
            ),
            frame(
                "index_finger",
                "jaw_right",
                [-0.0125, 2e-5, 0.1],
                [0.0, h, 0.0, h],
            ),
        ],
    }
}

fn node(name: &str) -> NodeOptions {
    NodeOptions {
        domain_id: Some(DOMAIN),
        name: name.into(),
        ..Default::default()
    }
}

#[test]
fn late_subscriber_gets_tf_static_in_private_netns() {
    common::run_ignored_test_in_netns("late_subscriber_gets_tf_static");
}

#[test]
#[ignore = "creates DDS participants: run by late_subscriber_gets_tf_static_in_private_netns"]
fn late_subscriber_gets_tf_static() {
    common::assert_isolated();
    let publisher = Ros2Publisher::new(&Ros2PublisherOptions {
        node: node("softgrip_sim"),
        ..Default::default()
    })
    .unwrap();
    let sent = tf_static();
    for k in 0..script::STEPS {
        let mut s = script::step(k);
        s.tf_static = (k == 0).then(|| sent.clone());
        publisher.publish_step_owned(s).unwrap();
    }
    // Every step handed to DDS before anyone subscribes; then nothing more is published.
    let deadline = Instant::now() + Duration::from_secs(10);
    while publisher.stats().published < script::STEPS {
        assert!(Instant::now() < deadline, "{:?}", publisher.stats());
        std::thread::sleep(Duration::from_millis(10));
    }
    assert_eq!(publisher.stats().publish_failures, 0);

    // The late joiners, as tf2_ros::StaticTransformListener subscribes (transient local) and
    // as a volatile subscriber would.
    let joined = Instant::now();
    let latched =
        Ros2Subscriber::<TFMessage>::new(&node("late_listener"), "/tf_static", qos::tf_static())
            .unwrap();
    let volatile = Ros2Subscriber::<SoftContactArrayMsg>::new(
        &node("late_volatile"),
        softgrip_record::topics::CONTACTS,
        qos::data(),
    )
    .unwrap();

    let deadline = joined + Duration::from_secs(60);
    let got = loop {
        assert!(
            Instant::now() < deadline,
            "the late transient-local subscriber got no /tf_static within 60 s"
        );
        if let Some(m) = latched.recv_timeout(Duration::from_millis(100)).unwrap() {
            break m;
        }
    };
    let latency = joined.elapsed();
    assert_eq!(got, sent, "what the late subscriber received");
    // Exactly once: keep-last 1 and a single write.
    assert!(
        latched
            .recv_timeout(Duration::from_millis(500))
            .unwrap()
            .is_none()
    );
    // The volatile one joined at the same time and has had at least as long: no history.
    let wait = latency.max(Duration::from_secs(1));
    let old = volatile.recv_timeout(wait).unwrap();
    assert!(
        old.is_none(),
        "a late subscriber of the volatile /softgrip/contacts received an old step: {:?}",
        old.map(|m| m.header.stamp)
    );
    let stats = publisher.close(Duration::from_secs(5)).unwrap();
    assert_eq!(stats.published, script::STEPS);
    eprintln!(
        "late transient-local subscriber: /tf_static ({} transforms) {latency:?} after joining; \
         volatile subscriber: nothing in {wait:?}",
        got.transforms.len()
    );
}
