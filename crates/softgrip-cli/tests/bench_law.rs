//! `softgrip bench-law --quick`: the table names every level and the figures are written.

use std::path::PathBuf;
use std::process::Command;

const LEVELS: [&str; 9] = [
    "linear",
    "hertz",
    "fit",
    "incompressible",
    "neo-hookean",
    "neo-hookean-exact",
    "tatara",
    "calibrated",
    "auto",
];

/// The table's cells for `level` in the section of the free sphere at `nu`.
fn cells<'a>(table: &'a str, nu: &str, level: &str) -> Vec<&'a str> {
    section_cells(table, &format!("free nu = {nu} "), level)
}

/// The table's cells for `level` in the section whose heading starts with `heading`.
fn section_cells<'a>(table: &'a str, heading: &str, level: &str) -> Vec<&'a str> {
    let nu = heading;
    let section = table
        .split("### ")
        .find(|s| s.starts_with(heading))
        .unwrap_or_else(|| panic!("no section {heading}"));
    let row = section
        .lines()
        .find(|l| l.starts_with(&format!("| {level} |")))
        .unwrap_or_else(|| panic!("no row for {level} at nu = {nu}"));
    row.trim_matches('|').split('|').map(str::trim).collect()
}

fn percent(cell: &str) -> f64 {
    cell.split(" %")
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("not a percentage: {cell}"))
}

#[test]
fn quick_run_prints_every_level_and_writes_five_pngs() {
    let out_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bench_law_quick");
    let _ = std::fs::remove_dir_all(&out_dir);
    let out = Command::new(env!("CARGO_BIN_EXE_softgrip"))
        .args(["bench-law", "--quick", "--out"])
        .arg(&out_dir)
        .output()
        .expect("the softgrip binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "bench-law failed: {stderr}");
    let table = String::from_utf8(out.stdout).expect("UTF-8 output");

    for nu in ["0.3", "0.49"] {
        for level in LEVELS {
            let c = cells(&table, nu, level);
            assert_eq!(c.len(), 8, "{c:?}");
            // Times are positive numbers (their size is not tested).
            for ns in &c[2..4] {
                let v: f64 = ns.parse().unwrap_or_else(|_| panic!("not a time: {ns}"));
                assert!(v > 0.0, "{level}: {ns}");
            }
        }
        // The paper's claims, read from the table: Eq. 38 within 5 % of FE on 0.01..0.5,
        // Hertz more than 50 % off (FE is more than twice Hertz at x = 0.5).
        assert!(percent(cells(&table, nu, "fit")[4]) < 5.0, "{table}");
        assert!(percent(cells(&table, nu, "hertz")[4]) > 50.0, "{table}");
    }

    // Each backed construction has its own section; its calibrated level is that
    // construction's law (within 1 % of the flat FE, seen 0.55 % at nu = 0.48), and the free
    // sphere's levels are far off (Hertz more than 50 %, the free calibrated more than 10 % at
    // x = 0.44).
    let flat_cal = section_cells(&table, "flat nu = 0.48 ", "calibrated");
    assert!(percent(flat_cal[5]) < 1.0, "{table}");
    assert!(
        percent(section_cells(&table, "flat nu = 0.48 ", "hertz")[5]) > 50.0,
        "{table}"
    );
    assert!(
        percent(section_cells(&table, "flat nu = 0.48 ", "fit")[5]) > 10.0,
        "{table}"
    );
    for heading in [
        "flat nu = 0.3 ",
        "core t/R = 0.4 nu = 0.48 ",
        "core t/R = 0.8 nu = 0.3 ",
    ] {
        for level in LEVELS {
            assert_eq!(
                section_cells(&table, heading, level).len(),
                8,
                "{heading} {level}"
            );
        }
    }

    // Each counterpart has its own section; calibrated on it is within its stated error of
    // its FE (crates/softgrip-law/tests/counterpart_fe.rs: ball K = 1 free 1.55 %, R/2 free
    // 1.17 %, cylinder K = 1 flat 1.11 %, K = 3 free 0.72 %: fails at 2 %; 2R flat 2.02 %
    // since session 14's refit of the flat pad on balls (1.21 % before): fails at 2.3 %; the
    // edge 4.25 % flat, 3.31 % free: fails at 5 %; the free sphere on 4R at nu 0.3 3.64 %
    // fails past it; the flat pad on R at nu 0.3, 5.05 % before the refit, 1.53 % since:
    // fails at 1.8 %; the held-out 0.7 R at nu 0.4 2.42 %, fails past it); the plane law
    // would be 89 % off on the ball of R at x = 0.7 (the 'softgrip is too stiff').
    for (heading, limit) in [
        ("free on ball:1 nu = 0.48 ", 2.0),
        ("free on ball:0.5 nu = 0.48 ", 2.0),
        ("flat on ball:2 nu = 0.48 ", 2.3),
        ("flat on cylinder:1 nu = 0.48 ", 2.0),
        ("free on cylinder:3 nu = 0.48 ", 2.0),
        ("flat on edge nu = 0.48 ", 5.0),
        ("free on edge nu = 0.48 ", 5.0),
        ("free on ball:4 nu = 0.3 ", 3.9),
        ("flat on ball:1 nu = 0.3 ", 1.8),
        ("free on ball:0.7 nu = 0.4 ", 2.7),
    ] {
        let cal = section_cells(&table, heading, "calibrated");
        assert!(percent(cal[5]) < limit, "{heading}: {cal:?}");
    }

    for name in [
        "law_force_vs_x.png",
        "law_force_vs_x_ball.png",
        "law_force_vs_x_cylinder.png",
        "law_force_vs_x_edge.png",
        "law_speed_vs_error.png",
    ] {
        let bytes = std::fs::read(out_dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(bytes.len() > 10_000, "{name} is only {} bytes", bytes.len());
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{name} is not a PNG");
    }
}
