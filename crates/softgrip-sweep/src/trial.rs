//! One trial: a checked scene run for its duration through the same ECS schedule as
//! `softgrip run`, its [`Summary`] (the run summary's peaks, slips and excursions) and the
//! hold watched to decide [`Outcome::held`].

use std::path::Path;

use softgrip_ecs::{Controllers, GraspView, McapSink, Phase, Physics, Scene, Simulation, Summary};

/// What a trial measured. Every figure but `wall_time` (in [`TrialRow`](crate::TrialRow)) is
/// a function of the trial's scene alone: a trial re-run gives the same bits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// The object is still in the grip, lifted, at the end of the hold: after the last step
    /// of the gripper's `hold` phase, (1) each jaw has a fingertip in contact with the object
    /// and (2) the object has risen along the gripper's `up` since the start of the lift by at
    /// least half the lift distance (skipped when `lift.distance` is 0). SWEEPS.md, "held".
    pub held: bool,
    /// Slip events summed over the fingertips (the run summary's `slips`).
    pub slips: u32,
    /// How far the object slid down in the grip from the start of the lift to the end of the
    /// hold \[m\]: the jaws' rise along `up` minus the object's (0 for an object that moved
    /// with the jaws, the lift distance for one left on the table).
    pub slip_distance: f64,
    /// Largest normal force of any fingertip in any substep \[N\] (the run summary's).
    pub peak_force: f64,
    /// Largest compression ratio x = delta / R of any fingertip \[-\] (the run summary's).
    pub peak_x: f64,
    /// Validity excursions summed over the fingertips (the run summary's).
    pub validity_excursions: u32,
}

/// Positions along `up` at one instant: the object's and the jaws' mean \[m\].
#[derive(Debug, Clone, Copy)]
struct Heights {
    object: f64,
    jaws: f64,
}

/// Runs `scene` (its text `text` goes into the recording's metadata), recording to `mcap`
/// if given; `object` is the body whose hold decides `held`. The error says why the trial
/// has no outcome (no such object, no gripper, the hold never ended, the recorder failed).
pub fn run_scene(
    scene: &Scene,
    text: &str,
    object: &str,
    mcap: Option<&Path>,
) -> Result<Outcome, String> {
    let object_index = scene
        .body_index(object)
        .ok_or_else(|| format!("`object`: no body is named `{object}`"))?;
    let view = grasp_view(scene)
        .ok_or("`held` needs a grasp: the scene has no [gripper] and no `grasp` controller")?;
    let (up, lift) = (view.up, view.lift_distance);
    let mut sim = Simulation::new(scene).with_summary();
    if let Some(path) = mcap {
        let every = scene.file().record.every_n_steps.max(1);
        let sink = McapSink::with_options(path, scene, text, every, &Default::default())
            .map_err(|e| format!("creating the recording {}: {e}", path.display()))?;
        sim = sim.with_recorder(sink);
    }
    sim.initialize();
    let object_entity = sim.entities.bodies[object_index];
    let phase = |sim: &Simulation| {
        sim.world
            .get_resource::<Controllers>()
            .and_then(|c| {
                c.0.controllers()
                    .iter()
                    .find_map(|c| c.grasp().and(c.phase()))
            })
            .unwrap_or(Phase::Done)
    };
    let mut lift_start = None;
    let mut hold_end = None;
    for _ in 0..sim.total_steps() {
        let before = phase(&sim);
        sim.step();
        let after = phase(&sim);
        if after == Phase::Lift && before != Phase::Lift {
            lift_start = heights(&sim, &view, object_entity, up);
        }
        if before == Phase::Hold && after == Phase::Release {
            let grip = in_grip(&sim, &view, object_entity);
            hold_end = heights(&sim, &view, object_entity, up).map(|h| (h, grip));
        }
    }
    sim.finish()
        .map_err(|e| format!("finishing the recording: {e}"))?;
    let (Some(start), Some((end, grip))) = (lift_start, hold_end) else {
        let t = sim.total_steps() as f64 * scene.file().dt;
        return Err(format!(
            "the hold did not end within the scene's duration ({t} s, phase {:?} at the end): \
             make `duration` longer",
            phase(&sim)
        ));
    };
    let rise = end.object - start.object;
    let slip_distance = (end.jaws - start.jaws) - rise;
    let lifted = lift == 0.0 || rise >= 0.5 * lift;
    let summary = sim.world.resource::<Summary>();
    let tips = summary.tips.iter().map(|(_, t)| t);
    Ok(Outcome {
        held: grip && lifted,
        slips: tips.clone().map(|t| t.slips).sum(),
        slip_distance,
        peak_force: tips.clone().map(|t| t.peak_force).fold(0.0, f64::max),
        peak_x: tips.clone().map(|t| t.peak_x).fold(0.0, f64::max),
        validity_excursions: tips.map(|t| t.validity_excursions).sum(),
    })
}

/// The first controller of `scene` that runs a grasp, seen from outside.
fn grasp_view(scene: &Scene) -> Option<GraspView> {
    scene.controllers().iter().find_map(|c| c.grasp())
}

/// The object's and the hand's (its jaws' or base's) mean position along `up` after the last
/// step.
fn heights(
    sim: &Simulation,
    view: &GraspView,
    object: softgrip_ecs::bevy_ecs::entity::Entity,
    up: [f64; 3],
) -> Option<Heights> {
    let physics = sim.world.resource::<Physics>();
    let handles = sim.world.resource::<Controllers>().0.handles();
    let along = |h| {
        let rb = physics.world.physics.bodies.get(h)?;
        let t = rb.translation();
        Some(t.x as f64 * up[0] + t.y as f64 * up[1] + t.z as f64 * up[2])
    };
    let mut hand = 0.0;
    for c in &view.hand {
        hand += along(handles.carrier(*c)?)?;
    }
    Some(Heights {
        object: along(physics.body_handle(object)?)?,
        jaws: hand / view.hand.len().max(1) as f64,
    })
}

/// Whether each jaw or finger has a fingertip in contact with the object after the last step.
fn in_grip(
    sim: &Simulation,
    view: &GraspView,
    object: softgrip_ecs::bevy_ecs::entity::Entity,
) -> bool {
    let physics = sim.world.resource::<Physics>();
    let handles = sim.world.resource::<Controllers>().0.handles();
    let Some(object) = physics.body_handle(object) else {
        return false;
    };
    let colliders = &physics.world.physics.colliders;
    let mut touching = vec![false; view.fingers.len()];
    for c in physics.world.soft.contacts() {
        let on_object = colliders.get(c.other).and_then(|o| o.parent()) == Some(object);
        for (k, t) in touching.iter_mut().enumerate() {
            let mine = view.fingers[k].iter().any(|&i| {
                handles
                    .fingertips
                    .get(i)
                    .is_some_and(|h| h.1 == c.fingertip)
            });
            *t |= on_object && c.normal_force > 0.0 && mine;
        }
    }
    !touching.is_empty() && touching.iter().all(|&t| t)
}
