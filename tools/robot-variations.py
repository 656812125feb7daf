#!/usr/bin/env python3
"""The shipped robot scenes (scenes/robots/*.toml) with their object's density scaled and their
grasp force varied, each run in both joint models by the `impulse_grasp` example: one row per
(scene, density factor, joint model, force) with the pads' peak and hold forces [N], the hold's
slip [um] and the time per step [ms] (softgrip-rapier README, Limits, "Stale rigid contacts").

    cargo build --release -p softgrip-scene --example impulse_grasp
    python3 tools/robot-variations.py [--density 0.2 1 5 20] [--out target/robot-variations]
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--density", type=float, nargs="+", default=[0.2, 1.0, 5.0, 20.0],
                    help="factors on each scene's first `density`")
    ap.add_argument("--forces-gripper", type=float, nargs="+", default=[1.0, 5.0, 20.0])
    ap.add_argument("--forces-hand", type=float, nargs="+", default=[0.5, 2.0, 5.0, 10.0])
    ap.add_argument("--out", default=os.path.join(ROOT, "target", "robot-variations"))
    ap.add_argument("--bin", default=os.path.join(ROOT, "target", "release", "examples", "impulse_grasp"))
    a = ap.parse_args()
    if not os.path.exists(a.bin):
        sys.exit(f"{a.bin} is missing: cargo build --release -p softgrip-scene --example impulse_grasp")
    os.makedirs(a.out, exist_ok=True)
    scenes = os.path.join(ROOT, "scenes", "robots")
    for name in sorted(f for f in os.listdir(scenes) if f.endswith(".toml")):
        text = open(os.path.join(scenes, name)).read()
        text = text.replace('"../../robots/', '"' + os.path.join(ROOT, "robots") + "/")
        forces = a.forces_hand if "three_finger" in name else a.forces_gripper
        for k in a.density:
            scaled, n = re.subn(r"density = ([0-9.eE+-]+)",
                                lambda m: f"density = {float(m.group(1)) * k}", text, count=1)
            if n != 1:
                sys.exit(f"{name}: no `density` to scale")
            path = os.path.join(a.out, f"{name[:-5]}_d{k}.toml")
            open(path, "w").write(scaled)
            r = subprocess.run([a.bin, path] + [str(f) for f in forces], capture_output=True, text=True)
            print(f"{os.path.basename(path)} (exit {r.returncode})")
            print("\n".join(r.stdout.splitlines()[2:]))
            if r.returncode:
                print(r.stderr[-2000:])
            sys.stdout.flush()


if __name__ == "__main__":
    main()
