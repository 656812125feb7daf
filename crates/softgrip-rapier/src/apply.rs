//! The impulse primitives the soft solve and its exact stick answer share: a row's relative
//! spin, a linear or torsional impulse applied to its bodies (a multibody link through its
//! multibody), and the bodies restored to where a solve started.

use nalgebra::Vector3;

use crate::mobility::{self, BodyState};
use crate::problem::{Row, body};

/// The relative spin of a row's bodies about its normal (body a - body b) \[rad/s\].
pub(crate) fn rel_spin(bodies: &[BodyState], r: &Row) -> f64 {
    let wa = body(bodies, r.a).map(|b| b.w).unwrap_or_default();
    let wb = body(bodies, r.b).map(|b| b.w).unwrap_or_default();
    (wa - wb).dot(&r.n)
}

/// Applies the linear impulse `imp` \[N s\] at a row's point: `+imp` to body a, `-imp` to
/// body b (a multibody link through its multibody).
pub(crate) fn apply_linear(bodies: &mut [BodyState], r: &Row, imp: &Vector3<f64>) {
    for (i, imp) in [(r.a, *imp), (r.b, -imp)] {
        let Some(i) = i else { continue };
        if bodies[i].link.is_some() {
            let arm = (r.p - bodies[i].com).cross(&imp);
            mobility::apply(bodies, i, &imp, &arm);
        } else {
            bodies[i].apply(&r.p, &imp);
        }
    }
}

/// Applies the torsional impulse `t` \[N m s\] about a row's normal: `+t` to body a, `-t` to
/// body b.
pub(crate) fn apply_torque(bodies: &mut [BodyState], r: &Row, t: f64) {
    let tv = r.n * t;
    for (i, sign) in [(r.a, 1.0), (r.b, -1.0)] {
        let Some(i) = i else { continue };
        if bodies[i].link.is_some() {
            mobility::apply(bodies, i, &Vector3::zeros(), &(tv * sign));
        } else if sign > 0.0 {
            bodies[i].w += bodies[i].inv_i * tv;
        } else {
            bodies[i].w -= bodies[i].inv_i * tv;
        }
    }
}

/// Restores body `i` to `base` (a multibody link: every link of its multibody in the table).
pub(crate) fn restore_body(bodies: &mut [BodyState], base: &[BodyState], i: usize) {
    let Some(host) = bodies[i].link.as_deref().map(|l| l.host) else {
        bodies[i].clone_from(&base[i]);
        return;
    };
    let links = match base[host].link.as_deref().and_then(|l| l.multi.as_ref()) {
        Some(g) => g.links.clone(),
        None => vec![i],
    };
    for k in links {
        bodies[k].clone_from(&base[k]);
    }
}

/// Restores the bodies of `rows` to `base`.
pub(crate) fn restore(bodies: &mut [BodyState], base: &[BodyState], rows: &[Row]) {
    for r in rows {
        for i in [r.a, r.b].into_iter().flatten() {
            restore_body(bodies, base, i);
        }
    }
}
