//! `softgrip export --csv` on a committed recording: the columns (with units) are those the
//! export always had, one row per recorded contact, wrench, pose and clock tick, and every
//! number reads back to the decoded message's value, bit for bit.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_record::{Message, Recording, topics};

/// The header of `contacts.csv` as written before the export went through `csv` + serde.
const CONTACTS_HEADER: &str = "time_s,fingertip,other,point_x_m,point_y_m,point_z_m,normal_x,normal_y,normal_z,compression_m,ratio_x,normal_force_N,friction_force_x_N,friction_force_y_N,friction_force_z_N,torsional_moment_Nm,contact_radius_m,mean_pressure_Pa,peak_pressure_Pa,stiffness_N_per_m,level,level_name,validity_exceeded,sliding,peak_normal_force_N,max_compression_m,contact_duration_s";

fn read(path: &std::path::Path) -> (String, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_owned();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows)
}

fn num(s: &str) -> f64 {
    s.parse().unwrap_or_else(|e| panic!("`{s}`: {e}"))
}

#[test]
fn export_keeps_its_columns_and_values() {
    let dir = common::temp_dir("export");
    let file = common::root().join("recordings/ecoflex_sphere.mcap");
    let o = common::softgrip(&[
        "export",
        file.to_str().unwrap(),
        "--csv",
        dir.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rec = Recording::open(&file).unwrap();

    let (header, rows) = read(&dir.join("contacts.csv"));
    assert_eq!(header, CONTACTS_HEADER);
    let contacts: Vec<_> = rec
        .on_topic(topics::CONTACTS)
        .flat_map(|m| match &m.message {
            Message::Contacts(a) => a.contacts.iter().map(|c| (m.log_time_ns, c)).collect(),
            _ => Vec::new(),
        })
        .collect();
    assert!(!contacts.is_empty());
    assert_eq!(rows.len(), contacts.len());
    for (row, (t, c)) in rows.iter().zip(&contacts) {
        assert_eq!(row.len(), 27, "{row:?}");
        assert_eq!(num(&row[0]), *t as f64 * 1e-9);
        assert_eq!(
            (row[1].as_str(), row[2].as_str()),
            (c.fingertip.as_str(), c.other.as_str())
        );
        let want = [
            c.point.x,
            c.point.y,
            c.point.z,
            c.normal.x,
            c.normal.y,
            c.normal.z,
            c.compression,
            c.ratio_x,
            c.normal_force,
            c.friction_force.x,
            c.friction_force.y,
            c.friction_force.z,
            c.torsional_moment,
            c.contact_radius,
            c.mean_pressure,
            c.peak_pressure,
            c.stiffness,
        ];
        for (i, w) in want.iter().enumerate() {
            assert_eq!(num(&row[3 + i]).to_bits(), w.to_bits(), "column {}", 3 + i);
        }
        assert_eq!(row[20], c.level.to_string());
        assert_eq!(row[21], c.level_name);
        assert_eq!(row[22], u8::from(c.validity_exceeded).to_string());
        assert_eq!(row[23], u8::from(c.sliding).to_string());
        assert_eq!(num(&row[24]), c.peak_normal_force);
        assert_eq!(num(&row[25]), c.max_compression);
        assert_eq!(num(&row[26]), c.contact_duration);
    }

    for (name, header, topic_rows) in [
        (
            "wrenches.csv",
            "time_s,fingertip,topic,force_x_N,force_y_N,force_z_N,torque_x_Nm,torque_y_Nm,torque_z_Nm",
            rec.messages
                .iter()
                .filter(|m| matches!(m.message, Message::Wrench(_)))
                .count(),
        ),
        (
            "poses.csv",
            "time_s,parent_frame,frame,x_m,y_m,z_m,qx,qy,qz,qw",
            rec.messages
                .iter()
                .map(|m| match &m.message {
                    Message::Tf(tf) => tf.transforms.len(),
                    _ => 0,
                })
                .sum(),
        ),
        (
            "clock.csv",
            "log_time_s,clock_s",
            rec.on_topic(topics::CLOCK).count(),
        ),
    ] {
        let (h, rows) = read(&dir.join(name));
        assert_eq!(h, header, "{name}");
        assert_eq!(rows.len(), topic_rows, "{name}");
    }
    let (_, clock) = read(&dir.join("clock.csv"));
    for (row, m) in clock.iter().zip(rec.on_topic(topics::CLOCK)) {
        let Message::Clock(c) = &m.message else {
            unreachable!()
        };
        assert_eq!(num(&row[1]), c.clock.as_nanos() as f64 * 1e-9);
    }
    std::fs::remove_dir_all(&dir).ok();
}
