#!/usr/bin/env python3
"""softgrip's FE campaign: run a list of cases, export the CSVs, check mesh convergence and the
reproduction of the reference.

  fe_campaign.py list
  fe_campaign.py run [--only NAME ...] [--runs DIR] [-j 2] [--deadline HH:MM] [--timeout S]
  fe_campaign.py export [--runs DIR]      # writes tests/data/fe/<geometry>/*.csv
  fe_campaign.py reproduce [--runs DIR]   # free vs tests/data/fe/force_nu{0.3,0.49}.csv

Case names are fe_model.Case.name: free_nu0.49_h60, flat_nu0.48_h60, core_nu0.48_t0.4_h60, ...
Runs live outside the repo (default /tmp/softgrip-fe, or $SOFTGRIP_FE_RUNS); at most two ccx at a
time, each single-threaded under nice.
"""
from __future__ import annotations

import argparse
import glob
import os
import sys
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import fe_run  # noqa: E402

OUT = os.path.join(REPO, "tests", "data", "fe")
PRESSURE_X = (0.1, 0.3, 0.5)
TEND = 0.7


def cases():
    """The campaign in priority order: (geometry, nu, t/R, R/h, role). role "main" makes the
    committed force and pressure files; "conv" is the other mesh of a convergence check (to
    x = 0.5), compared with the "main" run of the same geometry, nu and t; "smoke" is exactly the
    case smoke.sh runs (flat nu = 0.48, R/30, to x = 0.3), which is also flat's convergence check.
    free runs on the reference's fine mesh (R/60: it validates the pipeline against the
    reference); flat and core on R/40: each ccx iteration costs ~0.4 s CPU per 1000 elements,
    and the machine is shared. Convergence is checked against a coarser mesh (R/30 vs R/40, and
    R/40 vs R/60 for free): two meshes that agree within 0.5 % bound the finer one's error if convergence is monotone."""
    c = [("free", 0.49, 0, 60, "main"), ("free", 0.3, 0, 60, "main"),
         ("flat", 0.48, 0, 40, "main"), ("flat", 0.3, 0, 40, "main"),
         ("flat", 0.48, 0, 30, "smoke"),
         ("flat", 0.4, 0, 40, "main"),
         ("core", 0.48, 0.4, 40, "main"), ("core", 0.48, 0.4, 30, "conv"),
         ("flat", 0.499, 0, 40, "main"),
         ("core", 0.3, 0.4, 40, "main"), ("core", 0.499, 0.4, 40, "main"),
         ("free", 0.49, 0, 40, "conv")]
    for t in (0.2, 0.6, 0.8):
        c += [("core", nu, t, 40, "main") for nu in (0.48, 0.3, 0.499)]
    # the free sphere's reach at nu >= 0.4 (x = 0.76-0.78), for calibrated's extension past 0.65
    # checked on nu the reference does not have; R/40 (R/30 and R/60 agree to 0.003 % at x = 0.5)
    c += [("free", nu, 0, 40, "reach") for nu in (0.4, 0.45)]
    # held out of every fit: nu and t/R between the fitted ones, to check the calibrated forms
    # on constructions they were not fitted to (the tests say which files are held out)
    c += [("core", 0.4, 0.3, 40, "heldout"), ("flat", 0.45, 0, 40, "heldout"),
          ("core", 0.45, 0.5, 40, "heldout"), ("core", 0.35, 0.7, 40, "heldout"),
          ("flat", 0.35, 0, 40, "heldout"), ("core", 0.49, 0.3, 40, "heldout")]
    # mesh convergence of the thinnest skin (t/R = 0.2: 8 elements through it at R/40, 12 at
    # R/60), and core at nu = 0.4 for the fit: the other core runs are at nu = 0.3 and >= 0.48 only
    c += [("core", 0.48, 0.2, 60, "conv"), ("core", 0.4, 0.4, 40, "main"),
          ("core", 0.4, 0.2, 40, "main")]
    # a second held-out set (session 6): thin skins between the fitted t/R, where the core law's
    # residual is largest, at nu between the fitted ones
    c += [("core", 0.46, 0.25, 40, "heldout"), ("core", 0.33, 0.25, 40, "heldout"),
          ("core", 0.42, 0.55, 40, "heldout"), ("core", 0.36, 0.2, 40, "heldout"),
          ("core", 0.44, 0.8, 40, "heldout"), ("core", 0.495, 0.35, 40, "heldout")]
    # mesh convergence of the thinnest skin away from nu = 0.48 (session 7): near
    # incompressibility (nu = 0.499, K/mu = 500) a reduced-integration mesh can lock, and nu =
    # 0.4 is where the core law's residual at t/R = 0.2 has the other sign
    c += [("core", 0.499, 0.2, 60, "conv"), ("core", 0.4, 0.2, 60, "conv")]
    return c


def make(geometry, nu, t, h, role="main"):
    if role == "smoke":  # exactly what smoke.sh runs
        return fe_run.make_case(geometry, nu, t, h, 0.3, dt_small=0.005)
    # free only validates the pipeline against the reference (to x = 0.5, nu = 0.3 is cut at
    # 0.61 by element collapse): 0.6 is enough; convergence checks go to 0.5
    tend = (0.6 if geometry == "free" else TEND) if role == "main" else 0.5
    if role == "reach":
        tend = 0.82
    # free reproduces the reference with its increments (<= 0.0025 to x = 0.1); flat and core
    # use <= 0.005 to 0.1 and <= 0.01 beyond: a third fewer increments on a shared machine
    dt_small = 0.0025 if geometry == "free" else 0.005
    late_dt = 0.005 if nu >= 0.499 else 0.01
    if geometry == "core" and nu >= 0.499:
        # the nearly incompressible layer bonded on both sides: at 0.005 the first Newton
        # iterate past x = 0.04 (t/R = 0.4) throws the contact open and ccx aborts; 0.001 passes
        dt_small, late_dt = 0.001, 0.002
    return fe_run.make_case(geometry, nu, t, h, tend, dt_small=dt_small, late_dt=late_dt)


def cmd_run(a):
    todo = [make(*c) for c in cases()]
    names = [c.name for c in todo]
    todo = [c for i, c in enumerate(todo) if c.name not in names[:i]]
    if a.only:
        todo = [c for c in todo if c.name in a.only]
    deadline = None
    if a.deadline:
        hh, mm = map(int, a.deadline.split(":"))
        now = time.gmtime()
        deadline = time.mktime(now[:3] + (hh, mm, 0) + now[6:]) - time.timezone
    lock = threading.Lock()

    def worker():
        while True:
            with lock:
                if not todo:
                    return
                case = todo.pop(0)
            d = os.path.join(a.runs, case.name)
            # a case is claimed by creating its run directory, so that several campaign
            # processes can share one queue
            try:
                os.makedirs(d)
            except FileExistsError:
                if not a.force:
                    print(f"{case.name}: run directory exists (done or running), skipped",
                          flush=True)
                    continue
            timeout = a.timeout
            if deadline is not None:
                timeout = min(timeout, deadline - time.time())
                if timeout < 300:
                    print(f"{case.name}: not started, deadline too close", flush=True)
                    os.rmdir(d)
                    continue
            print(f"{case.name}: start {time.strftime('%H:%M:%S', time.gmtime())}, "
                  f"timeout {timeout:.0f} s", flush=True)
            meta = fe_run.run_case(case, d, timeout)
            res = fe_run.analyse(d)
            print(f"{case.name}: {meta['wall_s']} s, reached x = {res['reached']:g}: {res['why']}",
                  flush=True)

    th = [threading.Thread(target=worker) for _ in range(min(a.j, 2))]
    for t in th:
        t.start()
    for t in th:
        t.join()


def fname(geometry, nu, t, kind="force", x=None):
    s = f"{kind}_nu{nu:g}" + (f"_t{t:g}" if geometry == "core" else "")
    if x is not None:
        s += f"_d{x:g}"
    return os.path.join(OUT, geometry, s + ".csv")


def provenance(res, extra=""):
    m = res["meta"]
    c = m["case"]
    steps = ", ".join(f"<= {d:g} to x = {x:g}" for x, d in c["steps"])
    name = os.path.basename(res["dir"])
    return (f"# provenance: softgrip tools/fe, CalculiX {m['ccx']} (ccx), gmsh {m['mesh']['gmsh']}; "
            f"geometry {c['geometry']} nu = {c['nu']:g}" +
            (f" t/R = {c['t']:g}" if c["geometry"] == "core" else "") +
            f"; compressible neo-Hookean mu = {c['mu']:g} MPa (C10 = mu/2, D1 = 2/K), R = 1 mm, "
            f"NLGEOM; CAX8R, element edge R/{1 / c['h']:.0f} at the contact surface "
            f"({m['mesh']['elements']} elements); frictionless linear penalty {c['kpen']:g} MPa/mm "
            f"against a rigid plane; load increments {steps}; run {m['date']}, {m['wall_s']:.0f} s; "
            f"reached x = {res['reached']:g}: {res['why']}{extra}; "
            f"regenerate: PY=$(bash tools/fe/setup.sh); $PY tools/fe/fe_campaign.py run "
            f"--runs DIR --only {name} && $PY tools/fe/fe_campaign.py export --runs DIR")


def load(runs, geometry, nu, t, h, role="main"):
    case = make(geometry, nu, t, h, role)
    d = os.path.join(runs, case.name)
    if not os.path.exists(os.path.join(d, "meta.json")):
        return None
    res = fe_run.analyse(d)
    res["dir"] = d
    return res


def write_force(path, res):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(provenance(res) + "\n")
        f.write("delta_over_R,force_N,contact_radius_mm,min_element_J,V_over_V0,"
                "max_copen_over_delta,max_lift_mm\n")
        for r in res["rows"]:
            f.write(f"{r['x']:g},{r['F']:.6g},{r['a']:.6g},{r['minJ']:.4f},{r['VV0']:.5f},"
                    f"{r['copen']:.3g},{r['lift']:.3g}\n")


def write_pressure(path, res, x):
    pr = res["run"].pressure(round(x, 6))
    if pr is None or res["reached"] < x - 1e-9:
        return False
    r, p = pr
    F = [q["F"] for q in res["rows"] if abs(q["x"] - x) < 1e-9][0]
    integ = float(np.trapezoid(2 * np.pi * r * p, r))
    with open(path, "w") as f:
        f.write(provenance(res, f"; profile at x = {x:g}: nodal CPRESS of the curved surface "
                                f"against the deformed radius, the 4 nodes nearest the axis dropped "
                                f"(tied face), cut at a_lin and closed by p = 0 there; 2 pi int r p dr = {integ:.5g} N vs force {F:.5g} N") + "\n")
        f.write("r_mm,pressure_MPa\n")
        for ri, pi in zip(r, p):
            f.write(f"{ri:.6g},{pi:.6g}\n")
    return True


def cmd_export(a):
    done = {}
    for g, nu, t, h, role in cases():
        if role not in ("main", "reach", "heldout"):
            continue
        res = load(a.runs, g, nu, t, h, role)
        if res is None or not res["rows"]:
            continue
        write_force(fname(g, nu, t), res)
        for x in PRESSURE_X:
            write_pressure(fname(g, nu, t, "pressure", x), res, x)
        done[(g, nu, t)] = (h, res)
        print(f"{g} nu={nu:g} t={t:g}: reached x = {res['reached']:g}: {res['why']}")
    checks = {}
    for g, nu, t, h, role in cases():
        if role not in ("conv", "smoke"):
            continue
        other = load(a.runs, g, nu, t, h, role)
        if other is None or (g, nu, t) not in done:
            continue
        hb, base = done[(g, nu, t)]
        Fb = {r["x"]: r for r in base["rows"]}
        prov = provenance(other, f"; mesh convergence of {g} nu = {nu:g}" +
                          (f" t/R = {t:g}" if g == "core" else "") +
                          f": R/{hb:g} (the campaign mesh) against R/{h:g}; reldiff = "
                          f"(F_R/{hb:g} - F_R/{h:g}) / F_R/{h:g}")
        rows, worst = [], 0.0
        for r in other["rows"]:
            b = Fb.get(r["x"])
            if b is None:
                continue
            d = 100 * (b["F"] - r["F"]) / r["F"]
            worst = max(worst, abs(d))
            rows.append(f"{nu:g},{t:g},{hb:g},{h:g},{r['x']:g},{b['F']:.6g},{r['F']:.6g},{d:.3f},"
                        f"{b['a']:.5g},{r['a']:.5g}")
        checks.setdefault(g, {})[(nu, t, hb, h)] = (prov, rows)
        print(f"convergence {g} nu={nu:g} t={t:g}: max |F_h{hb:g} - F_h{h:g}| / F = {worst:.3f} %")
    for g, new in checks.items():
        write_convergence(os.path.join(OUT, g, "convergence.csv"), new)


CONV_HEADER = ("nu,t_over_R,h_campaign,h_other,delta_over_R,force_N_campaign,force_N_other,"
               "reldiff_pct,contact_radius_mm_campaign,contact_radius_mm_other")


def read_convergence(path):
    """The checks already in `path`, keyed (nu, t, R/h campaign, R/h other): (provenance, rows).
    Reads this format and the earlier one-check file (header delta_over_R,force_N_h40,...)."""
    if not os.path.exists(path):
        return {}
    lines = open(path).read().splitlines()
    provs = [ln for ln in lines if ln.startswith("# provenance:")]
    data = [ln for ln in lines if ln and not ln.startswith("#")]
    out = {}
    if data and data[0] == CONV_HEADER:
        for ln in data[1:]:
            v = ln.split(",")
            key = tuple(float(q) for q in v[:4])
            out.setdefault(key, [None, []])[1].append(ln)
        for key in out:  # the provenance line names its case's nu, t/R and both meshes
            tag = f"nu = {key[0]:g}" + (f" t/R = {key[1]:g}" if key[1] else "")
            mesh = f"R/{key[2]:g} (the campaign mesh) against R/{key[3]:g}"
            out[key][0] = next(pv for pv in provs if tag + ":" in pv and mesh in pv)
    elif data:  # one check: delta_over_R,force_N_h{A},force_N_h{B},reldiff_pct,...
        import re
        hb, h = (float(q) for q in re.findall(r"force_N_h(\d+)", data[0]))
        m = re.search(r"nu = ([\d.]+)(?: t/R = ([\d.]+))?:", provs[0])
        nu, t = float(m.group(1)), float(m.group(2) or 0)
        rows = [f"{nu:g},{t:g},{hb:g},{h:g}," + ln for ln in data[1:]]
        out[(nu, t, hb, h)] = [provs[0], rows]
    return {k: tuple(v) for k, v in out.items()}


def write_convergence(path, new):
    """`convergence.csv` of one geometry: every check (one provenance line each, then one table
    with nu and t/R columns); checks regenerated now replace their earlier rows, the others are
    kept (their runs need not be in this --runs directory)."""
    checks = read_convergence(path)
    checks.update(new)
    with open(path, "w") as f:
        for key in sorted(checks):
            f.write(checks[key][0] + "\n")
        f.write(CONV_HEADER + "\n")
        for key in sorted(checks):
            for ln in checks[key][1]:
                f.write(ln + "\n")


def cmd_reproduce(a):
    ok = True
    for nu in (0.3, 0.49):
        res = load(a.runs, "free", nu, 0, 60, "main")
        if res is None:
            print(f"nu = {nu}: not run")
            ok = False
            continue
        ref = np.genfromtxt(os.path.join(OUT, f"force_nu{nu:g}.csv"), delimiter=",", names=True)
        mine = {round(r["x"], 6): r["F"] for r in res["rows"]}
        errs = [(x, 100 * (mine[round(x, 6)] - F) / F) for x, F in zip(ref["delta_over_R"], ref["force_N"])
                if 0.01 - 1e-9 <= x <= 0.5 + 1e-9 and round(x, 6) in mine]
        w = max(errs, key=lambda e: abs(e[1]))
        print(f"free nu = {nu}: {len(errs)} points 0.01..0.5, max |rel err| = {abs(w[1]):.3f} % "
              f"at x = {w[0]:g}")
        ok &= abs(w[1]) <= 0.5 and len(errs) == 50
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("cmd", choices=["list", "run", "export", "reproduce"])
    ap.add_argument("--runs", default=os.environ.get("SOFTGRIP_FE_RUNS", "/tmp/softgrip-fe"))
    ap.add_argument("--only", nargs="*")
    ap.add_argument("-j", type=int, default=2)
    ap.add_argument("--deadline", help="HH:MM UTC: no run is started or allowed to run past it")
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--force", action="store_true", help="rerun cases that have a meta.json")
    a = ap.parse_args()
    if a.cmd == "list":
        for c in cases():
            print(make(*c).name, c[4])
    elif a.cmd == "run":
        cmd_run(a)
    elif a.cmd == "export":
        cmd_export(a)
    elif a.cmd == "reproduce":
        sys.exit(cmd_reproduce(a))


if __name__ == "__main__":
    main()
