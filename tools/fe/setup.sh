#!/usr/bin/env bash
# Installs what softgrip's FE pipeline needs on a fresh Debian machine and prints the venv's python.
#  - CalculiX `ccx` (Debian package calculix-ccx, 2.20 on Debian 13) if `ccx` is missing;
#  - the shared libraries the PyPI gmsh wheel links against (libGLU, libXcursor, libXft,
#    libXinerama, libGL, fontconfig, libgomp: found with `ldd libgmsh.so`), if any is missing;
#  - a venv at ${SOFTGRIP_FE_VENV:-target/fe-venv} with pinned gmsh, numpy, scipy.
# Idempotent: does nothing that is already done. Progress goes to stderr; stdout is the python.
set -euo pipefail
cd "$(dirname "$0")/../.."

VENV="${SOFTGRIP_FE_VENV:-target/fe-venv}"
PINS=(gmsh==4.15.2 numpy==2.4.6 scipy==1.17.1)
DEBS=(libglu1-mesa libxcursor1 libxft2 libxinerama1 libgl1 libfontconfig1 libxrender1 libgomp1)

need=()
command -v ccx >/dev/null 2>&1 || need+=(calculix-ccx)
for d in "${DEBS[@]}"; do
  dpkg-query -W -f='${Status}' "$d" 2>/dev/null | grep -q "install ok installed" || need+=("$d")
done
python3 -m venv --help >/dev/null 2>&1 || need+=(python3-venv)
if [ ${#need[@]} -gt 0 ]; then
  echo "setup.sh: apt-get install ${need[*]}" >&2
  apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >&2
fi

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
"$VENV/bin/python" -c "import gmsh, numpy, scipy; gmsh.initialize(); gmsh.finalize()" >&2
command -v ccx >/dev/null
echo "$(cd "$(dirname "$VENV")" && pwd)/$(basename "$VENV")/bin/python"
