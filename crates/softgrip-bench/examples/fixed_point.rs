//! Whether N never-asleep fingertips resting on the ground (`OverheadScene`'s grid, the scene
//! of `peers_softgrip resting`, here from its start) reach an exact fixed point: per step, how
//! many bodies' pose and velocity bits differ from the step before and from two steps before
//! (a cycle of two), ball 0's fields that change over the last two steps, and how many steps
//! the resting fast path replayed (`SoftCounters::replayed_steps`).
//!
//! Measured (session 21): from step 8 on every ball is on a cycle of two, bit for bit: its
//! height alternates between 9.981096e-3 and 9.981097e-3 m (neighbouring `f32` values) and
//! its stored vertical velocity between -6.131258e-2 and -6.1312467e-2 m/s; no ball stops on
//! one state (N = 1, 10, 100, 1000).
//!
//! ```text
//! cargo run --release -p softgrip-bench --example fixed_point [n] [steps] [push at step] [ball]
//! ```

use softgrip_testkit::resting::{PITCH, resting_grid};

/// Pose and velocity bits of every body, in the body set's order.
fn bits(world: &softgrip_rapier::SoftWorld) -> Vec<u32> {
    let mut out = Vec::new();
    for (_, rb) in world.physics.bodies.iter() {
        let p = rb.position();
        let t = p.translation;
        let r = p.rotation;
        let (v, w) = (rb.linvel(), rb.angvel());
        out.extend(
            [
                t.x, t.y, t.z, r.x, r.y, r.z, r.w, v.x, v.y, v.z, w.x, w.y, w.z,
            ]
            .map(f32::to_bits),
        );
    }
    out
}

fn changed(a: &[u32], b: &[u32]) -> usize {
    a.chunks(13)
        .zip(b.chunks(13))
        .filter(|(x, y)| x != y)
        .count()
}

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let n = args.first().copied().unwrap_or(10);
    let steps = args.get(1).copied().unwrap_or(300);
    let mut world = resting_grid(n, PITCH, true);
    let mut hist: Vec<Vec<u32>> = vec![bits(&world)];
    let mut first_fixed = None;
    let push = args.get(2).copied();
    for step in 1..=steps {
        if Some(step) == push {
            // Optional: the first ball pushed down at 0.05 m/s at this step.
            let which = args.get(3).copied().unwrap_or(0);
            let h = world.physics.bodies.iter().nth(which).map(|(h, _)| h);
            if let Some(h) = h {
                world.physics.bodies[h]
                    .set_linvel(rapier3d::prelude::Vector::new(0.0, -0.05, 0.0), true);
            }
        }
        world.step();
        let b = bits(&world);
        let d1 = changed(&b, &hist[hist.len() - 1]);
        let d2 = if hist.len() >= 2 {
            changed(&b, &hist[hist.len() - 2])
        } else {
            n
        };
        if d1 == 0 && first_fixed.is_none() {
            first_fixed = Some(step);
        }
        if step <= 10
            || step % 20 == 0
            || push.is_some_and(|p| step > p && step < p + 40)
            || (d1 == 0) != (first_fixed.is_some())
        {
            let y = world
                .physics
                .bodies
                .iter()
                .next()
                .map(|(_, rb)| rb.translation().y);
            println!(
                "step {step:4}: bodies changed vs last step {d1:5}, vs two steps back {d2:5}, ball 0 y = {y:?}"
            );
        }
        if step + 3 > steps {
            // Ball 0's fields that differ from the last step: (field, last, now).
            let names = [
                "x", "y", "z", "qx", "qy", "qz", "qw", "vx", "vy", "vz", "wx", "wy", "wz",
            ];
            let last = &hist[hist.len() - 1];
            let k = 0; // ball 0 (the ground is a collider without a body)
            for f in 0..13 {
                if b[k + f] != last[k + f] {
                    println!(
                        "  step {step}: ball 0 {} {:e} -> {:e}",
                        names[f],
                        f32::from_bits(last[k + f]),
                        f32::from_bits(b[k + f])
                    );
                }
            }
            let c = world.soft.counters();
            println!("  replayed {} of {} steps", c.replayed_steps, c.steps);
        }
        hist.push(b);
    }
    println!(
        "n = {n}: first step with every body bit-identical to the step before: {first_fixed:?}"
    );
}
