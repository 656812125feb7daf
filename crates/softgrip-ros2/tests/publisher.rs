//! `Ros2Publisher` against a real DDS stack, inside a private network namespace (each
//! `#[ignore]`d test here is run there by its `*_in_private_netns` parent):
//! - `close()` with no subscriber anywhere returns promptly (no hang on an absent peer);
//! - flooding a tiny queue drops steps, counts every one (published + dropped = submitted),
//!   and the newest step is the one that arrives last (the OLDEST are dropped).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;
#[path = "../src/bin/softgrip-ros2-probe/script.rs"]
mod script;

use std::time::{Duration, Instant};

use softgrip_record::msgs::softgrip_msgs::SoftContactArrayMsg;
use softgrip_ros2::{NodeOptions, Ros2Publisher, Ros2PublisherOptions, Ros2Subscriber, qos};

fn options(domain: u16, queue_capacity: usize) -> Ros2PublisherOptions {
    Ros2PublisherOptions {
        node: NodeOptions {
            domain_id: Some(domain),
            ..Default::default()
        },
        queue_capacity,
    }
}

#[test]
fn close_without_peer_in_private_netns() {
    common::run_ignored_test_in_netns("close_without_peer");
}

#[test]
#[ignore = "creates a DDS participant: run by close_without_peer_in_private_netns"]
fn close_without_peer() {
    common::assert_isolated();
    let t = Instant::now();
    let publisher = Ros2Publisher::new(&options(5, 1024)).unwrap();
    let created = t.elapsed();
    assert_eq!(publisher.domain_id(), 5);
    for k in 0..500 {
        publisher
            .publish_step_owned(script::step(k % script::STEPS))
            .unwrap();
    }
    let t = Instant::now();
    let stats = publisher.close(Duration::from_secs(10)).unwrap();
    let closed = t.elapsed();
    // Room for all: nothing dropped, everything handed to DDS (which sends to no one).
    assert_eq!(stats.submitted, 500);
    assert_eq!((stats.published, stats.dropped), (500, 0));
    assert_eq!(stats.publish_failures, 0);
    assert_eq!(stats.queued, 0);
    // Bounded: far below the 10 s flush timeout (a hang would show here).
    assert!(closed < Duration::from_secs(10), "close took {closed:?}");
    eprintln!(
        "no peer: new() {created:?}, close() {closed:?} to publish the 500 queued steps \
         (6 messages each) and linger {:?}",
        softgrip_ros2::CLOSE_LINGER
    );
}

#[test]
fn full_queue_drops_oldest_in_private_netns() {
    common::run_ignored_test_in_netns("full_queue_drops_oldest");
}

#[test]
#[ignore = "creates DDS participants: run by full_queue_drops_oldest_in_private_netns"]
fn full_queue_drops_oldest() {
    common::assert_isolated();
    let publisher = Ros2Publisher::new(&options(9, 2)).unwrap();
    let sub = Ros2Subscriber::<SoftContactArrayMsg>::new(
        &NodeOptions {
            domain_id: Some(9),
            name: "softgrip_test".into(),
            ..Default::default()
        },
        softgrip_record::topics::CONTACTS,
        qos::data(),
    )
    .unwrap();

    // Discovery: publish a warm-up step until the subscriber has one (generous deadline).
    let deadline = Instant::now() + Duration::from_secs(30);
    let warm = script::step(0);
    loop {
        assert!(Instant::now() < deadline, "no discovery within 30 s");
        publisher.publish_step(&warm).unwrap();
        if sub
            .recv_timeout(Duration::from_millis(50))
            .unwrap()
            .is_some()
        {
            break;
        }
    }
    while sub.try_recv().unwrap().is_some() {}
    let before = publisher.stats();

    // Flood: stamps 1e12 + i, a queue of 2.
    const N: u64 = 5_000;
    let mut slowest = Duration::ZERO;
    for i in 0..N {
        let mut s = script::step(i % script::STEPS);
        s.time_ns = 1_000_000_000_000 + i;
        let t = Instant::now();
        publisher.publish_step_owned(s).unwrap();
        slowest = slowest.max(t.elapsed());
    }
    // The subscriber sees increasing stamps ending with the newest one (read while the
    // publisher is alive, as a live subscriber does).
    let last = 1_000_000_000_000 + N - 1;
    let mut stamps = Vec::new();
    let deadline = Instant::now() + Duration::from_secs(30);
    while stamps.last() != Some(&last) && Instant::now() < deadline {
        if let Some(m) = sub.recv_timeout(Duration::from_millis(100)).unwrap() {
            stamps.push(m.header.stamp.as_nanos());
        }
    }
    let stats = publisher.close(Duration::from_secs(5)).unwrap();
    assert_eq!(stats.submitted - before.submitted, N);
    assert_eq!(stats.published + stats.dropped, stats.submitted);
    assert!(
        stamps.windows(2).all(|w| w[0] < w[1]),
        "reordered: {stamps:?}"
    );
    assert_eq!(stamps.last(), Some(&last), "the newest step did not arrive");
    eprintln!(
        "flood of {N} steps into a queue of 2: {} published, {} dropped, {} received by the \
         subscriber (keep-last 10), slowest publish_step {slowest:?}",
        stats.published - before.published,
        stats.dropped,
        stamps.len()
    );
}
