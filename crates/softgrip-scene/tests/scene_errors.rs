//! Scene files: unknown fields and invalid values give typed errors naming the field (and the
//! line, for parse errors); mesh shapes load from OBJ and STL.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;

use softgrip_scene::{PlainRun, Scene, SceneError};

const BASE: &str = "duration = 1.0\n[[body]]\nname = \"table\"\nkind = \"fixed\"\n";

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::parse(text, "test.toml", Path::new("."))
}

#[test]
fn unknown_field_names_the_field_and_line() {
    let text = format!(
        "{BASE}[[body.shape]]\ntype = \"plane\"\nnormal = [0.0, 1.0, 0.0]\nfrction = 0.4\n"
    );
    let err = parse(&text).unwrap_err();
    let SceneError::Parse { line, message, .. } = &err else {
        panic!("expected a parse error, got {err}");
    };
    assert_eq!(*line, 8);
    assert!(message.contains("frction"), "{message}");
    assert!(err.to_string().starts_with("test.toml:8:"), "{err}");
}

#[test]
fn wrong_type_names_the_line() {
    let err = parse("duration = \"long\"\n").unwrap_err();
    assert!(matches!(err, SceneError::Parse { line: 1, .. }), "{err}");
}

#[test]
fn invalid_values_are_typed_errors_naming_the_field() {
    let cases = [
        ("duration = -1.0\n", "duration"),
        (
            &format!("{BASE}[[body.shape]]\ntype = \"cuboid\"\nhalf_extents = [0.1, 0.0, 0.1]\n"),
            "body[0].shape[0].half_extents[1]",
        ),
        (
            &format!("{BASE}[[body.shape]]\ntype = \"ball\"\n"),
            "body[0].shape[0].radius",
        ),
        (
            &format!(
                "{BASE}[[body.shape]]\ntype = \"ball\"\nradius = 0.1\nnormal = [0.0, 1.0, 0.0]\n"
            ),
            "body[0].shape[0].normal",
        ),
        (
            &format!(
                "{BASE}[[fingertip]]\nname = \"t\"\nbody = \"nope\"\nradius = 0.01\npreset = \"dragon-skin-30\"\n"
            ),
            "fingertip[0].body",
        ),
        (
            &format!(
                "{BASE}[[fingertip]]\nname = \"t\"\nbody = \"table\"\nradius = 0.01\npreset = \"rubber\"\n"
            ),
            "fingertip[0].preset",
        ),
        (
            &format!(
                "{BASE}[[fingertip]]\nname = \"t\"\nbody = \"table\"\nradius = -0.01\npreset = \"dragon-skin-30\"\n"
            ),
            "fingertip[0]",
        ),
    ];
    for (text, field) in cases {
        let err = parse(text).unwrap_err();
        assert_eq!(err.field(), Some(field), "{err}");
        assert!(err.to_string().contains(field), "{err}");
    }
    let err = parse("duration = 1.0\naccuracy = 3.0\n").unwrap_err();
    assert!(
        matches!(&err, SceneError::Invalid { field, .. } if field == "accuracy"),
        "{err}"
    );
}

#[test]
fn mesh_shapes_load_from_obj_and_stl() {
    let dir = std::env::temp_dir().join(format!("softgrip-scene-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // A tetrahedron as OBJ (convex hull) and a two-triangle floor as ASCII STL.
    std::fs::write(
        dir.join("tet.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("floor.stl"),
        "solid f\nfacet normal 0 1 0\nouter loop\nvertex -1 0 -1\nvertex -1 0 1\nvertex 1 0 1\nendloop\nendfacet\n\
         facet normal 0 1 0\nouter loop\nvertex -1 0 -1\nvertex 1 0 1\nvertex 1 0 -1\nendloop\nendfacet\nendsolid f\n",
    )
    .unwrap();
    let text = "duration = 0.5\n[[body]]\nname = \"floor\"\nkind = \"fixed\"\n[[body.shape]]\ntype = \"triangle_mesh\"\nfile = \"floor.stl\"\n\
                [[body]]\nname = \"tet\"\nkind = \"dynamic\"\nposition = [0.0, 0.2, 0.0]\n[[body.shape]]\ntype = \"convex_mesh\"\nfile = \"tet.obj\"\nscale = 0.05\n";
    let scene = Scene::parse(text, "mesh.toml", &dir).unwrap();
    assert_eq!(scene.shapes(0)[0].as_trimesh().unwrap().indices().len(), 2);
    assert!(scene.shapes(1)[0].as_convex_polyhedron().is_some());
    let mut run = PlainRun::new(&scene);
    run.run(scene.steps(), |_| {});
    let missing =
        Scene::parse(&text.replace("tet.obj", "none.obj"), "mesh.toml", &dir).unwrap_err();
    assert!(matches!(missing, SceneError::Mesh { .. }), "{missing}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `[fingertip.tactile]`: the default scene's pads, and a bad pad's error naming its key.
#[test]
fn tactile_pads_parse_and_bad_pads_name_their_key() {
    let scene = Scene::default_scene();
    for tip in scene.fingertips() {
        let grid = tip
            .tactile()
            .expect("the default scene's fingertips carry pads");
        assert_eq!((grid.rows(), grid.columns()), (16, 16));
        assert!((grid.taxel_area() - 1e-6).abs() < 1e-18);
    }
    let tip = "[[fingertip]]\nname = \"t\"\nbody = \"table\"\nradius = 0.01\npreset = \"dragon-skin-30\"\n";
    let pad = |extra: &str| {
        format!(
            "{BASE}{tip}[fingertip.tactile]\nrows = 8\ncolumns = 8\ndirection = [0.0, -1.0, 0.0]\n{extra}"
        )
    };
    let ok = parse(&pad("width = 0.01\nheight = 0.01\n")).unwrap();
    let grid = ok.fingertips()[0].tactile().unwrap();
    // Default `up`: +z (the direction is not near the z axis).
    assert_eq!(grid.pad().up, [0.0, 0.0, 1.0]);
    for (extra, field, needle) in [
        (
            "width = 0.04\nheight = 0.01\n",
            "fingertip[0].tactile.width",
            "got 0.04",
        ),
        (
            "width = nan\nheight = 0.01\n",
            "fingertip[0].tactile.width",
            "got NaN",
        ),
        (
            "width = 0.01\nheight = 0.0\n",
            "fingertip[0].tactile.height",
            "> 0 m",
        ),
        (
            "width = 0.01\nheight = 0.01\nup = [0.0, 2.0, 0.0]\n",
            "fingertip[0].tactile.up",
            "not parallel",
        ),
    ] {
        let err = parse(&pad(extra)).unwrap_err();
        assert_eq!(err.field(), Some(field), "{err}");
        assert!(err.to_string().contains(needle), "{err}");
    }
    let err = parse(&pad("width = 0.01\nheight = 0.01\nrow = 3\n")).unwrap_err();
    assert!(matches!(err, SceneError::Parse { .. }), "{err}");
}

/// A fingertip on `table` with the extra keys `extra` (issue 10: backing, core_thickness,
/// facing).
fn tip_with(extra: &str) -> String {
    format!(
        "{BASE}[[fingertip]]\nname = \"tip\"\nbody = \"table\"\nradius = 0.01\npreset = \"dragon-skin-30\"\n{extra}"
    )
}

#[test]
fn backing_keys_are_checked_naming_the_field() {
    let cases = [
        (
            "backing = \"glued\"\n",
            "fingertip[0].backing",
            "one of free, flat, core",
        ),
        (
            "backing = \"flat\"\n",
            "fingertip[0].facing",
            "needs `facing`",
        ),
        (
            "backing = \"flat\"\nfacing = [0.0, 0.0, 0.0]\n",
            "fingertip[0].facing",
            "non-zero",
        ),
        (
            "backing = \"core\"\nfacing = [1.0, 0.0, 0.0]\n",
            "fingertip[0].core_thickness",
            "required",
        ),
        (
            "backing = \"flat\"\ncore_thickness = 0.004\nfacing = [1.0, 0.0, 0.0]\n",
            "fingertip[0].core_thickness",
            "applies only",
        ),
        (
            "core_thickness = 0.004\n",
            "fingertip[0].core_thickness",
            "applies only",
        ),
        (
            "backing = \"core\"\ncore_thickness = 0.01\nfacing = [1.0, 0.0, 0.0]\n",
            "fingertip[0].core_thickness",
            "(0, radius)",
        ),
        (
            "backing = \"core\"\ncore_thickness = -0.001\nfacing = [1.0, 0.0, 0.0]\n",
            "fingertip[0].core_thickness",
            "(0, radius)",
        ),
    ];
    for (extra, field, message) in cases {
        let err = parse(&tip_with(extra)).unwrap_err();
        assert_eq!(err.field(), Some(field), "{extra}: {err}");
        assert!(err.to_string().contains(message), "{extra}: {err}");
    }
    let err = parse(&tip_with("facing = [1.0, 0.0]\n")).unwrap_err();
    assert!(err.to_string().contains("exactly 3"), "{err}");
}

#[test]
fn backing_keys_reach_the_fingertip() {
    use softgrip_scene::softgrip_rapier::softgrip_law::Backing;
    let scene = parse(&tip_with(
        "backing = \"core\"\ncore_thickness = 0.004\nfacing = [0.0, 0.0, -2.0]\n",
    ))
    .unwrap();
    let tip = &scene.fingertips()[0];
    assert_eq!(tip.backing(), Backing::Core { thickness: 0.004 });
    assert_eq!(tip.facing(), Some([0.0, 0.0, -1.0]));
    assert_eq!(tip.law().params().thickness_ratio(), Some(0.4));
    let free = parse(&tip_with("")).unwrap();
    assert_eq!(free.fingertips()[0].backing(), Backing::Free);
    // The default scene's pads are bonded to their jaws, facing the box.
    let default = Scene::parse(
        softgrip_scene::DEFAULT_SCENE,
        "default.toml",
        Path::new("."),
    )
    .unwrap();
    let facings: Vec<_> = default
        .fingertips()
        .iter()
        .map(|t| (t.backing(), t.facing()))
        .collect();
    assert_eq!(
        facings,
        [
            (Backing::Flat, Some([1.0, 0.0, 0.0])),
            (Backing::Flat, Some([-1.0, 0.0, 0.0]))
        ]
    );
}
