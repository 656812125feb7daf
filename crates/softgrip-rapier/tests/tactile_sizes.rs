//! Regression (issue 26): a tactile pad of 1e-300 m was accepted; its taxel area was 0 and the
//! recorded pressures were NaN. A taxel narrower than `MIN_TAXEL_SIDE_OVER_RADIUS` R is now a
//! typed error naming `tactile.width` or `tactile.height`; at that boundary the taxels are
//! still exact: the one under the centre of a contact holds the peak pressure (3/2) F/(π a²)
//! to 1e-8.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_rapier::{
    Error, MIN_TAXEL_SIDE_OVER_RADIUS, Preset, SoftFingertip, TactileImage, TactilePad,
};

fn build(radius: f64, n: u32, width: f64, height: f64) -> Result<SoftFingertip, Error> {
    SoftFingertip::builder(radius)
        .preset(Preset::DragonSkin30)
        .tactile(TactilePad::new(n, n, [1.0, 0.0, 0.0], width, height))
        .build()
}

#[test]
fn tactile_pad_of_1e_300_m_is_refused() {
    for (w, h, field) in [
        (1e-300, 0.01, "tactile.width"),
        (0.01, 1e-300, "tactile.height"),
        (5e-324, 0.01, "tactile.width"),
        // 16 taxels of 0.99e-8 m on a 10 mm fingertip: below 1e-6 R.
        (16.0 * 0.99e-8, 0.01, "tactile.width"),
    ] {
        match build(0.01, 16, w, h).unwrap_err() {
            Error::InvalidTactilePad {
                field: f, range, ..
            } => {
                assert_eq!(f, field);
                assert!(range.contains("at least 16 x 1e-8 m"), "{range}");
            }
            other => panic!("{other}"),
        }
    }
}

#[test]
fn smallest_taxels_hold_the_peak_pressure() {
    for radius in [1e-9, 1e-3, 0.01, 1e3] {
        let n = 15; // odd: a taxel is centred on the pad's centre
        let side = MIN_TAXEL_SIDE_OVER_RADIUS * radius;
        let tip = build(radius, n, n as f64 * side, n as f64 * side).unwrap();
        let mut image = TactileImage::new(*tip.tactile().unwrap());
        let (a, force) = (0.2 * radius, 3.0);
        image.add_disc([0.0, 0.0], a, force);
        let peak = 1.5 * force / (std::f64::consts::PI * a * a);
        // Over a taxel of side s at the centre the mean of p = peak sqrt(1 - r²/a²) is
        // peak (1 - s²/(12 a²)) to second order: 2e-11 relative here.
        let got = image.at(n / 2, n / 2);
        assert!(
            (got / peak - 1.0).abs() < 1e-8,
            "R {radius}: {got} vs {peak}"
        );
        assert!(image.pressure().iter().all(|p| p.is_finite() && *p > 0.0));
    }
    // Just below the boundary: refused.
    let side = MIN_TAXEL_SIDE_OVER_RADIUS * 0.01 * (1.0 - 1e-9);
    assert!(build(0.01, 15, 15.0 * side, 0.01).is_err());
}
