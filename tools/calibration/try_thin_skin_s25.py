#!/usr/bin/env python3
"""Session 25 (issue 24 item 5): the thin skins on a core against the re-run FE (penalty 1e6
MPa/mm, ~9 elements through the skin: tools/fe/fe_thin_rerun.py, tests/data/fe/core/k1e6/),
and thin-layer forms that carry both of the thin layer's limits through Matthewson's
crossover.

The sets are session 24's (try_thin_skin_s23.training: the 14 fitted t/R 0.2-0.8 with the CAX8
nu 0.48 t/R 0.4 curve, the five thin fit skins t/R 0.05-0.1, 21 held out t/R 0.1-0.8, seven
blind t/R 0.06-0.08, the blind CAX8 deep skins). With --new every curve that has a re-run
(tests/data/fe/core/k1e6/force_nu{NU}_t{T}.csv, or its run directory under --runs when not
exported yet) is replaced by it, in whatever set it was; the rest keep the committed curves.

Forms (`form(mode)`, letters combined; each refitted on the fitted set: the law's eight
constants plus one per C, O, P, and B without 5). `law` is the Rust law unrefitted (backed.rs
CORE, CORE_DEVIATORIC: s23.form("K")); K is that form refitted.
  M   the series' second order cut by Matthewson's bonded thin layer's crossover in place of
      1/(1 + eps u^2): the flat punch on a layer of depth t bonded to a rigid base has
      stiffness k = (pi a^2 M/t) (1 - 2 I1(z)/(z I0(z))), z = a/lambda, lambda = t sqrt(M/(3
      mu)): the oedometer pi a^2 M/t (compressible thin layer) for a >> lambda, the bonded
      incompressible layer 3 pi mu a^4/(8 t^3) for a << lambda. psi(z) = 8 (1 - 2 I1/(z I0))/z^2
      (1 at z = 0, 8/z^2 for z >> 1) is the second order's share; no constant
  C   the incompressible thin layer's cubic growth while a < lambda: + c3 v^3 psi(z)
  O   the compressible thin layer's oedometer once a > lambda: + c_o (M/E*) v (1 - psi(z))
      (Winkler's (3 pi/4) (M/E*) u in the thin limit)
  P   the law's thin-layer floor with its p-norm power fitted (session 20b's F)
  B   the floor is Matthewson's thin layer with the patch widened by a fringe beta t
      (u -> u + beta, beta fitted; B5: 0.5 fixed; U: the fringe grows as u^2/(1 + u^2));
      `--fringe` measures the beta the FE wants (0.40-0.67 at nu >= 0.38)
  G   the floor on chi itself (thin layer against the whole law, chi_flat included), not on
      the excess over 1
  H   the floor's layer at the skin's mean depth t h (the series' depth) instead of t
  X   the floor's p-norm power 16 (a near max) instead of 4: where the thin layer and the series
      are close, the power-4 norm adds up to 2^(1/4) - 1 = 19 %
  S   the layer seen at the patch's mean thinned depth t (1 - c_s s) (S5: c_s = 0.5)

usage: PY tools/calibration/try_thin_skin_s25.py [--new] [--runs DIR] [--var MODE ...]
       [--curves MODE ...] [--fringe]
       (PY: /work/main/target/fe-venv/bin/python)
"""
import argparse
import os
import sys

import numpy as np
from scipy.special import i0e, i1e

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
import fit_core as f  # noqa: E402
import try_thin_skin_s20 as s20  # noqa: E402
import try_thin_skin_s20b as b  # noqa: E402
import try_thin_skin_s23 as s23  # noqa: E402
import try_thin_skin_s24 as s24  # noqa: E402

K1E6 = os.path.join(f.DATA, "k1e6")
LAW = s24.LAW


def new_curve(nu, tau, runs):
    """The session-25 re-run of a skin as a fit_core curve, or None."""
    path = os.path.join(K1E6, f"force_nu{nu:g}_t{tau:g}.csv")
    if os.path.exists(path):
        x, F = s23.curve_csv(path)
        where = os.path.relpath(path, f.DATA)
    else:
        import fe_thin_rerun as r
        name = r.case_name(nu, tau)
        if name not in r.CASES:
            return None
        res = r.analyse(name, runs)
        if res is None or len(res["rows"]) < 2:
            return None
        x = np.array([q["x"] for q in res["rows"]])
        F = np.array([q["F"] for q in res["rows"]])
        where = name + " (run dir)"
    c = s23.as_curve(nu, tau, x, F, where)
    return c if len(c["x"]) else None


def sets(new, runs):
    train, thin, held, blind, dblind = s23.training("/work/fe-scratch/runs/deep-s23", False)
    out = []
    for cs in (train, thin, held, blind):
        rep = []
        for c in cs:
            n = new_curve(c["nu"], c["tau"], runs) if new else None
            if n is not None:
                n["held"] = c["held"]
            rep.append(n if n is not None else c)
        out.append(rep)
    train, thin, held, blind = out
    thin = [c for c in train if c["tau"] < 0.15]
    return train, thin, held, blind, dblind


def psi(z):
    """8 (1 - 2 I1(z) / (z I0(z))) / z^2: Matthewson's bonded thin layer's crossover, the flat
    punch's stiffness over its incompressible limit (1 at z = 0, 8/z^2 for z >> 1)."""
    z = np.maximum(np.asarray(z, dtype=float), 1e-6)
    small = z < 1e-2
    r = 8 * (1 - 2 * i1e(z) / (z * i0e(z))) / (z * z)
    return np.where(small, 1 - z * z / 6, r)


def form(mode):
    def chi(p, x, nu, tau):
        e0, l0, l1, k0, k1, m, lc, cd = p[:8]
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        a_flat, a_core = f.radius(x, nu, tau)
        h = 1 + tau * tau / (1 - tau)
        t1 = f.dimitriadis_d1(nu) / 3 * np.sqrt(x) / (tau * h)
        wid = a_core / a_flat - 1
        a_core = a_flat * (1 + t1 * wid / np.sqrt(t1 * t1 + wid * wid + 1e-300))
        d1, e = f.dimitriadis_d1(nu), e0 * np.exp(-m * eps)
        m_mu = 2 * (1 - nu) / (1 - 2 * nu) if nu < 0.5 else 1e12  # M/mu
        z2_skin = 3 / m_mu * x / tau ** 2  # (a_H / lambda)^2, lambda = t sqrt(M/(3 mu))
        z2_hemi = 3 / m_mu * x

        es = 2 / (1 - nu)  # E*/mu
        extra = list(p[8:])

        def layer(v, z2, conf):
            if "M" in mode:  # the second order cut by Matthewson's crossover
                out = v * (d1 + e * v * psi(np.sqrt(z2)))
            else:  # the law's: cut by 1/(1 + eps u^2)
                out = v * (d1 + e * v / (1 + conf))
            q = 0
            if "C" in mode:  # the incompressible thin layer's cubic, while a < lambda
                out = out + extra[q] * v ** 3 * psi(np.sqrt(z2))
                q += 1
            if "O" in mode:  # the compressible thin layer's oedometer, once a > lambda
                out = out + extra[q] * (m_mu / es) * v * (1 - psi(np.sqrt(z2)))
                q += 1
            return out
        if "S" in mode:  # the layer seen at the patch's mean thinned depth t (1 - c_s s)
            c_s = 0.5 if "S5" in mode else extra[-1]
            tau_s = tau * (1 - np.clip(c_s, 0, 0.9) * x / tau)
        else:
            tau_s = tau
        z2_skin = 3 / m_mu * x / tau_s ** 2
        excess = (layer(a_core / (tau_s * h), z2_skin, eps * x / tau_s ** 2)
                  - layer(a_flat / h, z2_hemi, eps * x))
        if "B" in mode:  # Matthewson's layer with the patch widened by the fringe, beta t
            beta = 0.5 if "B5" in mode else extra[-1]
            u = np.sqrt(x) / tau
            if "U" in mode:  # the fringe grows as the patch outgrows the skin
                beta = beta * u * u / (1 + u * u)
            # G: the floor on chi itself (the thin layer's F/F_H against the whole law, the
            # hemisphere's chi_flat included), not on the excess over 1
            base = fl if "G" in mode else 1.0
            depth = tau * h if "H" in mode else tau  # H: at the skin's mean depth t h
            u = np.sqrt(x) / depth
            limit = np.clip(s20.thin_limit(x, nu, depth * u / (u + np.abs(beta))) - base, 0,
                            None)
        else:
            limit = np.clip(s20.thin_limit(x, nu, tau_s) - 1, 0, None)
        power = abs(p[-1]) if mode == "P" else (16.0 if "X" in mode else 4.0)
        excess = (np.abs(excess) ** power + limit ** power) ** (1 / power)
        s = x / tau
        squeeze = (l0 + l1 * eps) * s + (lc * eps / (1 + 4 * eps / 3) + cd) * f.confined(s)
        return fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
    return chi


def p0_of(mode):
    return (list(LAW) + [0.0] * sum(k in mode for k in "CO") + ([4.0] if "P" in mode else [])
            + ([0.5] if "B" in mode and "B5" not in mode else [])
            + ([0.5] if "S" in mode and "S5" not in mode else []))


def fringe(groups):
    """The patch widening beta (in skin thicknesses) at which Matthewson's thin layer gives the
    layer excess the FE wants under the law's own squeeze and coupling: X_FE = (chi_FE -
    chi_flat) / ((1 + squeeze) coupling) = chi_thin(u + beta) - 1, u = a_H / t, per point of
    every skin of t/R <= 0.15 at x <= 0.045 (the law unrefitted)."""
    from scipy.optimize import brentq
    e0, l0, l1, k0, k1, m, lc, cd = LAW
    rows = []
    for tag, cs in groups:
        for c in cs:
            if c["tau"] > 0.15:
                continue
            nu, tau = c["nu"], c["tau"]
            eps = f.eps_of(nu)
            for x, chi in zip(c["x"], c["chi"]):
                if x > 0.045 + 1e-9:
                    continue
                fl = f.chi_flat(x, nu)
                s = x / tau
                sq = (l0 + l1 * eps) * s + (lc * eps / (1 + 4 * eps / 3) + cd) * f.confined(s)
                want = (chi - fl) / ((1 + sq) * np.exp(-(k0 + k1 * eps) * (fl - 1)))
                u = np.sqrt(x) / tau

                def g(k):
                    return s20.thin_limit(np.array([x]), nu, tau / k)[0] - 1 - want
                try:
                    k = brentq(g, 0.5, 5)
                except ValueError:
                    k = np.nan
                rows.append((nu, u, tau, x, u * (k - 1), tag, "*" if "k1e6" in c["name"] else ""))
    print("| nu | u = a_H/t | t/R | x | beta | set |")
    print("|---|---|---|---|---|---|")
    for nu, u, tau, x, beta, tag, mark in sorted(rows):
        print(f"| {nu:g} | {u:.2f} | {tau:g} | {x:g} | {beta:.3f} | {tag}{mark} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--new", action="store_true", help="the k1e6 re-runs in place")
    ap.add_argument("--runs", default="/work/fe-scratch/s25-skin")
    ap.add_argument("--var", nargs="*")
    ap.add_argument("--curves", nargs="*")
    ap.add_argument("--fringe", action="store_true", help="the patch widening Matthewson's "
                    "thin layer needs to give the FE's excess (see `fringe`)")
    a = ap.parse_args()
    train, thin, held, blind, dblind = sets(a.new, a.runs)
    replaced = [c["name"] for c in train + held + blind if "k1e6" in c["name"]]
    print(f"data: {'re-runs in place: ' + ', '.join(replaced) if a.new else 'committed'}")
    old = [c for c in train if c not in thin]
    groups = (("fitted", train), ("the 14", old), ("thin fit", thin), ("held out", held),
              ("blind", blind), ("deep CAX8 blind", dblind))
    if a.fringe:
        fringe((("fit", train), ("held", held), ("blind", blind)))
    fits = {}
    for mode in (a.var or []) + [m for m in (a.curves or []) if m not in (a.var or [])]:
        f.chi_core = form("K" if mode == "law" else mode)
        p = LAW if mode == "law" else f.fit(train, p0_of(mode))
        fits[mode] = p
    if a.var:
        print("| form | " + " | ".join(g for g, _ in groups) + " | check |")
        print("|---" * (len(groups) + 2) + "|")
        for mode in a.var:
            f.chi_core = form("K" if mode == "law" else mode)
            p = fits[mode]
            print(f"| {mode} | " + " | ".join(b.worst(p, cs) for _, cs in groups) +
                  f" | {f.check(p)} |", flush=True)
            print("    constants " + " ".join(f"{v:.6f}" for v in p))
    if a.curves:
        print("| curve | " + " | ".join(a.curves) + " |")
        print("|---" * (len(a.curves) + 1) + "|")
        tagged = [("fit", c) for c in train] + [("held", c) for c in held] + \
                 [("blind", c) for c in blind] + [("deep", c) for c in dblind]
        for tag, c in sorted(tagged, key=lambda tc: (tc[0], tc[1]["tau"], tc[1]["nu"])):
            cells = []
            for mode in a.curves:
                f.chi_core = form("K" if mode == "law" else mode)
                w, x = f.worst(fits[mode], c)
                cells.append(f"{w:.2f} (x {x:g})")
            mark = " *" if "k1e6" in c["name"] else ""
            print(f"| {tag} ({c['nu']:g}, {c['tau']:g}){mark} | " + " | ".join(cells) + " |")
        for tag, c in tagged:
            if c["tau"] <= 0.15:
                for mode in a.curves:
                    f.chi_core = form("K" if mode == "law" else mode)
                    print(f"    {mode:4s} {tag} " + s23.s21.line(c, fits[mode]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
