//! The one builder from a [`Scene`] to a rapier world ([`Scene::build`],
//! [`Scene::build_into`]), and the rapier builders of a body, a shape and a fingertip that the
//! ECS's components use too (so a world built from components is the same world).
//!
//! Order: bodies, then shapes (body by body), then fingertips, each in file order. The ECS
//! spawns a scene's entities in that same order, so handles and entities line up.

use softgrip_rapier::rapier3d::prelude::{
    ColliderBuilder, ColliderHandle, RigidBodyBuilder, RigidBodyHandle, SharedShape,
};
use softgrip_rapier::{SoftAccuracy, SoftFingertip, SoftWorld};

use crate::control::Carrier;
use crate::format::BodyKind;
use crate::robot::RobotHandles;
use crate::scene::Scene;
use crate::vector::vector;

/// rapier's builder of a body of `kind` at `position` \[m\], rotated by the rotation vector
/// `rotation` (axis * angle) \[rad\]; sleeping disabled (a held object must not fall asleep
/// between the jaws).
pub fn body_builder(kind: BodyKind, position: [f64; 3], rotation: [f64; 3]) -> RigidBodyBuilder {
    let b = match kind {
        BodyKind::Fixed => RigidBodyBuilder::fixed(),
        BodyKind::Dynamic => RigidBodyBuilder::dynamic(),
        BodyKind::Kinematic => RigidBodyBuilder::kinematic_position_based(),
    };
    b.translation(vector(position))
        .rotation(vector(rotation))
        .can_sleep(false)
}

/// rapier's builder of a rigid collision shape at `offset` \[m\] from its body's origin, with
/// `density` [kg/m³] (> 0), rapier's `friction` (>= 0) and `restitution` (in [0, 1]).
pub fn collider_builder(
    shape: SharedShape,
    offset: [f64; 3],
    density: f64,
    friction: f64,
    restitution: f64,
) -> ColliderBuilder {
    ColliderBuilder::new(shape)
        .translation(vector(offset))
        .density(density as f32)
        .friction(friction as f32)
        .restitution(restitution as f32)
}

/// rapier's builder of a fingertip's ball collider: radius R of `tip`, centred at `offset`
/// \[m\] from its body's origin, `density` [kg/m³] (> 0). Register the inserted collider with
/// `SoftWorld::register`.
pub fn fingertip_builder(tip: &SoftFingertip, offset: [f64; 3], density: f64) -> ColliderBuilder {
    ColliderBuilder::ball(tip.radius() as f32)
        .translation(vector(offset))
        .density(density as f32)
}

/// The rapier handles of a scene built into a world, named and in file order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneHandles {
    /// Every body: (name, handle).
    pub bodies: Vec<(String, RigidBodyHandle)>,
    /// Every rigid shape, body by body: (its body's name, handle).
    pub shapes: Vec<(String, ColliderHandle)>,
    /// Every robot: (name, the handles of its links, colliders and joints).
    pub robots: Vec<(String, RobotHandles)>,
    /// Every fingertip's ball collider, registered with the plugin: (name, handle).
    pub fingertips: Vec<(String, ColliderHandle)>,
}

impl SceneHandles {
    /// The handle of the body named `name`.
    pub fn body(&self, name: &str) -> Option<RigidBodyHandle> {
        find(&self.bodies, name)
    }

    /// The collider of the fingertip named `name`.
    pub fn fingertip(&self, name: &str) -> Option<ColliderHandle> {
        find(&self.fingertips, name)
    }

    /// The handles of the robot named `name`.
    pub fn robot(&self, name: &str) -> Option<&RobotHandles> {
        self.robots.iter().find(|(n, _)| n == name).map(|(_, h)| h)
    }

    /// The body of a carrier (a body or a robot's link).
    pub fn carrier(&self, c: Carrier) -> Option<RigidBodyHandle> {
        match c {
            Carrier::Body(i) => self.bodies.get(i).map(|b| b.1),
            Carrier::Link { robot, link } => self.robots.get(robot)?.1.links.get(link).copied(),
        }
    }

    /// The rigid shapes of the body named `body`, in file order.
    pub fn shapes_of<'a>(&'a self, body: &'a str) -> impl Iterator<Item = ColliderHandle> + 'a {
        self.shapes
            .iter()
            .filter(move |(b, _)| b == body)
            .map(|(_, h)| *h)
    }
}

fn find<H: Copy>(list: &[(String, H)], name: &str) -> Option<H> {
    list.iter().find(|(n, _)| n == name).map(|(_, h)| *h)
}

/// A scene built into a world of its own ([`Scene::build`]).
pub struct BuiltScene {
    /// The plugin world: the scene's gravity, `dt` and accuracy, its bodies, shapes and
    /// registered fingertips.
    pub world: SoftWorld,
    /// The handles, by name.
    pub handles: SceneHandles,
}

impl Scene {
    /// An empty plugin world with the scene's settings: gravity [m/s²], `dt` \[s\], accuracy.
    pub fn empty_world(&self) -> SoftWorld {
        let f = self.file();
        let mut w = SoftWorld::new();
        w.physics.gravity = vector(f.gravity);
        w.physics.integration_parameters.dt = f.dt as f32;
        w.soft.set_accuracy(
            SoftAccuracy::try_new(f.accuracy).expect("invariant: checked by Scene::parse"),
        );
        w
    }

    /// The scene in a world of its own ([`empty_world`](Self::empty_world) +
    /// [`build_into`](Self::build_into)).
    pub fn build(&self) -> BuiltScene {
        let mut world = self.empty_world();
        let handles = self.build_into(&mut world);
        BuiltScene { world, handles }
    }

    /// Inserts the scene's bodies, shapes, robots and fingertips into `world` (bodies, then
    /// shapes, then robots, then fingertips, each in file order) and registers the fingertips
    /// with the plugin.
    /// The world's own settings (gravity, `dt`, accuracy) are left as they are.
    pub fn build_into(&self, world: &mut SoftWorld) -> SceneHandles {
        let f = self.file();
        let mut out = SceneHandles::default();
        for b in &f.bodies {
            let h = world
                .physics
                .bodies
                .insert(body_builder(b.kind, b.position, b.rotation));
            out.bodies.push((b.name.clone(), h));
        }
        for (i, b) in f.bodies.iter().enumerate() {
            for (s, shape) in b.shapes.iter().zip(self.shapes(i)) {
                let c = collider_builder(
                    shape.clone(),
                    s.offset,
                    s.density,
                    s.friction,
                    s.restitution,
                );
                let h = world.physics.colliders.insert_with_parent(
                    c,
                    out.bodies[i].1,
                    &mut world.physics.bodies,
                );
                out.shapes.push((b.name.clone(), h));
            }
        }
        for r in self.robots() {
            let h = r.insert(&mut world.physics);
            out.robots.push((r.name().to_string(), h));
        }
        for ((t, tip), carrier) in f
            .fingertips
            .iter()
            .zip(self.fingertips())
            .zip(self.carriers())
        {
            let body = out
                .carrier(*carrier)
                .expect("invariant: checked by Scene::parse");
            let c = fingertip_builder(tip, t.offset, t.density);
            let h = world
                .physics
                .colliders
                .insert_with_parent(c, body, &mut world.physics.bodies);
            world
                .register(h, tip.clone())
                .expect("invariant: the fingertip's own ball collider was just inserted");
            out.fingertips.push((t.name.clone(), h));
        }
        // The fingertips moved their links' centres of mass.
        for (i, (r, (_, h))) in self.robots().iter().zip(&out.robots).enumerate() {
            r.anchor_prismatic_at_com(&mut world.physics, h);
            let pads: Vec<usize> = (self.carriers().iter())
                .filter_map(|c| match *c {
                    Carrier::Link { robot, link } if robot == i => Some(link),
                    _ => None,
                })
                .collect();
            // Scene::parse refused a scene where this fails (start.rs, check_jointed_sweeps).
            let _ = r.set_jointed_sweeps(world, h, &pads);
            // Links that start overlapping never touch (robot/overlap.rs).
            crate::robot::keep_apart(r, h, world);
        }
        out
    }
}
