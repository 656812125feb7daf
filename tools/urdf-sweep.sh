#!/usr/bin/env bash
# Survey: every URDF under a folder (default: the pybullet_data of .ci/pybullet-data.sh, or
# $SOFTGRIP_PYBULLET_DATA) loaded through softgrip's scene loader and run (50 steps, or
# $SWEEP_STEPS) in both joint models (examples/urdf_sweep.rs). Prints a count per outcome and
# writes target/urdf-sweep/<model>.tsv (file, outcome, links, joints, colliders, detail).
# Each URDF runs in its own process under a 60 s timeout (a hang shows as `timeout`).
# Not a CI test: the whole pybullet_data needs the full 103 MB wheel
# (pip download pybullet==3.2.7 and unzip pybullet_data/, as .ci/pybullet-data.sh does).
set -euo pipefail
cd "$(dirname "$0")/.."
DIR=${1:-${SOFTGRIP_PYBULLET_DATA:-target/pybullet/pybullet_data}}
cargo build -q -p softgrip-scene --example urdf_sweep
OUT=target/urdf-sweep
mkdir -p "$OUT"
for model in multibody impulse; do
  find "$DIR" -name '*.urdf' | sort | while read -r f; do
    timeout 60 target/debug/examples/urdf_sweep "$model" "$f" 2>/dev/null \
      || printf '%s\ttimeout-or-crash(%s)\n' "$f" "$?"
  done > "$OUT/$model.tsv"
  echo "$model:"; cut -f2 "$OUT/$model.tsv" | sort | uniq -c
done
