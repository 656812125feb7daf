"""Drake's side of the peers' comparison: the squeeze with hydroelastic contact (a compliant
hydroelastic sphere against a rigid hydroelastic plate) and with point contact, and the
N-sphere resting scene.

The sphere of the squeeze is welded to the world at the origin (the FE reference's hemisphere
on a rigid plane, pressed by delta); the plate is a 1000 kg body on a vertical prismatic joint
whose position and velocity are set before every step (a prescribed motion: over one step the
contact moves a body of that mass by nothing measurable). The force is the contact result's
normal force after the step. MultibodyPlant is discrete (SAP, Drake's default solver).
"""

import time

import numpy as np
from pydrake.geometry import (
    AddCompliantHydroelasticProperties,
    AddContactMaterial,
    AddRigidHydroelasticProperties,
    Box,
    HalfSpace,
    ProximityProperties,
    Sphere,
)
from pydrake.math import RigidTransform
from pydrake.multibody.plant import (
    AddMultibodyPlantSceneGraph,
    ContactModel,
    CoulombFriction,
)
from pydrake.multibody.tree import PrismaticJoint, SpatialInertia
from pydrake.systems.analysis import Simulator
from pydrake.systems.framework import DiagramBuilder

from common import E_STAR, MASS, RADIUS, X_END, X_MATCH, StepTimer, hertz_force

R = RADIUS
FRICTIONLESS = CoulombFriction(0.0, 0.0)


def hydro_modulus_matched():
    """Hydroelastic modulus E_h from Drake's documented estimate (its C++ documentation's
    module `hydro_params`, analytical formulas to estimate hydroelastic parameters, with
    `multibody/plant/contact_model_doxygen.h` as its source): a compliant body of modulus E_h
    behaves as an elastic foundation of depth H, f = (E_h / H) V; for a sphere on a half-space
    H = R and V = pi R delta^2 at small delta, so f = pi E_h delta^2. Equated to Hertz's force
    at x = X_MATCH: E_h = (4/3) E* sqrt(R) delta^1.5 / (pi delta^2)."""
    delta = X_MATCH * R
    return float(hertz_force(X_MATCH) / (np.pi * delta**2))


def point_stiffness_matched():
    """Drake's point contact is a linear spring (plus Hunt-Crossley dissipation, zero here):
    its stiffness is Hertz's secant at x = X_MATCH."""
    return float(hertz_force(X_MATCH) / (X_MATCH * R))


def squeeze(model, dt=0.001, speed=0.01, hint=None, modulus=None):
    """The squeeze to X_END with `model` "hydroelastic" (compliant sphere, resolution hint
    `hint` [m], modulus `modulus` [Pa]) or "point". Returns (xs, Fs, timer, info)."""
    builder = DiagramBuilder()
    plant, _ = AddMultibodyPlantSceneGraph(builder, time_step=dt)
    plant.set_contact_model(
        ContactModel.kHydroelastic if model == "hydroelastic" else ContactModel.kPoint)
    ball = ProximityProperties()
    plate_props = ProximityProperties()
    if model == "hydroelastic":
        AddCompliantHydroelasticProperties(hint, modulus, ball)
        AddContactMaterial(dissipation=0.0, friction=FRICTIONLESS, properties=ball)
        AddRigidHydroelasticProperties(R / 4, plate_props)
        AddContactMaterial(friction=FRICTIONLESS, properties=plate_props)
    else:
        AddContactMaterial(dissipation=0.0, point_stiffness=point_stiffness_matched(),
                           friction=FRICTIONLESS, properties=ball)
        # Point stiffnesses combine in series: the plate's is 1e6 times the sphere's.
        AddContactMaterial(dissipation=0.0, point_stiffness=1e6 * point_stiffness_matched(),
                           friction=FRICTIONLESS, properties=plate_props)
    plant.RegisterCollisionGeometry(plant.world_body(), RigidTransform(), Sphere(R), "ball", ball)
    plate = plant.AddRigidBody("plate", SpatialInertia.SolidBoxWithMass(1000.0, 0.1, 0.1, 0.01))
    plant.RegisterCollisionGeometry(plate, RigidTransform([0, 0, 0.005]), Box(0.1, 0.1, 0.01),
                                    "plate", plate_props)
    joint = plant.AddJoint(PrismaticJoint("z", plant.world_frame(), plate.body_frame(), [0, 0, 1]))
    plant.mutable_gravity_field().set_gravity_vector([0, 0, 0])
    plant.Finalize()
    diagram = builder.Build()
    sim = Simulator(diagram)
    ctx = sim.get_mutable_context()
    pctx = plant.GetMyMutableContextFromRoot(ctx)
    z = R - 0.02 * R  # the plate's bottom face, x = 0.02
    joint.set_translation(pctx, z)
    joint.set_translation_rate(pctx, -speed)
    sim.Initialize()
    port = plant.get_contact_results_output_port()
    timer = StepTimer()
    xs, fs = [], []
    t = 0.0
    while True:
        z -= speed * dt
        x = (R - z) / R
        if x > X_END:
            break
        joint.set_translation(pctx, z)
        joint.set_translation_rate(pctx, -speed)
        t += dt
        timer.time(sim.AdvanceTo, t)
        # The step moved the plate by the contact's impulse over 1000 kg; read where it is.
        x = (R - joint.get_translation(pctx)) / R
        cr = port.Eval(pctx)
        f = sum(abs(cr.hydroelastic_contact_info(i).F_Ac_W().translational()[2])
                for i in range(cr.num_hydroelastic_contacts()))
        f += sum(abs(cr.point_pair_contact_info(i).contact_force()[2])
                 for i in range(cr.num_point_pair_contacts()))
        xs.append(x)
        fs.append(f)
    return xs, fs, timer


def resting(n, dt=1.0 / 60.0, settle=120, budget_s=15.0):
    """N free spheres (R, fingertip mass) on a 30 mm grid resting on a half-space, point
    contact with the Hertz-matched stiffness and a little Hunt-Crossley dissipation so that
    they come to rest; µs per step after `settle` steps, best of 3 rounds of
    clamp(20000/N, 60, 2000) steps. A Drake step grows faster than N (near a second at
    N = 1000 here), so the settle and each round also stop after `budget_s` of wall time (at
    least 5 steps): fewer steps, never skipped. The spheres start at their resting depth.
    Returns (µs/step, steps per round, max speed [m/s], settle steps done)."""
    builder = DiagramBuilder()
    plant, _ = AddMultibodyPlantSceneGraph(builder, time_step=dt)
    plant.set_contact_model(ContactModel.kPoint)
    props = ProximityProperties()
    AddContactMaterial(dissipation=1.0, point_stiffness=point_stiffness_matched(),
                       friction=CoulombFriction(0.5, 0.5), properties=props)
    plant.RegisterCollisionGeometry(plant.world_body(), RigidTransform(), HalfSpace(),
                                    "ground", props)
    side = int(np.ceil(np.sqrt(n)))
    bodies = []
    for i in range(n):
        body = plant.AddRigidBody(f"ball{i}", SpatialInertia.SolidSphereWithMass(MASS, R))
        plant.RegisterCollisionGeometry(body, RigidTransform(), Sphere(R), f"ball{i}", props)
        bodies.append(body)
    plant.Finalize()
    diagram = builder.Build()
    sim = Simulator(diagram)
    ctx = sim.get_mutable_context()
    pctx = plant.GetMyMutableContextFromRoot(ctx)
    rest = MASS * 9.81 / point_stiffness_matched()
    for i, body in enumerate(bodies):
        row, col = divmod(i, side)
        pose = RigidTransform([(col - 0.5 * (side - 1)) * 0.03,
                               (row - 0.5 * (side - 1)) * 0.03, R - rest])
        plant.SetFreeBodyPose(pctx, body, pose)
    sim.Initialize()
    t = 0.0
    settled = 0
    t0 = time.perf_counter()
    while settled < settle and (settled < 5 or time.perf_counter() - t0 < budget_s):
        t += dt
        sim.AdvanceTo(t)
        settled += 1
    steps = int(np.clip(20000 // n, 60, 2000))
    best, done = np.inf, steps
    for _ in range(3):
        timer = StepTimer()
        while timer.steps < steps and (timer.steps < 5 or timer.wall < budget_s):
            t += dt
            timer.time(sim.AdvanceTo, t)
        best = min(best, timer.us_per_step())
        done = min(done, timer.steps)
    speed = float(np.max(np.abs(plant.GetVelocities(pctx))))
    return best, done, speed, settled


def squeeze_rows():
    """The Drake rows of the squeeze table."""
    eh = hydro_modulus_matched()
    rows = []
    runs = [
        ("hydroelastic, E_h matched (Drake's estimate), hint R/4", "hydroelastic", R / 4, eh,
         f"E_h = {eh / 1e6:.3f} MPa from Drake's f = (E_h/H) V, H = R, V = pi R delta^2, "
         "equated to Hertz at x = 0.05"),
        ("hydroelastic, E_h matched (Drake's estimate), hint R/10", "hydroelastic", R / 10, eh,
         f"E_h = {eh / 1e6:.3f} MPa as above, a finer tetrahedral mesh"),
        ("hydroelastic, E_h = E, hint R/4", "hydroelastic", R / 4, 3.0e6,
         "E_h = Young's modulus, 3 MPa"),
        ("point contact matched to Hertz at x = 0.05", "point", None, None,
         f"linear point stiffness {point_stiffness_matched():.1f} N/m = Hertz's secant at x = 0.05"),
    ]
    for name, model, hint, modulus, how in runs:
        xs, fs, timer = squeeze(model, hint=hint, modulus=modulus)
        rows.append({
            "peer": "Drake",
            "variant": name,
            "dt": 0.001,
            "steps": timer.steps,
            "us_per_step": timer.us_per_step(),
            "x": xs,
            "force": fs,
            "note": how + "; sphere welded to the world, 1000 kg plate on a prismatic joint, "
                          "position and velocity prescribed each step at 10 mm/s; SAP, "
                          "no dissipation, frictionless",
        })
    return rows


__all__ = ["squeeze_rows", "resting", "E_STAR"]
