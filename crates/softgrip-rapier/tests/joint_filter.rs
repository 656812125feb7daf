//! A fingertip's pairs obey the joints' contact filtering as rapier's own pairs do (session 23,
//! issue 25): rapier's narrow phase never sees a fingertip (its collision groups are
//! `none()`), so until session 23 a pad on a robot's link pressed the links its robot keeps
//! from colliding with that link: the link it is jointed to (a URDF joint's two links:
//! `GenericJoint::contacts_enabled` false) and, with `self_contacts = false`
//! (`Multibody::set_self_contacts_enabled`), every other link of its robot.
//!
//! Each case: a fingertip (R = 10 mm) on a dynamic body, its ball 2 mm into a fixed box on a
//! second body jointed to the first, no gravity; one step; the soft contacts of the pair
//! counted (0 where rapier filters the bodies' pairs, 1 where it does not).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::SoftWorld;
use softgrip_testkit::scenes::{RADIUS as R, fingertip};

/// How the two bodies are held together.
#[derive(Debug, Clone, Copy)]
enum Joint {
    /// An impulse joint with its contacts enabled or not.
    Impulse { contacts: bool },
    /// A multibody (the box's body its root) with the joint's contacts enabled or not and its
    /// self-contacts on or off.
    Multibody { contacts: bool, self_contacts: bool },
    /// No joint.
    None,
}

/// The soft contacts of the fingertip with the box after one step, for `joint`.
fn contacts(joint: Joint) -> usize {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let w = &mut world.physics;
    let root = w.bodies.insert(RigidBodyBuilder::fixed());
    let block = w.colliders.insert_with_parent(
        ColliderBuilder::cuboid(0.02, 0.02, 0.02),
        root,
        &mut w.bodies,
    );
    // The ball's centre R - 2 mm above the box's top face.
    let y = 0.02 + R as f32 - 0.002;
    let finger = w
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.0, y, 0.0)));
    let tip = w.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32).density(1000.0),
        finger,
        &mut w.bodies,
    );
    // A revolute joint about z through the box's centre: the finger swings about it.
    let revolute = |contacts: bool| {
        RevoluteJointBuilder::new(Vector::Z)
            .local_anchor1(Vector::ZERO)
            .local_anchor2(Vector::new(0.0, -y, 0.0))
            .contacts_enabled(contacts)
    };
    match joint {
        Joint::Impulse { contacts } => {
            w.impulse_joints
                .insert(root, finger, revolute(contacts), true);
        }
        Joint::Multibody {
            contacts,
            self_contacts,
        } => {
            let h = w
                .multibody_joints
                .insert(root, finger, revolute(contacts), true)
                .unwrap();
            let (mb, _) = w.multibody_joints.get_mut(h).unwrap();
            mb.set_self_contacts_enabled(self_contacts);
        }
        Joint::None => {}
    }
    world
        .register(tip, fingertip(Level::Calibrated, 0.5).build().unwrap())
        .unwrap();
    world.step();
    (world.soft.contacts().iter())
        .filter(|c| c.fingertip == tip && c.other == block)
        .count()
}

#[test]
fn a_fingertip_does_not_press_a_body_its_joint_keeps_from_colliding() {
    let cases = [
        (Joint::None, 1),
        (Joint::Impulse { contacts: true }, 1),
        (Joint::Impulse { contacts: false }, 0),
        (
            Joint::Multibody {
                contacts: true,
                self_contacts: true,
            },
            1,
        ),
        (
            Joint::Multibody {
                contacts: false,
                self_contacts: true,
            },
            0,
        ),
        (
            Joint::Multibody {
                contacts: true,
                self_contacts: false,
            },
            0,
        ),
    ];
    for (joint, expected) in cases {
        assert_eq!(contacts(joint), expected, "{joint:?}");
    }
}
