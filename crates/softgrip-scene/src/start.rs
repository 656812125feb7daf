//! The start of a run: a fingertip may start touching or slightly pressed into a body (the
//! plugin pushes it out through the law), but not deeper than the law's validity range (a
//! fingertip starting inside the box gave 44 kN at x = 1.52). That is an error naming the
//! pair and the depth ([`SceneError::StartPenetration`]), checked on the built world. A robot's
//! link must not start inside a dynamic body either ([`SceneError::StartOverlap`]): a cylinder
//! started 15 mm inside a gripper's palm was pushed 14.5 mm into the table in one step and
//! toppled.

use std::collections::HashMap;

use softgrip_rapier::rapier3d::parry::bounding_volume::{Aabb, BoundingVolume};
use softgrip_rapier::rapier3d::parry::partitioning::{Bvh, BvhBuildStrategy};
use softgrip_rapier::rapier3d::parry::query;
use softgrip_rapier::rapier3d::prelude::{Collider, ColliderHandle, Pose, Vector};
use softgrip_rapier::softgrip_law::{ContactLaw, ContactParams};

use crate::build::SceneHandles;
use crate::error::SceneError;
use crate::scene::Scene;
use crate::validate::Checker;

/// Every fingertip against every other collider of the built scene at its start poses that its
/// bounding box touches (a BVH of the colliders' boxes: the check is linear in the scene's size,
/// not quadratic; 1000 resting fingertips spent seconds here), in file order, so the first
/// error is the one a check of every pair would find first.
pub(crate) fn check_start(c: &Checker, scene: &Scene) -> Result<(), SceneError> {
    let mut built = scene.build();
    check_jointed_sweeps(c, scene, &mut built)?;
    let (world, h) = (&built.world, &built.handles);
    let labels = labels(scene, h);
    check_links(c, scene, &built)?;
    let tip_of: HashMap<ColliderHandle, usize> = h
        .fingertips
        .iter()
        .enumerate()
        .map(|(i, (_, t))| (*t, i))
        .collect();
    let colliders = &world.physics.colliders;
    // Bounded boxes go into the BVH; an unbounded shape (a plane) is a candidate of every tip.
    let boxes: Vec<Aabb> = labels
        .iter()
        .map(|(ch, _)| {
            let co = &colliders[*ch];
            co.shape().compute_aabb(&start_pose(world, co))
        })
        .collect();
    let bounded = |b: &Aabb| b.mins.is_finite() && b.maxs.is_finite() && b.volume().is_finite();
    let (mut finite, mut unbounded) = (Vec::new(), Vec::new());
    for (k, b) in boxes.iter().enumerate() {
        if bounded(b) {
            finite.push(k)
        } else {
            unbounded.push(k)
        }
    }
    let leaves: Vec<Aabb> = finite.iter().map(|&k| boxes[k]).collect();
    let bvh = Bvh::from_leaves(BvhBuildStrategy::Binned, &leaves);
    let mut candidates = Vec::new();
    for (i, (_, tip_h)) in h.fingertips.iter().enumerate() {
        let tip_co = &colliders[*tip_h];
        let tip_box = tip_co.shape().compute_aabb(&start_pose(world, tip_co));
        candidates.clear();
        candidates.extend(
            bvh.intersect_aabb(&tip_box)
                .map(|leaf| finite[leaf as usize]),
        );
        candidates.extend_from_slice(&unbounded);
        candidates.sort_unstable();
        for &k in &candidates {
            let (other_h, other_label) = &labels[k];
            check_pair(
                c,
                scene,
                &built.world,
                i,
                *tip_h,
                *other_h,
                other_label,
                &tip_of,
            )?;
        }
    }
    Ok(())
}

/// A collider's pose at the scene's start: its parent body's pose times its pose on the body.
/// The built world's colliders still sit where their bodies were inserted until rapier's first
/// step syncs them, and a robot's links were moved to their start joint positions after that
/// (forward kinematics of the bodies only): read from the collider, a pad on a finger was
/// checked where the finger is at joint position 0.
pub(crate) fn start_pose(world: &softgrip_rapier::SoftWorld, co: &Collider) -> Pose {
    match (co.parent(), co.position_wrt_parent()) {
        (Some(b), Some(rel)) => match world.physics.bodies.get(b) {
            Some(body) => *body.position() * *rel,
            None => *co.position(),
        },
        _ => *co.position(),
    }
}

/// Every impulse-jointed robot's padded links are ones the soft solve sees through their
/// joints ([`Robot::set_jointed_sweeps`](crate::Robot::set_jointed_sweeps), asked again of
/// the built world: it only raises sweeps, so a second call sets nothing new): otherwise
/// [`SceneError::JointedUnseen`] names the link and what it would need.
fn check_jointed_sweeps(
    c: &Checker,
    scene: &Scene,
    built: &mut crate::build::BuiltScene,
) -> Result<(), SceneError> {
    for (i, ((name, rh), robot)) in built.handles.robots.iter().zip(scene.robots()).enumerate() {
        let pads: Vec<usize> = (scene.carriers().iter())
            .filter_map(|carrier| match *carrier {
                crate::Carrier::Link { robot, link } if robot == i => Some(link),
                _ => None,
            })
            .collect();
        if let Err(unseen) = robot.set_jointed_sweeps(&mut built.world, rh, &pads) {
            return Err(SceneError::JointedUnseen {
                origin: c.origin.to_string(),
                field: format!("robot[{i}].joints"),
                link: format!(
                    "robot[{i}] (`{name}`) link `{}`",
                    robot.links()[unseen.link].name
                ),
                needed: unseen.needed,
                max: crate::robot::MAX_JOINTED_SWEEPS,
            });
        }
    }
    Ok(())
}

/// Every robot link's collision shape against every shape of a dynamic body at the start poses
/// (their bounding boxes first): deeper than rapier's allowed linear error is an error naming
/// both shapes and the depth. A robot's link against a fixed or kinematic body (a hand's base on
/// its table) is left to rapier, unless the link overlaps it at all along a direction its
/// joints cannot move it ([`SceneError::StartBlocked`], [`immobile_along`]).
fn check_links(
    c: &Checker,
    scene: &Scene,
    built: &crate::build::BuiltScene,
) -> Result<(), SceneError> {
    let (world, h) = (&built.world, &built.handles);
    if h.robots.is_empty() {
        return Ok(());
    }
    let colliders = &world.physics.colliders;
    let allowed = world.physics.integration_parameters.allowed_linear_error() as f64;
    let (mut dynamic, mut held) = (Vec::new(), Vec::new());
    for (s, label, kind) in body_shapes(scene, h) {
        if kind == crate::format::BodyKind::Dynamic {
            dynamic.push((s, label));
        } else {
            held.push((s, label));
        }
    }
    for (i, ((name, rh), robot)) in h.robots.iter().zip(scene.robots()).enumerate() {
        check_self_overlap(c, i, robot, rh, world, allowed)?;
        for (l, link_colliders) in rh.colliders.iter().enumerate() {
            for (k, lh) in link_colliders.iter().enumerate() {
                let lc = &colliders[*lh];
                let lpose = start_pose(world, lc);
                let lbox = lc.shape().compute_aabb(&lpose);
                let link = || {
                    let link = &robot.links()[l].name;
                    format!("robot[{i}] (`{name}`) link `{link}` collision[{k}]")
                };
                // The fixed body first: parry 0.31 gives a cuboid against a half-space (a
                // plane) as shape 2 the wrong points and normal.
                for (bh, label) in &held {
                    let Some(contact) = start_contact(world, *bh, (lc, &lpose, &lbox), true) else {
                        continue;
                    };
                    let depth = -(contact.dist as f64);
                    let Some(body) = lc.parent() else { continue };
                    if depth > 0.0 && immobile_along(world, body, contact.point2, contact.normal1) {
                        return Err(SceneError::StartBlocked {
                            origin: c.origin.to_string(),
                            link: link(),
                            other: label.clone(),
                            depth,
                        });
                    }
                }
                for (bh, label) in &dynamic {
                    let Some(contact) = start_contact(world, *bh, (lc, &lpose, &lbox), false)
                    else {
                        continue;
                    };
                    let depth = -(contact.dist as f64);
                    if depth > allowed {
                        return Err(SceneError::StartOverlap {
                            origin: c.origin.to_string(),
                            link: link(),
                            other: label.clone(),
                            depth,
                            allowed,
                        });
                    }
                }
            }
        }
    }
    Ok(())
}

/// A robot whose links collide with each other (`self_contacts = true`): no two of its links
/// that rapier lets collide (not joined directly, not always in contact: those are kept apart,
/// `robot::always_in_contact`) may start overlapping deeper
/// than rapier's allowed linear error, or rapier pushes them apart against their joints in the
/// first step. A closed chain modelled as a tree overlaps at every pose and is kept apart
/// (session 34; before, the xArm gripper of PyPI's pybullet, a four-bar per finger whose inner
/// knuckle and finger share a pin 12 mm deep, was refused here: with nothing kept apart it
/// threw its drive joint 0.73 rad open in the first step, its motor at its 50 N m limit and its
/// mimic joints 0.14 rad apart). A pair that overlaps at the start but not at almost every
/// pose is a start pose to fix: an error naming both links, the depth and the remedy
/// (`SceneError::Urdf`, field `robot[i].self_contacts`; `tests/self_contacts.rs`).
fn check_self_overlap(
    c: &Checker,
    i: usize,
    robot: &crate::Robot,
    rh: &crate::robot::RobotHandles,
    world: &softgrip_rapier::SoftWorld,
    allowed: f64,
) -> Result<(), SceneError> {
    let moving = crate::robot::start_overlaps(robot, rh, world)
        .into_iter()
        .find(|p| {
            let (a, b) = (rh.links[p.link_a], rh.links[p.link_b]);
            !world.soft.is_excluded(a, b)
        });
    let Some(p) = moving else {
        return Ok(());
    };
    let remedy = "set `self_contacts = false` (pybullet's and Gazebo's default)";
    let name = |l: usize| &robot.links()[l].name;
    Err(SceneError::Urdf {
        origin: c.origin.to_string(),
        field: format!("robot[{i}].self_contacts"),
        path: robot.urdf_path().to_path_buf(),
        message: format!(
            "links `{}` and `{}` start overlapping by {:.2} mm (more than rapier's allowed \
             linear error, {:.2} mm), and with `self_contacts = true` rapier pushes them apart \
             against their joints in the first step (they are not in contact at almost every \
             pose, so they are not kept apart); {remedy}, or start positions where they do not \
             overlap",
            name(p.link_a),
            name(p.link_b),
            p.depth * 1e3,
            allowed * 1e3
        ),
    })
}

/// The contact at the start poses of a robot link's collider (`link`: the collider, its start
/// pose and bounding box) with collider `other`, if their boxes touch and parry finds one
/// (within 0 m): with `other_first`, `other` is shape 1 (its normal `normal1`, the link's point
/// `point2`), else the link is.
fn start_contact(
    world: &softgrip_rapier::SoftWorld,
    other: ColliderHandle,
    link: (&Collider, &Pose, &Aabb),
    other_first: bool,
) -> Option<query::Contact> {
    let (lc, lpose, lbox) = link;
    let oc = &world.physics.colliders[other];
    let opose = start_pose(world, oc);
    if !lbox.intersects(&oc.shape().compute_aabb(&opose)) {
        return None;
    }
    let found = if other_first {
        query::contact(&opose, oc.shape(), lpose, lc.shape(), 0.0)
    } else {
        query::contact(lpose, lc.shape(), &opose, oc.shape(), 0.0)
    };
    found.ok().flatten()
}

/// Every body shape's collider, its label `body[j].shape[k]` (`name`) and its body's kind, in
/// file order.
fn body_shapes<'a>(
    scene: &'a Scene,
    h: &'a SceneHandles,
) -> impl Iterator<Item = (ColliderHandle, String, crate::format::BodyKind)> + 'a {
    let f = scene.file();
    (f.bodies.iter().enumerate())
        .flat_map(|(j, b)| (0..b.shapes.len()).map(move |k| (j, k, b)))
        .zip(h.shapes.iter())
        .map(|((j, k, b), (_, s))| (*s, format!("body[{j}].shape[{k}] (`{}`)", b.name), b.kind))
}

/// Whether the multibody link of rigid body `body` cannot move along `normal` at `point`
/// (world) through its joints: its multibody's jacobian (`Multibody::body_jacobian`, computed
/// at build by `forward_kinematics`) moves that point along `normal` by at most
/// `softgrip_rapier::IMMOBILE` (`f32::EPSILON`) of its motion in any direction, summed over the
/// dofs (a prismatic finger's vertical under a kinematic base). `false` for a body that is not
/// a dynamic multibody link (impulse-jointed robots, free bodies).
fn immobile_along(
    world: &softgrip_rapier::SoftWorld,
    body: softgrip_rapier::rapier3d::prelude::RigidBodyHandle,
    point: Vector,
    normal: Vector,
) -> bool {
    let w = &world.physics;
    let Some(rb) = w.bodies.get(body).filter(|rb| rb.is_dynamic()) else {
        return false;
    };
    let Some(id) = w.multibody_joints.rigid_body_link(body) else {
        return false;
    };
    let Some(mb) = w.multibody_joints.get_multibody(id.multibody) else {
        return false;
    };
    let jac = mb.body_jacobian(id.id);
    let arm = point - rb.mass_properties().world_com;
    let (mut along, mut all) = (0.0f64, 0.0f64);
    for c in 0..jac.ncols() {
        let lin = Vector::new(jac[(0, c)], jac[(1, c)], jac[(2, c)]);
        let ang = Vector::new(jac[(3, c)], jac[(4, c)], jac[(5, c)]);
        let v = lin + ang.cross(arm);
        along += (v.dot(normal) as f64).powi(2);
        all += v.length_squared() as f64;
    }
    along <= softgrip_rapier::IMMOBILE * all
}

/// A label for every collider: `body[j].shape[k]` (`name`), then `fingertip[i]` (`name`).
fn labels(scene: &Scene, h: &SceneHandles) -> Vec<(ColliderHandle, String)> {
    let mut labels: Vec<(ColliderHandle, String)> = (body_shapes(scene, h))
        .map(|(s, label, _)| (s, label))
        .collect();
    for (i, ((name, rh), robot)) in h.robots.iter().zip(scene.robots()).enumerate() {
        for (l, colliders) in rh.colliders.iter().enumerate() {
            for (k, co) in colliders.iter().enumerate() {
                let link = &robot.links()[l].name;
                labels.push((
                    *co,
                    format!("robot[{i}] (`{name}`) link `{link}` collision[{k}]"),
                ));
            }
        }
    }
    for (i, (name, handle)) in h.fingertips.iter().enumerate() {
        labels.push((*handle, format!("fingertip[{i}] (`{name}`)")));
    }
    labels
}

/// Fingertip `i` (collider `tip_h`) against collider `other_h`: an error if it starts deeper
/// than its law's validity range. The contact is found first; the law of the pair is built only
/// for a pair in contact.
#[allow(clippy::too_many_arguments)]
fn check_pair(
    c: &Checker,
    scene: &Scene,
    world: &softgrip_rapier::SoftWorld,
    i: usize,
    tip_h: ColliderHandle,
    other_h: ColliderHandle,
    other_label: &str,
    tip_of: &HashMap<ColliderHandle, usize>,
) -> Result<(), SceneError> {
    let colliders = &world.physics.colliders;
    let tip = &scene.fingertips()[i];
    let tip_co = &colliders[tip_h];
    let other_co = &colliders[other_h];
    if other_h == tip_h || other_co.parent() == tip_co.parent() {
        return Ok(());
    }
    let other_tip = tip_of.get(&other_h).copied();
    // Each soft pair once.
    if other_tip.is_some_and(|j| j < i) {
        return Ok(());
    }
    let (other_pose, tip_pose) = (start_pose(world, other_co), start_pose(world, tip_co));
    let Ok(Some(contact)) = query::contact(
        &other_pose,
        other_co.shape(),
        &tip_pose,
        tip_co.shape(),
        0.0,
    ) else {
        return Ok(());
    };
    // Behind a backed fingertip's flat face is its rigid finger: rapier's contact, which
    // pushes out from any depth.
    let n = contact.normal1;
    let behind = |t: &softgrip_rapier::SoftFingertip, pose: &Pose, sign: f32| {
        t.facing().is_some_and(|[x, y, z]| {
            let f = pose.rotation * Vector::new(x as f32, y as f32, z as f32);
            sign * f.dot(n) < 0.0
        })
    };
    // But a fingertip whose centre is inside the other shape (depth > R) is buried, whichever
    // face the nearest surface is behind: refused (a pad buried 3R in a box ran, its normal
    // being behind, while 2.5R was refused).
    let depth = -(contact.dist as f64);
    let backs = [
        behind(tip, &tip_pose, -1.0).then_some((i, tip)),
        other_tip
            .map(|j| (j, &scene.fingertips()[j]))
            .filter(|(_, t)| behind(t, &other_pose, 1.0)),
    ];
    if backs.iter().any(Option::is_some) {
        if let Some((k, t)) = backs
            .into_iter()
            .flatten()
            .find(|(_, t)| depth > t.radius())
        {
            return Err(SceneError::StartBuried {
                origin: c.origin.to_string(),
                fingertip: format!("fingertip[{k}] (`{}`)", t.name()),
                other: if k == i {
                    other_label.to_string()
                } else {
                    format!("fingertip[{i}] (`{}`)", tip.name())
                },
                depth,
                radius: t.radius(),
            });
        }
        return Ok(());
    }
    // The law's compression ratio and validity range of the pair at this depth.
    let (x, x_max) = match other_tip {
        // A backed fingertip in the pair: the two in series on their mid-surface, valid while
        // the depth is within the sum of their own ranges (in x of the larger R).
        Some(j) if !(tip.backing().is_free() && scene.fingertips()[j].backing().is_free()) => {
            let o = &scene.fingertips()[j];
            let r = tip.radius().max(o.radius());
            (depth / r, (tip.law().delta_max() + o.law().delta_max()) / r)
        }
        Some(j) => {
            let o = &scene.fingertips()[j];
            let p =
                ContactParams::try_combine(tip.material(), tip.radius(), o.material(), o.radius());
            match p.and_then(|p| ContactLaw::try_new(p, tip.level())) {
                Ok(law) => (depth / law.params().radius(), law.x_max()),
                Err(_) => return Ok(()),
            }
        }
        None => (depth / tip.law().params().radius(), tip.law().x_max()),
    };
    if x > x_max {
        return Err(SceneError::StartPenetration {
            origin: c.origin.to_string(),
            fingertip: format!("fingertip[{i}] (`{}`)", tip.name()),
            other: other_label.to_string(),
            depth,
            x,
            x_max,
        });
    }
    Ok(())
}
