//! Prints the plugin's three benchmark tables in markdown (a few minutes):
//! `cargo run --release -p softgrip-bench --example plugin_tables`.
//!
//! 1. Overhead of softgrip over rapier's own contacts, N resting fingertips.
//! 2. Speed vs error for the quasi-static squeeze and the elastic bounce, per accuracy and level.
//! 3. rapier's FEM soft body (NeoHookean, solid tetrahedral ball) in the same squeeze.

use rapier3d::prelude::SoftBodySolver;
use softgrip_bench::bounce::bounce;
use softgrip_bench::fe::{fe_at, fe_curve};
use softgrip_bench::fem_ball::FemSqueeze;
use softgrip_bench::overhead::OverheadScene;
use softgrip_bench::squeeze::squeeze;
use softgrip_law::Level;
use softgrip_rapier::SoftAccuracy;

fn main() -> anyhow::Result<()> {
    overhead_table();
    speed_error_tables()?;
    fem_table();
    Ok(())
}

/// Steps timed per variant and round; rounds alternate the variants (shared machine).
fn overhead_steps(n: usize) -> usize {
    (20_000 / n).clamp(60, 2000)
}

fn overhead_table() {
    println!("## 1. Overhead: N fingertips resting on a fixed ground\n");
    println!(
        "R = 10 mm, E = 3 MPa, ν = 0.49, `Level::auto()`, e = 0.5, dt = 1/60 s, settled {} steps; \
         best of 3 rounds (rounds alternate the variants).\n",
        softgrip_bench::overhead::SETTLE_STEPS
    );
    println!(
        "| N | rapier µs/step | softgrip µs/step | ratio | substeps / step | detect µs | solve µs | rapier pipeline µs | rest µs |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in [1usize, 10, 100, 1000] {
        let mut rigid = OverheadScene::new(n, false);
        let mut soft = OverheadScene::new(n, true);
        let steps = overhead_steps(n);
        let (mut best_rigid, mut best_soft) = (f64::MAX, f64::MAX);
        let mut stages = None;
        for _ in 0..3 {
            let (w, _) = rigid.measure(steps);
            best_rigid = best_rigid.min(w.as_secs_f64() / steps as f64);
            let (w, s) = soft.measure(steps);
            let per = w.as_secs_f64() / steps as f64;
            if per < best_soft {
                best_soft = per;
                stages = Some(s);
            }
        }
        let s = stages.expect("invariant: three rounds ran");
        let us = |d: std::time::Duration| d.as_secs_f64() * 1e6 / s.steps as f64;
        let rest = best_soft * 1e6 - us(s.detect) - us(s.solve) - us(s.pipeline);
        println!(
            "| {n} | {:.1} | {:.1} | {:.2} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1} |",
            best_rigid * 1e6,
            best_soft * 1e6,
            best_soft / best_rigid,
            s.substeps as f64 / s.steps as f64,
            us(s.detect),
            us(s.solve),
            us(s.pipeline),
            rest
        );
    }
    println!();
}

const THETAS: [f64; 4] = [0.2, 0.1, 0.05, 0.02];

fn speed_error_tables() -> anyhow::Result<()> {
    println!("## 2a. Quasi-static squeeze (hard case 1)\n");
    println!(
        "Ball R = 10 mm, E = 3 MPa, ν = 0.49, e = 1, between a floor and a plate at 1 mm/s, x = 0.02 → 0.8 \
         (15.6 s simulated, dt = 1/60 s). Force error: max |F/F_law(δ) − 1| of both contacts for x ≥ 0.05, \
         δ = half the plate approach; vs FE: the plate force against the CalculiX reference (x ≤ 0.78).\n"
    );
    println!(
        "| level | θ | force error vs law | vs FE | substeps / step | wall ms per simulated s |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for level in Level::ALL {
        for theta in THETAS {
            let r = squeeze(level, SoftAccuracy::try_new(theta)?);
            println!(
                "| {} | {theta} | {:.3} % | {:.1} % | {:.3} | {:.2} |",
                level.name(),
                100.0 * r.law_error,
                100.0 * r.fe_error,
                r.substeps as f64 / r.steps as f64,
                r.wall.as_secs_f64() * 1e3 / r.sim_time
            );
        }
    }
    println!("\n## 2b. Elastic bounce at dt = 1/60 s (hard case 2)\n");
    println!(
        "The same ball, e = 1, dropped 10 cm on a rigid half-space; 1 s simulated (3.5 bounces). \
         Errors of the first impact against a 1-DOF RK4 of m δ'' = m g − F(δ) at h = 1e-7 s; \
         energy: after the first bounce over at release, minus 1.\n"
    );
    println!(
        "| level | θ | peak force | duration | energy | substeps / step | wall ms per simulated s |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for level in Level::ALL {
        for theta in THETAS {
            let r = bounce(level, SoftAccuracy::try_new(theta)?);
            println!(
                "| {} | {theta} | {:+.2} % | {:+.2} % | {:+.3} % | {:.1} | {:.2} |",
                level.name(),
                100.0 * (r.impact.peak_force / r.reference.peak_force - 1.0),
                100.0 * (r.impact.duration / r.reference.duration - 1.0),
                100.0 * r.energy_error,
                r.substeps as f64 / r.steps as f64,
                r.wall.as_secs_f64() * 1e3 / (r.steps as f64 / 60.0)
            );
        }
    }
    println!();
    Ok(())
}

fn fem_table() {
    println!("## 3. rapier's FEM soft body in the same squeeze\n");
    let samples: &'static [f32] = &[0.1, 0.2, 0.3, 0.4, 0.5, 0.6];
    let base = FemSqueeze {
        radius: 1.0,
        young_modulus: 3.0e6,
        poisson_ratio: 0.49,
        subdivisions: 2,
        cell_size: 0.5,
        mass: 0.0,
        solver: SoftBodySolver::Fem,
        speed: 0.1,
        dt: 1.0 / 60.0,
        samples,
    };
    // Mass whose contact frequency sqrt(E R / m) equals that of the real 10 mm, 4.48 g ball:
    // m scales like R at fixed E.
    let real_mass = 1070.0 * 4.0 / 3.0 * std::f32::consts::PI * 0.01f32.powi(3);
    let runs = [
        ("SI, R = 10 mm, real mass", 0.01, real_mass),
        (
            "R = 1 (×100), dynamically real mass",
            1.0,
            real_mass * 100.0,
        ),
        (
            "R = 1 (×100), 10⁴ × real mass",
            1.0,
            real_mass * 100.0 * 1.0e4,
        ),
    ];
    let fe = fe_curve();
    print!("| scene | particles | cells | cells ≤ f32::EPSILON | R_eff / R | ms/step |");
    for x in samples {
        print!(" f(x = {x}) |");
    }
    println!();
    println!(
        "|---|---:|---:|---:|---:|---:{}",
        "|---:".repeat(samples.len()) + "|"
    );
    print!("| FE reference | | | | | |");
    for x in samples {
        print!(" {:.3} |", fe_at(&fe, *x as f64).unwrap_or(f64::NAN));
    }
    println!();
    for (name, radius, mass) in runs {
        let cfg = FemSqueeze {
            radius,
            mass,
            ..base
        };
        let Some(r) = cfg.run() else {
            println!("| {name} | the tetrahedral fill failed |");
            continue;
        };
        print!(
            "| {name} | {} | {} | {} | {:.3} | {:.1} |",
            r.particles,
            r.cells,
            r.degenerate_cells,
            r.r_eff,
            r.ms_per_step()
        );
        for (i, x) in samples.iter().enumerate() {
            match r.force.get(i) {
                Some(&(xs, top, bottom)) => {
                    let err = fe_at(&fe, xs).map_or(f64::NAN, |f| 100.0 * (top / f - 1.0));
                    print!(" {top:.3} / {bottom:.3} ({err:+.0} %) |");
                }
                None => print!(" — (x = {x} not reached) |"),
            }
        }
        println!();
    }
    println!(
        "\nf = F/(E* R_eff²), plate / ground reaction (each pair's `ContactPair::total_impulse` / dt), \
         error of the plate side against FE. R_eff: the fill covers the sphere and reaches past it, \
         so x and f use half the particle cloud's height plus the particle radius."
    );
}
