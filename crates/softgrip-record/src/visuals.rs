//! `/softgrip/markers`: every rigid body's shapes (in their body frames), the fingertips
//! (spheres of radius R in their frames; a backed fingertip a hemisphere, its flat face on the
//! finger: [`hemisphere`]), the contact patches (discs of radius a on the
//! contact plane) and the contacts' normal forces (arrows), for Foxglove's 3D panel and RViz.

use std::collections::HashMap;

use crate::msgs::geometry_msgs::{Point, Pose, Quaternion, Vector3};
use crate::msgs::softgrip_msgs::SoftContactMsg;
use crate::msgs::std_msgs::{ColorRGBA, Header};
use crate::msgs::visualization_msgs::{Marker, MarkerArray};
use crate::sink::{SceneInfo, ShapeGeometry, ShapeInfo};
use crate::step::{FingertipState, StepRecord};

/// Marker namespace of the contact patches.
pub const NS_PATCHES: &str = "contact_patches";
/// Marker namespace of the fingertips.
pub const NS_FINGERTIPS: &str = "fingertips";
/// Marker namespace of the rigid bodies' shapes (id = the shape's index in
/// [`SceneInfo::shapes`], stable over the run).
pub const NS_BODIES: &str = "bodies";
/// Marker namespace of the contacts' normal-force arrows (id = the contact's index).
pub const NS_FORCES: &str = "contact_forces";

/// Thickness of a drawn contact disc relative to its radius [-]: 2 % of a, no absolute floor
/// (a 30 um cell's patches are drawn as thin as a 20 mm fingertip's, relatively).
pub const DISC_THICKNESS: f64 = 0.02;

/// Side of the square slab a plane is drawn as, in largest fingertip radii [-] (1 m without
/// fingertips); its thickness is 1/100 of its side, below the plane.
pub const PLANE_EXTENT_RADII: f64 = 40.0;

/// Longest force arrow, in fingertip radii [-]: [`arrow_length`] never draws an arrow longer
/// than 4 R, whatever the force (an impact, a cell pressed far past its range).
pub const ARROW_MAX_RADII: f64 = 4.0;

/// Length of a normal-force arrow \[m\] for a force `force` \[N\] on a fingertip of radius
/// `radius` \[m\] whose reference force is `radius / arrow_scale` (its law's force at x = 0.2,
/// [`arrow_scale`](crate::arrow_scale) \[m/N\]). With u = force · arrow_scale / radius (the force
/// in reference forces):
///
/// L / R = u for u ≤ 1 (linear: one radius at the reference force),
/// L / R = min(1 + ln u, [`ARROW_MAX_RADII`]) for u > 1 (logarithmic, continuous with the
/// linear part in value and slope, capped: 4 R from u = e³ ≈ 20 on).
///
/// The law's force grows steeply with x (Hertz alone: F(0.6 R) = 3^1.5 F(0.2 R) = 5.2 F(0.2 R)),
/// so a linear arrow would leave the view at large x and in impacts. 0 for a non-positive or non-finite force,
/// radius or scale (no arrow is drawn).
///
/// ```
/// use softgrip_record::visuals::{arrow_length, ARROW_MAX_RADII};
/// let (r, k) = (0.01, 0.01 / 5.0); // R = 10 mm, 5 N reference force
/// assert!((arrow_length(2.5, r, k) - 0.005).abs() < 1e-15); // linear: half the reference
/// assert!((arrow_length(10.0, r, k) - r * (1.0 + 2f64.ln())).abs() < 1e-15); // logarithmic
/// assert_eq!(arrow_length(1e6, r, k), ARROW_MAX_RADII * r); // capped
/// ```
pub fn arrow_length(force: f64, radius: f64, arrow_scale: f64) -> f64 {
    let u = force * arrow_scale / radius;
    if !(u > 0.0 && u.is_finite() && radius.is_finite()) {
        return 0.0;
    }
    let radii = if u <= 1.0 { u } else { 1.0 + u.ln() };
    radius * radii.min(ARROW_MAX_RADII)
}

/// Colour of a patch: green inside the law's validity range, red past it.
const PATCH_VALID: ColorRGBA = ColorRGBA::new(0.1, 0.8, 0.2, 0.9);
const PATCH_EXCEEDED: ColorRGBA = ColorRGBA::new(0.9, 0.1, 0.1, 0.9);
const FINGERTIP: ColorRGBA = ColorRGBA::new(0.3, 0.5, 0.9, 0.35);
const FORCE: ColorRGBA = ColorRGBA::new(1.0, 0.85, 0.1, 1.0);
const PLANE: ColorRGBA = ColorRGBA::new(0.55, 0.55, 0.58, 1.0);
/// Body colours, by body index (cycled).
const BODY: [ColorRGBA; 4] = [
    ColorRGBA::new(0.85, 0.55, 0.25, 0.8),
    ColorRGBA::new(0.6, 0.65, 0.75, 0.8),
    ColorRGBA::new(0.45, 0.7, 0.6, 0.8),
    ColorRGBA::new(0.75, 0.5, 0.7, 0.8),
];

fn id(i: usize) -> i32 {
    i32::try_from(i).unwrap_or(i32::MAX)
}

/// The markers of every rigid body's shape of `info` (ns [`NS_BODIES`], id = index), each in
/// its body's frame, stamp 0 ([`markers`] stamps them): a plane as a square slab below it
/// ([`PLANE_EXTENT_RADII`]), a cuboid as a `CUBE`, a ball as a `SPHERE`, a cylinder (body y
/// axis) as a `CYLINDER`, a mesh or convex hull as a `TRIANGLE_LIST`.
pub fn shape_markers(info: &SceneInfo) -> Vec<Marker> {
    let r_max = info.fingertips.iter().map(|t| t.radius).fold(0.0, f64::max);
    let extent = if r_max > 0.0 {
        PLANE_EXTENT_RADII * r_max
    } else {
        1.0
    };
    let bodies: HashMap<&str, usize> = info
        .bodies
        .iter()
        .enumerate()
        .rev()
        .map(|(i, b)| (b.as_str(), i))
        .collect();
    info.shapes
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let body = bodies.get(s.body.as_str()).copied().unwrap_or(i);
            shape_marker(s, id(i), BODY[body % BODY.len()], extent)
        })
        .collect()
}

/// One shape's marker (see [`shape_markers`]).
fn shape_marker(s: &ShapeInfo, id: i32, color: ColorRGBA, extent: f64) -> Marker {
    // The shape's own orientation in its body's frame, then the marker's in the shape's.
    let at = |offset: [f64; 3], orientation: Quaternion| Pose {
        position: Point::from_array(offset),
        orientation: Quaternion::from_xyzw(crate::frames::mul(
            s.rotation,
            [orientation.x, orientation.y, orientation.z, orientation.w],
        )),
    };
    let (r#type, pose, scale, color, points) = match &s.geometry {
        ShapeGeometry::Plane { normal: n } => {
            let t = extent / 100.0;
            let c: [f64; 3] = std::array::from_fn(|k| s.offset[k] - 0.5 * t * n[k]);
            let scale = Vector3 {
                x: extent,
                y: extent,
                z: t,
            };
            (
                Marker::CUBE,
                at(c, Quaternion::z_to(*n)),
                scale,
                PLANE,
                Vec::new(),
            )
        }
        ShapeGeometry::Cuboid { half_extents: h } => {
            let scale = Vector3::from_array(h.map(|v| 2.0 * v));
            (
                Marker::CUBE,
                at(s.offset, Quaternion::IDENTITY),
                scale,
                color,
                Vec::new(),
            )
        }
        ShapeGeometry::Ball { radius } => {
            let d = 2.0 * radius;
            let scale = Vector3 { x: d, y: d, z: d };
            (
                Marker::SPHERE,
                at(s.offset, Quaternion::IDENTITY),
                scale,
                color,
                Vec::new(),
            )
        }
        ShapeGeometry::Cylinder {
            half_height,
            radius,
        } => {
            let d = 2.0 * radius;
            let scale = Vector3 {
                x: d,
                y: d,
                z: 2.0 * half_height,
            };
            let pose = at(s.offset, Quaternion::z_to([0.0, 1.0, 0.0]));
            (Marker::CYLINDER, pose, scale, color, Vec::new())
        }
        ShapeGeometry::Mesh {
            vertices,
            triangles,
        } => {
            let points = triangles
                .iter()
                .flatten()
                .filter_map(|&v| vertices.get(v as usize))
                .map(|&p| Point::from_array(p))
                .collect();
            let scale = Vector3 {
                x: 1.0,
                y: 1.0,
                z: 1.0,
            };
            let pose = at(s.offset, Quaternion::IDENTITY);
            (Marker::TRIANGLE_LIST, pose, scale, color, points)
        }
    };
    Marker {
        header: Header::new(0, &s.body),
        ns: NS_BODIES.to_owned(),
        id,
        r#type,
        action: Marker::ADD,
        pose,
        scale,
        color,
        frame_locked: true,
        points,
        ..Default::default()
    }
}

/// The step's markers: a `DELETEALL` (so patches of contacts that ended disappear), every body
/// shape (ns [`NS_BODIES`], in its body frame), a sphere per free fingertip and a
/// [`hemisphere`] (a `TRIANGLE_LIST`) per backed one (ns `fingertips`, id = index, in its frame), a disc per contact (ns `contact_patches`, id = index: a cylinder at
/// the contact point, axis along the normal, diameter 2a, thickness [`DISC_THICKNESS`] a) and
/// an arrow per contact (ns [`NS_FORCES`], id = index) from the contact point along the normal
/// (the force on the fingertip), [`arrow_length`] long: one fingertip radius at the law's force
/// at x = 0.2 ([`arrow_scale`](crate::arrow_scale)), linear below it, logarithmic above it,
/// never longer than [`ARROW_MAX_RADII`] radii.
pub fn markers(step: &StepRecord) -> MarkerArray {
    let header = step.header();
    let base = |ns: &str, id: usize, r#type: i32| Marker {
        header: header.clone(),
        ns: ns.to_owned(),
        id: self::id(id),
        r#type,
        action: Marker::ADD,
        ..Default::default()
    };
    let n = 1 + step.shapes.len() + step.fingertips.len() + 2 * step.contacts.len();
    let mut markers = Vec::with_capacity(n);
    markers.push(Marker {
        header: header.clone(),
        action: Marker::DELETEALL,
        ..Default::default()
    });
    markers.extend(step.shapes.iter().map(|m| {
        let mut m = m.clone();
        m.header.stamp = header.stamp;
        m
    }));
    for (i, tip) in step.fingertips.iter().enumerate() {
        let d = 2.0 * tip.radius;
        let own = !tip.frame.is_empty();
        // A backed fingertip is a hemisphere (its flat face bonded to the finger), drawn as a
        // triangle list in its frame; a free one a sphere.
        let (r#type, scale, points) = match tip.facing {
            Some(n) => (
                Marker::TRIANGLE_LIST,
                Vector3 {
                    x: 1.0,
                    y: 1.0,
                    z: 1.0,
                },
                hemisphere(tip.radius, n),
            ),
            None => (Marker::SPHERE, Vector3 { x: d, y: d, z: d }, Vec::new()),
        };
        let mut m = Marker {
            pose: if own {
                Pose::default()
            } else {
                Pose {
                    position: Point::from_array(tip.position),
                    orientation: Quaternion::from_xyzw(tip.orientation),
                }
            },
            scale,
            color: FINGERTIP,
            frame_locked: own,
            points,
            ..base(NS_FINGERTIPS, i, r#type)
        };
        m.header.frame_id = step.frame_of(tip).to_owned();
        markers.push(m);
    }
    for (i, c) in step.contacts.iter().enumerate() {
        let (orientation, [a, b]) = patch_frame(c);
        markers.push(Marker {
            pose: Pose {
                position: c.point,
                orientation,
            },
            scale: Vector3 {
                x: 2.0 * a,
                y: 2.0 * b,
                z: DISC_THICKNESS * a,
            },
            color: if c.validity_exceeded {
                PATCH_EXCEEDED
            } else {
                PATCH_VALID
            },
            ..base(NS_PATCHES, i, Marker::CYLINDER)
        });
    }
    // Each contact's fingertip by name, indexed once (a lookup per contact was quadratic in the
    // number of fingertips).
    let tips: HashMap<&str, &FingertipState> = step
        .fingertips
        .iter()
        .rev()
        .map(|t| (t.name.as_str(), t))
        .collect();
    for (i, c) in step.contacts.iter().enumerate() {
        if let Some(arrow) = tips
            .get(c.fingertip.as_str())
            .and_then(|tip| force_arrow(tip, c))
        {
            markers.push(Marker {
                header: header.clone(),
                id: id(i),
                ..arrow
            });
        }
    }
    MarkerArray { markers }
}

/// The drawn patch of a contact: its orientation (the marker's z along the normal; for an
/// ellipse its x along `patch_direction`) and its semi-axes `[a, b]` along the marker's x and
/// y. A disc (`contact_radius2` equal to `contact_radius`, or 0 as in recordings made before
/// patches were ellipses) is drawn as before, by the shortest rotation of z to the normal.
fn patch_frame(c: &SoftContactMsg) -> (Quaternion, [f64; 2]) {
    let (a, b) = (c.contact_radius, c.contact_radius2);
    let n = c.normal.to_array();
    let d = c.patch_direction.to_array();
    if b == a || b <= 0.0 || !b.is_finite() {
        return (Quaternion::z_to(n), [a, a]);
    }
    match frame_quaternion(n, d) {
        Some(q) => (q, [a, b]),
        None => (Quaternion::z_to(n), [a, a]),
    }
}

/// The rotation whose z axis is `n` and x axis `d` made orthogonal to it (both normalised);
/// `None` if either is zero or non-finite or they are parallel.
fn frame_quaternion(n: [f64; 3], d: [f64; 3]) -> Option<Quaternion> {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let unit = |v: [f64; 3]| {
        let l = dot(v, v).sqrt();
        (l > 0.0 && l.is_finite()).then(|| v.map(|c| c / l))
    };
    let z = unit(n)?;
    let k = dot(d, z);
    let x = unit(std::array::from_fn(|i| d[i] - k * z[i]))?;
    let y = [
        z[1] * x[2] - z[2] * x[1],
        z[2] * x[0] - z[0] * x[2],
        z[0] * x[1] - z[1] * x[0],
    ];
    // The quaternion of the rotation matrix with columns x, y, z (Shepperd's method).
    let (m00, m11, m22) = (x[0], y[1], z[2]);
    let trace = m00 + m11 + m22;
    let q = if trace > 0.0 {
        let s = 2.0 * (trace + 1.0).sqrt();
        [
            (y[2] - z[1]) / s,
            (z[0] - x[2]) / s,
            (x[1] - y[0]) / s,
            0.25 * s,
        ]
    } else if m00 > m11 && m00 > m22 {
        let s = 2.0 * (1.0 + m00 - m11 - m22).sqrt();
        [
            0.25 * s,
            (y[0] + x[1]) / s,
            (z[0] + x[2]) / s,
            (y[2] - z[1]) / s,
        ]
    } else if m11 > m22 {
        let s = 2.0 * (1.0 + m11 - m00 - m22).sqrt();
        [
            (y[0] + x[1]) / s,
            0.25 * s,
            (z[1] + y[2]) / s,
            (z[0] - x[2]) / s,
        ]
    } else {
        let s = 2.0 * (1.0 + m22 - m00 - m11).sqrt();
        [
            (z[0] + x[2]) / s,
            (z[1] + y[2]) / s,
            0.25 * s,
            (x[1] - y[0]) / s,
        ]
    };
    Some(Quaternion::from_xyzw(q))
}

/// Meridian segments of a drawn hemisphere, pole to equator.
pub const HEMISPHERE_RINGS: usize = 4;
/// Segments around a drawn hemisphere's axis.
pub const HEMISPHERE_SEGMENTS: usize = 16;

/// The triangles (a `TRIANGLE_LIST`'s points, 3 per triangle, counter-clockwise seen from
/// outside) of a hemisphere of radius `radius` \[m\] centred at the origin whose pole is along
/// `facing` (any non-zero length; normalised here): the dome, [`HEMISPHERE_RINGS`] x
/// [`HEMISPHERE_SEGMENTS`] facets with its vertices on the sphere, and the flat face through
/// the centre. 16 x (2 x 4 - 1) + 16 = 128 triangles. Empty for a zero or non-finite `facing`.
///
/// ```
/// use softgrip_record::visuals::hemisphere;
/// let pts = hemisphere(0.01, [0.0, -2.0, 0.0]);
/// assert_eq!(pts.len(), 3 * 128);
/// // Every vertex is on the sphere or on the flat face, none on the finger's side.
/// for p in &pts {
///     let r = (p.x * p.x + p.y * p.y + p.z * p.z).sqrt();
///     assert!(p.y <= 1e-12 && (r <= 0.01 + 1e-12) && (p.y.abs() < 1e-12 || (r - 0.01).abs() < 1e-12));
/// }
/// assert!(hemisphere(0.01, [0.0; 3]).is_empty());
/// ```
pub fn hemisphere(radius: f64, facing: [f64; 3]) -> Vec<Point> {
    let len = (facing[0] * facing[0] + facing[1] * facing[1] + facing[2] * facing[2]).sqrt();
    if !(len > 0.0 && len.is_finite()) {
        return Vec::new();
    }
    let n = facing.map(|v| v / len);
    // Two unit vectors across the axis: u along the axis least aligned with n, made normal.
    let k = (0..3)
        .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(0);
    let mut u = [0.0; 3];
    u[k] = 1.0;
    let dot = u[k] * n[k];
    let u: [f64; 3] = std::array::from_fn(|j| u[j] - dot * n[j]);
    let ul = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let u = u.map(|v| v / ul);
    let v = [
        n[1] * u[2] - n[2] * u[1],
        n[2] * u[0] - n[0] * u[2],
        n[0] * u[1] - n[1] * u[0],
    ];
    // The vertex at polar angle ring * (pi/2)/RINGS from the pole, azimuth seg * 2 pi/SEGMENTS.
    let vertex = |ring: usize, seg: usize| {
        let theta = std::f64::consts::FRAC_PI_2 * ring as f64 / HEMISPHERE_RINGS as f64;
        let phi =
            std::f64::consts::TAU * (seg % HEMISPHERE_SEGMENTS) as f64 / HEMISPHERE_SEGMENTS as f64;
        let (st, ct) = theta.sin_cos();
        let (sp, cp) = phi.sin_cos();
        let p: [f64; 3] =
            std::array::from_fn(|j| radius * (ct * n[j] + st * (cp * u[j] + sp * v[j])));
        Point::from_array(p)
    };
    let centre = Point::from_array([0.0; 3]);
    let mut pts = Vec::with_capacity(3 * HEMISPHERE_SEGMENTS * (2 * HEMISPHERE_RINGS));
    for seg in 0..HEMISPHERE_SEGMENTS {
        pts.extend([vertex(0, 0), vertex(1, seg), vertex(1, seg + 1)]);
        for ring in 1..HEMISPHERE_RINGS {
            let (a, b) = (vertex(ring, seg), vertex(ring, seg + 1));
            let (c, d) = (vertex(ring + 1, seg), vertex(ring + 1, seg + 1));
            pts.extend([a, c, d, a, d, b]);
        }
        // The flat face, seen from behind (from -n).
        let (e0, e1) = (
            vertex(HEMISPHERE_RINGS, seg),
            vertex(HEMISPHERE_RINGS, seg + 1),
        );
        pts.extend([centre, e1, e0]);
    }
    pts
}

/// The normal-force arrow of contact `c` (ns [`NS_FORCES`]; header and id left to the caller),
/// drawn at fingertip `tip`'s scale.
fn force_arrow(tip: &FingertipState, c: &SoftContactMsg) -> Option<Marker> {
    let len = arrow_length(c.normal_force, tip.radius, tip.arrow_scale);
    let (p, n) = (c.point.to_array(), c.normal.to_array());
    let end: [f64; 3] = std::array::from_fn(|k| p[k] + len * n[k]);
    let r = tip.radius;
    Some(Marker {
        ns: NS_FORCES.to_owned(),
        r#type: Marker::ARROW,
        action: Marker::ADD,
        scale: Vector3 {
            x: 0.04 * r,
            y: 0.1 * r,
            z: 0.15 * r,
        },
        color: FORCE,
        points: vec![c.point, Point::from_array(end)],
        ..Default::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `q v q*` for a unit quaternion.
    fn rotate(q: Quaternion, v: [f64; 3]) -> [f64; 3] {
        let (x, y, z, w) = (q.x, q.y, q.z, q.w);
        let t = [
            2.0 * (y * v[2] - z * v[1]),
            2.0 * (z * v[0] - x * v[2]),
            2.0 * (x * v[1] - y * v[0]),
        ];
        [
            v[0] + w * t[0] + (y * t[2] - z * t[1]),
            v[1] + w * t[1] + (z * t[0] - x * t[2]),
            v[2] + w * t[2] + (x * t[1] - y * t[0]),
        ]
    }

    /// An elliptical patch's marker: z along the normal, x along the patch's first semi-axis,
    /// scaled by the two semi-axes; a disc is drawn as before.
    #[test]
    fn an_elliptical_patch_is_drawn_along_its_direction() {
        let s = 0.5f64.sqrt();
        for (n, d) in [
            ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]),
            ([0.0, 0.0, -1.0], [0.0, 1.0, 0.0]),
            ([s, s, 0.0], [0.0, 0.3, 1.0]),
            ([-0.2, 0.9, -0.3], [0.7, 0.1, -0.2]),
            ([1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
        ] {
            let c = SoftContactMsg {
                normal: Vector3::from_array(n),
                patch_direction: Vector3::from_array(d),
                contact_radius: 0.003,
                contact_radius2: 0.001,
                ..Default::default()
            };
            let (q, axes) = patch_frame(&c);
            assert_eq!(axes, [0.003, 0.001]);
            let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let nz = n.map(|c| c / norm(n));
            let z = rotate(q, [0.0, 0.0, 1.0]);
            let x = rotate(q, [1.0, 0.0, 0.0]);
            for i in 0..3 {
                assert!((z[i] - nz[i]).abs() < 1e-12, "{n:?} {d:?}: z {z:?}");
            }
            // x is d made tangent.
            let k: f64 = (0..3).map(|i| d[i] * nz[i]).sum();
            let t: [f64; 3] = std::array::from_fn(|i| d[i] - k * nz[i]);
            let tn = t.map(|c| c / norm(t));
            for i in 0..3 {
                assert!((x[i] - tn[i]).abs() < 1e-12, "{n:?} {d:?}: x {x:?}");
            }
        }
        // A disc, and a contact recorded before patches were ellipses (radius2 = 0).
        for b in [0.003, 0.0] {
            let c = SoftContactMsg {
                normal: Vector3::from_array([0.0, 1.0, 0.0]),
                contact_radius: 0.003,
                contact_radius2: b,
                ..Default::default()
            };
            let (q, axes) = patch_frame(&c);
            assert_eq!(axes, [0.003, 0.003]);
            assert_eq!(q, Quaternion::z_to([0.0, 1.0, 0.0]));
        }
    }
}
