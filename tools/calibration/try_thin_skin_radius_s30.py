#!/usr/bin/env python3
"""Session 30 (issue 24 item 5, "radius within 3 %" on thin skins): the core's contact radius on
thin skins from the exact small-strain bonded layer, with no fitted constant; the force
untouched.

The law's radius (backed.rs `RadiusForm`, fit_core.radius) was fitted on t/R 0.2-0.8 at x >= 0.05
(fit_radius_pressure.py). Below t/R 0.2 it is extrapolated, and on the seventeen k1e6 thin skins
(t/R 0.05-0.14, x 0.02-0.105) its mean error is -5.02 % (nu 0.3 t/R 0.05: the compressible
crossover S = s0 (1 - w E/(1 + E)) and the hold-back 1/(1 + k x/rc) both pull a/a_H down with x
where the FE's stays at 1.33-1.38) to +3.11 % (nu 0.46 t/R 0.1).

The exact linear layer: thin_layer_exact_s27.solve(a, nu) gives, for a contact radius a (t = 1),
the indentation delta R and the force, so the same solves that tabulate chi_lin(u, nu) (the
force's skeleton in the thin-skin form, shell.rs) give its contact radius, A_lin(u, nu) = a/a_H
at u = a_H/t (`a_lin`; `A_lin - 1` a spline in ln u per nu, as `tl.chi_table`). It has both
ends without a constant: Hertz as u -> 0 (A - 1 = (d1/3) u, Dimitriadis' first order), the
oedometer's sqrt 2 (compressible) and the incompressible layer's 2 as u -> inf, and between them
Matthewson's crossover in the real layer (not the thin-layer asymptotics, which at a/t 2-4 are
1.67-1.98: CORE_FORM.md session 27).

Radius forms (`radius(x, nu, tau, mode)`):
  law    today's, fit_core.radius (backed.rs)
  pure   a = a_H A_lin(u, nu): the exact layer alone
  F<e>   a = w a_H A_lin + (1 - w) a_law, w = 1 - z^2 (3 - 2 z), z = min(tau/e, 1): the law's
         fade shape (SHELL_FADE's) ending at t/R e. F0.2: the law kept wherever it was fitted
         (t/R >= 0.2, its thinnest fitted skin), the exact layer below; F0.3: the force's own
         fade end (SHELL_FADE)
  B...   as above with the hemisphere's finite-x radius and the law's hold-back,
         a_flat (1 + (A_lin - 1)/(1 + k x/rc)) in place of a_H A_lin
  C...   a_H (1 + (A_lin - 1)/(1 + k x/rc)): the hold-back without the hemisphere's widening

Sets: no constant is fitted. The form (which skeleton, which fade end) is chosen on the six thin
skins of the force's fitted set (nu 0.3, 0.4, 0.48 x t/R 0.05, 0.1; try_thin_skin_s26.sets) and
on the thick radius tests (t/R 0.2-0.25 within radius_pressure.rs's tolerances, which this
session must not loosen); the other eleven thin skins (the force's held-out and blind ones) are
reported held out. The thick tests are what decides the fade's end: with F0.3 nu 0.36 t/R 0.2
goes from 1.40 to 2.02 % (its tolerance 1.7 %) and nu 0.4 t/R 0.2 from 1.00 to 1.38 % (1.3 %):
at t/R 0.2, x 0.1-0.16 the small-strain layer is 2.5-5.3 % too wide (`--thick`), where the
fitted law is within 2.2 %.

Modes:
  (none) / --table   per thin skin the mean of a_law / (a_lin + 0.485 R/N) - 1 over 0.02 <= x <=
                     min(reach, x_max) [%] for each form, fit / held out, and the thick tests'
                     worst |a/a* - 1| over 0.1 <= x <= min(0.4, x_max) (a* smoothed + lag)
  --forms F ...      the forms to print (default: law pure F0.3 F0.25 F0.2 BF0.2 CF0.2)
  --thick            the thick t/R 0.14-0.25 campaign skins per x, law / pure [%]
  --campaign         the same mean on the campaign's thin files (tests/data/fe/core/, t/R < 0.2:
                     the penalty-1e5 twins of the k1e6 skins, R/40-R/120, and nu 0.47 t/R 0.15,
                     a skin not re-run)
  --shell            the exact shell on its core (shell_on_core_s27.chi_at, radial reading),
                     its a/a_H against the flat layer's at each thin skin's middle x (slow, ~1 min)

usage: PY tools/calibration/try_thin_skin_radius_s30.py [--forms ...] [--thick] [--campaign]
       [--shell]
       (PY: /work/main/target/fe-venv/bin/python)
"""
import argparse
import functools
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "fe"))

import fit_core as f  # noqa: E402
import fit_radius_pressure as frp  # noqa: E402
import thin_layer_exact_s27 as tl  # noqa: E402

# The force's fitted thin skins (try_thin_skin_s26.sets: session 20's six, nu 0.48 t/R 0.05
# among them); every other k1e6 skin is held out here.
FIT = {(0.3, 0.05), (0.3, 0.1), (0.4, 0.05), (0.4, 0.1), (0.48, 0.05), (0.48, 0.1)}
LAG = 0.485  # times R/N: half an element face (fit_radius_pressure.LAG_TIMES_N)


@functools.lru_cache(maxsize=None)
def a_table(nu):
    """A cubic spline of ln(A_lin - 1) in ln u from the solves `tl.chi_table` makes (the same a
    grid and node counts, so the same lru-cached solves), and its u range."""
    from scipy.interpolate import CubicSpline
    nu = float(nu)
    aa = np.geomspace(1e-3, 20.0, 160)
    sol = [tl.solve(a, nu, 16 if a <= 4 else (32 if a <= 10 else 64)) for a in aa]
    u = np.array([np.sqrt(q[0]) for q in sol])
    return CubicSpline(np.log(u), np.log(aa / u - 1)), u[0], u[-1]


def a_lin(u, nu):
    """A_lin = a/a_H of the exact linear bonded layer at u = a_H/t (vectorised; A - 1 linear in u
    below the table, held above it, as `tl.chi_lin`)."""
    sp, lo, hi = a_table(nu)
    u = np.asarray(u, dtype=float)
    uc = np.clip(u, lo, hi)
    ex = np.exp(sp(np.log(uc)))
    return 1 + np.where(u < lo, ex * u / lo, ex)


def fade(tau, end):
    z = min(tau / end, 1.0)
    return 1 - z * z * (3 - 2 * z)


def radius(x, nu, tau, mode):
    """The core's contact radius over R at x by `mode` (module docs)."""
    x = np.asarray(x, dtype=float)
    a_flat, a_law = f.radius(x, nu, tau)
    if mode == "law":
        return a_law
    a_h = np.sqrt(x)
    amp = a_lin(a_h / tau, nu)
    hold = 1 + f.RADIUS_CORE[3] * x / (1 - tau)
    if mode.startswith("B"):
        thin, rest = a_flat * (1 + (amp - 1) / hold), mode[1:]
    elif mode.startswith("C"):
        thin, rest = a_h * (1 + (amp - 1) / hold), mode[1:]
    else:
        thin, rest = a_h * amp, mode
    if rest == "pure":
        return thin
    if rest.startswith("F"):
        w = fade(tau, float(rest[1:]))
        return w * thin + (1 - w) * a_law
    raise ValueError(mode)


def thin_skins():
    """The seventeen k1e6 skins: (nu, t/R, R/N, x, a* = a_lin + 0.485 R/N) over 0.02 <= x <=
    min(reach, x_max), as radius_pressure.rs's `thin_skin_radius_is_what_the_readme_states`."""
    out = []
    for path in sorted(glob.glob(os.path.join(f.DATA, "k1e6", "force_nu*_t*.csv"))):
        nu, t = map(float, re.findall(r"nu([\d.]+)_t([\d.]+)\.csv", path)[0])
        with open(path) as fh:
            n = int(re.search(r"R/(\d+)", fh.readline()).group(1))
        d = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, a = d["delta_over_R"], d["contact_radius_mm"] + LAG / n
        sel = (x >= 0.02 - 1e-9) & (x <= min(f.flat_x_max(nu), f.SQUEEZE * t) + 1e-9)
        out.append((nu, t, n, x[sel], a[sel]))
    return out


def thick_skins(tmax=0.29):
    """The campaign's core skins of t/R <= tmax reaching x = 0.1: (path, nu, t, x, a*) with a*
    the smoothed column plus the lag, over 0.1 <= x <= min(0.4, x_max) (radius_pressure.rs's
    `radius_within_3_percent_of_the_smoothed_fe_radius`)."""
    out = []
    for c in frp.cases("core/force_nu*_t*.csv"):
        if c["t"] > tmax or c["x"].max() < 0.1:
            continue
        sm = frp.smooth(c["x"], c["a"])
        hi = min(f.flat_x_max(c["nu"]), f.SQUEEZE * c["t"], 0.4)
        k = (c["x"] >= 0.1 - 1e-9) & (c["x"] <= hi + 1e-9)
        out.append((c["path"], c["nu"], c["t"], c["x"][k], sm(c["x"][k]) + c["lag"]))
    return out


def table(forms):
    thin = thin_skins()
    thick = thick_skins()
    for mode in forms:
        means = [(nu, t, 100 * np.mean(radius(x, nu, t, mode) / a - 1)) for nu, t, _, x, a in thin]
        fit = [m for nu, t, m in means if (nu, t) in FIT]
        held = [m for nu, t, m in means if (nu, t) not in FIT]
        print(f"{mode:6s} thin fit worst {max(map(abs, fit)):.2f} %, held out worst "
              f"{max(map(abs, held)):.2f} %, all {min(m for *_, m in means):+.2f} .. "
              f"{max(m for *_, m in means):+.2f} %")
        print("       " + " ".join(f"{nu:g}/{t:g}{'' if (nu, t) in FIT else '*'}:{m:+.2f}"
                                   for nu, t, m in means))
        print("       thick (t/R <= 0.25, worst |a/a* - 1| at 0.1 <= x): " + " ".join(
            f"{nu:g}/{t:g}:{100 * np.max(np.abs(radius(x, nu, t, mode) / a - 1)):.2f}"
            for _, nu, t, x, a in thick))
    print("(* held out: not among the force's fitted thin skins; no form has a fitted constant)")


def campaign(forms):
    for path in sorted(glob.glob(os.path.join(f.DATA, "force_nu*_t*.csv"))):
        nu, t = map(float, re.findall(r"nu([\d.]+)_t([\d.]+)\.csv", path)[0])
        if t >= 0.2:
            continue
        with open(path) as fh:
            m = re.search(r"R/(\d+)", fh.readline())
        n = int(m.group(1)) if m else 40
        d = np.genfromtxt(path, delimiter=",", names=True, skip_header=1)
        x, a = d["delta_over_R"], d["contact_radius_mm"] + LAG / n
        sel = (x >= 0.02 - 1e-9) & (x <= min(f.flat_x_max(nu), f.SQUEEZE * t) + 1e-9)
        if not sel.any():
            continue
        print(f"campaign nu {nu:g} t/R {t:g} (R/{n}, {sel.sum()} points): " + " ".join(
            f"{mode} {100 * np.mean(radius(x[sel], nu, t, mode) / a[sel] - 1):+.2f}"
            for mode in forms))


def thick_detail():
    for path, nu, t, x, a in thick_skins():
        law = 100 * (radius(x, nu, t, "law") / a - 1)
        pure = 100 * (radius(x, nu, t, "pure") / a - 1)
        print(f"nu {nu:g} t/R {t:g}: " + " ".join(
            f"{xx:.2f}:{p:+.1f}/{q:+.1f}" for xx, p, q in zip(x, law, pure)))


def shell():
    import shell_on_core_s27 as sc
    for nu, t, _, x, a in thin_skins():
        xm = float(x[len(x) // 2])
        chi, amp, _ = sc.chi_at(xm, nu, t, "radial")
        flat = float(a_lin(np.sqrt(xm) / t, nu))
        fe = float(a[len(x) // 2] / np.sqrt(xm))
        print(f"nu {nu:g} t/R {t:g} x {xm:g}: a/a_H shell on core {amp:.4f}, flat layer "
              f"{flat:.4f} ({100 * (amp / flat - 1):+.2f} %), FE point {fe:.4f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--forms", nargs="*",
                    default=["law", "pure", "F0.3", "F0.25", "F0.2", "BF0.2", "CF0.2"])
    ap.add_argument("--table", action="store_true")
    ap.add_argument("--thick", action="store_true")
    ap.add_argument("--shell", action="store_true")
    ap.add_argument("--campaign", action="store_true")
    a = ap.parse_args()
    if a.thick:
        thick_detail()
    if a.shell:
        shell()
    if a.campaign:
        campaign(a.forms)
    if a.table or not (a.thick or a.shell or a.campaign):
        table(a.forms)
    return 0


if __name__ == "__main__":
    sys.exit(main())
