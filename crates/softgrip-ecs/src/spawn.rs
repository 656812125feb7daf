//! [`spawn_scene`]: a scene as entities and resources, spawned from `softgrip-scene`'s one
//! builder (the rapier world is built once, by [`Scene::build_into`]; the entities are
//! tagged with its handles).

use bevy_ecs::prelude::{Entity, Messages, Name, World};
use softgrip_rapier::SoftWorld;
use softgrip_scene::robot::BaseKind;
use softgrip_scene::{BodyKind, Carrier, Scene, SceneHandles, Trajectory};

use crate::components::{
    AttachedTo, Collider, Fingertip, KinematicPath, KinematicTarget, RapierBody, RapierCollider,
    RigidBody,
};
use crate::controller::{ControllerEntities, ControllerEntity, Controllers, RobotLinkEntity};
use crate::messages::{
    ContactEnded, ContactStarted, GoalEnded, GripReached, SlipStarted, ValidityExcursion,
};
use crate::resources::{
    CurrentFrame, Names, Physics, RecordSelection, SceneInfoResource, SimClock, StepFault,
};

/// The entities of a spawned scene, in scene order.
#[derive(Debug, Clone, Default)]
pub struct SceneEntities {
    /// Bodies.
    pub bodies: Vec<Entity>,
    /// Each robot's link entities (bodies), in the robot's link order.
    pub robot_links: Vec<Vec<Entity>>,
    /// Fingertips.
    pub fingertips: Vec<Entity>,
    /// Every controller, in the order they run (the `[gripper]` first if there is one).
    pub controllers: Vec<Entity>,
    /// The `[gripper]`'s controller, if any.
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
    world.init_resource::<Messages<GoalEnded>>();
    if !world.contains_resource::<Physics>() {
        world.insert_resource(Physics::new(soft_world));
    }
    world.init_resource::<SimClock>();
    world.init_resource::<CurrentFrame>();
    world.init_resource::<StepFault>();
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
    world.insert_resource(Names(softgrip_scene::SubjectNames::new(scene, &handles)));
    let mut out = SceneEntities {
        bodies: spawn_bodies(world, scene, &handles),
        ..SceneEntities::default()
    };
    spawn_colliders(world, scene, &handles, &out.bodies);
    out.robot_links = spawn_robots(world, scene, &handles);
    out.fingertips = spawn_fingertips(world, scene, &handles, &out);
    let control = scene.control_set(&handles);
    out.controllers = (control.controllers().iter().enumerate())
        .map(|(i, c)| {
            world
                .spawn((Name::new(c.name().to_string()), ControllerEntity(i)))
                .id()
        })
        .collect();
    out.gripper = scene
        .gripper()
        .and_then(|_| out.controllers.first().copied());
    world.insert_resource(ControllerEntities(out.controllers.clone()));
    world.insert_resource(Controllers(control));
    out
}

/// One entity per robot link (a body: `RigidBody`, named `<robot>/<link>`, tagged with its
/// handle) and one per link collider (attached to it).
fn spawn_robots(world: &mut World, scene: &Scene, handles: &SceneHandles) -> Vec<Vec<Entity>> {
    let mut out = Vec::new();
    for (r, (robot, (_, h))) in scene.robots().iter().zip(&handles.robots).enumerate() {
        let mut links = Vec::new();
        for (l, body) in h.links.iter().enumerate() {
            let kind = if l != robot.root() {
                BodyKind::Dynamic
            } else {
                match robot.base() {
                    BaseKind::Fixed => BodyKind::Fixed,
                    BaseKind::Kinematic => BodyKind::Kinematic,
                    BaseKind::Dynamic => BodyKind::Dynamic,
                }
            };
            let physics = world.resource::<Physics>();
            let position = (physics.world.physics.bodies.get(*body))
                .map(|rb| rb.translation())
                .map_or([0.0; 3], |t| [t.x as f64, t.y as f64, t.z as f64]);
            let e = world
                .spawn((
                    Name::new(robot.frame(l)),
                    RigidBody {
                        kind,
                        position,
                        rotation: [0.0; 3],
                    },
                    RapierBody(*body),
                    RobotLinkEntity { robot: r, link: l },
                ))
                .id();
            world.resource_mut::<Physics>().link_body(*body, e);
            for co in &h.colliders[l] {
                let c = world.spawn((AttachedTo(e), RapierCollider(*co))).id();
                world.resource_mut::<Physics>().link_collider(*co, c);
            }
            links.push(e);
        }
        out.push(links);
    }
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
    out: &SceneEntities,
) -> Vec<Entity> {
    let f = scene.file();
    let mut entities = Vec::new();
    for (((t, tip), (_, h)), carrier) in f
        .fingertips
        .iter()
        .zip(scene.fingertips())
        .zip(&handles.fingertips)
        .zip(scene.carriers())
    {
        let parent = match *carrier {
            Carrier::Body(i) => out.bodies[i],
            Carrier::Link { robot, link } => out.robot_links[robot][link],
        };
        let fingertip = Fingertip {
            tip: tip.clone(),
            offset: t.offset,
            density: t.density,
        };
        let e = world.spawn((
            Name::new(t.name.clone()),
            fingertip,
            AttachedTo(parent),
            RapierCollider(*h),
        ));
        let e = e.id();
        world.resource_mut::<Physics>().link_collider(*h, e);
        entities.push(e);
    }
    entities
}
