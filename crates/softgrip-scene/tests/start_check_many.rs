//! The start check of a scene with many fingertips: it built the law of every fingertip pair
//! before looking for a contact (O(N^2) laws: 1000 fingertips took ~11 s to load). Now a BVH of
//! the colliders' boxes gives each fingertip its candidates; these tests hold that the check
//! still finds a deep start against an unbounded shape (a plane), a box, and another fingertip
//! anywhere in a large grid, and that the error is the one a check of every pair in file order
//! finds first.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::fmt::Write as _;
use std::path::Path;

use softgrip_scene::{Scene, SceneError};

const R: f64 = 0.01;
const PITCH: f64 = 0.03;
const SIDE: usize = 20;

/// `SIDE * SIDE` free fingertips on a grid, each touching the ground (a plane, or a box if
/// `boxed`) 0.1 mm deep, with fingertip `deep` (if any) `depth` into it, and a small box `crate`
/// over fingertip `buried`'s place (if any) that the fingertip starts 8.9 mm inside.
fn grid(boxed: bool, deep: Option<(usize, f64)>, buried: Option<usize>) -> String {
    let mut s = String::from("duration = 0.1\n[[body]]\nname = \"ground\"\nkind = \"fixed\"\n");
    if boxed {
        let half = SIDE as f64 * PITCH;
        writeln!(
            s,
            "position = [0.0, -0.5, 0.0]\n[[body.shape]]\ntype = \"cuboid\"\nhalf_extents = [{half}, 0.5, {half}]"
        )
        .unwrap();
    } else {
        s.push_str("[[body.shape]]\ntype = \"plane\"\nnormal = [0.0, 1.0, 0.0]\n");
    }
    let at = |i: usize| ((i % SIDE) as f64 * PITCH, (i / SIDE) as f64 * PITCH);
    if let Some(b) = buried {
        let (x, z) = at(b);
        // The box's bottom face is 8.9 mm below the ball's top (x = 0.89 > fit's 0.81).
        writeln!(
            s,
            "[[body]]\nname = \"crate\"\nkind = \"fixed\"\nposition = [{x}, {}, {z}]\n[[body.shape]]\ntype = \"cuboid\"\nhalf_extents = [0.005, 0.005, 0.005]",
            2.0 * R - 0.009 + 0.005
        )
        .unwrap();
    }
    for i in 0..SIDE * SIDE {
        let (x, z) = at(i);
        let d = match deep {
            Some((k, depth)) if k == i => depth,
            _ => 1e-4,
        };
        writeln!(
            s,
            "[[body]]\nname = \"b{i}\"\nkind = \"dynamic\"\nposition = [{x}, {}, {z}]\n\
             [[fingertip]]\nname = \"t{i}\"\nbody = \"b{i}\"\nradius = {R}\npreset = \"dragon-skin-30\"\nlevel = \"fit\"",
            R - d
        )
        .unwrap();
    }
    s
}

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, "grid.toml", Path::new("."))
}

/// (fingertip, other) of a start penetration.
fn pair(err: SceneError) -> (String, String) {
    match err {
        SceneError::StartPenetration {
            fingertip, other, ..
        } => (fingertip, other),
        e => panic!("expected a start penetration, got {e}"),
    }
}

#[test]
fn four_hundred_resting_fingertips_start_fine_on_a_plane_and_a_box() {
    for boxed in [false, true] {
        let scene = parse(&grid(boxed, None, None)).unwrap();
        assert_eq!(scene.fingertips().len(), SIDE * SIDE);
    }
}

#[test]
fn one_deep_fingertip_among_four_hundred_is_found_on_a_plane_and_a_box() {
    // 9 mm into the ground: x = 0.9, past fit's x_max = 0.81.
    for boxed in [false, true] {
        let (tip, other) = pair(parse(&grid(boxed, Some((257, 0.009)), None)).unwrap_err());
        assert_eq!(tip, "fingertip[257] (`t257`)");
        assert_eq!(other, "body[0].shape[0] (`ground`)");
    }
}

#[test]
fn a_fingertip_buried_in_a_small_box_in_the_grid_is_found() {
    let (tip, other) = pair(parse(&grid(false, None, Some(123))).unwrap_err());
    assert_eq!(tip, "fingertip[123] (`t123`)");
    assert_eq!(other, "body[1].shape[0] (`crate`)");
}

#[test]
fn the_first_error_in_file_order_is_reported() {
    // Two deep fingertips: the lower index is named (as a check of every pair in order finds
    // first), whatever the BVH's order of candidates.
    let text = grid(false, Some((311, 0.009)), Some(42));
    let (tip, other) = pair(parse(&text).unwrap_err());
    assert_eq!(tip, "fingertip[42] (`t42`)");
    assert_eq!(other, "body[1].shape[0] (`crate`)");
}

#[test]
fn two_overlapping_fingertips_in_a_large_grid_are_one_pair_named_once() {
    // Move fingertip 200 to 9 mm beside fingertip 201: the two free balls overlap by 11 mm,
    // x = 2.2 over their combined radius R/2 = 5 mm, far past the combined law's range.
    let mut text = grid(false, None, None);
    let (x200, z200) = ((200 % SIDE) as f64 * PITCH, (200 / SIDE) as f64 * PITCH);
    let (x201, _) = ((201 % SIDE) as f64 * PITCH, 0.0);
    let from = format!("position = [{x200}, {}, {z200}]", R - 1e-4);
    let to = format!("position = [{}, {}, {z200}]", x201 - 0.009, R - 1e-4);
    assert!(text.contains(&from));
    text = text.replacen(&from, &to, 1);
    let (tip, other) = pair(parse(&text).unwrap_err());
    assert_eq!(tip, "fingertip[200] (`t200`)");
    assert_eq!(other, "fingertip[201] (`t201`)");
}
