//! [`spawn_scene`]: a scene as entities and resources.

use bevy_ecs::prelude::{Entity, Messages, Name, World};
use softgrip_rapier::{SoftAccuracy, SoftWorld};

use crate::components::{AttachedTo, BodyKind, KinematicPath, KinematicTarget};
use crate::gripper::{Gripper, GripperState};
use crate::messages::{ContactEnded, ContactStarted, GripReached, SlipStarted, ValidityExcursion};
use crate::resources::{CurrentFrame, Physics, RecordSelection, SceneInfoResource, SimClock};
use crate::scene::{Scene, Trajectory, body_from_spec, collider_from_spec, fingertip_from_spec};

/// The entities of a spawned scene, in scene order.
#[derive(Debug, Clone, Default)]
pub struct SceneEntities {
    /// Bodies.
    pub bodies: Vec<Entity>,
    /// Fingertips.
    pub fingertips: Vec<Entity>,
    /// The gripper, if any.
    pub gripper: Option<Entity>,
}

/// The plugin world of a scene's settings (gravity, dt, accuracy), empty.
pub fn soft_world_for(scene: &Scene) -> SoftWorld {
    let f = scene.file();
    let mut w = SoftWorld::new();
    w.gravity = crate::components::v32(f.gravity);
    w.params.dt = f.dt as f32;
    w.soft.set_accuracy(
        SoftAccuracy::try_new(f.accuracy).expect("invariant: checked by Scene::parse"),
    );
    w
}

/// Inserts the softgrip messages' buffers and the resources every world needs ([`Physics`],
/// [`SimClock`], [`CurrentFrame`]) if they are missing. The message buffers are rotated by the
/// schedule's [`sync_to_rapier`](crate::systems::sync_to_rapier), not through bevy's
/// `MessageRegistry`.
pub fn init_world(world: &mut World, soft_world: SoftWorld) {
    world.init_resource::<Messages<ContactStarted>>();
    world.init_resource::<Messages<ContactEnded>>();
    world.init_resource::<Messages<SlipStarted>>();
    world.init_resource::<Messages<ValidityExcursion>>();
    world.init_resource::<Messages<GripReached>>();
    if !world.contains_resource::<Physics>() {
        world.insert_resource(Physics::new(soft_world));
    }
    world.init_resource::<SimClock>();
    world.init_resource::<CurrentFrame>();
}

/// Spawns a scene's bodies, colliders, fingertips and gripper (in that order, each in scene
/// order) and inserts its resources (see [`init_world`]; also [`RecordSelection`] and
/// [`SceneInfoResource`]).
pub fn spawn_scene(world: &mut World, scene: &Scene) -> SceneEntities {
    init_world(world, soft_world_for(scene));
    let f = scene.file();
    world.insert_resource(RecordSelection(f.record.clone()));
    world.insert_resource(SceneInfoResource(crate::to_record::scene_info(scene)));
    let mut out = SceneEntities::default();
    for b in &f.bodies {
        let body = body_from_spec(b);
        let mut e = world.spawn((Name::new(b.name.clone()), body.clone()));
        if body.kind == BodyKind::Kinematic {
            e.insert(KinematicTarget::default());
            if !b.trajectory.is_empty() {
                e.insert(KinematicPath(Trajectory::of(b)));
            }
        }
        out.bodies.push(e.id());
    }
    for (i, b) in f.bodies.iter().enumerate() {
        for (spec, shape) in b.shapes.iter().zip(scene.shapes(i)) {
            world.spawn((
                collider_from_spec(spec, shape.clone()),
                AttachedTo(out.bodies[i]),
            ));
        }
    }
    for (t, tip) in f.fingertips.iter().zip(scene.fingertips()) {
        let body = scene
            .body_index(&t.body)
            .expect("invariant: checked by Scene::parse");
        let e = world.spawn((
            Name::new(t.name.clone()),
            fingertip_from_spec(t, tip.clone()),
            AttachedTo(out.bodies[body]),
        ));
        out.fingertips.push(e.id());
    }
    if let Some(p) = scene.gripper() {
        let jaws = p.jaws.map(|i| out.bodies[i]);
        let tips = p.jaws.map(|i| {
            f.fingertips
                .iter()
                .zip(&out.fingertips)
                .filter(|(t, _)| t.body == f.bodies[i].name)
                .map(|(_, e)| *e)
                .collect()
        });
        let state = GripperState::new(p.jaws.map(|i| f.bodies[i].position));
        let g = Gripper {
            program: p.clone(),
            state,
            jaws,
            tips,
        };
        out.gripper = Some(world.spawn((Name::new(p.name.clone()), g)).id());
    }
    out
}
