//! The README quick start: a silicone fingertip through the law's hot path, checked API and inverse.
//! `cargo run -p softgrip-law --example quick_start`

use softgrip_law::{ContactLaw, ContactParams, Level, Material};

fn main() -> Result<(), softgrip_law::Error> {
    // Silicone fingertip: R = 10 mm, E = 3 MPa, nu = 0.49.
    let tip = ContactParams::try_new(Material::try_new(3.0e6, 0.49)?, 0.010)?;
    let law = ContactLaw::try_new(tip, Level::Calibrated)?;

    // Hot path (per contact, per step): force [N] and stiffness [N/m] only.
    let r = law.response(0.004); // delta = 4 mm, x = 0.4
    println!(
        "F = {:.3} N, K = {:.1} N/m, {:?}",
        r.force, r.stiffness, r.regime
    );

    // Everything, checked: energy, contact radius, mean and peak pressure.
    let s = law.evaluate(0.004)?;
    println!(
        "W = {:.2e} J, a = {:.2} mm, p_peak = {:.0} kPa",
        s.energy,
        s.patch.radius * 1e3,
        s.patch.peak_pressure / 1e3
    );

    // Inverse: the squeeze depth for a 5 N grip.
    let delta = law.compression_for_force(5.0)?;
    println!("5 N needs delta = {:.3} mm", delta * 1e3);

    // Past the validity range the checked API says so; the hot path extends and flags it.
    assert!(law.evaluate(0.0095).is_err());
    Ok(())
}
