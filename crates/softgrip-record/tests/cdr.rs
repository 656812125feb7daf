//! CDR: exact bytes of known encodings, round trips of every type, and typed errors (never a
//! panic) for every truncation and for invalid bytes.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use proptest::prelude::*;
use softgrip_record::RosMessage;
use softgrip_record::cdr::{CdrError, CdrWriter};
use softgrip_record::msgs::builtin_interfaces::{Duration, Time};
use softgrip_record::msgs::geometry_msgs::*;
use softgrip_record::msgs::rosgraph_msgs::Clock;
use softgrip_record::msgs::sensor_msgs::{CompressedImage, Image};
use softgrip_record::msgs::softgrip_msgs::{SoftContactArrayMsg, SoftContactMsg};
use softgrip_record::msgs::std_msgs::{ColorRGBA, Header};
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_record::msgs::visualization_msgs::*;
use softgrip_record::visuals;

#[test]
fn header_bytes_by_hand() {
    let h = Header {
        stamp: Time { sec: 1, nanosec: 2 },
        frame_id: "world".into(),
    };
    #[rustfmt::skip]
    let expected = [
        0x00, 0x01, 0x00, 0x00, // encapsulation: CDR little-endian
        0x01, 0x00, 0x00, 0x00, // stamp.sec = 1        (payload offset 0)
        0x02, 0x00, 0x00, 0x00, // stamp.nanosec = 2    (4)
        0x06, 0x00, 0x00, 0x00, // frame_id length 6 = "world" + NUL (8)
        b'w', b'o', b'r', b'l', b'd', 0x00, // (12..18)
    ];
    assert_eq!(h.to_cdr(), expected);
    assert_eq!(Header::from_cdr(&expected).unwrap(), h);
}

#[test]
fn wrench_stamped_bytes_by_hand() {
    // After the header (18 payload bytes) the first float64 is aligned to 24: 6 zero bytes.
    let w = WrenchStamped {
        header: Header {
            stamp: Time { sec: 1, nanosec: 2 },
            frame_id: "world".into(),
        },
        wrench: Wrench {
            force: Vector3 {
                x: 1.0,
                y: -2.0,
                z: 0.5,
            },
            torque: Vector3 {
                x: 0.0,
                y: 0.0,
                z: 1e-3,
            },
        },
    };
    let bytes = w.to_cdr();
    assert_eq!(bytes.len(), 4 + 24 + 6 * 8);
    assert_eq!(&bytes[22..28], &[0u8; 6]);
    assert_eq!(&bytes[28..36], &1.0f64.to_le_bytes());
    assert_eq!(&bytes[36..44], &(-2.0f64).to_le_bytes());
    assert_eq!(&bytes[68..76], &1e-3f64.to_le_bytes());
    assert_eq!(WrenchStamped::from_cdr(&bytes).unwrap(), w);
}

#[test]
fn empty_strings_and_sequences() {
    // An empty string is length 1 and a NUL; an empty sequence is a zero count.
    let mut w = CdrWriter::new();
    w.encode(&("", Vec::<u8>::new()));
    assert_eq!(
        w.as_bytes(),
        &[0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
    );
    let img = CompressedImage::default();
    assert_eq!(CompressedImage::from_cdr(&img.to_cdr()).unwrap(), img);
}

fn roundtrip<M: RosMessage + PartialEq + std::fmt::Debug>(m: &M) {
    let bytes = m.to_cdr();
    assert_eq!(&bytes[..4], &[0, 1, 0, 0]);
    assert_eq!(&M::from_cdr(&bytes).unwrap(), m, "{}", M::TYPE_NAME);
    // Every strict prefix is a typed error, never a panic (at most 3 bytes of padding may be
    // missing at the very end, which CDR allows).
    for cut in 0..bytes.len().saturating_sub(3) {
        assert!(
            M::from_cdr(&bytes[..cut]).is_err(),
            "{} cut at {cut}",
            M::TYPE_NAME
        );
    }
    // Trailing garbage is rejected.
    let mut longer = bytes.clone();
    longer.extend_from_slice(&[0; 8]);
    assert!(matches!(
        M::from_cdr(&longer),
        Err(CdrError::TrailingBytes { extra: 8 })
    ));
}

#[test]
fn every_type_round_trips() {
    let step = common::step(17, 1_000_000);
    let header = step.header();
    roundtrip(&Time {
        sec: -3,
        nanosec: 999_999_999,
    });
    roundtrip(&Duration { sec: 7, nanosec: 1 });
    roundtrip(&header);
    roundtrip(&ColorRGBA::new(0.1, 0.2, 0.3, 0.4));
    roundtrip(&Point {
        x: 1.0,
        y: f64::MIN_POSITIVE,
        z: -0.0,
    });
    roundtrip(&Vector3 {
        x: 1e300,
        y: -1e-300,
        z: 3.0,
    });
    roundtrip(&Quaternion::z_to([0.3, -0.2, 0.9]));
    roundtrip(&Pose::default());
    roundtrip(&Transform::default());
    roundtrip(&step.tf().transforms[0]);
    roundtrip(&step.tf());
    roundtrip(&step.fingertips[0].wrench);
    roundtrip(&WrenchStamped {
        header: header.clone(),
        wrench: step.fingertips[1].wrench,
    });
    roundtrip(&Clock {
        clock: Time::from_nanos(123_456_789_012),
    });
    roundtrip(&step.contacts[0]);
    roundtrip(&SoftContactArrayMsg {
        header: header.clone(),
        contacts: step.contacts.clone(),
    });
    roundtrip(&visuals::markers(&step));
    roundtrip(&UVCoordinate { u: 0.25, v: 0.75 });
    roundtrip(&MeshFile {
        filename: "tip.stl".into(),
        data: vec![1, 2, 3, 255],
    });
    roundtrip(&CompressedImage {
        header: header.clone(),
        format: "png".into(),
        data: vec![9; 13],
    });
    let full = Marker {
        header,
        ns: "ns".into(),
        id: -4,
        r#type: Marker::TRIANGLE_LIST,
        action: Marker::ADD,
        frame_locked: true,
        points: vec![
            Point {
                x: 1.0,
                y: 2.0,
                z: 3.0
            };
            3
        ],
        colors: vec![ColorRGBA::new(1.0, 0.0, 0.0, 1.0); 3],
        texture_resource: "embedded://tex".into(),
        texture: CompressedImage {
            format: "png".into(),
            data: vec![1, 2],
            ..Default::default()
        },
        uv_coordinates: vec![UVCoordinate { u: 0.5, v: 0.5 }; 3],
        text: "ünïcode".into(),
        mesh_resource: "embedded://mesh".into(),
        mesh_file: MeshFile {
            filename: "m.stl".into(),
            data: vec![0; 5],
        },
        mesh_use_embedded_materials: true,
        lifetime: Duration { sec: 1, nanosec: 5 },
        ..Default::default()
    };
    roundtrip(&full);
    roundtrip(&MarkerArray {
        markers: vec![full.clone(), Marker::default(), full],
    });
}

#[test]
fn invalid_bytes_are_typed_errors() {
    assert!(matches!(
        Header::from_cdr(&[0, 1]),
        Err(CdrError::MissingHeader { len: 2 })
    ));
    assert!(matches!(
        Header::from_cdr(&[0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 0]),
        Err(CdrError::UnsupportedEncapsulation { kind: 0 })
    ));
    // frame_id claims 2^31 bytes: more than the buffer holds.
    let mut b = Header::default().to_cdr();
    b[12..16].copy_from_slice(&0x8000_0000u32.to_le_bytes());
    assert!(matches!(Header::from_cdr(&b), Err(CdrError::UnexpectedEnd)));
    // A sequence claiming 2^32 - 1 elements fails without allocating them.
    let mut b = TFMessage::default().to_cdr();
    b[4..8].copy_from_slice(&u32::MAX.to_le_bytes());
    assert!(matches!(
        TFMessage::from_cdr(&b),
        Err(CdrError::UnexpectedEnd)
    ));
    // No NUL terminator: cdr-encoding (as RustDDS) reads the string without its last byte.
    let mut b = Header {
        frame_id: "ab".into(),
        ..Default::default()
    }
    .to_cdr();
    let last = b.len() - 1;
    b[last] = b'c';
    assert_eq!(Header::from_cdr(&b).unwrap().frame_id, "ab");
    // Not UTF-8.
    let mut b = Header {
        frame_id: "ab".into(),
        ..Default::default()
    }
    .to_cdr();
    b[16] = 0xff;
    assert!(matches!(Header::from_cdr(&b), Err(CdrError::InvalidUtf8)));
    // A bool byte of 2.
    let c = SoftContactMsg {
        sliding: true,
        ..Default::default()
    };
    let mut b = c.to_cdr();
    let pos = b.iter().rposition(|&x| x == 1).unwrap();
    b[pos] = 2;
    assert!(SoftContactMsg::from_cdr(&b).is_err());
}

proptest! {
    #[test]
    fn soft_contact_round_trips(
        values in proptest::collection::vec(proptest::num::f64::ANY, 17),
        level in 0u8..8,
        name in "[a-zA-Z0-9 _-]{0,12}",
        flags in (any::<bool>(), any::<bool>()),
        sec in any::<i32>(), nanosec in 0u32..1_000_000_000,
    ) {
        let v = |i: usize| values[i];
        let c = SoftContactMsg {
            header: Header { stamp: Time { sec, nanosec }, frame_id: name.clone() },
            fingertip: name.clone(),
            other: format!("{name}-other"),
            point: Point { x: v(0), y: v(1), z: v(2) },
            normal: Vector3 { x: v(3), y: v(4), z: v(5) },
            compression: v(6), ratio_x: v(7), normal_force: v(8),
            friction_force: Vector3 { x: v(9), y: v(10), z: v(11) },
            torsional_moment: v(12), contact_radius: v(13), mean_pressure: v(14),
            peak_pressure: v(15), stiffness: v(16),
            level, level_name: name.clone(),
            validity_exceeded: flags.0, sliding: flags.1,
            peak_normal_force: v(1), max_compression: v(2), contact_duration: v(3),
            backing: level % 3, core_thickness: v(4),
            contact_radius2: v(5), patch_direction: Vector3 { x: v(6), y: v(7), z: v(8) },
            counterpart: level % 3, counterpart_curvature1: v(9), counterpart_curvature2: v(10),
        };
        let back = SoftContactMsg::from_cdr(&c.to_cdr()).unwrap();
        // Compare bit patterns: NaN != NaN.
        prop_assert_eq!(back.to_cdr(), c.to_cdr());
    }

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..300)) {
        let mut b = vec![0u8, 1, 0, 0];
        b.extend_from_slice(&bytes);
        let _ = MarkerArray::from_cdr(&b);
        let _ = SoftContactArrayMsg::from_cdr(&b);
        let _ = TFMessage::from_cdr(&b);
    }
}

/// A tactile image: `32FC1`, little-endian pressures, and the CDR layout of `sensor_msgs/Image`
/// (header, height, width, encoding, is_bigendian, step, data).
#[test]
fn tactile_image_bytes() {
    let img = Image::tactile(
        Header::new(1_500_000_000, "tip"),
        2,
        2,
        &[0.0, 1.0, 2.5e4, -0.0],
    );
    roundtrip(&img);
    assert_eq!(
        (img.height, img.width, img.step, img.is_bigendian),
        (2, 2, 8, 0)
    );
    assert_eq!(&img.data[4..8], &1.0f32.to_le_bytes());
    assert_eq!(img.pixels_f32(), vec![0.0, 1.0, 2.5e4, -0.0]);
    let bytes = img.to_cdr();
    // encapsulation 4, stamp 8, frame_id "tip\0" (4 + 4), height, width: then "32FC1\0".
    assert_eq!(&bytes[20..28], &[2, 0, 0, 0, 2, 0, 0, 0]);
    assert_eq!(&bytes[28..32], &6u32.to_le_bytes());
    assert_eq!(&bytes[32..38], b"32FC1\0");
    // The last 16 bytes are the pixels, after their count 16.
    assert_eq!(
        &bytes[bytes.len() - 20..bytes.len() - 16],
        &16u32.to_le_bytes()
    );
}
