"""A 1,000-trial grasp sweep as Ray tasks (one task per trial, each calling the softgrip
extension), on a local Ray cluster by default or on a running cluster with --address.

    python crates/softgrip-py/examples/ray_sweep.py                   # local Ray, 2 CPUs
    python crates/softgrip-py/examples/ray_sweep.py --compare-local   # and check against local
    python ray_sweep.py --address auto                                # on a cluster's head node

On a multi-node cluster the softgrip wheel must be installed on every node (or given as
``runtime_env={"pip": [...]}``), and the sweep file, its scene and the scene's meshes must be at
the same absolute path on every node (a shared filesystem), or shipped with
``ray_options={"runtime_env": {"working_dir": "."}}`` and relative paths: see
crates/softgrip-py/README.md, "Ray on a cluster".
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import ray

import softgrip

HERE = Path(__file__).resolve().parent


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--sweep", default=str(HERE / "ray_sweep.toml"), help="the sweep file")
    p.add_argument("--address", default=None, help="a running Ray cluster (e.g. auto); default: start a local one")
    p.add_argument("--num-cpus", type=int, default=2, help="CPUs of the local Ray (without --address)")
    p.add_argument("--out", default=None, help="write the results (.parquet or .csv)")
    p.add_argument("--compare-local", action="store_true", help="also run locally and compare row for row")
    args = p.parse_args()

    if args.address:
        ray.init(address=args.address)
    else:
        # A local cluster on loopback only, no dashboard.
        ray.init(num_cpus=args.num_cpus, include_dashboard=False, _node_ip_address="127.0.0.1")
    cpus = int(ray.cluster_resources().get("CPU", 0))
    trials = softgrip.Sweep.open(args.sweep).trials
    print(f"{trials} trials of {args.sweep} on Ray ({cpus} CPUs)")

    start = time.perf_counter()
    rows = softgrip.sweep(args.sweep, backend="ray", table="rows", out=args.out)
    wall = time.perf_counter() - start
    columns = softgrip.Sweep.open(args.sweep).columns()
    held = sum(1 for r in rows if r[columns.index("held")])
    errors = sum(1 for r in rows if r[-1] is not None)
    print(f"ray: {len(rows)} trials in {wall:.2f} s ({len(rows) / wall:.1f} trials/s), {held} held, {errors} errors")

    if args.compare_local:
        start = time.perf_counter()
        local = softgrip.sweep(args.sweep, table="rows", threads=max(cpus, 1))
        wall_local = time.perf_counter() - start
        w = columns.index("wall_time")
        same = all(
            a[:w] + a[w + 1 :] == b[:w] + b[w + 1 :] for a, b in zip(rows, local)
        ) and len(rows) == len(local)
        print(f"local: {len(local)} trials in {wall_local:.2f} s ({len(local) / wall_local:.1f} trials/s); "
              f"ray == local row for row (all columns but wall_time): {same}")
        if not same:
            raise SystemExit("the Ray run differs from the local run")
    ray.shutdown()


if __name__ == "__main__":
    main()
