//! Layouts of messages in recordings made by earlier softgrip versions, decoded into today's
//! types, so that no recording is lost when a message grows a field. Chosen by the schema the
//! recording embeds ([`Message::decode_with_schema`](crate::Message::decode_with_schema)).
//!
//! - `softgrip_msgs/SoftContact` before the fingertip's construction was recorded (issue 10,
//!   2026-12-02): no `backing` and `core_thickness` at the end. Read as a `free` fingertip
//!   (`backing = 0`, `core_thickness = 0`), which is what every fingertip was then.

use serde::Deserialize;

use super::geometry_msgs::{Point, Vector3};
use super::softgrip_msgs::{SoftContactArrayMsg, SoftContactMsg};
use super::std_msgs::Header;
use crate::cdr::{self, CdrError};

/// `softgrip_msgs/SoftContact` without `backing` and `core_thickness`.
#[derive(Deserialize)]
struct SoftContactBeforeBacking {
    header: Header,
    fingertip: String,
    other: String,
    point: Point,
    normal: Vector3,
    compression: f64,
    ratio_x: f64,
    normal_force: f64,
    friction_force: Vector3,
    torsional_moment: f64,
    contact_radius: f64,
    mean_pressure: f64,
    peak_pressure: f64,
    stiffness: f64,
    level: u8,
    level_name: String,
    validity_exceeded: bool,
    sliding: bool,
    peak_normal_force: f64,
    max_compression: f64,
    contact_duration: f64,
}

#[derive(Deserialize)]
struct SoftContactArrayBeforeBacking {
    header: Header,
    contacts: Vec<SoftContactBeforeBacking>,
}

/// The line of the schema that tells today's `SoftContact` from the one before it.
pub(crate) const BACKING_FIELD: &str = "uint8 backing";

/// Decodes a `SoftContactArray` of a recording whose schema has no `backing` field.
pub(crate) fn contacts_before_backing(data: &[u8]) -> Result<SoftContactArrayMsg, CdrError> {
    let old: SoftContactArrayBeforeBacking = cdr::decode(data)?;
    Ok(SoftContactArrayMsg {
        header: old.header,
        contacts: old
            .contacts
            .into_iter()
            .map(|c| SoftContactMsg {
                header: c.header,
                fingertip: c.fingertip,
                other: c.other,
                point: c.point,
                normal: c.normal,
                compression: c.compression,
                ratio_x: c.ratio_x,
                normal_force: c.normal_force,
                friction_force: c.friction_force,
                torsional_moment: c.torsional_moment,
                contact_radius: c.contact_radius,
                mean_pressure: c.mean_pressure,
                peak_pressure: c.peak_pressure,
                stiffness: c.stiffness,
                level: c.level,
                level_name: c.level_name,
                validity_exceeded: c.validity_exceeded,
                sliding: c.sliding,
                peak_normal_force: c.peak_normal_force,
                max_compression: c.max_compression,
                contact_duration: c.contact_duration,
                backing: 0,
                core_thickness: 0.0,
            })
            .collect(),
    })
}
