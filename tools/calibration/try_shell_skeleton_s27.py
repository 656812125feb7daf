#!/usr/bin/env python3
"""Session 27 (issue 24 item 5): the exact small-strain shell on its core as the law's skeleton.

The skin's small-strain skeleton is taken as

    chi_skel(u, nu, tau) = chi_lin(u, nu) (1 + tau g(u, nu)),   u = a_H/t = sqrt(x)/tau,

chi_lin the exact flat bonded layer (`thin_layer_exact_s27.chi_lin`) and g the first-order
factor of the core's curvature, tabulated from the exact shell on its core
(`shell_on_core_s27.chi_at`, radial reading) at tau = TAU_G:

    g(u, nu) = (chi_shell(x, nu, TAU_G)/chi_lin(u, nu) - 1)/TAU_G,   x = (u TAU_G)^2.

Nothing is fitted in g. The table (nu NUS x u US) is cached in `shell_g_s27.npz` beside this
file (`--table` rebuilds it; see CORE_FORM.md for its cost); g is interpolated bicubically in
(nu, log u), linear in u to 0 below the table and held at its end above it.

Forms (refitted on the FITTED set only, s26.sets(), as thin_layer_exact_s27's `--var`):
  KS   today's law (s25 "K", eight constants) with its layer excess scaled by chi_skel over the
       law's own skeleton at the same u (the law at t/R -> 0), NO fade (w = 1):
           chi = chi_flat + (chi_law - chi_flat) (chi_skel - 1)/(skel_law - 1)
  KSL  the same on session 27's LCF:P (the finite-strain film floor; nine constants)
  KS5  KS with tau in chi_skel capped at 0.5 (the shell's far field past t/R 0.5 is not the FE's)
  KT   the ratio taken at the skin's own tau: the shell's excess over the depth-R flat layer,
       chi_skel(u, nu, tau) - chi_lin(sqrt(x), nu) (clipped at 0), over the law's own excess at
       (x, tau) with its squeeze and coupling set to 0 (the law's mean depth and hemisphere
       subtraction are then not counted twice); KT5: tau capped at 0.5 in chi_skel; KTL5: KT5
       on LCF:P (its raw skeleton s25's P)
  KSH  KS with the law's skeleton taken at its own mean depth (u/h, h = 1 + tau^2/(1 - tau))
  KSF, KSLF  controls, not the brief's form: KS / KSL with K's fade (tau0 fitted)

Result (CORE_FORM.md "Thin skins: the shell skeleton refit, session 27"): g is -0.05..-1.25
(nu 0.3-0.499, u 0.1-4); KS (no fade) is worse than the law on every set but blind (fitted /
the 14 / held out / blind / deep CAX8 7.42 / 7.42 / 13.21 / 5.69 / 10.44 %, law 6.21 / 2.52 /
3.70 / 5.89 / 2.90) and fails the form check (F not increasing): it takes the thin skins'
small-x nu pattern out (x 0.01: -0.58..+2.66 %, law -3.42..+3.48) but makes every thick skin
soft at x 0.01 (-3.24..-0.16 %), the core's curvature counted twice against the law's own
stand-ins. Not adopted.

usage: PY tools/calibration/try_shell_skeleton_s27.py [--table] [--show]
           [--var MODE ... [--curves] [--check-form MODE]]
       (PY: /work/main/target/fe-venv/bin/python; run under nice)
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))

TAU_G = 0.05
NUS = (0.3, 0.35, 0.4, 0.45, 0.48, 0.49, 0.499)
US = (0.1, 0.15, 0.25, 0.35, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0)
NPZ = os.path.join(HERE, "shell_g_s27.npz")
NMAX_ALL = 20000

_COMP = {}


def _fast_comp_arrays(nmax, nu, tau):
    """shell_on_core_s27.comp_arrays, each degree's compliance solved once and cached per (nu,
    tau) up to NMAX_ALL (the same numbers; the original solves each degree four times)."""
    import shell_on_core_s27 as sh
    key = (float(nu), float(tau))
    if key not in _COMP or len(_COMP[key][0]) < nmax + 1:
        n_all = max(nmax, NMAX_ALL)
        c = [sh.compliance(n, nu, tau) for n in range(n_all + 1)]
        _COMP[key] = tuple(np.array([q[i][j] for q in c]) for i, j in
                           ((0, 0), (0, 1), (1, 0), (1, 1)))
    return tuple(a[:nmax + 1] for a in _COMP[key])


def build_table():
    import shell_on_core_s27 as sh
    import thin_layer_exact_s27 as tl
    sh.comp_arrays = _fast_comp_arrays
    g = np.zeros((len(NUS), len(US)))
    t0 = time.time()
    for i, nu in enumerate(NUS):
        for j, u in enumerate(US):
            cs = sh.chi_at((u * TAU_G) ** 2, nu, TAU_G, "radial")[0]
            g[i, j] = (cs / tl.chi_lin(u, nu) - 1) / TAU_G
        print(f"nu {nu}: g = " + " ".join(f"{v:+.4f}" for v in g[i]) +
              f"  ({time.time() - t0:.0f} s)", flush=True)
    np.savez(NPZ, nus=np.array(NUS), us=np.array(US), g=g, tau_g=TAU_G)
    print(f"wrote {NPZ} in {time.time() - t0:.0f} s")


_G = {}


def g_of(u, nu):
    """g(u, nu) from the cached table (bicubic in (nu, log u); linear to 0 below US[0], held
    above US[-1])."""
    if "sp" not in _G:
        from scipy.interpolate import RectBivariateSpline
        d = np.load(NPZ)
        _G["sp"] = RectBivariateSpline(d["nus"], np.log(d["us"]), d["g"], kx=3, ky=3)
        _G["lo"], _G["hi"] = float(d["us"][0]), float(d["us"][-1])
    u = np.asarray(u, dtype=float)
    uc = np.clip(u, _G["lo"], _G["hi"])
    v = _G["sp"].ev(np.full_like(uc, nu), np.log(uc))
    return np.where(u < _G["lo"], v * u / _G["lo"], v)


def chi_skel(u, nu, tau):
    import thin_layer_exact_s27 as tl
    return tl.chi_lin(u, nu) * (1 + tau * g_of(u, nu))


def form_ks(mode):
    """KS / KSL / KS5 (module docs)."""
    import fit_core as f
    import try_thin_skin_s25 as s25
    if "L" in mode:
        import try_thin_skin_s27 as s27
        law, skel_law, k = s27.form("LCF:P"), s25.form("P"), 9
    else:
        law, skel_law, k = s25.form("K"), s25.form("K"), 8
    t_s = 1e-3

    def chi(p, x, nu, tau):
        x = np.asarray(x, dtype=float)
        q = p[:k]
        fl = f.chi_flat(x, nu)
        u = np.sqrt(x) / tau
        ts = min(tau, 0.5) if "5" in mode else tau
        if "T" in mode:  # the law's own small-strain skeleton at this tau (squeeze, coupling 0)
            import thin_layer_exact_s27 as tl
            q0 = np.array(q, dtype=float)
            q0[[1, 2, 3, 4, 6, 7]] = 0.0
            raw = skel_law(q0, x, nu, tau) - fl
            shell = chi_skel(u, nu, ts) - tl.chi_lin(np.sqrt(x), nu)
            ratio = np.clip(shell, 0, None) / raw
        else:
            # H: the law's skeleton at its own mean depth t h (u/h), the curvature stand-in
            # its skin layer carries (s25: h = 1 + tau^2/(1 - tau)), so tau g is not counted twice
            uh = u / (1 + tau * tau / (1 - tau)) if "H" in mode else u
            skel = skel_law(q, (uh * t_s) ** 2, nu, t_s)
            ratio = (chi_skel(u, nu, ts) - 1) / (skel - 1)
        if "F" in mode:  # control: K's fade w = 1/(1 + (tau/tau0)^2), tau0 fitted
            ratio = 1 + (ratio - 1) / (1 + (tau / p[k]) ** 2)
        return fl + (law(q, x, nu, tau) - fl) * ratio
    return chi


def fit_table(modes, curves_too=False):
    """As thin_layer_exact_s27.fit_table, for the KS forms ('law' = today)."""
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
            f.chi_core = form_ks(mode)
            p = f.fit(train, list(s25.LAW) + ([3.61] if "L" in mode else []) +
                      ([0.1] if "F" in mode else []))
        fits[mode] = p
        print(f"| {mode} | " + " | ".join(b.worst(p, cs) for _, cs in groups) + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) +
              f"  ({time.time() - t0:.0f} s)", flush=True)
    if curves_too:
        tagged = [("fit", c) for c in train] + [("held", c) for c in held] + \
                 [("blind", c) for c in blind] + [("deep", c) for c in dblind]
        print("| curve | " + " | ".join(modes) + " |")
        print("|---" * (len(modes) + 1) + "|")
        for tag, c in sorted(tagged, key=lambda tc: (tc[0], tc[1]["tau"], tc[1]["nu"])):
            cells = []
            for mode in modes:
                f.chi_core = s25.form("K") if mode == "law" else form_ks(mode)
                r = f.chi_core(fits[mode], c["x"], c["nu"], c["tau"]) / c["chi"] - 1
                i = int(np.argmax(np.abs(r)))
                j = int(np.argmin(np.abs(c["x"] - 0.01)))
                cells.append(f"{100 * r[i]:+.2f} (x {c['x'][i]:g}; x 0.01 {100 * r[j]:+.2f})")
            print(f"| {tag} ({c['nu']:g}, {c['tau']:g}) | " + " | ".join(cells) + " |",
                  flush=True)
    return fits


def show():
    d = np.load(NPZ)
    print(f"g(u, nu) at tau {float(d['tau_g']):g} (rows nu, columns u = a_H/t)")
    print("| nu \\ u | " + " | ".join(f"{u:g}" for u in d["us"]) + " |")
    print("|---" * (len(d["us"]) + 1) + "|")
    for nu, row in zip(d["nus"], d["g"]):
        print(f"| {nu:g} | " + " | ".join(f"{v:+.3f}" for v in row) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--table", action="store_true", help="rebuild shell_g_s27.npz")
    ap.add_argument("--show", action="store_true", help="print the cached g table")
    ap.add_argument("--var", nargs="*", help="forms refitted ('law' = today, KS, KSL, KS5)")
    ap.add_argument("--curves", action="store_true", help="with --var: per curve")
    ap.add_argument("--check-form", help="fit_core.check on one --var form")
    a = ap.parse_args()
    if a.table:
        build_table()
    if a.show:
        show()
    if a.var:
        fits = fit_table(a.var, a.curves)
        if a.check_form:
            import fit_core as f
            f.chi_core = form_ks(a.check_form)
            if "L" in a.check_form:
                import try_thin_skin_s27 as s27
                print(a.check_form, "(coarse)", s27.coarse_check(fits[a.check_form]))
            else:
                print(a.check_form, f.check(fits[a.check_form]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
