//! Links held together by fixed joints whose collision shapes overlap.
//!
//! rapier skips the contacts of two links joined directly by a joint, but not of two links
//! joined through a chain of fixed joints (the Panda's `panda_link7` and `panda_hand`, through
//! `panda_link8`): such a pair, if its shapes overlap, is in contact at every pose, and the
//! solver pushes the links apart while the fixed joints hold them together. The Panda's arm went
//! to NaN in one step of a lift that way. A robot whose self-contacts are on is refused when
//! such a pair overlaps; the message names both links, the depth, and the remedy.

use rapier3d_urdf::UrdfRobot;
use softgrip_rapier::rapier3d::parry::query;

use crate::robot::model::{JointKind, RobotJoint, RobotLink};

/// Penetration below which two fixed-together links are taken as touching, not overlapping,
/// as a fraction of the smaller link's bounding radius (1e-3: a shared face modelled twice).
const OVERLAP_TOLERANCE: f64 = 1e-3;

/// The first pair of links joined through fixed joints only (not directly) whose collision
/// shapes overlap deeper than the tolerance: `(link a, link b, depth [m])`.
pub(crate) fn fixed_overlap(
    rapier: &UrdfRobot,
    links: &[RobotLink],
    joints: &[RobotJoint],
) -> Option<(String, String, f64)> {
    let n = rapier.links.len().min(links.len());
    // Rigid clusters: links joined by fixed joints (union-find).
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for j in joints.iter().filter(|j| j.kind == JointKind::Fixed) {
        if j.parent < n && j.child < n {
            let (a, b) = (find(&mut parent, j.parent), find(&mut parent, j.child));
            parent[a] = b;
        }
    }
    let joined = |a: usize, b: usize| {
        (joints.iter()).any(|j| (j.parent, j.child) == (a, b) || (j.parent, j.child) == (b, a))
    };
    for a in 0..n {
        for b in a + 1..n {
            if find(&mut parent, a) != find(&mut parent, b) || joined(a, b) {
                continue;
            }
            if let Some(depth) = link_overlap(rapier, a, b) {
                return Some((links[a].name.clone(), links[b].name.clone(), depth));
            }
        }
    }
    None
}

/// The deepest penetration of links `a` and `b`'s shapes past the tolerance \[m\], if any.
fn link_overlap(rapier: &UrdfRobot, a: usize, b: usize) -> Option<f64> {
    let (la, lb) = (&rapier.links[a], &rapier.links[b]);
    let mut deepest: Option<f64> = None;
    for ca in &la.colliders {
        for cb in &lb.colliders {
            let pa = *la.body.position() * *ca.collider.position();
            let pb = *lb.body.position() * *cb.collider.position();
            let (sa, sb) = (ca.collider.shape(), cb.collider.shape());
            let size = (sa.compute_local_bounding_sphere().radius())
                .min(sb.compute_local_bounding_sphere().radius()) as f64;
            let Ok(Some(c)) = query::contact(&pa, sa, &pb, sb, 0.0) else {
                continue;
            };
            let depth = -(c.dist as f64);
            if depth > OVERLAP_TOLERANCE * size && deepest.is_none_or(|d| depth > d) {
                deepest = Some(depth);
            }
        }
    }
    deepest
}
