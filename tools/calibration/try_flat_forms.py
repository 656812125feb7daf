#!/usr/bin/env python3
"""Session 13: forms tried for the bonded pad at nu = 0.3 on the ball of R (3.46 % at x = 0.65-0.66,
the one curve past the issue's 3 %), each refitted as fit_counterpart.py fits the law (`fit`:
r0, r1, g0, g1, q, plus the form's own constant, on the non-held-out flat ball curves, minimax
to the FE's reach) and printed on every flat curve, fitted and held out. None was kept: each
that brings the ball of R under 3 % takes the held-out balls of 0.7 R at nu = 0.35 and 0.4 over
3 % (COUNTERPART.md, session 13).

  law        the law (session 12): the plane law's compressible cap times rho_H
  x55        + (4/3) h q2 eps (1 - rho_H) x^(11/2): the collapsed column re-stiffening (the
             compressible neo-Hookean's J^(-2/3) term past the bar's limit point), next order
  x55rho     the same times rho_H (vanishing on small balls, whose FE's J stops falling)
  cap1.5     the cap times rho_H^(3/2): the squeezed region's volume ~ a^3, not a^2 x depth
  cap2       the cap times rho_H^2
  bury       the collapse term times (1 - mu x): its excess fades as the ball buries itself in
             the pad (mu x -> 1 where Hertz's patch reaches the ball's radius)

Usage: python3 tools/calibration/try_flat_forms.py [--with-mid] [FORM ...]   (numpy + scipy; a
minute each; session 13's FE runs, SESSION_13, are printed as blind and join no fit;
--with-mid: the held-out curves at nu 0.35-0.45 join the fit)
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fit_counterpart as F  # noqa: E402
from scipy.optimize import least_squares, minimize  # noqa: E402

FORMS = ("law", "x55", "x55rho", "cap1.5", "cap2", "bury", "x55e2", "x55e2rho")
LAW_FLAT = (0.832134, -0.872566, 0.332105, -0.173477, 2.196058)


def law(c, x, p, form):
    """The flat pad's force on a ball (fit_counterpart.law with the form's change)."""
    r0, r1, g0, g1, q = p[:5]
    eps = min(F.eps_of(c.nu), F.EPS_VALIDATED)
    r, g = r0 + r1 * eps, g0 + g1 * eps
    h, _, _, mu = F.geometry(c)
    rho_h = h * h
    rho = 1 / (1 + r * (1 / rho_h - 1))
    cap = min(rho_h, 1.0) ** {"cap1.5": 1.5, "cap2": 2.0}.get(form, 1.0)
    f = h / rho ** 1.5 * F.f_plane(rho * x, c.nu, "flat", cap) - 4 / 3 * h * g * mu * x ** 2.5
    collapse = 4 / 3 * h * q * eps * (1 - rho_h) * x ** 3.5
    f = f + (collapse * (1 - mu * x) if form == "bury" else collapse)
    if form == "x55":
        f = f + 4 / 3 * h * p[5] * eps * (1 - rho_h) * x ** 5.5
    if form == "x55rho":
        f = f + 4 / 3 * h * p[5] * eps * (1 - rho_h) * rho_h * x ** 5.5
    if form == "x55e2":
        f = f + 4 / 3 * h * p[5] * eps * eps * (1 - rho_h) * x ** 5.5
    if form == "x55e2rho":
        f = f + 4 / 3 * h * p[5] * eps * eps * (1 - rho_h) * rho_h * x ** 5.5
    reach = 1 / mu if mu > 0 else np.inf
    return f, min(F.x_max_plane(c.nu, "flat") / rho, F.REACH["flat"], reach)


def worst(c, p, form):
    f, top = law(c, c.x, p, form)
    sel = (c.x >= 0.01 - 1e-12) & (c.x <= top + 1e-12)
    return np.max(np.abs(f[sel] / c.f[sel] - 1))


def fit(curves, form):
    """fit_counterpart.fit's procedure: least squares, then the 8th power towards minimax; a
    law whose range ends before the FE's reach pays for it."""
    p0 = list(LAW_FLAT) + ([0.0] if form.startswith("x55") else [])
    if form == "law":
        return p0
    sels = [(c.x >= 0.01 - 1e-12) & (c.x <= F.REACH["flat"] + 1e-12) for c in curves]

    def res(p, power):
        e = [(law(c, c.x, p, form)[0] / c.f - 1)[s] for c, s in zip(curves, sels)]
        # session 14: the nearly incompressible pad pays no range penalty (the bonded plane
        # law's x_max at rho x cannot reach its FE's end whatever the map)
        short = [0.0 if c.nu >= 0.49 else
                 max(0.0, min(c.x.max(), F.REACH["flat"]) - law(c, c.x[:1], p, form)[1])
                 for c in curves]
        e = np.concatenate(e + [10 * np.array(short)])
        e = np.where(np.isfinite(e), e, 10.0)
        return np.sign(e) * np.abs(e) ** (power / 2)

    p = least_squares(lambda q: res(q, 2), p0).x
    return minimize(lambda q: np.sum(res(q, 8) ** 2), p, method="Nelder-Mead",
                    options=dict(xatol=1e-8, fatol=1e-24, maxiter=8000)).x


# Session 13's FE runs (fe_campaign.py's held13): blind, in no fit.
SESSION_13 = {f"ball/flat/force_nu{nu}_k{k}.csv" for nu, k in
              [("0.3", "0.7"), ("0.33", "1.4"), ("0.3", "3"), ("0.37", "1"), ("0.3", "1.4")]}


def main():
    args = sys.argv[1:]
    mid = "--with-mid" in args
    forms = [a for a in args if not a.startswith("--")] or FORMS
    curves = [c for c in F.load(os.path.join(F.ROOT, "tests", "data", "fe"))
              if c.kind == "ball" and c.construction == "flat"]
    for c in curves:
        c.blind = os.path.relpath(c.path, os.path.join("tests", "data", "fe")) in SESSION_13
    # --with-mid: the campaign's held-out curves at 0.33 < nu < 0.46 join the fit (the forms
    # above miss them when fitted at nu 0.3, 0.48, 0.499 alone)
    # --with-499: the nearly incompressible pad on 2 R and 4 R (held out of fit_counterpart.py's
    # fit by its list LANDED_AFTER_FIT, not by their provenance) join the fit, without the
    # range penalty (`fit`)
    w499 = "--with-499" in args
    fitted = [c for c in curves
              if not c.blind and (not c.held_out or (mid and 0.33 < c.nu < 0.46)
                                  or (w499 and c.nu >= 0.49 and c.k in (2, 4)))]
    for form in forms:
        p = fit(fitted, form)
        print(f"## {form}: {tuple(round(float(v), 6) for v in p)}")
        for c in curves:
            tag = "blind" if c.blind else ("fitted" if c in fitted else "held out")
            print(f"  {c.name():28s} {tag:8s} {100 * worst(c, p, form):6.2f} %")


if __name__ == "__main__":
    main()
