#!/usr/bin/env python3
"""Session 20, second part: the thin-layer floor of try_thin_skin_s20.py (the layer excess at
least Matthewson's thin bonded layer, `(X^p + (chi_thin - 1)^p)^(1/p)`) refitted with FIT data
on skins thinner than any fitted before: t/R 0.05 and 0.1 at nu 0.3, 0.4, 0.48
(tests/data/fe/core/, fit_core.S20B; tools/fe/fe_campaign.py's session-20 "main" cases, run under
/work/fe-scratch/runs/skins-s20b/; a run with fewer than 4 rows, which `export` leaves out, is
read from its run directory when it is on this machine, marked "(run dir)"). The t/R 0.08 skins stay blind: nu 0.4 and 0.3 (committed,
fit_core.HELD) and nu 0.48 (three rows, not exported: read from its run directory,
/work/fe-scratch/runs/thin-s20/core_nu0.48_t0.08_h75, when it is there).

Each variant (letters of try_thin_skin_s20.py; F: the floor's power fitted, an eighth
constant) is refitted on fit_core's 14 fitted curves plus every S20B file present, and printed
as: the worst fitted curve, the worst of the new thin fitted curves (each), the held-out
t/R >= 0.12 files (fit_core.HELD and LATER), the held-out (0.46, 0.1), and the blind t/R 0.08
skins (signed error along each, worst per nu). `x` is today's law (not refitted).

Result (session 20, CORE_FORM.md "Thin skins: session 20, fit data at t/R 0.05-0.1"): today's
law is 16.17 % too soft on the nu 0.3 t/R 0.05 skin (x = 0.03), 10.86 % at nu 0.4, 8.90 % at
0.48, 8.72 % at t/R 0.1 nu 0.3. Refitted with them, no variant is within 2 % on every fitted
curve (closest bUM / bFM 3.23 %, bF 3.39 %, bU 3.46 %) nor within 3 % on the blind nu 0.4 and
0.48 skins (3.1-3.3 %; nu 0.3 ~2 %, today 10.16 %): not adopted.

usage: PY tools/calibration/try_thin_skin_s20b.py [VARIANT ...]   (default: x bVM bV bU U)
       (PY: a python with numpy + scipy, e.g. /work/fe-scratch/fe-venv/bin/python)
"""
import os
import sys

import numpy as np

import fit_core as f
import try_thin_skin_s20 as s20

HERE = os.path.dirname(os.path.abspath(__file__))
BLIND_RUN = "/work/fe-scratch/runs/thin-s20"
NEW_RUNS = "/work/fe-scratch/runs/skins-s20b"


def from_run(runs, nu, tau, h, role):
    """A run's curve as fit_core.load's (x in [0.01, x_max]), read from its run directory (for
    the runs `fe_campaign.py export` leaves out: fewer than 4 rows); None if it is not on this
    machine."""
    sys.path.insert(0, os.path.join(HERE, "..", "fe"))
    import fe_campaign  # noqa: E402
    name = fe_campaign.make("core", nu, tau, h, role).name
    if not os.path.isdir(os.path.join(runs, name)):
        return None
    res = fe_campaign.load(runs, "core", nu, tau, h, role)
    if res is None or not res["rows"]:
        return None
    x = np.array([r["x"] for r in res["rows"]])
    force = np.array([r["F"] for r in res["rows"]])
    chi = force / (2 * (1 + nu) / (1 - nu ** 2)) / (4 / 3 * x ** 1.5)
    keep = (x >= 0.01 - 1e-9) & (x <= min(f.flat_x_max(nu), f.SQUEEZE * tau) + 1e-9)
    return dict(nu=nu, tau=tau, x=x[keep], chi=chi[keep], reach=x[-1], held=True,
                name=f"{name} (run dir)")


def curves():
    """fit_core's committed curves, plus the runs not exported: the blind nu 0.48 t/R 0.08
    (BLIND_RUN) and any S20B skin with no committed file (NEW_RUNS, R/120 at t/R 0.05, R/60 at
    0.1)."""
    cs = f.load()
    have = {(c["nu"], c["tau"]) for c in cs}
    extra = [from_run(BLIND_RUN, 0.48, 0.08, 75, "heldout")]
    extra += [from_run(NEW_RUNS, nu, tau, 120 if tau < 0.075 else 60, "main")
              for nu, tau in sorted(f.S20B) if (nu, tau) not in have]
    return cs + [c for c in extra if c is not None and len(c["x"])]


def worst(p, cs):
    if not cs:
        return "-"
    v, c = max(((f.worst(p, c)[0], c) for c in cs), key=lambda r: r[0])
    return f"{v:.2f} ({c['nu']:g}, {c['tau']:g})"


def signed(p, c):
    return 100 * (f.chi_core(p, c["x"], c["nu"], c["tau"]) / c["chi"] - 1)


def main(modes):
    cs = curves()
    new = [c for c in cs if (c["nu"], c["tau"]) in f.S20B]
    train = [c for c in cs if not c["held"]] + new
    blind = [c for c in cs if c["tau"] < 0.09 and (c["nu"], c["tau"]) not in f.S20B]
    held = [c for c in cs if c["held"] and c["tau"] >= 0.12]
    h46 = [c for c in cs if (c["nu"], c["tau"]) == (0.46, 0.1)]
    print(f"fit: {len(train)} curves ({len(new)} new: "
          + ", ".join(f"({c['nu']:g}, {c['tau']:g}) x <= {c['x'][-1]:g}" for c in new)
          + f"); blind: " + ", ".join(f"({c['nu']:g}, {c['tau']:g})" for c in blind))
    print("| variant | fitted | fitted, old 14 | new thin (each) | held out t/R >= 0.12 | "
          "(0.46, 0.1) | blind t/R 0.08 nu 0.3 / 0.4 / 0.48 |")
    print("|---|---|---|---|---|---|---|")
    for mode in modes:
        f.chi_core = s20.form(mode)
        if mode == "x":
            p = s20.TODAY
        else:
            p0 = list(f.START) + ([6.0] if "F" in mode else [])
            p = s20.fit(mode, train, p0)
        old = [c for c in train if c not in new]
        each = " / ".join(f"{f.worst(p, c)[0]:.2f}" for c in sorted(new, key=lambda c: (c["tau"], c["nu"])))
        bl = {c["nu"]: np.abs(signed(p, c)).max() for c in blind}
        print(f"| {mode} | {worst(p, train)} | {worst(p, old)} | {each or '-'} | {worst(p, held)} | "
              f"{worst(p, h46)} | " + " / ".join(f"{bl[n]:.2f}" if n in bl else "-" for n in (0.3, 0.4, 0.48))
              + " |", flush=True)
        print("    constants " + " ".join(f"{v:.6f}" for v in p) + "; check: " + f.check(p))
        for c in sorted(new, key=lambda c: (c["tau"], c["nu"])) + blind:
            print(f"    {'new' if c in new else 'blind'} ({c['nu']:g}, {c['tau']:g}): " + " ".join(
                f"{x:g}:{v:+.2f}" for x, v in zip(c["x"], signed(p, c))), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["x", "bVM", "bV", "bU", "U"]))
