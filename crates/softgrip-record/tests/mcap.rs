//! MCAP: write -> read back (after decoding, with tolerances), finished on drop and on panic,
//! recovery of unfinished files (cut at many points, writer forgotten or killed), and typed
//! errors for damaged ones.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::Path;

use softgrip_law::Level;
use softgrip_record::msgs::geometry_msgs::Point;
use softgrip_record::{
    Error, FingertipLaw, Message, Recorder, RecorderOptions, Recording, RecordingInfo, StepRecord,
    topics,
};

const DT_NS: u64 = 1_000_000;

fn info() -> RecordingInfo {
    RecordingInfo {
        scene: "two fingers squeeze a box".into(),
        law: vec![FingertipLaw {
            name: "tip".into(),
            level: Level::Calibrated,
            youngs_modulus: 3e6,
            poisson_ratio: 0.49,
            radius: 0.01,
            friction: 0.8,
            restitution: 0.5,
            backing: softgrip_law::Backing::Free,
            curve: None,
            custom_name: None,
        }],
        ..Default::default()
    }
}

fn write(path: &Path, steps: u64, options: &RecorderOptions) -> Vec<StepRecord> {
    let mut rec = Recorder::with_options(path, &info(), options).unwrap();
    let mut written = Vec::new();
    for k in 0..steps {
        let mut s = common::step(k, DT_NS);
        rec.write_step(&mut s).unwrap();
        written.push(s);
    }
    let stats = rec.finish().unwrap();
    assert_eq!(
        stats.messages,
        written.iter().map(messages_per_step).sum::<u64>()
    );
    written
}

fn messages_per_step(s: &StepRecord) -> u64 {
    4 + s.fingertips.len() as u64
}

fn assert_contacts_match(rec: &Recording, written: &[StepRecord]) {
    let contacts: Vec<_> = rec.on_topic(topics::CONTACTS).collect();
    assert!(contacts.len() <= written.len());
    for (m, s) in contacts.iter().zip(written) {
        assert_eq!(m.log_time_ns, s.time_ns);
        assert_eq!(m.publish_time_ns, s.time_ns);
        let Message::Contacts(a) = &m.message else {
            panic!("wrong type on {}", m.topic)
        };
        assert_eq!(a.header.stamp.as_nanos(), s.time_ns);
        assert_eq!(a.contacts.len(), s.contacts.len());
        for (got, want) in a.contacts.iter().zip(&s.contacts) {
            assert_eq!(got.fingertip, want.fingertip);
            assert_eq!(
                (got.level, got.level_name.as_str()),
                (want.level, want.level_name.as_str())
            );
            assert_eq!(
                (got.sliding, got.validity_exceeded),
                (want.sliding, want.validity_exceeded)
            );
            for (g, w) in [
                (got.normal_force, want.normal_force),
                (got.compression, want.compression),
                (got.contact_radius, want.contact_radius),
                (got.torsional_moment, want.torsional_moment),
                (got.friction_force.y, want.friction_force.y),
                (got.point.z, want.point.z),
            ] {
                assert!(common::close(g, w, 1e-12), "{g} vs {w}");
            }
        }
    }
}

#[test]
fn write_then_read_back() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("squeeze.mcap");
    let written = write(&path, 500, &RecorderOptions::default());
    let rec = Recording::open(&path).unwrap();
    assert!(!rec.recovered());
    assert_eq!(
        rec.softgrip_metadata("scene"),
        Some("two fingers squeeze a box")
    );
    assert_eq!(
        rec.softgrip_metadata("softgrip_version"),
        Some(softgrip_record::SOFTGRIP_VERSION)
    );
    // The typed record reads back what was written.
    assert_eq!(rec.info().unwrap(), Some(info()));
    let topics: Vec<_> = rec.channels.iter().map(|c| c.topic.as_str()).collect();
    assert_eq!(
        topics,
        [
            "/clock",
            "/tf",
            "/softgrip/contacts",
            "/softgrip/thumb/wrench",
            "/softgrip/index_finger/wrench",
            "/softgrip/markers"
        ]
    );
    assert!(
        rec.channels
            .iter()
            .all(|c| c.message_count == 500 && c.message_encoding == "cdr")
    );
    assert_contacts_match(&rec, &written);
    // Wrenches, tf and markers decode to what was written.
    let wrench: Vec<_> = rec.on_topic("/softgrip/thumb/wrench").collect();
    let Message::Wrench(w) = &wrench[123].message else {
        panic!()
    };
    assert!(common::close(
        w.wrench.force.x,
        written[123].fingertips[0].wrench.force.x,
        1e-12
    ));
    let tf: Vec<_> = rec.on_topic(topics::TF).collect();
    let Message::Tf(tf) = &tf[77].message else {
        panic!()
    };
    // Bodies only: the fingertips have frames of their own (on /tf_static in a scene's run).
    assert_eq!(tf.transforms.len(), 1);
    assert_eq!(tf.transforms[0].child_frame_id, "box");
    let markers: Vec<_> = rec.on_topic(topics::MARKERS).collect();
    let Message::Markers(m) = &markers[10].message else {
        panic!()
    };
    // DELETEALL, 2 fingertips, a patch and a force arrow per contact.
    assert_eq!(m.markers.len(), 1 + 2 + 2 * written[10].contacts.len());
    assert!(common::close(
        m.markers[3].scale.x,
        2.0 * written[10].contacts[0].contact_radius,
        1e-12
    ));
    assert_eq!(m.markers[3].pose.position, written[10].contacts[0].point);
    let clock: Vec<_> = rec.on_topic(topics::CLOCK).collect();
    let Message::Clock(c) = clock[499].message else {
        panic!()
    };
    assert_eq!(c.clock.as_nanos(), 499 * DT_NS);
}

#[test]
fn drop_finishes_the_file_and_so_does_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("dropped.mcap");
    {
        let mut rec = Recorder::create(&path, &info()).unwrap();
        rec.write_step(&mut common::step(0, DT_NS)).unwrap();
    }
    let rec = Recording::open(&path).unwrap();
    assert!(!rec.recovered());
    assert_eq!(rec.messages.len(), 6);

    let path = dir.path().join("panicked.mcap");
    let p = path.clone();
    let result = std::panic::catch_unwind(move || {
        let mut rec = Recorder::create(&p, &info()).unwrap();
        for k in 0..50 {
            rec.write_step(&mut common::step(k, DT_NS)).unwrap();
        }
        panic!("simulated failure mid-run");
    });
    assert!(result.is_err());
    let rec = Recording::open(&path).unwrap();
    assert!(!rec.recovered(), "the unwinding drop finished the file");
    assert_eq!(rec.messages.len(), 50 * 6);
}

/// A writer that disappears without running any destructor (as on SIGKILL: nothing buffered
/// in the process reaches the file) loses at most the open chunk.
#[test]
fn forgotten_writer_loses_at_most_one_chunk() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("killed.mcap");
    let options = RecorderOptions {
        chunk_size: 64 * 1024,
        ..Default::default()
    };
    let mut rec = Recorder::with_options(&path, &info(), &options).unwrap();
    let mut sizes = Vec::new();
    let mut written = Vec::new();
    for k in 0..3000 {
        let mut s = common::step(k, DT_NS);
        rec.write_step(&mut s).unwrap();
        sizes.push(s.contacts.len());
        written.push(s);
    }
    let total = rec.messages_written();
    std::mem::forget(rec);
    let read = Recording::open(&path).unwrap();
    let recovery = read.recovery.clone().expect("unfinished file is recovered");
    assert!(recovery.chunks >= 5, "{recovery:?}");
    let kept = read.messages.len() as u64;
    let lost = total - kept;
    // One step is ~2.8 KiB of CDR; a 64 KiB chunk holds ~23 steps (~140 messages).
    assert!(
        kept > 0 && lost < 200,
        "kept {kept} of {total} ({recovery:?})"
    );
    assert_contacts_match(&read, &written);
    eprintln!("forgotten writer: kept {kept} of {total} messages, lost {lost}; {recovery:?}");
}

#[test]
fn truncated_files_recover_or_fail_typed_never_panic() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("full.mcap");
    let options = RecorderOptions {
        chunk_size: 16 * 1024,
        ..Default::default()
    };
    let written = write(&path, 400, &options);
    let bytes = std::fs::read(&path).unwrap();
    let full = Recording::from_bytes(&bytes).unwrap();
    let mut last_kept = 0;
    let mut cuts: Vec<usize> = (0..64).collect();
    cuts.extend((0..bytes.len()).step_by(97));
    cuts.extend(bytes.len() - 64..bytes.len());
    for cut in cuts {
        match Recording::from_bytes(&bytes[..cut]) {
            Ok(r) => {
                assert!(r.recovered(), "cut at {cut} of {}", bytes.len());
                assert!(r.messages.len() <= full.messages.len());
                assert_eq!(r.messages[..], full.messages[..r.messages.len()]);
                assert_contacts_match(&r, &written);
                assert!(r.messages.len() >= last_kept, "monotone in the cut");
                last_kept = r.messages.len();
            }
            Err(Error::Truncated { .. } | Error::NotMcap) => assert!(cut < 8),
            Err(e) => panic!("cut at {cut}: unexpected {e}"),
        }
    }
    // The whole data section is kept when only the summary is cut off.
    assert_eq!(last_kept, full.messages.len());
}

#[test]
fn corrupt_bytes_are_typed_errors() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("full.mcap");
    write(
        &path,
        200,
        &RecorderOptions {
            chunk_size: 16 * 1024,
            ..Default::default()
        },
    );
    let bytes = std::fs::read(&path).unwrap();
    assert!(matches!(
        Recording::from_bytes(b"hello world, no mcap"),
        Err(Error::NotMcap)
    ));
    assert!(matches!(
        Recording::from_bytes(&bytes[..3]),
        Err(Error::Truncated { len: 3 })
    ));
    let mut errors = 0;
    let mut positions: Vec<usize> = (8..bytes.len()).step_by(101).collect();
    positions.extend(bytes.len() - 40..bytes.len() - 8);
    for i in positions {
        for flip in [0x01u8, 0x80, 0xff] {
            let mut b = bytes.clone();
            b[i] ^= flip;
            match Recording::from_bytes(&b) {
                Err(Error::Corrupt { .. } | Error::Decode { .. }) => errors += 1,
                Err(e) => panic!("byte {i}: unexpected {e}"),
                // A flip in a byte nobody checks (e.g. an index's padding) may pass; what is
                // read must then still be the recording.
                Ok(r) => assert_eq!(r.messages.len(), 200 * 6, "byte {i} ^ {flip:#x}"),
            }
        }
    }
    assert!(errors > 0);
}

#[test]
fn unknown_schema_is_kept_as_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("point.mcap");
    let mut rec = Recorder::create(&path, &info()).unwrap();
    rec.write(
        "/probe",
        5,
        &Point {
            x: 1.0,
            y: 2.0,
            z: 3.0,
        },
    )
    .unwrap();
    rec.finish().unwrap();
    let r = Recording::open(&path).unwrap();
    let Message::Other { schema_name, data } = &r.messages[0].message else {
        panic!()
    };
    assert_eq!(schema_name, "geometry_msgs/msg/Point");
    use softgrip_record::RosMessage;
    assert_eq!(Point::from_cdr(data).unwrap().y, 2.0);
}
