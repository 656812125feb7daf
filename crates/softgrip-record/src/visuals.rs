//! `/softgrip/markers`: the contact patches (discs of radius a on the contact plane) and the
//! fingertips (spheres of radius R), for Foxglove's 3D panel and RViz.

use crate::msgs::geometry_msgs::{Point, Pose, Quaternion, Vector3};
use crate::msgs::std_msgs::ColorRGBA;
use crate::msgs::visualization_msgs::{Marker, MarkerArray};
use crate::step::StepRecord;

/// Marker namespace of the contact patches.
pub const NS_PATCHES: &str = "contact_patches";
/// Marker namespace of the fingertips.
pub const NS_FINGERTIPS: &str = "fingertips";

/// Thickness of a drawn contact disc: 2 % of its radius, at least 0.05 mm [m].
fn disc_thickness(radius: f64) -> f64 {
    (0.02 * radius).max(5e-5)
}

/// Colour of a patch: green inside the law's validity range, red past it.
const PATCH_VALID: ColorRGBA = ColorRGBA::new(0.1, 0.8, 0.2, 0.9);
const PATCH_EXCEEDED: ColorRGBA = ColorRGBA::new(0.9, 0.1, 0.1, 0.9);
const FINGERTIP: ColorRGBA = ColorRGBA::new(0.3, 0.5, 0.9, 0.35);

/// The step's markers: a `DELETEALL` (so patches of contacts that ended disappear), a sphere
/// per fingertip (ns `fingertips`, id = index) and a disc per contact (ns `contact_patches`,
/// id = index): a cylinder at the contact point, axis along the normal, diameter 2a.
pub fn markers(step: &StepRecord) -> MarkerArray {
    let header = step.header();
    let base = |ns: &str, id: usize, r#type: i32| Marker {
        header: header.clone(),
        ns: ns.to_owned(),
        id: i32::try_from(id).unwrap_or(i32::MAX),
        r#type,
        action: Marker::ADD,
        ..Default::default()
    };
    let mut markers = Vec::with_capacity(1 + step.fingertips.len() + step.contacts.len());
    markers.push(Marker {
        header: header.clone(),
        action: Marker::DELETEALL,
        ..Default::default()
    });
    for (i, tip) in step.fingertips.iter().enumerate() {
        let d = 2.0 * tip.radius;
        markers.push(Marker {
            pose: Pose {
                position: Point::from_array(tip.position),
                orientation: Quaternion::from_xyzw(tip.orientation),
            },
            scale: Vector3 { x: d, y: d, z: d },
            color: FINGERTIP,
            ..base(NS_FINGERTIPS, i, Marker::SPHERE)
        });
    }
    for (i, c) in step.contacts.iter().enumerate() {
        let d = 2.0 * c.contact_radius;
        markers.push(Marker {
            pose: Pose {
                position: c.point,
                orientation: Quaternion::z_to(c.normal.to_array()),
            },
            scale: Vector3 {
                x: d,
                y: d,
                z: disc_thickness(c.contact_radius),
            },
            color: if c.validity_exceeded {
                PATCH_EXCEEDED
            } else {
                PATCH_VALID
            },
            ..base(NS_PATCHES, i, Marker::CYLINDER)
        });
    }
    MarkerArray { markers }
}
