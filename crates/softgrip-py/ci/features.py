"""Lists the packages whose features differ between a build of softgrip-py alone (what maturin
runs) and the workspace's build (what `cargo test --workspace` leaves in target/debug): each one
is compiled twice, and with it everything that depends on it. Exit 1 if any differ. Run from
anywhere: python3 crates/softgrip-py/ci/features.py"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def features(*args: str) -> dict:
    out = subprocess.run(
        ["cargo", "tree", "--locked", "--prefix", "none", "-f", "{p}|{f}", *args],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    found: dict = {}
    for line in out.splitlines():
        if "|" not in line:
            continue
        package, feats = line.split("|", 1)
        package = package.replace(" (*)", "").strip()
        found.setdefault(package, set()).update(f for f in feats.replace(" (*)", "").split(",") if f)
    return found


def main() -> int:
    alone = features("-p", "softgrip-py", "-e", "normal,build")
    workspace = features("--workspace", "-e", "normal,build,dev")
    differ = {p: (alone[p], workspace[p]) for p in alone if p in workspace and alone[p] != workspace[p]}
    for p, (a, w) in sorted(differ.items()):
        print(f"features differ: {p}: softgrip-py alone {sorted(a)}, workspace {sorted(w)}")
    if not differ:
        print("softgrip-py alone and the workspace build its dependencies with the same features")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
