//! One plain contact reading (issue 26 item 2): a `softgrip_law::ContactReading` becomes a
//! `SoftContact` message by one conversion (`soft_contact_msg`) and reads back by one
//! (`SoftContactMsg::reading`), every level, construction and counterpart of the law's tables
//! included, bit for bit; a message written before a field existed, or with a code this
//! version does not know, still reads.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::{
    BACKINGS, ContactPatch, ContactReading, Counterpart, CounterpartKind, LEVELS, Regime,
};
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{ContactSample, soft_contact_msg};

/// A reading with every number distinct and awkward (not representable in fewer bits).
fn reading(i: usize) -> ContactReading {
    let k = i as f64 + 1.0;
    let delta = 0.001_234_567_89 * k;
    let radius = 0.0101;
    ContactReading {
        point: [0.1 / k, -0.2 * k, 0.3 + k],
        normal: [0.6, 0.0, 0.8],
        delta,
        x: delta / radius,
        normal_force: 3.3 * k,
        friction_force: [0.01 * k, -0.02, 0.003],
        torsional_moment: -1e-4 * k,
        stiffness: 1234.5 * k,
        validity_exceeded: i.is_multiple_of(2),
        sliding: i.is_multiple_of(3),
        peak_normal_force: 4.4 * k,
        max_delta: 1.5 * delta,
        max_x: 1.5 * delta / radius,
        contact_duration: 0.016,
        patch_direction: [0.0, 1.0, 0.0],
        ..ContactReading::default()
    }
}

fn through_a_message(r: &ContactReading) -> ContactReading {
    let sample = ContactSample {
        fingertip: "tip".into(),
        other: "box".into(),
        contact: r.clone(),
    };
    soft_contact_msg(&sample).reading()
}

#[test]
fn every_kind_of_the_tables_round_trips_through_a_message() {
    let counterparts = [
        Counterpart::PLANE,
        Counterpart::try_cylinder(0.02).unwrap(),
        Counterpart::try_from_parts(CounterpartKind::Curved, [25.0, 50.0]).unwrap(),
        Counterpart::EDGE,
    ];
    let mut i = 0;
    for level in LEVELS.iter().filter_map(|row| row.kind) {
        for backing in BACKINGS.map(|row| row.kind.with_parameter(0.004)) {
            for counterpart in counterparts {
                let mut r = reading(i);
                i += 1;
                r.level = level;
                r.backing = backing;
                r.counterpart = counterpart;
                r.regime = if r.validity_exceeded {
                    Regime::Extended
                } else {
                    Regime::Valid
                };
                let back = through_a_message(&r);
                // max_x comes back through the message's own ratio: equal to rounding.
                assert!((back.max_x - r.max_x).abs() <= 1e-15 * r.max_x, "{i}");
                assert_eq!(
                    back,
                    ContactReading {
                        max_x: back.max_x,
                        ..r
                    },
                    "{i}"
                );
            }
        }
    }
    assert_eq!(
        i,
        LEVELS.iter().filter(|r| r.code.is_some()).count() * BACKINGS.len() * counterparts.len()
    );
}

#[test]
fn what_a_message_does_not_hold_is_documented_not_invented() {
    // A separated row (compression 0): regime separated, max_x the message's ratio.
    let r = ContactReading {
        normal_force: 0.5,
        ..ContactReading::default()
    };
    assert_eq!(through_a_message(&r).regime, Regime::Separated);
    // The patch is written as the message's radius and pressures, and reads back as none.
    let mut r = reading(0);
    r.patch = Some(ContactPatch::new(r.normal_force, 0.003));
    let m = soft_contact_msg(&ContactSample {
        fingertip: "tip".into(),
        other: "box".into(),
        contact: r.clone(),
    });
    assert_eq!(m.contact_radius, 0.003);
    assert_eq!(m.reading().patch, None);
    // Codes this version does not know: the default's kinds, and the accessors say so.
    let mut m = SoftContactMsg {
        level: 200,
        backing: 200,
        counterpart: 200,
        compression: 0.001,
        ratio_x: 0.1,
        normal_force: 2.0,
        ..SoftContactMsg::default()
    };
    let back = m.reading();
    let d = ContactReading::default();
    assert_eq!(
        (back.level, back.backing, back.counterpart),
        (d.level, d.backing, d.counterpart)
    );
    assert_eq!((back.normal_force, back.delta, back.x), (2.0, 0.001, 0.1));
    assert_eq!(
        (m.level_kind(), m.backing(), m.counterpart()),
        (None, None, None)
    );
    m.level = 8;
    assert_eq!(m.reading().level, softgrip_law::LevelKind::Tabulated);
}
