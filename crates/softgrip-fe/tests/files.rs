//! Every embedded FE file parses into its typed rows, with the ranges its README states, and
//! every CSV file of `tests/data/fe/` is in the table.

use std::path::Path;

use softgrip_fe::{
    Counterpart, Force3dRow, ForceRow, FullRow, MeshConvergenceRow, PressureMapRow, PressureRow,
    Schema, SmallXRow,
};

#[test]
fn every_file_parses_into_its_rows_and_points() {
    for f in softgrip_fe::all() {
        let rows = match f.schema {
            Schema::Force => f.rows::<ForceRow>().map(|r| r.len()),
            Schema::Full => f.rows::<FullRow>().map(|r| r.len()),
            Schema::SmallX => f.rows::<SmallXRow>().map(|r| r.len()),
            Schema::MeshConvergence => f.rows::<MeshConvergenceRow>().map(|r| r.len()),
            Schema::Force3d => f.rows::<Force3dRow>().map(|r| r.len()),
            Schema::Pressure => f.rows::<PressureRow>().map(|r| r.len()),
            Schema::PressureMap => f.rows::<PressureMapRow>().map(|r| r.len()),
        }
        .unwrap_or_else(|e| panic!("{e}"));
        let points = f.points().unwrap_or_else(|e| panic!("{e}"));
        let curve = !matches!(f.schema, Schema::Pressure | Schema::PressureMap);
        assert_eq!(points.len(), if curve { rows } else { 0 }, "{}", f.path);
        // The thinnest, most incompressible core skin stops earliest (t/R = 0.2, nu = 0.499:
        // x = 0.04, 4 rows).
        assert!(rows >= 4, "{}: {rows} rows", f.path);
        for p in &points {
            assert!(p.x > 0.0 && p.x < 1.0, "{}: x = {}", f.path, p.x);
            assert!(p.force_norm > 0.0 && p.force_norm.is_finite(), "{}", f.path);
            // An edge's semi-axes are NaN where its 3D post-processing finds no patch edge
            // (across the ridge at x <= 0.03, narrower than a node spacing; along it always).
            let edge = matches!(f.counterpart, Counterpart::Edge);
            assert!(
                (p.radius_norm > 0.0 && p.radius_norm < 2.0) || (edge && p.radius_norm.is_nan()),
                "{}",
                f.path
            );
            assert!(p.nu >= 0.3 && p.nu < 0.5, "{}: nu = {}", f.path, p.nu);
            if let Some(nu) = f.nu {
                assert_eq!(p.nu, nu, "{}", f.path);
            }
        }
        // A header line and one line per row (the files carry no comments yet).
        assert_eq!(f.text().lines().count(), rows + 1 + f.provenance().len());
    }
}

#[test]
fn force_references_have_their_ranges() {
    let f03 = softgrip_fe::force_reference(0.3)
        .expect("nu = 0.3")
        .points()
        .expect("parses");
    let f049 = softgrip_fe::force_reference(0.49)
        .expect("nu = 0.49")
        .points()
        .expect("parses");
    assert!(softgrip_fe::force_reference(0.4).is_none());
    assert_eq!(f03.len(), 61);
    assert_eq!(f03.last().map(|p| p.x), Some(0.61));
    assert_eq!(f049.last().map(|p| p.x), Some(0.78));
    // x = 0.01, nu = 0.3: 0.00397964 N / E*, E* = 2 (1.3) / (1 - 0.09) MPa.
    let e_star = 2.0 * 1.3 / (1.0 - 0.09);
    assert!((f03[0].force_norm - 0.00397964 / e_star).abs() < 1e-15);
    // FE is 1-3.5 % above Hertz at small x (MODEL.md).
    let ratio = f03[0].force_norm / (4.0 / 3.0 * 0.01f64.powf(1.5));
    assert!(ratio > 1.01 && ratio < 1.05, "{ratio}");
    let full = softgrip_fe::file("full_nu0.3.csv").expect("embedded");
    let points = full.points().expect("parses");
    assert_eq!(points.last().map(|p| p.x), Some(0.85));
    assert_eq!(points[0].min_element_j, Some(0.9278));
    assert_eq!(full.rows::<FullRow>().expect("parses")[0].v_over_v0, 0.9997);
}

#[test]
fn small_x_rows_carry_their_own_nu() {
    let rows: Vec<SmallXRow> = softgrip_fe::file("small_x_check.csv")
        .expect("embedded")
        .rows()
        .expect("parses");
    assert!(rows.iter().any(|r| r.nu == 0.3) && rows.iter().any(|r| r.nu == 0.49));
    assert!(rows.iter().any(|r| r.extra_fine_mesh == 1));
    assert!(rows.iter().all(|r| r.delta_over_r <= 0.01 + 1e-12));
}

#[test]
fn the_wrong_row_type_is_a_typed_error_naming_the_file() {
    let err = softgrip_fe::file("force_nu0.3.csv")
        .expect("embedded")
        .rows::<FullRow>()
        .expect_err("force files have no a_fit_mm");
    assert_eq!(err.path, "force_nu0.3.csv");
    assert!(
        err.to_string()
            .starts_with("FE reference `force_nu0.3.csv`"),
        "{err}"
    );
}

#[test]
fn every_csv_of_the_folder_is_in_the_table() {
    //! Adding a file to tests/data/fe/ without its row in FILES or COUNTERPART_FILES fails
    //! here. The campaign folders `free/`, `flat/`, `core/` (softgrip's own pipeline, tools/fe/)
    //! are the raw output of the backed-fingertip campaign; their force curves are rows of
    //! FILES where the law is calibrated on them (issue 10). The counterpart folders `ball/`,
    //! `cylinder/`, `edge/` are whole in COUNTERPART_FILES (tools/fe/fe_campaign.py export
    //! writes it), except each folder's `convergence.csv` (mesh and faceting checks, read by
    //! the docs, not by the law) and the semi-axes checks on a finer 3D mesh, `axes_*.csv`
    //! (cylinder/<construction>/, session 20: read by softgrip-law's `cylinder_axes_r40` test
    //! through include_str!, not by the loader). Any other subfolder is checked.
    const CAMPAIGN: [&str; 3] = ["free", "flat", "core"];
    fn csvs(dir: &Path, base: &Path, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).expect("readable folder") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
                if !(dir == base && CAMPAIGN.contains(&name)) {
                    csvs(&path, base, out);
                }
            } else if path.extension().is_some_and(|e| e == "csv")
                && path.file_name().and_then(|n| n.to_str()).is_some_and(|n| {
                    n != "convergence.csv" && !(n.starts_with("axes_") && dir != base)
                })
            {
                let rel = path.strip_prefix(base).expect("inside");
                out.push(rel.to_string_lossy().replace('\\', "/"));
            }
        }
    }
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/fe");
    let mut found = Vec::new();
    csvs(&base, &base, &mut found);
    assert!(!found.is_empty());
    for path in found {
        assert!(
            softgrip_fe::file(&path).is_some(),
            "{path} is not in softgrip_fe::FILES"
        );
    }
    assert!(softgrip_fe::PROVENANCE.contains("CalculiX"));
}

#[test]
fn counterpart_files_are_keyed_by_counterpart_construction_and_nu() {
    //! Every file of ball/, cylinder/, edge/ carries the counterpart of its folder and the
    //! construction of its subfolder, and force_file finds it by that key.
    for f in softgrip_fe::COUNTERPART_FILES {
        let mut parts = f.path.split('/');
        assert_eq!(parts.next(), Some(f.counterpart.kind()), "{}", f.path);
        assert_eq!(parts.next(), Some(f.geometry), "{}", f.path);
        let name = parts.next().expect("a file name");
        if let Some(k) = f.counterpart.k() {
            assert!(name.contains(&format!("_k{k}")), "{}: k = {k}", f.path);
        }
        if matches!(f.schema, Schema::Force | Schema::Force3d) {
            let nu = f.nu.expect("one nu per file");
            let found = softgrip_fe::force_file(f.counterpart, f.geometry, nu, None);
            assert_eq!(found.map(|g| g.path), Some(f.path));
        }
    }
    assert!(softgrip_fe::force_file(Counterpart::Ball { k: 1.0 }, "free", 0.48, None).is_some());
    assert!(softgrip_fe::force_file(Counterpart::Ball { k: 1.5 }, "free", 0.48, None).is_none());
    // The plane's campaign curves are keyed too.
    let plane = softgrip_fe::force_file(Counterpart::Plane, "flat", 0.48, None).expect("flat");
    assert_eq!(plane.path, "flat/force_nu0.48.csv");
    assert_eq!(
        softgrip_fe::force_file(Counterpart::Plane, "core", 0.48, Some(0.4)).map(|f| f.path),
        Some("core/force_nu0.48_t0.4.csv")
    );
}

#[test]
fn a_ball_is_hertz_with_the_effective_radius_at_small_x() {
    //! At x = 0.01 the free sphere on a ball of radius k R is Hertz with R_eff = R k / (1 + k):
    //! F / F_H(R_eff) is 1-3 % above 1 at nu >= 0.45 (the plane's FE is 1-3.5 % above Hertz,
    //! MODEL.md), up to 4.2 % at nu = 0.3 (the plane's there: 4.5 %). A ball
    //! read as a plane (R_eff = R) would be 29 % off at k = 1. (flat is 4 % stiffer than free
    //! at x = 0.01 on a plane: the bond already matters; it is not checked here.)
    let mut seen = 0;
    for f in softgrip_fe::COUNTERPART_FILES {
        let (Counterpart::Ball { k }, Schema::Force, "free") =
            (f.counterpart, f.schema, f.geometry)
        else {
            continue;
        };
        let p = f.points().expect("parses")[0];
        assert_eq!(p.x, 0.01, "{}", f.path);
        let r_eff = k / (1.0 + k);
        let hertz = 4.0 / 3.0 * r_eff.sqrt() * p.x.powf(1.5);
        let ratio = p.force_norm / hertz;
        // The plane's own FE at nu = 0.3 is 4.5 % above Hertz at x = 0.01
        // (`free/force_nu0.3.csv`), and a ball of 10 R is nearly a plane: 1.042 there.
        let top = if f.nu.is_some_and(|nu| nu < 0.45) {
            1.05
        } else {
            1.04
        };
        assert!(
            (1.0..top).contains(&ratio),
            "{}: F / F_H(R_eff) = {ratio}",
            f.path
        );
        seen += 1;
    }
    assert!(seen >= 1, "{seen} free ball force files");
}
