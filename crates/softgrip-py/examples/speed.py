"""Prints what the installed softgrip wheel costs at run time (best of 5): the law over 10^6
compressions, the default scene's 300 steps, the default_grid sweep's 36 trials on one
thread. Run it in two venvs to compare two wheels (the dev-profile wheel CI builds against a
`PROFILE=release bash crates/softgrip-py/ci/build-wheel.sh` one):

    python crates/softgrip-py/examples/speed.py [LABEL]
"""

from __future__ import annotations

import sys
import time

import numpy as np

import softgrip


def main() -> None:
    label = sys.argv[1] if len(sys.argv) > 1 else softgrip.__file__
    tip = softgrip.law("calibrated", 3e6, 0.49, 0.01)
    delta = np.random.default_rng(1).uniform(0.0, 0.006, 1_000_000)
    law, run = float("inf"), float("inf")
    for _ in range(5):
        start = time.perf_counter()
        tip.force(delta)
        law = min(law, time.perf_counter() - start)
        run = min(run, softgrip.run(softgrip.scenes.path("default")).wall_time)
    start = time.perf_counter()
    softgrip.sweep(softgrip.sweeps.path("default_grid"), threads=1, table="rows")
    sweep = time.perf_counter() - start
    print(
        f"{label}: law 1e6 evaluations {law * 1e3:.1f} ms; default scene 300 steps "
        f"{run * 1e3:.1f} ms; default_grid 36 trials on 1 thread {sweep:.2f} s"
    )


if __name__ == "__main__":
    main()
