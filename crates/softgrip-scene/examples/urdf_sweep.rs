//! Loads each URDF named on the command line through the scene loader (a generated scene per
//! URDF: the robot at the origin, base fixed, gravity on, `joints` = the first argument
//! `multibody` or `impulse`) and runs 50 steps; prints one tab-separated line per URDF:
//! `<file> <ok|error|nan|panic> <links> <joints> <colliders> <detail>` (for `ok`, the
//! largest link speed at the end). A local survey of
//! third-party models (`.ci/urdf-sweep.sh` runs it over pybullet_data), not a test.
//!
//! `cargo run -p softgrip-scene --example urdf_sweep -- multibody a.urdf b.urdf ...`

use std::path::Path;

use softgrip_scene::{PlainRun, Scene};

fn main() {
    let mut args = std::env::args().skip(1);
    let model = args.next().unwrap_or_else(|| "multibody".into());
    for file in args {
        let line = match std::panic::catch_unwind(|| one(Path::new(&file), &model)) {
            Ok(line) => line,
            Err(p) => {
                let what = (p.downcast_ref::<String>().cloned())
                    .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_default();
                format!("panic\t-\t-\t-\t{what}")
            }
        };
        println!("{file}\t{}", line.replace('\n', " "));
    }
}

/// `package://<name>/<rest>` guessed as `<name>` in the URDF's folder or one of its two
/// parents, or that folder itself: the first where `<rest>` exists (as a TOML inline table's entries).
fn packages(urdf: &Path) -> String {
    let text = std::fs::read_to_string(urdf).unwrap_or_default();
    let mut out = std::collections::BTreeMap::new();
    for piece in text.split("package://").skip(1) {
        let end = piece.find(['"', '\'', '<', ' ']).unwrap_or(piece.len());
        let Some((name, rest)) = piece[..end].split_once('/') else {
            continue;
        };
        let found = (urdf.ancestors().skip(1).take(3))
            .flat_map(|d| [d.join(name), d.to_path_buf()])
            .find(|d| d.join(rest).exists());
        if let Some(dir) = found {
            out.entry(name.to_string())
                .or_insert_with(|| dir.display().to_string());
        }
    }
    (out.iter())
        .map(|(k, v)| format!("\"{k}\" = {v:?}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The outcome of loading and running `urdf`.
fn one(urdf: &Path, model: &str) -> String {
    let Ok(urdf) = urdf.canonicalize() else {
        return "error\t-\t-\t-\tno such file".into();
    };
    let dir = std::env::temp_dir().join(format!("urdf_sweep_{}", std::process::id()));
    std::fs::create_dir_all(&dir).ok();
    let scene = format!(
        "duration = 1.0\ngravity = [0.0, 0.0, -9.81]\n[[robot]]\nname = \"r\"\nurdf = {:?}\n\
         base = \"fixed\"\njoints = \"{model}\"\nself_contacts = {}\npackage_paths = {{ {} }}\n",
        urdf.display().to_string(),
        model == "impulse",
        packages(&urdf)
    );
    let path = dir.join("scene.toml");
    if let Err(e) = std::fs::write(&path, scene) {
        return format!("error\t-\t-\t-\tcannot write the scene: {e}");
    }
    let scene = match Scene::from_file(&path) {
        Ok(s) => s,
        Err(e) => return format!("error\t-\t-\t-\t{e}"),
    };
    let r = &scene.robots()[0];
    let (links, joints) = (r.links().len(), r.joints().len());
    let mut run = PlainRun::new(&scene);
    let steps = std::env::var("SWEEP_STEPS")
        .ok()
        .and_then(|s| s.parse().ok());
    run.run(steps.unwrap_or(50), |_| {});
    let h = &run.handles.robots[0].1;
    let colliders: usize = h.colliders.iter().map(Vec::len).sum();
    let bad = (h.links.iter()).position(|b| {
        let p = run.world.physics.bodies[*b].translation();
        !(p.x.is_finite() && p.y.is_finite() && p.z.is_finite())
    });
    // The largest link speed tells a blow-up that stays finite (a fixed base with gravity on
    // lets unactuated joints swing: a few m/s is a fall, not a blow-up).
    let speed = (h.links.iter())
        .map(|b| run.world.physics.bodies[*b].linvel().length())
        .fold(0.0_f32, f32::max);
    match bad {
        Some(i) => format!(
            "nan\t{links}\t{joints}\t{colliders}\tlink `{}` is not finite",
            r.links()[i].name
        ),
        None => format!("ok\t{links}\t{joints}\t{colliders}\tlargest link speed {speed:.3} m/s"),
    }
}
