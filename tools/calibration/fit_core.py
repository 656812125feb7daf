#!/usr/bin/env python3
"""Fit and validate the `core` construction's calibrated force law (a soft skin of thickness t
over a rigid core, `Backing::Core`) against softgrip's own FE (tests/data/fe/core/).

Since session 21 the law (backed.rs) is this form plus the thin-layer floor and the small-patch
widening, refitted with the S20B skins: tools/calibration/try_thin_skin_s21.py reproduces it.
This script still fits the session-10 form below and reproduces the session-10 constants.

    chi_core = chi_flat + L T / K
      tau = t/R, eps = mu/kappa = 3 (1 - 2 nu) / (2 (1 + nu))
      h   = 1 + tau^2 / (1 - tau)                 the skin's mean depth over r <= 2t, over t
      L   = B(a_core / (t h), eps x / tau^2) - B(a_flat / (R h), eps x)
                                                   bonded layer of depth t h, less the hemisphere's
      B(v, E) = v (d1 + e v / (1 + E))             bonded layer: Dimitriadis + compressible crossover
      d1  = -2 alpha0(nu)/pi                       Dimitriadis et al. (2002), first order in a/h
      e   = e0 exp(-m eps)                         second order: the layer's confinement
      T   = 1 + (l0 + l1 eps) s + lc (mu/M) D(s)   the skin over the pole, squeezed by s = delta/t
      D(s) = (2/3) (1 - s)^(-5/3) (2 - s) - 4/3    confined neo-Hookean layer beyond linear (theory)
      mu/M = eps / (1 + 4 eps / 3)                 M = kappa + 4 mu/3, the oedometer modulus
      K   = exp((k0 + k1 eps) (chi_flat - 1))      the hemisphere's large-x stiffening, shared
      a_flat, a_core: the law's own contact radii (backed.rs `radius`, constants RADIUS,
        RADIUS_CORE, G; fitted to the FE radii by fit_radius_pressure.py, not refitted here)
      chi_flat: the flat construction's law (backed.rs FLAT)

Why each term:
- B(v): a contact of radius a on a layer of depth h bonded to a rigid base, at v = a/h. Its first
  order is Dimitriadis' d1(nu) (theory, no fit). The second order e v^2 is the confinement of the
  layer's material (the pressure it needs to flow out past the contact); a compressible layer
  loses volume instead, so e fades with the squeeze-film mechanism as e0 exp(-m eps) (e0 (1 - m
  eps) to first order, never negative; m = 1, the session-6 form, is 0.5 % worse). The
  crossover 1 + E: the layer acts incompressibly only over lengths below its confinement
  length l ~ depth sqrt(kappa/mu), beyond which it is an oedometer (stiffening linear in a/h):
  E = (a_H/l)^2 with Hertz's a_H = sqrt(R delta): eps (a_H/t)^2 = eps x/tau^2 for the skin,
  the radius law's own E = eps u^2 (one confinement measure for the radius and the force;
  coefficient 1, not fitted), and eps x for the hemisphere's depth R. (Before: eps v^2 with
  the law's radius a_core in v; with the radius law's own crossover in a_core, that form
  refitted is 3.39 % fitted / 3.18 % held out, this one with m = 1 2.79 / 2.21 %.)
- h: the core is a sphere of radius R - t, not a plane. Under the pole the skin is t thick; at
  a distance r the core has fallen away by r^2/(2(R - t)) and the surface by r^2/(2R), so the skin
  is t (1 + (r/t)^2 tau^2/(2(1 - tau))) thick, and over the disc r <= 2t the layer feels its mean
  depth t (1 + tau^2/(1 - tau)) (coefficient 1, not fitted; fitted it is 0.97). As t -> R,
  h -> infinity and L -> 0: core -> flat. As t/R -> 0, h -> 1: a flat bonded layer.
- a_core, a_flat: the patch on a bonded layer thinner than itself is wider than Hertz's; the
  law's radius carries that (and is what Dimitriadis' a is).
- - B(a_flat/(R h)): the depth-R layer that chi_flat (a hemisphere bonded at its flat face)
  already carries.
- T: the skin over the core's pole is squeezed by s = delta/t = x/tau (up to 0.8 here) between
  two rigid surfaces, a confined layer. (l0 + l1 eps) s is its small-strain thinning (a
  compressible skin stiffens more under it, l1 > 0). (mu/M) D(s) is its large-strain part,
  exact for the FE's material laterally confined (`confined`): zero for an incompressible skin,
  unbounded as a compressible one collapses (the FE's nu = 0.3 skins reach element J = 0.2 at
  s = 0.8). lc is the share of the layer excess that stiffens as the pole's skin does.
- K: the large-deformation stiffening of the hemisphere (chi_flat) and the layer excess do not
  multiply: near incompressibility (k > 0) the excess grows less than chi_flat, for a
  compressible skin (k < 0 at nu = 0.3) more. As an exponential (equal to 1 + k (chi_flat - 1)
  to first order) it cannot vanish: the linear form did at nu = 0.3 when that nu was held out
  of the fit (k -0.86, chi_flat - 1 up to 1.4: a pole, 1572 % off; exponential 8.05 %).

Fitted constants (7): e0, m, l0, l1, k0, k1, lc. Everything else is theory, geometry, the flat law or
the radius law.
Objective: the largest |F_law/F_FE - 1| (a smooth max: least squares, then least squares of
(50 r)^2 and (50 r)^4), over 0.01 <= x <= x_max = min(x_max_flat(nu), 0.8 t/R) on every
force_nu*_t*.csv in tests/data/fe/core/ except the held-out ones (HELD), which are only reported.
Prints: the constants, the residual per curve, the held-out files, each t/R and each nu held out
in turn, and a check of the form over nu in [0.3, 0.5], t/R in [0.02, 0.98] (chi > 0, F strictly
increasing, chi_core -> chi_flat as t -> R, chi decreasing in t/R at fixed x).

Result (this script, 14 fitted curves, session 10): e0 = 0.849512, l0 = 0.676765, l1 = 1.022037,
k0 = 0.266768, k1 = -1.622115, m = 1.470321, lc = 0.234092. Fitted max 2.48 % (each curve to its FE
reach, delta/t up to 0.8); held out (both sets, ten files) 1.05-2.37 % ((0.33, 0.25) at x = 0.15;
the third set of session 11, run after: 1.86 % (0.47, 0.15), 1.62 % (0.42, 0.25));
each t/R held out in turn 10.34 % (0.2, an extrapolation), 4.70 % (0.4), 3.31 % (0.6), 2.04 %
(0.8); each nu 5.80 % (0.3, an extrapolation), 2.74 % (0.4), 2.19 % (0.48), 2.60 % (0.499); each
fitted curve held out within 2.93 % except (0.3, 0.4) 3.73 % and (0.3, 0.2) 6.17 %. The session-7
form (T = 1 + (l0 + l1 eps) x/tau, six constants) was 2.31 % fitted, 2.25 % held out to delta/t
= 0.6 only, and 18 % off at the FE's reach (tools/calibration/CORE_FORM.md, extend_core_range.py).

usage: target/fe-venv/bin/python tools/calibration/fit_core.py      (numpy + scipy; ~10 s)
"""
import glob
import os
import re
import sys

import numpy as np
from scipy.optimize import least_squares

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "fe",
                    "core")
# FE runs kept out of every fit (tools/fe/fe_campaign.py role "heldout"): nu and t/R between the
# fitted ones.
HELD = {(0.35, 0.7), (0.45, 0.5), (0.4, 0.3), (0.49, 0.3),
        # the second held-out set (session 6, made after this form was chosen: a blind test)
        (0.46, 0.25), (0.33, 0.25), (0.42, 0.55), (0.36, 0.2), (0.44, 0.8), (0.495, 0.35),
        # the third (session 11): a skin thinner than any fitted, and one between them
        (0.47, 0.15), (0.42, 0.25),
        # the fourth (session 13): skins thinner than any fitted (t/R 0.1-0.14, R/60-R/75)
        (0.38, 0.12), (0.46, 0.1), (0.32, 0.14), (0.49, 0.12),
        # the fifth (session 15): a blind test of session 15's thin-skin variant (run after its
        # constants were fixed), beside the held-out miss (0.46, 0.25)
        (0.47, 0.25),
        # the sixth (session 20): skins thinner than any run before (t/R 0.08, R/75), blind tests
        # of the thin-layer variants of try_thin_skin_s20.py (run after they were fixed)
        (0.4, 0.08), (0.3, 0.08),
        # the seventh (session 21): blind tests of the adopted thin-layer floor (run after its
        # constants were fixed; tools/fe/fe_campaign.py S21_DT, smaller increments)
        (0.48, 0.08), (0.4, 0.06), (0.48, 0.06), (0.45, 0.07), (0.35, 0.06)}
# Fit data made after the law's constants (session 15, role "main" in tools/fe/fe_campaign.py:
# t/R 0.25, 0.3 and 0.35 between the fitted 0.2 and 0.4). The law was not refitted
# (CORE_FORM.md, "Thin skins: session 15"), so this script keeps them out of its fit and
# reports them as held out; a refit of the form moves them into the fit by deleting this set.
LATER = {(0.48, 0.3), (0.35, 0.3), (0.45, 0.35), (0.49, 0.25)}
# Fit data for the thin-layer floor (session 20, second part, role "main": t/R 0.05 and 0.1 at
# nu 0.3, 0.4, 0.48, try_thin_skin_s20b.py fits on them). The law was not refitted with them, so
# this script keeps them out of its fit (it reproduces the law's constants) and reports them as
# held out.
S20B = {(0.3, 0.05), (0.48, 0.05), (0.4, 0.05), (0.3, 0.1), (0.48, 0.1), (0.4, 0.1)}
# The flat construction's constants (backed.rs FLAT: c0, c1, e0, e1, b, d), not refitted here.
FLAT = (0.681614, -0.341872, 1.754842, -2.984330, 0.791282, 0.329388)
# The law's radius (backed.rs G, RADIUS, RADIUS_CORE), not refitted here.
G = (0.042222, 0.109823)
RADIUS = (0.648666, -0.706160, -0.954134)
RADIUS_CORE = (0.958112, 0.695966, 0.679698, 2.279033)
SQUEEZE = 0.8  # x_max = 0.8 t/R: the FE's furthest reach (t/R 0.2, 0.25, 0.4 at nu 0.3-0.36)
START = [0.85, 0.68, 1.02, 0.27, -1.62, 1.47, 0.23]
NAMES = ["e0", "l0", "l1", "k0", "k1", "m", "lc"]


def eps_of(nu):
    return 3 * (1 - 2 * nu) / (2 * (1 + nu))


def flat_x_max(nu):
    knots = [(0.3, 0.53), (0.4, 0.46), (0.48, 0.44)]
    if nu <= knots[0][0]:
        return knots[0][1]
    for (n0, x0), (n1, x1) in zip(knots, knots[1:]):
        if nu <= n1:
            return x0 + (x1 - x0) * (nu - n0) / (n1 - n0)
    return knots[-1][1]


def chi_flat(x, nu):
    c0, c1, e0, e1, b, d = FLAT
    eps = eps_of(nu)
    s = np.sqrt(x)
    return ((1 - x + x * x / 3) * (1 - d * x + (c0 + c1 * eps) * s + (e0 + e1 * eps) * x * x)
            / ((1 - x) ** 2 + b * b * eps * x * x))


def radius(x, nu, tau):
    """The law's contact radii over R (backed.rs `radius`): (a_flat, a_core)."""
    eps = eps_of(nu)
    s = np.sqrt(x)
    w = 1 - x
    g1, g3 = G
    q0, q1, q2 = RADIUS
    s0, s1, c, k = RADIUS_CORE
    free = np.arctanh(s) * (1 + (g1 + g3 * x * x) * x) * w / (w + 0.25 * eps * x)
    flat = free * (1 + (q0 + q1 * eps + q2 * x) * x)
    rc = 1 - tau
    u = s / tau
    return flat, flat * (1 + s0 * (1 - s1 * eps * u * u / (1 + eps * u * u)) * rc * rc * u / ((u + c) * (1 + k * x / rc)))


def dimitriadis_d1(nu):
    """First-order coefficient of Dimitriadis' bonded-layer series, chi = 1 + d1 a/h + ..."""
    alpha0 = -(1.2876 - 1.4678 * nu + 1.3442 * nu * nu) / (1 - nu)
    return -2 * alpha0 / np.pi


def confined(s):
    """The confined skin's large-strain stiffening: D(s) = (P(1 - s)/(-M s) - 1) M/mu, where
    P(lam) = (2/3) mu lam^(-5/3) (lam^2 - 1) + kappa (lam - 1) is the nominal stress of the
    neo-Hookean skin (C10 = mu/2, D1 = 2/kappa, the FE's material) compressed to the axial
    stretch lam = 1 - s with no lateral strain (an oedometer), M = kappa + 4 mu/3 its small-strain
    modulus. The volumetric part is linear in lam and cancels; what is left is the deviatoric
    part, D = (2/3) lam^(-5/3) (2 - s) - 4/3 = (14/9) s + O(s^2), growing without bound as the
    layer collapses (lam -> 0). Theory, no fit."""
    lam = 1 - s
    return 2 / 3 * lam ** (-5 / 3) * (2 - s) - 4 / 3


def chi_core(p, x, nu, tau):
    e0, l0, l1, k0, k1, m, lc = p
    eps = eps_of(nu)
    fl = chi_flat(x, nu)
    a_flat, a_core = radius(x, nu, tau)
    h = 1 + tau * tau / (1 - tau)  # the skin's mean depth over r <= 2t, over t
    d1, e = dimitriadis_d1(nu), e0 * np.exp(-m * eps)
    # (a_H / l)^2, l = depth sqrt(kappa/mu): the patch over the layer's confinement length, the
    # radius law's E = eps u^2 (u = a_H / t) for the skin, eps x for the hemisphere's depth R
    layer = lambda v, conf: v * (d1 + e * v / (1 + conf))  # noqa: E731
    excess = layer(a_core / (tau * h), eps * x / tau ** 2) - layer(a_flat / h, eps * x)
    # the skin over the pole squeezed by s = delta/t: linearly, and its confined large-strain
    # stiffening (mu/M) D(s), mu/M = eps/(1 + 4 eps/3) (0 for an incompressible skin)
    s = x / tau
    thinning = 1 + (l0 + l1 * eps) * s + lc * eps / (1 + 4 * eps / 3) * confined(s)
    return fl + excess * thinning * np.exp(-(k0 + k1 * eps) * (fl - 1))


def load():
    curves = []
    for path in sorted(glob.glob(os.path.join(DATA, "force_nu*_t*.csv"))):
        m = re.search(r"force_nu([\d.]+)_t([\d.]+)\.csv$", path)
        nu, tau = float(m.group(1)), float(m.group(2))
        a = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x = a["delta_over_R"]
        e_star = 2 * (1 + nu) / (1 - nu ** 2)  # MPa, mu = 1 MPa, R = 1 mm
        chi = a["force_N"] / e_star / (4 / 3 * x ** 1.5)
        hi = min(flat_x_max(nu), SQUEEZE * tau)
        keep = (x >= 0.01 - 1e-9) & (x <= hi + 1e-9)
        curves.append(dict(nu=nu, tau=tau, x=x[keep], chi=chi[keep], reach=x[-1],
                           held=(nu, tau) in HELD or (nu, tau) in LATER or (nu, tau) in S20B,
                           name=os.path.basename(path)))
    return curves


def residuals(p, curves):
    return np.concatenate([chi_core(p, c["x"], c["nu"], c["tau"]) / c["chi"] - 1 for c in curves])


def fit(curves, p0=START):
    f = lambda p: residuals(p, curves)  # noqa: E731
    p = least_squares(f, p0, x_scale="jac", max_nfev=5000).x
    for power in (2, 4):  # towards the smallest largest error
        g = lambda p: np.sign(f(p)) * np.abs(50 * f(p)) ** power  # noqa: E731
        p = least_squares(g, p, x_scale="jac", max_nfev=5000).x
    return p


def worst(p, c):
    r = chi_core(p, c["x"], c["nu"], c["tau"]) / c["chi"] - 1
    i = int(np.argmax(np.abs(r)))
    return 100 * abs(r[i]), c["x"][i]


def check(p):
    """The form over nu in [0.3, 0.5], t/R in [0.02, 0.98], 0 < x <= x_max: chi finite and > 0,
    F = chi x^1.5 strictly increasing (on a grid in s = sqrt(x)), chi_core -> chi_flat, and chi
    decreasing in t/R at fixed x (a thinner skin is stiffer)."""
    worst_f, min_chi, min_slope, rising = 0.0, np.inf, np.inf, 0
    for nu in np.linspace(0.3, 0.5, 21):
        for tau in np.linspace(0.02, 0.98, 49):
            x_max = min(flat_x_max(nu), SQUEEZE * tau)
            s = np.linspace(1e-4, np.sqrt(x_max), 400)
            x = s * s
            chi = chi_core(p, x, nu, tau)
            if not np.all(np.isfinite(chi)):
                return f"NOT finite at nu {nu:g}, t/R {tau:g}"
            force = chi * x ** 1.5
            min_chi = min(min_chi, chi.min())
            min_slope = min(min_slope, (np.diff(force) / np.diff(x) / np.sqrt(x[1:])).min())
        x = np.linspace(0.01, flat_x_max(nu), 50)
        worst_f = max(worst_f, np.max(np.abs(chi_core(p, x, nu, 0.999) / chi_flat(x, nu) - 1)))
        for x in (0.005, 0.01, 0.03, 0.06, 0.1, 0.2, 0.3, 0.4):  # a thinner skin is stiffer
            taus = np.linspace(0.02, 0.98, 97)
            taus = taus[x <= np.minimum(flat_x_max(nu), SQUEEZE * taus) + 1e-12]
            if len(taus) > 1:
                rising += int(np.sum(np.diff(chi_core(p, x, nu, taus)) > 0))
    return (f"min chi {min_chi:.3f}, min dF/dx / sqrt(x) {min_slope:.3f} (> 0: increasing), "
            f"|chi_core/chi_flat - 1| at t/R = 0.999: {100 * worst_f:.3f} %, "
            f"grid steps where chi rises with t/R: {rising}")


def main():
    curves = load()
    train = [c for c in curves if not c["held"]]
    held = [c for c in curves if c["held"]]
    print(f"fitted on {len(train)} curves ({sum(len(c['x']) for c in train)} points), "
          f"{len(held)} held out")
    p = fit(train)
    print("constants: " + ", ".join(f"{k} = {v:.6f}" for k, v in zip(NAMES, p)))
    print("check: " + check(p))
    print("\n| file | nu | t/R | x_max | FE reach | max abs err | at x | role |")
    print("|---|---|---|---|---|---|---|---|")
    for c in curves:
        w, x = worst(p, c)
        print(f"| {c['name']} | {c['nu']:g} | {c['tau']:g} | {c['x'][-1]:.2f} | {c['reach']:.2f} "
              f"| {w:.2f} % | {x:g} | {'held out' if c['held'] else 'fit'} |")
    print(f"\nfitted: max {max(worst(p, c)[0] for c in train):.2f} %; held-out files: max "
          f"{max(worst(p, c)[0] for c in held):.2f} %")
    print("\neach t/R held out in turn (refit without it):")
    for tau in sorted({c["tau"] for c in train}):
        q = fit([c for c in train if c["tau"] != tau], p)
        out = [c for c in train if c["tau"] == tau]
        print(f"  t/R = {tau:g}: {max(worst(q, c)[0] for c in out):.2f} % on it "
              f"(held-out files {max(worst(q, c)[0] for c in held):.2f} %)")
    print("\neach fitted nu held out in turn:")
    for nu in sorted({c["nu"] for c in train}):
        q = fit([c for c in train if c["nu"] != nu], p)
        out = [c for c in train if c["nu"] == nu]
        print(f"  nu = {nu:g}: {max(worst(q, c)[0] for c in out):.2f} % on it "
              f"(held-out files {max(worst(q, c)[0] for c in held):.2f} %)")
    print("\neach curve held out in turn (refit on the other 13 fitted curves):")
    for c in train:
        q = fit([d for d in train if d is not c], p)
        print(f"  {c['name']}: {worst(q, c)[0]:.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
