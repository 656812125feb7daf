//! Shared helpers: a sink that keeps every frame.

#![allow(dead_code)]

use std::sync::{Arc, Mutex};

use softgrip_ecs::{SinkError, StepFrame, StepSink};

/// Keeps every frame it receives (shared with the test through an `Arc`).
#[derive(Clone, Default)]
pub struct Probe(pub Arc<Mutex<Vec<StepFrame>>>);

impl StepSink for Probe {
    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        self.0.lock().map_err(|_| "poisoned")?.push(frame.clone());
        Ok(())
    }
}

impl Probe {
    /// The frames so far.
    pub fn frames(&self) -> Vec<StepFrame> {
        self.0.lock().expect("not poisoned").clone()
    }
}

/// The bits of every contact value of a run, frame by frame.
pub fn contact_bits(frames: &[StepFrame]) -> Vec<Vec<u64>> {
    frames
        .iter()
        .map(|f| {
            f.contacts
                .iter()
                .flat_map(|c| reading_bits(&c.contact))
                .collect()
        })
        .collect()
}

/// The bits of one plugin readout, in the order the equivalence tests compare them.
pub fn readout_bits(k: &softgrip_ecs::softgrip_rapier::TipContact) -> Vec<u64> {
    reading_bits(&softgrip_ecs::contact_reading(k, None))
}

/// The bits of one contact of a sink's frame, in the order the equivalence tests compare them.
pub fn reading_bits(k: &softgrip_ecs::ContactReading) -> Vec<u64> {
    let mut v = vec![
        k.normal_force,
        k.delta,
        k.x,
        k.torsional_moment,
        k.stiffness,
        k.peak_normal_force,
    ];
    v.extend(k.friction_force);
    v.extend(k.point);
    v.extend(k.normal);
    v.into_iter().map(f64::to_bits).collect()
}
