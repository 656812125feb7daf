#!/usr/bin/env bash
# softgrip against its peers, in one command (from the repository root or anywhere):
#   bash tools/peers/run.sh
# 1. sets up the peers' venv if needed (tools/peers/setup.sh: pinned MuJoCo and Drake),
# 2. builds the Rust side in release (crates/softgrip-bench/examples/peers_softgrip.rs and
#    crates/softgrip-sweep/examples/sweep_throughput.rs),
# 3. runs the softgrip/rapier squeezes and resting scenes, softgrip's grasp sweep on 1 thread,
#    then MuJoCo and Drake (tools/peers/peers.py), everything single-threaded and niced,
# 4. prints the tables and writes tools/peers/results.md, results.json and peers.png.
# Not part of CI's test run. Bounded: about 10-20 minutes on a shared 2-core machine.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cd "$root"
started="$(date +%s)"
load_start="$(cut -d' ' -f1-3 /proc/loadavg)"
echo "peers: started $(date -u '+%Y-%m-%d %H:%M:%S UTC'), load average $load_start" >&2

# One thread everywhere: BLAS/OpenMP pools (numpy, Drake), rayon (the sweep), no pinning.
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1 RAYON_NUM_THREADS=1
export DRAKE_NUM_THREADS=1

py="$(bash "$here/setup.sh")"
nice -n 10 cargo build --release --quiet -p softgrip-bench --example peers_softgrip \
    -p softgrip-sweep --example sweep_throughput
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
echo "peers: softgrip and rapier (peers_softgrip)" >&2
nice -n 10 target/release/examples/peers_softgrip > "$tmp/rust.jsonl"
echo "peers: softgrip's grasp sweep on 1 thread (sweep_throughput)" >&2
nice -n 10 target/release/examples/sweep_throughput sweeps/throughput.toml 1 > "$tmp/sweep.txt"
cat "$tmp/sweep.txt" >&2
echo "peers: MuJoCo and Drake (peers.py)" >&2
# From the scratch directory: MuJoCo writes its warnings to MUJOCO_LOG.TXT in the cwd.
cd "$tmp"
nice -n 10 "$py" "$here/peers.py" --rust "$tmp/rust.jsonl" --sweep "$tmp/sweep.txt" \
    --out "$here" --load-start "$load_start" --started "$started"
if [ -f MUJOCO_LOG.TXT ]; then
    echo "peers: MuJoCo logged $(grep -c WARNING MUJOCO_LOG.TXT) warnings; the distinct ones:" >&2
    grep WARNING MUJOCO_LOG.TXT | sed 's/Time = .*//; s/DOF [0-9]*/DOF N/' | sort | uniq -c >&2
fi
