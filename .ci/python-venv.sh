#!/usr/bin/env bash
# Creates target/pyvenv with the MCAP readers softgrip's tests check recordings against
# (mcap + mcap-ros2-support from PyPI, pinned) and the DDS participant the ROS 2 tests talk to
# (cyclonedds: its wheel bundles the Cyclone DDS C library, no ROS 2 or system package needed),
# and prints the Python to export as SOFTGRIP_PY.
# Idempotent: reuses the venv when the pinned versions are already installed.
set -euo pipefail
cd "$(dirname "$0")/.."

VENV=target/pyvenv
PINS=(mcap==1.6.0 mcap-ros2-support==0.6.0 zstandard==0.25.0 lz4==4.4.5 cyclonedds==11.0.1)

if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV" >&2
fi
FROZEN=$("$VENV/bin/python" -m pip freeze 2>/dev/null || true)
MISSING=0
for pin in "${PINS[@]}"; do
  grep -qxi "$pin" <<<"$FROZEN" || MISSING=1
done
if [ "$MISSING" = 1 ]; then
  "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check "${PINS[@]}" >&2
fi
"$VENV/bin/python" -c "import mcap, mcap_ros2.reader, cyclonedds.domain, cyclonedds.idl" >&2
echo "$PWD/$VENV/bin/python"
