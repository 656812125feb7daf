#!/usr/bin/env bash
# Fetches the Franka Panda model of PyPI's `pybullet` (pybullet_data/franka_panda: panda.urdf, its
# OBJ meshes and LICENSE.txt; Apache-2.0, never committed) into target/pybullet and prints the
# pybullet_data folder to export as SOFTGRIP_PYBULLET_DATA (crates/softgrip-scene/tests/panda.rs).
# Only the wheel is downloaded (pip, no install, no build: the x86-64 CPython 3.11 manylinux wheel
# whatever the local Python, 103 MB, ~5 s here) and only franka_panda/ is unzipped from it (1.2
# MB of collision meshes, 9.4 MB with the visual ones; the wheel is then deleted). 4.8 s from
# nothing here. Idempotent: reuses what is there.
set -euo pipefail
cd "$(dirname "$0")/.."

VERSION=3.2.7
OUT=target/pybullet
URDF="$OUT/pybullet_data/franka_panda/panda.urdf"
if [ ! -f "$URDF" ]; then
  DL=target/pybullet-dl
  mkdir -p "$DL" "$OUT"
  if ! ls "$DL"/pybullet-"$VERSION"-*.whl >/dev/null 2>&1; then
    python3 -m pip download --quiet --disable-pip-version-check --no-deps --only-binary=:all: \
      --python-version 3.11 --platform manylinux2014_x86_64 --implementation cp \
      -d "$DL" "pybullet==$VERSION" >&2
  fi
  python3 - "$DL" "$OUT" <<'PY'
import glob, sys, zipfile
wheel = sorted(glob.glob(f"{sys.argv[1]}/pybullet-*.whl"))[-1]
with zipfile.ZipFile(wheel) as z:
    for name in z.namelist():
        if name.startswith("pybullet_data/franka_panda/"):
            z.extract(name, sys.argv[2])
PY
  rm -rf "$DL"   # the 103 MB wheel is not needed once franka_panda/ is out
fi
test -f "$URDF"
echo "$PWD/$OUT/pybullet_data"
