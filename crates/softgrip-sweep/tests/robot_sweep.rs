//! Sweeps address robots and controllers (issue 25, item 7) with the same field paths as every
//! other scene value: `controller[0].speed` (the grasp's closing speed) and
//! `robot[0].initial.finger_joint` (a start joint position) on the shipped gripper scene. A
//! trial's row equals a direct run of the scene edited by hand, and the two speeds give two
//! different runs.

use std::path::Path;

use softgrip_sweep::{Outcome, Sweep, run_scene};

#[test]
fn robot_and_controller_fields_are_swept_like_any_other() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/robots");
    let text = "scene = \"parallel_gripper_box.toml\"\nobject = \"box\"\n\
        [[vary]]\nfield = \"controller[0].speed\"\nvalues = [0.02, 0.01]\n\
        [[vary]]\nfield = \"robot[0].initial.finger_joint\"\nvalues = [0.03]\n";
    let s = Sweep::from_str(text, &dir).expect("the sweep loads");
    let first = s.run_trial(0).expect("in range");
    let second = s.run_trial(1).expect("in range");
    let scene_text = std::fs::read_to_string(dir.join("parallel_gripper_box.toml")).unwrap();
    let edited = scene_text
        .replace("speed = 0.01 ", "speed = 0.02 ")
        .replace("finger_joint = 0.028 }", "finger_joint = 0.03 }");
    assert_ne!(edited, scene_text);
    let scene = softgrip_ecs::Scene::parse(&edited, "hand-edited", &dir).expect("valid");
    let direct: Outcome = run_scene(&scene, &edited, "box", None).expect("runs");
    assert_eq!(first.outcome, Ok(direct));
    assert_ne!(first.outcome, second.outcome);
}
