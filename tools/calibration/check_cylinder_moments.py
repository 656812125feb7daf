#!/usr/bin/env python3
"""The 3D FE's contact patch on a cylinder by its pressure moments, and how well two meshes agree.

The semi-axes of the 3D runs (`fe_post3d`: where the gap crosses zero along the two symmetry
lines) move in node steps: R/14 and R/20 differ by up to 11 % (check_cylinder_axes.py), so they
cannot test the law's semi-axes to 5 %. Integrals of the pressure converge like the force does.
For a pressure `p0 (1 - u²/a² - v²/b²)^m` over an ellipse of semi-axes a (along the axis) and b
(across it), the second moments over the patch are

    <u²> = ∫ u² p dA / ∫ p dA = a² / (2 (m + 2)),    <v²> = b² / (2 (m + 2)),

so the ratio sqrt(<v²>/<u²>) is b/a whatever the shape m, and each RMS extent is a semi-axis
over sqrt(2 (m + 2)). This script integrates the nodal contact pressure (CPRESS) of every
surface node of the quarter model over a Delaunay triangulation of the surface's projection on
the plane of the patch (deformed x, z; a degree-4 rule per triangle on the linear interpolant),
and prints per output x: the force it integrates to against the run's reaction force, the RMS
extents along and across, and the ratio; then the two meshes' difference.

What it shows (session 13, the cylinder R2 = R, flat pad, nu = 0.48, R/14 and R/20): nothing is
resolved either. The nodal CPRESS of these quadratic-tetrahedron meshes integrates to the reaction
force only within -34 % to +51 % (R/14) and -4 % to +56 % (R/20; -4 % to +15 % from x = 0.05),
and the two meshes' RMS extents differ by up to 33 % (along) and 32 % (across) point by point,
their ratio by up to 43 %. The patch of the 3D runs is no better resolved by its pressure than by its
edge (check_cylinder_axes.py); a 5 % test of the semi-axes needs a finer 3D mesh (COUNTERPART.md).

Usage: python3 tools/calibration/check_cylinder_moments.py [--runs DIR] [--case NAME_WITH_{}]
       [--meshes 14 20] [--out CSV]
(DIR: the campaign's runs, default $SOFTGRIP_FE_RUNS or /work/fe-scratch/runs; needs numpy,
scipy and the runs' job.frd files, which are not in the repository.)
"""
import argparse
import os
import sys

import numpy as np
from scipy.spatial import Delaunay

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
from fe_post3d import Run3D  # noqa: E402

# A node is in contact where its gap to the counterpart is at most this [mm] (the penalty's
# penetration is negative; the pressure maps' filter, fe_campaign.py).
GAP_IN_CONTACT = 2e-5

# Dunavant's degree-4 rule on a triangle: barycentric points and weights (sum 1).
_A, _B = 0.445948490915965, 0.091576213509771
_PTS = np.array([[_A, _A, 1 - 2 * _A], [_A, 1 - 2 * _A, _A], [1 - 2 * _A, _A, _A],
                 [_B, _B, 1 - 2 * _B], [_B, 1 - 2 * _B, _B], [1 - 2 * _B, _B, _B]])
_W = np.array([0.223381589678011] * 3 + [0.109951743655322] * 3)


def moments(run, t):
    """(force, <x²>, <z²>) of the contact pressure at output time t, over the quarter x, z >= 0
    (the symmetric full patch has the same moments; force = 4 x the quarter's integral)."""
    s = run.surf
    P = run.X0[s] + run.U[t][s]
    p = run.C[t][s, 1]
    # the surface facing the counterpart: nodes below the equator of the undeformed sphere
    lower = run.X0[s, 1] < 1.0 - 0.3
    xz = P[lower][:, [0, 2]]
    # CPRESS is extrapolated from the faces' integration points and stays positive up to a face
    # beyond the contact edge (fe_post3d.Run3D.pressure): the pressure maps keep gap <= 2e-5 mm
    pl = np.where(run.cp.gap(P[lower]) <= GAP_IN_CONTACT, np.clip(p[lower], 0.0, None), 0.0)
    tri = Delaunay(xz)
    f = m2x = m2z = 0.0
    for simplex in tri.simplices:
        c = xz[simplex]
        area = 0.5 * abs((c[1, 0] - c[0, 0]) * (c[2, 1] - c[0, 1])
                         - (c[2, 0] - c[0, 0]) * (c[1, 1] - c[0, 1]))
        if area == 0.0 or not pl[simplex].any():
            continue
        q = _PTS @ c
        pv = _PTS @ pl[simplex]
        f += area * np.sum(_W * pv)
        m2x += area * np.sum(_W * pv * q[:, 0] ** 2)
        m2z += area * np.sum(_W * pv * q[:, 1] ** 2)
    return 4.0 * f, m2x / f, m2z / f


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--runs", default=os.environ.get("SOFTGRIP_FE_RUNS", "/work/fe-scratch/runs"))
    ap.add_argument("--case", default="3d_cylinder_k1_flat_nu0.48_n{}")
    ap.add_argument("--meshes", type=int, nargs="+", default=[14, 20])
    ap.add_argument("--out", help="write the last mesh's moments as CSV here")
    a = ap.parse_args()
    res = {}
    for n in a.meshes:
        run = Run3D(os.path.join(a.runs, a.case.format(n)))
        rows = {}
        for t in run.times:
            if t < 0.01 - 1e-9:
                continue
            f, mx, mz = moments(run, t)
            rows[round(t, 4)] = (run.F[t], f, np.sqrt(mx), np.sqrt(mz))
        res[n] = rows
        print(f"{a.case.format(n)}: x, F_reaction, F_pressure/F_reaction - 1 [%], "
              "RMS x (across) [mm], RMS z (along) [mm], ratio z/x")
        for x, (F, f, rx, rz) in sorted(rows.items()):
            print(f"  {x:5.3f} {F:9.5f} {100 * (f / F - 1):+6.2f} {rx:.5f} {rz:.5f} {rz / rx:.4f}")
    if len(a.meshes) >= 2:
        n0, n1 = a.meshes[0], a.meshes[-1]
        print(f"R/{n0} over R/{n1} - 1 [%]: x, RMS across, RMS along, ratio")
        for x in sorted(set(res[n0]) & set(res[n1])):
            r0, r1 = res[n0][x], res[n1][x]
            print(f"  {x:5.3f} {100 * (r0[2] / r1[2] - 1):+6.2f} {100 * (r0[3] / r1[3] - 1):+6.2f} "
                  f"{100 * ((r0[3] / r0[2]) / (r1[3] / r1[2]) - 1):+6.2f}")
    if a.out:
        n = a.meshes[-1]
        with open(a.out, "w") as fh:
            fh.write("delta_over_R,force_N,force_from_pressure_N,rms_across_mm,rms_along_mm\n")
            for x, (F, f, rx, rz) in sorted(res[n].items()):
                fh.write(f"{x:g},{F:.6g},{f:.6g},{rx:.6g},{rz:.6g}\n")


if __name__ == "__main__":
    main()
