"""MuJoCo's side of the peers' comparison: the squeeze (rigid sphere with soft contact, two
parameter sets; flex FEM sphere, two meshes), the N-sphere resting scene and the default grasp.

MuJoCo is z-up; gravity is off in the squeeze (the two contacts then carry the same force).
Contact forces are `mj_contactForce`'s normal component. MuJoCo runs single-threaded (no
thread pool is created).
"""

import time

import mujoco
import numpy as np

from common import MASS, RADIUS, X_END, X_MATCH, StepTimer, fe_force, hertz_force

R = RADIUS
PLATE_HALF = 0.005  # half-thickness of the plate [m]


# --------------------------------------------------------------------------------------------
# Rigid sphere with soft contact
# --------------------------------------------------------------------------------------------


def rigid_xml(dt):
    """A plane (the floor, top at z = 0), a mocap plate above and between them a rigid sphere
    of the fingertip's mass on a vertical slide joint. Frictionless (condim 1), as the FE."""
    return f"""<mujoco model="squeeze">
  <option timestep="{dt}" gravity="0 0 0"/>
  <default><geom condim="1"/></default>
  <worldbody>
    <geom name="floor" type="plane" size="0.1 0.1 0.01"/>
    <body name="plate" mocap="true" pos="0 0 {2 * R + PLATE_HALF}">
      <geom name="plate" type="box" size="0.05 0.05 {PLATE_HALF}"/>
    </body>
    <body name="ball" pos="0 0 {R}">
      <joint name="z" type="slide" axis="0 0 1"/>
      <geom name="ball" type="sphere" size="{R}" mass="{MASS}"/>
    </body>
  </worldbody>
</mujoco>"""


def set_contact(model, solref, solimp):
    """The same solref/solimp on every geom (MuJoCo mixes the two geoms' values)."""
    model.geom_solref[:] = solref
    model.geom_solimp[:] = solimp


def mean_contact(model, data):
    """(mean penetration [m], mean normal force [N]) over the active contacts."""
    f6 = np.zeros(6)
    pens, forces = [], []
    for i in range(data.ncon):
        mujoco.mj_contactForce(model, data, i, f6)
        pens.append(-data.contact[i].dist)
        forces.append(f6[0])
    if not pens:
        return 0.0, 0.0
    return float(np.mean(pens)), float(np.mean(forces))


def static_forces(model, data, xs):
    """The held force at each x, from one `mj_forward` at the symmetric squeeze (sphere
    centre at R - delta, plate bottom at 2R - 2 delta, at rest). By symmetry the sphere's
    acceleration is zero there, so the constraint force is MuJoCo's steady-state force."""
    out = []
    for x in xs:
        delta = x * R
        data.mocap_pos[0] = [0.0, 0.0, 2 * R - 2 * delta + PLATE_HALF]
        data.qpos[0] = -delta
        data.qvel[0] = 0.0
        mujoco.mj_forward(model, data)
        out.append(mean_contact(model, data)[1])
    return np.array(out)


def match_hertz(model, data, solimp):
    """Direct stiffness k (solref = (-k, -b), b = 2 sqrt(k): critical in MuJoCo's reference
    acceleration) so that the held force at x = X_MATCH equals Hertz's (bisection in log k)."""
    target = hertz_force(X_MATCH)
    lo, hi = 1.0, 1.0e12
    for _ in range(200):
        k = np.sqrt(lo * hi)
        set_contact(model, [-k, -2.0 * np.sqrt(k)], solimp)
        f = static_forces(model, data, [X_MATCH])[0]
        if f < target:
            lo = k
        else:
            hi = k
        if hi / lo < 1.0 + 1e-12:
            break
    k = np.sqrt(lo * hi)
    return [-k, -2.0 * np.sqrt(k)]


def nelder_mead(fun, x0, step, iters=600):
    """A plain Nelder-Mead minimiser (no SciPy in the venv): returns the best point."""
    n = len(x0)
    pts = [np.array(x0, float)]
    for i in range(n):
        p = np.array(x0, float)
        p[i] += step[i]
        pts.append(p)
    vals = [fun(p) for p in pts]
    for _ in range(iters):
        order = np.argsort(vals)
        pts = [pts[i] for i in order]
        vals = [vals[i] for i in order]
        centroid = np.mean(pts[:-1], axis=0)
        refl = centroid + (centroid - pts[-1])
        fr = fun(refl)
        if fr < vals[0]:
            exp = centroid + 2.0 * (centroid - pts[-1])
            fe = fun(exp)
            pts[-1], vals[-1] = (exp, fe) if fe < fr else (refl, fr)
        elif fr < vals[-2]:
            pts[-1], vals[-1] = refl, fr
        else:
            con = centroid + 0.5 * (pts[-1] - centroid)
            fc = fun(con)
            if fc < vals[-1]:
                pts[-1], vals[-1] = con, fc
            else:
                for i in range(1, n + 1):
                    pts[i] = pts[0] + 0.5 * (pts[i] - pts[0])
                    vals[i] = fun(pts[i])
    return pts[int(np.argmin(vals))]


def fit_fe(model, data):
    """Least-squares fit of solref (direct stiffness, critical damping) and all five solimp
    numbers to the FE curve: minimises the sum of squared relative force errors at
    x = 0.05, 0.10, ... 0.60 of the static (steady-state) force. Parameters are mapped so that
    any real vector is a valid set (d0, dmax in (0, 1), midpoint in (0, 1), power >= 1)."""
    grid = np.round(np.arange(0.05, 0.6001, 0.05), 10)
    f_fe = fe_force(grid)

    def unpack(p):
        sig = lambda v: 1.0 / (1.0 + np.exp(-v))  # noqa: E731 (a one-line map)
        k = np.exp(p[0])
        d0 = 0.0001 + 0.9998 * sig(p[1])
        dmax = 0.0001 + 0.9998 * sig(p[2])
        width = np.exp(p[3])
        mid = sig(p[4])
        power = 1.0 + np.exp(p[5])
        return [-k, -2.0 * np.sqrt(k)], [d0, dmax, width, mid, power]

    def cost(p):
        solref, solimp = unpack(p)
        set_contact(model, solref, solimp)
        rel = static_forces(model, data, grid) / f_fe - 1.0
        return float(np.sum(rel**2))

    # Start from the Hertz-matched stiffness and MuJoCo's default solimp shape.
    start_ref = match_hertz(model, data, [0.9, 0.95, 0.001, 0.5, 2.0])
    logit = lambda v: np.log(v / (1.0 - v))  # noqa: E731
    p0 = [np.log(-start_ref[0]), logit(0.9), logit(0.95), np.log(0.006), 0.0, np.log(1.0)]
    best = nelder_mead(cost, p0, [1.0, 1.0, 1.0, 1.0, 1.0, 1.0])
    best = nelder_mead(cost, best, [0.3, 0.3, 0.3, 0.3, 0.3, 0.3])
    return unpack(best)


def rigid_squeeze(solref, solimp, dt=0.002, speed=0.01):
    """The dynamic squeeze: the mocap plate moves down at `speed` [m/s] from x = 0.02 to
    X_END per contact; each step's sample is (mean penetration / R, mean normal force)."""
    model = mujoco.MjModel.from_xml_string(rigid_xml(dt))
    set_contact(model, solref, solimp)
    data = mujoco.MjData(model)
    x0 = 0.02
    data.qpos[0] = -x0 * R
    data.mocap_pos[0] = [0.0, 0.0, 2 * R - 2 * x0 * R + PLATE_HALF]
    mujoco.mj_forward(model, data)
    timer = StepTimer()
    xs, fs = [], []
    while True:
        z = data.mocap_pos[0][2] - speed * dt
        if (2 * R - (z - PLATE_HALF)) / (2 * R) > X_END:
            break
        data.mocap_pos[0][2] = z
        timer.time(mujoco.mj_step, model, data)
        pen, force = mean_contact(model, data)
        xs.append(pen / R)
        fs.append(force)
    return xs, fs, timer


DT_CANDIDATES = (0.002, 0.001, 0.0005, 0.0002, 0.0001)  # s; 2 ms is MuJoCo's default


def resolved_squeeze(solref, solimp):
    """The squeeze at the largest step of DT_CANDIDATES whose run reproduces MuJoCo's own
    steady-state force (one mj_forward at rest) within 1 % at x = 0.1, 0.3, 0.5: a soft
    contact stiffer than its step can hold gives a different (time-step-limited) force, and
    that is not the contact that was set. Returns (xs, Fs, timer, dt, what was tried)."""
    model = mujoco.MjModel.from_xml_string(rigid_xml(0.001))
    set_contact(model, solref, solimp)
    data = mujoco.MjData(model)
    probe = np.array([0.1, 0.3, 0.5])
    want = static_forces(model, data, probe)
    tried = []
    for dt in DT_CANDIDATES:
        xs, fs, timer = rigid_squeeze(solref, solimp, dt=dt)
        xa, fa = np.array(xs), np.array(fs)
        got = np.array([fa[np.argmin(np.abs(xa - p))] if xa.size and xa.max() >= p else np.nan
                        for p in probe])
        worst = float(np.nanmax(np.abs(got / want - 1.0))) if np.isfinite(got).any() else np.inf
        if not np.isfinite(got).all():
            worst = np.inf
        tried.append(f"dt {dt * 1e3:g} ms: {worst * 100:.1f} % off its steady state")
        if worst <= 0.01:
            return xs, fs, timer, dt, tried
    return xs, fs, timer, dt, tried


def rigid_rows():
    """The two rigid-sphere rows: solref/solimp matched to Hertz at X_MATCH (MuJoCo's default
    solimp), and the least-squares fit to FE."""
    model = mujoco.MjModel.from_xml_string(rigid_xml(0.001))
    data = mujoco.MjData(model)
    rows = []
    default_imp = [0.9, 0.95, 0.001, 0.5, 2.0]
    ref = match_hertz(model, data, default_imp)
    t0 = time.perf_counter()
    fit_ref, fit_imp = fit_fe(model, data)
    fit_s = time.perf_counter() - t0
    for name, solref, solimp, how in [
        ("rigid sphere, soft contact matched to Hertz at x = 0.05", ref, default_imp,
         "solref = (-k, -2 sqrt k) with k bisected so that the steady-state force at x = 0.05 "
         "is Hertz's; solimp = MuJoCo's default (0.9, 0.95, 0.001, 0.5, 2)"),
        ("rigid sphere, soft contact fitted to FE (least squares)", fit_ref, fit_imp,
         f"solref and all of solimp fitted (Nelder-Mead on the steady-state force, {fit_s:.0f} s) "
         "to the FE force at x = 0.05, 0.10, ... 0.60"),
    ]:
        xs, fs, timer, dt, tried = resolved_squeeze(solref, solimp)
        rows.append({
            "peer": "MuJoCo",
            "variant": name,
            "dt": dt,
            "steps": timer.steps,
            "us_per_step": timer.us_per_step(),
            "x": xs,
            "force": fs,
            "note": how + "; solref = (%.4g, %.4g), solimp = (%s); mocap plate at 10 mm/s; "
                    "step = the largest that reproduces the steady state (%s)" % (
                        solref[0], solref[1], ", ".join("%.4g" % v for v in solimp),
                        "; ".join(tried)),
        })
    return rows, {"matched": (ref, default_imp), "fitted": (fit_ref, fit_imp)}


# --------------------------------------------------------------------------------------------
# Flex FEM sphere
# --------------------------------------------------------------------------------------------

FLEX_VERTEX_RADIUS = 1.0e-4  # m: the flex vertices' collision radius (1 % of R)


def flex_xml(count, dt):
    """A volumetric flex sphere (flexcomp type="ellipsoid", dim = 3, `count` vertices along
    each axis before the projection onto the sphere) with MuJoCo's built-in linear elasticity
    (young, poisson), between the floor and a mocap plate. Stiff contacts (solref at the
    minimum 2 dt, solimp d -> 0.9999) on all geoms and the flex, so that the vertices do not
    sink into the plates (MuJoCo mixes the geoms' and the flex's contact parameters)."""
    h = 2 * R / (count - 1)
    rv = FLEX_VERTEX_RADIUS
    contact = f'solref="{2 * dt} 1" solimp="0.99 0.9999 0.0001 0.5 2"'
    return f"""<mujoco model="flex squeeze">
  <option timestep="{dt}" gravity="0 0 0" integrator="discrete"/>
  <worldbody>
    <geom name="floor" type="plane" size="0.1 0.1 0.01" condim="1" {contact}/>
    <body name="plate" mocap="true" pos="0 0 {2 * R + 2 * rv + PLATE_HALF}">
      <geom name="plate" type="box" size="0.05 0.05 {PLATE_HALF}" condim="1" {contact}/>
    </body>
    <flexcomp name="ball" type="ellipsoid" count="{count} {count} {count}"
              spacing="{h} {h} {h}" pos="0 0 {R + rv}" dim="3" radius="{rv}" mass="{MASS}">
      <edge equality="false"/>
      <elasticity young="3e6" poisson="0.49" damping="0.0002"/>
      <contact condim="1" {contact} selfcollide="none"/>
    </flexcomp>
  </worldbody>
</mujoco>"""


def flex_squeeze(count, dt=0.001, speed=0.02, budget_s=120.0):
    """The flex sphere squeezed by the mocap plate at `speed` to X_END. x is the sphere's own
    compression, (2R - vertex extent in z) / 2R (the vertices also sink into the plates by
    their contact softness, which is not compression); F is the mean of the plate's and the
    floor's summed contact forces. Stops early (and says so) past `budget_s` of wall time."""
    model = mujoco.MjModel.from_xml_string(flex_xml(count, dt))
    data = mujoco.MjData(model)
    plate = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "plate")
    floor = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "floor")
    f6 = np.zeros(6)
    timer = StepTimer()
    xs, fs = [], []
    stopped = None
    while True:
        z = data.mocap_pos[0][2] - speed * dt
        if (2 * R + 2 * FLEX_VERTEX_RADIUS - (z - PLATE_HALF)) / (2 * R) > X_END + 0.05:
            break
        if timer.wall > budget_s:
            stopped = f"stopped by the {budget_s:.0f} s budget"
            break
        data.mocap_pos[0][2] = z
        timer.time(mujoco.mj_step, model, data)
        if not np.all(np.isfinite(data.qpos)):
            stopped = "diverged (non-finite state)"
            break
        zs = data.flexvert_xpos[:, 2]
        x = (2 * R - (zs.max() - zs.min())) / (2 * R)
        on_plate = on_floor = 0.0
        for i in range(data.ncon):
            g = data.contact[i].geom
            mujoco.mj_contactForce(model, data, i, f6)
            if plate in g:
                on_plate += f6[0]
            elif floor in g:
                on_floor += f6[0]
        xs.append(x)
        fs.append(0.5 * (on_plate + on_floor))
        if x > X_END:
            break
    note = (f"flexcomp ellipsoid dim=3, count {count}^3 -> {model.nflexvert} vertices, "
            f"{model.nflexelem} tetrahedra; elasticity young = 3e6, poisson = 0.49; "
            f"integrator discrete (MuJoCo 4 integrates flex elasticity implicitly only there), "
            f"dt = {dt}; plate {speed * 1e3:.0f} mm/s")
    if stopped:
        note += "; " + stopped
    return {
        "peer": "MuJoCo",
        "variant": f"flex FEM sphere, {model.nflexelem} tets",
        "dt": dt,
        "steps": timer.steps,
        "us_per_step": timer.us_per_step(),
        "x": xs,
        "force": fs,
        "note": note,
    }


# --------------------------------------------------------------------------------------------
# N spheres resting on a plane
# --------------------------------------------------------------------------------------------


def resting(n, solref=(0.02, 1.0), solimp=(0.9, 0.95, 0.001, 0.5, 2.0), dt=0.002, settle=120,
            sleep=False):
    """N rigid spheres (R, fingertip mass, free joints) on a 30 mm grid resting on a plane;
    µs per step after `settle` steps. The defaults are MuJoCo's own (contact solref, solimp
    and the 2 ms step): the Hertz-matched contact of the squeeze is not resolved at 2 ms or
    1/60 s (the spheres bounce; measured before choosing this). With `sleep`, MuJoCo's
    sleeping is enabled (`<flag sleep="enable"/>`, its default `sleep_tolerance`): the
    resting spheres' trees fall asleep. Returns (µs/step, steps timed per round, largest
    sphere speed at the end [m/s], settle steps, trees awake at the end, the median of the
    timed steps [µs])."""
    side = int(np.ceil(np.sqrt(n)))
    bodies = []
    for i in range(n):
        row, col = divmod(i, side)
        x = (col - 0.5 * (side - 1)) * 0.03
        y = (row - 0.5 * (side - 1)) * 0.03
        bodies.append(f'<body pos="{x} {y} {R}"><freejoint/>'
                      f'<geom type="sphere" size="{R}" mass="{MASS}"/></body>')
    ref = " ".join(str(v) for v in solref)
    imp = " ".join(str(v) for v in solimp)
    flag = '<flag sleep="enable"/>' if sleep else ""
    xml = f"""<mujoco><option timestep="{dt}">{flag}</option>
  <default><geom solref="{ref}" solimp="{imp}"/></default>
  <worldbody><geom type="plane" size="{side * 0.03 + 0.1} {side * 0.03 + 0.1} 0.01"/>
  {''.join(bodies)}</worldbody></mujoco>"""
    model = mujoco.MjModel.from_xml_string(xml)
    data = mujoco.MjData(model)
    for _ in range(settle):
        mujoco.mj_step(model, data)
    steps = int(np.clip(20000 // n, 60, 2000))
    best = np.inf
    samples = []
    for _ in range(3):
        timer = StepTimer()
        for _ in range(steps):
            timer.time(mujoco.mj_step, model, data)
        best = min(best, timer.us_per_step())
        samples += timer.samples
    speed = float(np.max(np.abs(data.qvel))) if model.nv else 0.0
    median = 1e6 * float(np.median(samples))
    return best, steps, speed, settle, int(data.ntree_awake), median


# --------------------------------------------------------------------------------------------
# The default grasp
# --------------------------------------------------------------------------------------------


JAW_MASS = 10.0  # kg: each jaw and the lift stage (gravity-compensated), stiffly driven


def grasp_xml(density, dt, solref, solimp):
    """softgrip's default scene in MJCF (z up): a table plane (friction 0.5), a 4 cm box
    (friction 0.5, `density`) on it, and a gripper: a lift stage (vertical slide joint)
    carrying two jaws (horizontal slide joints) 34 mm from the box's centre, each with a
    rigid R = 10 mm sphere (friction 0.8, the fingertip's solref/solimp: `priority` makes the
    fingertip's parameters the contact's). The joints are driven by position actuators
    (kp = 0.25 m / dt^2, critically damped, gravity compensated): MuJoCo's friction acts on
    velocities, so the jaws must be bodies that move (a mocap body teleports and drags
    nothing)."""
    kp = 0.25 * JAW_MASS / dt**2
    kv = 2.0 * np.sqrt(kp * JAW_MASS)
    imp = " ".join(map(str, solimp))
    tip = (f'type="sphere" size="{R}" friction="0.8 0.005 0.0001" priority="1" '
           f'solref="{solref[0]} {solref[1]}" solimp="{imp}"')
    return f"""<mujoco model="grasp">
  <option timestep="{dt}" gravity="0 0 -9.81" integrator="implicitfast"/>
  <worldbody>
    <geom name="table" type="plane" size="0.5 0.5 0.01" friction="0.5 0.005 0.0001"/>
    <body name="box" pos="0 0 0.02"><freejoint/>
      <geom name="box" type="box" size="0.02 0.02 0.02" density="{density}"
            friction="0.5 0.005 0.0001"/>
    </body>
    <body name="stage" pos="0 0 0.02" gravcomp="1">
      <joint name="lift" type="slide" axis="0 0 1"/>
      <geom type="sphere" size="0.005" mass="{JAW_MASS}" contype="0" conaffinity="0"/>
      <body name="left" pos="-0.034 0 0" gravcomp="1">
        <joint name="left" type="slide" axis="1 0 0"/>
        <geom name="left_tip" {tip} mass="{JAW_MASS}"/>
      </body>
      <body name="right" pos="0.034 0 0" gravcomp="1">
        <joint name="right" type="slide" axis="-1 0 0"/>
        <geom name="right_tip" {tip} mass="{JAW_MASS}"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position joint="lift" kp="{kp}" kv="{kv}"/>
    <position joint="left" kp="{kp}" kv="{kv}"/>
    <position joint="right" kp="{kp}" kv="{kv}"/>
  </actuator>
</mujoco>"""


def grasp_trial(depth, density, dt, solref, solimp, stop_after_settle=False):
    """One grasp trial, softgrip's gripper program on the jaws' position targets: approach
    at 10 mm/s until a fingertip touches the box; close to the touch point + `depth` at
    5 mm/s; settle 0.2 s; lift 10 cm at 0.1 m/s; hold 2 s; open 1 cm at 0.02 m/s; 5 s in all.
    `held` as softgrip's sweeps: at the end of the hold both fingertips touch the box and it
    rose >= half the lift. Returns (held, grip force at the end of the settle [N], steps)."""
    model = mujoco.MjModel.from_xml_string(grasp_xml(density, dt, solref, solimp))
    data = mujoco.MjData(model)
    tips = [mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, n) for n in ("left_tip", "right_tip")]
    box = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "box")
    q_lift, q_left, q_right = (model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, n)]
                               for n in ("lift", "left", "right"))
    f6 = np.zeros(6)

    def touching():
        """Per jaw: (penetration into the box [m], normal force [N]) or None."""
        out = [None, None]
        for i in range(data.ncon):
            c = data.contact[i]
            for j, tip in enumerate(tips):
                if tip in c.geom and box in c.geom:
                    mujoco.mj_contactForce(model, data, i, f6)
                    out[j] = (-c.dist, f6[0])
        return out

    ctrl = data.ctrl  # targets: lift height, left and right closing distances [m]
    phase, t, held, grip = "approach", 0.0, None, None
    touch = [None, None]
    box_z0 = None
    phase_t = 0.0
    steps = int(round(5.0 / dt))
    for _ in range(steps):
        if phase == "approach":
            contact = touching()
            for j in range(2):
                if touch[j] is None and contact[j] is not None:
                    touch[j] = data.qpos[(q_left, q_right)[j]] - contact[j][0]
                if touch[j] is None:
                    ctrl[1 + j] += 0.01 * dt
            if all(v is not None for v in touch):
                phase = "squeeze"
        elif phase == "squeeze":
            done = 0
            for j in range(2):
                goal = touch[j] + depth
                ctrl[1 + j] = min(goal, ctrl[1 + j] + 0.005 * dt)
                done += ctrl[1 + j] >= goal
            if done == 2:
                phase, phase_t = "settle", t
        elif phase == "settle" and t - phase_t >= 0.2:
            contact = touching()
            grip = float(np.mean([c[1] if c else 0.0 for c in contact]))
            if stop_after_settle:
                return None, grip, steps
            phase, phase_t = "lift", t
            box_z0 = data.qpos[2]
        elif phase == "lift":
            ctrl[0] = min(0.1, ctrl[0] + 0.1 * dt)
            if ctrl[0] >= 0.1:
                phase, phase_t = "hold", t
        elif phase == "hold" and t - phase_t >= 2.0:
            contact = touching()
            held = all(c is not None for c in contact) and data.qpos[2] - box_z0 >= 0.05
            phase, phase_t = "release", t
        elif phase == "release":
            for j in range(2):
                ctrl[1 + j] = max(touch[j] + depth - 0.01, ctrl[1 + j] - 0.02 * dt)
        mujoco.mj_step(model, data)
        t += dt
    return bool(held), grip, steps


def grasp_match(depth, force, dt):
    """Direct stiffness k of the fingertip contact (solref = (-k, -2 sqrt k), MuJoCo's
    default solimp) such that the grip at the end of the settle, in the default scene (32 g
    box) squeezed `depth`, equals `force` (softgrip's law at that depth): bisection in log k
    on whole approach-squeeze-settle runs. MuJoCo's soft-contact force depends on the bodies'
    masses, so the other box densities of the sweep get other grips, as they would for a user
    who sets solref once."""
    solimp = [0.9, 0.95, 0.001, 0.5, 2.0]
    lo, hi = 1.0, 1e9
    for _ in range(40):
        k = np.sqrt(lo * hi)
        _, grip, _ = grasp_trial(depth, 500.0, dt, [-k, -2 * np.sqrt(k)], solimp, True)
        if (grip or 0.0) < force:
            lo = k
        else:
            hi = k
        if hi / lo < 1.001:
            break
    k = np.sqrt(lo * hi)
    _, grip, _ = grasp_trial(depth, 500.0, dt, [-k, -2 * np.sqrt(k)], solimp, True)
    return [-k, -2 * np.sqrt(k)], solimp, grip
