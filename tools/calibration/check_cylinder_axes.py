#!/usr/bin/env python3
"""Is the 3D FE's contact patch resolved well enough to check the law's cylinder semi-axes to 5 %?

Reads the two meshes of the same case (the cylinder R2 = R, flat pad, nu = 0.48: element edge
R/14 and R/20 at the pole, fe_campaign.py roles "conv" and "main") from their run directories
and prints, per semi-axis (across the cylinder, along it) and per estimate (the last node in
contact, `a`/`b`; the gap's Hertzian edge through the first two nodes outside, `a32`/`b32`,
the columns the law is compared with): the two meshes' smoothed curves against each other for
0.1 <= x <= 0.3, and each mesh's scatter about its own smoothed curve (what one point is worth).

Usage: python3 tools/calibration/check_cylinder_axes.py [--runs DIR]   (DIR: the campaign's
runs, default $SOFTGRIP_FE_RUNS or /work/fe-scratch/runs; needs numpy, scipy and the runs'
job.frd files: they are not in the repository)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
sys.path.insert(0, HERE)
import fe_run  # noqa: E402
from fit_counterpart import smooth  # noqa: E402

CASE = "3d_cylinder_k1_flat_nu0.48_n{}"
MESHES = (14, 20)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--runs", default=os.environ.get("SOFTGRIP_FE_RUNS", "/work/fe-scratch/runs"))
    a = ap.parse_args()
    rows = {n: {round(r["x"], 4): r for r in fe_run.analyse(os.path.join(a.runs, CASE.format(n)))["rows"]}
            for n in MESHES}
    print(f"{CASE.format('N')}: N = {MESHES}, 0.1 <= x <= 0.3")
    xs = np.arange(0.1, 0.3001, 0.01)
    for key, what in (("a", "across, last node"), ("a32", "across, edge fit"),
                      ("b", "along, last node"), ("b32", "along, edge fit")):
        fits, scatter = {}, {}
        for n in MESHES:
            x = np.array([v for v in sorted(rows[n]) if v <= 0.3 + 1e-9])
            y = np.array([rows[n][v][key] for v in x])
            ok = np.isfinite(y)
            fits[n] = smooth(x[ok], y[ok])
            far = ok & (x >= 0.1 - 1e-9)
            scatter[n] = np.max(np.abs(y[far] / fits[n](x[far]) - 1))
        d = fits[MESHES[0]](xs) / fits[MESHES[1]](xs) - 1
        print(f"  {key:4s} ({what:17s}): smoothed R/{MESHES[0]} over R/{MESHES[1]} "
              f"{100 * d.min():+5.1f} .. {100 * d.max():+5.1f} %; one point about its own "
              f"smoothed curve: R/{MESHES[0]} {100 * scatter[MESHES[0]]:4.1f} %, "
              f"R/{MESHES[1]} {100 * scatter[MESHES[1]]:4.1f} %")


if __name__ == "__main__":
    main()
