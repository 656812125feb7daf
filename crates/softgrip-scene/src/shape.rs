//! The geometry of a checked shape spec (primitive or mesh), as a rapier [`SharedShape`].

use softgrip_rapier::rapier3d::prelude::{SharedShape, Vector};

use crate::format::{ShapeKind, ShapeSpec};
use crate::mesh::Mesh;
use crate::vector::vector;

/// The geometry of a checked shape spec; `None` if a mesh is degenerate.
pub(crate) fn shape(s: &ShapeSpec, mesh: Option<Mesh>) -> Option<SharedShape> {
    let r = s.radius.unwrap_or_default() as f32;
    Some(match s.kind {
        ShapeKind::Plane => {
            // Normalised in f64 first: a tiny normal (1e-50) is 0 as f32.
            let n = s.normal?;
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            SharedShape::halfspace(vector(n.map(|c| c / len)).normalize())
        }
        ShapeKind::Cuboid => {
            let h = s.half_extents?;
            SharedShape::cuboid(h[0] as f32, h[1] as f32, h[2] as f32)
        }
        ShapeKind::Ball => SharedShape::ball(r),
        ShapeKind::Cylinder => SharedShape::cylinder(s.half_height? as f32, r),
        ShapeKind::ConvexMesh => {
            let points: Vec<Vector> = mesh?.vertices.into_iter().map(vector).collect();
            SharedShape::convex_hull(&points)?
        }
        ShapeKind::TriangleMesh => {
            let m = mesh?;
            SharedShape::trimesh(m.vertices.into_iter().map(vector).collect(), m.triangles).ok()?
        }
    })
}
