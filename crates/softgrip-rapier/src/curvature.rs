//! What a fingertip touches: the counterpart of the law ([`Counterpart`]) at a contact, read
//! from the other collider's shape, and the direction of the contact patch's first semi-axis.
//!
//! The contact (parry's, `detect`) gives the point on the other shape and the outward normal
//! there; this module reads the shape at that point, in the shape's own frame:
//!
//! | shape | where | counterpart (k1 along `direction`, k2 across) |
//! |---|---|---|
//! | ball r | anywhere | curved (1/r, 1/r) |
//! | half-space | anywhere | plane |
//! | cuboid | face / edge / corner | plane / edge along the edge / edge (a corner is read as the sharpest kind the law has) |
//! | capsule r | side / caps | curved (0 along the axis, 1/r) / curved (1/r, 1/r) |
//! | cylinder r | side / caps / rim | curved (0 along the axis, 1/r) / plane / edge along the rim |
//! | cone | side / base / rim / apex | curved (0 along the generator, cos(β)/ρ: ρ the local radius, β the side's tilt from the axis' normal) / plane / edge along the rim / edge |
//! | convex polyhedron, triangle mesh, heightfield, triangle | faces, edges, vertices | the local fit below |
//! | segment, polyline | anywhere | edge along the segment |
//! | voxels | face / edge / corner | plane / edge / edge (by the normal, as the cuboid) |
//! | round shapes (border radius r_b) | anywhere | the inner shape's counterpart at `p - r_b n`, dilated: a curvature k becomes `k/(1 + k r_b)`, a plane stays a plane, an edge becomes curved (0 along it, 1/r_b) |
//! | compound | anywhere | the part the point lies on, in its own frame |
//!
//! **Faceted shapes** (meshes, hulls, heightfields) are read by a local fit. The facets
//! within `2e-4 R` of the contact point (R the fingertip's radius) are the feature the point
//! lies on: if any of them tilts from the contact normal by half of [`SHARP_DIHEDRAL`] (30°)
//! or more, the point is on a sharp edge or vertex (a box's, a blade's) and the counterpart is
//! an edge along the ridge. Otherwise the facets are a smooth surface's tessellation: the
//! shape operator `S` (the change of the normal along the surface, `n(p0 + d) - n0 = S d`) is
//! fitted by least squares, weighted by area, to the facets within `R` of the point whose
//! normals are within [`SHARP_DIHEDRAL`] of the contact normal (so a sharp ridge nearby, a
//! cylinder's cap next to its side, is not averaged in); its eigenvalues are the principal
//! curvatures, its eigenvectors their directions. A flat mesh fits `S = 0`: a plane. A fitted
//! curvature below `1e-4/R` is the f32 geometry's rounding and is read as 0.
//!
//! A curvature the fingertip's law cannot take (a groove tighter than the fingertip: concave
//! beyond `-0.999/R`) falls back to the plane, counted in
//! [`SoftCounters::counterpart_fallbacks`](crate::SoftCounters::counterpart_fallbacks); one
//! sharper than `1e4/R` (a needle, the apex of a cone) is read as an edge.

use nalgebra::{Matrix3, Vector3};
use rapier3d::parry::query::PointQuery;
use rapier3d::parry::shape::{Compound, ConvexPolyhedron, Shape, Triangle, TypedShape};
use rapier3d::prelude::{Aabb, Collider, Pose, Vector};
use softgrip_law::{Counterpart, MAX_RELATIVE_CURVATURE};

use crate::boundary::{to_f32, to_f64};

/// The dihedral angle from which two facets meet at a sharp edge, not a tessellated smooth
/// surface: 30° \[rad\].
pub const SHARP_DIHEDRAL: f64 = std::f64::consts::PI / 6.0;

/// How far a normal may be from a feature's to be read as it [rad] (parry's normals are f32).
const ALIGNED: f64 = 1e-3;

/// The counterpart at a contact and its first direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Touch {
    /// What the fingertip touches.
    pub counterpart: Counterpart,
    /// Unit tangent (world) along the counterpart's first principal direction (along an
    /// edge); the patch's first semi-axis lies along it.
    pub direction: Vector3<f64>,
    /// An edge that is a vertex (a corner, an apex): a rounded shape makes it a ball.
    pub vertex: bool,
}

impl Touch {
    /// A plane, its first direction any tangent at the normal `n`.
    pub(crate) fn plane(n: &Vector3<f64>) -> Self {
        Self {
            counterpart: Counterpart::PLANE,
            direction: any_tangent(n),
            vertex: false,
        }
    }

    fn edge(direction: Vector3<f64>) -> Self {
        Self {
            counterpart: Counterpart::EDGE,
            direction,
            vertex: false,
        }
    }

    /// A vertex (a corner, an apex), read as an edge: the sharpest kind the law has.
    fn vertex(direction: Vector3<f64>) -> Self {
        Self {
            vertex: true,
            ..Self::edge(direction)
        }
    }

    /// Curved `(k1, k2)` with k1 along `direction` (a unit tangent at the normal `n`); an
    /// edge along the less curved direction if either is sharper than the law takes for a
    /// fingertip of radius `radius` (`MAX_RELATIVE_CURVATURE / radius`).
    fn curved(k1: f64, k2: f64, direction: Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Self {
        let limit = MAX_RELATIVE_CURVATURE / radius;
        if k1 > limit || k2 > limit {
            let along = if k1 <= k2 {
                direction
            } else {
                n.cross(&direction)
            };
            return Self::edge(along);
        }
        Self {
            // Finite curvatures, not both 0 unless a plane: `try_curved` cannot fail here, and a
            // non-finite fit would be a plane.
            counterpart: Counterpart::try_curved(k1, k2).unwrap_or(Counterpart::PLANE),
            direction,
            vertex: false,
        }
    }
}

/// A unit vector orthogonal to the unit vector `n` (the one closest to the world's x axis,
/// or z when `n` is nearly x).
fn any_tangent(n: &Vector3<f64>) -> Vector3<f64> {
    let seed = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::z()
    };
    let t = seed - n * n.dot(&seed);
    t / t.norm()
}

/// The counterpart of `collider` at the contact point `point` (world, on its surface) with
/// outward unit normal `normal` (world, from it to the fingertip), for a fingertip of radius
/// `radius` \[m\].
pub(crate) fn counterpart_at(
    collider: &Collider,
    point: &Vector3<f64>,
    normal: &Vector3<f64>,
    radius: f64,
) -> Touch {
    let pose = collider.position();
    let p = to_f64(pose.inverse_transform_point(to_f32(point)));
    let n = to_f64(pose.inverse_transform_vector(to_f32(normal)));
    let n = n / n.norm();
    let local = read(collider.shape(), &p, &n, radius);
    Touch {
        direction: to_f64(pose.transform_vector(to_f32(&local.direction))),
        ..local
    }
}

/// The counterpart of `shape` at the local point `p` with local outward normal `n`.
///
/// The analytic shapes are read from where a point just outside the surface lies
/// (`p + 1e-3 R n`): which of the shape's faces, edges or vertices is nearest to it follows from
/// which of its bounds it is past, without trusting the contact's normal to better than a few
/// degrees (parry's normal on a rounded shape is from GJK/EPA and was seen 2.3° off).
fn read(shape: &dyn Shape, p: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Touch {
    let probe = p + n * (1e-3 * radius);
    read_at(shape, &probe, p, n, radius)
}

/// [`read`] with the probe point `q` (outside the shape, or on it) given: for a rounded shape
/// the point on the rounded surface is the probe of its inner shape.
fn read_at(
    shape: &dyn Shape,
    q: &Vector3<f64>,
    p: &Vector3<f64>,
    n: &Vector3<f64>,
    radius: f64,
) -> Touch {
    match shape.as_typed_shape() {
        TypedShape::Ball(b) => {
            let k = 1.0 / f64::from(b.radius);
            Touch::curved(k, k, any_tangent(n), n, radius)
        }
        TypedShape::HalfSpace(_) => Touch::plane(n),
        TypedShape::Cuboid(c) => cuboid(&to_f64(c.half_extents), q, n),
        TypedShape::Voxels(_) => box_feature(n),
        TypedShape::Capsule(c) => {
            let (a, b) = (to_f64(c.segment.a), to_f64(c.segment.b));
            capsule(&a, &b, f64::from(c.radius), q, n, radius)
        }
        TypedShape::Cylinder(c) => {
            cylinder(f64::from(c.half_height), f64::from(c.radius), q, n, radius)
        }
        TypedShape::Cone(c) => cone(f64::from(c.half_height), f64::from(c.radius), q, n, radius),
        TypedShape::Segment(s) => along(&to_f64(s.a), &to_f64(s.b), n),
        TypedShape::Polyline(l) => {
            let nearest = l
                .segments()
                .map(|s| (s.distance_to_local_point(to_f32(p), true), s))
                .min_by(|a, b| a.0.total_cmp(&b.0));
            match nearest {
                Some((_, s)) => along(&to_f64(s.a), &to_f64(s.b), n),
                None => Touch::plane(n),
            }
        }
        TypedShape::Triangle(t) => {
            let mut fit = Fit::new(p, n, radius);
            fit.add(t);
            fit.finish()
        }
        TypedShape::TriMesh(m) => {
            let mut fit = Fit::new(p, n, radius);
            let aabb = fit.query_box();
            for i in m.bvh().intersect_aabb(&aabb) {
                fit.add(&m.triangle(i));
            }
            fit.finish()
        }
        TypedShape::HeightField(h) => {
            let mut fit = Fit::new(p, n, radius);
            h.map_elements_in_local_aabb(&fit.query_box(), &mut |_, t| fit.add(t));
            fit.finish()
        }
        TypedShape::ConvexPolyhedron(c) => polyhedron(c, p, n, radius),
        TypedShape::Compound(c) => compound(c, p, n, radius),
        TypedShape::RoundCuboid(s) => rounded(&s.inner_shape, s.border_radius, p, n, radius),
        TypedShape::RoundTriangle(s) => rounded(&s.inner_shape, s.border_radius, p, n, radius),
        TypedShape::RoundCylinder(s) => rounded(&s.inner_shape, s.border_radius, p, n, radius),
        TypedShape::RoundCone(s) => rounded(&s.inner_shape, s.border_radius, p, n, radius),
        TypedShape::RoundConvexPolyhedron(s) => {
            rounded(&s.inner_shape, s.border_radius, p, n, radius)
        }
        // A user shape parry knows nothing of: a plane, as before counterparts were read.
        _ => Touch::plane(n),
    }
}

/// A convex polyhedron read as its faces' triangles (a fan over each polygon) near `p`.
fn polyhedron(c: &ConvexPolyhedron, p: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Touch {
    let mut fit = Fit::new(p, n, radius);
    let (points, ids) = (c.points(), c.vertices_adj_to_face());
    for face in c.faces() {
        let first = face.first_vertex_or_edge as usize;
        let count = face.num_vertices_or_edges as usize;
        let corner = |i: usize| points[ids[first + i] as usize];
        // A fan of triangles over the polygon.
        for i in 1..count.saturating_sub(1) {
            fit.add(&Triangle::new(corner(0), corner(i), corner(i + 1)));
        }
    }
    fit.finish()
}

/// A compound read as its part nearest `p`, in the part's frame.
fn compound(c: &Compound, p: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Touch {
    let part = c.shapes().iter().min_by(|a, b| {
        let d = |(pose, s): &(Pose, _)| {
            let s: &rapier3d::parry::shape::SharedShape = s;
            s.distance_to_local_point(pose.inverse_transform_point(to_f32(p)), true)
        };
        d(a).total_cmp(&d(b))
    });
    match part {
        Some((pose, s)) => {
            let lp = to_f64(pose.inverse_transform_point(to_f32(p)));
            let ln = to_f64(pose.inverse_transform_vector(to_f32(n)));
            let t = read(s.as_ref(), &lp, &(ln / ln.norm()), radius);
            Touch {
                direction: to_f64(pose.transform_vector(to_f32(&t.direction))),
                ..t
            }
        }
        None => Touch::plane(n),
    }
}

/// A shape rounded by `border` \[m\]: the inner shape's counterpart where the point on the
/// rounded surface (`border` outside the inner shape: its probe) lies, its surface offset
/// outwards by `border` (principal directions kept, `k -> k/(1 + k border)`; an edge's sharp
/// direction becomes `1/border`, a vertex a ball of `border`).
fn rounded(
    inner: &dyn Shape,
    border: f32,
    p: &Vector3<f64>,
    n: &Vector3<f64>,
    radius: f64,
) -> Touch {
    let border = f64::from(border);
    let q = p + n * (1e-3 * radius);
    let t = read_at(inner, &q, &(p - border * n), n, radius);
    let offset = |k: f64| k / (1.0 + k * border);
    match t.counterpart.kind() {
        softgrip_law::CounterpartKind::Plane => t,
        softgrip_law::CounterpartKind::Edge if t.vertex => {
            let k = 1.0 / border;
            Touch::curved(k, k, t.direction, n, radius)
        }
        softgrip_law::CounterpartKind::Edge => {
            Touch::curved(0.0, 1.0 / border, t.direction, n, radius)
        }
        softgrip_law::CounterpartKind::Curved => {
            let [k1, k2] = t.counterpart.curvatures();
            Touch::curved(offset(k1), offset(k2), t.direction, n, radius)
        }
    }
}

/// A cuboid of half extents `h` by where the probe `q` is past its faces: past one a face,
/// past two an edge along the third axis, past three a corner; inside (a deep contact) by the
/// normal.
fn cuboid(h: &Vector3<f64>, q: &Vector3<f64>, n: &Vector3<f64>) -> Touch {
    let past = [q.x.abs() > h.x, q.y.abs() > h.y, q.z.abs() > h.z];
    match past.iter().filter(|b| **b).count() {
        0 => box_feature(n),
        1 => Touch::plane(n),
        2 => {
            let axis = past.iter().position(|b| !*b).unwrap_or(0);
            Touch::edge(Vector3::ith(axis, 1.0))
        }
        _ => Touch::vertex(Vector3::ith(n.iamin(), 1.0)),
    }
}

/// A cuboid (or a voxel) by its normal: one non-zero component is a face, two an edge along the
/// third axis, three a corner (read as an edge along the axis of the smallest component).
fn box_feature(n: &Vector3<f64>) -> Touch {
    let tilted = n.iter().filter(|c| c.abs() > ALIGNED).count();
    if tilted <= 1 {
        return Touch::plane(n);
    }
    let axis = n.iamin();
    if tilted == 2 {
        Touch::edge(Vector3::ith(axis, 1.0))
    } else {
        Touch::vertex(Vector3::ith(axis, 1.0))
    }
}

/// A capsule of segment `a`-`b` and radius `r`: its side is a cylinder, its caps balls.
fn capsule(
    a: &Vector3<f64>,
    b: &Vector3<f64>,
    r: f64,
    q: &Vector3<f64>,
    n: &Vector3<f64>,
    radius: f64,
) -> Touch {
    let k = 1.0 / r;
    let ab = b - a;
    let len = ab.norm();
    if !(len > 0.0) {
        return Touch::curved(k, k, any_tangent(n), n, radius);
    }
    let axis = ab / len;
    // The side projects inside the segment; where side and cap meet the normal decides.
    let t = (q - a).dot(&axis) / len;
    let inside = t > 1e-6 && t < 1.0 - 1e-6;
    if inside || n.dot(&axis).abs() < ALIGNED {
        Touch::curved(0.0, k, axis, n, radius)
    } else {
        Touch::curved(k, k, any_tangent(n), n, radius)
    }
}

/// A cylinder of half-height `h` and radius `r` about the local y axis, by where the probe
/// `q` is: past the side (radially) the side, past a cap the cap, past both the rim; inside
/// (a deep contact) by the normal.
fn cylinder(h: f64, r: f64, q: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Touch {
    let rho = (q.x * q.x + q.z * q.z).sqrt();
    let (side, cap) = (rho > r, q.y.abs() > h);
    let (side, cap) = if side || cap {
        (side, cap)
    } else {
        (n.y.abs() < S45, n.y.abs() >= S45)
    };
    match (side, cap) {
        (true, false) => Touch::curved(0.0, 1.0 / r, Vector3::y(), n, radius),
        (false, _) => Touch::plane(n),
        (true, true) => Touch::edge(Vector3::new(-q.z, 0.0, q.x) / rho),
    }
}

/// `cos 45°`.
const S45: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// A cone of half-height `h` and base radius `r` (base at y = -h, apex at y = +h), by the
/// feature of its profile (the triangle apex A = (0, h), rim B = (r, -h), base centre
/// C = (0, -h) in the (rho, y) half-plane) nearest the probe `q`: the side AB, the base BC,
/// the rim B or the apex A.
fn cone(h: f64, r: f64, q: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Touch {
    let rho = (q.x * q.x + q.z * q.z).sqrt();
    let slant = (4.0 * h * h + r * r).sqrt();
    // The radial unit vector (any, on the axis).
    let out = if rho > 0.0 {
        Vector3::new(q.x, 0.0, q.z) / rho
    } else {
        any_tangent(&Vector3::y())
    };
    // Along the side from A to B, and the probe's parameter on it.
    let (ab_r, ab_y) = (r / slant, -2.0 * h / slant);
    let t_side = rho * ab_r + (q.y - h) * ab_y;
    let d_side = {
        let t = t_side.clamp(0.0, slant);
        (rho - t * ab_r).hypot(q.y - h - t * ab_y)
    };
    // The base, from C to B.
    let d_base = (rho - rho.clamp(0.0, r)).hypot(q.y + h);
    if d_base < d_side {
        return if rho < r {
            Touch::plane(n)
        } else {
            Touch::edge(Vector3::new(-out.z, 0.0, out.x))
        };
    }
    if t_side <= 0.0 {
        return Touch::vertex(any_tangent(n));
    }
    if t_side >= slant {
        return Touch::edge(Vector3::new(-out.z, 0.0, out.x));
    }
    // Along the generator, base to apex; the parallel circle of radius rho_s (at the foot of
    // the probe on the side) with its normal tilted from the horizontal by the side's slope:
    // normal curvature cos(beta)/rho_s, cos(beta) = 2h/slant.
    let generator = -ab_r * out - ab_y * Vector3::y();
    let rho_s = t_side * ab_r;
    Touch::curved(0.0, 2.0 * h / (slant * rho_s), generator, n, radius)
}

/// A segment `a`-`b` (a line on its own, a polyline's piece): an edge along it.
fn along(a: &Vector3<f64>, b: &Vector3<f64>, n: &Vector3<f64>) -> Touch {
    let d = b - a;
    let t = d - n * n.dot(&d);
    if t.norm() > 0.0 {
        Touch::edge(t / t.norm())
    } else {
        Touch::edge(any_tangent(n))
    }
}

/// The local fit of a faceted surface around a contact point (the module docs), accumulated
/// facet by facet (no buffer).
struct Fit {
    p0: Vector3<f64>,
    n0: Vector3<f64>,
    /// A tangent basis at the point.
    t1: Vector3<f64>,
    t2: Vector3<f64>,
    radius: f64,
    /// Distance within which a facet is on the contact's feature \[m\].
    touch: f64,
    /// The touching facet's normal farthest from `n0`, and its angle.
    far: Option<(Vector3<f64>, f64)>,
    /// The normal equations of the fit of `S` (s11, s12, s22).
    m: Matrix3<f64>,
    b: Vector3<f64>,
    facets: u32,
}

impl Fit {
    fn new(p: &Vector3<f64>, n: &Vector3<f64>, radius: f64) -> Self {
        let t1 = any_tangent(n);
        let t2 = n.cross(&t1);
        Self {
            p0: *p,
            n0: *n,
            t1,
            t2,
            radius,
            touch: 2e-4 * radius + 1e-6 * p.norm(),
            far: None,
            m: Matrix3::zeros(),
            b: Vector3::zeros(),
            facets: 0,
        }
    }

    /// The local box of facets that can count: within R of the point.
    fn query_box(&self) -> Aabb {
        let c = to_f32(&self.p0);
        let h = Vector::splat((self.radius + self.touch) as f32);
        Aabb::new(c - h, c + h)
    }

    fn add(&mut self, t: &Triangle) {
        let Some(normal) = t.normal() else {
            return; // a degenerate triangle
        };
        let mut nf = to_f64(normal);
        // Meshes need not be oriented: each facet is taken facing the fingertip.
        if nf.dot(&self.n0) < 0.0 {
            nf = -nf;
        }
        let angle = nf.dot(&self.n0).clamp(-1.0, 1.0).acos();
        let dist = f64::from(t.distance_to_local_point(to_f32(&self.p0), true));
        if dist <= self.touch && self.far.is_none_or(|(_, a)| angle > a) {
            self.far = Some((nf, angle));
        }
        let c = to_f64(t.center());
        let d = c - self.p0;
        if angle >= SHARP_DIHEDRAL || d.norm() > self.radius {
            return;
        }
        let w = f64::from(t.area());
        let (d1, d2) = (d.dot(&self.t1), d.dot(&self.t2));
        let (n1, n2) = (nf.dot(&self.t1), nf.dot(&self.t2));
        // Normal equations of min sum w |S d - dn|^2 over (s11, s12, s22).
        self.m += w * Matrix3::new(
            d1 * d1,
            d1 * d2,
            0.0,
            d1 * d2,
            d1 * d1 + d2 * d2,
            d1 * d2,
            0.0,
            d1 * d2,
            d2 * d2,
        );
        self.b += w * Vector3::new(d1 * n1, d2 * n1 + d1 * n2, d2 * n2);
        self.facets += 1;
    }

    fn finish(self) -> Touch {
        if let Some((nf, angle)) = self.far
            && angle >= 0.5 * SHARP_DIHEDRAL
        {
            // A sharp ridge: along it, i.e. orthogonal to both normals.
            let along = nf.cross(&self.n0);
            let along = along - self.n0 * self.n0.dot(&along);
            return if along.norm() > 0.0 {
                Touch::edge(along / along.norm())
            } else {
                Touch::edge(self.t1)
            };
        }
        if self.facets < 2 {
            return Touch::plane(&self.n0);
        }
        // Tikhonov: facets in a row (a tessellated cylinder seen from one edge) leave the
        // curvature along the row free; the smallest-norm solution reads it as 0.
        let scale = self.m.trace().max(f64::MIN_POSITIVE);
        let m = self.m + Matrix3::identity() * (1e-9 * scale);
        let Some(s) = m.lu().solve(&self.b) else {
            return Touch::plane(&self.n0);
        };
        let (s11, s12, s22) = (s.x, s.y, s.z);
        // Eigen-decomposition of [[s11, s12], [s12, s22]].
        let mean = 0.5 * (s11 + s22);
        let half = (0.25 * (s11 - s22) * (s11 - s22) + s12 * s12).sqrt();
        let (k1, k2) = (mean - half, mean + half);
        // k1's direction: (s12, k1 - s11) or (k1 - s22, s12), the better conditioned.
        let (u, v) = if (k1 - s11).abs() + s12.abs() >= (k1 - s22).abs() + s12.abs() {
            (s12, k1 - s11)
        } else {
            (k1 - s22, s12)
        };
        let dir = if u.hypot(v) > 0.0 {
            (u * self.t1 + v * self.t2) / u.hypot(v)
        } else {
            self.t1
        };
        let floor = 1e-4 / self.radius;
        let clean = |k: f64| if k.abs() < floor { 0.0 } else { k };
        Touch::curved(clean(k1), clean(k2), dir, &self.n0, self.radius)
    }
}
