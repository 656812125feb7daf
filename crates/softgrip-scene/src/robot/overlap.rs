//! A robot's links that are always in contact, kept from touching, and the ones that start
//! overlapping.
//!
//! rapier skips the contacts of two links joined directly by a joint, but not of two links
//! welded through a chain of fixed joints (the Franka Panda's `panda_link7` and `panda_hand`,
//! 23 mm deep through `panda_link8`), nor of the links of a closed chain written as a tree (the
//! xArm gripper's finger and inner knuckle, 12 mm deep at their shared pin, and its outer and
//! inner knuckles, 1.9 mm at the start and 3.7 mm as it closes): their shapes overlap at every
//! pose, and rapier pushes them apart against their own joints (the Panda's arm went to NaN in
//! one step of a lift; the xArm threw its drive joint 0.73 rad open in the first step, and with
//! only the pairs overlapping at the start kept apart its grasp diverged as it closed). As
//! MoveIt's setup assistant disables the pairs "always in collision" (in at least 95 % of
//! sampled configurations), every pair of a robot's links (not joined directly) that is in
//! contact in at least [`ALWAYS_SHARE`] of [`SAMPLES`] configurations over its joints' ranges
//! (mimic joints following their leaders; a Halton sequence, the same for every load) is kept
//! from touching (`SoftWorld::exclude_pair`) when its self-contacts are on; every other pair
//! still collides. Two links that are not always in contact but start overlapping deeper than
//! rapier's allowed linear error are refused (`start::check_self_overlap`: a start pose to fix).

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::parry::bounding_volume::BoundingVolume;
use softgrip_rapier::rapier3d::parry::query;

use crate::robot::build::RobotHandles;
use softgrip_rapier::rapier3d::prelude::{Pose, Rotation, Vector};

use crate::robot::model::{JointKind, Robot, RobotJoint};
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

/// Configurations sampled over a robot's joint ranges for [`always_in_contact`].
pub const SAMPLES: usize = 128;

/// The share of the [`SAMPLES`] in which a pair of links must be in contact to be kept apart
/// (MoveIt's "always in collision": 95 %).
pub const ALWAYS_SHARE: f64 = 0.95;

/// The pairs of `robot`'s links (index pairs, the lower first) not joined directly by a joint
/// whose collision shapes are in contact (penetrating) in at least [`ALWAYS_SHARE`] of
/// [`SAMPLES`] configurations: each moving joint that is not a mimic at a point of a Halton
/// sequence over its limits (a continuous joint over one turn, an unbounded prismatic over
/// +-1 m), each mimic at `multiplier q + offset` of its leader, fixed joints as they are; link
/// poses from the URDF's joint frames (`Robot::rapier`).
pub fn always_in_contact(robot: &Robot) -> Vec<(usize, usize)> {
    let rapier = robot.rapier();
    let n = rapier.links.len().min(robot.links().len());
    let joints = robot.joints();
    let joined = |a: usize, b: usize| {
        (joints.iter()).any(|j| (j.parent, j.child) == (a, b) || (j.parent, j.child) == (b, a))
    };
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            let has = |l: usize| !rapier.links[l].colliders.is_empty();
            if has(a) && has(b) && !joined(a, b) {
                pairs.push((a, b));
            }
        }
    }
    if pairs.is_empty() {
        return pairs;
    }
    let free: Vec<usize> = (0..joints.len())
        .filter(|&j| joints[j].kind.moves() && joints[j].mimic.is_none())
        .collect();
    let mut hits = vec![0usize; pairs.len()];
    let mut q = vec![0.0f64; joints.len()];
    for k in 0..SAMPLES {
        for (d, &j) in free.iter().enumerate() {
            let [lo, hi] = range(&joints[j]);
            q[j] = lo + (hi - lo) * halton(k + 1, PRIMES[d % PRIMES.len()]);
        }
        // Mimics after their leaders (a chain of mimics: as many passes as joints).
        for _ in 0..joints.len() {
            for (j, joint) in joints.iter().enumerate() {
                if let Some(m) = joint.mimic {
                    q[j] = m.multiplier * q[m.joint] + m.offset;
                }
            }
        }
        let poses = link_poses(robot, &q);
        for (h, &(a, b)) in pairs.iter().enumerate() {
            if in_contact(robot, &poses, a, b) {
                hits[h] += 1;
            }
        }
    }
    let need = (ALWAYS_SHARE * SAMPLES as f64).ceil() as usize;
    (pairs.into_iter().zip(hits))
        .filter(|&(_, h)| h >= need)
        .map(|(p, _)| p)
        .collect()
}

/// The first primes: the Halton bases of a robot's free joints.
const PRIMES: [u32; 16] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53];

/// The radical inverse of `k` in base `b`: a point of the Halton sequence in \[0, 1).
fn halton(mut k: usize, b: u32) -> f64 {
    let (mut f, mut r) = (1.0, 0.0);
    let b = b as usize;
    while k > 0 {
        f /= b as f64;
        r += f * (k % b) as f64;
        k /= b;
    }
    r
}

/// The range a joint is sampled over \[m or rad\].
fn range(j: &RobotJoint) -> [f64; 2] {
    let [lo, hi] = j.limits;
    match j.kind {
        JointKind::Continuous => [-std::f64::consts::PI, std::f64::consts::PI],
        _ if lo.is_finite() && hi.is_finite() && lo <= hi => [lo, hi],
        _ => [-1.0, 1.0],
    }
}

/// Each link's pose at joint positions `q` (the root where the URDF puts it): the child of a
/// joint at `parent * frame1 * motion(q) * frame2^-1`, the motion a rotation about the joint
/// frame's x axis (revolute, continuous) or a translation along it (prismatic), as rapier's
/// joint coordinates read it.
fn link_poses(robot: &Robot, q: &[f64]) -> Vec<Option<Pose>> {
    let rapier = robot.rapier();
    let n = rapier.links.len();
    let mut poses: Vec<Option<Pose>> = vec![None; n];
    if let Some(root) = poses.get_mut(robot.root()) {
        *root = Some(*rapier.links[robot.root()].body.position());
    }
    for _ in 0..rapier.joints.len() {
        let mut moved = false;
        for (j, uj) in rapier.joints.iter().enumerate() {
            let (Some(Some(parent)), None) =
                (poses.get(uj.link1), poses.get(uj.link2).copied().flatten())
            else {
                continue;
            };
            let qj = q.get(j).copied().unwrap_or(0.0) as f32;
            let motion = match robot.joints().get(j).map(|r| r.kind) {
                Some(JointKind::Revolute | JointKind::Continuous) => {
                    Pose::from_rotation(Rotation::from_axis_angle(Vector::X, qj))
                }
                Some(JointKind::Prismatic) => Pose::from_translation(Vector::X * qj),
                _ => Pose::IDENTITY,
            };
            let data = &uj.joint;
            let child = *parent * data.local_frame1 * motion * data.local_frame2.inverse();
            if let Some(slot) = poses.get_mut(uj.link2) {
                *slot = Some(child);
                moved = true;
            }
        }
        if !moved {
            break;
        }
    }
    poses
}

/// Whether a collision shape of link `a` penetrates one of link `b` at `poses`.
fn in_contact(robot: &Robot, poses: &[Option<Pose>], a: usize, b: usize) -> bool {
    let rapier = robot.rapier();
    let (Some(Some(pa)), Some(Some(pb))) = (poses.get(a), poses.get(b)) else {
        return false;
    };
    for ca in &rapier.links[a].colliders {
        for cb in &rapier.links[b].colliders {
            let (xa, xb) = (*pa * *ca.collider.position(), *pb * *cb.collider.position());
            let (sa, sb) = (ca.collider.shape(), cb.collider.shape());
            if !sa.compute_aabb(&xa).intersects(&sb.compute_aabb(&xb)) {
                continue;
            }
            if let Ok(Some(c)) = query::contact(&xa, sa, &xb, sb, 0.0)
                && c.dist < 0.0
            {
                return true;
            }
        }
    }
    false
}

/// Keeps every pair of [`always_in_contact`] from touching in `world` when `robot`'s
/// self-contacts are on; an impulse-jointed robot with its self-contacts off, every pair of
/// its links (a multibody's are rapier's own: `Multibody::set_self_contacts_enabled`). Returns
/// the pairs kept apart (link indices).
pub(crate) fn keep_apart(
    robot: &Robot,
    h: &RobotHandles,
    world: &mut SoftWorld,
) -> Vec<(usize, usize)> {
    let pairs: Vec<(usize, usize)> = if robot.self_contacts() {
        always_in_contact(robot)
    } else if robot.joint_model() == JointModel::Impulse {
        let n = h.links.len();
        (0..n)
            .flat_map(|a| (a + 1..n).map(move |b| (a, b)))
            .collect()
    } else {
        Vec::new()
    };
    for &(a, b) in &pairs {
        if let (Some(&ha), Some(&hb)) = (h.links.get(a), h.links.get(b)) {
            // Both are bodies of this world, two different links.
            let _ = world.exclude_pair(ha, hb);
        }
    }
    pairs
}
