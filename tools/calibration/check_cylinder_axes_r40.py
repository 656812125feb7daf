#!/usr/bin/env python3
"""The cylinder's semi-axes on the finer 3D mesh (R/40 at the pole), session 19 late runs.

Reads two 3D runs of the campaign (tools/fe/fe_campaign.py, /work/fe-scratch/runs/fe3d-axes):
the flat pad at nu = 0.48 on a plane (3d_flat_nu0.48_n40) and on the cylinder R2 = R
(3d_cylinder_k1_flat_nu0.48_n40), both to x = 0.3, and prints
  1. the 3D plane's radius (last node in contact `a`/`b`, edge fit `a32`/`b32`) against the
     axisymmetric R/40 run's (tests/data/fe/flat/force_nu0.48.csv, smoothed plus half an
     element, as fit_counterpart.py's plane_bias_3d), 0.05 <= x <= 0.3, per point;
  2. the cylinder's semi-axes at R/40 against the committed R/20 export
     (tests/data/fe/cylinder/flat/force_nu0.48_k1.csv), per point;
  3. the law's semi-axes (fit_counterpart.py's `law`, the law's form `LAW` fitted as that script
     does) against the R/40 cylinder per point and smoothed, raw and with the R/40 plane bias
     removed (the same correction as plane_bias_3d, from the R/40 plane run), 0.1 <= x <= 0.3;
  4. the upper envelope of each semi-axis column (a node-step reading only ever lags the true
     edge, so the readings that lie above a first smooth fit are the ones just after a node
     entered contact; `upper`): validated on the 3D planes (R/40 here, R/20 from
     tests/data/fe/cylinder/convergence.csv) against the axisymmetric radius, then the law
     over the cylinder's envelope at R/40 and R/20 at every x = 0.10, 0.11, ..., 0.30, for
     the envelope variants (fit from x >= 0.05 or 0.1; one or two passes; a/sqrt(x) of
     degree 1 or 2 in sqrt(x)).

Usage: python3 tools/calibration/check_cylinder_axes_r40.py [--runs DIR]  (numpy, scipy; the
runs' job.frd files are not in the repository)
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "fe"))
sys.path.insert(0, HERE)
import fe_run  # noqa: E402
import fit_counterpart as fc  # noqa: E402

ROOT = fc.ROOT
DATA = os.path.join(ROOT, "tests", "data", "fe")


def rows(runs, case):
    return {round(r["x"], 4): r for r in fe_run.analyse(os.path.join(runs, case))["rows"]}


def pct(v):
    return f"{100 * v:+6.1f}"


def fit_sqrt(x, y, deg):
    """Least-squares y/sqrt(x) = poly(sqrt x) of degree deg (fit_counterpart.py's `smooth`)."""
    s = np.sqrt(x)
    c = np.linalg.lstsq(np.vander(s, deg + 1, increasing=True), y / s, rcond=None)[0]
    return lambda xx: np.sqrt(xx) * (np.vander(np.sqrt(xx), deg + 1, increasing=True) @ c)


def upper(x, y, passes=1, deg=2):
    """The upper envelope of a node-step column: fit, keep the points on or above the fit,
    refit (`passes` times). Returns (curve, number of points kept)."""
    ok = np.isfinite(y)
    x, y = x[ok], y[ok]
    k = np.ones(len(x), bool)
    for _ in range(passes):
        f = fit_sqrt(x[k], y[k], deg)
        k = y >= f(x) * (1 - 1e-9)
    return fit_sqrt(x[k], y[k], deg), int(k.sum())


VARIANTS = [(lo, passes, deg) for lo in (0.05, 0.1) for passes in (1, 2) for deg in (1, 2)]


def envelopes(pl, cy, ax_s, law_of):
    """Section 4 (see the module doc)."""
    lag = 0.485 / 40
    conv = [ln.strip().split(",") for ln in open(os.path.join(DATA, "cylinder", "convergence.csv"))
            if ln.startswith("flat,0.48,0,3d,20,")]
    x20p = np.array([float(r[6]) for r in conv])
    a20p = np.array([float(r[10]) for r in conv])
    r20 = np.genfromtxt(os.path.join(DATA, "cylinder", "flat", "force_nu0.48_k1.csv"), delimiter=",",
                        names=True, skip_header=1)
    cols = {"a": "semi_axis_across_mm", "b": "semi_axis_along_mm",
            "a32": "semi_axis_across_32_mm", "b32": "semi_axis_along_32_mm"}
    xg = np.round(np.arange(0.1, 0.3001, 0.01), 4)
    law = law_of(xg)
    print("\n## 4. upper envelopes (variant: fit from x >= lo, passes, degree); % at x = 0.10..0.30")
    worst = {k: 0.0 for k in cols}
    for lo, passes, deg in VARIANTS:
        print(f"  -- lo {lo}, {passes} pass(es), degree {deg}")
        x = np.array([v for v in sorted(pl) if v >= lo - 1e-9])
        for k in ("a", "b", "a32", "b32"):
            f, n = upper(x, np.array([pl[v][k] for v in x]), passes, deg)
            e = f(xg) / (ax_s(xg) + lag) - 1
            print(f"    plane R/40 {k:4s}: envelope ({n:2d} pts) / axisymmetric {pct(e.min())} .. {pct(e.max())}")
        s = x20p >= lo - 1e-9
        f, n = upper(x20p[s], a20p[s], passes, deg)
        e = f(xg) / (ax_s(xg) + lag) - 1
        print(f"    plane R/20 a   : envelope ({n:2d} pts) / axisymmetric {pct(e.min())} .. {pct(e.max())}")
        x = np.array([v for v in sorted(cy) if v >= lo - 1e-9])
        s = (r20["delta_over_R"] >= lo - 1e-9) & (r20["delta_over_R"] <= 0.3 + 1e-9)
        for k, col in cols.items():
            f4, n4 = upper(x, np.array([cy[v][k] for v in x]), passes, deg)
            f2, n2 = upper(r20["delta_over_R"][s], r20[col][s], passes, deg)
            e4 = law[k] / f4(xg) - 1
            e2 = law[k] / f2(xg) - 1
            d = f4(xg) / f2(xg) - 1
            worst[k] = max(worst[k], np.max(np.abs(e4)))
            print(f"    cylinder {k:4s}: law / envelope R/40 ({n4:2d} pts) {pct(e4.min())} .. {pct(e4.max())}; "
                  f"law / envelope R/20 ({n2:2d} pts) {pct(e2.min())} .. {pct(e2.max())}; "
                  f"envelope R/40 / R/20 {pct(d.min())} .. {pct(d.max())}")
    print("  worst |law / envelope R/40 - 1| over all variants: "
          + ", ".join(f"{k} {100 * v:.1f} %" for k, v in worst.items()))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--runs", default="/work/fe-scratch/runs/fe3d-axes")
    args = ap.parse_args()

    # ---- 1. the 3D plane at R/40 against the axisymmetric R/40
    pl = rows(args.runs, "3d_flat_nu0.48_n40")
    axi = np.genfromtxt(os.path.join(DATA, "flat", "force_nu0.48.csv"), delimiter=",", names=True,
                        skip_header=1)
    ax_s = fc.smooth(axi["delta_over_R"], axi["contact_radius_mm"])
    lag = 0.485 / 40
    xs = np.array([x for x in sorted(pl) if 0.05 - 1e-9 <= x <= 0.3 + 1e-9])
    truth = ax_s(xs) + lag
    print("## 1. 3D plane R/40 over axisymmetric R/40 (smoothed + 0.485 R/40), per point, %")
    print("   x     a_axi   a(x)   b(z)   a32    b32")
    cols = {k: np.array([pl[x][k] for x in xs]) for k in ("a", "b", "a32", "b32")}
    for i, x in enumerate(xs):
        print(f"  {x:.2f}  {truth[i]:.4f} " + " ".join(pct(cols[k][i] / truth[i] - 1) for k in ("a", "b", "a32", "b32")))
    for k in ("a", "b", "a32", "b32"):
        e = cols[k] / truth - 1
        print(f"  {k:4s}: {pct(e.min())} .. {pct(e.max())} % (mean {pct(np.mean(e))} %)")
    # the bias as plane_bias_3d: true/read as a quadratic in the read radius (last node, the
    # mean of the two symmetry lines' readings, as R/20's one contact_radius column)
    read = 0.5 * (cols["a"] + cols["b"])
    bias = truth / read
    cb = np.polyfit(read, bias, 2)
    lo, hi = read.min(), read.max()
    correct = lambda a: a * np.polyval(cb, np.clip(a, lo, hi))  # noqa: E731
    low = 100 * (1 - 1 / bias)
    print(f"  bias fit (mean of a, b): read {low.min():.1f} .. {low.max():.1f} % low "
          f"(mean {100 * (1 - np.mean(1 / bias)):.1f} %); quadratic residual "
          f"{100 * np.max(np.abs(correct(read) / truth - 1)):.1f} % worst")

    # ---- 2. the cylinder at R/40 against the R/20 export
    cy = rows(args.runs, "3d_cylinder_k1_flat_nu0.48_n40")
    r20 = np.genfromtxt(os.path.join(DATA, "cylinder", "flat", "force_nu0.48_k1.csv"), delimiter=",",
                        names=True, skip_header=1)
    r20d = {round(float(x), 4): i for i, x in enumerate(r20["delta_over_R"])}
    names = {"a": "semi_axis_across_mm", "b": "semi_axis_along_mm",
             "a32": "semi_axis_across_32_mm", "b32": "semi_axis_along_32_mm"}
    print("\n## 2. cylinder R2 = R, flat, nu 0.48: R/40 over R/20 per point, % (a across, b along)")
    print("   x      a40    b40    a32_40 b32_40 | a      b      a32    b32   | force")
    xc = [x for x in sorted(cy) if x in r20d and x >= 0.05 - 1e-9]
    worst = {k: 0.0 for k in names}
    for x in xc:
        i = r20d[x]
        e = {k: cy[x][k] / r20[names[k]][i] - 1 for k in names}
        for k in names:
            if x >= 0.1 - 1e-9:
                worst[k] = max(worst[k], abs(e[k]))
        print(f"  {x:.2f}  " + " ".join(f"{cy[x][k]:.4f}" for k in ("a", "b", "a32", "b32")) + " | "
              + " ".join(pct(e[k]) for k in ("a", "b", "a32", "b32"))
              + f" | {pct(cy[x]['F'] / r20['force_N'][i] - 1)}")
    print("  worst |R/40 / R/20 - 1| for 0.1 <= x <= 0.3: "
          + ", ".join(f"{k} {100 * v:.1f} %" for k, v in worst.items()))

    # ---- 3. the law against R/40
    curves = fc.load(DATA)
    fitted = [c for c in curves if not c.held_out]
    coef = {cons: fc.fit(fitted, cons, fc.LAW) for cons in ("free", "flat")}
    coef["cap"] = True
    print("\n## 3. law (`%s`, flat: %s) over the R/40 cylinder, 0.1 <= x <= 0.3"
          % (fc.LAW, tuple(round(float(v), 6) for v in coef["flat"])))
    c = [c for c in curves if c.kind == "cylinder" and c.construction == "flat" and c.nu == 0.48
         and c.k == 1][0]
    x = np.array([v for v in sorted(cy)])
    _, axes, _, top = fc.law(c, x, coef)
    law = {"b": axes[0], "a": axes[1]}  # the law's first semi-axis is along the axis
    sel = (x >= 0.1 - 1e-9) & (x <= min(0.3, top) + 1e-9)
    print(f"  law valid to x = {top:.3f}")
    summary = []
    for k, lk, what in (("a", "a", "across, last node"), ("b", "b", "along, last node"),
                        ("a32", "a", "across, edge fit"), ("b32", "b", "along, edge fit")):
        fe = np.array([cy[v][k] for v in x])
        ok = np.isfinite(fe)
        fs = fc.smooth(x[ok], fe[ok])
        pp = law[lk][sel] / fe[sel] - 1
        sm = law[lk][sel] / fs(x[sel]) - 1
        line = (f"  {k:4s} ({what:17s}): per point {pct(pp.min())} .. {pct(pp.max())} % "
                f"(mean {pct(np.nanmean(pp))}); smoothed {pct(sm.min())} .. {pct(sm.max())} % "
                f"(mean {pct(sm.mean())})")
        if k in ("a", "b"):
            pc = law[lk][sel] / correct(fe[sel]) - 1
            scx = law[lk][sel] / correct(fs(x[sel])) - 1
            line += (f"\n        bias removed: per point {pct(pc.min())} .. {pct(pc.max())} % "
                     f"(mean {pct(pc.mean())}); smoothed {pct(scx.min())} .. {pct(scx.max())} %")
        print(line)
        summary.append((k, pp))
    print("\n  per point (law / FE - 1, %):\n   x     " + "  ".join(f"{k:>6s}" for k, _ in summary)
          + "   a_corr  b_corr")
    for j, v in enumerate(x[sel]):
        fa, fb = cy[v]["a"], cy[v]["b"]
        print(f"  {v:.2f} " + " ".join(pct(pp[j]) for _, pp in summary)
              + f"  {pct(law['a'][sel][j] / correct(fa) - 1)}  {pct(law['b'][sel][j] / correct(fb) - 1)}")

    def law_of(xx):
        _, ax, _, _ = fc.law(c, xx, coef)
        return {"a": ax[1], "b": ax[0], "a32": ax[1], "b32": ax[0]}
    envelopes(pl, cy, ax_s, law_of)


if __name__ == "__main__":
    main()
