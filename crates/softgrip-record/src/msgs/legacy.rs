//! Layouts of messages in recordings made by earlier softgrip versions, decoded into today's
//! types, so that no recording is lost when a message grows a field. Chosen by the schema the
//! recording embeds ([`Message::decode_with_schema`](crate::Message::decode_with_schema)).
//!
//! - `softgrip_msgs/SoftContact` before the fingertip's construction was recorded (issue 10,
//!   2026-12-02): no `backing` and `core_thickness` at the end. Read as a `free` fingertip
//!   (`backing = 0`, `core_thickness = 0`), which is what every fingertip was then.
//! - `softgrip_msgs/SoftContact` before the counterpart was recorded (issue 24, 2026-12-04): no
//!   `contact_radius2`, `patch_direction`, `counterpart` and its curvatures at the end. Read as
//!   a disc on a plane (`contact_radius2 = contact_radius`, `counterpart = 0`, zero direction
//!   and curvatures): every contact was computed as on a plane then.

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

/// `softgrip_msgs/SoftContact` with `backing` and `core_thickness`, before the counterpart:
/// the fields before `backing`, then `backing` and `core_thickness`. CDR has no field names and
/// aligns each field at its offset in the stream, so a struct nested first decodes the same
/// bytes as the fields spelled out in order.
#[derive(Deserialize)]
struct SoftContactBeforeCounterpart(SoftContactBeforeBacking, u8, f64);

#[derive(Deserialize)]
struct SoftContactArrayBeforeCounterpart {
    header: Header,
    contacts: Vec<SoftContactBeforeCounterpart>,
}

/// The line of the schema that tells a `SoftContact` with the fingertip's construction from
/// the one before it.
pub(crate) const BACKING_FIELD: &str = "uint8 backing";

/// The line of the schema that tells today's `SoftContact` from the one before the
/// counterpart was recorded.
pub(crate) const COUNTERPART_FIELD: &str = "uint8 counterpart";

/// Decodes a `SoftContactArray` of a recording whose schema has `backing` but no
/// `counterpart` field.
pub(crate) fn contacts_before_counterpart(data: &[u8]) -> Result<SoftContactArrayMsg, CdrError> {
    let old: SoftContactArrayBeforeCounterpart = cdr::decode(data)?;
    Ok(SoftContactArrayMsg {
        header: old.header,
        contacts: old
            .contacts
            .into_iter()
            .map(|c| {
                let SoftContactBeforeCounterpart(before, backing, core_thickness) = c;
                SoftContactMsg {
                    backing,
                    core_thickness,
                    ..today(before)
                }
            })
            .collect(),
    })
}

/// Decodes a `SoftContactArray` of a recording whose schema has no `backing` field.
pub(crate) fn contacts_before_backing(data: &[u8]) -> Result<SoftContactArrayMsg, CdrError> {
    let old: SoftContactArrayBeforeBacking = cdr::decode(data)?;
    Ok(SoftContactArrayMsg {
        header: old.header,
        contacts: old.contacts.into_iter().map(today).collect(),
    })
}

/// An old contact as today's: a free fingertip's disc on a plane.
fn today(c: SoftContactBeforeBacking) -> SoftContactMsg {
    SoftContactMsg {
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
        contact_radius2: c.contact_radius,
        patch_direction: Vector3::default(),
        counterpart: 0,
        counterpart_curvature1: 0.0,
        counterpart_curvature2: 0.0,
    }
}
