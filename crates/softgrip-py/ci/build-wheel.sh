#!/usr/bin/env bash
# Builds the softgrip wheel a user installs in seconds: abi3 (one wheel for CPython >= 3.9),
# manylinux_2_17 (glibc 2.17: RHEL 7/8, Ubuntu 18.04 on), license files and the example scenes
# and sweeps inside, stripped. Prints its path on the last line.
#
#   bash crates/softgrip-py/ci/build-wheel.sh             # the dev profile (CI's: it reuses the
#                                                          # workspace's target/debug)
#   PROFILE=release bash crates/softgrip-py/ci/build-wheel.sh   # a release build (target/release)
#
# Needs a Python with maturin and ziglang (PYTHON, default: the venv ci/test.sh makes,
# target/py-wheel-venv, else python3). zig (from PyPI's ziglang) is the linker of the
# extension alone (`-C linker=ci/zigcc.sh` after `--`, so no other crate is rebuilt and
# cargo's artifacts stay in target/<profile>): it links against glibc 2.17's symbol
# versions. maturin checks them against manylinux2014 (and fails the build otherwise).
set -euo pipefail
cd "$(dirname "$0")/../../.."

PROFILE=${PROFILE:-dev}
OUT=${OUT:-target/py-wheels}
if [ -z "${PYTHON:-}" ]; then
  if [ -x target/py-wheel-venv/bin/python ]; then PYTHON=target/py-wheel-venv/bin/python; else PYTHON=python3; fi
fi
BIN=$(cd "$(dirname "$PYTHON")" && pwd)
# maturin, and `python -m ziglang` for the linker, from the same environment.
export PATH="$BIN:$PATH"
"$PYTHON" -m ziglang version >/dev/null
rm -rf "$OUT"
"$PYTHON" -m maturin build --profile "$PROFILE" --locked --compatibility manylinux2014 \
  -m crates/softgrip-py/Cargo.toml --out "$OUT" \
  -- -C "linker=$PWD/crates/softgrip-py/ci/zigcc.sh" >&2
ls "$OUT"/softgrip-*.whl
