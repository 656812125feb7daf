//! The free sphere and the flat pad on a curved counterpart (`calibrated`): the plane law's
//! compressible cap scaled by the area the counterpart presses (session 12).
//!
//! Both plane laws end their large-x stiffening in a pole capped by compressibility: the
//! incompressible body's lateral-area pole `1/(1 - x)^2` becomes `1/((1 - x)^2 + B x^2)`
//! (`B = (b eps)^2` free, `b^2 eps` bonded; `crate::levels::calibrated`,
//! `crate::levels::backed`), because the material squeezed under the contact loses volume
//! instead of flowing out. The counterpart map (`crate::mapping`) evaluates the plane law at
//! `rho x`, and with it this cap as if the volume that can collapse were the plane's. It is
//! not: a counterpart of Hertz ratio `rho_H = R_eff/R` presses at compression delta a patch
//! of area `pi R_eff delta`, `rho_H` times the plane's, and the column under it, of the same
//! depth, holds `rho_H` of the plane's volume; what is around it is not squeezed and confines
//! it. So the cap is `rho_H B`: a ball loses less volume and stiffens more at large x than the
//! plane map says, by nothing at small x (the cap is of order `x^2`) and by nothing on a plane
//! (`rho_H = 1`) or for an incompressible fingertip (`B = 0`). No constant is fitted here;
//! the map's `r, g, q` were refitted with it (`tools/calibration/fit_counterpart.py`, form
//! `r+g+q, eps, cap`): the flat pad at nu = 0.3 on balls of R/2, R, 2R went from 3.76, 5.05,
//! 3.44 % to 2.22, 3.46, 2.69 %, the free sphere on 4R (blind) from 3.64 to 2.97 %.
//!
//! A concave counterpart (a bowl, `rho_H > 1`) keeps the plane's cap: it presses more than the
//! plane's area, but no FE of a concave counterpart says how much more volume collapses, and
//! `rho_H B` grows without bound as the bowl approaches the fingertip's own radius (at
//! `kappa R = -0.999`, `rho_H = 1000`: the free sphere at nu = 0.3 softened from x = 0.01 and its
//! range ended there, against x = 0.51 with the plane's cap).
//!
//! Only the calibrated plane laws carry the cap as a term; `auto`, `tabulated` and `custom`
//! take the map alone (their plane curve is a table) with session 11's constants, fitted
//! without the cap (`crate::mapping`). A calibrated core takes the flat pad's map and cap
//! (`crate::core_map`: its hemisphere's denominator carries `rho_H B` too, so that as t -> R
//! it is the flat pad's law on the counterpart). The hot path is unchanged (the same curve type); binding the flat pad
//! builds its table once (`cargo bench -p softgrip-law --bench law -- with_counterpart`).

use crate::backing::Backing;
use crate::curve::Curve;
use crate::error::Result;
use crate::level::Level;
use crate::levels::backed::Backed;
use crate::levels::calibrated::Calibrated;
use crate::mapping::CounterpartMap;
use crate::material::ContactParams;

/// The plane curve of `params` with its cap scaled by `map.cap`, for the calibrated free
/// sphere and flat pad on a curved counterpart; `None` for every other level, construction
/// and counterpart (a cap of 1: the plane's own curve).
pub(crate) fn capped_on_counterpart(
    level: Level,
    params: &ContactParams,
    map: &CounterpartMap,
) -> Result<Option<Curve>> {
    if !matches!(level, Level::Calibrated) || map.cap == 1.0 {
        return Ok(None);
    }
    let nu = params.poisson_ratio();
    Ok(match params.backing() {
        Backing::Free => Some(Curve::Calibrated(Calibrated::try_new_capped(nu, map.cap)?)),
        Backing::Flat => Some(Curve::Backed(Backed::try_new_capped(
            Backing::Flat,
            None,
            nu,
            None,
            map.cap,
        )?)),
        Backing::Core { .. } => None,
    })
}

#[cfg(test)]
mod tests {
    use crate::backing::Backing;
    use crate::levels::backed::Backed;
    use crate::levels::calibrated::Calibrated;
    use crate::normalised::NormalisedLaw;

    /// The two plane forms, plain and with the cap scaled by `cap`, at `nu`.
    fn pairs(nu: f64, cap: f64) -> [(Box<dyn NormalisedLaw>, Box<dyn NormalisedLaw>); 2] {
        let flat = |c| Backed::try_new_capped(Backing::Flat, None, nu, None, c).expect("flat");
        [
            (
                Box::new(Calibrated::try_new(nu).expect("free")),
                Box::new(Calibrated::try_new_capped(nu, cap).expect("free")),
            ),
            (Box::new(flat(1.0)), Box::new(flat(cap))),
        ]
    }

    /// The cap is a large-x, compressible effect: none for an incompressible fingertip, of
    /// order x^2 B at small x, and a narrower pressed area (cap < 1) stiffens at large x.
    #[test]
    fn the_cap_acts_at_large_x_on_a_compressible_fingertip_only() {
        for (plain, capped) in pairs(0.5, 0.5) {
            for x in [0.01, 0.2, 0.4] {
                assert_eq!(plain.force_stiffness(x), capped.force_stiffness(x));
            }
        }
        for (plain, capped) in pairs(0.3, 0.5) {
            let ratio = |x: f64| capped.force_stiffness(x).0 / plain.force_stiffness(x).0;
            // B x^2 / 2 at most: b^2 eps = 0.29 bonded, (b eps)^2 = 0.069 free at nu = 0.3.
            assert!((ratio(0.01) - 1.0).abs() < 1.5e-5, "{}", ratio(0.01));
            assert!(ratio(0.4) > 1.01, "{}", ratio(0.4));
            assert!(ratio(0.5) > ratio(0.4));
        }
    }
}
