#!/usr/bin/env python3
"""Session 15: thin skins on a core (issue 24 item 5), an experiment, not the law
(tools/calibration/CORE_FORM.md, "Thin skins: session 15"). Today's law (fit_core.py, session
10's constants) and session 14's closest variant (try_thin_skin_s14.py `bWyM`: the first-order
widening blend, the confinement lost faster and the compressible skin thinning more as the patch
outgrows the confinement length, seven constants, a sharper minimax) refitted with session 15's
two FE curves at t/R 0.3 (nu 0.48 and 0.35, VARIANT_FIT) in its fit. Prints both against every
plane core curve: the largest |F_law/F_FE - 1| (%) and where, and the maxima per group.

usage: target/fe-venv/bin/python tools/calibration/try_thin_skin_s15.py   (numpy + scipy; ~20 s)

Result (session 15): the variant is within 2.00 % on every fitted curve of t/R <= 0.35 (today
2.48 %), 2.08 % on all fitted (today 2.48), but the held-out thin skins stay over 2 % ((0.46,
0.25) 2.35 % at its end, (0.49, 0.3) 2.17 %; today 1.80 / 2.17 %), and the skins thinner than
any fitted 3.22 % (today 4.02 %) and the skin on a core on a ball,
which takes the plane form at Hertz's patch (core_map.rs), moves out of the issue's 3 % on three
curves (measured with the form ported to backed.rs: (0.48, 0.3, k 3) 2.60 -> 3.43 %, (0.3, 0.4,
k 2) 2.28 -> 3.14 %, (0.33, 0.45, k 3) 2.20 -> 3.00 %). Not adopted. The blind run (0.47, 0.25),
made after these constants were fixed: today 1.67 %, the variant 1.75 %.
"""
import sys

import numpy as np
from scipy.optimize import least_squares

import fit_core as f
import try_thin_skin_s14 as t14

TODAY = [0.849512, 0.676765, 1.022037, 0.266768, -1.622115, 1.470321, 0.234092]  # backed.rs CORE
# The session-15 curves in the variant's fit: the two t/R 0.3 runs it was fixed on (curves
# made later, in fit_core.LATER too, stay out so that these numbers and the blind test hold).
VARIANT_FIT = {(0.48, 0.3), (0.35, 0.3)}


def variant(curves):
    """bWyM fitted on the law's fitted curves and session 15's two t/R 0.3 runs."""
    f.chi_core = t14.form("bWy")
    train = [c for c in curves if not c["held"] or (c["nu"], c["tau"]) in VARIANT_FIT]
    p = f.fit(train, f.START + t14.extra("bWy"))

    def g0(p):
        return f.residuals(p, train)
    for power in (8, 16):
        p = least_squares(lambda p: np.sign(g0(p)) * np.abs(50 * g0(p)) ** power, p,
                          x_scale="jac", max_nfev=5000).x
    return p, train


def main():
    curves = f.load()
    base = f.chi_core
    rows = {}
    for c in curves:
        rows[c["name"]] = [c, f.worst(TODAY, c)]
    p, train = variant(curves)
    print("variant bWyM constants (e0, l0, l1, k0, k1, m, lc): " +
          ", ".join(f"{v:.6f}" for v in p))
    print("check: " + f.check(p))
    trained = {c["name"] for c in train}
    print("\n| file | nu | t/R | role | today | at x | variant | at x |")
    print("|---|---|---|---|---|---|---|---|")
    groups = {}
    for name, (c, (w0, x0)) in sorted(rows.items(), key=lambda r: (r[1][0]["tau"], r[1][0]["nu"])):
        w1, x1 = f.worst(p, c)
        role = "fit" if name in trained else "held out"
        print(f"| {name} | {c['nu']:g} | {c['tau']:g} | {role} | {w0:.2f} % | {x0:g} | "
              f"{w1:.2f} % | {x1:g} |")
        group = ("thin" if 0.2 <= c["tau"] <= 0.35 else "thinner" if c["tau"] < 0.2
                 else "thick") + " " + role
        g = groups.setdefault(group, [0.0, 0.0])
        g[0], g[1] = max(g[0], w0), max(g[1], w1)
    print("\n| group (thin: t/R 0.2-0.35) | today max | variant max |\n|---|---|---|")
    for k, (a, b) in sorted(groups.items()):
        print(f"| {k} | {a:.2f} % | {b:.2f} % |")
    f.chi_core = base
    return 0


if __name__ == "__main__":
    sys.exit(main())
