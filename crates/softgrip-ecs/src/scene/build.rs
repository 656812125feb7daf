//! From scene specs to the ECS components (and, through them, to rapier builders).

use softgrip_rapier::SoftFingertip;
use softgrip_rapier::rapier3d::prelude::{SharedShape, Vector};

use super::format::{BodyKindSpec, BodySpec, FingertipSpec, ShapeKind, ShapeSpec};
use super::mesh::Mesh;
use crate::components::{BodyKind, Collider, Fingertip, RigidBody};

fn v32(v: [f64; 3]) -> Vector {
    Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

/// The geometry of a checked shape spec; `None` if a mesh is degenerate.
pub(crate) fn shape(s: &ShapeSpec, mesh: Option<Mesh>) -> Option<SharedShape> {
    let r = s.radius.unwrap_or_default() as f32;
    Some(match s.kind {
        ShapeKind::Plane => SharedShape::halfspace(v32(s.normal?).normalize()),
        ShapeKind::Cuboid => {
            let h = s.half_extents?;
            SharedShape::cuboid(h[0] as f32, h[1] as f32, h[2] as f32)
        }
        ShapeKind::Ball => SharedShape::ball(r),
        ShapeKind::Cylinder => SharedShape::cylinder(s.half_height? as f32, r),
        ShapeKind::ConvexMesh => {
            let points: Vec<Vector> = mesh?.vertices.into_iter().map(v32).collect();
            SharedShape::convex_hull(&points)?
        }
        ShapeKind::TriangleMesh => {
            let m = mesh?;
            SharedShape::trimesh(m.vertices.into_iter().map(v32).collect(), m.triangles).ok()?
        }
    })
}

/// The [`RigidBody`] component of a body spec.
pub fn body_from_spec(b: &BodySpec) -> RigidBody {
    RigidBody {
        kind: match b.kind {
            BodyKindSpec::Fixed => BodyKind::Fixed,
            BodyKindSpec::Dynamic => BodyKind::Dynamic,
            BodyKindSpec::Kinematic => BodyKind::Kinematic,
        },
        position: b.position,
        rotation: b.rotation,
    }
}

/// The [`Collider`] component of a shape spec with its built geometry.
pub fn collider_from_spec(s: &ShapeSpec, shape: SharedShape) -> Collider {
    Collider {
        shape,
        offset: s.offset,
        density: s.density,
        friction: s.friction,
        restitution: s.restitution,
    }
}

/// The [`Fingertip`] component of a fingertip spec with its built fingertip.
pub fn fingertip_from_spec(t: &FingertipSpec, tip: SoftFingertip) -> Fingertip {
    Fingertip {
        tip,
        offset: t.offset,
        density: t.density,
    }
}
