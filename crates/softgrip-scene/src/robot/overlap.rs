//! A robot's links that start overlapping.
//!
//! rapier skips the contacts of two links joined directly by a joint, but not of two links
//! welded through a chain of fixed joints (the Franka Panda's `panda_link7` and `panda_hand`,
//! 23 mm deep through `panda_link8`): such a pair, if its shapes overlap, does so at every
//! pose, and rapier pushes the links apart against their own fixed joints (the Panda's arm went
//! to NaN in one step of a lift). As MoveIt's setup assistant disables the pairs that are
//! always in collision, such a pair is kept from touching (`SoftWorld::exclude_pair`) when the
//! robot's self-contacts are on; every other pair still collides. Two links that move against
//! each other and start overlapping (a closed chain written as a tree: the xArm gripper's
//! finger and inner knuckle, 12 mm deep at their shared pin) are refused instead
//! (`start::check_self_overlap`): keeping only the overlapping pair apart is not enough there
//! (with its two pairs kept apart the xArm's outer and inner knuckles, 1.9 mm deep at the
//! start, pressed 3.7 mm into each other as it closed and the grasp diverged).

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::parry::bounding_volume::BoundingVolume;
use softgrip_rapier::rapier3d::parry::query;

use crate::robot::build::RobotHandles;
use crate::robot::model::{JointKind, Robot};
use crate::robot::spec::JointModel;

/// Two links of a robot that start overlapping: link indices (`Robot::links`) and the deepest
/// penetration of their collision shapes \[m\].
#[derive(Debug, Clone, PartialEq)]
pub struct StartOverlap {
    /// The first link (the lower index).
    pub link_a: usize,
    /// The second link.
    pub link_b: usize,
    /// The deepest penetration of any shape of one into any shape of the other \[m\] (more
    /// than rapier's allowed linear error).
    pub depth: f64,
}

/// The pairs of `robot`'s links (handles `h` in `world`) not joined directly by a joint whose
/// collision shapes overlap deeper than `world`'s allowed linear error at their present poses
/// (call before the first step: the start positions), deepest first; none when its
/// self-contacts are off (rapier keeps every pair apart then).
pub fn start_overlaps(robot: &Robot, h: &RobotHandles, world: &SoftWorld) -> Vec<StartOverlap> {
    if !robot.self_contacts() {
        return Vec::new();
    }
    let allowed = world.physics.integration_parameters.allowed_linear_error() as f64;
    let colliders = &world.physics.colliders;
    let joined = |a: usize, b: usize| {
        (robot.joints().iter())
            .any(|j| (j.parent, j.child) == (a, b) || (j.parent, j.child) == (b, a))
    };
    let shapes: Vec<_> = (h.colliders.iter().enumerate())
        .flat_map(|(l, cs)| cs.iter().map(move |ch| (l, *ch)))
        .filter_map(|(l, ch)| {
            let co = colliders.get(ch)?;
            let pose = crate::start::start_pose(world, co);
            Some((l, ch, pose, co.shape().compute_aabb(&pose)))
        })
        .collect();
    let mut out: Vec<StartOverlap> = Vec::new();
    for (m, &(la, ca, pa, ba)) in shapes.iter().enumerate() {
        for &(lb, cb, pb, bb) in &shapes[m + 1..] {
            if la == lb || joined(la, lb) || !ba.intersects(&bb) {
                continue;
            }
            let (sa, sb) = (colliders[ca].shape(), colliders[cb].shape());
            let Ok(Some(contact)) = query::contact(&pa, sa, &pb, sb, 0.0) else {
                continue;
            };
            let depth = -(contact.dist as f64);
            if depth <= allowed {
                continue;
            }
            let (link_a, link_b) = (la.min(lb), la.max(lb));
            match out
                .iter_mut()
                .find(|o| (o.link_a, o.link_b) == (link_a, link_b))
            {
                Some(o) => o.depth = o.depth.max(depth),
                None => out.push(StartOverlap {
                    link_a,
                    link_b,
                    depth,
                }),
            }
        }
    }
    out.sort_by(|x, y| y.depth.total_cmp(&x.depth));
    out
}

/// Whether links `a` and `b` of `robot` are welded together through fixed joints only.
pub fn welded(robot: &Robot, a: usize, b: usize) -> bool {
    let n = robot.links().len();
    if a >= n || b >= n {
        return false;
    }
    // Rigid clusters: links joined by fixed joints (union-find).
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for j in robot.joints().iter().filter(|j| j.kind == JointKind::Fixed) {
        if j.parent < n && j.child < n {
            let (x, y) = (find(&mut parent, j.parent), find(&mut parent, j.child));
            parent[x] = y;
        }
    }
    find(&mut parent, a) == find(&mut parent, b)
}

/// Keeps every pair of [`start_overlaps`] that is [`welded`] from touching in `world`; an
/// impulse-jointed robot with its self-contacts off, every pair of its links (a multibody's
/// are rapier's own: `Multibody::set_self_contacts_enabled`).
pub(crate) fn keep_apart(robot: &Robot, h: &RobotHandles, world: &mut SoftWorld) {
    if !robot.self_contacts() && robot.joint_model() == JointModel::Impulse {
        for (i, &a) in h.links.iter().enumerate() {
            for &b in &h.links[i + 1..] {
                // Both are bodies of this world, two different links.
                let _ = world.exclude_pair(a, b);
            }
        }
        return;
    }
    for p in start_overlaps(robot, h, world) {
        if !welded(robot, p.link_a, p.link_b) {
            continue;
        }
        let (Some(&a), Some(&b)) = (h.links.get(p.link_a), h.links.get(p.link_b)) else {
            continue;
        };
        // Both are bodies of this world, two different links.
        let _ = world.exclude_pair(a, b);
    }
}
