#!/usr/bin/env bash
# Creates the peers' venv (MuJoCo, Drake, numpy, matplotlib at the pinned versions of
# requirements.txt) and prints the path of its python. Not part of CI's test run.
#   bash tools/peers/setup.sh            # venv at target/peers-venv
#   SOFTGRIP_PEERS_VENV=/some/dir bash tools/peers/setup.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
venv="${SOFTGRIP_PEERS_VENV:-$root/target/peers-venv}"
py="${PYTHON:-python3.11}"
command -v "$py" >/dev/null || py=python3
if [ ! -x "$venv/bin/python" ]; then
    "$py" -m venv "$venv" >&2
fi
"$venv/bin/python" -m pip install --quiet --upgrade pip >&2
"$venv/bin/python" -m pip install --quiet -r "$here/requirements.txt" >&2
echo "$venv/bin/python"
