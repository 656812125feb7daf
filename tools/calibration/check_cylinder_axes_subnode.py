#!/usr/bin/env python3
"""Can the 3D FE's patch be read between its nodes? A sub-node reading of the semi-axes, validated
where the answer is known before it is used on the cylinders.

The 3D quarter model (fe_model3d, R/20 at the pole) resolves its contact patch to a node spacing
(check_cylinder_axes.py: R/14 and R/20 differ by up to 11 %). Instead of a finer mesh, this
script reads each semi-axis between nodes from the nodes along the two symmetry lines
(fe_post3d.Run3D.line_x, line_z: across and along), with four estimators:

  hertz_p2       Hertz's pressure shape p = p0 sqrt(1 - s²/a²): p² linear in s² (least squares)
                 over the nodes in contact, a = sqrt(-intercept/slope)
  hertz_p2_in    the same without the last node in contact (the nodal CPRESS of the C3D10 faces
                 is extrapolated from their integration points and is polluted next to the edge)
  edge_32        the gap's Hertzian edge shape g = C (s - a)^(3/2) through the first two open
                 nodes (fe_post.edge_crossing's a_32, kept between the last node in and the
                 first node out)
  power3         g = C (s - a)^n through the first three open nodes (n free)

"In contact": the nodes from the pole whose signed gap is <= 1e-3 delta (the penalty's
penetration is 1e-4 to 7e-4 delta; `--threshold`).

Validation (the one 3D run on disk whose answer is known): the skin on a core, nu 0.48, t/R 0.4,
on a plane, 3D at R/20 (`3d_core_nu0.48_t0.4_n20`, the run behind tests/data/fe/cylinder/
convergence.csv's `3d` rows), against the axisymmetric run of the same case at R/80
(tests/data/fe/core/radius_mesh_nu0.48_t0.4.csv: a_lin, the last node in contact, so low by 0 to
one R/80 spacing: the reference is a_lin + h/2, +-h/2 = +-0.00625 mm, 0.9-2.4 % over the range).
Both semi-axes of the plane's patch are that radius. Then the two meshes of one cylinder case
(`3d_cylinder_k1_core_nu0.48_t0.4_n14` and `_n20`, the only mesh pair on disk), point by point.

What it showed (session 19, --threshold 1e-3; 46 readings on the plane, across and along at
0.05 <= x <= 0.27; 22 per axis on the cylinder pair, 0.05 <= x <= 0.3):
  on the plane, against the known radius (target: within 2 % per point), none validates:
    hertz_p2     -16.7 .. +71.0 %, 7 of 46 without a reading (the polluted nodes at the edge)
    hertz_p2_in  -21.8 .. +20.0 % (the core's pressure falls faster than Hertz's inside: at
                 x = 0.1, p/p0 = 0.78 and 0.56 at s = 0.21 and 0.28 against Hertz's 0.85 and
                 0.70 for a = 0.40)
    edge_32      -11.2 .. +1.6 % (it keeps to a node where the first open node's gap is already
                 many times the penalty's penetration: at x = 0.06 the first three open nodes'
                 gaps are 0.0035, 0.024 and 0.18 delta, growing 7x per node step, far faster
                 than (s - a)^(3/2) over one node spacing)
    power3       -7.4 .. +1.6 %, 28 of 46 without a reading (no root)
  R/14 over R/20 on the cylinder (target: within 3 % per point): hertz_p2 -68.8 .. +376.5 %
  across, -11.6 .. +51.3 % along; hertz_p2_in -20.0 .. +134.7 % and -31.7 .. +58.7 %; edge_32
  -18.5 .. +9.0 % and -23.6 .. +18.2 %; power3 -3.5 .. +11.7 % and -1.4 .. +0.7 % on the 2
  and 4 of 22 points where it has a reading on both meshes.
The threshold does not rescue it: at 3e-4 and 3e-3 delta the worst reading on the plane is 16.5 and
9.7 % (edge_32), 16.2 and 7.4 % (power3), 22.6 and 20.0 % (hertz_p2_in).
So the sub-node reading does not validate, and it is not applied to the cylinders' semi-axes.
The validation case is a skin on a core (the only 3D run with a known radius left on disk: the
3D plane run of the flat pad (2026-12-04) and the free and flat cylinders' raw runs are
gone; their committed pressure maps at x = 0.1 and 0.3 show the same polluted edge nodes and
non-Hertzian profiles along the axes, e.g. the free cylinder of R at x = 0.1: p² against s²
has R² 0.01 across and 0.93 along), so whether a Hertz fit would read a free or flat sphere's
patch is not tested.

Usage: python3 tools/calibration/check_cylinder_axes_subnode.py [--runs DIR] [--threshold T]
(DIR holds the run directories, default /work/fe-scratch/runs/fe3d-s18; needs numpy, scipy and
the runs' job.frd files, which are not in the repository: run with the FE venv's python.)
"""
import argparse
import os
import sys

import numpy as np
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
from fe_post3d import Run3D  # noqa: E402

PLANE = "3d_core_nu0.48_t0.4_n20"
PAIR = ("3d_cylinder_k1_core_nu0.48_t0.4_n14", "3d_cylinder_k1_core_nu0.48_t0.4_n20")
REFERENCE = os.path.join(ROOT, "tests", "data", "fe", "core", "radius_mesh_nu0.48_t0.4.csv")
H80 = 1.0 / 80.0


def last_in(g, thr):
    """Index of the last node, counted from the pole without a gap, whose gap is <= thr."""
    j = 0
    while j + 1 < len(g) and g[j + 1] <= thr:
        j += 1
    return j


def hertz_p2(c, p, g, thr, drop=0):
    j = last_in(g, thr)
    idx = np.arange(0, j + 1 - drop)
    if len(idx) < 3:
        return np.nan
    A = np.vstack([np.ones(len(idx)), c[idx] ** 2]).T
    al, be = np.linalg.lstsq(A, p[idx] ** 2, rcond=None)[0]
    return float(np.sqrt(-al / be)) if be < 0 < al else np.nan


def edge_32(c, g, thr):
    j = last_in(g, thr)
    if j + 2 >= len(c) or not 0 < g[j + 1] < g[j + 2]:
        return np.nan
    q = (g[j + 1] / g[j + 2]) ** (2 / 3)
    a = (c[j + 1] - q * c[j + 2]) / (1 - q)
    return float(min(max(a, c[j]), c[j + 1]))


def power3(c, g, thr):
    j = last_in(g, thr)
    if j + 3 >= len(c):
        return np.nan
    s, gg = c[j + 1:j + 4], g[j + 1:j + 4]
    if not (0 < gg[0] < gg[1] < gg[2]):
        return np.nan
    r1, r2 = np.log(gg[1] / gg[0]), np.log(gg[2] / gg[1])

    def f(a):
        return np.log((s[1] - a) / (s[0] - a)) * r2 - np.log((s[2] - a) / (s[1] - a)) * r1

    try:
        return float(brentq(f, c[j], s[0] - 1e-9))
    except ValueError:
        return np.nan


METHODS = {
    "hertz_p2": lambda c, p, g, thr: hertz_p2(c, p, g, thr),
    "hertz_p2_in": lambda c, p, g, thr: hertz_p2(c, p, g, thr, drop=1),
    "edge_32": lambda c, p, g, thr: edge_32(c, g, thr),
    "power3": lambda c, p, g, thr: power3(c, g, thr),
}


def read(run, thr_rel, x_lo, x_hi):
    """{x: {method: (across, along)}} over the run's output times in [x_lo, x_hi]."""
    out = {}
    for t in run.times:
        if not x_lo - 1e-9 <= t <= x_hi + 1e-9:
            continue
        P = run.X0 + run.U[t]
        C = run.C[t]
        row = {m: [] for m in METHODS}
        for line, ax in ((run.line_x, 0), (run.line_z, 2)):
            c, g, p = P[line, ax], run.cp.gap(P[line]), C[line, 1]
            for m, fn in METHODS.items():
                row[m].append(fn(c, p, g, thr_rel * t))
        out[round(t, 4)] = row
    return out


def summary(errs):
    e = np.array(errs, dtype=float)
    ok = np.isfinite(e)
    if not ok.any():
        return "no reading"
    return (f"{np.nanmin(e):+6.1f} .. {np.nanmax(e):+6.1f} % (max |.| {np.nanmax(abs(e)):5.1f} %, "
            f"{(~ok).sum()} of {len(e)} without a reading)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--runs", default="/work/fe-scratch/runs/fe3d-s18")
    ap.add_argument("--threshold", type=float, default=1e-3, help="contact: gap <= T delta")
    a = ap.parse_args()

    ref = np.genfromtxt(REFERENCE, delimiter=",", names=True, skip_header=1)
    plane = read(Run3D(os.path.join(a.runs, PLANE)), a.threshold, 0.05, 0.27)
    print(f"{PLANE} (R/20) against the axisymmetric R/80 radius + h/2 (+-{H80 / 2:.5f} mm), "
          f"0.05 <= x <= 0.27, threshold {a.threshold:g} delta; per x: across, along")
    print("   x     ref   " + "  ".join(f"{m:>19s}" for m in METHODS))
    errs = {m: [] for m in METHODS}
    for x, row in sorted(plane.items()):
        i = int(np.argmin(abs(ref["delta_over_R"] - x)))
        r = ref["contact_radius_mm_h80"][i] + H80 / 2
        cells = []
        for m in METHODS:
            e = [100 * (v / r - 1) for v in row[m]]
            errs[m] += e
            cells.append(f"{e[0]:+8.1f} {e[1]:+8.1f} %")
        print(f"  {x:.2f}  {r:.4f}  " + "  ".join(cells))
    for m in METHODS:
        print(f"  {m:12s} (across and along): {summary(errs[m])}")

    runs = [read(Run3D(os.path.join(a.runs, n)), a.threshold, 0.05, 0.3) for n in PAIR]
    print(f"\n{PAIR[0]} over {PAIR[1]} (R/14 over R/20), per point, 0.05 <= x <= 0.3:")
    for m in METHODS:
        for k, name in ((0, "across"), (1, "along")):
            d = [100 * (runs[0][x][m][k] / runs[1][x][m][k] - 1) for x in sorted(runs[1]) if x in runs[0]]
            print(f"  {m:12s} {name:6s}: {summary(d)}")


if __name__ == "__main__":
    main()
