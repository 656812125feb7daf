//! The bounded queue between the simulation and the publisher thread: a push never waits; a
//! full queue drops its OLDEST item and counts it; nothing is lost or reordered otherwise.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::sync::Arc;
use std::time::{Duration, Instant};

use softgrip_ros2::queue::{DropOldestQueue, Popped, Pushed};

#[test]
fn full_queue_drops_the_oldest_and_counts() {
    let q = DropOldestQueue::new(3);
    for i in 1..=10 {
        let want = if i <= 3 {
            Pushed::Queued
        } else {
            Pushed::DroppedOldest
        };
        assert_eq!(q.push(i), want, "push {i}");
    }
    assert_eq!(q.dropped(), 7);
    assert_eq!(q.len(), 3);
    // The newest three survive, oldest first.
    assert_eq!(
        [q.try_pop(), q.try_pop(), q.try_pop(), q.try_pop()],
        [Some(8), Some(9), Some(10), None]
    );
}

#[test]
fn zero_capacity_means_one() {
    let q = DropOldestQueue::new(0);
    assert_eq!(q.capacity(), 1);
    q.push('a');
    q.push('b');
    assert_eq!((q.try_pop(), q.dropped()), (Some('b'), 1));
}

#[test]
fn closed_queue_drains_then_reports_closed_and_counts_late_pushes() {
    let q = DropOldestQueue::new(4);
    q.push(1);
    q.push(2);
    q.close();
    assert_eq!(q.push(3), Pushed::Closed);
    assert_eq!(q.dropped(), 1);
    let soon = Duration::from_millis(1);
    assert_eq!(q.pop_timeout(soon), Popped::Item(1));
    assert_eq!(q.pop_timeout(soon), Popped::Item(2));
    assert_eq!(q.pop_timeout(soon), Popped::Closed);
}

#[test]
fn pop_waits_only_until_its_deadline() {
    let q = DropOldestQueue::<u8>::new(1);
    let t = Instant::now();
    assert_eq!(q.pop_timeout(Duration::from_millis(20)), Popped::TimedOut);
    assert!(t.elapsed() >= Duration::from_millis(20));
}

#[test]
fn concurrent_producer_and_slow_consumer_lose_only_counted_items_in_order() {
    const N: u64 = 200_000;
    let q = Arc::new(DropOldestQueue::new(8));
    let consumer = {
        let q = Arc::clone(&q);
        std::thread::spawn(move || {
            let mut got = Vec::new();
            loop {
                match q.pop_timeout(Duration::from_secs(10)) {
                    Popped::Item(i) => {
                        got.push(i);
                        if got.len() % 64 == 0 {
                            std::thread::sleep(Duration::from_micros(200)); // a slow network
                        }
                    }
                    Popped::Closed => return got,
                    Popped::TimedOut => panic!("producer stalled"),
                }
            }
        })
    };
    for i in 0..N {
        q.push(i);
    }
    q.close();
    let got = consumer.join().unwrap();
    assert!(got.windows(2).all(|w| w[0] < w[1]), "reordered");
    assert_eq!(got.len() as u64 + q.dropped(), N, "lost without a count");
    assert_eq!(*got.last().unwrap(), N - 1, "the newest item must survive");
    eprintln!(
        "{N} pushed, {} delivered, {} dropped",
        got.len(),
        q.dropped()
    );
}
