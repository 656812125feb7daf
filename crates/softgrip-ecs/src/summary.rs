//! [`Summary`]: per-fingertip peaks, slips, validity excursions and the grip at the commanded
//! depth, accumulated by [`accumulate_summary`].
//!
//! One definition of each figure, over every substep of every step (the run summary, the
//! recording's `softgrip_run_summary` and `softgrip inspect` use the same):
//! - peak force: the largest `TipContact::peak_normal_force` (a substep's normal force);
//! - peak x: the largest `TipContact::max_x` (the compression at the start of any substep or
//!   the end of the step, over R); the two are independent maxima: in an impact the force
//!   peaks before the compression does;
//! - validity excursions: steps in which a contact's `validity_exceeded` (past the law's range
//!   in any substep) is set and was not in the step before; slips likewise with `sliding`;
//! - excursion time: the total duration of the steps in which any contact of the fingertip has
//!   `validity_exceeded` set (the law's extension, its barrier, carried the contact), in
//!   seconds of simulated time.

use std::collections::BTreeMap;
use std::fmt;

use bevy_ecs::prelude::{Entity, MessageReader, Name, Query, Res, ResMut, Resource, With};
use softgrip_record::units::{si, sig};
use softgrip_scene::Phase;

use crate::components::Fingertip;
use crate::controller::Controllers;
use crate::messages::{SlipStarted, ValidityExcursion};
use crate::resources::Physics;

/// One fingertip's summary.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TipSummary {
    /// Fingertip name.
    pub name: String,
    /// Largest normal force of any contact of the fingertip in any substep \[N\].
    pub peak_force: f64,
    /// Largest compression ratio x = delta / R of any contact in any substep (including the
    /// end of each step) [-]; a maximum of its own, not x at the peak force.
    pub peak_x: f64,
    /// Contact radius at the largest compression (the law's at it) \[m\].
    pub peak_radius: f64,
    /// Slip events (`SlipStarted`).
    pub slips: u32,
    /// Validity excursions (`ValidityExcursion`).
    pub validity_excursions: u32,
    /// How long the excursions lasted \[s\]: the summed duration of the steps in which a
    /// contact of the fingertip was past its law's range (`validity_exceeded`), >= 0.
    pub excursion_time: f64,
    /// Commanded compression of the gripper's squeeze \[m\] (fingertips on a gripper jaw).
    pub commanded_depth: Option<f64>,
    /// Normal force at the end of the squeeze's settle phase \[N\].
    pub squeeze_force: Option<f64>,
    /// Compression at the end of the squeeze's settle phase \[m\].
    pub squeeze_delta: Option<f64>,
}

/// The run's summary: one entry per fingertip, in spawn (scene) order.
#[derive(Resource, Debug, Clone, Default)]
pub struct Summary {
    /// Per fingertip.
    pub tips: Vec<(Entity, TipSummary)>,
}

impl Summary {
    /// The summary of the fingertip named `name`.
    pub fn tip(&self, name: &str) -> Option<&TipSummary> {
        self.tips.iter().map(|(_, t)| t).find(|t| t.name == name)
    }

    /// The summary as `key = value` pairs (for a recording's metadata): `steps` (steps run),
    /// and per fingertip `<name>.slips`, `<name>.validity_excursions`, `<name>.peak_force`
    /// \[N\] and `<name>.peak_x`.
    pub fn to_metadata(&self, steps: u64) -> BTreeMap<String, String> {
        let mut m = BTreeMap::new();
        m.insert("steps".to_string(), steps.to_string());
        for (_, t) in &self.tips {
            let n = &t.name;
            m.insert(format!("{n}.slips"), t.slips.to_string());
            m.insert(
                format!("{n}.validity_excursions"),
                t.validity_excursions.to_string(),
            );
            m.insert(format!("{n}.peak_force"), t.peak_force.to_string());
            m.insert(format!("{n}.peak_x"), t.peak_x.to_string());
        }
        m
    }

    fn entry(&mut self, tip: Entity, name: &str) -> &mut TipSummary {
        let i = match self
            .tips
            .binary_search_by_key(&tip.index_u32(), |(e, _)| e.index_u32())
        {
            Ok(i) => i,
            Err(i) => {
                let t = TipSummary {
                    name: name.to_string(),
                    ..TipSummary::default()
                };
                self.tips.insert(i, (tip, t));
                i
            }
        };
        &mut self.tips[i].1
    }
}

/// Updates the [`Summary`] from the last step's contacts and messages.
pub fn accumulate_summary(
    physics: Res<Physics>,
    mut summary: ResMut<Summary>,
    tips: Query<(Entity, &Name), With<Fingertip>>,
    controllers: Option<Res<Controllers>>,
    mut slips: MessageReader<SlipStarted>,
    mut excursions: MessageReader<ValidityExcursion>,
) {
    for (e, name) in &tips {
        summary.entry(e, name.as_str());
    }
    let dt = f64::from(physics.world.physics.integration_parameters.dt);
    // A fingertip with several contacts past the range in one step counts the step once.
    let mut exceeded: Vec<Entity> = Vec::new();
    for c in physics.world.soft.contacts() {
        let Some(tip) = physics.collider_entity(c.fingertip) else {
            continue;
        };
        let Ok((_, name)) = tips.get(tip) else {
            continue;
        };
        let s = summary.entry(tip, name.as_str());
        if c.validity_exceeded && !exceeded.contains(&tip) {
            exceeded.push(tip);
            s.excursion_time += dt;
        }
        s.peak_force = s.peak_force.max(c.peak_normal_force);
        if c.max_x > s.peak_x {
            s.peak_x = c.max_x;
            s.peak_radius = c.law().patch(c.max_delta).radius;
        }
    }
    for m in slips.read() {
        if let Ok((_, name)) = tips.get(m.fingertip) {
            summary.entry(m.fingertip, name.as_str()).slips += 1;
        }
    }
    for m in excursions.read() {
        if let Ok((_, name)) = tips.get(m.fingertip) {
            summary
                .entry(m.fingertip, name.as_str())
                .validity_excursions += 1;
        }
    }
    let Some(controllers) = controllers else {
        return;
    };
    let handles = controllers.0.handles();
    for c in controllers.0.controllers() {
        let (Some(Phase::Settle), Some(view)) = (c.phase(), c.grasp()) else {
            continue;
        };
        for (fingertips, depth) in view.fingers.iter().zip(&view.depth) {
            for &i in fingertips {
                let Some(collider) = handles.fingertips.get(i).map(|h| h.1) else {
                    continue;
                };
                let Some(tip) = physics.collider_entity(collider) else {
                    continue;
                };
                let Ok((_, name)) = tips.get(tip) else {
                    continue;
                };
                let (force, delta) = (physics.world.soft.contacts_of(collider))
                    .fold((0.0, 0.0f64), |(f, d), c| {
                        (f + c.normal_force, d.max(c.delta))
                    });
                let s = summary.entry(tip, name.as_str());
                s.commanded_depth = *depth;
                s.squeeze_force = Some(force);
                s.squeeze_delta = Some(delta);
            }
        }
    }
}

impl fmt::Display for TipSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: peak force {}, peak x {}, peak contact radius {}, slips {}, validity excursions {}",
            self.name,
            si(self.peak_force, "N"),
            sig(self.peak_x),
            si(self.peak_radius, "m"),
            self.slips,
            self.validity_excursions
        )?;
        if self.validity_excursions > 0 || self.excursion_time > 0.0 {
            write!(f, " lasting {} in all", si(self.excursion_time, "s"))?;
        }
        if let (Some(d), Some(force)) = (self.commanded_depth, self.squeeze_force) {
            write!(
                f,
                ", squeeze {} at commanded depth {}",
                si(force, "N"),
                si(d, "m")
            )?;
        }
        Ok(())
    }
}
