"""Shared pieces of the peers' harness: the squeeze's parameters, the FE reference, the error
measures, a step timer and the machine's description.

Units are SI throughout (m, N, Pa, s). The compression of a squeeze is `x = delta / R`, with
`delta` one plate's approach (the FE reference's definition: a sphere between two plates, each
advancing delta, or equally a hemisphere pressed by delta onto a rigid plane).
"""

import csv
import os
import platform
import resource
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]

# The squeeze of issue 13: a silicone fingertip.
RADIUS = 0.010  # m
YOUNGS = 3.0e6  # Pa
POISSON = 0.49
SHEAR = YOUNGS / (2.0 * (1.0 + POISSON))  # mu [Pa]
E_STAR = YOUNGS / (1.0 - POISSON**2)  # effective modulus against a rigid plane [Pa]
DENSITY = 1070.0  # kg/m^3, as softgrip's test scenes
MASS = DENSITY * 4.0 / 3.0 * np.pi * RADIUS**3  # kg

X_END = 0.61  # the squeezes run to this x (just past 0.6, so that 0.6 is inside every run)
ERR_RANGE = (0.05, 0.6)  # x range of the max and mean errors
ERR_AT = (0.1, 0.3, 0.5)  # x where the error is reported on its own
X_MATCH = 0.05  # x where the "matched" peers equal Hertz

FE_FILE = ROOT / "tests/data/fe/force_nu0.49.csv"
# The FE file is for R = 1 mm and mu = 1 MPa. At a fixed x the force scales as mu R^2 (the
# neo-Hookean problem has no other length or stress scale), so F(R, mu) = F_file * scale.
FE_SCALE = (SHEAR / 1.0e6) * (RADIUS / 1.0e-3) ** 2


def hertz_force(x):
    """Hertz's force [N] of the sphere on a rigid plane at compression ratio x."""
    delta = np.asarray(x) * RADIUS
    return 4.0 / 3.0 * E_STAR * np.sqrt(RADIUS) * delta**1.5


def load_fe():
    """(x, F [N]) of the FE reference, scaled to this squeeze (R = 10 mm, E = 3 MPa)."""
    xs, fs = [], []
    with open(FE_FILE, newline="") as fh:
        for row in csv.DictReader(fh):
            xs.append(float(row["delta_over_R"]))
            fs.append(float(row["force_N"]) * FE_SCALE)
    return np.array(xs), np.array(fs)


FE_X, FE_F = load_fe()


def fe_force(x):
    """The FE force [N] at x: linear interpolation of F / x^1.5 (smooth, as in
    softgrip-bench's `fe_at`); NaN outside the data."""
    x = np.asarray(x, dtype=float)
    g = np.interp(x, FE_X, FE_F / FE_X**1.5, left=np.nan, right=np.nan)
    return g * x**1.5


def errors(xs, fs):
    """Force error of a squeeze's samples against FE.

    The samples are resampled (linear interpolation, sorted by x) on x = 0.05, 0.06, ... 0.60,
    limited to the x the peer reached, so that a peer sampled densely at small x is not
    favoured. Returns a dict: max and mean |F/F_FE - 1| over that grid, the signed error at
    each x of ERR_AT (None where not reached) and the x range actually covered.
    """
    xs = np.asarray(xs, dtype=float)
    fs = np.asarray(fs, dtype=float)
    ok = np.isfinite(xs) & np.isfinite(fs)
    xs, fs = xs[ok], fs[ok]
    if xs.size < 2:
        return None
    order = np.argsort(xs)
    xs, fs = xs[order], fs[order]
    grid = np.round(np.arange(ERR_RANGE[0], ERR_RANGE[1] + 1e-9, 0.01), 10)
    grid = grid[(grid >= xs[0]) & (grid <= xs[-1])]
    if grid.size == 0:
        return None
    rel = np.interp(grid, xs, fs) / fe_force(grid) - 1.0
    at = {}
    for x in ERR_AT:
        if xs[0] <= x <= xs[-1]:
            at[x] = float(np.interp(x, xs, fs) / fe_force(x) - 1.0)
        else:
            at[x] = None
    return {
        "max": float(np.max(np.abs(rel))),
        "mean": float(np.mean(np.abs(rel))),
        "at": at,
        "x_from": float(grid[0]),
        "x_to": float(grid[-1]),
    }


class StepTimer:
    """Wall time of the timed calls (time.perf_counter) and the process's CPU time over them,
    so that a table can show that a run used one core."""

    def __init__(self):
        self.wall = 0.0
        self.steps = 0
        self.samples = []
        self._cpu0 = self._cpu()

    @staticmethod
    def _cpu():
        r = resource.getrusage(resource.RUSAGE_SELF)
        return r.ru_utime + r.ru_stime

    def time(self, fn, *args):
        """Calls fn(*args) and adds its wall time as one step."""
        t0 = time.perf_counter()
        out = fn(*args)
        dt = time.perf_counter() - t0
        self.wall += dt
        self.steps += 1
        self.samples.append(dt)
        return out

    def us_per_step(self):
        return 1e6 * self.wall / max(self.steps, 1)

    def median_us(self):
        """The median wall time of one timed call [µs]: on a loaded machine a round's mean
        carries every preemption that fell in it, the median of single calls does not."""
        return 1e6 * float(np.median(self.samples)) if self.samples else float("nan")


def machine():
    """CPU model, logical cores, cores this process may use, load average now, kernel."""
    model = platform.processor() or "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "cpu": model,
        "logical_cores": os.cpu_count(),
        "usable_cores": len(os.sched_getaffinity(0)),
        "loadavg": " ".join(f"{v:.2f}" for v in os.getloadavg()),
        "kernel": platform.release(),
        "python": platform.python_version(),
    }
