#!/usr/bin/env python3
"""Session 33 (issue 24 item 5): the thin-skin form's film towards nu 0.5.

SFF (the law on main; try_deep_squeeze_s29.py, backed.rs `ShellForce`) squeezes the thin skin
(t/R < 0.3) by

    T' = 1 + (l0 + l1 eps) s + lc (mu/M) D(s) + cf psi(z') (Phi_c(s, tau) - 1),  z' = z/(1 - s)

and is too stiff in the deep squeeze of the nearly incompressible thin skins, the more so the
nearer nu is to 0.5 (CAX8, held out, t/R 0.12, delta/t 0.79: +1.27 % at nu 0.49, +9.90 % at
0.495, +22.32 % at 0.499), while nu 0.44-0.48 is 2-4.6 % too soft there (CORE_FORM.md, session
32). This script asks why, and judges forms exactly as try_deep_fade_s32.py does (the same sets,
the same refit on "fitted+" = the FITTED set of try_thin_skin_s26.sets() plus session 32's five
deep fit runs; held-out, blind and deep skins in no fit), with the held-out deep nu 0.499 t/R
0.12 CAX8 skin (tests/data/fe/core/cax8/k1e6/) and, when exported, session 33's held-out deep nu
0.497 t/R 0.15 CAX8 skin as their own groups.

`--need` prints, per thin curve of nu >= 0.44 at delta/t ~0.4, ~0.6 and its end: SFF's miss, the
film SFF has (`cf psi(z') (Phi_c - 1)`), the film the FE wants (that plus dsq,
try_deep_fade_s32's need), the film weight that is (in place of SFF's psi(z'), and over mu/M),
the skeleton's mean contact pressure over the bulk modulus q = p/K beside the FE's own largest
volumetric strain 1 - J (its `min_element_J` column), and the pressure-stiffened shear factor
G = (1 - q)^(-5/3) - 1 (alone and on the flow share psi(z')).
`--ratio` prints the nu 0.499 over the nu 0.49 t/R 0.12 deep skin: the FE's, SFF's, the skeleton's.
`--peak` prints the FE's peak (K (1 - min J)) over mean contact pressure against the h^-3 film's.
`--nhfilm` prints the exact finite-strain incompressible neo-Hookean squeezed film of a flat
bonded disc (lubrication limit) against the h^-3 forms.
`--var MODE ...` refits and prints max |F/F_FE - 1| per set, `--curves` per curve; modes:

  SFF  the law on main (not refitted)
  R    SFF's six refitted on fitted+ (the control: session 32's R)
  Z    the film dropped (cf = 0), the other five refitted (what is left with no film)
  J    the film replaced by the pressure-stiffened shear of the compressible neo-Hookean film,
       cj ((1 - q)^(-5/3) - 1), q = p/K from the skeleton (module docs of pressure_q); cj fitted
  Jt   J with cj = 1 (theory), the other five refitted
  JF   J and SFF's film both (cf and cj fitted)
  Jp   J on the flow share at the unthinned crossover, cj psi(z) ((1 - q)^(-5/3) - 1)
  Jq   J on the flow share at the thinned crossover, cj psi(z') ((1 - q)^(-5/3) - 1)
  Jpt, Jqt  the same with cj = 1
  c    (suffix) q from the form's own chi (its squeeze before the J term, coupling included)
       over the skeleton's chi0 = chi_flat + excess: the film's pressure as the form has it
  W    (with F) SFF's film on the unsqueezed skin's confined share, cf psi(z') (1 - psi(z))
       (Phi_c - 1): no h^-3 film for the incompressible skin
  k    (suffix) SFF's coupling k0, k1 kept
  A    SFF's film attenuated towards nu 0.5 by (mu/M)/((mu/M) + m0), m0 fitted (the FE's deep
       film weight is ~17.5 mu/M near nu 0.5, `--need`); As: SFF's six kept, only m0 fitted
  N    cj (mu/M) (Phi_c - 1), cf = 0: the film weighted by the compressibility, no flow share
  H    SFF's film weighted by the skin's compressibility: cj (mu/M) psi(z') (Phi_c - 1), cf = 0

usage: PY tools/calibration/try_film_nu_s33.py [--need] [--nhfilm] [--ratio] [--peak] [--var MODE ...] [--curves]
           [--check-form MODE]
       (PY: /work/main/target/fe-venv/bin/python, under nice -n 10)
"""
import argparse
import os
import sys
import time

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
import fit_core as f  # noqa: E402
import try_deep_fade_s32 as s32  # noqa: E402
import try_deep_squeeze_s29 as s29  # noqa: E402
import try_shell_table_s28 as s28  # noqa: E402
import try_thin_skin_s25 as s25  # noqa: E402

SFF = s29.SFF
S33_HELD = ((0.497, 0.15),)  # session 33's deep CAX8 run, declared held out before any form


def pressure_q(x, nu, tau):
    """The thin skin's mean contact pressure over its bulk modulus, from the skeleton (no fitted
    constant): p = chi0 F_Hertz / (pi a^2), chi0 = chi_flat + (chi_shell - chi_hemi) (the
    small-strain shell on its core), a = the law's core radius; F_Hertz = (4/3) E* R^2 x^1.5, K
    = E*(1 - nu^2)/(3 (1 - 2 nu)): q = p/K = chi0 (4/3) x^1.5 / (pi a^2) 3 (1 - 2 nu)/(1 - nu^2)."""
    x = np.asarray(x, dtype=float)
    chi0 = f.chi_flat(x, nu) + s28.chi_shell(x, nu, min(tau, s28.TAUS[-1])) - s28.chi_hemi(x, nu, "F")
    a = f.radius(x, nu, tau)[1]
    return chi0 * 4 / 3 * x ** 1.5 / (np.pi * a * a) * 3 * (1 - 2 * nu) / (1 - nu * nu)


def stiffened(q):
    """(1 - q)^(-5/3) - 1: the compressible neo-Hookean's (CalculiX NEO HOOKE, U = C10 (I1bar - 3)
    + (J - 1)^2 / D1) deviatoric Cauchy stress is mu J^(-5/3) dev(B), so a film compressed in
    volume to J = 1 - p/K shears with mu J^(-5/3)."""
    return (1 - np.minimum(q, 0.9)) ** (-5 / 3) - 1


def form(mode):
    if mode == "SFF":
        return s29.form("SFF")

    def chi(p, x, nu, tau):
        if np.ndim(tau):
            return np.array([float(np.squeeze(chi(p, np.array([x]), nu, float(t)))) for t in tau])
        x = np.asarray(x, dtype=float)
        w = s28.weight(tau, "SFB0030")
        out_law = s32._LAW_K(s32.LAW, x, nu, tau) if w < 1 else 0.0
        if w <= 0:
            return out_law
        l0, l1, k0, k1, lc, cf = p[:6]
        cj = p[6] if len(p) > 6 else 0.0
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        excess = s28.chi_shell(x, nu, min(tau, s28.TAUS[-1])) - s28.chi_hemi(x, nu, "F")
        s = x / tau
        share = eps / (1 + 4 * eps / 3)
        film = s25.psi(s32.z_of(x, nu, tau) / (1 - s)) * (s29.phi_c(s, tau) - 1)
        if "W" in mode:  # SFF's film on the confined share of the unsqueezed skin only
            film = film * (1 - s25.psi(s32.z_of(x, nu, tau)))
        if "A" in mode:  # the film attenuated towards nu 0.5: (mu/M)/((mu/M) + |m0|)
            film = film * share / (share + abs(cj))
        squeeze = (l0 + l1 * eps) * s + lc * share * f.confined(s) + cf * film
        if "J" in mode:
            q = pressure_q(x, nu, tau)
            if "c" in mode:  # the form's own pressure (its squeeze before this term), not the skeleton's
                cpl = np.exp(-(k0 + k1 * eps) * (fl - 1))
                q = q * (fl + excess * (1 + squeeze) * cpl) / (fl + excess)
            g = stiffened(q)
            if "p" in mode:
                g = g * s25.psi(s32.z_of(x, nu, tau))
            if "q" in mode:
                g = g * s25.psi(s32.z_of(x, nu, tau) / (1 - s))
            squeeze = squeeze + cj * g
        if "H" in mode:  # the film weighted by the skin's compressibility, cj (mu/M) in place of cf
            squeeze = squeeze + cj * share * film
        if "N" in mode:  # cj (mu/M) (Phi_c - 1): no flow share
            squeeze = squeeze + cj * share * (s29.phi_c(s, tau) - 1)
        shell = fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
        return w * shell + (1 - w) * out_law
    return chi


def fit_mode(mode, train):
    if mode == "SFF":
        return form("SFF"), list(SFF)
    chi = form(mode)
    full = np.array(list(SFF) + ([0.0] if any(k in mode for k in "JHN") else
                                 [0.01] if "A" in mode else []), dtype=float)
    idx = list(range(len(full)))
    if "s" in mode:  # SFF's six kept, only the added constant fitted
        idx = [6]
    elif mode != "R" and "F" not in mode and "A" not in mode:  # no film of SFF's kind
        full[5] = 0.0
        idx.remove(5)
    if "t" in mode:  # the pressure-stiffened shear at its theory amplitude
        full[6] = 1.0
        idx.remove(6)
    if "k" in mode:  # SFF's coupling k0, k1 kept
        idx.remove(2)
        idx.remove(3)

    def sub(q, x, nu, tau):
        pp = full.copy()
        pp[idx] = q
        return chi(pp, x, nu, tau)
    f.chi_core = sub
    q = f.fit(train, list(full[idx]))
    p = full.copy()
    p[idx] = q
    return chi, p


def groups():
    gs = list(s32.groups())
    extra = s32.k1e6(S33_HELD, s29.DEEP_K1E6)
    if extra:
        gs.insert(-1, ("s33 held CAX8 (0.497, 0.15)", extra))
    return gs


_S32_TAGGED = s32.tagged_curves


def tagged_curves():
    return (_S32_TAGGED()
            + [("s32held499 CAX8", c) for c in s32.k1e6(s32.S32_HELD_499, s29.DEEP_K1E6)]
            + [("s33held CAX8", c) for c in s32.k1e6(S33_HELD, s29.DEEP_K1E6)])


def min_j(c):
    path = os.path.join(f.DATA, c["name"])
    try:
        d = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        return np.interp(c["x"], d["delta_over_R"], d["min_element_J"])
    except (ValueError, KeyError, OSError):
        return np.full_like(c["x"], np.nan)


def need():
    s32.tagged_curves = tagged_curves  # the same need, with the nu 0.499 (and 0.497) skins
    cf = SFF[5]
    for r in s32.need_rows():
        c, s = r["c"], r["s"]
        if c["nu"] < 0.44:
            continue
        q = pressure_q(c["x"], c["nu"], c["tau"])
        jfe = min_j(c)
        print(f"{r['tag']} ({c['nu']:g}, {c['tau']:g}) w {r['w']:.2f} mu/M {r['share']:.3f} {c['name']}")
        for i in sorted({int(np.argmin(np.abs(s - 0.4))), int(np.argmin(np.abs(s - 0.6))),
                         len(s) - 1}):
            film = cf * r["p1"][i] * r["phi"][i]
            wanted = film + r["dsq"][i]
            weight = wanted / (cf * r["phi"][i]) if r["phi"][i] > 0.05 else np.nan
            print(f"    s {s[i]:.2f}: SFF {r['err'][i]:+.2f} %, film {film:.3f}, wanted "
                  f"{wanted:+.3f}; film weight wanted {weight:+.3f} (SFF's psi(z') "
                  f"{r['p1'][i]:.3f}; over mu/M {weight / r['share']:+.1f}); q {q[i]:.4f} (FE 1 - "
                  f"min J {1 - jfe[i]:.4f} = {(1 - jfe[i]) / q[i]:.2f} q), G = (1-q)^-5/3 - 1 = "
                  f"{float(stiffened(q[i])):.3f}, psi(z') G {r['p1'][i] * float(stiffened(q[i])):.3f}")


def ratio():
    """The nu 0.499 over the nu 0.49 skin at t/R 0.12 (both CAX8, penalty 1e6): the FE's chi ratio
    against SFF's and the skeleton's (the small-strain shell's excess, chi_shell - chi_hemi), and
    SFF's film cf psi(z') (Phi_c - 1) on each."""
    cs = {c["nu"]: c for c in s32.k1e6(((0.49, 0.12), (0.499, 0.12)), s29.DEEP_K1E6)}
    sff = form("SFF")
    print("| x (delta/t) | FE chi 0.499 / 0.49 | SFF's | skeleton excess' | SFF's film 0.49 / 0.499 |")
    print("|---|---|---|---|---|")
    for x in (0.02, 0.04, 0.06, 0.08, 0.095):
        row = []
        for nu in (0.49, 0.499):
            c = cs[nu]
            fe = float(np.interp(x, c["x"], c["chi"]))
            xx = np.array([x])
            ex = float(np.squeeze(s28.chi_shell(xx, nu, 0.12) - s28.chi_hemi(xx, nu, "F")))
            film = SFF[5] * float(np.squeeze(s25.psi(s32.z_of(xx, nu, 0.12) / (1 - x / 0.12))
                                              * (s29.phi_c(x / 0.12, 0.12) - 1)))
            row.append((fe, float(np.squeeze(sff(SFF, xx, nu, 0.12))), ex, film))
        (a, b) = row
        print(f"| {x:g} ({x / 0.12:.2f}) | {b[0] / a[0]:.3f} | {b[1] / a[1]:.3f} | "
              f"{b[2] / a[2]:.3f} | {a[3]:.3f} / {b[3]:.3f} |")


def peak():
    """The FE's peak pressure over its mean contact pressure in the squeeze, against the squeezed
    film's. FE: peak = K (1 - min J) (CalculiX's volumetric law p = (2/D1)(1 - J) = K (1 - J):
    the largest hydrostatic pressure, wherever its element is), mean = F / (pi a^2) with the
    FE's contact radius. Film: lubrication in the gap h(v) = t (1 - s + 2 s v/(1 - tau)) between
    the plane and the core's sphere, patch fixed, p(a) = 0: p(v) ~ int_v^1 dv'/h^3, so peak/mean
    = int_0^1 h^-3 dv / int_0^1 v h^-3 dv (2 for a uniform gap; Matthewson's p = p' = 0 rim gives
    3 at small strain)."""
    print("| skin | delta/t | FE peak [mu] | FE mean [mu] | FE peak/mean | film peak/mean |")
    print("|---|---|---|---|---|---|")
    for nu, t in ((0.49, 0.12), (0.495, 0.12), (0.497, 0.15), (0.499, 0.12)):
        c = s32.k1e6(((nu, t),), s29.DEEP_K1E6)[0]
        d = np.genfromtxt(os.path.join(f.DATA, c["name"]), delimiter=",", names=True,
                          skip_header=1)
        k = 2 * (1 + nu) / (3 * (1 - 2 * nu))  # K / mu
        for sq in (0.1, 0.4, 0.6, 0.79):
            i = int(np.argmin(np.abs(d["delta_over_R"] - sq * t)))
            x = d["delta_over_R"][i]
            s = x / t
            h = lambda v: 1 - s + 2 * s * v / (1 - t)  # noqa: E731
            film = quad(lambda v: h(v) ** -3, 0, 1)[0] / quad(lambda v: v * h(v) ** -3, 0, 1)[0]
            pk = k * (1 - d["min_element_J"][i])
            pm = d["force_N"][i] / (np.pi * d["contact_radius_mm"][i] ** 2)
            print(f"| {nu:g}/{t:g} | {s:.2f} | {pk:.2f} | {pm:.2f} | {pk / pm:.2f} | {film:.2f} |")


def nhfilm():
    """The flat bonded incompressible neo-Hookean disc in the lubrication limit (radius a >> t):
    x_r = R g(Z), x_z = w(Z), det F = g^2 w' = 1; the shear energy (mu/2) R^2 g'^2 dominates, and
    its minimiser under int_0^t g^-2 dZ = h is g^2 = 1 + K zeta (1 - zeta), zeta = Z/t (exact
    within the ansatz: the Euler-Lagrange g'' = -L/g^3 integrates to it). E = (mu pi a^4/(16 t))
    int K^2 (1 - 2 zeta)^2/(1 + K zeta (1 - zeta)) dzeta; F = dE/d delta. Small strain: F =
    (3 pi mu a^4/(2 t^3)) delta (the linear lubrication layer)."""
    lam = lambda k: quad(lambda z: 1 / (1 + k * z * (1 - z)), 0, 1)[0]  # noqa: E731
    en = lambda k: quad(lambda z: k * k * (1 - 2 * z) ** 2 / (1 + k * z * (1 - z)), 0, 1)[0] / 16  # noqa: E731
    k_of = lambda s: brentq(lambda k: lam(k) - (1 - s), 0, 1e9) if s > 0 else 0.0  # noqa: E731
    print("| s = delta/t | NH exact F / F_small | (t/h)^3 = (1-s)^-3 (the film as a secant, Phi's "
          "kind) | h^-3 tangent integrated ((1-s)^-2 - 1)/(2 s) | NH over (1-s)^-3 |")
    print("|---|---|---|---|---|")
    for s in (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.79):
        d = 1e-5
        F = (en(k_of(s + d)) - en(k_of(s - d))) / (2 * d)
        nh = F / (1.5 * s)
        print(f"| {s:.2f} | {nh:.3f} | {(1 - s) ** -3:.3f} | {((1 - s) ** -2 - 1) / (2 * s):.3f} | "
              f"{nh / (1 - s) ** -3:.3f} |")


def fit_table(modes, curves_too=False):
    gs = groups()
    train = gs[0][1]
    print("| form | " + " | ".join(g for g, _ in gs) + " |")
    print("|---" * (len(gs) + 1) + "|")
    fits = {}
    for mode in modes:
        t0 = time.time()
        chi, p = fit_mode(mode, train)
        fits[mode] = (chi, p)
        cells = []
        for _, cs in gs:
            v = max(((s29.signed(p, c, chi), c) for c in cs), key=lambda r: abs(r[0][0]))
            cells.append(f"{abs(v[0][0]):.2f} ({v[1]['nu']:g}, {v[1]['tau']:g})")
        print(f"| {mode} | " + " | ".join(cells) + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) + f"  ({time.time() - t0:.0f} s)",
              flush=True)
    if curves_too:
        s32.tagged_curves = tagged_curves
        s32.per_curve(modes, fits)
    return fits


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--var", nargs="*")
    ap.add_argument("--curves", action="store_true")
    ap.add_argument("--check-form")
    ap.add_argument("--need", action="store_true")
    ap.add_argument("--nhfilm", action="store_true")
    ap.add_argument("--ratio", action="store_true")
    ap.add_argument("--peak", action="store_true")
    a = ap.parse_args()
    if a.nhfilm:
        nhfilm()
    if a.ratio:
        ratio()
    if a.peak:
        peak()
    if a.need:
        need()
    if a.var:
        fits = fit_table(a.var, a.curves)
        if a.check_form:
            chi, p = fits[a.check_form]
            f.chi_core = chi
            print(a.check_form, f.check(p))
    return 0


if __name__ == "__main__":
    sys.exit(main())
