//! The skin-on-core files on a counterpart (`tests/data/fe/{ball,cylinder,edge}/core/`,
//! `CORE_COUNTERPART_FILES`): keyed by counterpart, construction, nu and t/R, and at small x
//! the layer's Hertz on a ball.

use softgrip_fe::{CORE_COUNTERPART_FILES, Counterpart, Schema};

#[test]
fn core_files_on_a_counterpart_are_keyed_by_thickness() {
    //! Every file carries its folder's counterpart and construction, its name's t/R and k (an
    //! edge has no k), and `force_file` finds each force curve by that key (and not without
    //! the t/R). The ball's files are axisymmetric (`Force`), the cylinder's and the edge's
    //! from the 3D quarter model (`Force3d`, session 18).
    assert!(!CORE_COUNTERPART_FILES.is_empty());
    for f in CORE_COUNTERPART_FILES {
        assert_eq!(f.geometry, "core", "{}", f.path);
        let t = f.thickness_ratio.expect("a core file has t/R");
        let (folder, key, force) = match f.counterpart {
            Counterpart::Ball { k } => ("ball/core/", format!("_t{t}_k{k}"), Schema::Force),
            Counterpart::Cylinder { k } => {
                ("cylinder/core/", format!("_t{t}_k{k}"), Schema::Force3d)
            }
            Counterpart::Edge => ("edge/core/", format!("_t{t}."), Schema::Force3d),
            Counterpart::Plane => panic!("{}: a plane core file is not a counterpart's", f.path),
        };
        assert!(f.path.starts_with(folder), "{}", f.path);
        let named = f.path.contains(&key) || f.path.contains(&format!("_t{t}_d"));
        assert!(named, "{}", f.path);
        assert!(softgrip_fe::file(f.path).is_some(), "{}", f.path);
        assert!(
            f.schema == force || f.path.contains("/pressure_"),
            "{}: {:?}",
            f.path,
            f.schema
        );
        if f.schema == force {
            let nu = f.nu.expect("one nu per file");
            let found = softgrip_fe::force_file(f.counterpart, "core", nu, Some(t));
            assert_eq!(found.map(|g| g.path), Some(f.path));
            assert!(softgrip_fe::force_file(f.counterpart, "core", nu, None).is_none());
        }
    }
}

#[test]
fn a_core_on_a_ball_is_the_layer_over_hertz_at_small_x() {
    //! At x = 0.01 the skin on a core pressed on a ball of k R carries more than Hertz with
    //! R_eff = R k / (1 + k), by the bonded layer's stiffening (on the plane 1.21x the free
    //! sphere at t/R 0.4, nu 0.48), and not by more than half (a ball read as a plane would be
    //! sqrt(2) = 1.41x Hertz on k = 1 before any layer term).
    for f in CORE_COUNTERPART_FILES
        .iter()
        .filter(|f| f.schema == Schema::Force)
    {
        let Counterpart::Ball { k } = f.counterpart else {
            continue;
        };
        let p = f.points().expect("parses")[0];
        assert_eq!(p.x, 0.01, "{}", f.path);
        let hertz = 4.0 / 3.0 * (k / (1.0 + k)).sqrt() * p.x.powf(1.5);
        let ratio = p.force_norm / hertz;
        assert!(
            (1.0..1.5).contains(&ratio),
            "{}: F / F_H(R_eff) = {ratio}",
            f.path
        );
    }
}
