//! [`SubjectNames`]: the scene's names of the bodies, links, joints and contacts a
//! [`StepError`] points at by rapier handle.

use std::collections::HashMap;

use softgrip_rapier::rapier3d::prelude::{ColliderHandle, RigidBodyHandle};
use softgrip_rapier::{StepError, Subject};

use crate::build::SceneHandles;
use crate::scene::Scene;

/// The scene's name of each body (its `[[body]]` name, or `<robot>/<link>` for a robot's
/// link), of each multibody joint by its child link (`<robot>/<joint>`), and of each collider
/// (a fingertip's name, or its body's name).
#[derive(Debug, Clone, Default)]
pub struct SubjectNames {
    bodies: HashMap<RigidBodyHandle, String>,
    joints: HashMap<RigidBodyHandle, String>,
    colliders: HashMap<ColliderHandle, String>,
}

impl SubjectNames {
    /// The names of `scene` as built with `handles` ([`Scene::build`], `Scene::build_into`).
    pub fn new(scene: &Scene, handles: &SceneHandles) -> Self {
        let mut n = Self::default();
        for (name, h) in &handles.bodies {
            n.bodies.insert(*h, name.clone());
        }
        for (body, h) in &handles.shapes {
            n.colliders.insert(*h, body.clone());
        }
        for (name, h) in &handles.fingertips {
            n.colliders.insert(*h, name.clone());
        }
        for (robot, (_, h)) in scene.robots().iter().zip(&handles.robots) {
            for (l, body) in h.links.iter().enumerate() {
                n.bodies.insert(*body, robot.frame(l));
                for co in h.colliders.get(l).into_iter().flatten() {
                    n.colliders.insert(*co, robot.frame(l));
                }
            }
            for joint in robot.joints() {
                if let Some(child) = h.links.get(joint.child) {
                    n.joints
                        .insert(*child, format!("{}/{}", robot.name(), joint.name));
                }
            }
        }
        n
    }

    /// The scene's name of `subject`: a body's or link's name; a joint's
    /// `<robot>/<joint>`; a contact's `<fingertip> on <other>`. `None` for a handle the scene
    /// did not create.
    pub fn name(&self, subject: Subject) -> Option<String> {
        match subject {
            Subject::Body(h) => self.bodies.get(&h).cloned(),
            Subject::Joint { link, .. } => self
                .joints
                .get(&link)
                .or_else(|| self.bodies.get(&link))
                .cloned(),
            Subject::Contact { fingertip, other } => {
                let tip = self.colliders.get(&fingertip)?;
                let other = self.colliders.get(&other).map_or("?", String::as_str);
                Some(format!("{tip} on {other}"))
            }
        }
    }

    /// `e` with its subject's scene name ([`StepError::with_name`]).
    pub fn named(&self, e: StepError) -> StepError {
        match e.subject() {
            Some(s) => {
                let name = self.name(s);
                e.with_name(name)
            }
            None => e,
        }
    }
}
