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
