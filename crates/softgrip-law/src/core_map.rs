//! A skin on a rigid core (`Backing::Core`) on a curved counterpart: its calibrated law is not
//! the plane's curve rescaled (`mapping`), because its three parts follow three different
//! compressions (session 11, against the FE of a core on balls, `tests/data/fe/ball/core/`):
//!
//! - the hemisphere's large-deformation stiffening (`chi_flat`, and the exponent that shares it
//!   with the layer) follows the counterpart map's `rho x`, as for the flat pad (`mapping`: the
//!   squeeze counts the counterpart's curvature `r < 1` times);
//! - the layer excess `L` is a function of the patch over the skin (Dimitriadis' `a/t`, the
//!   crossover `(a_H/l)^2`): it follows Hertz's patch exactly, the plane's at `rho_H x`
//!   (`rho_H = h^2`, `a^2 = R_eff delta` on a ball);
//! - the skin over the core's pole is squeezed between two rigid surfaces by the true `delta`
//!   whatever the counterpart: its thinning `T` takes `s = delta/t = x/tau` itself.
//!
//! No constant is fitted here: `rho` and the counterpart's tail are the bonded pad's
//! (`mapping`), `rho_H` is Hertz's. With the plane's curve at `rho x` throughout (the session-10
//! map) the layer's patch was too wide and the pole's squeeze too small: 4.1 % too stiff at
//! x = 0.02 on a ball of R (t/R 0.3, nu 0.48), and the range stopped at 0.6 t/R.
//!
//! The force is `h (4/3) chi_on(x) x^(3/2) - tail x^(5/2)` with `chi_on` tabulated when the law
//! is bound (the core's own table, 256 cells in `sqrt(x)`): stiffness, energy and inverse stay
//! exact (the table's derivative and integral, as on the plane). Binding costs one table
//! (`cargo bench -p softgrip-law --bench law -- with_counterpart`).

use crate::backing::Backing;
use crate::curve::Curve;
use crate::error::Result;
use crate::level::Level;
use crate::levels::backed::Backed;
use crate::mapping::CounterpartMap;
use crate::material::ContactParams;

/// The curve and map of the calibrated core law of `params` on a curved counterpart whose
/// plane map is `map`; `None` for every other level, construction or counterpart (they keep
/// the plane's curve, rescaled by `map`).
pub(crate) fn core_on_counterpart(
    level: Level,
    params: &ContactParams,
    map: &CounterpartMap,
    curved: bool,
) -> Result<Option<(Curve, CounterpartMap)>> {
    let backing = params.backing();
    if !curved || !matches!(level, Level::Calibrated) || !matches!(backing, Backing::Core { .. }) {
        return Ok(None);
    }
    // h = s rho^(3/2): Hertz's force over the plane's at small x; rho_H = h^2.
    let h = map.force * map.rho * map.rho.sqrt();
    let backed = Backed::try_new_on(
        backing,
        params.thickness_ratio(),
        params.poisson_ratio(),
        map.rho,
        h * h,
    )?;
    // The curve is in the true x now: rho = 1 and s = h; the patch's axes stay the plane's
    // at rho x (the curve's radius is evaluated there).
    let on = CounterpartMap {
        rho: 1.0,
        force: h,
        ..*map
    };
    Ok(Some((Curve::Backed(backed), on)))
}
