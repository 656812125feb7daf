#!/usr/bin/env python3
"""Run one softgrip FE case: mesh + deck (fe_model), CalculiX, post-processing (fe_post).

usage: fe_run.py GEOMETRY --nu NU [--t T] [--h 60] [--tend 0.75] [--dt-small 0.0025] [--dir DIR]
                 [--timeout S] [--counterpart plane|ball|cylinder|edge --k R2/R] [--dim 2|3]
                 [--element CAX8R|CAX8]
  GEOMETRY free | flat | core; --h is R / element size at the contact (60 = fine, 30 = coarse).
  --counterpart: what the fingertip is pressed on: plane (the default) or a rigid ball of radius
  k R (axisymmetric), a rigid cylinder of radius k R or a right-angle edge (3D quarter models,
  fe_model3d; --h is then R / element size at the pole). --dim 3 runs the plane in 3D.
Writes DIR/job.inp, job.dat, job.frd, log, meta.json and prints x, force, contact radius, min J.
ccx runs single-threaded under nice (OMP_NUM_THREADS=1, nice -n 5).
"""
from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fe_model  # noqa: E402
import fe_model3d  # noqa: E402
import fe_post  # noqa: E402
import fe_post3d  # noqa: E402

J_CUT = 0.2
_GMSH = threading.Lock()  # gmsh keeps global state: one mesh at a time per process  # data beyond the first point with min element J below this are dropped


def ccx_version():
    try:
        out = subprocess.run(["ccx", "-v"], capture_output=True, text=True, timeout=30).stdout
        m = re.search(r"Version\s+(\S+)", out)
        return m.group(1) if m else "unknown"
    except Exception:
        return "unknown"


def make_case(geometry, nu, t=0.0, h=60, tend=0.75, dt_small=0.0025, late_dt=0.01,
              counterpart="plane", k=0.0, dim=2, element="CAX8R"):
    """Load steps: increments <= dt_small to x = 0.1 (the contact front crosses a face every few
    increments there; coarser increments leave a jitter of up to 0.5 % in force), <= 2 dt_small
    to 0.2, <= late_dt beyond (0.005 for nearly incompressible material). `element`: the
    axisymmetric body's element type (fe_model.ELEMENTS; the 3D models have C3D10 only)."""
    steps = [(0.1, dt_small), (0.2, min(2 * dt_small, late_dt)), (tend, late_dt)]
    steps = [s for s in steps if s[0] < tend] + [(tend, [d for x, d in steps if x >= tend][0])]
    if dim == 3 or counterpart in ("cylinder", "edge"):
        if element != "CAX8R":
            raise ValueError(f"the 3D models have C3D10 elements only, not {element}")
        if geometry not in fe_model3d.GEOMETRIES:
            raise ValueError(f"3D models are {fe_model3d.GEOMETRIES}, not {geometry}")
        return fe_model3d.Case3D(geometry=geometry, nu=nu, t=t, counterpart=counterpart, k=k,
                                 n=h, steps=steps)
    return fe_model.Case(geometry=geometry, nu=nu, t=t, h=1.0 / h, steps=steps,
                         counterpart=counterpart, k=k, element=element)


def run_case(case, rundir, timeout=3000):
    os.makedirs(rundir, exist_ok=True)
    with _GMSH:
        deck = fe_model3d.deck if getattr(case, "dim", 2) == 3 else fe_model.deck
        info = deck(case, f"{rundir}/job.inp")
    env = dict(os.environ, OMP_NUM_THREADS="1")
    t0 = time.time()
    with open(f"{rundir}/log", "w") as log:
        try:
            rc = subprocess.run(["nice", "-n", "5", "ccx", "job"], cwd=rundir, env=env,
                                stdout=log, stderr=subprocess.STDOUT, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
    meta = dict(case=case.__dict__, mesh=info, rc=rc, wall_s=round(time.time() - t0, 1),
                ccx=ccx_version(), date=time.strftime("%Y-%m-%d", time.gmtime()),
                timeout_s=timeout)
    json.dump(meta, open(f"{rundir}/meta.json", "w"), indent=1, default=str)
    return meta


def analyse(rundir):
    """Rows of every converged output point, the cut (J) and why the run stopped."""
    meta = json.load(open(f"{rundir}/meta.json"))
    run = (fe_post3d.Run3D if meta["case"].get("dim", 2) == 3 else fe_post.Run)(rundir)
    rows = [run.row(t) for t in run.times]
    tend = meta["case"]["steps"][-1][0]
    last = rows[-1]["x"] if rows else 0.0
    log = open(f"{rundir}/log", errors="replace").read()
    why = []
    stopped = os.path.join(rundir, "STOPPED")  # a note left by whoever stopped the run by hand
    if os.path.exists(stopped):
        why.append(open(stopped).read().strip())
    elif meta["rc"] == "timeout":
        why.append(f"wall-clock limit ({meta['timeout_s']} s) reached")
    elif last >= tend - 1e-9:
        why.append(f"reached the end of the load (x = {tend:g})")
    else:
        incs = [float(v) for v in re.findall(r"largest increment of disp=\s*(\S+)", log[-200000:])]
        err = re.findall(r"\*ERROR[^\n]*", log)
        big = max(incs[-40:]) if incs else 0.0
        s = "diverged"
        if big > 0.5:
            s += f" (displacement increments up to {big:.3g} mm)"
        if err:
            s += ": " + err[-1].strip()
        why.append(s)
    cut = None
    for r in rows:
        if r["minJ"] < J_CUT:
            cut = r["x"]
            break
    if cut is not None:
        why.append(f"min element J < {J_CUT} from x = {cut:g}: data cut there")
        rows = [r for r in rows if r["x"] < cut]
    if rows and rows[-1]["lift"] > 1e-4:
        why.append(f"free surface above the bonded edge by {rows[-1]['lift']:.3g} mm (fold-over)")
    fpk = max(range(len(rows)), key=lambda i: rows[i]["F"]) if rows else None
    if fpk is not None and fpk < len(rows) - 1:
        why.append(f"force peaks at x = {rows[fpk]['x']:g}")
    return dict(meta=meta, rows=rows, run=run, reached=rows[-1]["x"] if rows else 0.0,
                last_converged=last, why="; ".join(why))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("geometry", choices=fe_model.GEOMETRIES)
    ap.add_argument("--dim", type=int, choices=[2, 3], default=2)
    ap.add_argument("--nu", type=float, required=True)
    ap.add_argument("--t", type=float, default=0.0, help="shell thickness / R (core)")
    ap.add_argument("--h", type=float, default=60, help="R / element size at the contact")
    ap.add_argument("--tend", type=float, default=0.75)
    ap.add_argument("--dt-small", type=float, default=0.0025,
                    help="max load increment to x = 0.1 (twice that to 0.2, 0.01 beyond)")
    ap.add_argument("--dir", default=None)
    ap.add_argument("--timeout", type=float, default=3000)
    ap.add_argument("--counterpart", choices=["plane", "ball", "cylinder", "edge"],
                    default="plane")
    ap.add_argument("--k", type=float, default=0.0, help="ball or cylinder radius / R")
    ap.add_argument("--element", choices=fe_model.ELEMENTS, default="CAX8R",
                    help="the axisymmetric body's element (CAX8R reduced, CAX8 full integration)")
    a = ap.parse_args()
    case = make_case(a.geometry, a.nu, a.t, a.h, a.tend, a.dt_small, counterpart=a.counterpart,
                     k=a.k, dim=a.dim, element=a.element)
    d = a.dir or f"/tmp/softgrip-fe/{case.name}"
    meta = run_case(case, d, a.timeout)
    res = analyse(d)
    print(f"# {case.name}: {meta['wall_s']} s, reached x = {res['reached']:g}: {res['why']}")
    if "b" in (res["rows"] or [{}])[0]:
        print("delta_over_R,force_N,semi_axis_across_mm,semi_axis_along_mm,min_element_J")
        for r in res["rows"]:
            print(f"{r['x']:g},{r['F']:.6g},{r['a']:.6g},{r['b']:.6g},{r['minJ']:.4f}")
        return
    print("delta_over_R,force_N,contact_radius_mm,min_element_J")
    for r in res["rows"]:
        print(f"{r['x']:g},{r['F']:.6g},{r['a']:.6g},{r['minJ']:.4f}")


if __name__ == "__main__":
    main()
