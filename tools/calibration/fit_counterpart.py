#!/usr/bin/env python3
"""Fit and validate the counterpart map of softgrip's law against the FE of curved counterparts.

The law of a fingertip on a counterpart (crates/softgrip-law/src/mapping.rs) is its law on a
plane at a scaled compression and force:

    F(x) = s F_p(rho x),   s rho^(3/2) = h          (h: Hertz's force over the plane's, exact
                                                     at small x: sqrt(R_eff/R) for a ball,
                                                     the elliptical factor for a cylinder)
    a_i(x) = c_i a_p(rho x),  c_i = (semi-axis over sqrt(R delta) in Hertz) / sqrt(rho)

with rho_H = h^2 (the ball with the same small-x force) and the calibrated
    1/rho - 1 = r (1/rho_H - 1)        r = r0 + r1 eps, eps = mu/kappa = 3 (1 - 2 nu)/(2 (1 + nu))
r = 1 is the pure patch argument (rho = rho_H: the patch a^2 = R_eff delta is the plane's at
rho_H delta); r < 1: the counterpart's curvature counts less than the fingertip's in the large-x
stiffening, because the sphere's axial compression (the lateral-area pole at x -> 1) does not
care what it is pressed on. An edge: F = s_e F_p(rho_e x), both fitted.

Reads tests/data/fe/{ball,cylinder,edge}/{free,flat}/force_*.csv (copied from the fe-curved
branch, provenance in each file's first line) and the plane laws' constants below (as in
crates/softgrip-law/src/levels/{calibrated,backed}.rs). Prints every number of
tools/calibration/COUNTERPART.md.

Usage: python3 tools/calibration/fit_counterpart.py [--data DIR]     (numpy + scipy)
"""
import argparse
import glob
import os
import re
import sys

import numpy as np
from scipy.optimize import least_squares, minimize

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_hertz_ellipse import ellipse  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# ---------------------------------------------------------------- the plane laws (Rust's)
CAL = dict(c0=0.36889, c1=0.28197, e=0.837, f=-0.25364, b=0.56801)
G = (0.042222, 0.109823)
FLAT = (0.681614, -0.341872, 1.754842, -2.984330, 0.791282, 0.329388)
RAD_FLAT = (0.648666, -0.706160, -0.954134)


def eps_of(nu):
    return 3 * (1 - 2 * nu) / (2 * (1 + nu))


def chi_free(x, nu, cap=1.0):
    beta = (1 - 2 * nu) / (2 * (1 - nu))
    eps = eps_of(nu)
    c = CAL["c0"] + CAL["c1"] * beta
    w = 1 - x
    n = w + x * x / 3
    s = w + c * np.sqrt(x) + CAL["e"] * x * x + CAL["f"] * x ** 3
    return n * s / (w * w + cap * (CAL["b"] * eps) ** 2 * x * x)


def chi_flat(x, nu, cap=1.0):
    c0, c1, e0, e1, b, d = FLAT
    eps = eps_of(nu)
    w = 1 - x
    n = w + x * x / 3
    s = 1 - d * x + (c0 + c1 * eps) * np.sqrt(x) + (e0 + e1 * eps) * x * x
    return n * s / (w * w + cap * b * b * eps * x * x)


def f_plane(x, nu, construction, cap=1.0):
    """The plane law; `cap` scales its compressible cap (the denominator's eps term): 1 on a
    plane, rho_H on a curved counterpart (the pressed area's fraction, mapping.rs)."""
    chi = chi_free if construction == "free" else chi_flat
    return 4 / 3 * x ** 1.5 * chi(x, nu, cap)


def a_plane(x, nu, construction):
    eps = eps_of(nu)
    w = 1 - x
    free = np.arctanh(np.sqrt(x)) * (1 + G[0] * x + G[1] * x ** 3) * w / (w + eps * x / 4)
    if construction == "free":
        return free
    q0, q1, q2 = RAD_FLAT
    return free * (1 + (q0 + q1 * eps) * x + q2 * x * x)


# x_max of the plane laws (where they stop) and the counterpart's reach (mapping.rs).
def x_max_plane(nu, construction):
    if construction == "free":
        return 0.65 + 0.13 * min(max((nu - 0.3) / 0.1, 0), 1)
    knots = [(0.3, 0.53), (0.4, 0.46), (0.48, 0.44)]
    if nu <= 0.3:
        return 0.53
    for (n0, x0), (n1, x1) in zip(knots, knots[1:]):
        if nu <= n1:
            return x0 + (x1 - x0) * (nu - n0) / (n1 - n0)
    return 0.44


REACH = {"free": 0.70, "flat": 0.66}

# Curves that landed after the law's constants were fixed (mapping.rs): blind tests, kept out of
# the fit so that the constants printed stay the law's.
# (The nu = 0.3 balls, blind to the first nu-dependent constants at 4.61-9.40 %, joined the fit;
# COUNTERPART.md keeps those numbers.)
LANDED_AFTER_FIT = {"ball/free/force_nu0.499_k2.csv"} | {
    # The campaign's end (session 10): R2/R = 4 and 10 at nu 0.3, 0.48 (10), 0.499, free and
    # flat, R/2 at nu = 0.499 free (its flat run failed at x = 0.02: not exported) and 2R at
    # nu = 0.499 flat. Refitting with them did not lower the largest error (the fit is
    # held by the nu = 0.3 curves past x = 0.6; COUNTERPART.md): they stay blind.
    f"ball/{g}/force_nu{nu}_k{k}.csv" for g in ("free", "flat")
    for nu, k in [("0.3", 4), ("0.3", 10), ("0.48", 10), ("0.499", 4), ("0.499", 10)]} | {
    "ball/free/force_nu0.499_k0.5.csv"}
# Session 14: the bonded pad at nu = 0.499 on 2 R and 4 R joins the fit (without the range
# penalty, `fit`): the only nearly incompressible flat curves past x = 0.05, they hold r0 and g0
# (the eps -> 0 limit) where the mid-nu curves would move them (fitted without them the
# refit's law is 4.26 % off on 2 R at nu = 0.499, COUNTERPART.md session 14). 10 R stays blind.
LANDED_AFTER_FIT -= {"ball/flat/force_nu0.499_k2.csv", "ball/flat/force_nu0.499_k4.csv"}


# ---------------------------------------------------------------- data
class Curve:
    def __init__(self, path):
        self.path = os.path.relpath(path, ROOT)
        m = re.search(r"(ball|cylinder|edge)/(free|flat)/force_nu([0-9.]+?)(?:_k([0-9.]+))?\.csv$", path)
        self.kind, self.construction, self.nu = m.group(1), m.group(2), float(m.group(3))
        self.k = float(m.group(4)) if m.group(4) else None
        first = open(path).readline()
        # Held out of every fit: the campaign's held-out runs, and every cylinder (the ellipse
        # is the balls' form generalised by Hertz's theory, not fitted: a blind test of it).
        self.held_out = ("held-out" in first or "held out" in first or self.kind == "cylinder"
                         or os.path.relpath(path, os.path.join(ROOT, "tests", "data", "fe"))
                         in LANDED_AFTER_FIT)
        r = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        es = 2 * (1 + self.nu) / (1 - self.nu ** 2)  # E* [MPa], mu = 1 MPa, R = 1 mm
        r = np.atleast_1d(r)  # a run that stopped at its first step has one row
        self.x = r["delta_over_R"]
        self.f = r["force_N"] / es
        names = r.dtype.names
        # Ball: one radius; cylinder and edge: the semi-axis along the axis or edge (the law's
        # first) and across it.
        if "contact_radius_mm" in names:
            self.a, self.b = r["contact_radius_mm"], None
        elif "semi_axis_along_32_mm" in names:
            # The 3D runs' unbiased estimate (the gap's Hertzian edge shape through the first two
            # nodes outside; the *_mm columns lag by up to a node spacing): no lag to add.
            self.a, self.b = r["semi_axis_along_32_mm"], r["semi_axis_across_32_mm"]
        else:
            self.a = self.b = None

    def name(self):
        k = f" K={self.k:g}" if self.k is not None else ""
        return f"{self.kind}{k} {self.construction} nu={self.nu:g}"

    def hertz(self):
        """(alpha, beta, h) of Hertz's contact at small x."""
        if self.kind == "ball":
            rho_h = self.k / (1 + self.k)
            return np.sqrt(rho_h), np.sqrt(rho_h), np.sqrt(rho_h)
        if self.kind == "cylinder":
            return ellipse(0.5, 0.5 * (1 + 1 / self.k))
        return None


def load(data):
    curves = []
    for kind in ("ball", "cylinder", "edge"):
        for path in sorted(glob.glob(os.path.join(data, kind, "f*", "force_*.csv"))):
            curves.append(Curve(path))
    return curves


# ---------------------------------------------------------------- the map
LAW = "r+g+q+q2+g3, eps, cap"
# Session 14's form (the law to session 15): no sextic term.
LAW_14 = "r+g+q+q2, eps, cap"
# The free sphere with the sextic term (session 16: tried, see COUNTERPART.md).
LAW_12_G3 = "r+g+q+g3, eps, cap"
# Session 16: the bonded r = r0 + r1 eps held at session 14's in the law's fit. A calibrated core
# takes the bonded pad's map, and its squeeze excess chi_flat(rho s)/chi_flat(rho_H s) follows r
# (core_map.rs): refitted with the sextic term r rose by 0.015-0.06 and took the core's curves
# up to 3.3 % softer at their ends (nu 0.3, t/R 0.5 on R: 1.38 -> 4.68 %; COUNTERPART.md);
# held, the flat pad loses 0.1-0.5 % on a few curves and the core stays as validated.
R_HELD = (0.860941, -1.052105)
# Session 12's form (the law to session 13): no re-stiffening term.
LAW_12 = "r+g+q, eps, cap"
# Session 11's form: the core's constants (core_map.rs keeps them; session 12 did not refit the
# core, whose hemisphere's cap is not scaled).
LAW_11 = "r+g+q, eps"
# The order in eps of the plane law's compressible softening (its denominator's b^2 eps x^2
# bonded, (b eps)^2 x^2 free): the collapse term's.
COLLAPSE_ORDER = {"free": 2, "flat": 1}
# Sneddon's shrink of the patch by the counterpart's quartic, a = a_H (1 - (a/R2)^2/6) for a
# rigid sphere on a half-space, weighted by the compressibility eps/eps(0.3) (no constant fitted).
SNEDDON_SHRINK = 1 / 6
EPS_VALIDATED = 3 * (1 - 0.6) / (2 * 1.3)
FORMS = {
    # name: (free parameters, description)
    "theory": "rho = rho_H (r = 1), no counterpart size (g = 0): the patch argument alone",
    "r": "r fitted, g = 0",
    "r+g": "r and g fitted, one pair per construction (the law's form at nu = 0.48 only)",
    "r+g, eps": "r = r0 + r1 eps, g = g0 + g1 eps (the law up to session 10)",
    LAW_11: "r+g, eps and the collapse term q eps^n (1 - rho_H) x^(7/2) (session 11; the core's)",
    LAW_12: "r+g+q, eps with the plane law's compressible cap scaled by the pressed area, rho_H "
            "(session 12)",
    LAW_14: "session 12's form and, bonded, the collapsed column's re-stiffening "
            "q2 eps (1 - rho_H) rho_H x^(11/2) (session 14; free: q2 = 0)",
    LAW_12_G3: "session 12's form and the sphere's sextic g3 mu2 x^(7/2) (free only: tried, "
               "session 16)",
    LAW: "session 14's form and, bonded, the sphere's next order beyond its paraboloid, "
         "g3 mu2 x^(7/2), mu2 = (m1|m1| + m2|m2|)/2, r held at session 14's (the law's form, "
         "session 16; free: session 12's, q2 = g3 = 0)",
}


def unpack(form, p):
    """(r0, r1, g0, g1, q) of a form's parameter vector."""
    if form == "theory":
        return (1.0, 0.0, 0.0, 0.0, 0.0)
    if form == "r":
        return (p[0], 0.0, 0.0, 0.0, 0.0)
    if form == "r+g":
        return (p[0], 0.0, p[1], 0.0, 0.0)
    if form == "r+g, eps":
        return tuple(p) + (0.0,)
    if form == LAW_12_G3:
        return tuple(p[:5]) + (0.0, p[5])
    if form == LAW:
        # r held at session 14's (R_HELD): the core's squeeze excess takes the bonded r
        return R_HELD + tuple(p)
    return tuple(p)


def start(form):
    return {"theory": [], "r": [0.8], "r+g": [0.8, 0.2], "r+g, eps": [0.8, 0.0, 0.2, 0.0],
            LAW_11: [0.8, 0.0, 0.2, 0.0, 0.0], LAW_12: [0.8, 0.0, 0.2, 0.0, 0.0],
            LAW_14: [0.8, 0.0, 0.2, 0.0, 0.0, 0.0], LAW_12_G3: [0.8, 0.0, 0.2, 0.0, 0.0, 0.0],
            LAW: [0.283373, -0.248553, -0.310668, 9.332449, 0.0]}[form]


def geometry(c):
    """(h, alpha, beta, mu) of a curved counterpart: Hertz's force factor and semi-axes, and
    mu = ((alpha k1)^2 sign k1 + (beta k2)^2 sign k2)/2, k = kappa R."""
    alpha, beta, h = c.hertz()
    if c.kind == "ball":
        k1 = k2 = 1 / c.k
    else:  # cylinder: 0 along the axis (alpha), 1/K across (beta)
        k1, k2 = 0.0, 1 / c.k
    mu = 0.5 * (alpha ** 2 * k1 * abs(k1) + beta ** 2 * k2 * abs(k2))
    return h, alpha, beta, mu


def mu2_of(c):
    """mu2 = (m1|m1| + m2|m2|)/2, m_i = alpha_i^2 k_i|k_i|: the counterpart's sextic over the
    Hertz patch, per x^2 (mapping.rs)."""
    _, alpha, beta, _ = geometry(c)
    k1, k2 = (1 / c.k, 1 / c.k) if c.kind == "ball" else (0.0, 1 / c.k)
    m1, m2 = alpha ** 2 * k1 * abs(k1), beta ** 2 * k2 * abs(k2)
    return 0.5 * (m1 * abs(m1) + m2 * abs(m2))


def law(c, x, coef):
    """(force, semi-axes (first, second), rho, top of the validity range)."""
    eps = eps_of(c.nu)
    if c.kind == "edge":
        s, rho = coef["edge_" + c.construction]
        f = s * f_plane(rho * x, c.nu, c.construction)
        top = min(x_max_plane(c.nu, c.construction) / rho, REACH[c.construction])
        return f, None, rho, top
    r0, r1, g0, g1, q = coef[c.construction][:5]
    q2 = coef[c.construction][5] if len(coef[c.construction]) > 5 else 0.0
    g3 = coef[c.construction][6] if len(coef[c.construction]) > 6 else 0.0
    cap_on = coef.get("cap", False)
    eps = min(eps, EPS_VALIDATED)
    r, g = r0 + r1 * eps, g0 + g1 * eps
    h, alpha, beta, mu = geometry(c)
    rho_h = h * h
    rho = 1 / (1 + r * (1 / rho_h - 1))
    # The compressible cap of the plane law scaled by the area the counterpart presses, rho_H
    # of the plane's at the same delta (a^2 = R_eff delta): the volume that can collapse.
    cap = min(rho_h, 1.0) if cap_on else 1.0  # a concave counterpart keeps the plane's (cap_map.rs)
    f = h / rho ** 1.5 * f_plane(rho * x, c.nu, c.construction, cap) - 4 / 3 * h * g * mu * x ** 2.5
    # The collapse: the plane law's compressible softening (order eps^n) changed in proportion
    # to how much the counterpart narrows the patch (1 - rho_H).
    f = f + 4 / 3 * h * q * eps ** COLLAPSE_ORDER[c.construction] * (1 - rho_h) * x ** 3.5
    # The collapsed column's re-stiffening (session 14, bonded): the collapse's own order in
    # eps, two orders of x past it, where the counterpart narrows the patch (1 - rho_H) and the
    # patch is still wide enough to collapse (rho_H; mapping.rs).
    f = f + 4 / 3 * h * q2 * eps * (1 - rho_h) * min(rho_h, 1.0) * x ** 5.5
    # The sphere's next order beyond its paraboloid (session 16): over Hertz's patch its
    # surface's r^6 term is (a_i kappa_i)^4 = m_i^2 x^2 relative to the paraboloid, the square
    # of the quartic's m_i x; signed by the curvature as the quartic is.
    f = f - 4 / 3 * h * g3 * mu2_of(c) * x ** 3.5
    ap = a_plane(rho * x, c.nu, c.construction) / np.sqrt(rho)
    reach = 1 / mu if mu > 0 else np.inf
    top = min(x_max_plane(c.nu, c.construction) / rho, REACH[c.construction], reach)
    # Sneddon's shrink per semi-axis, (a_i kappa_i)^2 = alpha_i^2 k_i |k_i| x, weighted by
    # eps/eps(0.3); not for the patch argument alone (theory: r = 1, g = 0).
    k1, k2 = (1 / c.k, 1 / c.k) if c.kind == "ball" else (0.0, 1 / c.k)
    gamma = 0.0 if (r0, r1, g0, g1) == (1.0, 0.0, 0.0, 0.0) else SNEDDON_SHRINK * eps / EPS_VALIDATED
    xs = np.minimum(x, top)
    axes = (alpha * ap * (1 - gamma * alpha ** 2 * k1 * abs(k1) * xs),
            beta * ap * (1 - gamma * beta ** 2 * k2 * abs(k2) * xs))
    return f, axes, rho, top


def errors(c, coef):
    f, _, _, top = law(c, c.x, coef)
    sel = (c.x >= 0.01 - 1e-12) & (c.x <= top + 1e-12)
    return (f / c.f - 1)[sel]


def worst(c, coef):
    e = errors(c, coef)
    return np.max(np.abs(e)) if len(e) else np.nan


def fit(curves, construction, form):
    """The construction's (r0, r1, g0, g1) for `form` on `curves`: least squares of the
    relative force errors, then of their 8th power (towards the smallest largest error).

    Every curve is fitted from x = 0.01 to the FE's reach (fixed points: the optimiser must not
    see their number change), and a law whose validity range (`top`: the plane law's x_max/rho,
    the counterpart's reach) ends before the FE's reach pays for the difference: the law must
    cover what the FE covers. Without that the fit shortens the range instead (at nu = 0.3 a
    bonded pad's rho went to 0.97, the law ending at x = 0.55 of the FE's 0.68) and misses the
    held-out R2/R = 0.7 at nu = 0.4 by 8 % (COUNTERPART.md)."""
    mine = [c for c in curves if c.construction == construction and c.kind != "edge"]
    if form == "theory" or not mine:
        return unpack("theory", [])
    if form == LAW and construction == "free":
        # the free sphere has no re-stiffening term and no sextic term: session 12's form,
        # q2 = g3 = 0 (session 16: with g3 fitted, LAW_12_G3, no curve gains; COUNTERPART.md)
        return fit(curves, construction, LAW_12) + (0.0, 0.0)
    if form == LAW_14 and construction == "free":
        return fit(curves, construction, LAW_12) + (0.0,)
    sels = [(c.x >= 0.01 - 1e-12) & (c.x <= REACH[construction] + 1e-12) for c in mine]

    def res(q, power):
        cf = {construction: unpack(form, q), "cap": form in (LAW, LAW_14, LAW_12, LAW_12_G3)}
        e = [(law(c, c.x, cf)[0] / c.f - 1)[s] for c, s in zip(mine, sels)]
        # Session 14: not the nearly incompressible curves (nu >= 0.49): the bonded plane law's
        # x_max at rho x cannot reach their FE's end whatever the map, and the penalty then
        # bends r0 to shorten the others (COUNTERPART.md session 13).
        short = [0.0 if c.nu >= 0.49 else
                 max(0.0, min(c.x.max(), REACH[construction]) - law(c, c.x[:1], cf)[3])
                 for c in mine]
        e = np.concatenate(e + [10 * np.array(short)])
        e = np.where(np.isfinite(e), e, 10.0)
        return np.sign(e) * np.abs(e) ** (power / 2)

    p = least_squares(lambda q: res(q, 2), start(form)).x
    p = minimize(lambda q: np.sum(res(q, 8) ** 2), p, method="Nelder-Mead",
                 options=dict(xatol=1e-8, fatol=1e-24, maxiter=8000)).x
    return unpack(form, p)


def fit_edge(curves, construction):
    mine = [c for c in curves if c.kind == "edge" and c.construction == construction]
    if not mine:
        return None

    def res(p, power):
        coef = {"edge_" + construction: (p[0], p[1])}
        e = np.concatenate([errors(c, coef) for c in mine])
        return np.sign(e) * np.abs(e) ** (power / 2)

    p = least_squares(lambda p: res(p, 2), [0.8, 0.5], bounds=([0.01, 0.01], [10, 1])).x
    p = minimize(lambda p: np.sum(res(p, 8) ** 2), p, method="Nelder-Mead").x
    return tuple(p)


def smooth(x, a, lo=0.05):
    """Least-squares a/sqrt(x) = poly(sqrt x) on lo <= x (tools/calibration/
    fit_radius_pressure.py's `smooth`: the FE radius column moves in node steps)."""
    k = x >= lo - 1e-9
    deg = 3 if x[k].max() - lo > 0.25 else 2
    s = np.sqrt(x[k])
    c = np.linalg.lstsq(np.vander(s, deg + 1, increasing=True), a[k] / s, rcond=None)[0]
    return lambda xx: np.sqrt(xx) * (np.vander(np.sqrt(xx), deg + 1, increasing=True) @ c)


def mesh_of(c):
    """N of the mesh R/N, from the file's provenance (`element edge R/N`)."""
    m = re.search(r"element edge R/(\d+)", open(os.path.join(ROOT, c.path)).readline())
    return int(m.group(1)) if m else 40


def radius_errors(c, coef, lo=0.1, hi=0.4):
    """Semi-axes against the FE's estimate a* = a_lin smoothed plus half an element edge,
    0.485 R/N on a mesh R/N (as tools/calibration/fit_radius_pressure.py), lo <= x <= hi;
    per semi-axis the FE has."""
    if c.a is None or c.kind == "edge":
        return []
    _, axes, _, top = law(c, c.x, coef)
    sel = (c.x >= lo) & (c.x <= min(hi, top))
    out = []
    for law_axis, fe_axis in zip(axes, (c.a, c.b)):
        if fe_axis is None:
            continue
        lag = 0.485 / mesh_of(c) if c.kind == "ball" else 0.0
        fe = smooth(c.x, fe_axis)(c.x[sel]) + lag
        out.append(law_axis[sel] / fe - 1)
    return out


def plane_bias_3d(data):
    """The 3D mesh's own radius error, measured on a plane: the 3D quarter model on a plane at
    R/20 (cylinder/convergence.csv, check "3d": its contact radius, the last node in contact,
    against the axisymmetric R/40 run's, smoothed plus half an element) as a function of what
    the 3D mesh reads, fitted by a quadratic over 0.05 <= x <= 0.44. Returns a -> true a."""
    rows = [line.strip().split(",") for line in open(os.path.join(data, "cylinder", "convergence.csv"))
            if ",3d," in line]
    rows = [r for r in rows if r[4] == "20"]
    x = np.array([float(r[6]) for r in rows])
    a3 = np.array([float(r[10]) for r in rows])
    axi = np.array([float(r[11]) for r in rows])
    sel = (x >= 0.05) & (x <= 0.44)
    bias = (smooth(x, axi)(x[sel]) + 0.485 / 40) / a3[sel]
    cb = np.polyfit(a3[sel], bias, 2)
    lo, hi = a3[sel].min(), a3[sel].max()
    print(f"  the 3D mesh on a plane reads the radius {100 * (1 - 1 / bias.min()):.0f}-"
          f"{100 * (1 - 1 / bias.max()):.0f} % low (mean {100 * (1 - np.mean(1 / bias)):.0f} %)")
    return lambda a: a * np.polyval(cb, np.clip(a, lo, hi))


def cylinder_axes(c, coef, correct, lo=0.1, hi=0.4):
    """The law's semi-axes over the 3D FE's (the last-node columns, smoothed), raw and with the
    3D mesh's plane bias removed: (name, raw errors, corrected errors) per semi-axis."""
    r = np.genfromtxt(os.path.join(ROOT, c.path), delimiter=",", names=True, skip_header=1)
    _, axes, _, top = law(c, c.x, coef)
    sel = (c.x >= lo) & (c.x <= min(hi, top))
    out = []
    for name, mine, col in zip(("along", "across"), axes, ("semi_axis_along_mm", "semi_axis_across_mm")):
        fe = smooth(c.x, r[col])(c.x[sel])
        out.append((name, mine[sel] / fe - 1, mine[sel] / correct(fe) - 1))
    return out


def sneddon_coefficient():
    """-(F/F_H - 1)/(a_H/R)^2 of Sneddon's exact rigid sphere on an elastic half-space
    (F = (E*/2)((a^2 + R^2) ln((R + a)/(R - a)) - 2 a R), delta = (a/2) ln((R + a)/(R - a)))
    against Hertz's paraboloid at the same delta, a_H^2 = R delta: the counterpart's own size to
    first order."""
    out = []
    for a in (0.05, 0.1, 0.2):
        el = np.log((1 + a) / (1 - a))
        f = 0.5 * ((a * a + 1) * el - 2 * a)
        d = 0.5 * a * el
        out.append(-(f / (4 / 3 * d ** 1.5) - 1) / d)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", default=os.path.join(ROOT, "tests", "data", "fe"))
    args = ap.parse_args()
    curves = load(args.data)
    print(f"{len(curves)} FE curves from {os.path.relpath(args.data, ROOT)}:")
    for c in curves:
        print(f"  {c.path}: {c.name()}, x = {c.x.min():.2f}..{c.x.max():.2f}"
              + (" (held out)" if c.held_out else ""))
    print("\nSneddon's rigid sphere: F/F_H = 1 - g (a_H/R2)^2 with g =",
          ", ".join(f"{g:.5f}" for g in sneddon_coefficient()), "(a/R2 = 0.05, 0.1, 0.2)")
    fitted = [c for c in curves if not c.held_out]
    best = None
    for form, what in FORMS.items():
        coef = {cons: fit(fitted, cons, form) for cons in ("free", "flat")}
        coef["cap"] = form in (LAW, LAW_14, LAW_12, LAW_12_G3)
        print(f"\n## form `{form}`: {what}")
        for cons in ("free", "flat"):
            print(f"  {cons}: r0, r1, g0, g1[, q[, q2]] = {tuple(round(float(v), 6) for v in coef[cons])}")
        for c in curves:
            if c.kind == "edge":
                continue
            tag = "held out" if c.held_out else "fitted"
            print(f"  {c.name():32s} {tag:8s} force {100 * worst(c, coef):6.2f} %")
        if form == LAW:
            best = coef
    # Leave-one-out of the law's form: each fitted curve out of its construction's fit.
    print(f"\n## the law (`{LAW}`): its validity range against the FE's reach")
    for c in curves:
        if c.kind == "edge":
            continue
        _, _, rho, top = law(c, c.x, best)
        print(f"  {c.name():32s} rho = {rho:.3f}, law to x = {min(top, c.x.max()):.3f}, "
              f"FE to {c.x.max():.2f}")
    print(f"\n## `{LAW}`, each curve left out of the fit in turn (the only curve at its nu and construction: then an extrapolation in nu; nan: the law ends before x = 0.01)")
    for c in fitted:
        if c.kind == "edge":
            continue
        rest = [o for o in fitted if o is not c]
        coef = {c.construction: fit(rest, c.construction, LAW), "cap": True}
        print(f"  {c.name():32s} force {100 * worst(c, coef):6.2f} %")
    for cons in ("free", "flat"):
        e = fit_edge(fitted, cons)
        if e is not None:
            best["edge_" + cons] = e
            print(f"\n## edge {cons}: s = {e[0]:.6f}, rho = {e[1]:.6f}")
            for c in curves:
                if c.kind == "edge" and c.construction == cons:
                    print(f"  {c.name():32s} force {100 * worst(c, best):6.2f} %")
    print(f"\n## radius (law `{LAW}`) against the FE estimate a* (a_lin smoothed + 0.485 R/N), 0.1 <= x <= 0.4")
    for c in curves:
        for which, e in zip(("a", "b"), radius_errors(c, best)):
            if not len(e):
                continue
            print(f"  {c.name():32s} {which}: {100 * np.max(np.abs(e)):6.2f} % (mean {100 * np.mean(e):+.2f} %)")
    print(f"\n## cylinder semi-axes (law `{LAW}`) against the 3D FE (last node in contact, smoothed), "
          "0.1 <= x <= 0.4, raw and with the 3D mesh's bias on a plane removed")
    correct = plane_bias_3d(args.data)
    for c in curves:
        if c.kind != "cylinder":
            continue
        for name, raw, cor in cylinder_axes(c, best, correct):
            print(f"  {c.name():32s} {name:6s}: raw mean {100 * raw.mean():+5.1f} % (worst "
                  f"{100 * np.max(np.abs(raw)):4.1f} %), corrected mean {100 * cor.mean():+5.1f} % "
                  f"(worst {100 * np.max(np.abs(cor)):4.1f} %)")
    print("\nconstants (mapping.rs):",
          {k: tuple(round(float(v), 6) for v in p) for k, p in best.items() if k != "cap"})


if __name__ == "__main__":
    main()
