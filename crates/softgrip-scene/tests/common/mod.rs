//! What the grasp tests (and the `impulse_grasp` example, through `#[path]`) measure the same
//! way: how far a held object moves against the hand holding it.

/// The largest distance \[m\] of `path[from..]` from `path[from]`: with `from = 0` a grasp's
/// hold slip (the object's position relative to the hand's base at each hold step), with
/// `from = 1` its creep after the step the grasp stopped at. 0 if `path` has no point at
/// `from`.
#[allow(dead_code)] // each test binary uses its own part of this module
pub fn excursion(path: &[[f64; 3]], from: usize) -> f64 {
    let Some(start) = path.get(from) else {
        return 0.0;
    };
    path[from..]
        .iter()
        .map(|p| {
            (0..3)
                .map(|i| (p[i] - start[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}

/// The shipped robot scene `scenes/robots/{name}.toml` with each `(from, to)` of `edits`
/// replaced, parsed with the scene's folder as the base of its paths (its URDF's). Each `from`
/// must be in the text (a test of an edited scene breaks when the shipped scene moves on).
#[allow(dead_code)] // each test binary uses its own part of this module
pub fn shipped_robot_scene(
    name: &str,
    edits: &[(&str, &str)],
) -> Result<softgrip_scene::Scene, softgrip_scene::SceneError> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("../../scenes/robots/{name}.toml"));
    let mut text = std::fs::read_to_string(&path).expect("a shipped robot scene");
    for (from, to) in edits {
        assert!(text.contains(from), "`{from}` is not in {}", path.display());
        text = text.replace(from, to);
    }
    let dir = path.parent().expect("the scene's folder");
    softgrip_scene::Scene::parse(&text, &format!("{name}.toml"), dir)
}

/// `J^T F` of joint `j` of the scene's robot, written out here from the contacts and the links
/// (independently of `softgrip_scene::robot::joint_load`): the generalised force along the
/// joint's axis of the loads on the links beyond it (every pad's contact force and torsional
/// moment, and the links' weights), plus `multiplier` times that of each joint mimicking it
/// when `mimics` (the mimic's load reaches the driven joint's motor through the coupling)
/// \[N or N m\].
#[allow(dead_code)] // each test binary uses its own part of this module
pub fn jt_f(
    run: &softgrip_scene::PlainRun,
    robot: &softgrip_scene::robot::Robot,
    j: usize,
    mimics: bool,
) -> f64 {
    use softgrip_scene::robot::{JointKind, RobotJointHandle};
    let h = &run.handles.robots[0].1;
    let p = &run.world.physics;
    let joint = &robot.joints()[j];
    let RobotJointHandle::Multibody(mh) = h.joints[j] else {
        panic!("the shipped hands are multibodies")
    };
    let (mb, id) = p
        .multibody_joints
        .get(mh)
        .expect("the robot's multibody joint");
    let frame = *p.bodies[h.links[joint.parent]].position()
        * mb.link(id)
            .expect("the joint's link")
            .joint
            .data
            .local_frame1;
    let a = frame.rotation * softgrip_scene::softgrip_rapier::rapier3d::prelude::Vector::X;
    let (a, o) = (
        [a.x as f64, a.y as f64, a.z as f64],
        [
            frame.translation.x as f64,
            frame.translation.y as f64,
            frame.translation.z as f64,
        ],
    );
    let revolute = joint.kind != JointKind::Prismatic;
    let mut beyond = vec![false; robot.links().len()];
    beyond[joint.child] = true;
    for _ in 0..robot.joints().len() {
        for o in robot.joints() {
            beyond[o.child] |= beyond[o.parent];
        }
    }
    let dot = |u: [f64; 3], v: [f64; 3]| (0..3).map(|k| u[k] * v[k]).sum::<f64>();
    let cross = |u: [f64; 3], v: [f64; 3]| {
        [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ]
    };
    // A force `f` at `x` projected on the joint.
    let project = |x: [f64; 3], f: [f64; 3]| {
        if revolute {
            dot(cross([0, 1, 2].map(|k| x[k] - o[k]), f), a)
        } else {
            dot(f, a)
        }
    };
    let mut load = 0.0;
    for c in run.world.soft.contacts() {
        let body = (p.colliders[c.fingertip].parent()).expect("a pad on a body");
        let Some(link) = h.links.iter().position(|&l| l == body) else {
            continue;
        };
        if !beyond[link] {
            continue;
        }
        let r = &c.reading;
        let f = [0, 1, 2].map(|k| r.normal_force * r.normal[k] + r.friction_force[k]);
        load += project(r.point, f);
        if revolute {
            load += r.torsional_moment * dot(r.normal, a);
        }
    }
    let g = p.gravity;
    for (i, &l) in h.links.iter().enumerate() {
        if beyond[i] {
            let rb = &p.bodies[l];
            let w = g * (rb.mass() * rb.gravity_scale());
            let com = rb.center_of_mass();
            load += project(
                [com.x as f64, com.y as f64, com.z as f64],
                [w.x as f64, w.y as f64, w.z as f64],
            );
        }
    }
    for (m, o) in robot.joints().iter().enumerate() {
        if let Some(mimic) = o.mimic.filter(|mm| mm.joint == j && mimics) {
            load += mimic.multiplier * jt_f(run, robot, m, true);
        }
    }
    load
}

/// Runs `scene` to the last step of its grasp's hold: each moving joint of its first robot as
/// `(joint, state with the loaded effort, J^T F with its mimics, J^T F of its own links)`, and
/// the pads' normal forces \[N\].
#[allow(clippy::type_complexity, dead_code)]
pub fn to_the_end_of_the_hold(
    scene: &softgrip_scene::Scene,
) -> (
    Vec<(usize, softgrip_scene::robot::JointState, f64, f64)>,
    Vec<f64>,
) {
    let mut run = softgrip_scene::PlainRun::new(scene);
    let robot = scene.robots()[0].clone();
    let h = run.handles.robots[0].1.clone();
    let dt = scene.file().dt;
    let mut last = None;
    for _ in 0..scene.steps() {
        run.step();
        if run.control.controllers()[0].phase() == Some(softgrip_scene::control::Phase::Hold) {
            let rows: Vec<_> = (0..robot.joints().len())
                .filter(|&j| robot.joints()[j].kind.moves())
                .map(|j| {
                    let s =
                        softgrip_scene::robot::joint_state_loaded(&robot, &run.world, &h, j, dt);
                    (
                        j,
                        s,
                        jt_f(&run, &robot, j, true),
                        jt_f(&run, &robot, j, false),
                    )
                })
                .collect();
            let pads = run
                .world
                .soft
                .contacts()
                .iter()
                .map(|c| c.normal_force)
                .collect();
            last = Some((rows, pads));
        }
    }
    last.expect("the grasp held")
}

/// The effort against `J^T F` of every moving joint of `scene`'s first robot at the last step
/// of its grasp's hold: `(joint, effort, J^T F, |effort + J^T F| / |J^T F|)`, the mimic joints
/// against the load their coupling carries; and each mimic joint's effort against its share of
/// the driven joint's motor, `(tau_motor + J^T F_own) / multiplier`: `(joint, effort, share,
/// relative difference)`.
#[allow(clippy::type_complexity, dead_code)]
pub fn hold_efforts(
    scene: &softgrip_scene::Scene,
) -> (Vec<(String, f64, f64, f64)>, Vec<(String, f64, f64, f64)>) {
    let robot = &scene.robots()[0];
    let (states, _) = to_the_end_of_the_hold(scene);
    let rows: Vec<_> = states
        .iter()
        .map(|(j, st, load, own)| (*j, st.effort, *load, *own))
        .collect();
    let name = |j: usize| robot.joints()[j].name.clone();
    let loads = rows
        .iter()
        .map(|&(j, e, load, _)| (name(j), e, load, (e + load).abs() / load.abs()))
        .collect();
    let shares = rows
        .iter()
        .filter_map(|&(j, e, _, _)| {
            let mimic = robot.joints()[j].mimic?;
            let &(_, lead, _, own) = rows.iter().find(|r| r.0 == mimic.joint)?;
            let share = (lead + own) / mimic.multiplier;
            Some((name(j), e, share, (e - share).abs() / share.abs()))
        })
        .collect();
    (loads, shares)
}

/// The pybullet_data folder of PyPI's `pybullet` (`SOFTGRIP_PYBULLET_DATA`, with
/// `franka_panda/` and `xarm/`; `bash .ci/pybullet-data.sh` fetches them and prints the path).
#[allow(dead_code)] // each test binary uses its own part of this module
pub fn pybullet_data() -> std::path::PathBuf {
    let dir = std::env::var("SOFTGRIP_PYBULLET_DATA").unwrap_or_else(|_| {
        panic!(
            "SOFTGRIP_PYBULLET_DATA is not set: it must name pybullet's pybullet_data folder \
             with franka_panda/ and xarm/; `bash .ci/pybullet-data.sh` fetches it and prints \
             the path"
        )
    });
    std::path::PathBuf::from(dir)
}
