//! Readout: poses back from rapier, one [`SoftContact`] entity per live contact, fingertip
//! wrenches, and the transition messages.

use bevy_ecs::prelude::{Commands, MessageWriter, Query, Res, ResMut};
use softgrip_law::Regime;

use crate::components::{BodyPose, FingertipWrench, RapierBody};
use crate::contact::SoftContact;
use crate::messages::{ContactEnded, ContactStarted, SlipStarted, ValidityExcursion};
use crate::resources::{PatchRequest, Physics, SimClock, Tracked};

/// Copies every synchronised body's pose into its [`BodyPose`].
pub fn read_poses(physics: Res<Physics>, mut poses: Query<(&RapierBody, &mut BodyPose)>) {
    for (body, mut pose) in &mut poses {
        if let Some(rb) = physics.world.bodies.get(body.0) {
            let (t, q) = (rb.translation(), rb.rotation());
            pose.translation = [t.x as f64, t.y as f64, t.z as f64];
            pose.rotation = [q.x as f64, q.y as f64, q.z as f64, q.w as f64];
        }
    }
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The messages the readout writes.
type Writers<'a> = (
    MessageWriter<'a, ContactStarted>,
    MessageWriter<'a, ContactEnded>,
    MessageWriter<'a, SlipStarted>,
    MessageWriter<'a, ValidityExcursion>,
);

/// Spawns, updates and despawns the [`SoftContact`] entities, sums the [`FingertipWrench`]es
/// and writes one message per transition (started, ended, slip started, validity excursion).
pub fn read_contacts(
    mut physics: ResMut<Physics>,
    clock: Res<SimClock>,
    patches: Option<Res<PatchRequest>>,
    mut commands: Commands,
    mut contacts: Query<&mut SoftContact>,
    mut wrenches: Query<&mut FingertipWrench>,
    (mut started, mut ended, mut slip, mut excursion): Writers,
) {
    let physics = &mut *physics;
    let time = clock.time;
    for mut w in &mut wrenches {
        if *w != FingertipWrench::default() {
            *w = FingertipWrench::default();
        }
    }
    for t in physics.contacts.values_mut() {
        t.seen = false;
    }
    for c in physics.world.soft.contacts() {
        let (Some(tip), Some(other)) = (
            physics.collider_entity.get(&c.fingertip).copied(),
            physics.collider_entity.get(&c.other).copied(),
        ) else {
            continue;
        };
        let other_body = physics
            .world
            .colliders
            .get(c.other)
            .and_then(|co| co.parent())
            .and_then(|b| physics.body_entity.get(&b).copied());
        let patch = patches.as_ref().map(|_| c.patch());
        let (sliding, extended) = (c.sliding, c.regime == Regime::Extended);
        let readout = SoftContact {
            fingertip: tip,
            other,
            other_body,
            contact: c.clone(),
            patch,
        };
        let (entity, was_sliding, was_extended) = match physics.contacts.get_mut(&(tip, other)) {
            Some(t) => {
                if let Ok(mut sc) = contacts.get_mut(t.entity) {
                    *sc = readout;
                }
                let old = (t.entity, t.sliding, t.extended);
                (t.sliding, t.extended, t.seen) = (sliding, extended, true);
                old
            }
            None => {
                let entity = commands.spawn(readout).id();
                let t = Tracked {
                    entity,
                    sliding,
                    extended,
                    seen: true,
                };
                physics.contacts.insert((tip, other), t);
                started.write(ContactStarted {
                    contact: entity,
                    fingertip: tip,
                    other,
                    time,
                });
                (entity, false, false)
            }
        };
        if sliding && !was_sliding {
            slip.write(SlipStarted {
                contact: entity,
                fingertip: tip,
                other,
                time,
            });
        }
        if extended && !was_extended {
            excursion.write(ValidityExcursion {
                contact: entity,
                fingertip: tip,
                x: c.x,
                x_max: c.law().x_max(),
                time,
            });
        }
        if let Ok(mut w) = wrenches.get_mut(tip) {
            let center = physics
                .world
                .colliders
                .get(c.fingertip)
                .map(|co| co.translation())
                .map(|t| [t.x as f64, t.y as f64, t.z as f64])
                .unwrap_or(c.point);
            let f = [0, 1, 2].map(|i| c.normal[i] * c.normal_force + c.friction_force[i]);
            let arm = [0, 1, 2].map(|i| c.point[i] - center[i]);
            let tau = cross(arm, f);
            for i in 0..3 {
                w.force[i] += f[i];
                w.torque[i] += tau[i] + c.normal[i] * c.torsional_moment;
            }
        }
    }
    physics.contacts.retain(|&(tip, other), t| {
        if !t.seen {
            commands.entity(t.entity).despawn();
            ended.write(ContactEnded {
                fingertip: tip,
                other,
                time,
            });
        }
        t.seen
    });
}
