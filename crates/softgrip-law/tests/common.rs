//! Shared helpers of the law's integration tests.
#![allow(dead_code)]

use softgrip_law::{ContactLaw, ContactParams, Level};

/// A law in normalised units (E* = 1 Pa, R = 1 m): force is f, delta is x.
pub fn normalised(level: Level, nu: f64) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu).expect("valid params");
    ContactLaw::try_new(p, level).expect("level builds")
}

/// Every level that can be built at `nu`.
pub fn levels_at(nu: f64) -> Vec<ContactLaw> {
    Level::ALL
        .iter()
        .filter(|l| nu < 0.5 || !matches!(l, Level::NeoHookean | Level::NeoHookeanExact))
        .map(|l| normalised(*l, nu))
        .collect()
}

/// Compression ratios spread over (0, x_max) that avoid the cell boundaries of tables and of
/// `Auto` (multiples of 1/256 and 1/64).
pub fn grid(x_max: f64, n: usize) -> Vec<f64> {
    (1..n)
        .map(|i| x_max * (i as f64 + 0.293_7) / (n as f64 + 0.5))
        .collect()
}

/// `(r/R, p/E*)` of an FE pressure profile (R = 1 mm, mu = 1 MPa), the two nodes nearest the
/// axis dropped (the tied on-axis face makes them jitter by up to 20 %: see the file's
/// provenance line); the last row is the contact edge a_lin (p = 0).
pub fn profile(text: &str, nu: f64) -> Vec<(f64, f64)> {
    let e_star = 2.0 * (1.0 + nu) / (1.0 - nu * nu); // MPa
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("r_mm"))
        .skip(2)
        .map(|l| {
            let mut it = l
                .split(',')
                .map(|v| v.trim().parse::<f64>().expect("number"));
            (it.next().expect("r"), it.next().expect("p") / e_star)
        })
        .collect()
}
