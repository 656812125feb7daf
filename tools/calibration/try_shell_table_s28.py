#!/usr/bin/env python3
"""Session 28 (issue 24 item 5): the exact small-strain shell on its core, tabulated in (nu, t/R,
u = a_H/t), as the law's skeleton in place of its layer excess.

Session 27 (CORE_FORM.md "Thin skins: the shell on its core at small strain" and "the shell
skeleton refit") found the exact small-strain shell bonded to a rigid core
(`shell_on_core_s27.chi_at`, radial reading) within 1 % of the FE's small-strain limit on all 17
thin skins and within 1.8 % up to t/R 0.5, but as a first-order factor (1 + tau g) on the law's
excess it counts the core's curvature twice (the law's mean depth h and its subtracted depth-R
layer are fitted stand-ins for it). Here the law's excess itself,
`layer(a_core/(t h)) - layer(a_flat/h)` (and its thin-layer floor, a small-strain stand-in for
the same shell), is replaced by the shell's:

    excess = chi_shell(x, nu, tau) - chi_hemi(x, nu)

with the shell's own tau dependence (not its first order) to t/R 0.5, and the law's squeeze and
coupling refitted on top; past the shell's validity the current law (blend below).

The table (`--table`, cached in `shell_table_s28.npz` beside this file; the t/R 0.05 row is
session 27's `shell_g_s27.npz`, the same solves):

    G(nu, tau, u) = (chi_shell(x, nu, tau)/chi_lin(u, nu) - 1)/tau,   x = (u tau)^2,

chi_lin the exact flat bonded layer (`thin_layer_exact_s27.chi_lin`, evaluated at the query nu,
nothing interpolated in it), so chi_shell = chi_lin (1 + tau G); G is session 27's g at t/R 0.05
and varies slowly with tau (-0.142 / -0.160 at t/R 0.05 / 0.4, nu 0.3, u 0.25). Grid: nu NUS (7)
x t/R TAUS (8) x u (per t/R node: session 27's 13 values of u up to the domain of the next
thinner node, x = 0.8 t'/R, plus that edge; 7-13 per node). Interpolant (`G_of`): per t/R node a
bicubic spline in (nu, ln u), G linear in u to 0 below u 0.1 and held past the node's last u;
across the nodes a cubic spline in t/R (not-a-knot); held at the 0.05 node below t/R 0.05 (there
chi_shell = chi_lin (1 + tau g), session 27's first order) and at the 0.6 node above it.
`--interp` checks it against direct solves at off-grid points.

chi_hemi, the bonded hemisphere's own small-strain chi at the same x (what chi_flat carries and
the excess must not count again), in two readings:
  L  the exact flat bonded layer of depth R, chi_lin(sqrt(x), nu): the law's own stand-in
     `layer(a_flat/h)` (Dimitriadis' series of a layer of depth R) made exact; nothing fitted
  F  the flat law's own first order, 1 + (c0 + c1 eps) sqrt(x) (FLAT's c0, c1): the hemisphere's
     small-strain excess as chi_flat has it fitted (the FE hemisphere, whose depth thins away
     from the pole, is softer than a depth-R layer: c0 + c1 eps 0.52-0.68 against d1 0.88-1.13)

Forms (`form(mode)`; letters; constants refitted on the FITTED set only, s26.sets()):
  S   chi = chi_flat + (chi_shell - chi_hemi) (1 + squeeze) exp(-k (chi_flat - 1)), the law's
      squeeze (l0 + l1 eps) s + (lc eps/(1 + 4 eps/3) + cd) D(s) and coupling k = k0 + k1 eps:
      six constants (l0, l1, k0, k1, lc, cd; e0 and m, the layer's second order, drop out)
  SL / SF  chi_hemi reading L / F (S alone = SL)
  N   the coupling on the hemisphere's large-deformation stiffening only, chi_flat - chi_hemi
      (chi_flat - 1 also holds the hemisphere's small-strain excess, which the shell's
      subtraction already handles)
  B<a><b>  the blend to the current law (s25.form("K"), LAW, unrefitted) in t/R: shell form
      alone to t/R a/10, the law alone from b/10, a C1 smoothstep between (default B56: 0.5,
      0.6, session 27: the shell within 1.8 % of the FE to t/R 0.5, not past 0.55);
      B<aa><bb> (four digits): the same in hundredths (B0030: a fade from t/R 0 to 0.3)
  Q   the squeeze's slope l0 + l1 sqrt(eps); E: l0 + l1 eps/(eps + e_c), e_c fitted (seven)
  O1 / O2  the confined term's share mu/M times / replaced by the oedometric share 1 - psi(z)
  A   the shell read at the hemisphere's finite-strain patch, x -> a_flat(x)^2

Result (CORE_FORM.md "Thin skins: the shell table as the skeleton, session 28"): the table's
interpolant is within 0.012 % of direct solves at 16 off-grid points. The brief's form (SF: the
shell to t/R 0.5, blend to the law by 0.6, six constants) is worse than the law on the 14, held
out and deep CAX8 (4.86 / 6.01 / 6.05 % against 2.52 / 3.70 / 2.90; the thick skins at finite x);
SL (the depth-R exact layer as the hemisphere) far worse. SFE (seven constants) is better fitted
/ thin / blind but not held out / deep. Only a fade beats the law on every set: SFB0030 (the
shell form faded into the law by t/R 0.3) 2.42 / 2.42 / 2.06 / 2.84 / 2.88 / 2.49 % (fitted /
the 14 / thin fit / held out / blind / deep CAX8) against 6.21 / 2.52 / 6.21 / 3.70 / 5.89 /
2.90, with its fade's end chosen after the held-out and blind numbers were seen; 7 of 55 curves
worse by more than 0.1 %. Not ported.

usage: PY tools/calibration/try_shell_table_s28.py [--table] [--show] [--interp] [--hemi] [--need]
           [--var MODE ... [--curves] [--check-form MODE]]
       (PY: /work/main/target/fe-venv/bin/python; run under nice -n 10)
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))

NUS = (0.3, 0.35, 0.4, 0.45, 0.48, 0.49, 0.499)
TAUS = (0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6)
US = (0.1, 0.15, 0.25, 0.35, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0)
X_DOMAIN = 0.53  # the law's x_max = min(flat_x_max(nu) <= 0.53, 0.8 t/R)
NPZ = os.path.join(HERE, "shell_table_s28.npz")
NPZ_G = os.path.join(HERE, "shell_g_s27.npz")


def u_cover(j):
    """The largest u the t/R node j must hold: the domain of the next thinner node (the cubic in
    t/R between them uses this node there), x = min(0.53, 0.8 t'/R) at t' = TAUS[j - 1]."""
    tp = TAUS[max(j - 1, 0)]
    return np.sqrt(min(X_DOMAIN, 0.8 * tp)) / tp


def node_us(j):
    uc = u_cover(j)
    us = [u for u in US if u < 0.97 * uc]
    return tuple(us) if uc <= US[-1] + 1e-9 and us[-1] == US[-1] else tuple(us + [round(uc, 4)])


_COMP = {}


def _comp_arrays(nmax, nu, tau):
    """shell_on_core_s27.comp_arrays, each degree solved once per (nu, tau) (the same numbers)."""
    import shell_on_core_s27 as sh
    key = (float(nu), float(tau))
    if key not in _COMP or len(_COMP[key][0]) < nmax + 1:
        c = [sh.compliance(n, nu, tau) for n in range(nmax + 1)]
        _COMP[key] = tuple(np.array([q[i][j] for q in c]) for i, j in
                           ((0, 0), (0, 1), (1, 0), (1, 1)))
    return tuple(a[:nmax + 1] for a in _COMP[key])


def shell_chi(x, nu, tau):
    """A direct solve: chi_shell(x, nu, tau), radial reading (shell_on_core_s27.chi_at)."""
    import shell_on_core_s27 as sh
    sh.comp_arrays = _comp_arrays
    return sh.chi_at(x, nu, tau, "radial")[0]


def build_table():
    """G on the grid (module docs); resumable: nodes already in the npz are kept."""
    import thin_layer_exact_s27 as tl
    have = {}
    if os.path.exists(NPZ):
        d = np.load(NPZ)
        for nu, tau, u, g in zip(d["nu"], d["tau"], d["u"], d["g"]):
            have[(float(nu), float(tau), float(u))] = float(g)
    d = np.load(NPZ_G)
    assert abs(float(d["tau_g"]) - TAUS[0]) < 1e-12
    for i, nu in enumerate(d["nus"]):
        for k, u in enumerate(d["us"]):
            have[(float(nu), TAUS[0], float(u))] = float(d["g"][i, k])
    t0 = time.time()

    def save():
        keys = sorted(have)
        np.savez(NPZ, nu=np.array([k[0] for k in keys]), tau=np.array([k[1] for k in keys]),
                 u=np.array([k[2] for k in keys]), g=np.array([have[k] for k in keys]))
    for j, tau in enumerate(TAUS):
        for nu in NUS:
            row = []
            for u in node_us(j):
                key = (float(nu), float(tau), float(u))
                if key not in have:
                    cs = shell_chi((u * tau) ** 2, nu, tau)
                    have[key] = (cs / tl.chi_lin(u, nu) - 1) / tau
                row.append(have[key])
            _COMP.clear()
            save()
            print(f"t/R {tau} nu {nu}: G = " + " ".join(f"{v:+.4f}" for v in row) +
                  f"  ({time.time() - t0:.0f} s)", flush=True)
    print(f"wrote {NPZ} in {time.time() - t0:.0f} s")


_T = {}


def _table():
    if "nodes" not in _T:
        from scipy.interpolate import RectBivariateSpline
        d = np.load(NPZ)
        nodes = []
        for j, tau in enumerate(TAUS):
            us = np.array(node_us(j))
            g = np.zeros((len(NUS), len(us)))
            for i, nu in enumerate(NUS):
                for k, u in enumerate(us):
                    sel = ((np.abs(d["nu"] - nu) < 1e-9) & (np.abs(d["tau"] - tau) < 1e-9) &
                           (np.abs(d["u"] - u) < 1e-6))
                    if not sel.any():
                        raise SystemExit(f"{NPZ} lacks nu {nu} t/R {tau} u {u}: run --table")
                    g[i, k] = d["g"][sel][0]
            nodes.append((RectBivariateSpline(NUS, np.log(us), g, kx=3, ky=3), us[0], us[-1],
                          us, g))
        _T["nodes"] = nodes
    return _T["nodes"]


def G_of(u, nu, tau):
    """G(nu, tau, u) from the table (module docs), vectorised in u."""
    from scipy.interpolate import CubicSpline
    u = np.atleast_1d(np.asarray(u, dtype=float))
    rows = []
    for sp, lo, hi, _, _ in _table():
        uc = np.clip(u, lo, hi)
        v = sp.ev(np.full_like(uc, nu), np.log(uc))
        rows.append(np.where(u < lo, v * u / lo, v))
    rows = np.array(rows)
    tc = min(max(tau, TAUS[0]), TAUS[-1])
    return CubicSpline(TAUS, rows, axis=0)(tc)


def chi_shell(x, nu, tau):
    """chi_shell from the table: chi_lin(u, nu) (1 + tau G), u = sqrt(x)/tau."""
    import thin_layer_exact_s27 as tl
    x = np.asarray(x, dtype=float)
    u = np.sqrt(x) / tau
    return tl.chi_lin(u, nu) * (1 + tau * G_of(u, nu, tau).reshape(np.shape(u)))


def show():
    for j, (sp, lo, hi, us, g) in enumerate(_table()):
        print(f"\nG at t/R {TAUS[j]} (rows nu, columns u = a_H/t)")
        print("| nu \\ u | " + " | ".join(f"{u:g}" for u in us) + " |")
        print("|---" * (len(us) + 1) + "|")
        for nu, row in zip(NUS, g):
            print(f"| {nu:g} | " + " | ".join(f"{v:+.3f}" for v in row) + " |")


INTERP_POINTS = ((0.32, 0.05, 0.0025), (0.38, 0.12, 0.01), (0.49, 0.12, 0.0025),
                 (0.46, 0.1, 0.03), (0.33, 0.25, 0.05), (0.42, 0.25, 0.01), (0.47, 0.25, 0.12),
                 (0.36, 0.2, 0.1), (0.495, 0.35, 0.05), (0.45, 0.35, 0.2), (0.42, 0.55, 0.1),
                 (0.45, 0.5, 0.3), (0.35, 0.45, 0.01), (0.44, 0.07, 0.0225), (0.3, 0.14, 0.08),
                 (0.495, 0.08, 0.004))


def interp_check():
    """The interpolant against direct solves at off-grid points (nu, t/R, x)."""
    print("| nu | t/R | x | u | chi_shell direct | table | table/direct - 1 [%] | "
          "shell excess (chi - 1) error [%] |")
    print("|---" * 8 + "|")
    worst = 0.0
    for nu, tau, x in INTERP_POINTS:
        d = shell_chi(x, nu, tau)
        t = float(chi_shell(np.array([x]), nu, tau)[0])
        worst = max(worst, abs(t / d - 1))
        _COMP.clear()
        print(f"| {nu:g} | {tau:g} | {x:g} | {np.sqrt(x) / tau:.3f} | {d:.5f} | {t:.5f} | "
              f"{100 * (t / d - 1):+.3f} | {100 * ((t - 1) / (d - 1) - 1):+.2f} |", flush=True)
    print(f"max |table/direct - 1| = {100 * worst:.3f} %")


def hemi_check():
    """Which small-strain hemisphere the excess must subtract: at each FE skin's first point
    (x 0.0025 or 0.01), t/R <= 0.6, chi_flat + chi_shell - chi_hemi against the FE (no squeeze,
    no coupling: their share is O(x)), for the readings L and F."""
    import fit_core as f
    import try_thin_skin_s26 as s26
    train, thin, held, blind, dblind = s26.sets()
    print("| skin | x | FE/shell - 1 | L: skeleton/FE - 1 | F: skeleton/FE - 1 |")
    print("|---|---|---|---|---|")
    rows = []
    for tag, cs in (("fit", train), ("held", held), ("blind", blind), ("deep", dblind)):
        for c in sorted(cs, key=lambda c: (c["tau"], c["nu"])):
            if c["tau"] > 0.6:
                continue
            x, nu, tau, fe = c["x"][:1], c["nu"], c["tau"], c["chi"][0]
            fl, sh = f.chi_flat(x, nu)[0], chi_shell(x, nu, tau)[0]
            el = fl + sh - chi_hemi(x, nu, "L")[0]
            ef = fl + sh - chi_hemi(x, nu, "F")[0]
            rows.append((tau, 100 * (el / fe - 1), 100 * (ef / fe - 1)))
            print(f"| {tag} ({nu:g}, {tau:g}) | {x[0]:g} | {100 * (fe / sh - 1):+.2f} | "
                  f"{rows[-1][1]:+.2f} | {rows[-1][2]:+.2f} |")
    for lo, hi in ((0, 0.15), (0.15, 0.61)):
        sel = [r for r in rows if lo < r[0] <= hi]
        print(f"t/R in ({lo}, {hi}]: L {min(r[1] for r in sel):+.2f}..{max(r[1] for r in sel):+.2f}"
              f" %, F {min(r[2] for r in sel):+.2f}..{max(r[2] for r in sel):+.2f} %")


def need():
    """The factor the FE asks of the shell's excess, (chi_FE - chi_flat)/(chi_shell - chi_hemi F),
    at seven points along each fitted and held-out skin of t/R <= 0.6, against s = delta/t (what
    the squeeze times the coupling must be)."""
    import fit_core as f
    import try_thin_skin_s26 as s26
    train, thin, held, blind, dblind = s26.sets()
    print("skin: s:factor at seven points (s = x/(t/R))")
    for c in sorted(train + held, key=lambda c: (c["tau"], c["nu"])):
        nu, tau, x = c["nu"], c["tau"], c["x"]
        if tau > 0.6:
            continue
        fl = f.chi_flat(x, nu)
        fac = (c["chi"] - fl) / (chi_shell(x, nu, tau) - chi_hemi(x, nu, "F"))
        idx = np.unique(np.linspace(0, len(x) - 1, 7).astype(int))
        print(f"({nu:g}, {tau:g}) " + " ".join(f"{x[i] / tau:.2f}:{fac[i]:.3f}" for i in idx))


# ---------------- forms ----------------


def chi_hemi(x, nu, mode):
    """The bonded hemisphere's own small-strain chi at x (module docs, L or F)."""
    import fit_core as f
    import thin_layer_exact_s27 as tl
    x = np.asarray(x, dtype=float)
    if "F" in mode:
        c0, c1 = f.FLAT[0], f.FLAT[1]
        return 1 + (c0 + c1 * f.eps_of(nu)) * np.sqrt(x)
    return tl.chi_lin(np.sqrt(x), nu)


def blend_ends(mode):
    if "B" in mode:
        i = mode.index("B")
        d = mode[i + 1:i + 5]
        if len(d) == 4 and d.isdigit():  # B<aa><bb>: hundredths
            return int(d[:2]) / 100, int(d[2:]) / 100
        return int(mode[i + 1]) / 10, int(mode[i + 2]) / 10
    return 0.5, 0.6


def weight(tau, mode):
    """The shell form's weight: 1 to t/R a, 0 from b, C1 smoothstep between."""
    a, b = blend_ends(mode)
    z = np.clip((tau - a) / (b - a), 0, 1)
    return 1 - z * z * (3 - 2 * z)


def form(mode):
    """The shell-skeleton forms (module docs). p = (l0, l1, k0, k1, lc, cd)."""
    import fit_core as f
    import try_thin_skin_s25 as s25
    law = s25.form("K")

    def chi(p, x, nu, tau):
        if np.ndim(tau):  # fit_core.check's scan in t/R at one x
            return np.array([float(np.squeeze(chi(p, np.array([x]), nu, float(t)))) for t in tau])
        x = np.asarray(x, dtype=float)
        w = weight(tau, mode)
        out_law = law(s25.LAW, x, nu, tau) if w < 1 else 0.0
        if w <= 0:
            return out_law
        l0, l1, k0, k1, lc, cd = p[:6]
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        hemi = chi_hemi(x, nu, mode)
        if "A" in mode:  # the shell at the patch's finite-strain width: a_H -> a_flat (hemisphere)
            xe = f.radius(x, nu, tau)[0] ** 2
            excess = chi_shell(xe, nu, min(tau, TAUS[-1])) - chi_hemi(xe, nu, mode)
        else:
            excess = chi_shell(x, nu, min(tau, TAUS[-1])) - hemi
        s = x / tau
        se = np.sqrt(eps) if "Q" in mode else eps  # Q: the squeeze's slope in sqrt(eps)
        if "E" in mode:  # E: the slope's compressibility crossover eps/(eps + e_c), e_c fitted
            se = eps / (eps + abs(p[6]))
        share = eps / (1 + 4 * eps / 3)  # mu/M: the oedometer's deviatoric share
        if "O" in mode:  # ... on the skin's oedometric share 1 - psi(z) (Matthewson's crossover)
            nu_ = min(nu, 0.4999)
            z = np.sqrt(3 * (1 - 2 * nu_) / (2 * (1 - nu_)) * x) / tau  # a_H / lambda
            share = (1 - s25.psi(z)) * (share if "O1" in mode else 1.0)
        squeeze = (l0 + l1 * se) * s + (lc * share + cd) * f.confined(s)
        big = fl - hemi if "N" in mode else fl - 1
        shell = fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * big)
        return w * shell + (1 - w) * out_law
    return chi


def p0_of(mode):
    e0, l0, l1, k0, k1, m, lc, cd = __import__("try_thin_skin_s25").LAW
    return [l0, l1, k0, k1, lc, cd] + ([0.05] if "E" in mode else [])


def fit_table(modes, curves_too=False):
    """Each form refitted on the FITTED set only (s26.sets()); max |F/F_FE - 1| per set, as
    try_shell_skeleton_s27.fit_table ('law' = the current law, unrefitted)."""
    import fit_core as f
    import try_thin_skin_s20b as b
    import try_thin_skin_s25 as s25
    import try_thin_skin_s26 as s26
    train, thin, held, blind, dblind = s26.sets()
    old = [c for c in train if c not in thin]
    groups = (("fitted", train), ("the 14", old), ("thin fit", thin), ("held out", held),
              ("blind", blind), ("deep CAX8 blind", dblind))
    fits = {}
    print("| form | " + " | ".join(g for g, _ in groups) + " |")
    print("|---" * (len(groups) + 1) + "|")
    for mode in modes:
        t0 = time.time()
        if mode == "law":
            f.chi_core = s25.form("K")
            p = s25.LAW
        else:
            f.chi_core = form(mode)
            p = f.fit(train, p0_of(mode))
        fits[mode] = p
        print(f"| {mode} | " + " | ".join(b.worst(p, cs) for _, cs in groups) + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) +
              f"  ({time.time() - t0:.0f} s)", flush=True)
    if curves_too:
        tagged = [("fit", c) for c in train] + [("held", c) for c in held] + \
                 [("blind", c) for c in blind] + [("deep", c) for c in dblind]
        print("| curve | " + " | ".join(modes) + " |")
        print("|---" * (len(modes) + 1) + "|")
        worst = {m: [] for m in modes}
        for tag, c in sorted(tagged, key=lambda tc: (tc[0], tc[1]["tau"], tc[1]["nu"])):
            cells = []
            for mode in modes:
                f.chi_core = s25.form("K") if mode == "law" else form(mode)
                r = f.chi_core(fits[mode], c["x"], c["nu"], c["tau"]) / c["chi"] - 1
                i = int(np.argmax(np.abs(r)))
                j = int(np.argmin(np.abs(c["x"] - 0.01)))
                worst[mode].append((100 * abs(r[i]), f"{tag} ({c['nu']:g}, {c['tau']:g})"))
                cells.append(f"{100 * r[i]:+.2f} (x {c['x'][i]:g}; x 0.01 {100 * r[j]:+.2f})")
            print(f"| {tag} ({c['nu']:g}, {c['tau']:g}) | " + " | ".join(cells) + " |",
                  flush=True)
        for mode in modes:
            w = worst[mode]
            line = f"{mode}: {sum(v <= 2 for v, _ in w)} of {len(w)} curves within 2 %"
            if "law" in worst and mode != "law":
                pairs = list(zip(worst["law"], w))
                better = [n for (a, n), (b, _) in pairs if b < a - 0.1]
                worse = [f"{n} {a:.2f} -> {b:.2f}" for (a, n), (b, _) in pairs if b > a + 0.1]
                line += (f"; {len(better)} better, {len(worse)} worse by > 0.1 % than the law"
                         + (": " + ", ".join(worse) if worse else ""))
            print(line)
    return fits


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--table", action="store_true", help="build shell_table_s28.npz")
    ap.add_argument("--show", action="store_true", help="print the cached G table")
    ap.add_argument("--interp", action="store_true", help="interpolant against direct solves")
    ap.add_argument("--hemi", action="store_true", help="the hemisphere readings L, F at small x")
    ap.add_argument("--need", action="store_true", help="the factor the FE asks of the excess")
    ap.add_argument("--var", nargs="*", help="forms refitted ('law' = today)")
    ap.add_argument("--curves", action="store_true", help="with --var: per curve")
    ap.add_argument("--check-form", help="fit_core.check on one --var form")
    a = ap.parse_args()
    if a.table:
        build_table()
    if a.show:
        show()
    if a.interp:
        interp_check()
    if a.hemi:
        hemi_check()
    if a.need:
        need()
    if a.var:
        fits = fit_table(a.var, a.curves)
        if a.check_form:
            import fit_core as f
            f.chi_core = form(a.check_form)
            t0 = time.time()
            print(a.check_form, f.check(fits[a.check_form]), f"({time.time() - t0:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
