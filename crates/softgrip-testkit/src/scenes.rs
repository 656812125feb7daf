//! The scenes of hard cases 1 and 2, built once for the benchmarks here and for
//! `softgrip-rapier`'s integration tests (`quasi_static_squeeze.rs`, `bounce.rs`), so that a
//! table and a test measure the same set-up: the same positions, densities and f32 casts,
//! inserted in the same order.
//!
//! - [`PlateSqueeze`]: a dynamic fingertip ball between a fixed floor and a kinematic plate.
//! - [`BallDrop`]: a fingertip ball dropped on a rigid half-space.
//!
//! Both take the fingertip, usually [`fingertip`]`(level, restitution).build()`, so that the
//! caller picks the level, the restitution and, for a drop, the friction.

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, Level, Material};
use softgrip_rapier::{SoftFingertip, SoftFingertipBuilder, SoftWorld};

/// Fingertip radius of the scenes \[m\].
pub const RADIUS: f64 = 0.01;
/// Gravity [m/s^2], the magnitude of [`SoftWorld`]'s default (along -y).
pub const G: f64 = 9.81;
/// Density of the fingertip balls [kg/m^3].
pub const DENSITY: f32 = 1070.0;

/// The scenes' fingertip, to be built: R = [`RADIUS`], E = 3 MPa, nu = 0.49, `level`,
/// restitution `restitution`; the other settings are the builder's defaults.
pub fn fingertip(level: Level, restitution: f64) -> SoftFingertipBuilder {
    SoftFingertip::builder(RADIUS)
        .material(Material::try_new(3.0e6, 0.49).expect("invariant: valid material"))
        .level(level)
        .restitution(restitution)
}

/// Inserts the rigid half-space `y <= 0` (normal +y) as a fixed collider.
pub fn half_space_ground(world: &mut SoftWorld) -> ColliderHandle {
    world
        .physics
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)))
}

/// A dynamic fingertip ball (density [`DENSITY`]) between a fixed floor (top face at y = 0)
/// and a position-based kinematic plate above it. It starts at rest, squeezed to x0 = 0.02 per
/// contact and in equilibrium under gravity: an elastic ball that the moving plate hits
/// would ring for a while (nothing damps it), which is not the quasi-static squeeze.
pub struct PlateSqueeze {
    /// The world; the fingertip is registered.
    pub world: SoftWorld,
    /// The floor, a fixed cuboid.
    pub floor: ColliderHandle,
    /// The ball's body.
    pub ball_body: RigidBodyHandle,
    /// The ball, registered as the fingertip.
    pub ball: ColliderHandle,
    /// The plate's body (position-based kinematic).
    pub plate_body: RigidBodyHandle,
    /// The plate, a cuboid of half-thickness [`PlateSqueeze::HALF`].
    pub plate: ColliderHandle,
    /// The fingertip's law.
    pub law: ContactLaw,
}

impl PlateSqueeze {
    /// Half-thickness of the plate \[m\].
    pub const HALF: f32 = 0.005;

    /// The scene with `tip` as the ball (of the tip's radius).
    pub fn new(tip: SoftFingertip) -> Self {
        let r = tip.radius();
        let mut world = SoftWorld::new();
        let floor = world.physics.colliders.insert(
            ColliderBuilder::cuboid(0.1, 0.01, 0.1).translation(Vector::new(0.0, -0.01, 0.0)),
        );
        let law = tip.law().clone();
        let mass = DENSITY as f64 * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
        let d0 = 0.02 * r;
        let d_eq = d0 + mass * G / (2.0 * law.response(d0).stiffness);
        let ball_body = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, (r - d_eq) as f32, 0.0))
                .can_sleep(false),
        );
        let ball = world.physics.colliders.insert_with_parent(
            ColliderBuilder::ball(r as f32).density(DENSITY),
            ball_body,
            &mut world.physics.bodies,
        );
        let half = Self::HALF;
        let plate_body = world.physics.bodies.insert(
            RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
                0.0,
                (2.0 * r - 2.0 * d0) as f32 + half,
                0.0,
            )),
        );
        let plate = world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(0.05, half, 0.05),
            plate_body,
            &mut world.physics.bodies,
        );
        world
            .register(ball, tip)
            .expect("invariant: a ball of the fingertip's radius");
        Self {
            world,
            floor,
            ball_body,
            ball,
            plate_body,
            plate,
            law,
        }
    }

    /// Height of the plate's bottom face \[m\] (the floor's top face is at 0).
    pub fn plate_bottom(&self) -> f64 {
        self.world.physics.bodies[self.plate_body].translation().y as f64 - Self::HALF as f64
    }

    /// Sets the plate's next kinematic position `step` \[m\] below its current one (reached at
    /// the end of the next `world.step()`).
    pub fn lower_plate(&mut self, step: f64) {
        let plate = &mut self.world.physics.bodies[self.plate_body];
        let y = plate.translation().y as f64;
        plate.set_next_kinematic_translation(Vector::new(0.0, (y - step) as f32, 0.0));
    }
}

/// A dynamic fingertip ball (density [`DENSITY`], friction 0) released at rest with its
/// lowest point `h0` above a rigid half-space ([`half_space_ground`]).
pub struct BallDrop {
    /// The world; the fingertip is registered.
    pub world: SoftWorld,
    /// The ball's body.
    pub body: RigidBodyHandle,
    /// The fingertip's law.
    pub law: ContactLaw,
    /// The ball's mass as rapier computed it \[kg\].
    pub mass: f64,
    /// The ball's radius \[m\].
    pub radius: f64,
}

impl BallDrop {
    /// The scene with `tip` as the ball (of the tip's radius), dropped from `h0` \[m\].
    pub fn new(tip: SoftFingertip, h0: f64) -> Self {
        let r = tip.radius();
        let mut world = SoftWorld::new();
        half_space_ground(&mut world);
        let body = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, (r + h0) as f32, 0.0))
                .can_sleep(false),
        );
        let ball = world.physics.colliders.insert_with_parent(
            ColliderBuilder::ball(r as f32)
                .density(DENSITY)
                .friction(0.0),
            body,
            &mut world.physics.bodies,
        );
        let law = tip.law().clone();
        world
            .register(ball, tip)
            .expect("invariant: a ball of the fingertip's radius");
        let mass = world.physics.bodies[body].mass() as f64;
        Self {
            world,
            body,
            law,
            mass,
            radius: r,
        }
    }

    /// The ball's true vertical velocity [m/s] in free flight. rapier's step is N =
    /// `num_solver_iterations` passes of symplectic Euler, whose stored velocity lags the true
    /// one by `g dt / (2N)`: this is `v_y + g dt / (2N)` with g = -[`G`] y.
    pub fn true_velocity_y(&self) -> f64 {
        let dt = self.world.physics.integration_parameters.dt as f64;
        let n = self
            .world
            .physics
            .integration_parameters
            .num_solver_iterations
            .max(1) as f64;
        self.world.physics.bodies[self.body].linvel().y as f64 - 0.5 * G * dt / n
    }

    /// Height of the ball's lowest point above the ground \[m\] (negative in contact).
    pub fn gap(&self) -> f64 {
        self.world.physics.bodies[self.body].translation().y as f64 - self.radius
    }

    /// Energy of the ball \[J\] with the [true velocity](Self::true_velocity_y):
    /// `E = m/2 |v + g dt/(2N)|^2 + m g y + W(delta)`, exactly conserved in free flight under
    /// constant gravity.
    pub fn energy(&self) -> f64 {
        let rb = &self.world.physics.bodies[self.body];
        let v = rb.linvel();
        let vy = self.true_velocity_y();
        let y = rb.translation().y as f64;
        let delta = (self.radius - y).max(0.0);
        0.5 * self.mass * (vy * vy + (v.x * v.x + v.z * v.z) as f64)
            + self.mass * G * (y - self.radius)
            + self.law.energy(delta)
    }
}
