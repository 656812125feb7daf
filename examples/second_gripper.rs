//! A user's own bevy_ecs app: the default scene, plus a second gripper (two kinematic jaws
//! with soft fingertips around a second box) driven by a custom system that reads the
//! `FingertipContact` components: a proportional grip-force controller holding 4 N per fingertip.
//!
//! `cargo run -p softgrip-ecs --example second_gripper`

use softgrip_ecs::bevy_ecs::prelude::*;
use softgrip_ecs::softgrip_rapier::rapier3d::prelude::SharedShape;
use softgrip_ecs::softgrip_rapier::{Preset, SoftFingertip};
use softgrip_ecs::{
    AttachedTo, BodyKind, BodyPose, Collider, Fingertip, FingertipContact, KinematicTarget,
    RigidBody, Scene, SoftgripSystems, build_schedule, spawn_scene,
};

/// A jaw of the second gripper: closes along `dir` until its fingertip pushes with `target` N.
#[derive(Component)]
struct ForceJaw {
    dir: f64,
    x: f64,
    target: f64,
}

/// The custom controller: reads every FingertipContact, moves each jaw by a gain times the force error.
fn grip_force_controller(
    contacts: Query<&FingertipContact>,
    tips: Query<&AttachedTo, With<Fingertip>>,
    mut jaws: Query<(Entity, &mut ForceJaw, &mut KinematicTarget)>,
) {
    for (entity, mut jaw, mut target) in &mut jaws {
        let force: f64 = contacts
            .iter()
            .filter(|c| tips.get(c.fingertip).is_ok_and(|a| a.0 == entity))
            .map(|c| c.contact.normal_force)
            .sum();
        // 0.01 mm/N per step, at most 0.02 mm per step (1.2 mm/s at 60 Hz): slow enough that
        // the contact's damping force stays small (a faster jaw makes it chatter).
        let step = (1e-5 * (jaw.target - force)).clamp(-2e-5, 2e-5);
        jaw.x += jaw.dir * step;
        target.0 = Some([jaw.x, 0.02, 0.2]);
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut world = World::new();
    spawn_scene(&mut world, &Scene::default_scene());

    // The second box (500 kg/m^3), 20 cm behind the first, and its two jaws.
    let cube = RigidBody::at(BodyKind::Dynamic, [0.0, 0.02, 0.2]);
    let cube = world.spawn((Name::new("box2"), cube)).id();
    let shape = Collider::new(SharedShape::cuboid(0.02, 0.02, 0.02)).with_density(500.0);
    world.spawn((shape, AttachedTo(cube)));
    for (name, x, dir) in [("jaw2_left", -0.034, 1.0), ("jaw2_right", 0.034, -1.0)] {
        let body = RigidBody::at(BodyKind::Kinematic, [x, 0.02, 0.2]);
        let controller = ForceJaw {
            dir,
            x,
            target: 4.0,
        };
        let jaw = (
            Name::new(name),
            body,
            KinematicTarget::default(),
            controller,
        );
        let jaw = world.spawn(jaw).id();
        let tip = SoftFingertip::builder(0.01).name(format!("{name}_tip"));
        let tip = Fingertip::new(tip.preset(Preset::DragonSkin20).build()?);
        world.spawn((Name::new(format!("{name}_tip")), tip, AttachedTo(jaw)));
    }

    let mut schedule = build_schedule(&world);
    schedule.add_systems(grip_force_controller.in_set(SoftgripSystems::Control));
    for _ in 0..600 {
        schedule.run(&mut world);
    }

    for c in world.query::<&FingertipContact>().iter(&world) {
        let name = world.get::<Name>(c.fingertip).map_or("?", |n| n.as_str());
        let (f, x) = (c.contact.normal_force, c.contact.x);
        println!("{name}: {f:.3} N at x = {x:.3}");
    }
    for (n, p) in world.query::<(&Name, &BodyPose)>().iter(&world) {
        if n.as_str().starts_with("box") {
            println!("{n}: y = {:.4} m", p.translation[1]);
        }
    }
    Ok(())
}
