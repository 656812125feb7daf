//! softgrip-record's CDR (serde through `cdr-encoding`, with its own encapsulation header and
//! framing) and the serde CDR that ros2-client publishes with
//! (RustDDS's `CDRSerializerAdapter`, the serialiser of every `ros2_client::Publisher`) give
//! identical bytes for every message softgrip publishes, and each decodes the other's bytes.
//! Strings of every length mod 8 move the later fields through every alignment.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

#[path = "../src/bin/softgrip-ros2-probe/script.rs"]
mod script;

use std::fmt::Debug;

use ros2_client::dds::rustdds::RepresentationIdentifier;
use ros2_client::dds::rustdds::no_key::{DeserializerAdapter, SerializerAdapter};
use ros2_client::dds::rustdds::{CDRDeserializerAdapter, CDRSerializerAdapter};
use serde::Serialize;
use serde::de::DeserializeOwned;
use softgrip_record::msgs::geometry_msgs::{Point, WrenchStamped};
use softgrip_record::msgs::rosgraph_msgs::Clock;
use softgrip_record::msgs::softgrip_msgs::SoftContactArrayMsg;
use softgrip_record::msgs::std_msgs::ColorRGBA;
use softgrip_record::msgs::visualization_msgs::{MarkerArray, UVCoordinate};
use softgrip_record::{RosMessage, StepRecord, visuals};

/// The RTPS serialized-payload header of CDR little-endian: representation id `00 01`, options
/// `00 00` (RTPS 10.2); softgrip-record's `to_cdr` starts with the same four bytes.
const CDR_LE_HEADER: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

fn check<M>(msg: &M) -> usize
where
    M: RosMessage + Serialize + DeserializeOwned + PartialEq + Debug,
{
    assert_eq!(
        <CDRSerializerAdapter<M> as SerializerAdapter<M>>::output_encoding(),
        RepresentationIdentifier::CDR_LE
    );
    let serde_payload = CDRSerializerAdapter::<M>::to_bytes(msg).unwrap();
    let mut serde_bytes = CDR_LE_HEADER.to_vec();
    serde_bytes.extend_from_slice(&serde_payload);
    let hand = msg.to_cdr();
    if let Some(i) = hand.iter().zip(&serde_bytes).position(|(a, b)| a != b) {
        panic!(
            "{}: first differing byte at {i}: hand-written {:02x?}, serde {:02x?}",
            M::TYPE_NAME,
            &hand[i..(i + 16).min(hand.len())],
            &serde_bytes[i..(i + 16).min(serde_bytes.len())]
        );
    }
    assert_eq!(hand.len(), serde_bytes.len(), "{}: length", M::TYPE_NAME);

    // Each side decodes the other's bytes to the same message.
    let by_serde: M =
        CDRDeserializerAdapter::<M>::from_bytes(&hand[4..], RepresentationIdentifier::CDR_LE)
            .unwrap();
    assert_eq!(&by_serde, msg, "{}: serde decoding", M::TYPE_NAME);
    assert_eq!(&M::from_cdr(&serde_bytes).unwrap(), msg, "{}", M::TYPE_NAME);
    hand.len()
}

/// The script's step with string lengths shifted by `pad` characters.
fn step(k: u64, pad: usize) -> StepRecord {
    let mut s = script::step(k % script::STEPS);
    let extra = "x".repeat(pad);
    s.world_frame.push_str(&extra);
    for c in &mut s.contacts {
        c.other.push_str(&extra);
    }
    for t in &mut s.fingertips {
        t.name.push_str(&extra);
    }
    s
}

fn contacts(s: &StepRecord) -> SoftContactArrayMsg {
    let header = s.header();
    let mut contacts = s.contacts.clone();
    for c in &mut contacts {
        c.header = header.clone();
    }
    SoftContactArrayMsg { header, contacts }
}

/// The step's markers, plus every optional field of a marker filled (points, colours, texture
/// bytes, uv coordinates, mesh bytes, text), so that each field type is exercised.
fn markers(s: &StepRecord, pad: usize) -> MarkerArray {
    let mut m = visuals::markers(s);
    let last = m.markers.last_mut().unwrap();
    last.points = vec![Point::from_array([1.0 / 3.0, -2.0, 1e-300]); 3];
    last.colors = vec![ColorRGBA::new(0.1, 0.2, 0.3, 1.0 / 3.0); 3];
    last.texture_resource = "t".repeat(pad);
    last.texture.format = "png".into();
    last.texture.data = (0..pad as u8 + 3).collect();
    last.uv_coordinates = vec![
        UVCoordinate {
            u: 0.25,
            v: 1.0 / 3.0
        };
        pad
    ];
    last.text = "\u{3b4}/R".repeat(pad);
    last.mesh_resource = "package://softgrip/tip.stl".into();
    last.mesh_file.filename = "tip.stl".into();
    last.mesh_file.data = vec![0xab; pad * 3 + 1];
    last.mesh_use_embedded_materials = pad.is_multiple_of(2);
    last.frame_locked = true;
    m
}

#[test]
fn serde_cdr_and_hand_written_cdr_are_identical() {
    let mut sizes = [0usize; 5];
    for pad in 0..8 {
        for k in 0..script::STEPS {
            let s = step(k, pad);
            sizes[0] += check(&contacts(&s));
            sizes[1] += check(&WrenchStamped {
                header: s.header(),
                wrench: s.fingertips[1].wrench,
            });
            sizes[2] += check(&s.tf());
            sizes[3] += check(&markers(&s, pad));
            sizes[4] += check(&s.clock());
        }
    }
    // Empty messages too.
    check(&SoftContactArrayMsg::default());
    check(&MarkerArray::default());
    check(&softgrip_record::msgs::tf2_msgs::TFMessage::default());
    check(&Clock::default());
    eprintln!(
        "bytes compared (SoftContactArrayMsg, WrenchStamped, TFMessage, MarkerArray, Clock): {sizes:?}"
    );
}
