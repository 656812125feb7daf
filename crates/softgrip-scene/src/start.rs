//! The start of a run: a fingertip may start touching or slightly pressed into a body (the
//! plugin pushes it out through the law), but not deeper than the law's validity range (a
//! fingertip starting inside the box gave 44 kN at x = 1.52). That is an error naming the
//! pair and the depth ([`SceneError::StartPenetration`]), checked on the built world.

use softgrip_rapier::rapier3d::parry::query;
use softgrip_rapier::rapier3d::prelude::{Collider, ColliderHandle, Vector};
use softgrip_rapier::softgrip_law::{ContactLaw, ContactParams};

use crate::error::SceneError;
use crate::scene::Scene;
use crate::validate::Checker;

/// Every fingertip against every other collider of the built scene at its start poses.
pub(crate) fn check_start(c: &Checker, scene: &Scene) -> Result<(), SceneError> {
    let built = scene.build();
    let (world, h) = (&built.world, &built.handles);
    let f = scene.file();
    // A label for every collider: `body[j].shape[k]` (`name`) or `fingertip[i]` (`name`).
    let mut labels: Vec<(ColliderHandle, String)> = Vec::new();
    let mut shapes = h.shapes.iter();
    for (j, b) in f.bodies.iter().enumerate() {
        for k in 0..b.shapes.len() {
            if let Some((_, s)) = shapes.next() {
                labels.push((*s, format!("body[{j}].shape[{k}] (`{}`)", b.name)));
            }
        }
    }
    for (i, (name, handle)) in h.fingertips.iter().enumerate() {
        labels.push((*handle, format!("fingertip[{i}] (`{name}`)")));
    }
    for (i, (_, tip_h)) in h.fingertips.iter().enumerate() {
        let tip = &scene.fingertips()[i];
        let tip_co = &world.physics.colliders[*tip_h];
        for (other_h, other_label) in &labels {
            let other_co = &world.physics.colliders[*other_h];
            if other_h == tip_h || other_co.parent() == tip_co.parent() {
                continue;
            }
            let other_tip = h.fingertips.iter().position(|(_, t)| t == other_h);
            // (x, x_max) of a depth [m]: the law's compression ratio and validity range.
            let range: Box<dyn Fn(f64) -> (f64, f64)> = match other_tip {
                // Each soft pair once.
                Some(j) if j < i => continue,
                // A backed fingertip in the pair: the two in series on their mid-surface, valid
                // while the depth is within the sum of their own ranges (in x of the larger R).
                Some(j)
                    if !(tip.backing().is_free() && scene.fingertips()[j].backing().is_free()) =>
                {
                    let o = &scene.fingertips()[j];
                    let r = tip.radius().max(o.radius());
                    let x_max = (tip.law().delta_max() + o.law().delta_max()) / r;
                    Box::new(move |depth| (depth / r, x_max))
                }
                Some(j) => {
                    let o = &scene.fingertips()[j];
                    let p = ContactParams::try_combine(
                        tip.material(),
                        tip.radius(),
                        o.material(),
                        o.radius(),
                    );
                    match p.and_then(|p| ContactLaw::try_new(p, tip.level())) {
                        Ok(law) => {
                            Box::new(move |depth| (depth / law.params().radius(), law.x_max()))
                        }
                        Err(_) => continue,
                    }
                }
                None => {
                    let law = tip.law().clone();
                    Box::new(move |depth| (depth / law.params().radius(), law.x_max()))
                }
            };
            let Ok(Some(contact)) = query::contact(
                other_co.position(),
                other_co.shape(),
                tip_co.position(),
                tip_co.shape(),
                0.0,
            ) else {
                continue;
            };
            // Behind a backed fingertip's flat face is its rigid finger: rapier's contact,
            // which pushes out of a shallow overlap. But a fingertip whose centre is inside the
            // other shape (depth > R) is buried, whichever face the nearest surface is behind:
            // refused (a pad buried 3R in a box ran, its normal being behind, while 2.5R was
            // refused).
            let n = contact.normal1;
            let behind = |t: &softgrip_rapier::SoftFingertip, co: &Collider, sign: f32| {
                t.facing().is_some_and(|[x, y, z]| {
                    let f = co.position().rotation * Vector::new(x as f32, y as f32, z as f32);
                    sign * f.dot(n) < 0.0
                })
            };
            let depth = -(contact.dist as f64);
            let backs = [
                behind(tip, tip_co, -1.0).then_some((i, tip)),
                other_tip
                    .map(|j| (j, &scene.fingertips()[j]))
                    .filter(|(_, t)| behind(t, other_co, 1.0)),
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
                            other_label.clone()
                        } else {
                            format!("fingertip[{i}] (`{}`)", tip.name())
                        },
                        depth,
                        radius: t.radius(),
                    });
                }
                continue;
            }
            let (x, x_max) = range(depth);
            if x > x_max {
                return Err(SceneError::StartPenetration {
                    origin: c.origin.to_string(),
                    fingertip: format!("fingertip[{i}] (`{}`)", tip.name()),
                    other: other_label.clone(),
                    depth,
                    x,
                    x_max,
                });
            }
        }
    }
    Ok(())
}
