//! [`spawn_scene`]: a scene as entities and resources, spawned from `softgrip-scene`'s one
//! builder (the rapier world is built once, by [`Scene::build_into`]; the entities are
//! tagged with its handles).

use bevy_ecs::prelude::{Entity, Messages, Name, World};
use softgrip_rapier::SoftWorld;
use softgrip_scene::{BodyKind, GripperState, Scene, SceneHandles, Trajectory};

use crate::components::{
    AttachedTo, Collider, Fingertip, KinematicPath, KinematicTarget, RapierBody, RapierCollider,
    RigidBody,
};
use crate::gripper::Gripper;
use crate::messages::{ContactEnded, ContactStarted, GripReached, SlipStarted, ValidityExcursion};
use crate::resources::{CurrentFrame, Physics, RecordSelection, SceneInfoResource, SimClock};

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

/// Builds a scene into the world's [`Physics`] (a new one with the scene's settings if there
/// is none, see [`init_world`]) and spawns its bodies, colliders, fingertips and gripper (in
/// that order, each in scene order), tagged with their rapier handles; inserts
/// [`RecordSelection`] and [`SceneInfoResource`].
pub fn spawn_scene(world: &mut World, scene: &Scene) -> SceneEntities {
    init_world(world, scene.empty_world());
    world.insert_resource(RecordSelection(scene.file().record.clone()));
    world.insert_resource(SceneInfoResource(crate::to_record::scene_info(scene)));
    let handles = scene.build_into(&mut world.resource_mut::<Physics>().world);
    let mut out = SceneEntities {
        bodies: spawn_bodies(world, scene, &handles),
        ..SceneEntities::default()
    };
    spawn_colliders(world, scene, &handles, &out.bodies);
    out.fingertips = spawn_fingertips(world, scene, &handles, &out.bodies);
    out.gripper = scene.gripper().map(|p| {
        let g = Gripper {
            program: p.clone(),
            state: GripperState::new(p.jaws.map(|i| scene.file().bodies[i].position)),
            jaws: p.jaws.map(|i| out.bodies[i]),
            tips: (p.tips.clone()).map(|tips| tips.iter().map(|&i| out.fingertips[i]).collect()),
        };
        world.spawn((Name::new(p.name.clone()), g)).id()
    });
    out
}

/// One entity per body, tagged with its handle; kinematic ones with a target (and their
/// scripted path).
fn spawn_bodies(world: &mut World, scene: &Scene, handles: &SceneHandles) -> Vec<Entity> {
    let mut entities = Vec::new();
    for (b, (_, h)) in scene.file().bodies.iter().zip(&handles.bodies) {
        let body = RigidBody {
            kind: b.kind,
            position: b.position,
            rotation: b.rotation,
        };
        let mut e = world.spawn((Name::new(b.name.clone()), body, RapierBody(*h)));
        if b.kind == BodyKind::Kinematic {
            e.insert(KinematicTarget::default());
            if !b.trajectory.is_empty() {
                e.insert(KinematicPath(Trajectory::of(b)));
            }
        }
        let e = e.id();
        world.resource_mut::<Physics>().link_body(*h, e);
        entities.push(e);
    }
    entities
}

/// One entity per rigid shape, attached to its body and tagged with its handle.
fn spawn_colliders(world: &mut World, scene: &Scene, handles: &SceneHandles, bodies: &[Entity]) {
    let mut shapes = handles.shapes.iter();
    for (i, b) in scene.file().bodies.iter().enumerate() {
        for ((s, shape), (_, h)) in b.shapes.iter().zip(scene.shapes(i)).zip(shapes.by_ref()) {
            let collider = Collider {
                shape: shape.clone(),
                offset: s.offset,
                density: s.density,
                friction: s.friction,
                restitution: s.restitution,
            };
            let e = world.spawn((collider, AttachedTo(bodies[i]), RapierCollider(*h)));
            let e = e.id();
            world.resource_mut::<Physics>().link_collider(*h, e);
        }
    }
}

/// One entity per fingertip, attached to its body and tagged with its (registered) collider.
fn spawn_fingertips(
    world: &mut World,
    scene: &Scene,
    handles: &SceneHandles,
    bodies: &[Entity],
) -> Vec<Entity> {
    let f = scene.file();
    let mut entities = Vec::new();
    for ((t, tip), (_, h)) in f
        .fingertips
        .iter()
        .zip(scene.fingertips())
        .zip(&handles.fingertips)
    {
        let body = scene
            .body_index(&t.body)
            .expect("invariant: checked by Scene::parse");
        let fingertip = Fingertip {
            tip: tip.clone(),
            offset: t.offset,
            density: t.density,
        };
        let e = world.spawn((
            Name::new(t.name.clone()),
            fingertip,
            AttachedTo(bodies[body]),
            RapierCollider(*h),
        ));
        let e = e.id();
        world.resource_mut::<Physics>().link_collider(*h, e);
        entities.push(e);
    }
    entities
}
