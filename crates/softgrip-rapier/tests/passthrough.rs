//! The user's rapier hooks and events pass through the plugin: on rigid pairs they behave
//! exactly as in plain rapier while a fingertip is active elsewhere in the scene. The same
//! scene is stepped by rapier's own `PhysicsWorld::step_with_events` and by the plugin
//! (`SoftWorld::step_with`, and `SoftContacts::step` on the user's own `PhysicsWorld`); every
//! body's pose and velocity, every event and every hook call must be bit-identical, in the same
//! order.
//!
//! The rigid part is rapier's getting-started scene (a ground cuboid and a bouncing ball) with
//! a contact-modification hook (a conveyor box: the hook sets its friction and the solver
//! contacts' target velocity), a pair filter (a ghost ball that falls through the ground), an
//! intersection filter (a sensor the ball falls through) and collision and contact-force
//! events. The soft part, 10 m away: a fingertip on a velocity-based kinematic body pressing
//! a fixed block at 0.5 mm/s (never substepped: no dynamic body in the contact, so rapier runs
//! once per step with the same `dt` as plain rapier).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::sync::Mutex;

use rapier3d::prelude::*;
use softgrip_law::Material;
use softgrip_rapier::{SoftContacts, SoftFingertip, SoftWorld};

/// `user_data` of the ghost ball, filtered out of every contact pair by the user's hook.
const GHOST: u128 = 1;
/// `user_data` of the conveyor box, whose contacts the user's hook modifies.
const CONVEYOR: u128 = 2;
/// Steps of a run (4 s at 60 Hz: the ball bounces, the ghost falls through, the box slides).
const STEPS: usize = 240;

/// The user's hooks: a pair filter, an intersection filter and a contact modification, each
/// call logged.
#[derive(Default)]
struct UserHooks {
    calls: Mutex<Vec<String>>,
}

fn marked(ctx_colliders: &ColliderSet, a: ColliderHandle, b: ColliderHandle, mark: u128) -> bool {
    ctx_colliders[a].user_data == mark || ctx_colliders[b].user_data == mark
}

impl PhysicsHooks for UserHooks {
    fn filter_contact_pair(&self, ctx: &PairFilterContext) -> Option<SolverFlags> {
        self.log(format!("filter {:?} {:?}", ctx.collider1, ctx.collider2));
        if marked(ctx.colliders, ctx.collider1, ctx.collider2, GHOST) {
            None
        } else {
            Some(SolverFlags::COMPUTE_RIGID_IMPULSES)
        }
    }

    fn filter_intersection_pair(&self, ctx: &PairFilterContext) -> bool {
        self.log(format!("intersect {:?} {:?}", ctx.collider1, ctx.collider2));
        true
    }

    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        self.log(format!("modify {:?} {:?}", ctx.collider1, ctx.collider2));
        if !marked(ctx.colliders, ctx.collider1, ctx.collider2, CONVEYOR) {
            return;
        }
        if let Some(m) = ctx.rigid_mut() {
            *m.friction = 0.9;
            *m.restitution = 0.0;
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = Vector::new(0.5, 0.0, 0.0);
            }
        }
    }
}

impl UserHooks {
    fn log(&self, s: String) {
        self.calls.lock().unwrap().push(s);
    }
}

/// The user's event handler: every event logged, forces by their bits.
#[derive(Default)]
struct UserEvents {
    events: Mutex<Vec<String>>,
}

impl EventHandler for UserEvents {
    fn handle_collision_event(
        &self,
        _bodies: &RigidBodySet,
        _colliders: &ColliderSet,
        event: CollisionEvent,
        contact_pair: Option<&ContactPair>,
    ) {
        let touching = contact_pair.map(|p| p.has_any_active_contact());
        self.events
            .lock()
            .unwrap()
            .push(format!("{event:?} {touching:?}"));
    }

    fn handle_contact_force_event(
        &self,
        dt: f32,
        _bodies: &RigidBodySet,
        _colliders: &ColliderSet,
        contact_pair: &ContactPair,
        total_force_magnitude: f32,
    ) {
        self.events.lock().unwrap().push(format!(
            "force {:?} {:?} {:#x} {:#x}",
            contact_pair.collider1,
            contact_pair.collider2,
            total_force_magnitude.to_bits(),
            dt.to_bits()
        ));
    }

    fn handle_soft_body_tear_event(&self, _: &SoftBodySet, event: &SoftBodyTearEvent) {
        self.events.lock().unwrap().push(format!("tear {event:?}"));
    }
}

/// The scene's handles.
struct Scene {
    /// The soft part: the fingertip's body and collider, and the block it presses.
    tip_body: RigidBodyHandle,
    tip: ColliderHandle,
    block: ColliderHandle,
}

/// The rigid part (first, so its handles are the same in every world), then the soft part
/// with the fingertip's ball not yet registered.
fn build(world: &mut PhysicsWorld) -> Scene {
    let everything = ActiveEvents::COLLISION_EVENTS | ActiveEvents::CONTACT_FORCE_EVENTS;
    let hooks = ActiveHooks::FILTER_CONTACT_PAIRS | ActiveHooks::MODIFY_SOLVER_CONTACTS;
    world.insert_collider(
        ColliderBuilder::cuboid(2.0, 0.1, 2.0)
            .active_events(everything)
            .active_hooks(hooks)
            .contact_force_event_threshold(1.0),
        None,
    );
    world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 3.0, 0.0)),
        ColliderBuilder::ball(0.5).restitution(0.7),
    );
    world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(-1.0, 0.35, 1.0)),
        ColliderBuilder::cuboid(0.2, 0.2, 0.2).user_data(CONVEYOR),
    );
    world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(1.0, 2.0, -0.5)),
        ColliderBuilder::ball(0.3).user_data(GHOST),
    );
    world.insert_collider(
        ColliderBuilder::cuboid(0.6, 0.2, 0.6)
            .translation(Vector::new(0.0, 1.5, 0.0))
            .sensor(true)
            .active_events(ActiveEvents::COLLISION_EVENTS)
            .active_hooks(ActiveHooks::FILTER_INTERSECTION_PAIR),
        None,
    );
    // The soft part, 10 m away. The block has the user's hooks and events on too: a
    // fingertip's pair never reaches them.
    let block = world.insert_collider(
        ColliderBuilder::cuboid(0.05, 0.05, 0.05)
            .translation(Vector::new(10.0, 0.05, 0.0))
            .active_events(everything)
            .active_hooks(hooks),
        None,
    );
    let (tip_body, tip) = world.insert(
        RigidBodyBuilder::kinematic_velocity_based()
            .translation(Vector::new(10.0, 0.1 + 0.01 - 0.0005, 0.0))
            .linvel(Vector::new(0.0, -0.0005, 0.0)),
        ColliderBuilder::ball(0.01),
    );
    Scene {
        tip_body,
        tip,
        block,
    }
}

fn fingertip() -> SoftFingertip {
    SoftFingertip::builder(0.01)
        .material(Material::try_new(3.0e6, 0.49).unwrap())
        .friction(0.5)
        .build()
        .unwrap()
}

/// What a run produced: every body's pose and velocity bits per step (the fingertip's body
/// excluded), the events and the hook calls.
#[derive(Debug, PartialEq)]
struct Trace {
    bodies: Vec<u32>,
    events: Vec<String>,
    calls: Vec<String>,
}

fn record(world: &PhysicsWorld, skip: Option<RigidBodyHandle>, out: &mut Vec<u32>) {
    for (h, rb) in world.bodies.iter() {
        if Some(h) == skip {
            continue;
        }
        let p = rb.position();
        let values = [
            p.translation.to_array(),
            rb.linvel().to_array(),
            rb.angvel().to_array(),
        ];
        out.extend(values.iter().flatten().map(|v| v.to_bits()));
        out.extend(p.rotation.to_array().iter().map(|v| v.to_bits()));
    }
}

/// How the plugin steps the scene.
#[derive(Clone, Copy)]
enum Plugin {
    /// rapier's own `PhysicsWorld::step_with_events`, no plugin.
    None,
    /// `SoftWorld::step_with`.
    SoftWorld,
    /// `SoftContacts::step` on the user's own `PhysicsWorld`.
    OwnWorld,
}

fn run(plugin: Plugin) -> Trace {
    let (hooks, events) = (UserHooks::default(), UserEvents::default());
    let mut bodies = Vec::new();
    let mut world = SoftWorld::new();
    let scene = build(&mut world.physics);
    let mut own = SoftContacts::new();
    match plugin {
        Plugin::None => {}
        Plugin::SoftWorld => world.register(scene.tip, fingertip()).unwrap(),
        Plugin::OwnWorld => own
            .register(&mut world.physics, scene.tip, fingertip())
            .unwrap(),
    }
    for step in 0..STEPS {
        match plugin {
            Plugin::None => world.physics.step_with_events(&hooks, &events),
            Plugin::SoftWorld => world.step_with(&hooks, &events),
            Plugin::OwnWorld => own.step(&mut world.physics, &hooks, &events),
        }
        let soft = match plugin {
            Plugin::None => None,
            Plugin::SoftWorld => Some(&world.soft),
            Plugin::OwnWorld => Some(&own),
        };
        if let Some(soft) = soft {
            // The fingertip is active, and rapier ran once with the whole dt.
            let c = soft.contacts();
            assert_eq!(c.len(), 1, "step {step}");
            assert_eq!(c[0].other, scene.block);
            assert!(c[0].normal_force > 0.0, "step {step}");
            assert_eq!(soft.counters().substeps_last, 1, "step {step}");
        }
        record(&world.physics, Some(scene.tip_body), &mut bodies);
    }
    let trace = Trace {
        bodies,
        events: events.events.into_inner().unwrap(),
        calls: hooks.calls.into_inner().unwrap(),
    };
    // Nothing of the soft part reached the user (plain rapier does not pair a kinematic and a
    // fixed collider; the plugin's fingertip is filtered before any hook or event).
    let soft_part = [format!("{:?}", scene.tip), format!("{:?}", scene.block)];
    for s in trace.events.iter().chain(&trace.calls) {
        assert!(!soft_part.iter().any(|h| s.contains(h.as_str())), "{s}");
    }
    trace
}

fn count(trace: &Trace, prefix: &str) -> usize {
    trace
        .events
        .iter()
        .chain(&trace.calls)
        .filter(|s| s.starts_with(prefix))
        .count()
}

#[test]
fn user_hooks_and_events_on_rigid_pairs_match_plain_rapier_bit_for_bit() {
    let plain = run(Plugin::None);
    println!(
        "passthrough: {} values, {} events ({} started, {} stopped, {} force), {} hook calls ({} filter, {} intersect, {} modify)",
        plain.bodies.len(),
        plain.events.len(),
        count(&plain, "Started"),
        count(&plain, "Stopped"),
        count(&plain, "force"),
        plain.calls.len(),
        count(&plain, "filter"),
        count(&plain, "intersect"),
        count(&plain, "modify"),
    );
    // The scene exercises every hook and event kind.
    for kind in [
        "Started",
        "Stopped",
        "force",
        "filter",
        "intersect",
        "modify",
    ] {
        assert!(count(&plain, kind) > 0, "no {kind} in the plain run");
    }
    let soft = run(Plugin::SoftWorld);
    assert_eq!(soft.events, plain.events);
    assert_eq!(soft.calls, plain.calls);
    assert!(soft.bodies == plain.bodies, "trajectories differ");
}

#[test]
fn soft_contacts_on_the_users_own_world_match_plain_rapier_bit_for_bit() {
    let plain = run(Plugin::None);
    let own = run(Plugin::OwnWorld);
    assert_eq!(own, plain);
}

/// The user's hooks do what they say in both worlds: the ghost ball falls through the ground,
/// the conveyor box slides along +x, the bouncing ball bounces.
#[test]
fn user_hooks_take_effect_beside_a_fingertip() {
    let (hooks, events) = (UserHooks::default(), UserEvents::default());
    let mut world = SoftWorld::new();
    let scene = build(&mut world.physics);
    world.register(scene.tip, fingertip()).unwrap();
    let handles: Vec<RigidBodyHandle> = world.physics.bodies.iter().map(|(h, _)| h).collect();
    let (ball, conveyor, ghost) = (handles[0], handles[1], handles[2]);
    let mut ball_min = f32::MAX;
    for _ in 0..STEPS {
        world.step_with(&hooks, &events);
        ball_min = ball_min.min(world.physics.bodies[ball].translation().y);
    }
    let y = |h: RigidBodyHandle| world.physics.bodies[h].translation().y;
    let x = |h: RigidBodyHandle| world.physics.bodies[h].translation().x;
    println!(
        "hooks: ghost y = {:.2} m, conveyor x = {:.3} m (from -1), ball lowest y = {:.3} m",
        y(ghost),
        x(conveyor),
        ball_min
    );
    assert!(y(ghost) < -10.0, "the ghost fell through the ground");
    assert!(x(conveyor) > -0.5, "the conveyor box moved along +x");
    assert!(
        ball_min > 0.5 && ball_min < 0.7,
        "the ball bounced on the ground"
    );
}
