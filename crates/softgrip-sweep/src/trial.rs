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
    /// How hard the object is held at the end of the hold \[N\]: after the hold's last step,
    /// the smallest over the grasp's fingertips (every fingertip of its jaws or fingers) of the
    /// normal force it presses on the object with (summed over its contacts; 0 for one not
    /// touching it). A `grasp` controller closes each finger until each of its fingertips
    /// presses its `force`: this is that force as held, after the settle, the lift and the
    /// hold.
    pub hold_force: f64,
}

/// Positions along `up` at one instant: the object's and the jaws' mean \[m\].
#[derive(Debug, Clone, Copy)]
struct Heights {
    object: f64,
    jaws: f64,
}

/// Runs `scene` (its text `text` goes into the recording's metadata), recording to `mcap`
/// if given; `object` is the body whose hold decides `held`. The run takes the scene's
/// duration, and goes on past it until the grasp's hold ends when that can be later (a `grasp`
/// controller's timeline, `trial_steps`). The error says why the trial
/// has no outcome (no such object, no gripper, the hold never ended, the recorder failed, a
/// step diverged: `the simulation diverged at step N (t = ... s, ...)`, the recording then
/// finished with every step before it).
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
    let steps = trial_steps(scene, &view);
    for k in 0..steps {
        if k >= sim.total_steps() && hold_end.is_some() {
            break;
        }
        let before = phase(&sim);
        sim.step();
        if sim.fault().is_some() {
            break;
        }
        let after = phase(&sim);
        if after == Phase::Lift && before != Phase::Lift {
            lift_start = heights(&sim, &view, object_entity, up);
        }
        if before == Phase::Hold && after == Phase::Release {
            let grip = grip(&sim, &view, object_entity);
            hold_end = heights(&sim, &view, object_entity, up).map(|h| (h, grip));
        }
    }
    sim.finish()
        .map_err(|e| format!("finishing the recording: {e}"))?;
    if let Some(e) = sim.fault() {
        // The trial's row carries the reason; the recording holds every step before it.
        return Err(e.to_string());
    }
    let (Some(start), Some((end, grip))) = (lift_start, hold_end) else {
        let (dt, total) = (scene.file().dt, sim.total_steps());
        let t = total as f64 * dt;
        let on = if steps > total {
            format!(
                ", run on to {} s, the grasp's longest timeline",
                steps as f64 * dt
            )
        } else {
            String::new()
        };
        return Err(format!(
            "the hold did not end within the scene's duration ({t} s{on}, phase {:?} at the \
             end): make `duration` longer",
            phase(&sim)
        ));
    };
    let rise = end.object - start.object;
    let slip_distance = (end.jaws - start.jaws) - rise;
    let lifted = lift == 0.0 || rise >= 0.5 * lift;
    let summary = sim.world.resource::<Summary>();
    let tips = summary.tips.iter().map(|(_, t)| t);
    Ok(Outcome {
        held: grip.each_finger && lifted,
        slips: tips.clone().map(|t| t.slips).sum(),
        slip_distance,
        peak_force: tips.clone().map(|t| t.peak_force).fold(0.0, f64::max),
        peak_x: tips.clone().map(|t| t.peak_x).fold(0.0, f64::max),
        validity_excursions: tips.map(|t| t.validity_excursions).sum(),
        hold_force: grip.least_tip_force,
    })
}

/// Steps a trial may take: the scene's duration, or more when its grasp's hold can end later
/// ([`GraspView::hold_ends_by`], plus a step for each of its five phase changes and three to
/// spare): the trial then runs on past `duration` until the hold ends. Why: a varied value
/// changes the grasp's timeline (a grasp that never reaches its force closes its whole
/// stroke: the URDF gripper's 28 mm at 10 mm/s is 2.8 s where its 5 N grip takes 1.0 s), and
/// a hold ending after the scene's fixed `duration` made the trial an error row instead of
/// the outcome it is (held or not).
fn trial_steps(scene: &Scene, view: &GraspView) -> u64 {
    let dt = scene.file().dt;
    let needed = view
        .hold_ends_by
        .filter(|t| t.is_finite() && dt > 0.0)
        .map_or(0, |t| (t / dt).ceil() as u64 + 8);
    scene.steps().max(needed)
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

/// What the grasp's fingertips press on the object after the last step.
struct Grip {
    /// Each jaw or finger touches the object (one of its fingertips with a normal force > 0).
    each_finger: bool,
    /// The smallest over the grasp's fingertips of the normal force it presses on the object
    /// with, summed over its contacts with it \[N\] (0 for one not touching it).
    least_tip_force: f64,
}

/// The grasp's grip on the object after the last step.
fn grip(
    sim: &Simulation,
    view: &GraspView,
    object: softgrip_ecs::bevy_ecs::entity::Entity,
) -> Grip {
    let physics = sim.world.resource::<Physics>();
    let handles = sim.world.resource::<Controllers>().0.handles();
    let tips: Vec<Vec<_>> = (view.fingers.iter())
        .map(|f| {
            (f.iter())
                .filter_map(|&i| handles.fingertips.get(i).map(|h| h.1))
                .collect()
        })
        .collect();
    let mut forces: Vec<Vec<f64>> = tips.iter().map(|f| vec![0.0; f.len()]).collect();
    if let Some(object) = physics.body_handle(object) {
        let colliders = &physics.world.physics.colliders;
        for c in physics.world.soft.contacts() {
            if colliders.get(c.other).and_then(|o| o.parent()) != Some(object) {
                continue;
            }
            for (finger, f) in tips.iter().zip(forces.iter_mut()) {
                for (&t, f) in finger.iter().zip(f.iter_mut()) {
                    if t == c.fingertip {
                        *f += c.normal_force.max(0.0);
                    }
                }
            }
        }
    }
    Grip {
        each_finger: !forces.is_empty() && forces.iter().all(|f| f.iter().any(|&x| x > 0.0)),
        least_tip_force: forces
            .iter()
            .flatten()
            .copied()
            .reduce(f64::min)
            .unwrap_or(0.0),
    }
}
