//! rapier's own FEM soft body (`fem` feature, `SoftBodyCellModel::NeoHookean`) as a solid
//! tetrahedral ball, squeezed quasi-statically between a kinematic plate and the fixed ground
//! (no gravity).
//!
//! The force is each side's reaction: `ContactPair::total_impulse` of the plate-ball and of the
//! ground-ball pair over the step, over dt. For a soft-rigid pair rapier sums the impulses of
//! the pair's solver manifolds there (not the predictive vertex contacts nor the volume patch
//! it may add beside them); with no gravity, the two sides must agree in a quasi-static
//! squeeze, which is the check that nothing is missing.
//!
//! A load cell (a dynamic plate under the ball, its ground contact read as an ordinary rigid
//! pair) was tried first: it read 0.5 % of the force, and was dropped.

use std::time::{Duration, Instant};

use rapier3d::prelude::*;

use softgrip_testkit::icosphere::icosphere;

/// Collision radius of the ball's particles, as a fraction of the radius (rapier's default is
/// half the mean boundary edge, a quarter of the radius on a coarse mesh).
pub const PARTICLE_RADIUS: f32 = 0.01;

/// Settings of one FEM squeeze.
#[derive(Debug, Clone, Copy)]
pub struct FemSqueeze {
    /// Ball radius in the scene's length unit.
    pub radius: f32,
    /// Young's modulus in the scene's units.
    pub young_modulus: f32,
    /// Poisson's ratio, in [0, 0.5).
    pub poisson_ratio: f32,
    /// Icosphere subdivisions of the surface handed to the tetrahedral fill.
    pub subdivisions: u32,
    /// Target tetrahedron size, as a fraction of the radius.
    pub cell_size: f32,
    /// Total mass of the ball.
    pub mass: f32,
    /// Solver of the soft body's elasticity.
    pub solver: SoftBodySolver,
    /// Plate speed, in radii per second.
    pub speed: f32,
    /// Step \[s\].
    pub dt: f32,
    /// Compression ratios x at which the force is sampled (increasing).
    pub samples: &'static [f32],
}

/// What one FEM squeeze measured.
#[derive(Debug, Clone)]
pub struct FemResult {
    /// Particles of the ball.
    pub particles: usize,
    /// Tetrahedra of the ball.
    pub cells: usize,
    /// Tetrahedra whose rest volume is at most `f32::EPSILON` (rapier gives them no elastic
    /// element: a zero inverse rest matrix).
    pub degenerate_cells: usize,
    /// `(x, f on the plate, f on the ground)`, f = F/(E* R_eff^2), from each pair's
    /// `ContactPair::total_impulse` over the step.
    pub force: Vec<(f64, f64, f64)>,
    /// Steps taken.
    pub steps: usize,
    /// Wall time of all steps.
    pub wall: Duration,
    /// Lowest particle y over the ground's top, over the radius, at the end (a collapsed ball
    /// goes to 0).
    pub height_ratio: f64,
    /// Half the particle cloud's height plus the particle radius, over the surface mesh's
    /// radius: the ball's effective radius, used for x and f.
    pub r_eff: f64,
}

impl FemResult {
    /// Mean wall time per step \[ms\].
    pub fn ms_per_step(&self) -> f64 {
        self.wall.as_secs_f64() * 1e3 / self.steps.max(1) as f64
    }
}

impl FemSqueeze {
    /// Runs the squeeze until the last sample (or the ball gives way).
    // 115 lines: a benchmark driver for rapier's own FEM ball (set-up, loop, sampling) read
    // top to bottom beside the table it prints; nothing else calls it.
    pub fn run(&self) -> Option<FemResult> {
        let r = self.radius;
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        world.integration_parameters.dt = self.dt;
        world.integration_parameters.length_unit = r;
        let wide = 4.0 * r;
        let half_cell = 0.1 * r;
        // Fixed ground, top at y = 0.
        let ground = world.insert_collider(
            ColliderBuilder::cuboid(wide, half_cell, wide)
                .translation(Vector::new(0.0, -half_cell, 0.0)),
            None,
        );
        let floor = 0.0;
        // The ball. rapier's fill covers the surface (its cells may reach past it) and its
        // particles collide with a radius: both are measured, and the plates touch the
        // particle cloud's real top and bottom (its extent is the effective diameter).
        let (vertices, triangles) = icosphere(Vector::ZERO, r, self.subdivisions);
        let builder = SoftBodyBuilder::volumetric(&vertices, &triangles, self.cell_size * r)?
            .cell_model(SoftBodyCellModel::NeoHookean)
            .material(SoftBodyMaterial {
                young_modulus: self.young_modulus,
                poisson_ratio: self.poisson_ratio,
                ..Default::default()
            })
            .solver(self.solver)
            .mass(self.mass)
            .particle_radius(PARTICLE_RADIUS * r)
            .can_sleep(false);
        let (low, high) = builder
            .particle_positions()
            .iter()
            .fold((f32::MAX, f32::MIN), |(lo, hi), p| {
                (lo.min(p.y), hi.max(p.y))
            });
        let skin = PARTICLE_RADIUS * r;
        let r_eff = 0.5 * (high - low) + skin;
        let builder = builder.translated(Vector::new(0.0, floor + skin - low, 0.0));
        let ball = world.insert_soft_body(builder);
        let (particles, cells, degenerate_cells) = {
            let sb = &world.soft_bodies[ball];
            let degenerate = sb
                .cells()
                .iter()
                .filter(|c| c.rest_volume.abs() <= f32::EPSILON)
                .count();
            (sb.num_particles(), sb.cells().len(), degenerate)
        };
        // Kinematic plate, bottom touching the ball's top.
        let plate_body = world.insert_body(
            RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
                0.0,
                floor + 2.0 * r_eff + half_cell,
                0.0,
            )),
        );
        let plate = world.insert_collider(
            ColliderBuilder::cuboid(wide, half_cell, wide),
            Some(plate_body),
        );
        let e_star = self.young_modulus as f64 / (1.0 - (self.poisson_ratio as f64).powi(2));
        let norm = e_star * (r_eff as f64).powi(2);
        let dt = self.dt as f64;
        let mut force = Vec::new();
        let mut next = 0;
        let (mut steps, mut wall) = (0usize, Duration::ZERO);
        let max_steps = (2.0 * (self.samples.last().copied().unwrap_or(0.0) + 0.05)
            / (self.speed * self.dt)) as usize;
        while next < self.samples.len() && steps < max_steps {
            let y = world.bodies[plate_body].translation().y;
            world.bodies[plate_body].set_next_kinematic_translation(Vector::new(
                0.0,
                y - self.speed * r_eff * self.dt,
                0.0,
            ));
            let t = Instant::now();
            world.step();
            wall += t.elapsed();
            steps += 1;
            let plate_bottom = world.bodies[plate_body].translation().y - half_cell;
            let x = ((2.0 * r_eff - (plate_bottom - floor)) / (2.0 * r_eff)) as f64;
            if x >= self.samples[next] as f64 {
                let mesh = world.soft_bodies[ball]
                    .collision_mesh()
                    .map(|m| m.collider());
                let reaction = |other| {
                    mesh.and_then(|m| world.narrow_phase.contact_pair(other, m))
                        .map_or(0.0, |p| p.total_impulse().y.abs() as f64)
                        / dt
                        / norm
                };
                force.push((x, reaction(plate), reaction(ground)));
                next += 1;
            }
        }
        let low = world.soft_bodies[ball]
            .particle_positions()
            .map(|p| p.y)
            .fold(f32::MAX, f32::min);
        let high = world.soft_bodies[ball]
            .particle_positions()
            .map(|p| p.y)
            .fold(f32::MIN, f32::max);
        Some(FemResult {
            particles,
            cells,
            degenerate_cells,
            force,
            steps,
            wall,
            height_ratio: ((high - low) / (2.0 * r_eff)) as f64,
            r_eff: (r_eff / r) as f64,
        })
    }
}
