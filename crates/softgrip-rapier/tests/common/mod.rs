//! Scene helpers shared by the integration tests.

#![allow(dead_code)] // each test file uses a subset
#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{SoftFingertip, SoftWorld};

/// Standard gravity used by the tests [m/s^2].
pub const G: f64 = 9.81;

/// A fingertip of radius `r` [m], Young's modulus `e` [Pa], nu = 0.49.
pub fn tip(r: f64, e: f64, level: Level, restitution: f64, friction: f64) -> SoftFingertip {
    SoftFingertip::builder(r)
        .material(Material::try_new(e, 0.49).unwrap())
        .level(level)
        .restitution(restitution)
        .friction(friction)
        .build()
        .unwrap()
}

/// A dynamic ball of radius `r` at `pos`, density `rho`, registered as `tip`.
pub fn dynamic_tip(
    world: &mut SoftWorld,
    pos: Vector,
    rho: f32,
    tip: SoftFingertip,
) -> (RigidBodyHandle, ColliderHandle) {
    let body = world.physics.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(pos)
            .can_sleep(false),
    );
    let co = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(tip.radius() as f32).density(rho),
        body,
        &mut world.physics.bodies,
    );
    world.register(co, tip).unwrap();
    (body, co)
}

/// A position-based kinematic body at `pos` carrying the fingertip `tip` (a jaw).
pub fn kinematic_tip(
    world: &mut SoftWorld,
    pos: Vector,
    tip: SoftFingertip,
) -> (RigidBodyHandle, ColliderHandle) {
    let body = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::kinematic_position_based().translation(pos));
    let co = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(tip.radius() as f32),
        body,
        &mut world.physics.bodies,
    );
    world.register(co, tip).unwrap();
    (body, co)
}

/// Moves a kinematic body to `pos` over the next step.
pub fn move_to(world: &mut SoftWorld, body: RigidBodyHandle, pos: Vector) {
    world.physics.bodies[body].set_next_kinematic_translation(pos);
}

/// Smoothstep 0 -> 1 over s in [0, 1] (zero velocity at both ends).
pub fn smoothstep(s: f64) -> f64 {
    let s = s.clamp(0.0, 1.0);
    s * s * (3.0 - 2.0 * s)
}

/// `true` if every pose and velocity in the world is finite.
pub fn all_finite(world: &SoftWorld) -> bool {
    world.physics.bodies.iter().all(|(_, rb)| {
        rb.translation().is_finite()
            && rb.rotation().is_finite()
            && rb.linvel().is_finite()
            && rb.angvel().is_finite()
    }) && world.soft.contacts().iter().all(|c| {
        c.normal_force.is_finite()
            && c.delta.is_finite()
            && c.friction_force.iter().all(|f| f.is_finite())
            && c.torsional_moment.is_finite()
    })
}

/// A box on the ground and two kinematic jaws carrying soft fingertips on its +-x faces.
pub struct Grasp {
    pub world: SoftWorld,
    pub object: RigidBodyHandle,
    pub jaws: [RigidBodyHandle; 2],
    pub tips: [ColliderHandle; 2],
    /// Half extent of the cubic box [m].
    pub half: f64,
    /// Squeeze depth per fingertip from the law's inverse at the grip force [m].
    pub squeeze: f64,
    /// Jaw centre height at the start [m].
    pub y0: f64,
    /// Jaw centre |x| when open and when closed [m].
    pub x_open: f64,
    pub x_closed: f64,
}

/// Settings of a [`Grasp`].
pub struct GraspSpec {
    pub dt: f32,
    pub mass: f32,
    pub half: f64,
    pub grip_force: f64,
    pub friction: f64,
    pub youngs_modulus: f64,
    /// Centre-of-mass offset of the box along z [m] (off-centre load).
    pub com_offset_z: f32,
    pub torsion: bool,
    /// The fingertips' construction (backed pads face the box).
    pub backing: softgrip_law::Backing,
}

impl Default for GraspSpec {
    fn default() -> Self {
        Self {
            dt: 1.0 / 60.0,
            mass: 0.2,
            half: 0.025,
            grip_force: 5.0,
            friction: 0.3,
            youngs_modulus: 0.59e6,
            com_offset_z: 0.0,
            torsion: true,
            backing: softgrip_law::Backing::Free,
        }
    }
}

/// Mindlin's static slide of a [`Grasp`]'s held box with the friction spring (the default
/// since session 19): each of the two pads shears like a spring of stiffness `k_t = 8 G* a`
/// (`G* = G / (2 - nu)` against the rigid box, `a` the law's contact radius at the squeeze
/// `squeeze` [m]), so the box sags by its weight shared over the two pads, `m g / (2 k_t)`
/// [m]. Returns `(sag, k_t)`.
pub fn mindlin_sag(spec: &GraspSpec, squeeze: f64) -> (f64, f64) {
    let nu = 0.49;
    let g_star = spec.youngs_modulus / (2.0 * (1.0 + nu)) / (2.0 - nu);
    let tip = SoftFingertip::builder(GRASP_R)
        .material(Material::try_new(spec.youngs_modulus, nu).unwrap())
        .backing(spec.backing)
        .facing([-1.0, 0.0, 0.0])
        .build()
        .unwrap();
    let a = tip.law().patch(squeeze).radius;
    let k_t = 8.0 * g_star * a;
    (f64::from(spec.mass) * 9.81 / (2.0 * k_t), k_t)
}

/// The largest distance of the samples of `hold`'s second half from the first of them [m]
/// (creep after the slide; the f32 poses near 0.1 m are ~1e-8 m apart).
pub fn late_spread(hold: &[f64]) -> f64 {
    let late = &hold[hold.len() / 2..];
    late.iter().fold(0.0f64, |m, r| m.max((r - late[0]).abs()))
}

/// Fingertip radius of the grasp scenes [m].
pub const GRASP_R: f64 = 0.01;

pub fn grasp(spec: &GraspSpec) -> Grasp {
    let mut world = SoftWorld::new();
    world.physics.integration_parameters.dt = spec.dt;
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(1.0, 0.1, 1.0).translation(Vector::new(0.0, -0.1, 0.0)));
    let h = spec.half as f32;
    let object = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.0, h, 0.0)));
    let i = spec.mass * (2.0 * h * h) / 3.0; // solid cube about its centre
    world.physics.colliders.insert_with_parent(
        ColliderBuilder::cuboid(h, h, h).mass_properties(MassProperties::new(
            Vector::new(0.0, 0.0, spec.com_offset_z),
            spec.mass,
            Vector::splat(i),
        )),
        object,
        &mut world.physics.bodies,
    );
    // The jaw at +x (sign 1) faces -x, the one at -x faces +x: towards the box.
    let make_tip = |sign: f64| {
        SoftFingertip::builder(GRASP_R)
            .material(Material::try_new(spec.youngs_modulus, 0.49).unwrap())
            .friction(spec.friction)
            .torsional_friction(spec.torsion)
            .backing(spec.backing)
            .facing([-sign, 0.0, 0.0])
            .build()
            .unwrap()
    };
    let squeeze = make_tip(1.0)
        .law()
        .compression_for_force(spec.grip_force)
        .unwrap();
    let x_closed = spec.half + GRASP_R - squeeze;
    let x_open = spec.half + GRASP_R + 0.002;
    let y0 = spec.half;
    let mut jaws = Vec::new();
    let mut tips = Vec::new();
    for sign in [1.0, -1.0] {
        let (b, c) = kinematic_tip(
            &mut world,
            Vector::new((sign * x_open) as f32, y0 as f32, 0.0),
            make_tip(sign),
        );
        jaws.push(b);
        tips.push(c);
    }
    Grasp {
        world,
        object,
        jaws: [jaws[0], jaws[1]],
        tips: [tips[0], tips[1]],
        half: spec.half,
        squeeze,
        y0,
        x_open,
        x_closed,
    }
}

impl Grasp {
    /// Places the jaws at opening `x` (|x| of each jaw centre) and height `y` for the next step.
    pub fn jaws_to(&mut self, x: f64, y: f64) {
        for (jaw, sign) in self.jaws.into_iter().zip([1.0, -1.0]) {
            move_to(
                &mut self.world,
                jaw,
                Vector::new((sign * x) as f32, y as f32, 0.0),
            );
        }
    }

    /// Jaw height [m].
    pub fn jaw_y(&self) -> f64 {
        self.world.physics.bodies[self.jaws[0]].translation().y as f64
    }

    /// Box centre height [m].
    pub fn object_y(&self) -> f64 {
        self.world.physics.bodies[self.object].translation().y as f64
    }

    /// Rotation angle of the box from its start [deg].
    pub fn object_turn_deg(&self) -> f64 {
        let (_, angle) = self.world.physics.bodies[self.object]
            .rotation()
            .to_axis_angle();
        let a = angle as f64;
        let a = if a > std::f64::consts::PI {
            2.0 * std::f64::consts::PI - a
        } else {
            a
        };
        a.to_degrees()
    }

    /// Runs the standard schedule: close over 0.5 s, settle 0.5 s, lift `lift` [m] over 1 s,
    /// hold `hold` [s]. `each` is called after every step with the phase name.
    pub fn run(&mut self, lift: f64, hold: f64, mut each: impl FnMut(&Grasp, &str)) {
        let dt = self.world.physics.integration_parameters.dt as f64;
        let n = |t: f64| (t / dt).round() as usize;
        for i in 1..=n(0.5) {
            let s = smoothstep(i as f64 / n(0.5) as f64);
            self.jaws_to(self.x_open + (self.x_closed - self.x_open) * s, self.y0);
            self.world.step();
            each(self, "close");
        }
        for _ in 0..n(0.5) {
            self.jaws_to(self.x_closed, self.y0);
            self.world.step();
            each(self, "settle");
        }
        for i in 1..=n(1.0) {
            let s = smoothstep(i as f64 / n(1.0) as f64);
            self.jaws_to(self.x_closed, self.y0 + lift * s);
            self.world.step();
            each(self, "lift");
        }
        for _ in 0..n(hold) {
            self.jaws_to(self.x_closed, self.y0 + lift);
            self.world.step();
            each(self, "hold");
        }
    }
}
