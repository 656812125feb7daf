//! How many substeps a step needs, and how implicit each contact's update is.
//!
//! A contact is **dynamic** when it is touching and its dynamic amplitude `|v_n| / omega`
//! exceeds [`AMPLITUDE_FRACTION`] of `max(delta, 1e-3 R)`, or when it is approaching with a
//! gap that closes within the step (`gap < |v_n| dt + 0.01 R`). Such a contact needs its
//! oscillation resolved: the step is split into `n = ceil(omega_est dt / theta)` equal
//! substeps, where `theta` is [`SoftAccuracy`] (radians of contact phase per substep),
//! `omega_est = sqrt(K(delta_est) w)`, `w = 1/m_eff` the contact's normal mobility and
//! `delta_est` the compression at which the law's energy reaches `W(delta) + m_eff v_n^2 / 2`
//! (the deepest point of the impact, found by Newton on `W` with `W' = F`).
//! Quasi-static contacts (resting) take no substeps; a contact held by joint motors takes the
//! substeps its motors' push needs (`step::split`).

use softgrip_law::ContactLaw;

/// Dynamic amplitude, as a fraction of `max(delta, 1e-3 R)`, above which a touching contact
/// is resolved by substeps.
pub const AMPLITUDE_FRACTION: f64 = 0.05;
/// Largest number of substeps per step (counted in `SoftCounters::substep_cap_hits`).
pub const MAX_SUBSTEPS: u32 = 2000;

/// The one accuracy setting: contact phase `omega h` \[rad\] per substep of a dynamic contact.
///
/// Cost and error scale together: the number of substeps of an impact step is
/// `omega dt / theta`, and the symplectic (explicit) update's error on the peak force,
/// compression and duration of an impact is O(theta) (about 1 % at the default 0.05 in the
/// bounce test). Energy is conserved to O(theta^2) per bounce. Larger values are cheaper and
/// less accurate; above ~0.5 the update blends into the damped implicit form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SoftAccuracy(f64);

impl SoftAccuracy {
    /// Default phase per substep: 0.05 rad (about 125 substeps per contact period).
    pub const DEFAULT: SoftAccuracy = SoftAccuracy(0.05);

    /// Phase per substep `theta` \[rad\], finite and in (0, 2].
    pub fn try_new(theta: f64) -> crate::Result<Self> {
        if theta > 0.0 && theta <= 2.0 {
            Ok(Self(theta))
        } else {
            Err(crate::Error::InvalidParameter {
                field: "accuracy",
                value: theta,
                range: "in (0, 2] rad",
            })
        }
    }

    /// The phase per substep \[rad\].
    pub fn theta(self) -> f64 {
        self.0
    }
}

impl Default for SoftAccuracy {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The compression at which `W(delta_est) = W(delta) + kinetic + P (delta_est - delta)`
/// (Newton on that balance, `W' = F`), where `P` is `push` \[N\] (the external load pressing
/// the contact) when it is more than the law's range holds (`force_max`), else 0: a load past
/// the range runs into the extension's barrier, and its work over the run is what the barrier
/// must absorb. A load within the range leaves the estimate as it was.
pub(crate) fn delta_estimate(law: &ContactLaw, delta: f64, kinetic: f64, push: f64) -> f64 {
    let d0 = delta.max(0.0);
    let push = if push > law.force_max() { push } else { 0.0 };
    if !(kinetic > 0.0) && (push == 0.0 || law.response(d0).force >= push) {
        // At rest, and the law holds the load where it is: no run.
        return d0;
    }
    let kinetic = kinetic.max(0.0);
    let target = law.energy(d0) + kinetic;
    let p = law.params();
    // Hertz start: W = (8/15) E* sqrt(R) d^(5/2).
    let hertz = (15.0 / 8.0 * target / (p.effective_modulus() * p.radius().sqrt())).powf(0.4);
    let mut d = hertz.max(d0);
    // Against a load the root may be nearly double (the load just above the force at
    // `delta`), where Newton only halves its distance per pass: more passes then.
    let passes = if push > 0.0 { 120 } else { 30 };
    for _ in 0..passes {
        let f = law.response(d).force - push;
        let g = law.energy(d) - target - push * (d - d0);
        if !(f > 0.0) {
            d *= 2.0;
            continue;
        }
        let next = (d - g / f).max(0.5 * d);
        if (next - d).abs() <= 1e-10 * d {
            d = next;
            break;
        }
        d = next;
    }
    if d.is_finite() { d } else { d0 }
}

/// Substeps needed by one contact (1 = none); `push` \[N\] is the external load pressing it
/// ([`delta_estimate`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn substeps_for(
    law: &ContactLaw,
    radius: f64,
    delta: f64,
    vn: f64,
    mobility: f64,
    push: f64,
    dt: f64,
    theta: f64,
) -> u32 {
    if !(mobility > 0.0) || !vn.is_finite() {
        return 1;
    }
    let m_eff = 1.0 / mobility;
    let dynamic = if delta > 0.0 {
        true
    } else {
        let approach = -vn;
        approach > 0.0 && -delta < approach * dt + 0.01 * radius
    };
    if !dynamic {
        return 1;
    }
    let kinetic = 0.5 * m_eff * vn * vn;
    let overloaded = push > law.force_max();
    if delta > 0.0 && !overloaded {
        // Quick accept of a quasi-static touching contact, without the energy inversion: a
        // kinetic energy below 1e-3 F delta moves the estimate by about 1e-3 delta, where the
        // stiffness (hence omega) cannot fall by the factor 4 that the halved threshold
        // leaves as margin.
        let resp = law.response(delta);
        if resp.force > 0.0 && kinetic <= 1e-3 * resp.force * delta {
            let omega0 = (resp.stiffness * mobility).sqrt();
            if omega0 > 0.0
                && vn.abs() / omega0 <= 0.5 * AMPLITUDE_FRACTION * delta.max(1e-3 * radius)
            {
                return 1;
            }
        }
    }
    let d_est = delta_estimate(law, delta, kinetic, push);
    let omega = (law.response(d_est).stiffness * mobility).sqrt();
    if !(omega > 0.0) {
        return 1;
    }
    // A contact pressed by a load past the law's range (`overloaded`) is never taken as
    // quasi-static: it rests on the extension's barrier, whose force is convex with a pole,
    // and one update linearised over a whole step from below overshoots it (Newton from below
    // on a convex function: from 0.985 of the way to the wall, a heavy ball's update landed
    // 0.3 % of R past the wall). It is resolved at its own frequency at the estimate instead.
    if delta > 0.0 && !overloaded {
        let amplitude = vn.abs() / omega;
        if amplitude <= AMPLITUDE_FRACTION * delta.max(1e-3 * radius) {
            return 1;
        }
    }
    let n = (omega * dt / theta).ceil();
    if n >= MAX_SUBSTEPS as f64 {
        MAX_SUBSTEPS
    } else {
        (n as u32).max(1)
    }
}

/// Blend of the update: 0 (explicit, symplectic with rapier's position update) when the
/// contact is resolved (`omega h <= 0.5`), 1 (linearised implicit, unconditionally stable and
/// numerically damped) when `omega h >= 2`, smoothstep in between.
pub(crate) fn theta_blend(omega_h: f64) -> f64 {
    let s = ((omega_h - 0.5) / 1.5).clamp(0.0, 1.0);
    if s.is_finite() {
        s * s * (3.0 - 2.0 * s)
    } else {
        1.0
    }
}
