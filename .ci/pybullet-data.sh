#!/usr/bin/env bash
# Fetches the Franka Panda model of PyPI's `pybullet` (pybullet_data/franka_panda: panda.urdf, its
# OBJ meshes and LICENSE.txt; Apache-2.0, never committed) and its UFactory xArm 6 with gripper
# (pybullet_data/xarm: xarm6_with_gripper.urdf and its STL/OBJ meshes, 5.1 MB) into
# target/pybullet and prints the pybullet_data folder to export as SOFTGRIP_PYBULLET_DATA
# (crates/softgrip-scene/tests/panda.rs, xarm.rs).
# Only the wheel is downloaded (pip, no install, no build: the x86-64 CPython 3.11 manylinux wheel
# whatever the local Python, 103 MB, ~5 s here) and only franka_panda/ and xarm/ are unzipped (1.2
# MB of Panda collision meshes, 9.4 MB with the visual ones, and 5.1 MB of xArm; the wheel is then deleted). 4.8 s from
# nothing here. Idempotent: reuses what is there.
set -euo pipefail
cd "$(dirname "$0")/.."

VERSION=3.2.7
OUT=target/pybullet
URDF="$OUT/pybullet_data/franka_panda/panda.urdf"
XARM="$OUT/pybullet_data/xarm/xarm6_with_gripper.urdf"
if [ ! -f "$URDF" ] || [ ! -f "$XARM" ]; then
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
        if name.startswith(("pybullet_data/franka_panda/", "pybullet_data/xarm/")):
            z.extract(name, sys.argv[2])
PY
  rm -rf "$DL"   # the 103 MB wheel is not needed once franka_panda/ and xarm/ are out
fi
test -f "$URDF" && test -f "$XARM"
echo "$PWD/$OUT/pybullet_data"
