#!/usr/bin/env python3
"""Session 21: the thin-layer floor adopted (issue 24 item 5; CORE_FORM.md "Thin skins: session
21"). The law's core form since session 21 is session 20's variant bU (try_thin_skin_s20.py):
the layer excess X of the bonded-layer series, with session 11's small-patch widening (b), at
least Matthewson's thin bonded layer L = chi_thin - 1 through X (1 + (L/X)^4)^(1/4) (U), seven
constants refitted on fit_core's 14 curves plus the six t/R 0.05-0.1 skins (fit_core.S20B,
nu 0.48 t/R 0.05 from its run directory).

Modes:
  (none)  the adopted constants' errors: fitted, held out (t/R >= 0.1), blind (t/R 0.08, and
          session 21's skins when their run directories are on this machine)
  var V.. the variants tried this session (letters below), each refitted, one table row each
  loo     leave-out of the thin fit skins: each t/R and each nu of S20B out in turn
Variant letters (on top of b and the floor U, power 4 unless Q/P):
  Q  the floor's power fitted (an eighth constant)
  P  the floor's power linear in mu/M (two constants): p0 + p1 mu/M
  E  the thin layer's fringe: L (1 + beta t/a_H)^2 (the layer carries load ~ beta t past the edge)
  W  the thin layer added to the series (p = 1, Shull's additive form), with a weight
  H  the crossover at Matthewson's confinement length, E = c (3 mu/M) (a_H/t)^2, c fitted
  G  diagnostic only: a free quadratic in eps multiplying the excess (what a nu factor can do)
  C / 3  Dimitriadis' third-order coefficient (theory), faded by (1 + E)^2; C: its weight fitted

usage: PY tools/calibration/try_thin_skin_s21.py [var VARIANT ... | loo]
       (PY: a python with numpy + scipy, e.g. /work/fe-scratch/fe-venv/bin/python)
"""
import os
import sys

import numpy as np

import fit_core as f
import try_thin_skin_s20 as s20
import try_thin_skin_s20b as b

# backed.rs CORE since session 21 (variant bU refitted as above)
ADOPTED = [1.174920, 0.215824, 0.794899, 0.238558, -1.731562, 1.195527, 0.134278]
# session 21's FE skins (tools/fe/fe_campaign.py S21_DT), blind: run after ADOPTED was fixed
S21_RUNS = "/work/fe-scratch/runs/skins-s21"
S21 = [(0.48, 0.08, 80), (0.4, 0.06, 100), (0.48, 0.06, 100), (0.45, 0.07, 90), (0.35, 0.06, 100)]


def form(mode):
    def chi(p, x, nu, tau):
        e0, l0, l1, k0, k1, m, lc = p[:7]
        eps = f.eps_of(nu)
        fl = f.chi_flat(x, nu)
        a_flat, a_core = f.radius(x, nu, tau)
        a_h = np.sqrt(x)
        u = a_h / tau
        h = 1 + tau * tau / (1 - tau)
        t1 = f.dimitriadis_d1(nu) / 3 * a_h / (tau * h)
        wid = a_core / a_flat - 1
        a_core = a_flat * (1 + t1 * wid / np.sqrt(t1 * t1 + wid * wid + 1e-300))
        d1, e = f.dimitriadis_d1(nu), e0 * np.exp(-m * eps)
        k = 7
        g3 = 0.0
        if "3" in mode:
            g3 = 1.0
        if "C" in mode:
            g3 = p[k]
            k += 1
        a0 = -(1.2876 - 1.4678 * nu + 1.3442 * nu * nu) / (1 - nu)
        b0 = (0.6387 - 1.0277 * nu + 1.5164 * nu * nu) / (1 - nu)
        c3 = -8 / np.pi ** 3 * (a0 ** 3 + 4 * np.pi ** 2 * b0 / 15)

        def layer(v, c):
            return v * (d1 + e * v / (1 + c) + g3 * c3 * v * v / (1 + c) ** 2)
        ce = eps
        if "H" in mode:
            ce = abs(p[k]) * 3 * eps / (1 + 4 * eps / 3)
            k += 1
        excess = layer(a_core / (tau * h), ce * x / tau ** 2) - layer(a_flat / h, ce * x)
        if "G" in mode:
            excess = excess * (1 + p[k] * eps + p[k + 1] * eps * eps)
            k += 2
        limit = np.clip(s20.thin_limit(x, nu, tau) - 1, 0, None)
        if "E" in mode:
            limit = limit * (1 + abs(p[k]) / np.maximum(u, 1e-9)) ** 2
            k += 1
        power = 4.0
        if "P" in mode:
            power = abs(p[k]) + p[k + 1] * eps / (1 + 4 * eps / 3)
            k += 2
        elif "Q" in mode:
            power = abs(p[k])
            k += 1
        if "W" in mode:
            excess = excess + abs(p[k]) * limit
        else:
            excess = (np.abs(excess) ** power + limit ** power) ** (1 / power)
        s = x / tau
        squeeze = (l0 + l1 * eps) * s + lc * eps / (1 + 4 * eps / 3) * f.confined(s)
        return fl + excess * (1 + squeeze) * np.exp(-(k0 + k1 * eps) * (fl - 1))
    return chi


EXTRA = {"C": [0.5], "H": [0.5], "G": [0.0, 0.0], "E": [0.3], "P": [4.0, 0.0], "Q": [4.0],
         "W": [0.5]}


def sets():
    cs = b.curves()
    new = [c for c in cs if (c["nu"], c["tau"]) in f.S20B]
    train = [c for c in cs if not c["held"]] + new
    blind = [c for c in cs if c["tau"] < 0.09 and (c["nu"], c["tau"]) not in f.S20B]
    held = [c for c in cs if c["held"] and c["tau"] >= 0.1 and c not in new]
    s21 = [c for c in (b.from_run(S21_RUNS, nu, t, h, "heldout") for nu, t, h in S21)
           if c is not None and len(c["x"])]
    return train, new, held, blind, s21


def line(c, p):
    return (f"({c['nu']:g}, {c['tau']:g}) max {np.abs(b.signed(p, c)).max():.2f}: " +
            " ".join(f"{x:g}:{v:+.2f}" for x, v in zip(c["x"], b.signed(p, c))))


def adopted():
    train, new, held, blind, s21 = sets()
    old = [c for c in train if c not in new]
    for mode, p in (("today (session 20)", s20.TODAY), ("adopted (session 21)", ADOPTED)):
        f.chi_core = s20.form("x") if p is s20.TODAY else form("")
        print(f"{mode}: fitted {b.worst(p, train)}, the 14 {b.worst(p, old)}, thin fit skins "
              f"{b.worst(p, new)}, held out t/R >= 0.1 {b.worst(p, held)}, blind t/R 0.08 "
              f"{b.worst(p, blind)}, session 21 blind {b.worst(p, s21)}")
        for c in sorted(old + held, key=lambda c: (c["tau"], c["nu"])):
            print(f"    {'fit ' if c in old else 'held'} ({c['nu']:g}, {c['tau']:g}): "
                  f"{f.worst(p, c)[0]:.2f} at x = {f.worst(p, c)[1]:g}")
        for c in sorted(new, key=lambda c: (c["tau"], c["nu"])):
            print("    new   " + line(c, p))
        for c in blind:
            print("    blind " + line(c, p))
        for c in s21:
            print("    s21   " + line(c, p) + f"  [{c['name']}]")
        print("    check: " + f.check(p), flush=True)


def variants(modes):
    train, new, held, blind, s21 = sets()
    old = [c for c in train if c not in new]
    print("| variant | fitted | the 14 | thin fit skins | held out t/R >= 0.1 | blind t/R 0.08 "
          "nu 0.3 / 0.4 / 0.48 | session 21 blind |")
    print("|---|---|---|---|---|---|---|")
    for mode in modes:
        f.chi_core = form(mode)
        p0 = list(f.START) + sum((EXTRA[k] for k in "CHGEPQW" if k in mode), [])
        p = s20.fit(mode, train, p0)
        bl = " / ".join(f"{np.abs(b.signed(p, c)).max():.2f}"
                        for c in sorted(blind, key=lambda c: c["nu"]))
        print(f"| b{mode}U | {b.worst(p, train)} | {b.worst(p, old)} | {b.worst(p, new)} | "
              f"{b.worst(p, held)} | {bl} | {b.worst(p, s21)} |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p))


def loo():
    f.chi_core = form("")
    train, new, held, blind, s21 = sets()
    for name, out in [("t/R 0.05", lambda c: c["tau"] == 0.05),
                      ("t/R 0.1", lambda c: c["tau"] == 0.1 and c in new),
                      ("nu 0.3", lambda c: c["nu"] == 0.3 and c in new),
                      ("nu 0.4", lambda c: c["nu"] == 0.4 and c in new),
                      ("nu 0.48", lambda c: c["nu"] == 0.48 and c in new)]:
        tr = [c for c in train if not out(c)]
        q = f.fit(tr, ADOPTED)
        o = [c for c in train if out(c)]
        print(f"thin skins at {name} out: on them " + " / ".join(
            f"({c['nu']:g}, {c['tau']:g}) {f.worst(q, c)[0]:.2f}" for c in o) +
            f"; fitted {b.worst(q, tr)}; held out {b.worst(q, held)}; blind {b.worst(q, blind)}",
            flush=True)


def main(args):
    if args and args[0] == "var":
        variants(args[1:])
    elif args and args[0] == "loo":
        loo()
    else:
        adopted()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
