#!/usr/bin/env bash
# The Python package's CI step (called by .ci/test after the workspace's tests, which leave
# target/debug/softgrip for the comparisons): builds the abi3 wheel with the dev profile (so it
# shares the workspace's debug artifacts in target/debug), installs it into the pinned venv
# target/py-wheel-venv (created from python3 -m venv and requirements-test.txt, idempotent) and
# runs pytest on crates/softgrip-py/tests. Prints the time of each part.
set -euo pipefail
cd "$(dirname "$0")/../../.."

VENV=target/py-wheel-venv
REQ=crates/softgrip-py/requirements-test.txt
WHEELS=target/py-wheels
t0=$(date +%s)

if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
fi
FROZEN=$("$VENV/bin/python" -m pip freeze 2>/dev/null || true)
MISSING=0
while read -r pin; do
  case "$pin" in ''|'#'*) continue ;; esac
  grep -qxi "$pin" <<<"$FROZEN" || MISSING=1
done <"$REQ"
if [ "$MISSING" = 1 ]; then
  "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check -r "$REQ"
fi
t1=$(date +%s)
echo "python venv $VENV: $((t1 - t0)) s"

# The wheel's build (softgrip-py alone) must see the workspace's features, or it recompiles
# most of the workspace (see the workspace hack in Cargo.toml).
python3 crates/softgrip-py/ci/features.py

# `pip wheel` runs maturin's PEP 517 backend (the venv's pinned maturin: no build isolation);
# MATURIN_PEP517_ARGS picks the dev profile, whose dependencies the workspace build compiled.
# Without build isolation maturin is found on PATH: the venv's.
export PATH="$PWD/$VENV/bin:$PATH"
rm -rf "$WHEELS"
MATURIN_PEP517_ARGS="--profile dev --locked" "$VENV/bin/python" -m pip wheel --quiet \
  --disable-pip-version-check --no-build-isolation --no-deps -w "$WHEELS" crates/softgrip-py
WHEEL=$(ls "$WHEELS"/softgrip-*.whl)
"$VENV/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps "$WHEEL"
t2=$(date +%s)
echo "wheel $WHEEL (dev profile) built and installed: $((t2 - t1)) s"

export SOFTGRIP_WHEEL="$PWD/$WHEEL" SOFTGRIP_BIN="$PWD/target/debug/softgrip"
"$VENV/bin/python" -m pytest crates/softgrip-py/tests -q -rs -p no:cacheprovider \
  --ignore crates/softgrip-py/tests/test_ray.py
# Ray's servers listen on every interface (whatever _node_ip_address says): its test runs in a
# private network namespace whose one interface is loopback (as the DDS tests do).
t_ray=$(date +%s)
unshare --net -- sh -c 'ip link set lo up && exec "$0" -m pytest crates/softgrip-py/tests/test_ray.py -q -rs -p no:cacheprovider' \
  "$VENV/bin/python"
echo "Ray test (private network namespace): $(( $(date +%s) - t_ray )) s"
t3=$(date +%s)
echo "pytest: $((t3 - t2)) s; the Python step took $((t3 - t0)) s"
