"""softgrip against its peers: runs the MuJoCo and Drake sides of the comparison, reads the
softgrip/rapier side (the JSON lines of `peers_softgrip`) and softgrip's grasp throughput
(`sweep_throughput`'s table), and writes the speed-vs-error table (markdown), the raw results
(JSON) and the plot (PNG). Run through `bash tools/peers/run.sh`, which builds and runs the
Rust side first.

    python tools/peers/peers.py --rust RUST.jsonl --sweep SWEEP.txt --out DIR
"""

import argparse
import json
import os
import platform
import re
import subprocess
import sys
import time
import tomllib
from importlib.metadata import version
from pathlib import Path

import numpy as np

import drake_peers
import mujoco_peers
from common import (ERR_AT, ERR_RANGE, FE_FILE, FE_X, ROOT, StepTimer, errors, fe_force,
                    machine)


def log(msg):
    """Progress on stderr (the tables go to stdout)."""
    print(f"[peers {time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def read_rust(path):
    """The records of `peers_softgrip`, by kind."""
    out = {}
    for line in Path(path).read_text().splitlines():
        if line.startswith("{"):
            rec = json.loads(line)
            out.setdefault(rec["kind"], []).append(rec)
    return out


def read_sweep(path):
    """softgrip's grasp throughput from `sweep_throughput`'s markdown table (1 thread)."""
    text = Path(path).read_text()
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[0] == "1":
            return {
                "trials": int(cells[1]),
                "wall_s": float(cells[2]),
                "trials_per_s": float(cells[3]),
                "cores_used": cells[5],
                "held": int(cells[6]),
                "errors": int(cells[7]),
            }
    raise SystemExit(f"{path}: no 1-thread row in sweep_throughput's table:\n{text}")


def guarded(name, fn, *args, **kw):
    """Runs one peer; a peer that raises is reported as a row with the reason, not dropped."""
    t0 = time.perf_counter()
    try:
        out = fn(*args, **kw)
        log(f"{name}: {time.perf_counter() - t0:.1f} s")
        return out, None
    except Exception as exc:  # a peer's failure is a result of the comparison
        log(f"{name} FAILED: {exc!r}")
        return None, f"{type(exc).__name__}: {exc}"


def run_squeezes(rust):
    """Every squeeze row: softgrip and rapier (from the Rust side), MuJoCo and Drake."""
    rows = list(rust.get("squeeze", []))
    log("MuJoCo rigid sphere (match, fit, resolved steps)")
    mj_rows, err = guarded("MuJoCo rigid", mujoco_peers.rigid_rows)
    if mj_rows:
        rows += mj_rows[0]
    else:
        rows.append(failed_row("MuJoCo", "rigid sphere, soft contact", err))
    for count in (5, 9):
        log(f"MuJoCo flex sphere, count {count}")
        row, err = guarded(f"MuJoCo flex {count}", mujoco_peers.flex_squeeze, count)
        rows.append(row or failed_row("MuJoCo", f"flex FEM sphere, count {count}^3", err))
    log("Drake hydroelastic and point contact")
    d_rows, err = guarded("Drake squeeze", drake_peers.squeeze_rows)
    rows += d_rows or [failed_row("Drake", "hydroelastic / point", err)]
    for row in rows:
        row["errors"] = errors(row["x"], row["force"]) if row.get("x") else None
    return rows


def failed_row(peer, variant, reason):
    return {"peer": peer, "variant": variant, "dt": None, "steps": 0, "us_per_step": None,
            "x": [], "force": [], "note": f"FAILED: {reason}"}


def run_resting(rust, drake=True):
    """N = 1, 10, 100, 1000 spheres resting: softgrip (its law, `auto`) and rapier (its own
    contacts) from the Rust side at dt = 1/60 s, never asleep and allowed to sleep; MuJoCo
    (its default contact) at its 2 ms step and at the same 1/60 s, never asleep and with its
    sleeping enabled; and Drake (point contact, Hertz-matched stiffness, dt = 1/60 s; it has
    no sleeping) here, unless `drake` is false."""
    names = {("resting", "softgrip"): "softgrip (rapier + plugin), dt = 16.7 ms",
             ("resting", "rapier"): "rapier's own contacts, dt = 16.7 ms",
             ("resting_sleep", "softgrip"): "softgrip, allowed to sleep, dt = 16.7 ms",
             ("resting_sleep", "rapier"): "rapier's own contacts, allowed to sleep, dt = 16.7 ms"}
    table = {}
    for kind in ("resting", "resting_sleep"):
        for rec in rust.get(kind, []):
            median = rec.get("median_us_per_step")
            note = f"median {fmt_us(median)}" if median is not None else ""
            table.setdefault(names[(kind, rec["peer"])], {})[rec["n"]] = {
                "us": rec["us_per_step"], "note": note, "median_us": median}
    mujoco_rows = [("MuJoCo (default contact), dt = 2 ms", 0.002, False),
                   ("MuJoCo (default contact), dt = 16.7 ms", 1 / 60, False),
                   ("MuJoCo (default contact), sleep enabled, dt = 16.7 ms", 1 / 60, True)]
    for n in (1, 10, 100, 1000):
        for name, dt, sleep in mujoco_rows:
            log(f"resting N = {n}: {name}")
            out, err = guarded(f"MuJoCo resting {n}", mujoco_peers.resting, n, dt=dt,
                               sleep=sleep)
            table.setdefault(name, {})[n] = resting_cell(out, err)
        if drake:
            log(f"resting N = {n}: Drake")
            out, err = guarded(f"Drake resting {n}", drake_peers.resting, n)
            table.setdefault("Drake (point contact, SAP), dt = 16.7 ms", {})[n] = \
                resting_cell(out, err)
    return table


def resting_cell(out, err):
    """One cell of the resting table from (µs/step, steps per round, max speed, settle
    steps[, trees awake]), or the failure."""
    if out is None:
        return {"us": None, "note": err}
    us, steps, speed, settled = out[:4]
    note = f"{settled}+3x{steps} steps, max speed {speed:.0e} m/s"
    if len(out) > 4:
        note += f", {out[4]} awake, median {fmt_us(out[5])}"
        return {"us": us, "note": note, "median_us": out[5]}
    return {"us": us, "note": note}


def run_grasp(rust, softgrip_sweep):
    """MuJoCo running the throughput sweep's 64 grasps (squeeze depth x box density), its
    fingertip contact matched to softgrip's law at the default 2 mm; trials per second on this
    one core, whole trials (model compiled from MJCF, program, steps)."""
    sweep = tomllib.loads((ROOT / "sweeps/throughput.toml").read_text())
    axes = {v["field"]: v["values"] for v in sweep["vary"]}
    depths = axes["gripper.squeeze.depth"]
    densities = axes["body[1].shape[0].density"]
    law = rust["grasp_law"][0]
    grip_2mm = float(np.interp(0.002, law["depth"], law["force"]))
    out = {"softgrip (rapier + plugin, dt = 16.7 ms)": dict(
        softgrip_sweep, note=f"sweep_throughput on 1 thread; {softgrip_sweep['errors']} error rows")}
    for dt in (0.002, 1.0 / 60.0):
        name = f"MuJoCo, dt = {dt * 1e3:.3g} ms"
        solref, solimp, grip = mujoco_peers.grasp_match(0.002, grip_2mm, dt)
        held, failed = 0, None
        cpu0 = StepTimer._cpu()
        t0 = time.perf_counter()
        for depth in depths:  # the sweep's trial order: the last axis fastest
            for density in densities:
                try:
                    ok, _, _ = mujoco_peers.grasp_trial(depth, density, dt, solref, solimp)
                    held += ok
                except Exception as exc:  # reported; the sweep goes on
                    failed = f"{type(exc).__name__}: {exc}"
        wall = time.perf_counter() - t0
        n = len(depths) * len(densities)
        # The grip MuJoCo gives the same 2 mm squeeze of the lightest and the heaviest box
        # (its soft contact's force scales with the bodies' masses; softgrip's does not).
        grips = [mujoco_peers.grasp_trial(0.002, rho, dt, solref, solimp, True)[1] or 0.0
                 for rho in (min(densities), max(densities))]
        matched = (f"grip {grip:.3f} N at the end of the settle, matched to softgrip's "
                   f"{grip_2mm:.3f} N at 2 mm" if grip and abs(grip / grip_2mm - 1) < 0.01 else
                   f"NOT matched: the grip at the end of the settle is {grip or 0:.3f} N "
                   f"(softgrip's: {grip_2mm:.3f} N) at every stiffness tried, 1 to 1e9 "
                   f"(at 0 N the box has left the grip: the squeeze pops it out)")
        out[name] = {"trials": n, "wall_s": wall, "trials_per_s": n / wall,
                     "cores_used": f"{(StepTimer._cpu() - cpu0) / wall:.2f}", "held": held,
                     "errors": 1 if failed else 0,
                     "note": f"solref = ({solref[0]:.4g}, {solref[1]:.4g}), default solimp; "
                             + matched
                             + f"; the same 2 mm squeeze grips the {min(densities):g} kg/m^3 box "
                               f"with {grips[0]:.3f} N and the {max(densities):g} kg/m^3 box "
                               f"with {grips[1]:.3f} N"
                             + (f"; a trial failed: {failed}" if failed else "")}
        log(f"{name}: {n} trials in {wall:.1f} s, {held} held")
    return out


def versions():
    """Versions of everything that ran."""
    def cmd(*args):
        try:
            return subprocess.run(args, capture_output=True, text=True, check=True,
                                  cwd=ROOT).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return "unknown"
    lock = (ROOT / "Cargo.lock").read_text()
    rapier = re.search(r'name = "rapier3d"\nversion = "([^"]+)"', lock)
    return {
        "softgrip": cmd("git", "rev-parse", "--short", "HEAD")
                    + (" (+ uncommitted changes)" if cmd("git", "status", "--porcelain") else ""),
        "rapier3d": rapier.group(1) if rapier else "unknown",
        "rustc": cmd("rustc", "--version"),
        "mujoco": version("mujoco"),
        "drake": version("drake"),
        "numpy": version("numpy"),
        "matplotlib": version("matplotlib"),
        "python": platform.python_version(),
    }


def pct(v):
    return "—" if v is None else f"{100 * v:+.1f} %"


def fmt_us(us):
    """A duration given in µs, in µs, ms or s."""
    if us is None:
        return "—"
    if us >= 1e6:
        return f"{us / 1e6:.2f} s"
    return f"{us / 1e3:.2f} ms" if us >= 1000 else f"{us:.1f} µs"


def markdown(rows, resting, grasp, info):
    """The tables of the README."""
    out = []
    m = info["machine"]
    out.append(f"Run {info['date']} in {info['duration_s'] / 60:.1f} min on {m['cpu']}, "
               f"{m['logical_cores']} logical cores ({m['usable_cores']} usable), shared: load average "
               f"{info['load_start']} at the start and {m['loadavg']} at the end; every peer "
               f"single-threaded, `nice -n 10`. Versions: "
               + ", ".join(f"{k} {v}" for k, v in info["versions"].items()) + ".")
    out.append("")
    out.append("### Quasi-static squeeze: R = 10 mm, E = 3 MPa, ν = 0.49, x = δ/R up to 0.6\n")
    out.append(f"Error = F/F_FE − 1 against `{FE_FILE.relative_to(ROOT)}` (CalculiX, scaled by μR²); "
               f"max and mean of |error| on x = {ERR_RANGE[0]}, {ERR_RANGE[0] + 0.01:.2f}, … "
               f"{ERR_RANGE[1]} (or as far as the peer got: column `x range`).\n")
    head = ("| peer | variant | dt | time/step | time per simulated s | max err | mean err | "
            + " | ".join(f"x = {x}" for x in ERR_AT) + " | x range |")
    out.append(head)
    out.append("|---|---|---:|---:|---:|---:|---:|" + "---:|" * len(ERR_AT) + "---|")
    for r in rows:
        e = r.get("errors")
        dt = "—" if r.get("dt") is None else f"{r['dt'] * 1e3:.3g} ms"
        if e is None:
            out.append(f"| {r['peer']} | {r['variant']} | {dt} | {fmt_us(r.get('us_per_step'))} | | "
                       f"no data: {r['note']} |" + " |" * (len(ERR_AT) + 2))
            continue
        per_s = fmt_us(r["us_per_step"] / r["dt"]) if r.get("dt") else "—"
        out.append(f"| {r['peer']} | {r['variant']} | {dt} | {fmt_us(r['us_per_step'])} | "
                   f"{per_s} | {100 * e['max']:.1f} % | {100 * e['mean']:.1f} % | "
                   + " | ".join(pct(e["at"][x]) for x in ERR_AT)
                   + f" | {e['x_from']:.2f}–{e['x_to']:.2f} |")
    out.append("")
    out.extend(resting_markdown(resting))
    out.append("### Whole grasp trials per second on one core: `sweeps/throughput.toml` (the default grasp, 8 squeeze depths × 8 box densities)\n")
    out.append("| engine | trials | held | wall | trials/s | cores used (CPU/wall) "
               "| trials per CPU-second | note |")
    out.append("|---|---:|---:|---:|---:|---:|---:|---|")
    for eng, g in grasp.items():
        try:
            per_cpu = f"{g['trials_per_s'] / float(g['cores_used']):.1f}"
        except (ValueError, ZeroDivisionError):
            per_cpu = "—"
        out.append(f"| {eng} | {g['trials']} | {g['held']} | {g['wall_s']:.2f} s | "
                   f"{g['trials_per_s']:.1f} | {g['cores_used']} | {per_cpu} | "
                   f"{g.get('note', '')} |")
    out.append("")
    out.append("On a shared machine a single-threaded run gets less than a core: trials per "
               "CPU-second (trials/s over the cores used) is the per-core rate.")
    out.append("")
    out.append("Notes per squeeze row (how each peer was set up and matched):\n")
    for r in rows:
        out.append(f"- **{r['peer']}, {r['variant']}**: {r['note']}")
    return "\n".join(out) + "\n"


# The curves drawn in the left panel (the right one has every row): one or a few per peer,
# so that the lines stay readable.
CURVES = (
    ("softgrip", "calibrated"), ("softgrip", "fit"), ("softgrip", "hertz"),
    ("rapier", "rigid ball, contact softness, velocity cap lifted"),
    ("rapier", "FEM ball (R = 1 (x100), 1e4 x dynamically real mass)"),
    ("MuJoCo", "rigid sphere, soft contact matched to Hertz at x = 0.05"),
    ("MuJoCo", "rigid sphere, soft contact fitted to FE (least squares)"),
    ("MuJoCo", "flex FEM sphere, 192 tets"), ("MuJoCo", "flex FEM sphere, 768 tets"),
    ("Drake", "hydroelastic, E_h matched (Drake's estimate), hint R/4"),
    ("Drake", "hydroelastic, E_h = E, hint R/4"),
    ("Drake", "point contact matched to Hertz at x = 0.05"),
)


def plot(rows, path):
    """Left: F/F_FE against x for the rows of CURVES; right: time per step against the max
    error (log-log), one point per row."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(16, 8.5))
    colors = {"softgrip": "tab:green", "rapier": "tab:orange", "MuJoCo": "tab:blue",
              "Drake": "tab:red"}
    markers = "os^vD<>phH*P"
    styles = ["-", "--", ":", "-."]
    counts, lines = {}, {}
    for r in rows:
        e = r.get("errors")
        if not e:
            continue
        i = counts.get(r["peer"], 0)
        counts[r["peer"]] = i + 1
        label = f"{r['peer']}: {r['variant']} (dt {r['dt'] * 1e3:.3g} ms)"
        color = colors.get(r["peer"], "k")
        ax2.loglog(max(e["max"], 1e-4) * 100, r["us_per_step"], markers[i % len(markers)],
                   color=color, ms=7, label=label)
        if (r["peer"], r["variant"]) in CURVES:
            j = lines.get(r["peer"], 0)
            lines[r["peer"]] = j + 1
            xs, fs = np.array(r["x"]), np.array(r["force"])
            keep = (xs >= 0.02) & (xs <= FE_X[-1])
            order = np.argsort(xs[keep])
            xk, fk = xs[keep][order], fs[keep][order]
            ax1.plot(xk, fk / fe_force(xk), color=color, lw=1.2, ls=styles[j % 4],
                     label=f"{r['peer']}: {r['variant']}")
    ax1.axhline(1.0, color="k", lw=0.8)
    ax1.set_xlim(0.0, 0.62)
    ax1.set_ylim(0.0, 1.8)
    ax1.set_xlabel("x = δ/R")
    ax1.set_ylabel("F / F_FE")
    ax1.set_title("Squeeze force against FE (R = 10 mm, E = 3 MPa, ν = 0.49)")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2)
    ax2.set_xlabel(f"max |F/F_FE − 1| over x in [{ERR_RANGE[0]}, {ERR_RANGE[1]}] [%]")
    ax2.set_ylabel("wall time per step [µs], one core")
    ax2.set_title("Speed vs error (each peer at its own dt)")
    ax2.grid(alpha=0.3, which="both")
    ax2.legend(fontsize=6.5, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, dpi=100, bbox_inches="tight")


def resting_markdown(resting):
    """The resting table's lines (heading, table, blank line)."""
    out = ["### N spheres resting on a plane (R = 10 mm, 4.48 g, 30 mm grid), time per step: best of 3 rounds after settling (note: settle + rounds x steps)\n",
           "| engine | N = 1 | N = 10 | N = 100 | N = 1000 | note |",
           "|---|---:|---:|---:|---:|---|"]
    for eng, per in resting.items():
        notes = "; ".join(f"{n}: {v['note']}" for n, v in sorted(per.items()) if v["note"])
        out.append(f"| {eng} | " + " | ".join(fmt_us(per.get(n, {}).get("us")) for n in (1, 10, 100, 1000))
                   + f" | {notes} |")
    out.append("")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rust", required=True, help="JSON lines of peers_softgrip")
    ap.add_argument("--sweep", help="sweep_throughput's output (1 thread); required unless "
                    "--resting-only")
    ap.add_argument("--resting-only", action="store_true",
                    help="run only the resting scenes (MuJoCo; Drake is skipped) and print "
                    "their table; nothing is written")
    ap.add_argument("--out", default=str(ROOT / "tools/peers"), help="output directory")
    ap.add_argument("--load-start", default=" ".join(f"{v:.2f}" for v in os.getloadavg()))
    ap.add_argument("--started", type=float, default=time.time(),
                    help="Unix time the harness started (for its duration)")
    args = ap.parse_args()
    out = Path(args.out)
    rust = read_rust(args.rust)
    if args.resting_only:
        print("\n".join(resting_markdown(run_resting(rust, drake=False))))
        return
    if args.sweep is None:
        ap.error("--sweep is required unless --resting-only")
    rows = run_squeezes(rust)
    resting = run_resting(rust)
    grasp = run_grasp(rust, read_sweep(args.sweep))
    info = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime(args.started)),
            "duration_s": time.time() - args.started, "load_start": args.load_start,
            "machine": machine(), "versions": versions()}
    text = markdown(rows, resting, grasp, info)
    (out / "results.md").write_text(text)
    # The raw samples are thinned to the force at x = 0.02, 0.025, ... (as far as each peer got).
    grid = np.round(np.arange(0.02, 0.6001, 0.005), 10)
    slim = []
    for r in rows:
        s = {k: v for k, v in r.items() if k not in ("x", "force")}
        xs, fs = np.array(r["x"]), np.array(r["force"])
        if xs.size > 1:
            o = np.argsort(xs)
            g = grid[(grid >= xs.min()) & (grid <= xs.max())]
            s["curve_x"] = [float(v) for v in g]
            s["curve_force"] = [float(v) for v in np.interp(g, xs[o], fs[o])]
        slim.append(s)
    (out / "results.json").write_text(json.dumps(
        {"info": info, "squeeze": slim, "resting": resting, "grasp": grasp}, indent=1))
    plot(rows, out / "peers.png")
    print(text)


if __name__ == "__main__":
    main()
